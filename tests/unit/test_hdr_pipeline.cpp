// tiershade tests: the two HDR paths (glue/hdr/paths*.cpp) on every backend/API pair against their
// C twins, on the HDR demo scene (glue/demo/hdr_scene.h): the integer path's RGBA8 frame,
// and the float path's RGBA16F linear frame, quarter-size RGBA16F bloom and RGBA8
// result must equal the C frames code for code and bit for bit. This checks what the
// per-pixel family conformance cannot: the real fp16 and RGBA8 targets (storage
// rounding), fragment positions from gl_FragCoord, texelFetch (NEAREST sampling on
// GLES 2.0) and the bilinear sampling of RGBA16F textures. No tolerance.
// Prints "PASS name" / "FAIL name: detail"; exits 1 if anything failed.
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "hdr/paths.h"
#include "demo/hdr_scene.h"
#include "unit_gl.h"

namespace {

template <class T>
std::string first_difference(const std::vector<T> &a, const std::vector<T> &b, int w) {
  if (a.size() != b.size()) return "sizes " + std::to_string(a.size()) + " and " + std::to_string(b.size());
  long n = 0;
  size_t first = 0;
  for (size_t i = 0; i < a.size(); ++i)
    if (std::memcmp(&a[i], &b[i], sizeof(T)) != 0 && n++ == 0) first = i;
  if (!n) return "";
  const size_t p = first / 4;
  return std::to_string(n) + " values differ, first at pixel (" + std::to_string(p % w) + ", " + std::to_string(p / w) +
      ") channel " + std::to_string(first % 4) + ": GL " + std::to_string(static_cast<double>(a[first])) + ", C " +
      std::to_string(static_cast<double>(b[first]));
}

struct Fixture {
  std::vector<ShaderDecl> decls;
  Variant lit_linear, lit_display;
  const ShaderFamily *lit = nullptr;
  SceneDeferredFrame frame;
};

void run(const Fixture &fx, Backend b, Api api) {
  const std::string name = config_name(b, api);
  std::string err;
  auto ctx = open_context(b, api, "hdr paths " + name);
  if (!ctx) return;
  GlRenderer r(*ctx);
  PassRunner run(r);
  HdrPipelineGl gl(run, api);
  if (!gl.init(*fx.lit, fx.lit_linear, fx.lit_display, fx.frame.in, &err)) {
    check(false, "hdr paths " + name + ": set-up", err);
    return;
  }
  const int w = fx.frame.in.w;
  for (float scale : {0.05f, 1.0f, 4.0f}) {
    const std::string tag = name + ", tone-map scale " + std::to_string(scale).substr(0, 4);
    HdrFrameC c;
    std::vector<uint8_t> got8;
    if (!gl.integer_frame(fx.frame.in.shared, scale, &err) || !read_rgba8(r.gl(), gl.display(), &got8, &err)) {
      check(false, "integer path " + tag, err);
      continue;
    }
    hdr_integer_frame_c(*fx.lit, fx.lit_display, fx.frame.in, scale, &c);
    std::string d = first_difference(got8, c.display, w);
    check(d.empty(), "integer path " + tag + ": RGBA8 frame equals the C frame", d);

    HdrSettings s;
    s.tone_map_scale = scale;
    s.bloom_amount = 0.4f;
    s.bloom_exponent = 1.5f;
    std::vector<float> hdr, bloom;
    if (!gl.float_frame(fx.frame.in.shared, s, &err) || !read_rgba8(r.gl(), gl.display(), &got8, &err) ||
        !read_float(r.gl(), gl.hdr(), &hdr, &err) || !read_float(r.gl(), gl.bloom(), &bloom, &err)) {
      check(false, "float path " + tag, err);
      continue;
    }
    hdr_float_frame_c(*fx.lit, fx.lit_linear, fx.frame.in, s, &c);
    d = first_difference(hdr, c.hdr, w);
    check(d.empty(), "float path " + tag + ": RGBA16F linear frame equals the C frame (toward-zero fp16)", d);
    d = first_difference(bloom, c.bloom, c.bw);
    check(d.empty(), "float path " + tag + ": RGBA16F bloom (downsample, blur X, blur Y) equals the C bloom", d);
    d = first_difference(got8, c.display, w);
    check(d.empty(), "float path " + tag + ": RGBA8 result equals the C result", d);
    // Not a test that cannot fail: the frames hold HDR values and a visible bloom.
    float hmax = 0, bmax = 0;
    for (float v : hdr) hmax = v > hmax ? v : hmax;
    for (float v : bloom) bmax = v > bmax ? v : bmax;
    long codes[256] = {0};
    for (uint8_t v : got8) ++codes[v];
    int used = 0;
    for (long k : codes) used += k > 0;
    if (scale != 1.0f) continue;
    check(hmax > 4.f && bmax > 0.5f && used > 64, "float path " + tag + ": the frame is HDR and not trivial",
          "max linear " + std::to_string(hmax) + ", max bloom " + std::to_string(bmax) + ", codes used " +
              std::to_string(used));
  }
}

}  // namespace

int main() {
  ts_math_init();
  Fixture fx;
  std::string err, note;
  if (!load_shader_decls(&fx.decls, &err) || !hdr_lit_variant(fx.decls, 0, &fx.lit_linear, &err) ||
      !hdr_lit_variant(fx.decls, 2, &fx.lit_display, &err)) {
    check(false, "set-up", err);
    return 1;
  }
  fx.lit = find_family("model_lighting");
  // 70 x 42: not a multiple of 4, so the quarter-size bloom (17 x 10) does not tile the frame exactly.
  if (!fx.lit || !hdr_scene_frame(kHdrDaylightGltf, 70, 42, &fx.frame, &note, &err)) {
    check(false, "set-up", err);
    return 1;
  }
  printf("# scene: %s\n", note.c_str());
  for (const BackendApi &c : all_gl_configs()) run(fx, c.backend, c.api);
  return g_failed ? 1 : 0;
}
