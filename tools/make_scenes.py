#!/usr/bin/env python3
# tiershade -- tools/make_scenes.py
# Writes the shipped glTF scenes (scenes/model_lighting.gltf, world_lighting.gltf,
# hdr_atrium.gltf, and sphere_grid.gltf: the demo's and bench's sphere grid, whose lights are
# read from scenes/sphere_grid.lights, their one source; probe_chart.gltf: the colour-correction
# frame), their geometry (.bin next to each) and small procedural PNG textures
# (scenes/textures/). Python 3 standard library only. Run once from the repo root:
#   python3 tools/make_scenes.py
# The output is committed; builds and tests never run this script. Format: docs/scenes.md.
import json
import math
import os
import struct
import zlib

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
SCENES = os.path.join(ROOT, "scenes")
TEX = os.path.join(SCENES, "textures")


# ------------------------------------------------------------------------------ PNG ---
def write_png(path, w, h, px, channels=4):
    """px: list of rows (top row first), each a list of per-pixel tuples of 0..255 ints."""
    raw = bytearray()
    for row in px:
        raw.append(0)
        for p in row:
            raw.extend(bytes(max(0, min(255, int(round(c)))) for c in p[:channels]))

    def chunk(tag, data):
        c = struct.pack(">I", len(data)) + tag + data
        return c + struct.pack(">I", zlib.crc32(tag + data) & 0xFFFFFFFF)

    colour_type = {1: 0, 3: 2, 4: 6}[channels]
    png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, colour_type, 0, 0, 0))
    png += chunk(b"IDAT", zlib.compress(bytes(raw), 9)) + chunk(b"IEND", b"")
    with open(path, "wb") as f:
        f.write(png)


def image(w, h, fn):
    return [[fn(x, y) for x in range(w)] for y in range(h)]


def hash01(x, y, seed=0):
    """Deterministic value noise in [0, 1) on integer lattice points."""
    n = (x * 374761393 + y * 668265263 + seed * 2147483647) & 0xFFFFFFFF
    n = ((n ^ (n >> 13)) * 1274126177) & 0xFFFFFFFF
    return ((n ^ (n >> 16)) & 0xFFFF) / 65536.0


def smooth_noise(u, v, cells, seed):
    """Bilinear value noise, periodic with `cells` cells over [0,1)."""
    x, y = u * cells, v * cells
    x0, y0 = int(math.floor(x)), int(math.floor(y))
    fx, fy = x - x0, y - y0
    fx, fy = fx * fx * (3 - 2 * fx), fy * fy * (3 - 2 * fy)

    def at(i, j):
        return hash01(i % cells, j % cells, seed)

    a = at(x0, y0) * (1 - fx) + at(x0 + 1, y0) * fx
    b = at(x0, y0 + 1) * (1 - fx) + at(x0 + 1, y0 + 1) * fx
    return a * (1 - fy) + b * fy


def normal_map(w, h, height, strength, alpha=None):
    """Tangent-space normal map (glTF: green = image up) from height(x, y) in pixels, wrapped."""
    hf = [[height(x, y) for x in range(w)] for y in range(h)]

    def px(x, y):
        dx = (hf[y][(x + 1) % w] - hf[y][(x - 1) % w]) * 0.5
        dy_up = (hf[(y - 1) % h][x] - hf[(y + 1) % h][x]) * 0.5
        n = (-strength * dx, -strength * dy_up, 1.0)
        ln = math.sqrt(sum(c * c for c in n))
        a = 255 if alpha is None else alpha(x, y)
        return tuple((c / ln * 0.5 + 0.5) * 255 for c in n) + (a,)

    return [[px(x, y) for x in range(w)] for y in range(h)], hf


def ssbump_map(w, h, height, strength):
    """Self-shadowed bump weights: for each of the three RNM basis directions, the cosine of
    the bumped normal with it times how much of the direction the height field leaves unoccluded."""
    nm, hf = normal_map(w, h, height, strength)
    s6, s2, s3 = 1 / math.sqrt(6), 1 / math.sqrt(2), 1 / math.sqrt(3)
    basis = [(math.sqrt(2 / 3), 0, s3), (-s6, s2, s3), (-s6, -s2, s3)]

    def px(x, y):
        n = [c / 255 * 2 - 1 for c in nm[y][x][:3]]
        out = []
        for b in basis:
            cos = max(0.0, sum(n[i] * b[i] for i in range(3)))
            vis = 1.0
            for step in range(1, 6):  # march towards the basis direction in the image (+y up)
                sx = int(round(x + b[0] * step * 1.5)) % w
                sy = int(round(y - b[1] * step * 1.5)) % h
                rise = (hf[sy][sx] - hf[y][x]) * strength
                if rise > step * 1.5 * b[2] / math.sqrt(b[0] ** 2 + b[1] ** 2):
                    vis = min(vis, 0.35 + 0.13 * step)
            out.append(255 * cos * vis)
        return tuple(out) + (255,)

    return [[px(x, y) for x in range(w)] for y in range(h)]


# --------------------------------------------------------------------------- math ---
def sub(a, b):
    return [a[i] - b[i] for i in range(3)]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def dot(a, b):
    return sum(a[i] * b[i] for i in range(3))


def norm(a):
    ln = math.sqrt(dot(a, a))
    return [c / ln for c in a] if ln > 0 else [0.0, 0.0, 0.0]


def look_quat(eye, target, up=(0, 1, 0)):
    """Rotation quaternion (x, y, z, w) turning the node's -Z towards target, +Y near up."""
    f = norm(sub(target, eye))
    z = [-c for c in f]
    if abs(dot(norm(list(up)), z)) > 0.999:
        up = (0, 0, 1)
    x = norm(cross(list(up), z))
    y = cross(z, x)
    m00, m11, m22 = x[0], y[1], z[2]
    tr = m00 + m11 + m22
    if tr > 0:
        s = math.sqrt(tr + 1) * 2
        q = [(y[2] - z[1]) / s, (z[0] - x[2]) / s, (x[1] - y[0]) / s, 0.25 * s]
    elif m00 > m11 and m00 > m22:
        s = math.sqrt(1 + m00 - m11 - m22) * 2
        q = [0.25 * s, (y[0] + x[1]) / s, (z[0] + x[2]) / s, (y[2] - z[1]) / s]
    elif m11 > m22:
        s = math.sqrt(1 + m11 - m00 - m22) * 2
        q = [(y[0] + x[1]) / s, 0.25 * s, (z[1] + y[2]) / s, (z[0] - x[2]) / s]
    else:
        s = math.sqrt(1 + m22 - m00 - m11) * 2
        q = [(z[0] + x[2]) / s, (z[1] + y[2]) / s, 0.25 * s, (x[1] - y[0]) / s]
    return [round(c, 7) for c in q]


# ----------------------------------------------------------------------- geometry ---
def fix_winding_and_tangents(mesh):
    """Counter-clockwise front faces (against the normals) and tangent w = sign of
    dot(cross(N, T), B) where B is the texture's up direction (decreasing v)."""
    P, N, T, B, idx = mesh["pos"], mesh["nrm"], mesh["tan"], mesh.pop("bit"), mesh["idx"]
    for t in range(0, len(idx), 3):
        a, b, c = idx[t:t + 3]
        fn = cross(sub(P[b], P[a]), sub(P[c], P[a]))
        navg = [N[a][i] + N[b][i] + N[c][i] for i in range(3)]
        if dot(fn, navg) < 0:
            idx[t + 1], idx[t + 2] = c, b
    for i in range(len(P)):
        w = 1.0 if dot(cross(N[i], T[i][:3]), B[i]) >= 0 else -1.0
        T[i] = list(T[i][:3]) + [w]
    return mesh


def uv_sphere(r, seg, rings):
    pos, nrm, uv, tan, bit, idx = [], [], [], [], [], []
    for j in range(rings + 1):
        th = math.pi * j / rings
        for i in range(seg + 1):
            ph = 2 * math.pi * i / seg
            n = [math.sin(th) * math.cos(ph), math.cos(th), -math.sin(th) * math.sin(ph)]
            pos.append([r * c for c in n])
            nrm.append(n)
            uv.append([i / seg, j / rings])
            tan.append([-math.sin(ph), 0.0, -math.cos(ph)])  # dP/dphi
            bit.append([-math.cos(th) * math.cos(ph), math.sin(th), math.cos(th) * math.sin(ph)])  # -dP/dtheta
    for j in range(rings):
        for i in range(seg):
            a, b = j * (seg + 1) + i, (j + 1) * (seg + 1) + i
            if j != 0:
                idx += [a, b, a + 1]
            if j != rings - 1:
                idx += [a + 1, b, b + 1]
    return fix_winding_and_tangents(dict(pos=pos, nrm=nrm, uv=uv, tan=tan, bit=bit, idx=idx))


