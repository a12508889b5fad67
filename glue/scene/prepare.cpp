// tiershade scene: prepares a scene's draws (glue/scene/prepare.h): camera, per-draw shared
// slots and textures, the world bake (glue/bake/world_bake.h) and the probe cube maps, all
// limited to what the selected variants use. Host geometry in double with GLM.
#include "scene/prepare.h"
#include "gl/mipmaps.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstring>
#include <map>
#include <memory>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "bake/ray_scene.h"
#include "bake/world_bake.h"
#include "scene/bake_inputs.h"
#include "scene/probe_render.h"
#include "scene/scene_probes.h"
#include "scene/draw_geometry.h"
#include "scene/scene_volume.h"
#include "scene/textures.h"
#include "twins/model_lighting.h"
#include "scene/camera_ortho.h"
#include "twins/world_lighting.h"
#include "base/srgb.h"

namespace {

using Clock = std::chrono::steady_clock;

glm::dvec3 d3(const double *p) { return glm::make_vec3(p); }
glm::dvec3 d3f(const float *p) { return glm::dvec3(p[0], p[1], p[2]); }
glm::dvec3 d3(ts_vec3d v) { return glm::dvec3(v.x, v.y, v.z); }
double length2(const glm::dvec3 &v) { return glm::dot(v, v); }

// View (right-handed, camera looks down -Z) and projection (OpenGL clip space, glTF's
// perspective: infinite when zfar is 0; glTF 2.0, 3.10.3), in double.
glm::dmat4 camera_matrix(const SceneCamera &c, double aspect) {
  // lookAt from the origin along forward, then the eye's translation: lookAt(eye, eye + forward)
  // would round eye + forward - eye.
  const glm::dmat4 view =
      glm::lookAtRH(glm::dvec3(0.0), d3(c.forward), d3(c.up)) * glm::translate(glm::dmat4(1.0), -d3(c.eye));
  const glm::dmat4 proj = c.zfar > 0 ? glm::perspectiveRH_NO(c.yfov, aspect, c.znear, c.zfar)
                                     : glm::infinitePerspectiveRH(c.yfov, aspect, c.znear);
  return proj * view;
}

float srgb_to_linear(float c) { return static_cast<float>(srgb_decode<double>(c)); }

TextureDesc black_cube() {
  TextureDesc t;
  t.sampler = "u_envmap";
  t.kind = TexKind::Cube;
  t.w = t.h = 1;
  t.rgba.assign(24, 0.f);
  for (int f = 0; f < 6; ++f) t.rgba[f * 4 + 3] = 1.f;
  return t;
}

TextureDesc solid(const char *sampler, float r, float g, float b, float a) {
  TextureDesc t;
  t.sampler = sampler;
  t.w = t.h = 1;
  t.rgba = {r, g, b, a};
  return t;
}

// An image as a texture: colour images are sRGB-decoded and multiplied by a factor.
// With the sampler's mipmap filter (a material texture the shaders sample at the surface's uv;
// glue/gl/mipmaps.h), its chain: mips kMipNone for the light warp ramp, which is indexed by
// lighting and stays one level, as do lightmaps.
enum MipUse { kMipNone, kMipColor, kMipNormal };
TextureDesc image_texture(const Scene &s, const SceneTextureRef &ref, const char *sampler, bool srgb,
                          const float factor[4], MipUse mips) {
  const SceneImage &im = s.images.at(ref.image);
  TextureDesc t;
  t.sampler = sampler;
  t.w = im.w;
  t.h = im.h;
  t.linear = ref.linear;
  t.repeat = ref.repeat;
  t.rgba = im.rgba;
  for (size_t i = 0; i < t.rgba.size(); i += 4)
    for (int c = 0; c < 4; ++c) {
      float v = t.rgba[i + c];
      if (srgb && c < 3) v = srgb_to_linear(v);
      if (factor) v *= factor[c];
      t.rgba[i + c] = v;
    }
  if (ref.mip != 0 && mips != kMipNone) {
    build_mip_chain(&t, mips == kMipNormal ? MipContent::NormalMap : MipContent::Color);
    if (!t.mips.empty()) t.mip_filter = ref.mip;
  }
  return t;
}

ts_vec4f v4(float x, float y, float z, float w) { return ts_v4f(x, y, z, w); }

// Every texture once: draws that sample the same image the same way share one entry.
struct TexturePool {
  std::vector<TextureDesc> *out;
  std::map<std::string, int> index;
  bool mipmaps = true;  // PrepareOptions::mipmaps
  template <class Make>
  int get(const std::string &key, Make make) {
    auto it = index.find(key);
    if (it != index.end()) return it->second;
    out->push_back(make());
    if (!mipmaps) out->back().mips.clear(), out->back().mip_filter = 0;
    const int i = static_cast<int>(out->size()) - 1;
    index[key] = i;
    return i;
  }
};
std::string key_of(const char *sampler, const SceneTextureRef &r, bool srgb, const float *factor) {
  std::string k = std::string(sampler) + "|" + std::to_string(r.image) + "|" + (r.linear ? "L" : "N") +
      (r.repeat ? "R" : "C") + (srgb ? "s" : "l") + "m" + std::to_string(r.mip);
  if (factor)
    for (int c = 0; c < 4; ++c) k += "|" + std::to_string(factor[c]);
  return k;
}
std::string key_solid(const char *sampler, float r, float g, float b, float a) {
  return std::string(sampler) + "|solid|" + std::to_string(r) + "," + std::to_string(g) + "," + std::to_string(b) +
      "," + std::to_string(a);
}

// The index of the item (a probe, an ambient sample: anything with a `position`) nearest c, the
// lowest index on a tie; -1 for none.
template <class T>
int nearest_of(const std::vector<T> &items, const double c[3]) {
  int best = -1;
  double bd = 0;
  for (size_t i = 0; i < items.size(); ++i) {
    const double dd = length2(d3(items[i].position) - d3(c));
    if (best < 0 || dd < bd) {
      best = static_cast<int>(i);
      bd = dd;
    }
  }
  return best;
}

bool model_draw(const Scene &s, const PreparedScene &ps, const SceneDrawChoice &c, Tier tier, SceneProbeSet *probes, Api api,
                TexturePool *pool, DrawGeometryCache *geo, PreparedDraw *d, std::string *err) {
  const ScenePrimitive &p = s.primitives[c.primitive];
  const SceneMaterial &m = s.materials[p.material];
  const Variant &v = *c.variant;
  const SceneInstance *inst = p.instance >= 0 ? &s.instances.at(p.instance) : nullptr;
  double center[3];
  if (inst) {
    for (int k = 0; k < 3; ++k) center[k] = inst->center[k];
  } else {
    primitive_center(s, p, center);
  }
  d->shared.assign(ML_SLOTS, v4(0, 0, 0, 0));
  // Ambient cube: the nearest sample of the irradiance volume (Source: the model's leaf).
  float cube[6][3] = {};
  const int best = nearest_of(s.ambient, center);
  if (best >= 0) {
    const SceneAmbientSample &a = s.ambient[best];
    if (a.from_probe >= 0) {
      if (!probes->cube(a.from_probe, nullptr, cube, err)) return false;
    } else {
      for (int f = 0; f < 6; ++f)
        for (int k = 0; k < 3; ++k) cube[f][k] = a.cube[f][k];
    }
  } else if (!ps.volume.cube.empty()) {
    scene_volume_cube(s, ps.volume, center, cube);  // no hand-typed samples: the baked irradiance volume
  }
  std::memcpy(d->ambient, cube, sizeof cube);
  // Lights: the tier's limit per pixel, the rest folded into the cube (docs/light_folding.md).
  std::vector<ts_light> lights;
  for (const SceneLight &l : s.lights) lights.push_back(l.light);
  const int max_local = max_local_lights(tier);
  std::vector<int> kept(lights.size() + 1);
  const float cf[3] = {static_cast<float>(center[0]), static_cast<float>(center[1]), static_cast<float>(center[2])};
  const int half = v.value("HALF_LAMBERT");
  const int nk = lights.empty()
      ? 0
      : ts_fold_lights(lights.data(), static_cast<int>(lights.size()), max_local, cf, half, cube, kept.data());
  for (int f = 0; f < 6; ++f) d->shared[ML_SLOT_AMBIENT + f] = v4(cube[f][0], cube[f][1], cube[f][2], 0);
  d->shared[ML_SLOT_PARAMS] = v4(ps.tone_map_scale, static_cast<float>(nk), 0, 0);
  d->shared[ML_SLOT_ALBEDO] = v4(m.base_color[0], m.base_color[1], m.base_color[2], m.base_color[3]);
  for (int i = 0; i < nk; ++i) {
    float packed[5][4];
    char msg[200];
    if (!ts_light_pack(&lights[kept[i]], packed, msg, sizeof msg)) {
      *err = s.path + ": " + s.lights[kept[i]].name + ": " + msg;
      return false;
    }
    for (int k = 0; k < 5; ++k)
      d->shared[ML_SLOT_LIGHT0 + 5 * i + k] = v4(packed[k][0], packed[k][1], packed[k][2], packed[k][3]);
  }
  d->shared[ML_SLOT_EYE] = v4(ps.eye[0], ps.eye[1], ps.eye[2], 1);
  // A $selfillum material without $phong runs the Phong path with the specular term off.
  const float boost = m.phong ? m.phong_boost : 0.f;
  d->shared[ML_SLOT_PHONG] = v4(m.phong_exponent, m.phong_exponent_factor, boost, m.base_alpha_phong_mask ? 1.f : 0.f);
  const float *fr = m.phong_fresnel_ranges;
  d->shared[ML_SLOT_FRESNEL] = v4((fr[1] - fr[0]) * 2, fr[1], (fr[2] - fr[1]) * 2, m.invert_phong_mask ? 1.f : 0.f);
  d->shared[ML_SLOT_PHONG_TINT] =
      v4(m.phong_tint[0], m.phong_tint[1], m.phong_tint[2], m.phong_albedo_tint ? 1.f : 0.f);
  // Features the material does not use contribute nothing (they are compiled in only in the
  // all-features baseline): rim boost 0, envmap scale 0.
  d->shared[ML_SLOT_RIM] = v4(m.rim_exponent, m.rim_light ? m.rim_boost : 0.f, m.rim_mask, 0);
  d->shared[ML_SLOT_ENVMAP] = v4(m.envmap ? m.envmap_scale : 0.f, m.envmap_fresnel, 0, 0);
  d->shared[ML_SLOT_ENVMAP_TINT] = v4(m.envmap_tint[0], m.envmap_tint[1], m.envmap_tint[2], 0);
  d->shared[ML_SLOT_SELF_ILLUM] =
      v4(m.self_illum_tint[0], m.self_illum_tint[1], m.self_illum_tint[2], m.self_illum ? 1.f : 0.f);
  // Textures: only what the variant samples is real; the others are 1x1 placeholders.
  d->tex.clear();
  if (v.value("ALBEDO_TEXTURE")) {
    if (m.base_texture.image >= 0)
      d->tex.push_back(pool->get(key_of("u_albedo", m.base_texture, true, m.base_color),
                                 [&] { return image_texture(s, m.base_texture, "u_albedo", true, m.base_color, kMipColor); }));
    else
      d->tex.push_back(pool->get(
          key_solid("u_albedo", m.base_color[0], m.base_color[1], m.base_color[2], m.base_color[3]),
          [&] { return solid("u_albedo", m.base_color[0], m.base_color[1], m.base_color[2], m.base_color[3]); }));
  } else {
    d->tex.push_back(pool->get(key_solid("u_albedo", 1, 1, 1, 1), [&] { return solid("u_albedo", 1, 1, 1, 1); }));
  }
  const bool phong = v.value("PHONG") != 0;
  if (phong && m.normal_texture.image >= 0)
    d->tex.push_back(pool->get(key_of("u_normal_map", m.normal_texture, false, nullptr),
                               [&] { return image_texture(s, m.normal_texture, "u_normal_map", false, nullptr, kMipNormal); }));
  else
    d->tex.push_back(pool->get(key_solid("u_normal_map", 0.5f, 0.5f, 1.f, 1.f),
                               [&] { return solid("u_normal_map", 0.5f, 0.5f, 1.f, 1.f); }));
  if (v.value("PHONG_EXPONENT_MAP") && m.phong_exponent_texture.image >= 0)
    d->tex.push_back(pool->get(key_of("u_exponent_map", m.phong_exponent_texture, false, nullptr), [&] {
      return image_texture(s, m.phong_exponent_texture, "u_exponent_map", false, nullptr, kMipColor);
    }));
  else
    d->tex.push_back(
        pool->get(key_solid("u_exponent_map", 1, 1, 1, 1), [&] { return solid("u_exponent_map", 1, 1, 1, 1); }));
  if (v.value("LIGHT_WARP") && m.light_warp_texture.image >= 0)
    d->tex.push_back(pool->get(key_of("u_light_warp", m.light_warp_texture, false, nullptr),
                               [&] { return image_texture(s, m.light_warp_texture, "u_light_warp", false, nullptr, kMipNone); }));
  else
    d->tex.push_back(pool->get("u_light_warp|identity", [&] {
      // An identity ramp (value = u), for a LIGHT_WARP variant whose material has no ramp.
      TextureDesc t = solid("u_light_warp", 1, 1, 1, 1);
      t.w = 256;
      t.linear = true;
      t.rgba.resize(256 * 4);
      for (int i = 0; i < 256; ++i)
        for (int c = 0; c < 4; ++c) t.rgba[i * 4 + c] = c < 3 ? (i + 0.5f) / 256.f : 1.f;
      return t;
    }));
  int pi = -1;
  if (v.value("ENVMAP") && !s.probes.empty()) {
    pi = m.probe >= 0 ? m.probe : nearest_of(s.probes, center);  // a model moves: the nearest probe
    if (!probes->cube(pi, nullptr, nullptr, err)) return false;
  }
  d->tex.push_back(pool->get("u_envmap|" + std::to_string(pi), [&] {
    TextureDesc env = black_cube();
    if (pi >= 0) {
      probes->cube(pi, &env, nullptr, nullptr);
      if (api != Api::GL33) env.linear = false;  // GLES cube maps are always seamless
    }
    return env;
  }));
  d->display_encoded = v.value("OUTPUT_MODE") != 0;
  geo->set(p, d);
  return true;
}

}  // namespace

