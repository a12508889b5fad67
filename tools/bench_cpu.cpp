// ============================================================================
// tiershade -- tools/bench_cpu.cpp
// A small timing harness for the C fallback, not part of `make test` or `make all`:
// the model_lighting rows of `tiershade bench` (1024x1024 sphere grid / Phong ball),
// llvmpipe (OSMesa GL 3.3) and cpu_render_frame (2 threads) in the same run: the per-pixel
// scalar path (the family with eval_row_f cleared) and the fast path, and whether the GL and
// both C frames are bit-equal. Build (after `make all`):
//   g++ -std=c++17 -O2 -ffp-contract=off -Iglue -Ic_ref -Ibuild/gen tools/bench_cpu.cpp \
//       $(ls build/obj/c_ref/*.o build/obj/glue/*.o | grep -v main.o) build/obj/gen/shader_sources.o \
//       -lEGL $(pkg-config --libs OpenEXR libpng OpenColorIO tinygltf) -lpthread -ldl -lm -o build/bench_cpu
// Usage: build/bench_cpu [runs] [row-substring]
// ============================================================================
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "demo/family_frame.h"
#include "gl/context.h"
#include "demo/scene_files.h"
#include "scene/deferred.h"
#include "demo/room_scene.h"
#include "math/ts_batch.h"
#include "demo/room_render.h"
#include "shaderlib/variants.h"

namespace {
double now_ms() {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now().time_since_epoch()).count();
}
double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0 : v[v.size() / 2];
}
struct Row {
  const char *label, *variant;
  int max_local;
  bool phong_scene;
};
}  // namespace