def torus(R, r, seg, sides):
    pos, nrm, uv, tan, bit, idx = [], [], [], [], [], []
    for j in range(sides + 1):
        be = 2 * math.pi * j / sides
        for i in range(seg + 1):
            al = 2 * math.pi * i / seg
            c = [math.cos(al), 0.0, -math.sin(al)]
            n = [math.cos(be) * c[0], math.sin(be), math.cos(be) * c[2]]
            pos.append([R * c[k] + r * n[k] for k in range(3)])
            nrm.append(n)
            uv.append([2 * i / seg, j / sides])
            tan.append([-math.sin(al), 0.0, -math.cos(al)])
            bit.append([-math.sin(be) * c[0], math.cos(be), -math.sin(be) * c[2]])
    for j in range(sides):
        for i in range(seg):
            a, b = j * (seg + 1) + i, (j + 1) * (seg + 1) + i
            idx += [a, b, a + 1, a + 1, b, b + 1]
    return fix_winding_and_tangents(dict(pos=pos, nrm=nrm, uv=uv, tan=tan, bit=bit, idx=idx))


def quad(o, U, V, su=1.0, sv=1.0):
    """Rectangle o + a U + b V (a, b in 0..1), front face towards cross(U, V); texture u along U
    (su repeats), texture up along V (sv repeats)."""
    n = norm(cross(U, V))
    t = norm(U)
    pos, uv = [], []
    for a, b in ((0, 0), (1, 0), (1, 1), (0, 1)):
        pos.append([o[k] + a * U[k] + b * V[k] for k in range(3)])
        uv.append([a * su, (1 - b) * sv])
    return fix_winding_and_tangents(dict(pos=pos, nrm=[n] * 4, uv=uv, tan=[t] * 4, bit=[norm(V)] * 4,
                                         idx=[0, 1, 2, 0, 2, 3]))


def wall_with_window(o, U, V, su, sv, a0, a1, b0, b1):
    """The rectangle o + a U + b V (as quad()) less the window a0 < a < a1, b0 < b < b1: four quads
    (below, above, left, right of it) whose texture continues across them as quad()'s would."""
    def part(pa0, pa1, pb0, pb1):
        q = quad([o[k] + pa0 * U[k] + pb0 * V[k] for k in range(3)], [(pa1 - pa0) * U[k] for k in range(3)],
                 [(pb1 - pb0) * V[k] for k in range(3)])
        for uv, (a, b) in zip(q["uv"], ((pa0, pb0), (pa1, pb0), (pa1, pb1), (pa0, pb1))):
            uv[0], uv[1] = a * su, (1 - b) * sv
        return q
    return [part(0, 1, 0, b0), part(0, 1, b1, 1), part(0, a0, b0, b1), part(a1, 1, b0, b1)]


