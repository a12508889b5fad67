// tiershade bake: the world bake (glue/bake/world_bake.h): luxels (supersampled, with shadow rays through
// glue/bake/ray_scene.h), page, probes, encodings.
#include "bake/world_bake.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>

#include "bake/bounce.h"
#include "bake/glm_ts.h"
#include "bake/luxel_rng.h"
#include "bake/ray_scene.h"
#include "base/cube_faces.h"
#include "base/parallel_rows.h"
#include "offline/envmap_probes.h"
#include "offline/lightmap_encoding.h"

namespace {

int luxels(double len, double per_unit) { return std::max(2, static_cast<int>(std::lround(len * per_unit)) + 1); }

// Shadow rays start this far off the surface along its normal (scene units, metres in glTF): above
// Embree's float precision at room scale (~1e-6 m), below any contact a lightmap resolves.
const double kRayOffset = 1e-4;

// The lights that reach p: those it faces (n . L > 0) whose segment to p nothing blocks. A sun with
// an angular spread (WorldBakeInput::light_spread, vrad's _sunspreadangle) sends its shadow rays
// jittered within its cone, stratified from the sample's own stream `rng`, and reaches p scaled by
// the share of them that nothing blocks (a ray below the face's plane counting as blocked); its
// cosines stay those of its central direction (vrad's emit_skylight: the dots times the visible
// fraction). `rays` counts the shadow rays.
void visible_lights(const WorldBakeInput &s, const glm::dvec3 &p, const glm::dvec3 &n, std::vector<rnm_light> *out,
                    LuxelRng *rng, long *rays) {
  out->clear();
  for (size_t li = 0; li < s.lights.size(); ++li) {
    const rnm_light &l = s.lights[li];
    const glm::dvec3 to = l.directional ? -to_glm(l.dir) : to_glm(l.pos) - p;
    if (!(glm::dot(to, n) > 0)) continue;  // behind the face: it feeds no value (rnm_bake_texel)
    const glm::dvec3 o = p + n * kRayOffset;
    const double spread = li < s.light_spread.size() ? s.light_spread[li] : 0.0;
    if (l.directional && spread > 0 && s.rays) {
      // spread_samples per luxel, shared among its ss x ss samples (each a square of strata).
      const int ss = std::max(1, s.supersample);
      const int per = std::max(1, (s.spread_samples + ss * ss - 1) / (ss * ss));
      const int side = std::max(1, static_cast<int>(std::ceil(std::sqrt(static_cast<double>(per)))));
      const glm::dvec3 a = glm::normalize(to);
      glm::dvec3 au, av;
      frame_of(a, &au, &av);
      int seen = 0;
      for (int k = 0; k < side * side; ++k) {
        double r1, r2;
        stratum(k, side, rng, &r1, &r2);
        const glm::dvec3 d = cone_dir(a, au, av, std::cos(spread), r1, r2);
        if (!(glm::dot(d, n) > 0)) continue;
        ++*rays;
        seen += !s.rays->occluded(o, d, 0.0, INFINITY);
      }
      if (seen == 0) continue;
      rnm_light part = l;
      const double share = static_cast<double>(seen) / (side * side);
      part.color = ts_v3d(l.color.x * share, l.color.y * share, l.color.z * share);
      out->push_back(part);
      continue;
    }
    const glm::dvec3 d = l.directional ? to : to_glm(l.pos) - o;
    // Point and spot lights: the segment up to the light (t < 1); a sun: the whole ray.
    if (s.rays) ++*rays;
    if (s.rays && s.rays->occluded(o, d, 0.0, l.directional ? INFINITY : 1.0 - 1e-9)) continue;
    out->push_back(l);
  }
}

// The four values (flat, b0, b1, b2) at p with visibility.
int lit_values(const WorldBakeInput &s, const glm::dvec3 &p, ts_vec3d n, const ts_vec3d bump[3], ts_vec3d v4[4],
               std::vector<rnm_light> *scratch, LuxelRng *rng, long *rays, char *msg, size_t len) {
  visible_lights(s, p, to_glm(n), scratch, rng, rays);
  return rnm_bake_texel(to_ts(p), n, bump, scratch->data(), static_cast<int>(scratch->size()), v4, msg, len);
}

// A ray scene of the faces alone (two triangles each), for a bake given none.
bool face_rays(const std::vector<WorldFace> &faces, RayScene *r, std::string *err) {
  for (size_t i = 0; i < faces.size(); ++i) {
    const WorldFace &f = faces[i];
    if (f.chart) {  // a TEXCOORD_1 chart: its triangles, in order (hits name them: chart_hit_ab)
      std::vector<float> p(f.chart->pos.begin(), f.chart->pos.end());
      std::vector<uint32_t> idx(p.size() / 3);
      for (size_t k = 0; k < idx.size(); ++k) idx[k] = static_cast<uint32_t>(k);
      if (!r->add_mesh(p, idx, static_cast<int>(i), f.name, err)) return false;
      continue;
    }
    const glm::dvec3 o = to_glm(f.origin), u = to_glm(f.u) * f.su, v = to_glm(f.v) * f.sv;
    std::vector<float> p;
    for (const glm::dvec3 &q : {o, o + u, o + u + v, o + v})
      for (int k = 0; k < 3; ++k) p.push_back(static_cast<float>(q[k]));
    if (!r->add_mesh(p, {0, 1, 2, 0, 2, 3}, static_cast<int>(i), f.name, err)) return false;
  }
  return r->commit(err);
}

}  // namespace