int main(int argc, char **argv) {
  const int runs = argc > 1 ? atoi(argv[1]) : 5;
  const char *only = argc > 2 ? argv[2] : "";
  const int n = 1024;
  std::vector<ShaderDecl> decls;
  std::string err;
  if (!load_shader_decls(&decls, &err)) return fprintf(stderr, "%s\n", err.c_str()), 1;
  const ShaderFamily *fam = find_family("model_lighting");
  const Row rows[] = {
      {"ps20", "ps20:ALBEDO_TEXTURE=1,HALF_LAMBERT=1,NUM_LIGHTS=2", 2, false},
      {"ps2b", "ps2b:ALBEDO_TEXTURE=1,HALF_LAMBERT=1,OUTPUT_MODE=1,NUM_LIGHTS=4", 4, false},
      {"sm3", "sm3:ALBEDO_TEXTURE=1,HALF_LAMBERT=1,OUTPUT_MODE=2", 4, false},
      {"ps2b Phong", "ps2b:ALBEDO_TEXTURE=1,HALF_LAMBERT=1,OUTPUT_MODE=2,PHONG=1,PHONG_EXPONENT_MAP=1,NUM_LIGHTS=4", 4,
       true},
      {"ps2b full",
       "ps2b:ALBEDO_TEXTURE=1,HALF_LAMBERT=1,OUTPUT_MODE=2,PHONG=1,PHONG_EXPONENT_MAP=1,RIM_LIGHT=1,ENVMAP=1,NUM_LIGHTS=4", 4,
       true},
      {"sm3 full", "sm3:ALBEDO_TEXTURE=1,HALF_LAMBERT=1,OUTPUT_MODE=2,PHONG=1,PHONG_EXPONENT_MAP=1,RIM_LIGHT=1,ENVMAP=1", 4,
       true},
  };
  Scene grid, ball;
  if (!load_scene(kSphereGridGltf, &grid, &err) || !load_scene(kPhongSphereGltf, &ball, &err))
    return fprintf(stderr, "%s\n", err.c_str()), 1;
  printf("%-12s %10s %12s %8s %10s %8s %10s\n", "row", "llvmpipe", "C scalar", "C/llvm", "C fast", "C/llvm", "mismatch");
  ShaderFamily scalar_fam = *fam;
  scalar_fam.eval_row_f = nullptr;
  for (const Row &row : rows) {
    if (*only && !strstr(row.label, only)) continue;
    Variant v;
    if (!find_variant(decls, "model_lighting", row.variant, &v, &err)) return fprintf(stderr, "%s\n", err.c_str()), 1;
    SceneDeferredFrame frame;  // the scene renderer's G-buffer, lights folded for the row's tier
    if (!scene_deferred_frame(row.phong_scene ? ball : grid, v.tier, n, n, &frame, &err, row.phong_scene))
      return fprintf(stderr, "%s\n", err.c_str()), 1;
    ImageF gl_img, cpu, cpu_scalar;
    std::vector<double> tg, tc, ts;
    {
      auto ctx = GlContext::create(Backend::OSMesa, Api::GL33, &err);
      if (!ctx) return fprintf(stderr, "%s\n", err.c_str()), 1;
      GlRenderer r(*ctx);
      GlFrameProgram fp;
      if (!gl_frame_setup(r, Api::GL33, *fam, v, frame.in, &fp, &err)) return fprintf(stderr, "%s\n", err.c_str()), 1;
      double ms = 0;
      gl_frame_draw(r, fp, frame.in, &gl_img, &ms, &err);
      for (int i = 0; i < runs; ++i) {
        gl_frame_draw(r, fp, frame.in, &gl_img, &ms, &err);
        tg.push_back(ms);
      }
      gl_frame_release(r, &fp);
    }
    for (int i = 0; i < runs; ++i) {
      double t0 = now_ms();
      cpu_render_frame(*fam, v, frame.in, &cpu, 2);
      tc.push_back(now_ms() - t0);
      if (i < 3) {  // the slow path: 3 frames are enough
        t0 = now_ms();
        cpu_render_frame(scalar_fam, v, frame.in, &cpu_scalar, 2);
        ts.push_back(now_ms() - t0);
      }
    }
    long mism = 0;
    for (size_t p = 0; p < cpu.rgba.size(); ++p) {
      const float a = cpu.rgba[p], b = gl_img.rgba[p], c = cpu_scalar.rgba[p];
      if (std::memcmp(&a, &b, 4) != 0 || std::memcmp(&a, &c, 4) != 0) ++mism;
    }
    const double g = median(tg), c = median(tc), sc = median(ts);
    printf("%-12s %10.2f %12.2f %8.2f %10.2f %8.2f %10ld\n", row.label, g, sc, sc / g, c, c / g, mism);
    fflush(stdout);
  }
  // world_lighting: the demo's room (one pass per cube-map probe) at 1024x512, the demo's tiers.
  // "C scalar" here is the batch API forced to the scalar twin (ts_batch_force_isa).
  if (*only && !strstr("world", only)) return 0;
  const WorldScene scene = default_world_scene();
  WorldBake bake;
  WorldFrame wf;
  if (!bake_world(scene, &bake, &err) || !world_frame(scene, bake, 1024, 512, &wf, &err))
    return fprintf(stderr, "%s\n", err.c_str()), 1;
  const char *wrows[3][2] = {{"world ps20", "ps20:BUMPMAP=1,LIGHTMAP_ENCODING=1,ENVMAP=1,ENVMAPMASK=1"},
                             {"world ps2b", "ps2b:BUMPMAP=1,LIGHTMAP_ENCODING=0,ENVMAP=1,ENVMAPMASK=1"},
                             {"world sm3", "sm3:BUMPMAP=1,LIGHTMAP_ENCODING=0,ENVMAP=1,ENVMAPMASK=1"}};
  for (const auto &wr : wrows) {
    Variant v;
    if (!find_variant(decls, "world_lighting", wr[1], &v, &err)) return fprintf(stderr, "%s\n", err.c_str()), 1;
    const TextureDesc page = encode_page(scene, bake, v.value("LIGHTMAP_ENCODING"));
    const WorldPass pass{&v, &page, false, false};
    ImageF gl_img, cpu, cpu_scalar;
    std::vector<double> tg, tc, ts;
    {
      auto ctx = GlContext::create(Backend::OSMesa, Api::GL33, &err);
      if (!ctx) return fprintf(stderr, "%s\n", err.c_str()), 1;
      GlRenderer r(*ctx);
      WorldGl g;
      if (!world_gl_setup(r, Api::GL33, wf, bake, pass, &g, &err)) return fprintf(stderr, "%s\n", err.c_str()), 1;
      double ms = 0;
      world_gl_draw(r, g, wf, &gl_img, &err, &ms);
      for (int i = 0; i < runs; ++i) {
        world_gl_draw(r, g, wf, &gl_img, &err, &ms);
        tg.push_back(ms);
      }
      world_gl_release(r, &g);
    }
    for (int i = 0; i < runs; ++i) {
      double t0 = now_ms();
      world_render_cpu(wf, bake, pass, &cpu, 2);
      tc.push_back(now_ms() - t0);
      if (i < 3) {
        ts_batch_force_isa(TS_BATCH_SCALAR);
        t0 = now_ms();
        world_render_cpu(wf, bake, pass, &cpu_scalar, 2);
        ts.push_back(now_ms() - t0);
        ts_batch_force_isa(-1);
      }
    }
    long mism = 0;
    for (size_t p = 0; p < cpu.rgba.size(); ++p) {
      const float a = cpu.rgba[p], b = gl_img.rgba[p], c = cpu_scalar.rgba[p];
      if (std::memcmp(&a, &b, 4) != 0 || std::memcmp(&a, &c, 4) != 0) ++mism;
    }
    const double gm = median(tg), cm = median(tc), sm = median(ts);
    printf("%-12s %10.2f %12.2f %8.2f %10.2f %8.2f %10ld\n", wr[0], gm, sm, sm / gm, cm, cm / gm, mism);
    fflush(stdout);
  }
  return 0;
}
