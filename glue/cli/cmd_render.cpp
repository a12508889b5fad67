// tiershade cli: `render` subcommand: a glTF scene through the variants it needs, on llvmpipe
// (OSMesa or EGL) or the C fallback, written as EXR (the lit pass, RGBA32F) and PNG (the
// final display frame). Prints the variants built and why, and what the selection saved.
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <chrono>
#include <cstdio>
#include <map>
#include <memory>
#include <thread>
#include <vector>

#include "cli/args.h"
#include "cli/memory_estimate.h"
#include "conform/conform.h"
#include "bundle/draw_dump.h"
#include "gl/float_target.h"
#include "base/image.h"
#include "io/atomic_file.h"
#include "io/exr.h"
#include "io/png.h"
#include "scene/scene.h"
#include "scene/selection.h"
#include "scene/frame.h"
#include "scene/prepare.h"
#include "scene/msaa.h"
#include "base/stats.h"

namespace {

// Peak resident memory of this process (VmHWM of /proc/self/status), MiB; -1 if unknown.
double peak_mib() {
  FILE *f = fopen("/proc/self/status", "r");
  if (!f) return -1;
  char line[256];
  double kib = -1;
  while (fgets(line, sizeof line, f))
    if (sscanf(line, "VmHWM: %lf kB", &kib) == 1) break;
  fclose(f);
  return kib < 0 ? -1 : kib / 1024.0;
}

using Clock = std::chrono::steady_clock;

// "<scene>: <err>", the scene named once (some errors from prepare.cpp already begin with it).
std::string scene_message(const Scene &s, const std::string &err) {
  if (err.compare(0, s.path.size() + 2, s.path + ": ") == 0) return err;
  return s.path + ": " + err;
}

// Compiles and links every combo of the families the scene uses (the baseline the selection
// is measured against), in a context like the render's; returns the time in ms.
bool compile_all_programs(const SceneSelection &sel, Backend b, Api api, double *ms, std::string *err) {
  auto ctx = GlContext::create(b, api, err);
  if (!ctx) return false;
  GlRenderer r(*ctx);
  const auto t0 = Clock::now();
  for (const Variant *v : sel.all_variants) {
    const GLuint p = build_production_program(r, api, *v, err);
    if (!p) return false;
    r.delete_program(p);
  }
  ctx->gl().Finish();
  *ms = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
  return true;
}

// The first frame (init included) and the median of 5 further frames, in ms.
bool warm_frame_ms(const Scene &s, const SceneSelection &sel, const SceneRenderConfig &cfg, double *first,
                   double *frame, double *lit, std::string *err) {
  const auto t0 = Clock::now();
  SceneRenderer r;
  SceneRenderResult res;
  if (!r.init(s, sel, cfg, err) || !r.frame(&res, err)) return false;
  if (first) *first = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
  std::vector<double> t, l;
  for (int i = 0; i < 5; ++i) {
    if (!r.frame(&res, err)) return false;
    t.push_back(res.frame_ms);
    l.push_back(res.lit_ms);
  }
  *frame = median(t);
  *lit = median(l);
  return true;
}

}  // namespace

// `tiershade render --help`.
const char kHelp[] = R"(usage: tiershade render SCENE.gltf [--tier ps20|ps2b|sm3] [--backend egl|osmesa|cpu]
                        [--api gles3|gles2|gl33] [--hdr integer|float] [--size WxH] -o OUT
                        [--check] [--compile-all] [--threads N] [--progress] [--quiet]
                        [--dump-draws DIR] [--frames N] [--msaa 2|4|8] [--max-memory MIB]
                        [--probe-cubes c|gl]
