// tiershade scene: world probes' cube maps rendered in-engine (glue/scene/probe_render.h).
#include "scene/probe_render.h"

#include <algorithm>
#include <chrono>
#include <cstring>

#include <glm/glm.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "base/cube_faces.h"
#include "offline/lightmap_encoding.h"
#include "scene/cpu_renderer.h"
#include "scene/finite_check.h"
#include "scene/gl_renderer.h"
#include "twins/world_lighting.h"

namespace {

using Clock = std::chrono::steady_clock;
double ms_since(Clock::time_point t0) { return std::chrono::duration<double, std::milli>(Clock::now() - t0).count(); }

void set_value(Variant *v, const char *combo, int value) {
  for (auto &kv : v->values)
    if (kv.first == combo) kv.second = value;
}

bool emits(const PreparedDraw &d) { return d.emission[0] > 0 || d.emission[1] > 0 || d.emission[2] > 0; }

// Face `face`'s texels from a size x size frame (rows bottom-up, as the cube's rows: t grows with y).
void put_face(const ImageF &img, int size, int face, std::vector<float> *rgba) {
  const size_t n = static_cast<size_t>(size) * size;
  for (size_t i = 0; i < n; ++i) {
    float *t = &(*rgba)[(face * n + i) * 4];
    std::memcpy(t, &img.rgba[i * 4], 3 * sizeof(float));
    t[3] = 1.f;
  }
}

// The rendered texels into the probe's cube texture: times its scale, clamped to fp16's range.
bool store_cube(const Scene &s, PreparedScene *ps, PreparedProbeCube *pc, const std::vector<float> &rgba,
                std::string *err) {
  const SceneProbe &pr = s.probes.at(pc->probe);
  TextureDesc &t = ps->textures.at(pc->texture);
  t.w = t.h = pr.size;
  t.rgba = rgba;
  for (size_t i = 0; i < t.rgba.size(); i += 4)
    for (int c = 0; c < 3; ++c) t.rgba[i + c] *= pr.scale;
  return clamp_texels_to_fp16(t.rgba.data(), t.rgba.size(),
                              s.path + ": probes[" + std::to_string(pc->probe) + "] (\"" + pr.name + "\"): its cube map",
                              nullptr, err);
}

std::string made_note(const Scene &s, const ProbeView &v, const PreparedProbeCube &pc) {
  const SceneProbe &pr = s.probes.at(pc.probe);
  char b[400];
  snprintf(b, sizeof b,
           "probe %s: its %d x %d cube map rendered in-engine by the %s from the baked world (%zu world draws%s), "
           "%.1f ms",
           pr.name.c_str(), pr.size, pr.size, pc.source.c_str(), v.p.draws.size(),
           v.p.sky.present() ? ", the sky" : "", pc.ms);
  return b;
}

}  // namespace