def write_sky_hdr(path, w, h, fn):
    """A lat-long Radiance RGBE image (flat scanlines, row 0 at the top: v = acos(y) / pi down, u =
    atan2(x, -z) / 2pi + 0.5 across, glue's probe convention) of the linear radiance fn(x, y, z)."""
    out = bytearray(b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y %d +X %d\n" % (h, w))
    for j in range(h):
        theta = (j + 0.5) / h * math.pi
        for i in range(w):
            phi = ((i + 0.5) / w - 0.5) * 2 * math.pi
            x, y, z = math.sin(theta) * math.sin(phi), math.cos(theta), -math.sin(theta) * math.cos(phi)
            rgb = fn(x, y, z)
            m = max(rgb)
            if m < 1e-32:
                out += bytes(4)
                continue
            e = math.frexp(m)[1]
            out += bytes([min(255, int(c / 2.0 ** e * 256)) for c in rgb] + [e + 128])
    with open(path, "wb") as f:
        f.write(out)


def day_sky(x, y, z):
    """A smooth daylight sky (linear radiance): blue at the zenith, bright at the horizon, a warm
    glow towards the sun's side (-z, up), a dim brown ground below the horizon."""
    if y < 0:
        return (0.25, 0.2, 0.15)
    glow = max(0.0, 0.3 * x + 0.5 * y - 0.8 * z) ** 4
    h = 1 - y
    return (1.2 + 1.6 * h + 2.0 * glow, 1.6 + 1.4 * h + 1.6 * glow, 2.6 + 0.6 * h + 1.0 * glow)


def box_quads(center, size, tiles=1.0):
    """Five faces (no bottom) of an axis-aligned box standing on y = center[1]."""
    cx, cy, cz = center
    sx, sy, sz = size
    x0, x1, y0, y1, z0, z1 = cx - sx / 2, cx + sx / 2, cy, cy + sy, cz - sz / 2, cz + sz / 2
    return [
        quad([x0, y0, z1], [sx, 0, 0], [0, sy, 0], sx * tiles, sy * tiles),   # +Z
        quad([x1, y0, z0], [-sx, 0, 0], [0, sy, 0], sx * tiles, sy * tiles),  # -Z
        quad([x1, y0, z1], [0, 0, -sz], [0, sy, 0], sz * tiles, sy * tiles),  # +X
        quad([x0, y0, z0], [0, 0, sz], [0, sy, 0], sz * tiles, sy * tiles),   # -X
        quad([x0, y1, z1], [sx, 0, 0], [0, 0, -sz], sx * tiles, sz * tiles),  # +Y
    ]


# -------------------------------------------------------------------------- glTF ---
class Gltf:
    def __init__(self, name):
        self.name = name
        self.bin = bytearray()
        self.doc = {"asset": {"version": "2.0", "generator": "tiershade tools/make_scenes.py"},
                    "scene": 0, "scenes": [{"name": name, "nodes": []}], "nodes": [], "meshes": [],
                    "materials": [], "textures": [], "images": [], "samplers": [{"magFilter": 9729,
                    "minFilter": 9987, "wrapS": 10497, "wrapT": 10497}], "accessors": [], "bufferViews": [],
                    "buffers": [], "cameras": [], "extensionsUsed": ["KHR_lights_punctual"],
                    "extensions": {"KHR_lights_punctual": {"lights": []}}}
        self.tex_ids = {}

    def _view(self, data, target):
        while len(self.bin) % 4:
            self.bin.append(0)
        off = len(self.bin)
        self.bin.extend(data)
        self.doc["bufferViews"].append({"buffer": 0, "byteOffset": off, "byteLength": len(data), "target": target})
        return len(self.doc["bufferViews"]) - 1

    def _acc(self, rows, typ, n):
        flat = [float(c) for row in rows for c in row[:n]]
        view = self._view(struct.pack("<%df" % len(flat), *flat), 34962)
        acc = {"bufferView": view, "componentType": 5126, "count": len(rows), "type": typ}
        if typ == "VEC3":
            acc["min"] = [min(r[k] for r in rows) for k in range(3)]
            acc["max"] = [max(r[k] for r in rows) for k in range(3)]
        self.doc["accessors"].append(acc)
        return len(self.doc["accessors"]) - 1

    def primitive(self, mesh, material):
        big = max(mesh["idx"]) > 65535
        data = struct.pack("<%d%s" % (len(mesh["idx"]), "I" if big else "H"), *mesh["idx"])
        view = self._view(data, 34963)
        self.doc["accessors"].append({"bufferView": view, "componentType": 5125 if big else 5123,
                                      "count": len(mesh["idx"]), "type": "SCALAR"})
        ind = len(self.doc["accessors"]) - 1
        return {"attributes": {"POSITION": self._acc(mesh["pos"], "VEC3", 3),
                               "NORMAL": self._acc(mesh["nrm"], "VEC3", 3),
                               "TEXCOORD_0": self._acc(mesh["uv"], "VEC2", 2),
                               "TANGENT": self._acc(mesh["tan"], "VEC4", 4),
                               **({"TEXCOORD_1": self._acc(mesh["uv1"], "VEC2", 2)} if "uv1" in mesh else {})},
                "indices": ind, "material": material, "mode": 4}

    def node(self, node, root=True):
        self.doc["nodes"].append(node)
        i = len(self.doc["nodes"]) - 1
        if root:
            self.doc["scenes"][0]["nodes"].append(i)
        return i

    def mesh(self, name, meshes_and_materials, **node):
        root = node.pop("root", True)
        prims = [self.primitive(m, mat) for m, mat in meshes_and_materials]
        self.doc["meshes"].append({"name": name, "primitives": prims})
        return self.node(dict(name=name, mesh=len(self.doc["meshes"]) - 1, **node), root)

    def instance(self, name, prim, material, **node):
        """A node drawing primitive `prim` (from primitive()) with another material: the geometry's
        accessors are shared, not written again."""
        self.doc["meshes"].append({"name": name, "primitives": [dict(prim, material=material)]})
        return self.node(dict(name=name, mesh=len(self.doc["meshes"]) - 1, **node))

    def texture(self, file, clamp=False):
        """The texture of scenes/textures/FILE, linear filtering, repeat (clamp: clamp to edge, a
        second sampler added on first use)."""
        key = (file, clamp)
        if key not in self.tex_ids:
            sampler = 0
            if clamp:
                edge = {"magFilter": 9729, "minFilter": 9729, "wrapS": 33071, "wrapT": 33071}
                if edge not in self.doc["samplers"]:
                    self.doc["samplers"].append(edge)
                sampler = self.doc["samplers"].index(edge)
            self.doc["images"].append({"uri": "textures/" + file})
            self.doc["textures"].append({"source": len(self.doc["images"]) - 1, "sampler": sampler})
            self.tex_ids[key] = len(self.doc["textures"]) - 1
        return self.tex_ids[key]

    def material(self, name, source, base=None, normal=None, color=(1, 1, 1, 1), clamp=False):
        pbr = {"baseColorFactor": list(color), "metallicFactor": 0.0, "roughnessFactor": 1.0}
        if base:
            pbr["baseColorTexture"] = {"index": self.texture(base, clamp)}
        m = {"name": name, "pbrMetallicRoughness": pbr, "extras": {"source": source}}
        if normal:
            m["normalTexture"] = {"index": self.texture(normal)}
        self.doc["materials"].append(m)
        return len(self.doc["materials"]) - 1

    def tex(self, file):
        return {"index": self.texture(file)}

    def light(self, name, typ, color, intensity, eye, target=None, inner=None, outer=None, source=None):
        l = {"name": name, "type": typ, "color": list(color), "intensity": intensity}
        if typ == "spot":
            l["spot"] = {"innerConeAngle": inner, "outerConeAngle": outer}
        if source:
            l["extras"] = {"source": source}
        lights = self.doc["extensions"]["KHR_lights_punctual"]["lights"]
        lights.append(l)
        node = {"name": name, "translation": list(eye),
                "extensions": {"KHR_lights_punctual": {"light": len(lights) - 1}}}
        if target is not None:
            node["rotation"] = look_quat(eye, target)
        return self.node(node)

    def ortho_camera(self, name, eye, target, xmag, ymag, znear, zfar):
        self.doc["cameras"].append({"name": name, "type": "orthographic",
                                    "orthographic": {"xmag": xmag, "ymag": ymag, "znear": znear, "zfar": zfar}})
        return self.node({"name": name, "camera": len(self.doc["cameras"]) - 1,
                          "translation": list(eye), "rotation": look_quat(eye, target)})

    def camera(self, name, eye, target, yfov, aspect=None):
        cam = {"name": name, "type": "perspective", "perspective": {"yfov": yfov, "znear": 0.05, "zfar": 100.0}}
        if aspect:
            cam["perspective"]["aspectRatio"] = aspect
        self.doc["cameras"].append(cam)
        return self.node({"name": name, "camera": len(self.doc["cameras"]) - 1,
                          "translation": list(eye), "rotation": look_quat(eye, target)})

    def write(self, tiershade):
        self.doc["buffers"].append({"uri": self.name + ".bin", "byteLength": len(self.bin)})
        self.doc["extras"] = {"tiershade": tiershade}
        for k in ("textures", "images"):
            if not self.doc[k]:
                del self.doc[k]
        with open(os.path.join(SCENES, self.name + ".bin"), "wb") as f:
            f.write(self.bin)
        with open(os.path.join(SCENES, self.name + ".gltf"), "w") as f:
            json.dump(self.doc, f, indent=1)
            f.write("\n")


# ----------------------------------------------------------------------- textures ---
def make_textures():
    os.makedirs(TEX, exist_ok=True)
    w = lambda name, px, ch=4: write_png(os.path.join(TEX, name), len(px[0]), len(px), px, ch)
    # sphere grid albedo: hue bands across u, a soft checker across v (sRGB codes of the linear colour)
    enc = lambda c: 255 * (12.92 * c if c <= 0.0031308 else 1.055 * c ** (1 / 2.4) - 0.055)
    band = lambda x, y, k, off: (1.0 if (x // 8 + y // 8) % 2 else 0.75) * (0.5 + 0.3 * math.cos(2 * math.pi * (x / 64 + off))) * k
    w("sphere_bands.png", image(64, 64, lambda x, r: (enc(band(x, 63 - r, 1, 0.0)), enc(band(x, 63 - r, 1, 0.33)),
                                                      enc(band(x, 63 - r, 0.8 + 0.2 * (63 - r) / 64, 0.67)))), 3)
    # Phong sphere: a grid of round dimples (normals from the height gradient; alpha: glossy
    # stripes, the specular mask) and the exponent map (r exponent, g albedo-tint mask, a rim mask)
    def dimple(x, y, n=128, cells=8):
        u, v = (x + 0.5) / n * cells, (y + 0.5) / n * cells
        fu, fv = u - math.floor(u) - 0.5, v - math.floor(v) - 0.5
        r = math.hypot(fu, fv)
        g = (-0.9 * math.sin(r / 0.4 * math.pi) / r) if 1e-9 < r < 0.4 else 0.0
        nx, ny, nz = -g * fu, -g * fv, 1.0
        ln = math.sqrt(nx * nx + ny * ny + nz * nz)
        return (255 * (0.5 + 0.5 * nx / ln), 255 * (0.5 + 0.5 * ny / ln), 255 * (0.5 + 0.5 * nz / ln),
                255 if (x * 4 // n) % 2 else 0.35 * 255)
    w("dimples_normal.png", image(128, 128, lambda x, r: dimple(x, 127 - r)))
    w("phong_exponent.png", image(64, 64, lambda x, r: (255 * (0.05 + 0.6 * (0.5 + 0.5 * math.cos(
        2 * math.pi * (63 - r) / 64 * 2))), 255 * x / 64, 0, 255)))
    w("checker.png", image(128, 128, lambda x, y: (200, 190, 170) if (x // 16 + y // 16) % 2 else (70, 90, 130)), 3)
    w("skin.png", image(128, 128, lambda x, y: tuple(c * (0.9 + 0.1 * smooth_noise(x / 128, y / 128, 16, 1))
                                                     for c in (224, 172, 150)) + (255,)))
    bumps = lambda x, y: 3.0 * smooth_noise(x / 128, y / 128, 24, 2) + 1.5 * smooth_noise(x / 128, y / 128, 8, 3)
    w("skin_normal.png", normal_map(128, 128, bumps, 1.5)[0])
    # r: exponent (pores duller), g: albedo tint mask, a: rim mask
    w("skin_exponent.png", image(128, 128, lambda x, y: (90 + 80 * smooth_noise(x / 128, y / 128, 24, 2), 40,
                                                         0, 255)))
    w("metal.png", image(64, 64, lambda x, y: tuple(c * (0.85 + 0.15 * hash01(x, y // 8, 4)) for c in (180, 170, 150))
                         + (255,)))
    w("metal_normal.png", normal_map(64, 64, lambda x, y: 0.6 * math.sin(2 * math.pi * y / 16), 1.0)[0])
    w("lightwarp.png", image(256, 4, lambda x, y: (255 * min(1, (x / 255) ** 0.8 * 1.1),
                                                   255 * (x / 255) ** 1.1, 255 * (x / 255) ** 1.6, 255)))
    w("selfillum.png", image(128, 128, lambda x, y: (60, 60, 70, 255 if (y // 8) % 3 == 0 else 0)))
    tile_h = lambda x, y: 0.0 if (x % 32 < 2 or y % 32 < 2) else 2.0
    w("tiles.png", image(128, 128, lambda x, y: (90, 88, 85) if tile_h(x, y) == 0 else
                         tuple(c * (0.92 + 0.08 * smooth_noise(x / 128, y / 128, 8, 5)) for c in (205, 200, 190))), 3)
    # alpha of the normal map = envmap mask ($normalmapalphaenvmapmask): glossy tiles, dull grout
    w("tiles_normal.png", normal_map(128, 128, tile_h, 1.0, lambda x, y: 40 if tile_h(x, y) == 0 else 230)[0])
    w("plaster.png", image(64, 64, lambda x, y: tuple(c * (0.93 + 0.07 * smooth_noise(x / 64, y / 64, 8, 6))
                                                      for c in (225, 222, 215))), 3)
    brick_h = lambda x, y: 0.0 if (y % 16 < 2 or (x + (8 if (y // 16) % 2 else 0)) % 32 < 2) else 1.5
    w("brick.png", image(128, 128, lambda x, y: (150, 145, 140) if brick_h(x, y) == 0 else
                         tuple(c * (0.8 + 0.2 * hash01((x + (8 if (y // 16) % 2 else 0)) // 32, y // 16, 7))
                               for c in (160, 80, 60))), 3)
    w("brick_normal.png", normal_map(128, 128, brick_h, 1.2)[0])
    stone_h = lambda x, y: 4.0 * smooth_noise(x / 128, y / 128, 6, 8) + 2.0 * smooth_noise(x / 128, y / 128, 16, 9)
    w("stone.png", image(128, 128, lambda x, y: tuple(c * (0.75 + 0.25 * smooth_noise(x / 128, y / 128, 6, 8))
                                                      for c in (170, 165, 150))), 3)
    w("stone_ssbump.png", ssbump_map(128, 128, stone_h, 1.2))
    plank = lambda x, y: (x // 32) % 2
    w("crate.png", image(128, 128, lambda x, y: tuple(c * (0.8 + 0.2 * smooth_noise(x / 128, y / 128 * 0.25, 32, 10))
                                                      for c in ((150, 110, 70) if plank(x, y) else (135, 98, 62)))), 3)
    edge = lambda x, y: x < 12 or x > 115 or y < 12 or y > 115
    w("crate_mask.png", image(128, 128, lambda x, y: (230, 230, 230) if edge(x, y) else (25, 25, 25)), 3)
    # $basealphaenvmapmask: the envmap is masked by 1 - base alpha (glossy where alpha is low)
    w("glossy_tile.png", image(128, 128, lambda x, y: (40, 70, 110, 30) if (x // 64 + y // 64) % 2 else
                               (210, 205, 195, 200)))
    w("const_mask.png", image(4, 4, lambda x, y: (128, 128, 128)), 3)
    w("marble.png", image(128, 128, lambda x, y: tuple(c * (0.75 + 0.25 * math.sin(
        (x / 128 + 2 * smooth_noise(x / 128, y / 128, 8, 11)) * 2 * math.pi * 3) ** 2) for c in (235, 232, 225))
                                                       + (255,)))


# ------------------------------------------------------------------------- scenes ---
def model_lighting():
    g = Gltf("model_lighting")
    plain = g.material("lambert_plain", {"shader": "VertexLitGeneric", "$halflambert": 0}, color=(0.7, 0.7, 0.72, 1))
    checker = g.material("halflambert_checker", {"shader": "VertexLitGeneric", "$halflambert": 1}, base="checker.png")
    skin = g.material("skin", {"shader": "VertexLitGeneric", "$phong": 1, "$phongboost": 2.0,
                               "$phongexponenttexture": g.tex("skin_exponent.png"), "$phongexponentfactor": 60,
                               "$phongfresnelranges": [0.3, 0.6, 1.0], "$rimlight": 1, "$rimlightexponent": 4,
                               "$rimlightboost": 2.0, "$rimmask": 1},
                      base="skin.png", normal="skin_normal.png")
    metal = g.material("metal_envmap", {"shader": "VertexLitGeneric", "$phong": 1, "$phongexponent": 40,
                                        "$phongboost": 1.5, "$phongfresnelranges": [0.15, 0.5, 1.0],
                                        "$envmap": 1, "$envmaptint": [0.6, 0.6, 0.6], "$envmapfresnel": 0.5,
                                        "$lightwarptexture": g.tex("lightwarp.png")},
                       base="metal.png", normal="metal_normal.png")
    glow = g.material("selfillum_stripes", {"shader": "VertexLitGeneric", "$selfillum": 1,
                                            "$selfillumtint": [1.0, 0.6, 0.2]}, base="selfillum.png")
    sphere = uv_sphere(0.6, 48, 24)
    g.mesh("plain_sphere", [(sphere, plain)], translation=[-3.0, 0.0, 0.0])
    g.mesh("checker_sphere", [(sphere, checker)], translation=[-1.5, 0.0, -0.5])
    g.mesh("skin_sphere", [(sphere, skin)], translation=[0.0, 0.0, 0.0])
    # the torus hangs under a tilted, scaled parent: the loader applies the hierarchy
    tor = g.mesh("metal_torus", [(torus(0.55, 0.22, 48, 24), metal)], rotation=[0.5, 0.0, 0.0, 0.8660254],
                 root=False)
    g.node({"name": "torus_parent", "translation": [1.5, 0.0, -0.5], "scale": [1.1, 1.1, 1.1], "children": [tor]})
    g.mesh("glow_sphere", [(sphere, glow)], translation=[3.0, 0.0, 0.0])
    g.light("key_point", "point", (1.0, 0.9, 0.8), 10.0, (-2.5, 2.5, 2.5))
    g.light("fill_point", "point", (0.6, 0.7, 1.0), 4.0, (3.0, 1.0, 2.5))
    g.light("top_spot", "spot", (1.0, 1.0, 0.95), 15.0, (0.0, 4.0, 1.0), (0.0, 0.0, 0.0), 0.3, 0.5,
            {"exponent": 2})
    g.light("back_spot", "spot", (0.8, 0.9, 1.0), 12.0, (1.5, 1.5, -3.0), (0.0, 0.0, 0.0), 0.4, 0.7,
            {"exponent": 1, "constant": 0, "linear": 0, "quadratic": 1})
    g.light("sun", "directional", (1.0, 0.95, 0.85), 0.6, (0.0, 5.0, 0.0), (1.0, 4.0, -0.5))
    g.light("ground_bounce", "directional", (0.35, 0.4, 0.5), 0.3, (0.0, -5.0, 0.0), (0.0, 5.0, 0.0))
    g.camera("main", (0.0, 1.0, 6.0), (0.0, 0.0, 0.0), 0.7)
    g.write({"camera": 0,
             "probes": [{"name": "grace", "position": [0, 1, 0], "image": "../../shared/data/probes/grace.hdr",
                         "scale": 1.0, "size": 64}],
             "ambient": [{"position": [0, 0, 0], "from_probe": 0},
                         {"position": [4, 0, 0], "cube": [[0.20, 0.18, 0.15], [0.05, 0.06, 0.08],
                                                          [0.25, 0.27, 0.30], [0.04, 0.035, 0.03],
                                                          [0.10, 0.10, 0.12], [0.08, 0.08, 0.08]]}],
             "hdr": {"path": "integer", "tone_map_scale": 1.0}})


def ceiling_disc(c, rad, seg):
    """A flat disc facing down (a ceiling fixture) centred at c: a fan of seg triangles, TEXCOORD_0
    and TEXCOORD_1 its plan projection."""
    pos, nrm, uv, uv1, tan, bit, idx = [list(c)], [[0.0, -1.0, 0.0]], [[0.5, 0.5]], [[0.5, 0.5]], [], [], []
    for i in range(seg):
        ph = 2 * math.pi * i / seg
        x, z = rad * math.cos(ph), rad * math.sin(ph)
        pos.append([c[0] + x, c[1], c[2] + z])
        nrm.append([0.0, -1.0, 0.0])
        uv.append([0.5 + 0.5 * x / rad, 0.5 + 0.5 * z / rad])
        uv1.append([0.5 + 0.5 * x / rad, 0.5 + 0.5 * z / rad])
    for i in range(seg + 1):
        tan.append([1.0, 0.0, 0.0])
        bit.append([0.0, 0.0, -1.0])
    for i in range(seg):
        idx += [0, 1 + i, 1 + (i + 1) % seg]
    return fix_winding_and_tangents(dict(pos=pos, nrm=nrm, uv=uv, uv1=uv1, tan=tan, bit=bit, idx=idx))


def world_lighting():
    write_sky_hdr(os.path.join(SCENES, "textures", "day_sky.hdr"), 64, 32, day_sky)
    g = Gltf("world_lighting")
    W = "LightmappedGeneric"
    floor = g.material("floor_tiles", {"shader": W, "$envmap": 1, "$normalmapalphaenvmapmask": 1,
                                       "$envmaptint": [0.4, 0.4, 0.4], "$fresnelreflection": 0.3},
                       base="tiles.png", normal="tiles_normal.png")
    ceiling = g.material("ceiling_plaster", {"shader": W}, base="plaster.png")
    brick = g.material("wall_brick", {"shader": W}, base="brick.png", normal="brick_normal.png")
    stone = g.material("wall_stone_ssbump", {"shader": W, "$ssbump": 1}, base="stone.png", normal="stone_ssbump.png")
    crate = g.material("crate_masked", {"shader": W, "$envmap": 1, "$envmapmask": g.tex("crate_mask.png"),
                                        "probe": 1, "$envmaptint": [0.8, 0.8, 0.8]}, base="crate.png")
    glossy = g.material("glossy_tile_basealpha", {"shader": W, "$envmap": 1, "$basealphaenvmapmask": 1,
                                                  "$envmapcontrast": 0.3, "$envmapsaturation": 0.8},
                        base="glossy_tile.png", normal="brick_normal.png")
    const = g.material("plinth_const_mask", {"shader": W, "$envmap": 1, "$envmapmask": g.tex("const_mask.png"),
                                             "$envmapscale": 0.8}, base="plaster.png")
    X, Y, Z = 4.0, 3.0, 3.0
    g.mesh("floor", [(quad([-X, 0, Z], [2 * X, 0, 0], [0, 0, -2 * Z], 2 * X / 2, 2 * Z / 2), floor)])
    g.mesh("ceiling", [(quad([-X, Y, -Z], [2 * X, 0, 0], [0, 0, 2 * Z], 2 * X / 2, 2 * Z / 2), ceiling)])
    # the back wall has a window (x -0.4..2.6, y 0.9..2.6) onto the sky (extras.tiershade.sky)
    g.mesh("wall_back", [(q, brick) for q in wall_with_window([-X, 0, -Z], [2 * X, 0, 0], [0, Y, 0], 2 * X / 2,
                                                             Y / 2, 3.6 / 8, 6.6 / 8, 0.9 / 3, 2.6 / 3)])
    g.mesh("wall_front", [(quad([X, 0, Z], [-2 * X, 0, 0], [0, Y, 0], 2 * X / 2, Y / 2), brick)])
    g.mesh("wall_left_ssbump", [(quad([-X, 0, Z], [0, 0, -2 * Z], [0, Y, 0], 2 * Z / 1.5, Y / 1.5), stone)])
    g.mesh("wall_right", [(quad([X, 0, -Z], [0, 0, 2 * Z], [0, Y, 0], 2 * Z / 2, Y / 2), brick)])
    g.mesh("crate", [(q, crate) for q in box_quads((-2.6, 0.0, -1.8), (1.0, 1.0, 1.0))])
    g.mesh("pillar", [(q, glossy) for q in box_quads((2.4, 0.0, -1.6), (0.8, 1.8, 0.8), 0.5)])
    g.mesh("plinth", [(q, const) for q in box_quads((-0.5, 0.0, -0.5), (0.6, 0.6, 0.6))])
    # a round ceiling light fixture: an emissive LightmappedGeneric disc with its own lightmap UVs
    # (TEXCOORD_1), sampled by the bake as an area light of spherical triangles (glue/bake/area_lights.h)
    lamp = g.material("ceiling_lamp", {"shader": W})
    g.doc["materials"][lamp]["emissiveFactor"] = [1.0, 0.92, 0.78]
    g.doc["materials"][lamp]["extensions"] = {"KHR_materials_emissive_strength": {"emissiveStrength": 100.0}}
    g.doc["extensionsUsed"].append("KHR_materials_emissive_strength")
    g.mesh("ceiling_lamp", [(ceiling_disc((-0.5, Y - 0.02, -0.5), 0.35, 24), lamp)])
    g.light("lamp_left", "point", (1.0, 0.85, 0.65), 6.0, (-2.5, 2.6, -1.0))
    g.light("lamp_right", "point", (0.7, 0.8, 1.0), 5.0, (2.5, 2.6, 1.0))
    g.light("lamp_low", "point", (1.0, 0.95, 0.9), 3.0, (0.0, 1.2, 2.0))
    g.camera("corner_view", (3.2, 1.7, 2.4), (-4.0, 0.8, -3.0), 1.0)
    g.write({"camera": 0,
             "probes": [{"name": "room_centre", "position": [0, 1.5, 0], "size": 64},
                        {"name": "by_the_crate", "position": [-2.6, 1.0, -1.0], "size": 32}],
             "lightmaps": {"luxels_per_unit": 8, "encoding": "rgbe", "page": [512, 256]},
             # the sky seen through the window: a small smooth lat-long HDR written here, few rays
             # per luxel (the scene is baked at every load); its sun through the window, soft-edged
             "sky": {"image": "textures/day_sky.hdr", "scale": 0.6, "samples": 16,
                     "sun": {"direction": [0.35, 0.55, -1.0], "color": [1.0, 0.93, 0.8], "intensity": 1.5,
                             "spread_degrees": 4.0}},
             # a faint range fog: the pixel fog ps2b/sm3 apply and ps20 drops (docs/world_lighting.md)
             "fog": {"color": [0.05, 0.05, 0.06], "start": 3.0, "end": 15.0, "max_density": 0.5},
             "hdr": {"path": "integer", "tone_map_scale": 1.0}})


def hdr_atrium():
    g = Gltf("hdr_atrium")
    M = "VertexLitGeneric"
    marble = g.material("marble", {"shader": M, "$halflambert": 1}, base="marble.png")
    floor = g.material("atrium_floor", {"shader": M, "$halflambert": 0}, base="tiles.png")
    gold = g.material("gold", {"shader": M, "$phong": 1, "$phongexponent": 60, "$phongboost": 3.0,
                               "$phongtint": [1.0, 0.8, 0.4], "$phongfresnelranges": [0.4, 0.7, 1.0],
                               "$envmap": 1, "$envmaptint": [1.0, 0.8, 0.45], "$envmapfresnel": 0.3,
                               "$rimlight": 1, "$rimlightboost": 1.5},
                      base="metal.png", normal="metal_normal.png")
    matte = g.material("matte_blue", {"shader": M}, color=(0.25, 0.35, 0.7, 1))
    panel = g.material("light_panel", {"shader": M, "$selfillum": 1, "$selfillumtint": [24.0, 21.0, 17.0]},
                       color=(1, 1, 1, 1))
    sphere = uv_sphere(0.7, 48, 24)
    g.mesh("floor", [(quad([-5, 0, 4], [10, 0, 0], [0, 0, -8], 5, 4), floor)])
    g.mesh("marble_sphere", [(sphere, marble)], translation=[-1.8, 0.7, 0.0])
    g.mesh("gold_torus", [(torus(0.6, 0.25, 48, 24), gold)], translation=[0.0, 0.85, -0.3],
           rotation=[0.3826834, 0.0, 0.0, 0.9238795])
    g.mesh("matte_sphere", [(sphere, matte)], translation=[1.8, 0.7, 0.0])
    g.mesh("light_panel", [(quad([-1.5, 1.2, -3.5], [3.0, 0, 0], [0, 1.2, 0]), panel)])
    g.light("sun_lamp", "point", (1.0, 0.92, 0.8), 200.0, (0.0, 5.0, 2.0))
    g.light("cool_fill", "point", (0.6, 0.75, 1.0), 20.0, (-4.0, 2.0, 3.0))
    g.light("stage_spot", "spot", (1.0, 0.95, 0.9), 120.0, (2.5, 4.5, 2.5), (0.0, 0.5, 0.0), 0.25, 0.45,
            {"exponent": 1})
    g.light("skylight", "directional", (0.9, 0.95, 1.0), 20.0, (0.0, 8.0, 0.0), (-0.3, 7.0, -0.4))
    g.camera("main", (0.0, 1.8, 6.0), (0.0, 0.8, 0.0), 0.75)
    g.write({"camera": 0,
             "probes": [{"name": "uffizi", "position": [0, 1, 0], "image": "../../shared/data/probes/uffizi.hdr",
                         "scale": 4.0, "size": 64}],
             "ambient": [{"position": [0, 0.8, 0], "from_probe": 0}],
             "hdr": {"path": "float", "tone_map_scale": 0.3, "auto_exposure": True, "exposure_min": 0.02,
                     "exposure_max": 4.0, "bloom": 0.3,
                     "luts": [{"file": "luts/day_for_night.cube", "weight": 0.3},
                              {"file": "luts/desaturate.cube", "weight": 0.2}]}})

def read_lights(path):
    """The lights of a tiershade lights file (format: `tiershade fold --help`) as dicts."""
    out = []
    with open(path) as f:
        for line in f:
            v = line.split("#")[0].split()
            if not v:
                continue
            n = [float(x) for x in v[1:]]
            l = {"type": v[0], "color": n[0:3]}
            if v[0] == "directional":
                l["dir"] = n[3:6]
            elif v[0] == "point":
                l["pos"], l["atten"] = n[3:6], n[6:9]
            elif v[0] == "spot":
                l["pos"], l["dir"], l["exponent"] = n[3:6], n[6:9], n[9]
                l["inner"], l["outer"], l["atten"] = math.radians(n[10]), math.radians(n[11]), n[12:15]
            else:
                raise ValueError("%s: unknown light type %r" % (path, v[0]))
            out.append(l)
    return out


def sphere_grid_mesh(cols, rows, spacing):
    """cols x rows unit spheres `spacing` apart around the origin, in one mesh: one draw, so the
    lights beyond a tier's limit are folded once, at the grid's centre (the mesh's bounding-box
    centre), as a deferred frame of the grid has one set of uniforms."""
    base = uv_sphere(1.0, 48, 24)
    grid = dict(pos=[], nrm=[], uv=[], tan=[], idx=[])
    for r in range(rows):
        for c in range(cols):
            off = [(c - (cols - 1) / 2) * spacing, (r - (rows - 1) / 2) * spacing, 0.0]
            first = len(grid["pos"])
            grid["pos"] += [[p[k] + off[k] for k in range(3)] for p in base["pos"]]
            grid["nrm"] += base["nrm"]
            grid["tan"] += base["tan"]
            # each sphere shows another part of the texture (u twice around, 0.75 turning u = 0 to -Z,
            # the back; shifted per column and row)
            grid["uv"] += [[2.0 * (u + 0.75 + 0.17 * c), v + 0.29 * r] for u, v in base["uv"]]
            grid["idx"] += [first + i for i in base["idx"]]
    return grid


def add_wall(mesh, z, half):
    """A wall facing +Z at depth z behind the grid (2 half wide), in the same mesh; uv = world / 4."""
    first = len(mesh["pos"])
    for x, y in ((-half, -half), (half, -half), (half, half), (-half, half)):
        mesh["pos"].append([x, y, z])
        mesh["nrm"].append([0.0, 0.0, 1.0])
        mesh["tan"].append([1.0, 0.0, 0.0, 1.0])
        mesh["uv"].append([0.25 * x, 0.25 * y])
    mesh["idx"] += [first, first + 1, first + 2, first, first + 2, first + 3]
    return mesh


def hdr_spheres(name, lights, ambient, probes=None):
    """The HDR demo and bench scenes: the sphere grid before a wall (z = -1.2), the integer path at
    tone-map scale 1 (the HDR code scales the linear frame itself), sm3's 4 lights: none folded."""
    g = Gltf(name)
    mat = g.material("halflambert_bands", {"shader": "VertexLitGeneric", "$halflambert": 1}, base="sphere_bands.png")
    g.mesh("spheres_and_wall", [(add_wall(sphere_grid_mesh(5, 3, 2.4), -1.2, 40.0), mat)])
    for l in lights:
        g.light(*l[:5], **l[5] if len(l) > 5 else {})
    g.ortho_camera("front", (0.0, 0.0, 60.0), (0.0, 0.0, 0.0), 6.0, 3.6, 1.0, 120.0)
    extras = {"camera": 0, "ambient": [ambient], "hdr": {"path": "integer", "tone_map_scale": 1.0}}
    if probes:
        extras["probes"] = probes
    g.write(extras)


def hdr_scenes():
    # Daylight: a sun, a hot spot on the wall (well above 1 after any sensible exposure: the
    # bloom's source) and a cool bounce; the sky's ambient cube from the Uffizi probe x 0.12.
    sun_dir = norm([-0.45, -0.55, -0.70])
    spot_dir = norm([0.2, 0.1, -1.0])
    hdr_spheres("hdr_daylight", [
        ("sun", "directional", (0.9, 0.82, 0.68), 1.0, (0.0, 0.0, 0.0), dict(target=sun_dir)),
        ("hot_spot", "spot", (250.0, 190.0, 120.0), 1.0, (3.5, 2.5, 1.5),
         dict(target=[3.5 + spot_dir[0], 2.5 + spot_dir[1], 1.5 + spot_dir[2]], inner=0.06, outer=0.20,
              source={"exponent": 1, "constant": 1, "linear": 0, "quadratic": 0.6})),
        ("cool_bounce", "point", (0.1, 0.15, 0.35), 1.0, (-5.0, -1.0, 3.0),
         dict(source={"constant": 0.5, "linear": 0.1, "quadratic": 0.05})),
    ], {"position": [0, 0, 0], "from_probe": 0},
        [{"name": "uffizi", "position": [0, 0, 0], "image": "../../shared/data/probes/uffizi.hdr", "scale": 0.12,
          "size": 8}])
    # A dark room: one dim lamp and a faint ambient cube.
    hdr_spheres("hdr_dark_room", [
        ("dim_lamp", "point", (0.10, 0.075, 0.045), 1.0, (-2.0, 2.0, 2.5),
         dict(source={"constant": 0.5, "linear": 0.2, "quadratic": 0.1})),
    ], {"position": [0, 0, 0], "cube": [[0.004, 0.0036, 0.0032], [0.003, 0.0028, 0.0024], [0.005, 0.0045, 0.004],
                                        [0.002, 0.0016, 0.0016], [0.004, 0.0036, 0.0032], [0.0024, 0.002, 0.002]]})


def phong_sphere():
    """The Episode One section of the demo and bench: one sphere with the dimple normal map, the
    exponent map, rim light and the Grace Cathedral envmap; the first four grid lights (the blue
    fill brighter); the ambient cube from the probe x 0.35 (a second, scaled probe)."""
    g = Gltf("phong_sphere")
    mat = g.material("episode_one", {"shader": "VertexLitGeneric", "$phong": 1, "$phongboost": 4.0,
                                     "$phongexponenttexture": g.tex("phong_exponent.png"), "$phongexponentfactor": 149,
                                     "$phongfresnelranges": [0.15, 0.5, 1.0], "$phongalbedotint": 1,
                                     "$rimlight": 1, "$rimlightexponent": 4, "$rimlightboost": 2.0, "$rimmask": 1,
                                     "$envmap": 1, "$envmapscale": 0.25, "$envmapfresnel": 1, "probe": 0},
                     base="sphere_bands.png", normal="dimples_normal.png")
    g.mesh("sphere", [(sphere_grid_mesh(1, 1, 2.4), mat)])
    lights = read_lights(os.path.join(SCENES, "sphere_grid.lights"))[:4]
    lights[1]["color"] = [0.6, 0.8, 1.8]
    add_lights(g, lights)
    g.ortho_camera("front", (0.0, 0.0, 60.0), (0.0, 0.0, 0.0), 1.2, 1.2, 1.0, 120.0)
    grace = "../../shared/data/probes/grace.hdr"
    g.write({"camera": 0,
             "probes": [{"name": "grace", "position": [0, 0, 0], "image": grace, "scale": 1.0, "size": 32},
                        {"name": "grace_ambient", "position": [0, 0, 0], "image": grace, "scale": 0.35, "size": 32}],
             "ambient": [{"position": [0, 0, 0], "from_probe": 1}],
             "hdr": {"path": "integer", "tone_map_scale": 0.8}})


def add_lights(g, lights):
    for i, l in enumerate(lights):
        name = "%s_%d" % (l["type"], i)
        if l["type"] == "directional":
            g.light(name, "directional", l["color"], 1.0, (0.0, 0.0, 0.0), norm(l["dir"]))
        else:
            src = dict(zip(("constant", "linear", "quadratic"), l["atten"]))
            if l["type"] == "spot":
                src["exponent"] = l["exponent"]
                tgt = [l["pos"][k] + l["dir"][k] for k in range(3)]
                g.light(name, "spot", l["color"], 1.0, l["pos"], tgt, l["inner"], l["outer"], src)
            else:
                g.light(name, "point", l["color"], 1.0, l["pos"], source=src)


def sphere_grid():
    """The model-lighting demo and bench scene: a 5 x 3 grid of unit spheres 2.4 apart seen by an
    orthographic camera on +Z, the six lights of scenes/sphere_grid.lights and a sky-lit ambient cube."""
    g = Gltf("sphere_grid")
    mat = g.material("halflambert_bands", {"shader": "VertexLitGeneric", "$halflambert": 1}, base="sphere_bands.png")
    cols, rows, spacing = 5, 3, 2.4
    g.mesh("sphere_grid", [(sphere_grid_mesh(cols, rows, spacing), mat)])
    add_lights(g, read_lights(os.path.join(SCENES, "sphere_grid.lights")))
    # xmag/ymag: the grid's half extents; the view keeps square pixels (docs/scenes.md)
    g.ortho_camera("front", (0.0, 0.0, 60.0), (0.0, 0.0, 0.0), round(cols * spacing / 2, 6), round(rows * spacing / 2, 6),
                   1.0, 120.0)
    g.write({"camera": 0,
             # sky-lit ambient cube (+X -X +Y -Y +Z -Z): blue from above, warm bounce from below
             "ambient": [{"position": [0, 0, 0], "cube": [[0.10, 0.10, 0.12], [0.08, 0.08, 0.10],
                                                          [0.16, 0.20, 0.30], [0.07, 0.05, 0.04],
                                                          [0.10, 0.10, 0.11], [0.05, 0.05, 0.06]]}],
             "hdr": {"path": "integer", "tone_map_scale": 0.6}})


def chart_colour(u, t):
    """The colour chart (display values 0..1): hue along u; down the chart (t = 0 at the top) full
    saturation from value 1 to 0.4, then saturation 1 to 0.3 while value rises to 0.8 (t < 0.8),
    then a grey ramp along u."""
    if t >= 0.8:
        return (u, u, u)
    sat = 1.0 if t < 0.4 else 1.0 - (t - 0.4) / 0.4 * 0.7
    val = 1.0 - t * 1.5 if t < 0.4 else 0.4 + (t - 0.4)
    h6 = u * 6.0
    i, f = int(h6) % 6, h6 - math.floor(h6)
    p, q, r = val * (1 - sat), val * (1 - sat * f), val * (1 - sat * (1 - f))
    return [(val, r, p), (q, val, p), (p, val, r), (p, q, val), (r, p, val), (val, p, q)][i]


def probe_chart():
    """The colour-correction demo and bench frame: in the bottom third a colour chart drawn as it
    is stored (a self-illuminated quad, tint 1, no light on it: the shader outputs the texture);
    above it mirror spheres reflecting two real HDR probes through $envmap (Grace Cathedral, and
    Uffizi; each probe's scale takes its log-average luminance to 0.18), a third sphere showing
    Grace three stops darker, before a diffuse wall lit by Grace's ambient cube. Orthographic
    camera, square view, integer path at tone-map scale 1."""
    g = Gltf("probe_chart")
    W, H = 384, 128
    write_png(os.path.join(TEX, "color_chart.png"), W, H,
              image(W, H, lambda x, y: tuple(255 * c for c in chart_colour((x + 0.5) / W, y / (H - 1)))), 3)
    M = "VertexLitGeneric"
    chart = g.material("colour_chart", {"shader": M, "$selfillum": 1}, base="color_chart.png", clamp=True)
    wall = g.material("wall", {"shader": M, "$halflambert": 1}, color=(0.6, 0.6, 0.6, 1))

    def mirror(name, probe, scale):
        return g.material(name, {"shader": M, "$phong": 1, "$phongboost": 0, "$envmap": 1, "probe": probe,
                                 "$envmapscale": scale}, color=(0, 0, 0, 1))

    grace, uffizi, grace_dark = mirror("mirror_grace", 0, 1.0), mirror("mirror_uffizi", 1, 1.0), \
        mirror("mirror_grace_3_stops_down", 0, 0.125)
    third = round(1 / 3, 6)
    g.mesh("chart", [(quad([-1, -1, 0], [2, 0, 0], [0, 2 * third, 0]), chart)])
    g.mesh("wall", [(quad([-1.5, -1.5, -1.5], [3, 0, 0], [0, 3, 0]), wall)])
    ball = g.primitive(uv_sphere(1.0, 64, 32), grace)
    # the upper two thirds: a sphere of radius 2/3 on the left, two of 1/3 stacked on the right
    g.instance("ball_grace", ball, grace, translation=[-third, third, 0.0], scale=[2 * third] * 3)
    g.instance("ball_uffizi", ball, uffizi, translation=[2 * third, 2 * third, 0.0], scale=[third] * 3)
    g.instance("ball_grace_dark", ball, grace_dark, translation=[2 * third, 0.0, 0.0], scale=[third] * 3)
    g.ortho_camera("front", (0.0, 0.0, 60.0), (0.0, 0.0, 0.0), 1.0, 1.0, 1.0, 120.0)
    probes = "../../shared/data/probes/"
    g.write({"camera": 0,
             # scales: 0.18 / exp(mean log(1e-4 + Rec. 709 luminance)) over each probe's texels
             "probes": [{"name": "grace", "position": [0, 0, 0], "image": probes + "grace.hdr", "scale": 6.2816,
                         "size": 128},
                        {"name": "uffizi", "position": [0, 0, 0], "image": probes + "uffizi.hdr", "scale": 0.6452,
                         "size": 128}],
             # the wall takes Grace's irradiance; the chart the black cube next to it (no light at all)
             "ambient": [{"position": [0, 0, -1.5], "from_probe": 0},
                         {"position": [0, -2 * third, 0], "cube": [[0, 0, 0]] * 6}],
             "hdr": {"path": "integer", "tone_map_scale": 1.0}})


def large_hall():
    """A scene of real size for the large-scene bench (glue/bench/large_scene.cpp): a hall of world
    faces (floor, ceiling, walls, a row of pillars), 400 model instances (one glTF node per copy of
    three meshes: the geometry is written once and shared), 48 lights (point and spot lamps in a grid
    under the ceiling), four probes and a grid of ambient samples. Direct light only (bounces 0) at a
    modest luxel density, so that it bakes and renders in seconds. The first N nodes in file order
    are spread over the whole hall, so that the bench's subsets (its first 40 / 160 models) cover it."""
    g = Gltf("large_hall")
    W = "LightmappedGeneric"
    floor = g.material("hall_floor", {"shader": W}, base="tiles.png", normal="tiles_normal.png")
    wall = g.material("hall_wall", {"shader": W}, base="brick.png", normal="brick_normal.png")
    ceiling = g.material("hall_ceiling", {"shader": W}, base="plaster.png")
    X, Y, Z = 20.0, 6.0, 20.0
    g.mesh("floor", [(quad([-X, 0, Z], [2 * X, 0, 0], [0, 0, -2 * Z], X / 2, Z / 2), floor)])
    g.mesh("ceiling", [(quad([-X, Y, -Z], [2 * X, 0, 0], [0, 0, 2 * Z], X / 2, Z / 2), ceiling)])
    g.mesh("wall_back", [(quad([-X, 0, -Z], [2 * X, 0, 0], [0, Y, 0], X / 2, Y / 2), wall)])
    g.mesh("wall_front", [(quad([X, 0, Z], [-2 * X, 0, 0], [0, Y, 0], X / 2, Y / 2), wall)])
    g.mesh("wall_left", [(quad([-X, 0, Z], [0, 0, -2 * Z], [0, Y, 0], Z / 2, Y / 2), wall)])
    g.mesh("wall_right", [(quad([X, 0, -Z], [0, 0, 2 * Z], [0, Y, 0], Z / 2, Y / 2), wall)])
    for i in range(4):
        for j in range(2):
            g.mesh("pillar_%d_%d" % (i, j),
                   [(q, wall) for q in box_quads((-15.0 + 10.0 * i, 0.0, -8.0 + 16.0 * j), (1.0, Y, 1.0), 0.5)])
    plain = g.material("hall_plain", {"shader": "VertexLitGeneric", "$halflambert": 0}, color=(0.7, 0.7, 0.72, 1))
    checker = g.material("hall_checker", {"shader": "VertexLitGeneric", "$halflambert": 1}, base="checker.png")
    skin = g.material("hall_skin", {"shader": "VertexLitGeneric", "$phong": 1, "$phongboost": 2.0,
                                    "$phongexponenttexture": g.tex("skin_exponent.png"), "$phongexponentfactor": 60,
                                    "$phongfresnelranges": [0.3, 0.6, 1.0], "$rimlight": 1,
                                    "$rimlightexponent": 4, "$rimlightboost": 2.0, "$rimmask": 1},
                      base="skin.png", normal="skin_normal.png")
    meshes = []
    for name, geo, mat in (("hall_sphere_plain", uv_sphere(0.5, 32, 16), plain),
                           ("hall_sphere_checker", uv_sphere(0.5, 32, 16), checker),
                           ("hall_torus_skin", torus(0.45, 0.18, 32, 16), skin)):
        g.doc["meshes"].append({"name": name, "primitives": [g.primitive(geo, mat)]})
        meshes.append(len(g.doc["meshes"]) - 1)
    # 400 models on a 20 x 20 grid 1.8 apart, visited in a bit-reversed order (any first N spread).
    cells = [(i, j) for i in range(20) for j in range(20)]
    def rev(k):
        return int(format(k, "09b")[::-1], 2)
    order = sorted(range(400), key=lambda k: rev(k))
    for n, k in enumerate(order):
        i, j = cells[k]
        g.node({"name": "model_%03d" % n, "mesh": meshes[k % 3],
                "translation": [-17.1 + 1.8 * i, 0.6 + 0.4 * ((i + j) % 3), -17.1 + 1.8 * j]})
    # 48 lights: a 8 x 6 grid of lamps under the ceiling, every third a spot pointing down.
    for i in range(8):
        for j in range(6):
            pos = (-17.5 + 5.0 * i, 5.0, -16.0 + 6.4 * j)
            col = (1.0, 0.85 + 0.02 * j, 0.7 + 0.04 * i)
            src = {"constant": 0, "linear": 0, "quadratic": 1}
            if (i + j) % 3 == 0:
                src["exponent"] = 1
                g.light("spot_%d_%d" % (i, j), "spot", col, 12.0, pos, (pos[0], 0.0, pos[2] + 0.01), 0.4, 0.8, src)
            else:
                g.light("lamp_%d_%d" % (i, j), "point", col, 6.0, pos, source=src)
    g.camera("overview", (0.0, 4.5, 19.0), (0.0, 0.3, -4.0), 1.1)
    grace = "../../shared/data/probes/grace.hdr"
    probes = [{"name": "probe_%d" % k, "position": [(-10.0 if k % 2 == 0 else 10.0), 2.0,
                                                    (-10.0 if k < 2 else 10.0)],
               "image": grace, "scale": 0.3 + 0.1 * k, "size": 16} for k in range(4)]
    ambient = [{"position": [-12.0 + 8.0 * i, 1.0, -12.0 + 8.0 * j],
                "cube": [[0.05 + 0.01 * i, 0.05, 0.06], [0.04, 0.04, 0.05 + 0.01 * j], [0.08, 0.09, 0.11],
                         [0.03, 0.025, 0.02], [0.05, 0.05, 0.055], [0.04, 0.04, 0.045]]}
               for i in range(4) for j in range(4)]
    g.write({"camera": 0, "probes": probes, "ambient": ambient,
             "lightmaps": {"luxels_per_unit": 1, "encoding": "rgbe", "page": [512, 512], "bounces": 0},
             "hdr": {"path": "integer", "tone_map_scale": 1.0}})
    # The bench's smaller halls: the same file and buffer (large_hall.bin), only the first n models
    # among the scene's root nodes (the other nodes stay in the file, unreferenced).
    for n in (40, 160):
        doc = json.loads(json.dumps(g.doc))
        doc["scenes"][0]["nodes"] = [i for i in doc["scenes"][0]["nodes"]
                                     if not doc["nodes"][i].get("name", "").startswith("model_")
                                     or int(doc["nodes"][i]["name"][6:]) < n]
        with open(os.path.join(SCENES, "large_hall_%d.gltf" % n), "w") as f:
            json.dump(doc, f, indent=1)
            f.write("\n")


def lightmap_charts():
    """Curved LightmappedGeneric meshes carrying their own lightmap UVs (TEXCOORD_1, the glTF
    convention; glue/bake/charts.h) in a room of planar faces charted automatically: a dome (a
    height field, TEXCOORD_1 its plan projection) and a quarter-pipe cove between the floor and the
    back wall (TEXCOORD_1 its unrolled arc), lit by two point lights; the dome shadows the floor."""
    g = Gltf("lightmap_charts")
    W = "LightmappedGeneric"
    plaster = g.material("plaster", {"shader": W}, base="plaster.png")
    brick = g.material("brick", {"shader": W}, base="brick.png", normal="brick_normal.png")
    X, Y, Z, R = 3.0, 2.5, 2.5, 1.0

    def dome(cx, cz, rad, h, rings, seg):  # y = h (1 - r^2 / rad^2)^2 over a disc, TEXCOORD_1 = its plan
        pos, nrm, uv, uv1, tan, bit, idx = [], [], [], [], [], [], []
        for j in range(rings + 1):
            r = rad * j / rings
            q = 1 - r * r / (rad * rad)
            dq = -4 * h * q / (rad * rad)  # dy/dx = dq x, dy/dz = dq z
            for i in range(seg if j else 1):
                ph = 2 * math.pi * i / seg
                x, z = r * math.cos(ph), r * math.sin(ph)
                pos.append([cx + x, h * q * q, cz + z])
                nrm.append(norm([-dq * x, 1.0, -dq * z]))
                uv.append([x + rad, z + rad])
                uv1.append([0.5 + 0.5 * x / rad, 0.5 + 0.5 * z / rad])
                tan.append(norm([1.0, dq * x, 0.0]))
                bit.append(norm([0.0, -dq * z, -1.0]))
        for i in range(seg):  # the fan round the top, then the rings' quads
            idx += [0, 1 + (i + 1) % seg, 1 + i]
        for j in range(1, rings):
            a0, b0 = 1 + (j - 1) * seg, 1 + j * seg
            for i in range(seg):
                i1 = (i + 1) % seg
                idx += [a0 + i, a0 + i1, b0 + i1, a0 + i, b0 + i1, b0 + i]
        return fix_winding_and_tangents(dict(pos=pos, nrm=nrm, uv=uv, uv1=uv1, tan=tan, bit=bit, idx=idx))

    def cove(seg):  # a quarter cylinder of radius R along x, centre (., R, -Z + R), facing the room
        L = 2 * X
        arc = math.pi / 2 * R
        pos, nrm, uv, uv1, tan, bit, idx = [], [], [], [], [], [], []
        for j in range(seg + 1):
            th = math.pi / 2 * j / seg  # 0: the floor's edge, pi/2: the wall's
            n = [0.0, math.cos(th), math.sin(th)]
            for i in range(2):
                x = -X + L * i
                pos.append([x, R - R * math.cos(th), -Z + R - R * math.sin(th)])
                nrm.append(n)
                uv.append([i * L / 2, arc * j / seg / 2])
                uv1.append([i, arc * j / seg / L])  # the unrolled arc at the same scale as the length
                tan.append([1.0, 0.0, 0.0])
                bit.append([0.0, -math.sin(th), math.cos(th)])
        for j in range(seg):
            a, b = 2 * j, 2 * (j + 1)
            idx += [a, a + 1, b + 1, a, b + 1, b]
        return fix_winding_and_tangents(dict(pos=pos, nrm=nrm, uv=uv, uv1=uv1, tan=tan, bit=bit, idx=idx))

    g.mesh("floor", [(quad([-X, 0, Z], [2 * X, 0, 0], [0, 0, -(2 * Z - R)], X, Z), plaster)])
    g.mesh("wall_back", [(quad([-X, R, -Z], [2 * X, 0, 0], [0, Y - R, 0], X, (Y - R) / 2), brick)])
    g.mesh("wall_left", [(quad([-X, 0, Z], [0, 0, -2 * Z], [0, Y, 0], Z, Y / 2), brick)])
    g.mesh("wall_right", [(quad([X, 0, -Z], [0, 0, 2 * Z], [0, Y, 0], Z, Y / 2), brick)])
    g.mesh("dome", [(dome(0.4, 0.3, 1.2, 0.7, 8, 32), plaster)])
    g.mesh("cove", [(cove(12), brick)])
    g.light("lamp_warm", "point", (1.0, 0.85, 0.65), 5.0, (-1.2, 2.1, 0.9))
    g.light("lamp_cool", "point", (0.7, 0.8, 1.0), 3.0, (2.0, 1.4, -1.2))
    g.camera("room_view", (1.6, 1.6, 2.4), (-0.6, 0.5, -2.0), 1.0)
    g.write({"camera": 0, "lightmaps": {"luxels_per_unit": 8, "encoding": "rgbe", "page": [512, 256]},
             "hdr": {"path": "integer", "tone_map_scale": 1.0}})
    # The same scene and buffer on pages of 256 x 128: the faces fill two pages (each its own texture).
    doc = json.loads(json.dumps(g.doc))
    doc["extras"]["tiershade"]["lightmaps"]["page"] = [256, 128]
    with open(os.path.join(SCENES, "lightmap_charts_pages.gltf"), "w") as f:
        json.dump(doc, f, indent=1)
        f.write("\n")


if __name__ == "__main__":
    make_textures()
    model_lighting()
    world_lighting()
    hdr_atrium()
    sphere_grid()
    phong_sphere()
    hdr_scenes()
    probe_chart()
    large_hall()
    lightmap_charts()
    print("wrote scenes/model_lighting.gltf, world_lighting.gltf, hdr_atrium.gltf, sphere_grid.gltf, "
          "phong_sphere.gltf, hdr_daylight.gltf, hdr_dark_room.gltf, probe_chart.gltf, large_hall.gltf")