Renders a glTF 2.0 scene (docs/scenes.md) with only the shader variants it needs and writes
OUT.exr (the lit pass, RGBA32F as the shaders wrote it) and OUT.png (the final frame).
Defaults: sm3, EGL surfaceless GLES 3.0 (OSMesa: GL 3.3), the scene's HDR path, 1280x720.
--backend cpu renders with the C fallback alone (its own rasteriser, the bit-exact twins).
--check: on GL, also shades GL's own G-buffer with the C twin and fails unless equal bit for bit.
--compile-all: also compiles every combo of the families used, to measure what the selection saved.
--dump-draws DIR: GL: writes the draws (geometry, uniform values, textures) and the lit frame, for
a bare engine to replay with a shader bundle (docs/bundles.md; tests/bundle/bare_gl_render).
--frames N: after the first frame (the one written), renders N more with the same renderer and
prints their median ("median frame X ms", with the lit pass and post times): a scene's warm frame
time on a backend, without the bench.
--msaa N: N samples per pixel (default: the scene's "hdr": {"msaa": N}, else none) on the integer
HDR path: a multisampled RGBA8 target with the shaders' in-shader tone map, resolved with
glBlitFramebuffer (GLES 3.0 / GL 3.3; llvmpipe has 4 samples only: 2 allocates 4, 8 is refused);
the C fallback rasterises the same pattern (2 and 8: the standard patterns). The float path and
GLES 2.0 refuse MSAA and say why (docs/rendering.md, "MSAA"). --check then compares GL's
interior pixels with the C twin bit for bit (on GL's multisample G-buffer) and reports the edge
pixels against the C fallback's MSAA frame.
--probe-cubes gl: a GL frame renders the world probes' cube maps on GL (the float target read
back; --check compares each face with the C twin on GL's G-buffer); c (default): the C fallback
renders them while preparing, the same cubes on every backend (docs/world_lighting.md).
--threads N: the C fallback's threads and those of a bake at load (0 = all cores, the default; the
bake gives the same bytes for any N).

--max-memory MIB: what input files and the render may take (default 1024): an image, accessor,
probe set, lightmap page or --size that needs more is refused before it is read, naming the
limit (docs/reliability.md). --size is at most 8192x8192.)";