bool bake_world(const WorldBakeInput &in, WorldBake *out, std::string *err) {
  for (const WorldFace &f : in.faces)
    if (!(f.normal.x * f.normal.x + f.normal.y * f.normal.y + f.normal.z * f.normal.z > 0)) {
      *err = std::string(f.name) + ": the face has no front normal";
      return false;
    }
  // Every visibility and probe ray goes through a ray scene: the caller's (every triangle of the
  // scene), else one of the faces alone.
  RayScene own;
  WorldBakeInput s = in;
  if (!s.rays) {
    if (!face_rays(s.faces, &own, err)) return false;
    s.rays = &own;
  }
  std::vector<lm_face_size> sizes;
  for (const WorldFace &f : s.faces)  // a chart's block is its own (glue/bake/charts.h)
    sizes.push_back(f.chart ? lm_face_size{f.chart->w, f.chart->h, 1}
                            : lm_face_size{luxels(f.su, s.luxels_per_unit), luxels(f.sv, s.luxels_per_unit), 1});
  out->place.resize(s.faces.size());
  char msg[256];
  if (lm_page_pack_pages(s.page_w, s.page_h, kMaxLightmapPages, sizes.data(), static_cast<int>(sizes.size()),
                         out->place.data(), &out->pages, msg, sizeof msg) != 0) {
    *err = msg;
    const char *face = std::strstr(msg, "face ");
    if (face) {  // name the primitive
      const long fi = std::strtol(face + 5, nullptr, 10);
      if (fi >= 0 && fi < static_cast<long>(s.faces.size())) {
        const WorldFace &f = s.faces[static_cast<size_t>(fi)];  // a chart names its primitive too
        *err = std::string(f.name) + (f.chart ? " (" + f.chart->where + ")" : std::string()) + ": " + msg;
      }
    }
    return false;
  }
  out->page.assign(static_cast<size_t>(s.page_w) * s.page_h * out->pages * 4, 0.f);
  for (size_t i = 0; i < out->page.size(); i += 4) out->page[i + 3] = 1.f;
  // Each face's bump basis and its luxel grid, the direct light first.
  std::vector<std::array<ts_vec3d, 3>> bump(s.faces.size());
  std::vector<LuxelGrid> grids(s.faces.size());
  for (size_t fi = 0; fi < s.faces.size(); ++fi) {
    const WorldFace &f = s.faces[fi];
    const ts_vec3d n = world_face_normal(f);
    if (rnm_bump_basis(f.u, f.v, n, n, bump[fi].data(), msg, sizeof msg) != 0) {
      *err = std::string(f.name) + ": " + msg;
      return false;
    }
    grids[fi].w = sizes[fi].luxels_w;
    grids[fi].h = sizes[fi].luxels_h;
    grids[fi].v.assign(static_cast<size_t>(grids[fi].w) * grids[fi].h * 4, ts_v3d(0, 0, 0));
  }
  const bool bake_luxels = s.page_in == nullptr;
  if (!bake_luxels && s.page_in->size() != out->page.size()) {
    *err = "the lightmap page holds " + std::to_string(s.page_in->size() / 4) + " texels, the layout " +
        std::to_string(out->page.size() / 4);
    return false;
  }
  if (!bake_luxels) out->page = *s.page_in;
  using Clock = std::chrono::steady_clock;
  const auto t_direct = Clock::now();
  for (const LuxelGrid &g : grids) out->luxels += static_cast<long>(g.w) * g.h;
  // A saved pass to resume from (checkpoints, glue/bake/bake_dir.h): its grids, no direct pass.
  const BakePassState *resume = bake_luxels && s.hooks ? s.hooks->resume : nullptr;
  if (resume) {
    bool fits = resume->grids.size() == grids.size();
    for (size_t fi = 0; fits && fi < grids.size(); ++fi)
      fits = resume->grids[fi].w == grids[fi].w && resume->grids[fi].h == grids[fi].h &&
          resume->grids[fi].v.size() == grids[fi].v.size();
    if (!fits) {
      *err = "the saved pass to resume from does not fit the faces' luxel grids";
      return false;
    }
    grids = resume->grids;
    out->resumed_after = resume->pass;
  }
  long luxels_done = 0;
  for (size_t fi = 0; bake_luxels && !resume && fi < s.faces.size(); ++fi) {
    const WorldFace &f = s.faces[fi];
    const ts_vec3d n = world_face_normal(f);
    {  // every light checked once per face (a bad light is an error naming the face)
      ts_vec3d v4[4];
      if (rnm_bake_texel(world_face_point(f, 0, 0), n, bump[fi].data(), s.lights.data(),
                         static_cast<int>(s.lights.size()), v4, msg, sizeof msg) != 0) {
        *err = std::string(f.name) + ": " + msg;
        return false;
      }
    }
    const int ss = std::max(1, s.supersample);
    LuxelGrid &g = grids[fi];
    // Rows on the bake's threads (each luxel's samples and streams its own: the same bytes on any
    // count); a row's first error is reported, the lowest row's first.
    std::vector<std::string> row_err(static_cast<size_t>(g.h));
    std::vector<long> row_rays(static_cast<size_t>(g.h), 0);
    parallel_rows(g.h, s.bounce.threads, [&](int j) {
      std::vector<rnm_light> scratch;
      char rmsg[256];
      for (int i = 0; i < g.w && row_err[static_cast<size_t>(j)].empty(); ++i) {
        // The luxel's footprint is one luxel spacing wide, centred on its grid point; ss x ss samples.
        glm::dvec3 v4[4] = {glm::dvec3(0.0), glm::dvec3(0.0), glm::dvec3(0.0), glm::dvec3(0.0)};
        if (f.chart && !f.chart->at(i, j).lit) continue;  // no triangle touches it: dilation fills it
        int taken = 0;
        for (int sj = 0; sj < ss; ++sj)
          for (int si = 0; si < ss; ++si) {
            ts_vec3d s4[4];
            LuxelRng rng = LuxelRng::of(0x53756E /* "Sun" */, fi, static_cast<uint64_t>(j), static_cast<uint64_t>(i),
                                        static_cast<uint64_t>(sj * ss + si), s.bounce.seed);
            LuxelFrame lf;
            if (f.chart) {
              // A chart's sample: the point of the luxel's square, on the triangle holding it; a
              // sample no triangle holds is skipped (the luxel's own frame when none is held).
              if (!chart_frame_at(*f.chart, (i + (si + 0.5) / ss) / g.w, (j + (sj + 0.5) / ss) / g.h, &lf)) continue;
            } else {
              const double a = std::clamp((i + (si + 0.5) / ss - 0.5) / (g.w - 1), 0.0, 1.0);
              const double b = std::clamp((j + (sj + 0.5) / ss - 0.5) / (g.h - 1), 0.0, 1.0);
              lf.p = world_face_sample(f, a, b);
              lf.n = n;
              for (int k = 0; k < 3; ++k) lf.bump[k] = bump[fi][static_cast<size_t>(k)];
            }
            if (lit_values(s, to_glm(lf.p), lf.n, lf.bump, s4, &scratch, &rng, &row_rays[static_cast<size_t>(j)],
                           rmsg, sizeof rmsg) != 0) {
              row_err[static_cast<size_t>(j)] = std::string(f.name) + ": " + rmsg;
              return;
            }
            for (int k = 0; k < 4; ++k) v4[k] += to_glm(s4[k]);
            ++taken;
          }
        if (taken == 0) {  // a luxel a triangle only grazes: its frame (the nearest point)
          const LuxelFrame &lf = f.chart->at(i, j);
          ts_vec3d s4[4];
          LuxelRng rng = LuxelRng::of(0x53756E /* "Sun" */, fi, static_cast<uint64_t>(j), static_cast<uint64_t>(i),
                                      static_cast<uint64_t>(ss * ss), s.bounce.seed);
          if (lit_values(s, to_glm(lf.p), lf.n, lf.bump, s4, &scratch, &rng, &row_rays[static_cast<size_t>(j)], rmsg,
                         sizeof rmsg) != 0) {
            row_err[static_cast<size_t>(j)] = std::string(f.name) + ": " + rmsg;
            return;
          }
          for (int k = 0; k < 4; ++k) v4[k] = to_glm(s4[k]);
          taken = 1;
        }
        for (int k = 0; k < 4; ++k) g.at(i, j, k) = to_ts(v4[k] / static_cast<double>(taken));
      }
    });
    for (int j = 0; j < g.h; ++j) {
      out->direct_rays += row_rays[static_cast<size_t>(j)];
      if (!row_err[static_cast<size_t>(j)].empty()) {
        *err = row_err[static_cast<size_t>(j)];
        return false;
      }
    }
    luxels_done += static_cast<long>(g.w) * g.h;
    if (s.hooks && s.hooks->progress) s.hooks->progress("direct", luxels_done, out->luxels);
  }
  out->direct_ms = std::chrono::duration<double, std::milli>(Clock::now() - t_direct).count();
  // The sky (glue/bake/sky.h) and the emitters as area lights (glue/bake/area_lights.h), added like
  // the direct light: the first bounce reflects them; emission the area lights sampled is not sent
  // again by the bounces (docs/baking.md, "Emitters").
  // A resumed bake's saved pass 0 already holds them (checkpoints, glue/bake/bake_dir.h).
  if (bake_luxels && !resume) {
    if (!sky_light(s.faces, bump, *s.rays, s.sky, s.bounce.threads, s.bounce.seed, &grids, &out->sky, err))
      return false;
    AreaLightSettings as;
    as.samples = s.area_samples;
    as.threads = s.bounce.threads;
    as.seed = s.bounce.seed;
    if (!area_lights(s.faces, bump, s.model_emitters, *s.rays, as, &grids, &out->area, err)) return false;
  }
  s.bounce.emission_sampled = bake_luxels && s.area_samples > 0;
  s.bounce.model_emitters = &s.model_emitters;  // (their emission gathered when not sampled)
  // The interreflected light (glue/bake/bounce.h), then the page.
  const auto t_bounce = Clock::now();
  if (bake_luxels) {
    BakePassState state;  // the direct pass: a state of its own (pass 0), saved before the bounces
    state.direct_ms = resume ? resume->direct_ms : out->direct_ms;
    state.direct_rays = resume ? resume->direct_rays : out->direct_rays;
    out->direct_ms = state.direct_ms;
    out->direct_rays = state.direct_rays;
    if (!resume && s.hooks && s.hooks->on_pass) {
      state.stopped = s.bounce.max_bounces <= 0;
      state.grids = grids;
      if (!s.hooks->on_pass(state, err)) return false;
    }
    if (!bounce_light(s.faces, bump, *s.rays, s.bounce, &grids, &out->bounce, err, s.hooks, &state)) return false;
    out->bounce_ms = std::chrono::duration<double, std::milli>(Clock::now() - t_bounce).count();
    for (size_t fi = 0; fi < s.faces.size(); ++fi) {
      const LuxelGrid &g = grids[fi];
      for (int j = 0; j < g.h; ++j)
        for (int i = 0; i < g.w; ++i)
          for (int k = 0; k < 4; ++k) {
            int tx, ty;
            lm_page_texel(&out->place[fi], k, i, j, &tx, &ty);
            float *t = &out->page[(static_cast<size_t>(ty) * s.page_w + tx) * 4];
            const ts_vec3d &v = g.at(i, j, k);
            t[0] = static_cast<float>(v.x);
            t[1] = static_cast<float>(v.y);
            t[2] = static_cast<float>(v.z);
          }
      if (!s.faces[fi].chart) {
        lm_page_fill_borders(&out->place[fi], s.page_w, out->page.data());
        continue;
      }
      // A chart's blocks: their unlit texels and borders dilated from the lit ones (glue/bake/charts.h).
      std::vector<int> lit(s.faces[fi].chart->luxel_tri.size());
      for (size_t k = 0; k < lit.size(); ++k) lit[k] = s.faces[fi].chart->luxel_tri[k] >= 0;
      const lm_face_place &pl = out->place[fi];
      for (int k = 0; k < pl.count; ++k)
        chart_dilate(out->page.data(), s.page_w, pl.x + k * pl.block_w + 1, pl.y + 1, g.w, g.h, lit, kChartDilateRings,
                     nullptr);
    }
  }
  // The grids as the page holds them (float32, whether baked or read): the probes see what the
  // renderer samples, so a page read from a file gives the same probes as the bake that wrote it.
  for (size_t fi = 0; fi < s.faces.size(); ++fi) {
    LuxelGrid &g = grids[fi];
    for (int j = 0; j < g.h; ++j)
      for (int i = 0; i < g.w; ++i)
        for (int k = 0; k < 4; ++k) {
          int tx, ty;
          lm_page_texel(&out->place[fi], k, i, j, &tx, &ty);
          const float *t = &out->page[(static_cast<size_t>(ty) * s.page_w + tx) * 4];
          g.at(i, j, k) = ts_v3d(t[0], t[1], t[2]);
        }
  }
  // Probes: each face's, then each probe's cube, ray cast from the probe: a wall shows its
  // flat lightmap value times its mean albedo, a light shows as a small bright sphere.
  out->face_probe.clear();
  for (const WorldFace &f : s.faces) {
    const int p = env_pick_probe(world_face_point(f, 0.5, 0.5), s.probes.data(), static_cast<int>(s.probes.size()),
                                 f.probe, msg, sizeof msg);
    if (p < 0) {
      *err = std::string(f.name) + ": " + msg;
      return false;
    }
    out->face_probe.push_back(p);
  }
  out->cubes.clear();
  const auto t_cubes = std::chrono::steady_clock::now();
  const int N = s.cube_size;
  for (const ts_vec3d &pos : s.probes) {
    const size_t pi = static_cast<size_t>(&pos - s.probes.data());
    if (pi < s.trace_cube.size() && !s.trace_cube[pi]) {
      out->cubes.emplace_back();  // rendered in-engine by the scene
      continue;
    }
    TextureDesc c = blank_texture("u_envmap", N, N * 6, true, false);
    c.kind = TexKind::Cube;
    c.h = N;
    for (int face = 0; face < 6; ++face) {
      for (int j = 0; j < N; ++j) {
        for (int i = 0; i < N; ++i) {
          const double sc = 2 * (i + 0.5) / N - 1, tc = 2 * (j + 0.5) / N - 1;
          const glm::dvec3 d = cube_face_direction(face, sc, tc);
          glm::dvec3 rad(0.0);
          const RayScene::Hit hit = s.rays->intersect(to_glm(pos), d, 1e-6, INFINITY);
          const double t = hit.id >= 0 ? hit.t : INFINITY;
          if (hit.id >= 0 && hit.id < static_cast<int>(s.faces.size())) {
            // A face: the radiance it leaves there (emission + reflectivity x its lightmap).
            const WorldFace &f = s.faces[static_cast<size_t>(hit.id)];
            double ha, hb;
            world_face_hit(f, to_glm(pos) + d * t, hit, -to_glm(world_face_normal(f)), &ha, &hb);
            rad = to_glm(luxel_exitant(f, grids[static_cast<size_t>(hit.id)], ha, hb));
          } else if (hit.id >= 0) {  // other geometry: its flat irradiance (with shadows) x a mean albedo
            const glm::dvec3 n = glm::dot(hit.normal, d) > 0 ? -hit.normal : hit.normal;
            const glm::dvec3 side = std::fabs(n.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
            const glm::dvec3 su = glm::normalize(glm::cross(side, n)), sv = glm::cross(n, su);
            ts_vec3d b3[3], v4[4];
            std::vector<rnm_light> scratch;
            rnm_bump_basis(to_ts(su), to_ts(sv), to_ts(n), to_ts(n), b3, msg, sizeof msg);
            LuxelRng rng = LuxelRng::of(0x50726F /* "Pro" */, static_cast<uint64_t>(&pos - s.probes.data()),
                                        static_cast<uint64_t>(face), static_cast<uint64_t>(j), static_cast<uint64_t>(i),
                                        s.bounce.seed);
            long probe_rays = 0;
            lit_values(s, to_glm(pos) + d * t, to_ts(n), b3, v4, &scratch, &rng, &probe_rays, msg, sizeof msg);
            rad = to_glm(v4[0]) * 0.6;
          } else if (hit.id <= model_emitter_id(0) &&
                     model_emitter_of_id(hit.id) < static_cast<int>(s.model_emitters.size())) {
            // An emissive model: its emission from the front (its back as other models: nothing).
            model_emitter_seen(s.model_emitters[static_cast<size_t>(model_emitter_of_id(hit.id))], hit.triangle, d,
                               &rad);
          } else if (s.sky.present()) {  // nothing: the sky
            rad = to_glm(sky_radiance(s.sky, to_ts(d)));
          }
          for (const rnm_light &l : s.lights) {  // a light bulb of radius 0.08 (not for a sun)
            if (l.directional) continue;
            const glm::dvec3 lp = to_glm(l.pos) - to_glm(pos);
            const double along = glm::dot(lp, d);
            if (along > 0 && along < t && glm::dot(lp, lp) - along * along < 0.08 * 0.08) rad = to_glm(l.color) * 4.0;
          }
          float *px = &c.rgba[((static_cast<size_t>(face) * N + j) * N + i) * 4];
          px[0] = static_cast<float>(rad.x);
          px[1] = static_cast<float>(rad.y);
          px[2] = static_cast<float>(rad.z);
          px[3] = 1.f;
        }
      }
    }
    out->cubes.push_back(c);
  }
  out->cubes_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t_cubes).count();
  return true;
}

