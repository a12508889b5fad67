// tiershade bench: the mipmaps section of `tiershade bench` (docs/accuracy_cost.md): what the
// samplers' mip chains (docs/rendering.md "Mipmaps") buy and cost on the shipped scenes with
// receding textured floors and walls, at N/2 x N*9/32: the texture error against a 16x
// supersampled reference (the same scene rendered with mipmaps by the C fallback at 4x the width
// and height, box-averaged 4x4 in display codes, in double), the lit pass's time with and without
// the chains on GL (EGL GLES 3.0 / llvmpipe) and on the C fallback, measured in turn in the same
// run, and the textures' bytes. Not a test.
#include <algorithm>
#include <cmath>
#include <sstream>

#include "base/stats.h"
#include "families/family.h"
#include "scene/frame.h"
#include "scene/prepare.h"
#include "scene/scene.h"
#include "scene/selection.h"

#include "bench/table_format.h"

namespace {

using bench::f1;
using bench::f2;

bool reference(const Scene &s, const SceneSelection &sel, int w, int h, std::vector<double> *ref, std::string *err) {
  SceneRenderConfig c;
  c.backend = Backend::CPU;
  c.w = 4 * w;
  c.h = 4 * h;
  SceneRenderResult r;
  if (!render_scene(s, sel, c, &r, err)) return false;
  ref->assign(static_cast<size_t>(w) * h * 3, 0.0);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int ch = 0; ch < 3; ++ch) {
        double acc = 0;
        for (int j = 0; j < 4; ++j)
          for (int i = 0; i < 4; ++i) acc += r.display[((static_cast<size_t>(4 * y + j) * c.w) + 4 * x + i) * 4 + ch];
        (*ref)[(static_cast<size_t>(y) * w + x) * 3 + ch] = acc / 16.0;
      }
  return true;
}

struct Err {
  double mean = 0, over8 = 0, p99 = 0;
  int max = 0;
};
// The largest channel's |frame - reference| per pixel, over every pixel.
Err error_of(const std::vector<uint8_t> &d, const std::vector<double> &ref) {
  Err e;
  const size_t n = ref.size() / 3;
  std::vector<double> px(n);
  for (size_t i = 0; i < n; ++i) {
    double m = 0;
    for (int ch = 0; ch < 3; ++ch) m = std::max(m, std::fabs(d[i * 4 + ch] - ref[i * 3 + ch]));
    px[i] = m;
    e.mean += m;
    e.over8 += m > 8;
    e.max = std::max(e.max, static_cast<int>(std::lround(m)));
  }
  e.mean /= static_cast<double>(n);
  e.over8 = 100.0 * e.over8 / static_cast<double>(n);
  std::sort(px.begin(), px.end());
  e.p99 = px[std::min(n - 1, n * 99 / 100)];
  return e;
}

double texture_mib(const Scene &s, const SceneSelection &sel, int w, int h, bool mips, std::string *err) {
  PrepareOptions o;
  o.mipmaps = mips;
  PreparedScene p;
  if (!prepare_scene(s, sel, w, h, Api::GL33, s.hdr.tone_map_scale, &p, err, o)) return -1;
  size_t b = 0;
  for (const TextureDesc &t : p.textures) {
    b += t.rgba.size() * sizeof(float);
    for (const std::vector<float> &l : t.mips) b += l.size() * sizeof(float);
  }
  return static_cast<double>(b) / (1 << 20);
}

bool run(const BenchOptions &opt, std::string *md, std::string *err) {
  const int w = std::max(32, opt.size / 2), h = std::max(18, opt.size * 9 / 32);
  const int runs = std::max(1, std::min(opt.runs, 7));
  std::ostringstream rows;
  for (const char *scene : {"scenes/world_lighting.gltf", "scenes/large_hall_40.gltf", "scenes/hdr_atrium.gltf"}) {
    Scene s;
    SceneSelection sel;
    if (!load_scene(scene, &s, err) || !select_scene_variants(s, Tier::SM3, "integer", &sel, err)) return false;
    std::vector<double> ref;
    if (!reference(s, sel, w, h, &ref, err)) return false;
    // Both settings on both backends, their warm frames taken in turn (the same machine state).
    SceneRenderer r[2][2];  // [mips][backend: 0 EGL, 1 C]
    SceneRenderResult first[2][2];
    for (int m = 0; m < 2; ++m)
      for (int b = 0; b < 2; ++b) {
        SceneRenderConfig c;
        c.backend = b ? Backend::CPU : Backend::EGL;
        c.w = w;
        c.h = h;
        c.mipmaps = m == 1;
        if (!r[m][b].init(s, sel, c, err) || !r[m][b].frame(&first[m][b], err)) return false;
      }
    std::vector<double> lit[2][2];
    for (int i = 0; i < runs; ++i)
      for (int m = 0; m < 2; ++m)
        for (int b = 0; b < 2; ++b) {
          SceneRenderResult f;
          if (!r[m][b].frame(&f, err)) return false;
          lit[m][b].push_back(f.lit_ms);
        }
    const double mib[2] = {texture_mib(s, sel, w, h, false, err), texture_mib(s, sel, w, h, true, err)};
    for (int m = 0; m < 2; ++m) {
      const Err e = error_of(first[m][1].display, ref);
      const double gl = median(lit[m][0]), c = median(lit[m][1]);
      rows << "| " << (scene + 7) << " | " << (m ? "mipmaps (sampler's minFilter)" : "level 0 only") << " | "
           << f2(e.mean) << " | " << f1(e.p99) << " | " << f2(e.over8) << "% | " << e.max << " | " << f1(gl) << " | "
           << f2(gl / median(lit[0][0])) << " | " << f1(c) << " | " << f2(c / median(lit[0][1])) << " | "
           << f1(mib[m]) << " |\n";
    }
  }
  std::ostringstream o;
  o << "## Mipmaps: the samplers' chains against level 0 (" << w << "x" << h << ")\n\n"
    << "sm3, integer path. The material textures the shaders sample at the surface's uv with the mip chains\n"
    << "tiershade builds (docs/rendering.md, \"Mipmaps\": 2x2 box means in linear light, normal maps renormalised,\n"
    << "llvmpipe's level of detail mirrored by the C fallback), against the same scene with every texture at level 0\n"
    << "(`PrepareOptions::mipmaps` false). **Reference**: the scene with mipmaps rendered by the C fallback at\n"
    << 4 * w << "x" << 4 * h << " and box-averaged 4x4 in display codes (double). **error**: the largest channel's\n"
    << "|frame - reference| in 8-bit codes per pixel, over every pixel (the C fallback's frame; GL 3.3's is the same\n"
    << "bytes): mean, 99th percentile, share beyond 8 codes, max (silhouettes stay: neither setting antialiases\n"
    << "geometry). **lit ms**: the lit pass, median of " << runs
    << " warm frames, the four renderers' frames taken in turn; **x level 0**: the\n"
    << "ratio to the level-0 row of the same backend in the same run. **texture MiB**: RGBA32F texels the scene's\n"
    << "draws bind (lightmap pages and probe cubes included; the chains add about a third to what they apply to).\n\n"
    << "| scene | textures | mean error | p99 | > 8 codes | max | GL lit ms | GL x level 0 | C lit ms | C x level 0 | "
       "texture MiB |\n"
    << "|---|---|---|---|---|---|---|---|---|---|---|\n"
    << rows.str();
  *md = o.str();
  return true;
}

const BenchSection kSection = {"mipmaps", run};
const BenchRegistrar kRegister(&kSection);

}  // namespace