int cmd_render(int argc, char **argv) {
  Args a("render", argc, argv, {"--help", "--check", "--quiet", "--progress", "--compile-all", "--report-memory"},
         {"--tier", "--backend", "--api", "--hdr", "--size", "-o", "--threads", "--exposure-frames", "--dump-draws",
          "--frames", "--max-memory", "--msaa", "--probe-cubes"});
  if (a.help(kHelp)) return 0;
  if (a.positional().size() != 1) a.fail("expected one scene file (tiershade render SCENE.gltf -o OUT)");
  if (!a.has("-o")) a.fail("-o OUT is required");
  Tier tier = Tier::SM3;
  if (a.has("--tier") && !parse_tier(a.get("--tier"), &tier)) a.fail("unknown tier '" + a.get("--tier") + "'");
  SceneRenderConfig cfg;
  if (a.has("--backend")) {
    const std::string b = a.get("--backend");
    if (b == "cpu")
      cfg.backend = Backend::CPU;
    else if (!parse_backend(b, &cfg.backend) || cfg.backend == Backend::CPU)
      a.fail("unknown backend '" + b + "' (egl, osmesa, cpu)");
  }
  cfg.api = cfg.backend == Backend::OSMesa ? Api::GL33 : Api::GLES3;
  if (a.has("--api") && !parse_api(a.get("--api"), &cfg.api)) a.fail("unknown API '" + a.get("--api") + "'");
  std::string why;
  if (cfg.backend != Backend::CPU && !config_supported(cfg.backend, cfg.api, &why)) a.fail(why);
  const std::string hdr = a.get("--hdr");
  if (!hdr.empty() && hdr != "integer" && hdr != "float") a.fail("unknown HDR path '" + hdr + "' (integer, float)");
  if (a.has("--size") && !parse_wxh(a.get("--size"), 1, 8192, &cfg.w, &cfg.h))
    a.fail("bad --size '" + a.get("--size") + "' (WxH: two integers, 1..8192 each, as 1280x720)");
  apply_max_memory(a);
  cfg.threads = a.get_int("--threads", 0, 0, 256);
  cfg.exposure_frames = a.get_int("--exposure-frames", cfg.exposure_frames, 1, 10000);
  cfg.check = a.flag("--check");
  if (a.has("--probe-cubes")) {
    const std::string pc = a.get("--probe-cubes");
    if (pc != "c" && pc != "gl") a.fail("--probe-cubes " + pc + ": expected c or gl");
    if (pc == "gl" && cfg.backend == Backend::CPU) a.fail("--probe-cubes gl renders the cubes on GL: it needs a GL backend");
    cfg.gl_probe_cubes = pc == "gl";
  }
  const int warm_frames = a.get_int("--frames", 0, 0, 10000);
  const int msaa_arg = a.has("--msaa") ? a.get_int("--msaa", 0, 1, 8) : -1;
  if (msaa_arg > 1 && msaa_arg != 2 && msaa_arg != 4 && msaa_arg != 8)
    a.fail("--msaa " + a.get("--msaa") + ": samples per pixel are 1 (none), 2, 4 or 8");
  if (warm_frames > 0 && cfg.check) a.fail("--frames times warm frames; --check compares one frame: use one or the other");
  if (cfg.check && cfg.backend == Backend::CPU) a.fail("--check compares GL with C: it needs a GL backend");
  if (a.has("--dump-draws") && cfg.backend == Backend::CPU)
    a.fail("--dump-draws captures GL draws: it needs a GL backend");
  DumpFrame dump;
  std::string dump_err;
  bool first_frame = true;  // the draw dump captures the first frame only (--frames renders more)
  std::map<int, std::shared_ptr<const TextureDesc>> dump_textures;  // one copy per scene texture
  if (a.has("--dump-draws")) {
    cfg.on_draw = [&](const GlFns &gl, const PreparedScene &ps, const PreparedDraw &d, GLuint prog) {
      if (!first_frame) return;
      DumpDraw dd;
      dd.shader = d.variant->shader->name;
      dd.variant = d.variant->name();
      // The draw's arrays as bound (a shared mesh's in object space: its u_model is a uniform).
      dd.position = d.geo->position;
      dd.normal = d.geo->normal;
      dd.uv = d.geo->uv;
      dd.tangent = d.geo->tangent;
      dd.lightmap = d.geo->lightmap;
      dd.indices = d.geo->indices;
      for (int t : d.tex) {
        auto &shared = dump_textures[t];
        if (!shared) shared = std::make_shared<const TextureDesc>(ps.textures.at(t));
        dd.textures.push_back(shared);
      }
      if (!dump_capture_uniforms(gl, prog, &dd.uniforms, &dump_err) && dump_err.empty())
        dump_err = "uniform capture failed";
      dump.draws.push_back(std::move(dd));
    };
    cfg.on_lit = [&](const ImageF &lit) {
      if (first_frame) dump.rgba = lit.rgba;
    };
  }
  const bool quiet = a.flag("--quiet");
  const bool show_progress = a.flag("--progress") || isatty(2);
  if (show_progress)
    cfg.progress = [](const char *stage, double f) {
      fprintf(stderr, "\r%s: %3.0f%%%s", stage, f * 100, f >= 1 ? "\n" : "");
    };
  std::string out = a.get("-o");
  for (const char *ext : {".png", ".exr"})
    if (out.size() > 4 && out.compare(out.size() - 4, 4, ext) == 0) out.resize(out.size() - 4);
  {  // OUT names files: not empty, not a directory ("out/" would write out/.exr)
    const size_t slash = out.rfind('/');
    const std::string base = slash == std::string::npos ? out : out.substr(slash + 1);
    if (base.empty() || base == "." || base == "..")
      a.fail("-o '" + a.get("-o") + "': expected a file name (OUT writes OUT.exr and OUT.png)");
  }

  const auto t0 = Clock::now();
  Scene scene;
  std::string err;
  if (!load_scene(a.positional()[0], &scene, &err)) {
    fprintf(stderr, "tiershade render: %s\n", err.c_str());
    return 1;
  }
  scene.lightmaps.bake_progress = !quiet;  // a long bake at load shows its passes (docs/baking.md)
  scene.lightmaps.threads = cfg.threads;  // and runs on --threads (the same bytes for any count)
  cfg.msaa = msaa_arg >= 0 ? msaa_arg : scene.hdr.msaa;
  if (cfg.msaa > 1 && a.has("--dump-draws")) {
    fprintf(stderr, "tiershade render: %s: --dump-draws captures the one-sample frame a bare engine replays "
            "(docs/bundles.md); render it without MSAA (--msaa 1)\n", scene.path.c_str());
    return 1;
  }
  if (!render_fits_memory(scene, cfg.w, cfg.h, cfg.backend != Backend::CPU, cfg.check, &err, cfg.msaa)) {
    fprintf(stderr, "tiershade render: %s: %s\n", scene.path.c_str(), err.c_str());
    return 1;
  }
  SceneSelection sel;
  if (!select_scene_variants(scene, tier, hdr, &sel, &err)) {
    fprintf(stderr, "tiershade render: %s\n", scene_message(scene, err).c_str());
    return 1;
  }
  if (cfg.msaa > 1 && sel.hdr_path == "float") {
    fprintf(stderr, "tiershade render: %s: --msaa %d: %s\n", scene.path.c_str(), cfg.msaa,
            msaa_refusal(PreparedScene(), true, cfg.backend == Backend::CPU, cfg.api, cfg.msaa).c_str());
    return 1;
  }
  // A draw dump holds geometry draws only: the skybox's full-screen pass is not in its format yet
  // (docs/bundles.md), so a dumped frame is drawn without it, on GL and in C alike.
  const bool dump_without_sky = a.has("--dump-draws") && sel.sky;
  if (dump_without_sky) sel.sky = nullptr;
  if (!quiet) {
    printf("scene %s: %zu primitives, %zu materials, %zu lights, %zu probes; tier %s, %s HDR path, %s\n",
           scene.path.c_str(), scene.primitives.size(), scene.materials.size(), scene.lights.size(),
           scene.probes.size(), tier_name(tier), sel.hdr_path.c_str(),
           cfg.backend == Backend::CPU ? "C fallback"
                                       : (std::string(backend_name(cfg.backend)) + " " + api_name(cfg.api)).c_str());
    printf("variants built (%zu):\n", sel.variants.size());
    for (size_t i = 0; i < sel.variants.size(); ++i) {
      printf("  %s %s\n", sel.variants[i].shader->name.c_str(), sel.variants[i].name().c_str());
      for (const std::string &w : sel.variant_why[i]) printf("      %s\n", w.c_str());
    }
  }
  SceneRenderResult res;
  std::vector<double> warm_frame, warm_lit, warm_post;  // --frames: the warm frames' times
  {
    const auto t_init = Clock::now();
    SceneRenderer renderer;
    bool ok = renderer.init(scene, sel, cfg, &err) && renderer.frame(&res, &err);
    res.frame_ms = std::chrono::duration<double, std::milli>(Clock::now() - t_init).count();  // init included
    first_frame = false;
    SceneRenderResult warm;  // one result for the warm frames: its frame buffers are reused, as an engine's
    for (int i = 0; ok && i < warm_frames; ++i) {
      ok = renderer.frame(&warm, &err);
      warm_frame.push_back(warm.frame_ms);
      warm_lit.push_back(warm.lit_ms);
      warm_post.push_back(warm.post_ms);
    }
    if (!ok) {
      fprintf(stderr, "tiershade render: %s\n", scene_message(scene, err).c_str());
      return 1;
    }
  }
  const double total_ms = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
  if (a.has("--dump-draws")) {
    dump.w = res.w;
    dump.h = res.h;
    dump.depth_format = "DEPTH_COMPONENT24";  // as glue/scene/gl_renderer.cpp allocates it
    if (scene.camera >= 0 && scene.camera < static_cast<int>(scene.cameras.size())) {
      const SceneCamera &c = scene.cameras[scene.camera];
      DumpCamera &dc = dump.camera;
      dc.present = true;
      dc.orthographic = c.orthographic;
      for (int k = 0; k < 3; ++k) {
        dc.eye[k] = c.eye[k];
        dc.forward[k] = c.forward[k];
        dc.up[k] = c.up[k];
      }
      dc.yfov = c.yfov;
      dc.znear = c.znear;
      dc.zfar = c.zfar;
      dc.xmag = c.xmag;
      dc.ymag = c.ymag;
    }
    if (!dump_err.empty() || !write_draw_dump(a.get("--dump-draws"), dump, &dump_err)) {
      fprintf(stderr, "tiershade render: --dump-draws: %s\n", dump_err.c_str());
      return 1;
    }
  }
  // The two files on two threads, each to a temporary name of this process (written whole and
  // synced by the writers' own atomic files); both are renamed into place only when both were
  // written, so a failed run leaves no frame behind and the previous OUT.exr and OUT.png intact.
  const std::string tmp = temp_path_for(out);
  std::string png_err;
  bool png_ok = false;
  std::thread png_writer([&] { png_ok = write_png_rgba8(tmp + ".png", res.w, res.h, res.display, &png_err); });
  const bool exr_ok = write_exr(tmp + ".exr", res.lit, &err);
  png_writer.join();
  bool ok = exr_ok && png_ok;
  std::string wfail = exr_ok ? png_err : err;
  if (ok) {
    // OUT.exr first; if OUT.png then cannot be replaced, the previous OUT.exr (kept as a hard
    // link) comes back, or the new one goes: the pair is never half replaced.
    const std::string exr = out + ".exr", keep = tmp + ".prev.exr";
    const bool had = link(exr.c_str(), keep.c_str()) == 0;
    if (std::rename((tmp + ".exr").c_str(), exr.c_str()) != 0) {
      wfail = exr + ": cannot replace (" + std::strerror(errno) + ")";
      ok = false;
    } else if (std::rename((tmp + ".png").c_str(), (out + ".png").c_str()) != 0) {
      wfail = out + ".png: cannot replace (" + std::strerror(errno) + ")";
      ok = false;
      if (had ? std::rename(keep.c_str(), exr.c_str()) != 0 : unlink(exr.c_str()) != 0)
        wfail += "; and " + exr + " could not be restored";
    }
    if (had) unlink(keep.c_str());
  }
  if (!ok) {
    unlink((tmp + ".exr").c_str());
    unlink((tmp + ".png").c_str());
    // The writers name the temporary: name the file the user asked for.
    for (size_t p; (p = wfail.find(tmp)) != std::string::npos;) wfail.replace(p, tmp.size(), out);
    fprintf(stderr, "tiershade render: %s\n", wfail.c_str());
    return 1;
  }
  if (!quiet) {
    for (const std::string &n : res.notes) printf("note: %s\n", n.c_str());
    if (dump_without_sky) printf("note: --dump-draws: the frame is drawn without the skybox (draw dumps hold geometry draws only)\n");
    printf("selection: %zu of %d combos of the families used (%.1f%%)\n", sel.variants.size(), sel.all_combos,
           100.0 * sel.variants.size() / std::max(1, sel.all_combos));
    if (cfg.backend != Backend::CPU) {
      printf("compile: %.1f ms for the %zu selected variants", res.compile_ms, sel.variants.size());
      if (a.flag("--compile-all")) {
        double all_ms = 0;
        if (!compile_all_programs(sel, cfg.backend, cfg.api, &all_ms, &err)) {
          fprintf(stderr, "\ntiershade render: compiling every combo: %s\n", err.c_str());
          return 1;
        }
        printf("; every combo: %.1f ms (%d programs), %.1fx the selection\n", all_ms, sel.all_combos,
               all_ms / std::max(1e-3, res.compile_ms));
        // The frame an engine without selection would draw: every feature compiled in.
        SceneSelection uber;
        SceneRenderConfig c2 = cfg;
        c2.check = false;
        c2.on_draw = nullptr;
        c2.on_lit = nullptr;
        c2.progress = nullptr;
        double sel_frame = 0, sel_lit = 0, uber_first = 0, uber_frame = 0, uber_lit = 0;
        if (!select_scene_variants(scene, tier, hdr, &uber, &err, true) ||
            !warm_frame_ms(scene, sel, c2, nullptr, &sel_frame, &sel_lit, &err) ||
            !warm_frame_ms(scene, uber, c2, &uber_first, &uber_frame, &uber_lit, &err)) {
          fprintf(stderr, "tiershade render: all-features frame: %s\n", err.c_str());
          return 1;
        }
        printf(
            "all features compiled in (%zu variants): first frame %.1f ms, frame %.1f ms, lit pass %.1f ms\n"
            "the selection (%zu variants):         first frame %.1f ms, frame %.1f ms, lit pass %.1f ms"
            " (medians of 5; lit pass %.2fx faster)\n",
            uber.variants.size(), uber_first, uber_frame, uber_lit, sel.variants.size(), res.frame_ms, sel_frame,
            sel_lit, uber_lit / std::max(1e-3, sel_lit));
      } else {
        printf(" (--compile-all measures every combo and the all-features frame)\n");
      }
    }
    printf("frame %dx%d: prepare %.1f ms, lit pass %.1f ms, post %.1f ms, frame %.1f ms, total with loading %.1f ms\n",
           cfg.w, cfg.h, res.prepare_ms, res.lit_ms, res.post_ms, res.frame_ms, total_ms);
    if (res.msaa_samples > 1) printf("msaa: %d samples per pixel, resolved as RGBA8\n", res.msaa_samples);
    if (res.auto_exposure) printf("auto exposure: tone-map scale %.4f\n", res.tone_map_scale);
    printf("wrote %s.exr (lit pass) and %s.png\n", out.c_str(), out.c_str());
  }
  if (warm_frames > 0)  // printed with --quiet too: it is what --frames asks for
    printf("median frame %.2f ms (lit pass %.2f ms, post %.2f ms; median of %d warm frames at %dx%d)\n",
           median(warm_frame), median(warm_lit), median(warm_post), warm_frames, cfg.w, cfg.h);
  if (!quiet || a.flag("--report-memory")) {
    printf("peak memory: %.1f MiB\n", peak_mib());
    printf("geometry: %.1f KiB of vertex arrays in %d sets for %d draws (instances of a mesh share one)\n",
           static_cast<double>(res.geometry_bytes) / 1024.0, res.geometries, res.draws);
  }
  if (cfg.check && res.check_msaa_interior >= 0) {
    printf("check: MSAA interior pixels, GL's resolved frame vs the C twin on GL's G-buffer: %ld of %ld differ (max %d "
           "codes)\n",
           res.check_mismatched, res.check_pixels, res.check_msaa_interior_max);
    printf("check: MSAA background pixels (no sample covered): %ld of %ld differ\n", res.check_msaa_background_mismatched,
           res.check_msaa_background);
    printf("check: MSAA edge pixels, GL vs the C fallback's MSAA frame: %ld pixels, %ld beyond 1 code, %ld beyond "
           "64 codes, max %d\n",
           res.check_msaa_edge, res.check_msaa_edge_over_1, res.check_msaa_edge_over_64, res.check_msaa_edge_max);
    printf("check: HDR path and colour correction on GL vs their C twins on GL's lit frame: %ld of %ld channels differ\n",
           res.check_post_mismatched, res.check_post_channels);
    // Interior pixels: tolerance 0 (the same records through the same arithmetic); edge pixels
    // are reported (their bound is tests/cli/test_msaa.sh's).
    if (res.check_mismatched != 0 || res.check_msaa_background_mismatched != 0 || res.check_post_mismatched != 0)
      return 1;
  } else if (cfg.check) {
    printf("check: GL frame vs the C twin on GL's G-buffer: %ld of %ld covered pixels differ (max %u ULP)\n",
           res.check_mismatched, res.check_pixels, res.check_max_ulp);
    printf(
        "check: HDR path and colour correction on GL vs their C twins on GL's lit frame: %ld of %ld channels differ\n",
        res.check_post_mismatched, res.check_post_channels);
    if (res.check_cube_mismatched >= 0)
      printf("check: probe cube maps on GL vs the C twin on GL's G-buffer of each face: %ld of %ld texels differ\n",
             res.check_cube_mismatched, res.check_cube_texels);
    if (res.check_mismatched != 0 || res.check_post_mismatched != 0 || res.check_cube_mismatched > 0) return 1;
  }
  return 0;
}