void set_scene_tone_map_scale(PreparedScene *p, float scale) {
  p->tone_map_scale = scale;
  for (PreparedDraw &d : p->draws) {
    if (d.world)
      d.shared[WL_SLOT_TINT_SCALE].w = scale;
    else
      d.shared[ML_SLOT_PARAMS].x = scale;
  }
  skybox_set_tone_map_scale(&p->sky, scale);
}

bool prepare_scene(const Scene &s, const SceneSelection &sel, int w, int h, Api api, float tone_map_scale,
                   PreparedScene *out, std::string *err, const PrepareOptions &opt) {
  PreparedScene ps;
  ps.w = w;
  ps.h = h;
  ps.tone_map_scale = sel.hdr_path == "float" ? 1.f : tone_map_scale;
  if (s.cameras.empty() || s.camera < 0 || s.camera >= static_cast<int>(s.cameras.size())) {
    *err = s.path + ": no camera to render from";
    return false;
  }
  const SceneCamera &cam = s.cameras[s.camera];
  // The output's aspect: a glTF aspectRatio that differs would stretch the picture.
  double vp[16];
  if (cam.orthographic) {
    ortho_view_projection(cam, static_cast<double>(w) / h, vp);
  } else {
    const glm::dmat4 vpm = camera_matrix(cam, static_cast<double>(w) / h);
    std::memcpy(vp, glm::value_ptr(vpm), sizeof vp);  // column-major, as GL takes it
  }
  for (int i = 0; i < 16; ++i) ps.view_proj[i] = static_cast<float>(vp[i]);
  for (int k = 0; k < 3; ++k) ps.eye[k] = static_cast<float>(cam.eye[k]);
  const Tier tier = sel.variants.empty() ? Tier::SM3 : sel.variants[0].tier;
  SceneProbeSet probes(s);
  TexturePool pool{&ps.textures, {}, opt.mipmaps};
  DrawGeometryCache geometry;

  // World: faces from the World primitives, baked only if some draw is a world draw.
  WorldBakeInput ws;
  std::vector<int> face_of_draw(sel.draws.size(), -1);
  std::vector<std::array<double, 4>> face_frame;  // min a, min b (projection offsets)
  std::vector<int> world_probe_index(s.probes.size(), -1);
  std::vector<std::string> face_where;  // each face's primitive, for the bake directory
  std::string quality_note;  // the bake's quality (scene/bake_inputs.h: a bake directory's own)
  const BakeQuality quality = scene_bake_quality(s, &quality_note);
  for (size_t di = 0; di < sel.draws.size(); ++di) {
    const SceneDrawChoice &c = sel.draws[di];
    if (c.family != "world_lighting") continue;
    const ScenePrimitive &p = s.primitives[c.primitive];
    const SceneMaterial &m = s.materials[p.material];
    if (p.indices.size() < 3) continue;
    WorldFace f{};
    double frame_min[2];
    if (!p.uv1.empty()) {  // TEXCOORD_1: the mesh's own lightmap chart (glue/bake/charts.h)
      if (!world_face_from_chart(p.position, p.normal, p.tangent, p.uv1, p.indices, m.name.c_str(), m.probe,
                                 quality.luxels_per_unit, p.where, &f, err)) {
        *err = s.path + ": " + *err;
        return false;
      }
      frame_min[0] = frame_min[1] = 0;
    } else if (!world_face_from_quad(p.position, p.normal, p.tangent, p.indices, m.name.c_str(), m.probe, &f,
                                     frame_min)) {
      *err = s.path + ": " + p.where + ": a world primitive whose first triangle and normal are degenerate";
      return false;
    }
    // What the face gives the bounces: its reflectivity (the base colour times its texture's mean, as
    // vrad takes a texture's reflectivity) and its emission (the glTF emissive terms; docs/baking.md).
    const glm::dvec3 base = d3f(m.base_color) * texture_mean_linear(s, m.base_texture);
    const glm::dvec3 emit = d3f(m.emission) * texture_mean_linear(s, m.emissive_texture);
    f.reflectivity = ts_v3d(base.x, base.y, base.z);
    f.emission = ts_v3d(emit.x, emit.y, emit.z);
    f.bumped = m.normal_texture.image >= 0;  // BUMPMAP 0 samples the flat lightmap alone
    face_where.push_back(p.where);
    face_of_draw[di] = static_cast<int>(ws.faces.size());
    ws.faces.push_back(f);
    face_frame.push_back({frame_min[0], frame_min[1], 0, 0});
  }
  WorldBake bake;
  std::unique_ptr<RayScene> rays;  // every triangle of the scene: the bake's visibility, the probes' sight
  if (!ws.faces.empty()) {
    const auto t0 = Clock::now();
    const double cpu0 = process_cpu_ms();
    bake_lights_of(s, &ws);  // the lights and the suns' spread (glue/scene/bake_inputs.h)
    if (s.sky.image >= 0) {  // the sky pass (glue/bake/sky.h)
      const SceneImage &si = s.images.at(static_cast<size_t>(s.sky.image));
      ws.sky = BakeSky{si.rgba.data(), si.w, si.h, s.sky.scale};
    }
    int cube_size = 16;
    for (size_t i = 0; i < s.probes.size(); ++i) {
      if (s.probes[i].image >= 0) continue;
      world_probe_index[i] = static_cast<int>(ws.probes.size());
      ws.trace_cube.push_back(probe_traced(s, static_cast<int>(i)));  // else rendered (scene/probe_render.h)
      ws.probes.push_back(ts_v3d(s.probes[i].position[0], s.probes[i].position[1], s.probes[i].position[2]));
      cube_size = std::max(cube_size, s.probes[i].size);
    }
    if (ws.probes.empty()) ws.probes.push_back(ts_v3d(0, 0, 0)), ws.trace_cube.push_back(0);  // bake_world picks one per face
    for (WorldFace &f : ws.faces)
      if (f.probe >= 0) f.probe = world_probe_index.at(f.probe) >= 0 ? world_probe_index[f.probe] : -1;
    apply_bake_quality(quality, &ws);  // density, samples, bounces (and the sky's samples)
    ws.page_w = s.lightmaps.page_w, ws.page_h = s.lightmaps.page_h, ws.cube_size = cube_size;
    ws.bounce.seed = static_cast<uint64_t>(s.lightmaps.seed);
    ws.bounce.threads = s.lightmaps.threads;  // the same bytes for any count
    const bool from_file = !s.lightmaps.image_rgba.empty();
    if (from_file) ws.page_in = &s.lightmaps.image_rgba;
    // Visibility: one BVH of every triangle of the scene, world and model (glue/bake/ray_scene.h).
    // Emissive model primitives light the faces as area lights (glue/bake/area_lights.h).
    std::vector<int> emitter_of;
    ws.model_emitters = scene_model_emitters(s, face_of_draw, &emitter_of);
    rays.reset(new RayScene);
    if (!build_scene_rays(s, face_of_draw, rays.get(), err, &emitter_of)) return false;
    ws.rays = rays.get();
    const BakeDirUse use{s.lightmaps.bake, s.lightmaps.bake_checkpoint, s.lightmaps.bake_progress};
    if (!bake_world_dir(use, ws, face_where, &bake, &ps.bake_summary, err)) {
      *err = s.path + (s.lightmaps.image.empty() ? std::string(": lightmap bake: ")
                                                  : ": extras.tiershade.lightmaps.image " + s.lightmaps.image +
                                                        ": the page cannot hold the scene's faces: ") + *err;
      return false;
    }
    ps.bake_summary.quality = quality;
    if (!quality_note.empty()) ps.notes.push_back(quality_note);  // a render says so
    // A page from the scene's lightmaps.image: the placement above is its layout (the same
    // faces, density and page size as the bake that wrote it; docs/scenes.md).
    ps.lightmap_page = bake.page;
    ps.lightmap_places = bake.place;
    ps.lightmap_w = ws.page_w;
    ps.lightmap_h = ws.page_h * bake.pages;  // the pages stacked (c_ref/offline/lightmap_page.h)
    ps.lightmap_pages = bake.pages;
    probes.have_world = true;
    probes.traced.assign(s.probes.size(), TextureDesc());
    for (size_t i = 0; i < s.probes.size(); ++i)
      if (world_probe_index[i] >= 0) probes.traced[i] = bake.cubes.at(world_probe_index[i]);
    ps.lightmap_texels = ws.page_w * ws.page_h;
    ps.bake_ms = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
    ps.bake_cpu_ms = process_cpu_ms() - cpu0;
    ps.bake_luxels = bake.luxels;
    ps.bake_gather_rays = bake.bounce.rays;
    ps.bake_passes = bake.bounce.passes;
    ps.bake_direct_ms = bake.direct_ms, ps.bake_bounce_ms = bake.bounce_ms;
    ps.bake_direct_rays = bake.direct_rays;
    ps.bake_sky_rays = bake.sky.rays, ps.bake_area_rays = bake.area.rays;
    ps.bake_sky_ms = bake.sky.ms, ps.bake_area_ms = bake.area.ms, ps.bake_cubes_ms = bake.cubes_ms;
    if (!bake_scene_volume(s, sel, ws.faces, bake, ws.page_w, *rays, &ps.volume, err, &ws.model_emitters)) return false;
  }
  for (size_t di = 0; di < sel.draws.size(); ++di) {
    const SceneDrawChoice &c = sel.draws[di];
    PreparedDraw d;
    d.choice = &c;
    d.variant = c.variant;
    if (c.family == "model_lighting") {
      if (!model_draw(s, ps, c, tier, &probes, api, &pool, &geometry, &d, err)) return false;
      ps.draws.push_back(std::move(d));
      continue;
    }
    d.world = true;
    const ScenePrimitive &p = s.primitives[c.primitive];
    const SceneMaterial &m = s.materials[p.material];
    const Variant &v = *c.variant;
    const int enc = v.value("LIGHTMAP_ENCODING");
    const int code = s.lightmaps.encoding == "float32" ? -1 : s.lightmaps.encoding == "rgbe" ? kPageRgbeToHalf : enc;
    const int fi = face_of_draw[di];
    if (fi < 0) continue;
    const WorldFace &f = ws.faces[fi];
    d.face = fi;
    const double rf[3] = {f.reflectivity.x, f.reflectivity.y, f.reflectivity.z};  // the probe cubes draw
    const double em[3] = {f.emission.x, f.emission.y, f.emission.z};  // emitters with them (probe_render.h)
    for (int k = 0; k < 3; ++k) d.reflectivity[k] = static_cast<float>(rf[k]), d.emission[k] = static_cast<float>(em[k]);
    DrawGeometry g = DrawGeometryCache::copy_of(p);  // world primitives are never shared
    // Per-vertex lightmap coordinates: the face's (a, b) in [0, 1] placed on the page.
    const size_t n = p.position.size() / 3;
    g.lightmap.resize(n * 4);
    const glm::dvec3 t = d3(f.u), b = d3(f.v);
    for (size_t i = 0; f.chart && i < n; ++i) {  // a chart: TEXCOORD_1 on its block, the bake's tangents
      float lm[2];
      lm_page_chart_uv(&bake.place[fi], ws.page_w, ws.page_h, p.uv1[i * 2], p.uv1[i * 2 + 1], lm);
      g.lightmap[i * 4 + 0] = lm[0];
      g.lightmap[i * 4 + 1] = lm[1];
      g.lightmap[i * 4 + 2] = bake.place[fi].offset[0];
      g.lightmap[i * 4 + 3] = bake.place[fi].offset[1];
      for (int k = 0; k < 4; ++k) g.tangent[i * 4 + k] = f.chart->vertex_tangent[i * 4 + k];
    }
    for (size_t i = 0; !f.chart && i < n; ++i) {
      const glm::dvec3 q = d3f(&p.position[i * 3]);
      const double a = (glm::dot(q, t) - face_frame[fi][0]) / f.su, bb = (glm::dot(q, b) - face_frame[fi][1]) / f.sv;
      float lm[2];
      lm_page_uv(&bake.place[fi], ws.page_w, ws.page_h, a, bb, lm);
      g.lightmap[i * 4 + 0] = lm[0];
      g.lightmap[i * 4 + 1] = lm[1];
      g.lightmap[i * 4 + 2] = bake.place[fi].offset[0];
      g.lightmap[i * 4 + 3] = bake.place[fi].offset[1];
      // The face's tangent frame as the baker used it (the shader's binormal = N x T * w).
      g.tangent[i * 4 + 0] = static_cast<float>(t.x);
      g.tangent[i * 4 + 1] = static_cast<float>(t.y);
      g.tangent[i * 4 + 2] = static_cast<float>(t.z);
      const glm::dvec3 nn = d3f(&g.normal[i * 3]);
      g.tangent[i * 4 + 3] = glm::dot(glm::cross(nn, t), b) < 0 ? -1.f : 1.f;
    }
    d.geo = std::make_shared<const DrawGeometry>(std::move(g));
    d.shared.assign(WL_SLOTS, v4(0, 0, 0, 0));
    // c12 = tint x lightmap scale: sqrt3 for bumped lightmaps (docs/world_lighting.md), 1 flat.
    const float lm_scale = v.value("BUMPMAP") ? 1.7320508f : 1.f;
    d.shared[WL_SLOT_TINT_SCALE] = v4(lm_scale, lm_scale, lm_scale, ps.tone_map_scale);
    const float mk = c.mask_constant ? c.mask_value : 1.f;
    d.shared[WL_SLOT_ENV_TINT] =
        v4(m.envmap_tint[0] * mk, m.envmap_tint[1] * mk, m.envmap_tint[2] * mk, m.envmap ? m.envmap_scale : 0.f);
    d.shared[WL_SLOT_ENV_PARAMS] =
        v4(m.envmap_contrast, m.envmap_saturation, 1.f - m.fresnel_reflection, m.fresnel_reflection);
    // Range fog (scene.h SceneFog; the shader's u_fog_color / u_fog_params): density 0 = none.
    const SceneFog &fog = s.fog;
    const double range = fog.end - fog.start;
    d.shared[WL_SLOT_FOG_COLOR] = fog.enabled ? v4(fog.color[0], fog.color[1], fog.color[2], fog.max_density)
                                              : v4(0, 0, 0, 0);
    d.shared[WL_SLOT_FOG_PARAMS] =
        fog.enabled ? v4(static_cast<float>(1.0 / range), static_cast<float>(fog.start / range), 0, 0)
                    : v4(0, 0, 0, 0);
    if (m.base_texture.image >= 0)
      d.tex.push_back(pool.get(key_of("u_base", m.base_texture, true, m.base_color),
                               [&] { return image_texture(s, m.base_texture, "u_base", true, m.base_color, kMipColor); }));
    else
      d.tex.push_back(pool.get(
          key_solid("u_base", m.base_color[0], m.base_color[1], m.base_color[2], m.base_color[3]),
          [&] { return solid("u_base", m.base_color[0], m.base_color[1], m.base_color[2], m.base_color[3]); }));
    if (v.value("BUMPMAP") && m.normal_texture.image >= 0)
      d.tex.push_back(pool.get(key_of("u_normalmap", m.normal_texture, false, nullptr),
                               [&] { return image_texture(s, m.normal_texture, "u_normalmap", false, nullptr, m.ssbump ? kMipColor : kMipNormal); }));
    else
      d.tex.push_back(pool.get(key_solid("u_normalmap", 0.5f, 0.5f, 1.f, 1.f),
                               [&] { return solid("u_normalmap", 0.5f, 0.5f, 1.f, 1.f); }));
    // The face's page (one texture per page and encoding; several pages: each draw binds its own).
    d.lightmap_page = bake.place[fi].page;
    d.tex.push_back(pool.get("u_lightmap|" + std::to_string(enc) + "|" + std::to_string(d.lightmap_page),
                             [&] { return encode_page(ws, bake, code, d.lightmap_page); }));
    if (v.value("ENVMAPMASK") == 1 && m.envmap_mask_texture.image >= 0)
      d.tex.push_back(pool.get(key_of("u_envmap_mask", m.envmap_mask_texture, false, nullptr), [&] {
        return image_texture(s, m.envmap_mask_texture, "u_envmap_mask", false, nullptr, kMipColor);
      }));
    else
      d.tex.push_back(
          pool.get(key_solid("u_envmap_mask", 1, 1, 1, 1), [&] { return solid("u_envmap_mask", 1, 1, 1, 1); }));
    int pi = -1;
    if (v.value("ENVMAP") && !s.probes.empty()) {
      const glm::dvec3 mid = d3(f.origin) + t * (f.su / 2) + b * (f.sv / 2);
      const double fn[3] = {f.normal.x, f.normal.y, f.normal.z};
      pi = best_probe(s, rays.get(), glm::value_ptr(mid), fn, m.probe);  // the nearest in sight
      if (!probes.cube(pi, nullptr, nullptr, err)) return false;
    }
    d.tex.push_back(pool.get("u_envmap|" + std::to_string(pi), [&] {
      TextureDesc env = black_cube();
      if (pi >= 0) {
        probes.cube(pi, &env, nullptr, nullptr);
        if (api != Api::GL33) env.linear = false;
      }
      return env;
    }));
    ps.draws.push_back(std::move(d));
  }
  ps.probes_made = static_cast<int>(probes.cubes.size());
  for (const auto &c : probes.cubes) {  // where each cube comes from; the pending ones rendered below
    const std::string key = "u_envmap|" + std::to_string(c.first);
    if (!pool.index.count(key)) continue;  // only an ambient sample's
    PreparedProbeCube pc;
    pc.probe = c.first;
    pc.texture = pool.index.at(key);
    pc.source = s.probes[c.first].image >= 0 ? "image" : probes.pending.count(c.first) ? "pending" : "rays";
    ps.probe_cubes.push_back(pc);
  }
  if (!prepare_skybox(s, sel.sky, api, &ps, err)) return false;
  if (!opt.gl_probe_cubes && !render_probe_cubes_cpu(s, &ps, opt.threads, err)) return false;
  *out = std::move(ps);
  return true;
}
