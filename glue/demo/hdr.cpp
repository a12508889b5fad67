// tiershade demo: the `demo` section of the HDR work (docs/hdr.md):
//   1. the HDR scene at the tone-map scales 0.05, 1 and 4 (the talk's Lost Coast row),
//      through the integer path and the float path (with bloom), on every GL backend
//      and in C, GL frames compared with the C frames code for code;
//   2. the exposure adaptation sequence from a dark room into daylight (integer path,
//      running histogram, controller), on GL and in C, exposures compared frame by frame.
// Writes OUT/hdr_*.png (display images), OUT/hdr_*.exr (the linear fp16 frame, the bloom,
// the histograms of the sequence) and OUT/hdr_adaptation.svg (exposure against time).
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include <unistd.h>

#include "demo/exposure_walk.h"
#include "demo/hdr_scene.h"
#include "demo/section_util.h"
#include "io/exr.h"
#include "io/png.h"
#include "io/atomic_file.h"

namespace {

const float kScales[3] = {0.05f, 1.0f, 4.0f};

ImageF image_of_codes(const std::vector<uint8_t> &codes, int w, int h) {
  ImageF img;
  img.w = w;
  img.h = h;
  img.rgba.resize(codes.size());
  for (size_t i = 0; i < codes.size(); ++i) img.rgba[i] = codes[i] / 255.0f;
  return img;
}

ImageF image_of_floats(const std::vector<float> &v, int w, int h) {
  ImageF img;
  img.w = w;
  img.h = h;
  img.rgba = v;
  return img;
}

// Half size by 2x2 box (display images, for the film strip).
ImageF half_size(const ImageF &a) {
  ImageF o;
  o.w = a.w / 2;
  o.h = a.h / 2;
  o.rgba.assign(static_cast<size_t>(o.w) * o.h * 4, 0.f);
  for (int y = 0; y < o.h; ++y)
    for (int x = 0; x < o.w; ++x)
      for (int c = 0; c < 4; ++c) {
        float s = 0;
        for (int j = 0; j < 2; ++j)
          for (int i = 0; i < 2; ++i) s += a.rgba[((static_cast<size_t>(2 * y + j)) * a.w + 2 * x + i) * 4 + c];
        o.rgba[(static_cast<size_t>(y) * o.w + x) * 4 + c] = s * 0.25f;
      }
  return o;
}

std::string scale_tag(float s) {
  char b[16];
  snprintf(b, sizeof b, "%g", s);
  return b;
}

long count_diff(const std::vector<uint8_t> &a, const std::vector<uint8_t> &b) {
  if (a.size() != b.size()) return -1;
  long n = 0;
  for (size_t i = 0; i < a.size(); ++i) n += a[i] != b[i];
  return n;
}

struct Scenes {
  std::vector<ShaderDecl> decls;  // the variants below point into it
  const ShaderFamily *lit = nullptr;
  Variant lit_linear, lit_display;
  SceneDeferredFrame day, room;
  std::string note;
};

bool make_scenes(int w, int h, Scenes *s, std::string *err) {
  if (!load_shader_decls(&s->decls, err) || !hdr_lit_variant(s->decls, 0, &s->lit_linear, err) ||
      !hdr_lit_variant(s->decls, 2, &s->lit_display, err))
    return false;
  s->lit = find_family("model_lighting");
  if (!s->lit) {
    *err = "the model_lighting family is not registered";
    return false;
  }
  std::string room_note;
  return hdr_scene_frame(kHdrDaylightGltf, w, h, &s->day, &s->note, err) &&
      hdr_scene_frame(kHdrDarkRoomGltf, w, h, &s->room, &room_note, err);
}

// 1. The tone-map row.
bool tonemap_row(const DemoOptions &opt, const Scenes &sc, int *failures, std::string *err) {
  const FamilyInputs &in = sc.day.in;
  const int w = in.w, h = in.h;
  HdrFrameC ci[3], cf[3];
  HdrSettings set[3];
  std::vector<ImageF> row_i, row_f;
  for (int k = 0; k < 3; ++k) {
    set[k].tone_map_scale = kScales[k];
    hdr_integer_frame_c(*sc.lit, sc.lit_display, in, kScales[k], &ci[k]);
    hdr_float_frame_c(*sc.lit, sc.lit_linear, in, set[k], &cf[k]);
    const std::string t = scale_tag(kScales[k]);
    if (!write_png_rgba8(opt.dir + "/hdr_integer_scale_" + t + ".png", w, h, ci[k].display, err) ||
        !write_png_rgba8(opt.dir + "/hdr_float_scale_" + t + ".png", w, h, cf[k].display, err))
      return false;
    row_i.push_back(image_of_codes(ci[k].display, w, h));
    row_f.push_back(image_of_codes(cf[k].display, w, h));
  }
  if (!write_exr_half(opt.dir + "/hdr_float_linear.exr", image_of_floats(cf[1].hdr, w, h), err) ||
      !write_exr_half(opt.dir + "/hdr_float_bloom.exr", image_of_floats(cf[1].bloom, cf[1].bw, cf[1].bh), err) ||
      !write_png(opt.dir + "/hdr_tonemap_row_float.png", hstack({&row_f[0], &row_f[1], &row_f[2]}, 4, 1.f),
                 Encode::Linear, err) ||
      !write_png(opt.dir + "/hdr_tonemap_row_integer.png", hstack({&row_i[0], &row_i[1], &row_i[2]}, 4, 1.f),
                 Encode::Linear, err))
    return false;
  printf("%s\n", sc.note.c_str());
  printf("%-8s %-6s %-16s %12s\n", "path", "scale", "backend", "mismatched");
  const bool gl_ok = for_each_gl_config(
      opt,
      [&](const BackendApi &cfg, const std::string &tag, GlRenderer &r) {
        PassRunner run(r);
        HdrPipelineGl gl(run, cfg.api);
        if (!gl.init(*sc.lit, sc.lit_linear, sc.lit_display, in, err)) return false;
        for (int k = 0; k < 3; ++k) {
          std::vector<uint8_t> got;
          if (!gl.integer_frame(in.shared, kScales[k], err) || !read_rgba8(r.gl(), gl.display(), &got, err))
            return false;
          const long di = count_diff(got, ci[k].display);
          if (!gl.float_frame(in.shared, set[k], err) || !read_rgba8(r.gl(), gl.display(), &got, err)) return false;
          const long df = count_diff(got, cf[k].display);
          if (di || df) ++*failures;
          printf("%-8s %-6g %-16s %12ld\n%-8s %-6g %-16s %12ld\n", "integer", kScales[k], tag.c_str(), di, "float",
                 kScales[k], tag.c_str(), df);
        }
        return true;
      },
      err);
  if (!gl_ok) return false;
  printf(
      "wrote %s/hdr_tonemap_row_float.png and _integer.png (tone-map scale 0.05 | 1 | 4), hdr_float_linear.exr, "
      "hdr_float_bloom.exr\n",
      opt.dir.c_str());
  return true;
}

// Exposure and goal against time, the door marked.
std::string adaptation_svg(const std::vector<AdaptationFrame> &fr, const AdaptationSpec &spec) {
  const int W = 640, H = 300, L = 60, B = 40, T = 20, R = 20;
  double lo = 1e9, hi = -1e9;
  for (const auto &f : fr) {
    lo = std::fmin(lo, std::log2(std::fmin(f.scale, f.goal)));
    hi = std::fmax(hi, std::log2(std::fmax(f.scale, f.goal)));
  }
  lo = std::floor(lo) - 0.5;
  hi = std::ceil(hi) + 0.5;
  auto X = [&](double f) { return L + (W - L - R) * f / std::max(1, spec.frames - 1); };
  auto Y = [&](double s) { return (H - B) - (H - B - T) * (std::log2(s) - lo) / (hi - lo); };
  std::ostringstream o;
  o << "<svg xmlns='http://www.w3.org/2000/svg' width='" << W << "' height='" << H
    << "' font-family='sans-serif' font-size='12'>\n<rect width='100%' height='100%' fill='white'/>\n"
    << "<line x1='" << L << "' y1='" << H - B << "' x2='" << W - R << "' y2='" << H - B << "' stroke='black'/>\n"
    << "<line x1='" << L << "' y1='" << T << "' x2='" << L << "' y2='" << H - B << "' stroke='black'/>\n"
    << "<line x1='" << X(spec.door_frame) << "' y1='" << T << "' x2='" << X(spec.door_frame) << "' y2='" << H - B
    << "' stroke='#999' stroke-dasharray='4 3'/>\n<text x='" << X(spec.door_frame) + 4 << "' y='" << T + 12
    << "'>door: daylight</text>\n<text x='" << W / 2 << "' y='" << H - 8 << "' text-anchor='middle'>frame (" << spec.fps
    << " per second)</text>\n<text x='14' y='" << H / 2 << "' transform='rotate(-90 14 " << H / 2
    << ")' text-anchor='middle'>tone-map scale (log)</text>\n";
  for (double e = std::ceil(lo); e <= hi; e += 1) {
    char b[160];
    snprintf(b, sizeof b, "<text x='%d' y='%.0f' text-anchor='end'>%g</text>\n", L - 4, Y(std::exp2(e)) + 4,
             std::exp2(e));
    o << b;
  }
  for (int pass = 0; pass < 2; ++pass) {
    o << "<polyline fill='none' stroke='" << (pass ? "#cc3333" : "#3366cc") << "' stroke-width='" << (pass ? 1 : 2)
      << "' points='";
    for (size_t i = 0; i < fr.size(); ++i)
      o << X(static_cast<double>(i)) << "," << Y(pass ? fr[i].goal : fr[i].scale) << " ";
    o << "'/>\n";
  }
  o << "<text x='" << W - R - 150 << "' y='" << T + 12 << "' fill='#3366cc'>exposure</text><text x='" << W - R - 80
    << "' y='" << T + 12 << "' fill='#cc3333'>goal</text>\n</svg>\n";
  return o.str();
}

// 2. The adaptation sequence.
bool adaptation(const DemoOptions &opt, int *failures, std::string *err) {
  const int w = std::max(16, opt.w / 2 / 4 * 4), h = std::max(16, opt.h / 2 / 4 * 4);
  Scenes sc;
  if (!make_scenes(w, h, &sc, err)) return false;
  AdaptationScenes as;
  as.lit = sc.lit;
  as.lit_display = sc.lit_display;
  as.room = sc.day.in;  // the same G-buffer under both lightings
  as.room.shared = sc.room.in.shared;
  as.daylight = sc.day.in;
  AdaptationSpec spec = default_adaptation_spec();
  {
    // The camera has been in the room for a while: start from the room's settled exposure,
    // found by running the loop on the room alone (10 s, at a small size).
    Scenes small;
    if (!make_scenes(80, 40, &small, err)) return false;
    AdaptationScenes pre = as;
    pre.lit_display = small.lit_display;
    pre.room = small.day.in;
    pre.room.shared = small.room.in.shared;
    pre.daylight = pre.room;
    AdaptationSpec in_room = spec;
    in_room.frames = 300;
    in_room.door_frame = in_room.frames;
    std::vector<AdaptationFrame> settle;
    run_adaptation_c(pre, in_room, {}, &settle, nullptr);
    spec.initial_scale = settle.back().scale;
  }
  const std::vector<int> keep = {0, 12, 23, 24, 26, 29, 34, 44, 59, 79, 99, 119};
  std::vector<AdaptationFrame> cf;
  std::vector<HistogramMeasurement> cm;
  run_adaptation_c(as, spec, keep, &cf, &cm);
  // Film strip (half size), histograms (EXR: x bucket, y frame, value = fraction), plot.
  std::vector<ImageF> strip;
  for (int f : keep)
    if (f < spec.frames) strip.push_back(half_size(image_of_codes(cf[f].display, w, h)));
  std::vector<const ImageF *> ptrs;
  for (const auto &s : strip) ptrs.push_back(&s);
  ImageF hist;
  hist.w = AE_BUCKETS;
  hist.h = spec.frames;
  hist.rgba.assign(static_cast<size_t>(hist.w) * hist.h * 4, 1.f);
  for (int f = 0; f < spec.frames; ++f)
    for (int b = 0; b < AE_BUCKETS; ++b) {
      const float v = static_cast<float>(ae_fraction(&cf[f].hist, b));
      // Row 0 of the file is the first frame (ImageF rows are bottom-up).
      float *p = &hist.rgba[(static_cast<size_t>(spec.frames - 1 - f) * hist.w + b) * 4];
      p[0] = p[1] = p[2] = v;
    }
  if (!write_file_atomic(opt.dir + "/hdr_adaptation.svg", adaptation_svg(cf, spec), err) ||
      !write_png(opt.dir + "/hdr_adaptation_strip.png", hstack(ptrs, 2, 1.f), Encode::Linear, err) ||
      !write_exr(opt.dir + "/hdr_adaptation_histograms.exr", hist, err))
    return false;
  int settle = -1;
  const double final_scale = cf.back().scale;
  for (int f = spec.frames - 1; f >= spec.door_frame; --f)
    if (std::fabs(std::log2(cf[f].scale / final_scale)) > 0.14) {
      settle = f + 1;
      break;
    }
  printf(
      "\nadaptation (%dx%d, integer path, %d frames at %g fps, door at frame %d): exposure %.3f in the room "
      "(settled), %.3f outside, within 10%% of it from frame %d (%.2f s after the door)\n",
      w, h, spec.frames, spec.fps, spec.door_frame, cf[spec.door_frame - 1].scale, final_scale, settle,
      (settle - spec.door_frame) / spec.fps);
  printf("%-16s %12s %12s %14s %10s\n", "backend", "exposures", "frames", "histogram", "late reads");
  const bool gl_ok = for_each_gl_config(
      opt,
      [&](const BackendApi &cfg, const std::string &tag, GlRenderer &r) {
        PassRunner run(r);
        std::vector<AdaptationFrame> gf;
        std::vector<HistogramMeasurement> gm;
        int late = 0;
        if (!run_adaptation_gl(run, cfg.backend, cfg.api, as, spec, keep, &gf, &gm, &late, err)) return false;
        long bad_scale = 0, bad_frames = 0, bad_counts = gm.size() == cm.size() ? 0 : 1;
        for (size_t i = 0; i < gf.size() && i < cf.size(); ++i) {
          bad_scale += gf[i].scale != cf[i].scale;
          bad_frames += count_diff(gf[i].display, cf[i].display) != 0;
        }
        for (size_t i = 0; !bad_counts && i < gm.size(); ++i)
          bad_counts += gm[i].bucket != cm[i].bucket || gm[i].frame != cm[i].frame || gm[i].count != cm[i].count;
        if (bad_scale || bad_frames || bad_counts) ++*failures;
        printf("%-16s %12s %12s %14s %10d\n", tag.c_str(), bad_scale ? "DIFFER" : "= C",
               bad_frames ? "DIFFER" : "= C", bad_counts ? "DIFFER" : "= exact", late);
        return true;
      },
      err);
  if (!gl_ok) return false;
  printf("wrote %s/hdr_adaptation_strip.png (frames", opt.dir.c_str());
  for (int f : keep) printf(" %d", f);
  printf("), hdr_adaptation.svg, hdr_adaptation_histograms.exr (17 buckets x %d frames)\n", spec.frames);
  return true;
}

bool run_demo(const DemoOptions &opt, std::string *err) {
  Scenes sc;
  const int w = std::max(16, opt.w / 4 * 4), h = std::max(16, opt.h / 4 * 4);
  if (!make_scenes(w, h, &sc, err)) return false;
  int failures = 0;
  if (!tonemap_row(opt, sc, &failures, err) || !adaptation(opt, &failures, err)) return false;
  return demo_section_result(failures, "GL runs differ from the C twin", err);
}

const DemoSection kHdrDemo = {"hdr", run_demo};
const DemoRegistrar kRegisterHdrDemo(&kHdrDemo);

}  // namespace