bool make_probe_view(const Scene &s, const PreparedScene &ps, ProbeView *v, std::string *err) {
  PreparedScene &p = v->p;
  p = PreparedScene();
  v->variants.clear();
  p.textures = ps.textures;
  p.tone_map_scale = 1.f;
  p.sky = ps.sky;
  skybox_set_tone_map_scale(&p.sky, 1.f);
  // The cube's lightmap pages: the page as the bake holds it (float32), emitters' flat blocks their
  // exitant radiance, stored as fp16 (LIGHTMAP_ENCODING 0; the "float32" scene encoding: unquantised).
  const int pages = std::max(1, ps.lightmap_pages), W = ps.lightmap_w, H = ps.lightmap_h / pages;
  std::vector<float> page = ps.lightmap_page;
  if (page.size() != static_cast<size_t>(W) * H * pages * 4) {
    *err = s.path + ": the probes' renderer has no lightmap page";
    return false;
  }
  for (const PreparedDraw &d : ps.draws) {
    if (!d.world || !emits(d)) continue;
    const lm_face_place &pl = ps.lightmap_places.at(d.face);
    for (int y = pl.y; y < pl.y + pl.block_h; ++y)
      for (int x = pl.x; x < pl.x + pl.block_w; ++x) {
        float *t = &page[(static_cast<size_t>(y) * W + x) * 4];
        for (int c = 0; c < 3; ++c) t[c] = d.emission[c] + d.reflectivity[c] * t[c];
      }
  }
  const bool quantise = s.lightmaps.encoding != "float32";
  std::vector<int> page_tex;
  for (int k = 0; k < pages; ++k) {
    TextureDesc t;
    t.sampler = "u_lightmap";
    t.w = W;
    t.h = H;
    t.linear = true;
    t.rgba.assign(page.begin() + static_cast<size_t>(k) * W * H * 4, page.begin() + static_cast<size_t>(k + 1) * W * H * 4);
    for (size_t i = 0; i < t.rgba.size(); i += 4) {
      for (int c = 0; c < 3 && quantise; ++c) t.rgba[i + c] = ts_half_quantize(t.rgba[i + c]);
      t.rgba[i + 3] = 1.f;
    }
    page_tex.push_back(static_cast<int>(p.textures.size()));
    p.textures.push_back(std::move(t));
  }
  int white = -1;
  for (const PreparedDraw &d : ps.draws) {
    if (!d.world) continue;  // the static world only
    PreparedDraw c = d;
    Variant var = *d.variant;
    set_value(&var, "ENVMAP", 0);
    set_value(&var, "ENVMAPMASK", 0);
    set_value(&var, "LIGHTMAP_ENCODING", 0);
    if (emits(d)) {
      set_value(&var, "BUMPMAP", 0);
      if (white < 0) {
        TextureDesc w;
        w.sampler = "u_base";
        w.w = w.h = 1;
        w.rgba = {1, 1, 1, 1};
        white = static_cast<int>(p.textures.size());
        p.textures.push_back(w);
      }
      c.tex.at(0) = white;
    }
    const std::string name = var.name();
    auto it = std::find_if(v->variants.begin(), v->variants.end(), [&](const Variant &o) { return o.name() == name; });
    if (it == v->variants.end()) it = v->variants.insert(v->variants.end(), var);
    c.variant = &*it;
    // c12 = lightmap scale (sqrt3 bumped, 1 flat; as prepare_scene), tone-map scale 1: linear HDR.
    const float lm = c.variant->value("BUMPMAP") ? 1.7320508f : 1.f;
    c.shared.at(WL_SLOT_TINT_SCALE) = ts_v4f(lm, lm, lm, 1.f);
    c.tex.at(2) = page_tex.at(static_cast<size_t>(d.lightmap_page));
    p.draws.push_back(std::move(c));
  }
  return true;
}

void probe_view_face(ProbeView *v, const double pos[3], int size, int face) {
  PreparedScene &p = v->p;
  glm::dvec3 f, r, u;
  cube_face_axes(face, &f, &r, &u);
  const glm::dvec3 eye(pos[0], pos[1], pos[2]);
  // lookAt(0, forward, up): the camera's x is cross(forward, up) = right, its y up (cube_faces.h).
  const glm::dmat4 view = glm::lookAtRH(glm::dvec3(0.0), f, u) * glm::translate(glm::dmat4(1.0), -eye);
  const glm::dmat4 proj = glm::infinitePerspectiveRH(glm::half_pi<double>(), 1.0, kProbeNear);
  const glm::dmat4 vp = proj * view;
  for (int i = 0; i < 16; ++i) p.view_proj[i] = static_cast<float>(glm::value_ptr(vp)[i]);
  for (int k = 0; k < 3; ++k) p.eye[k] = static_cast<float>(pos[k]);
  p.w = p.h = size;
  if (p.sky.present()) skybox_set_camera(&p.sky, p.view_proj, size, size);
}

void render_probe_cube_cpu(ProbeView *v, const double pos[3], int size, int threads, std::vector<float> *rgba,
                           std::vector<int> *draw) {
  const size_t n = static_cast<size_t>(size) * size;
  rgba->assign(6 * n * 4, 1.f);
  if (draw) draw->assign(6 * n, -1);
  SceneVisibility vis;
  ImageF img;
  for (int face = 0; face < 6; ++face) {
    probe_view_face(v, pos, size, face);
    scene_rasterize_cpu(v->p, &vis, threads);
    scene_shade_cpu(v->p, vis, &img, threads);
    put_face(img, size, face, rgba);
    if (draw) std::copy(vis.draw.begin(), vis.draw.end(), draw->begin() + static_cast<long>(face * n));
  }
}