TextureDesc encode_page(const WorldBakeInput &s, const WorldBake &b, int encoding, int page) {
  TextureDesc t = blank_texture("u_lightmap", s.page_w, s.page_h, encoding != WL_LM_RGBE, false);
  const size_t first = static_cast<size_t>(page) * s.page_w * s.page_h * 4;
  for (size_t i = 0; i < t.rgba.size(); i += 4) {
    const float *in = &b.page[first + i];
    float *o = &t.rgba[i];
    o[3] = 1.f;
    if (encoding == WL_LM_RGBE) {
      ts_rgbe e;
      ts_rgbe_encode(in, &e);  // the page is finite (the baker refuses anything else)
      ts_rgbe_texel(e, o);
      continue;
    }
    if (encoding == kPageRgbeToHalf) {  // RGBE on disk, fp16 at run time (c * 2^e / 255 is exact in double)
      ts_rgbe e;
      ts_rgbe_encode(in, &e);
      double d[3];
      ts_rgbe_decode(e, d);
      for (int c = 0; c < 3; ++c) o[c] = ts_half_quantize(static_cast<float>(d[c]));
      continue;
    }
    for (int c = 0; c < 3; ++c) {
      switch (encoding) {
        case WL_LM_FLOAT:
          o[c] = ts_half_quantize(in[c]);
          break;
        case WL_LM_412:
          o[c] = ts_u16_412_quantize(in[c]);
          break;
        case WL_LM_LDR:
          o[c] = ts_ldr_quantize(in[c]);
          break;
        default:
          o[c] = in[c];
          break;  // float32, unquantised
      }
    }
  }
  return t;
}

void decode_texel(int encoding, const float t[4], double rgb[3]) {
  for (int c = 0; c < 3; ++c) {
    switch (encoding) {
      case WL_LM_412:
        rgb[c] = 16.0 * t[c];
        break;
      case WL_LM_LDR:
        rgb[c] = std::pow(2.0 * t[c], 2.2);
        break;
      case WL_LM_RGBE:
        rgb[c] = t[c] * std::ldexp(1.0, static_cast<int>(std::lround(t[3] * 255.0)) - 128);
        break;
      default:
        rgb[c] = t[c];
        break;
    }
  }
}
