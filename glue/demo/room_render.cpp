// tiershade demo: world_lighting frames in GL and in C (see world_render.h).
#include "demo/room_render.h"

namespace {

FamilyInputs pass_inputs(const WorldFrame &f, const WorldBake &b, const WorldPass &p, int probe) {
  FamilyInputs in = f.in;
  in.textures = world_pass_textures(f, *p.page, b, probe, p.white_base, p.nearest_cube);
  return in;
}

// Copies the pixels of `probe` from src into dst; background pixels become (0, 0, 0, 1).
void composite(const WorldFrame &f, int probe, const ImageF &src, ImageF *dst) {
  if (dst->rgba.empty()) {
    dst->w = src.w;
    dst->h = src.h;
    dst->rgba.assign(src.rgba.size(), 0.f);
    for (size_t i = 3; i < dst->rgba.size(); i += 4) dst->rgba[i] = 1.f;
  }
  for (size_t px = 0; px < f.probe.size(); ++px)
    if (f.probe[px] == probe)
      for (int c = 0; c < 4; ++c) dst->rgba[px * 4 + c] = src.rgba[px * 4 + c];
}

}  // namespace

bool world_gl_setup(GlRenderer &r, Api api, const WorldFrame &f, const WorldBake &b, const WorldPass &p, WorldGl *g,
                    std::string *err) {
  for (int probe = 0; probe < static_cast<int>(b.cubes.size()); ++probe) {
    g->inputs.push_back(pass_inputs(f, b, p, probe));
    g->programs.emplace_back();
    if (!gl_frame_setup(r, api, kWorldLightingFamily, *p.variant, g->inputs.back(), &g->programs.back(), err)) {
      world_gl_release(r, g);
      return false;
    }
  }
  return true;
}

bool world_gl_draw(GlRenderer &r, const WorldGl &g, const WorldFrame &f, ImageF *out, std::string *err,
                   double *draw_ms) {
  *out = ImageF();
  if (draw_ms) *draw_ms = 0;
  for (size_t probe = 0; probe < g.programs.size(); ++probe) {
    ImageF img;
    double ms = 0;
    if (!gl_frame_draw(r, g.programs[probe], g.inputs[probe], &img, draw_ms ? &ms : nullptr, err)) return false;
    if (draw_ms) *draw_ms += ms;
    composite(f, static_cast<int>(probe), img, out);
  }
  return true;
}

void world_gl_release(GlRenderer &r, WorldGl *g) {
  for (GlFrameProgram &fp : g->programs) gl_frame_release(r, &fp);
  g->programs.clear();
  g->inputs.clear();
}

bool world_render_gl(GlRenderer &r, Api api, const WorldFrame &f, const WorldBake &b, const WorldPass &p, ImageF *out,
                     std::string *err, double *draw_ms) {
  WorldGl g;
  if (!world_gl_setup(r, api, f, b, p, &g, err)) return false;
  const bool ok = world_gl_draw(r, g, f, out, err, draw_ms);
  world_gl_release(r, &g);
  return ok;
}

void world_render_cpu(const WorldFrame &f, const WorldBake &b, const WorldPass &p, ImageF *out, int threads) {
  *out = ImageF();
  for (int probe = 0; probe < static_cast<int>(b.cubes.size()); ++probe) {
    const FamilyInputs in = pass_inputs(f, b, p, probe);
    ImageF img;
    cpu_render_frame(kWorldLightingFamily, *p.variant, in, &img, threads);
    composite(f, probe, img, out);
  }
}

void world_render_double(const WorldFrame &f, const WorldBake &b, const WorldPass &p, std::vector<double> *out) {
  out->assign(f.probe.size() * 4, 0.0);
  for (int probe = 0; probe < static_cast<int>(b.cubes.size()); ++probe) {
    const FamilyInputs in = pass_inputs(f, b, p, probe);
    std::vector<double> d;
    cpu_render_frame_double(kWorldLightingFamily, *p.variant, in, &d);
    for (size_t px = 0; px < f.probe.size(); ++px)
      if (f.probe[px] == probe)
        for (int c = 0; c < 4; ++c) (*out)[px * 4 + c] = d[px * 4 + c];
  }
  for (size_t px = 0; px < f.probe.size(); ++px)
    if (f.probe[px] < 0) (*out)[px * 4 + 3] = 1.0;
}