bool render_probe_cube_gl(ProbeView *v, SceneGl *g, const double pos[3], int size, std::vector<float> *rgba,
                          std::string *err, long *check, std::vector<int> *draws) {
  const size_t n = static_cast<size_t>(size) * size;
  rgba->assign(6 * n * 4, 1.f);
  if (draws) draws->assign(6 * n, -1);
  if (check) *check = 0;
  ImageF img, twin;
  for (int face = 0; face < 6; ++face) {
    probe_view_face(v, pos, size, face);
    g->update(v->p);
    if (!g->frame(&img, err)) return false;
    put_face(img, size, face, rgba);
    if (!check && !draws) continue;
    std::vector<int> draw;
    std::vector<float> slots, grads;
    if (!g->gbuffer(&draw, &slots, err, check ? &grads : nullptr)) return false;
    if (draws) std::copy(draw.begin(), draw.end(), draws->begin() + static_cast<long>(face * n));
    if (!check) continue;
    scene_shade_records(v->p, draw, slots, &twin, 0, &grads);
    for (size_t i = 0; i < static_cast<size_t>(size) * size; ++i)
      *check += std::memcmp(&img.rgba[i * 4], &twin.rgba[i * 4], 3 * sizeof(float)) != 0;
  }
  return true;
}

bool render_probe_cubes_cpu(const Scene &s, PreparedScene *ps, int threads, std::string *err) {
  ProbeView v;
  bool made = false;
  for (PreparedProbeCube &pc : ps->probe_cubes) {
    if (pc.source != "pending") continue;
    if (!made && !make_probe_view(s, *ps, &v, err)) return false;
    made = true;
    const auto t0 = Clock::now();
    std::vector<float> rgba;
    render_probe_cube_cpu(&v, s.probes.at(pc.probe).position, s.probes[pc.probe].size, threads, &rgba);
    if (!store_cube(s, ps, &pc, rgba, err)) return false;
    pc.ms = ms_since(t0);
    pc.source = "C fallback";
    ps->notes.push_back(made_note(s, v, pc));
  }
  return true;
}

bool render_probe_cubes_gl(const Scene &s, PreparedScene *ps, GlRenderer &r, Api api, const std::string &gl_name,
                           bool check, std::string *err) {
  ProbeView v;
  for (const PreparedProbeCube &pc : ps->probe_cubes)
    if (pc.source == "pending") v.max_size = std::max(v.max_size, s.probes.at(pc.probe).size);
  if (v.max_size == 0) return true;
  if (!make_probe_view(s, *ps, &v, err)) return false;
  probe_view_face(&v, s.probes[0].position, v.max_size, 0);
  SceneGl g(r, api);
  if (!g.init(v.p, err, nullptr, v.max_size, v.max_size)) {
    *err = "the probes' cube maps on GL: " + *err;
    return false;
  }
  for (PreparedProbeCube &pc : ps->probe_cubes) {
    if (pc.source != "pending") continue;
    const auto t0 = Clock::now();
    std::vector<float> rgba;
    long mismatched = 0;
    if (!render_probe_cube_gl(&v, &g, s.probes.at(pc.probe).position, s.probes[pc.probe].size, &rgba, err,
                              check ? &mismatched : nullptr) ||
        !store_cube(s, ps, &pc, rgba, err))
      return false;
    pc.ms = ms_since(t0);
    pc.source = "GL " + gl_name;
    if (check) {
      pc.check_texels = 6L * s.probes[pc.probe].size * s.probes[pc.probe].size;
      pc.check_mismatched = mismatched;
    }
    ps->notes.push_back(made_note(s, v, pc));
    if (check)
      ps->notes.push_back("probe " + s.probes[pc.probe].name + ": --check: " + std::to_string(mismatched) + " of " +
                          std::to_string(pc.check_texels) + " cube texels differ from the C twin on GL's G-buffer");
  }
  return true;
}
