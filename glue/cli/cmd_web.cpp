// tiershade cli: `web` subcommand: the WebGL 2 demo page of a scene from its essl300 bundle and its
// draw dump, and its headless check against tiershade render (glue/browser/webgl_scene.h;
// docs/bundles.md, "The WebGL 2 demo page").
#include <cstdio>

#include "browser/webgl_scene.h"
#include "cli/args.h"

namespace {
const char kHelp[] = R"(usage: tiershade web --bundle BUNDLE --dump DUMP -o DIR [--check] [--tolerance A,R,S] [--timeout S]
Writes DIR/index.html, webgl_scene.js and scene.js: a page that renders the scene in WebGL 2 from
its bundle (tiershade variants SCENE --tier T --target essl300 -o BUNDLE) and its draw dump
(tiershade render SCENE --tier T --dump-draws DUMP ...), with an orbit camera (drag: orbit, wheel:
distance, double-click: back to the scene's camera). Open DIR/index.html in a browser; it needs no
server and nothing of tiershade.
--check: then opens DIR/index.html?check in headless Chromium (ANGLE on SwiftShader), reads back the
first frame (RGBA32F, at the dump's camera) and compares it with the dump's frame.f32 (tiershade
render's lit pass on llvmpipe): prints the camera uniforms' agreement and the per-pixel difference
distribution; exit 1 when outside the tolerance: a pixel is within when every channel differs by at
most A + R x |llvmpipe's value|, and at most the share S of the pixels may not be (default
0.015625,0.0625,0.005; docs/bundles.md says why). --timeout: the browser is killed after S seconds
(default 120).
Exit 2 on bad arguments or unreadable inputs (the file named), 1 when the check fails.)";
}  // namespace

int cmd_web(int argc, char **argv) {
  Args a("web", argc, argv, {"--help", "--check"}, {"--bundle", "--dump", "-o", "--timeout", "--tolerance"});
  if (a.help(kHelp)) return 0;
  a.no_positional();
  if (!a.has("--bundle") || !a.has("--dump")) a.fail("needs --bundle BUNDLE and --dump DUMP");
  if (!a.has("-o")) a.fail("needs -o DIR");
  const int timeout = a.get_int("--timeout", 120, 1, 3600);
  WebSceneTolerance tol;
  if (a.has("--tolerance")) {
    const std::string t = a.get("--tolerance");
    char tail = 0;
    if (sscanf(t.c_str(), "%lf,%lf,%lf%c", &tol.abs, &tol.rel, &tol.share, &tail) != 3 || !(tol.abs >= 0) ||
        !(tol.rel >= 0) || !(tol.share >= 0 && tol.share <= 1))
      a.fail("--tolerance " + t + ": expected A,R,S (three numbers >= 0, S at most 1)");
  }
  WebScenePage page;
  std::string err;
  const std::string dir = a.get("-o");
  if (!webgl_scene_write_page(a.get("--bundle"), a.get("--dump"), dir, &page, &err)) {
    fprintf(stderr, "tiershade web: %s\n", err.c_str());
    // the output refused or not writable (the message starts with DIR): 1; the inputs: 2
    return err.compare(0, dir.size(), dir) == 0 ? 1 : 2;
  }
  printf("wrote %s/index.html: %dx%d, %zu draws, %zu programs, %zu textures, scene.js %.1f MB\n", dir.c_str(), page.w,
         page.h, page.draws, page.programs, page.textures, page.bytes / 1048576.0);
  if (!a.flag("--check")) return 0;
  WebSceneCheck c;
  if (!webgl_scene_check(dir, a.get("--dump"), timeout, tol, &c, &err)) {
    fprintf(stderr, "tiershade web: --check: %s\n", err.c_str());
    return 1;
  }
  printf("chromium: %s\n", c.renderer.c_str());
  printf("camera uniforms recomputed in JavaScript: %d of %d elements differ from the dump's\n", c.view_proj_differ,
         c.view_proj_compared);
  printf("tolerance: |difference| <= %g + %g |value| per channel on all but %g%% of the pixels\n", tol.abs, tol.rel,
         100 * tol.share);
  printf("pixels: %zu; bit-equal %.2f%%; within tolerance %.2f%%; largest channel difference per pixel: median %.3g, "
         "99th percentile %.3g, max %.3g at (%d, %d)\n",
         c.pixels, 100.0 * c.equal / c.pixels, 100.0 * c.within / c.pixels, c.median_diff, c.p99_diff, c.max_diff,
         c.worst_x, c.worst_y);
  printf("%s\n", c.pass ? "ok: the page's first frame matches tiershade render" : "FAIL: outside the tolerance");
  return c.pass ? 0 : 1;
}
