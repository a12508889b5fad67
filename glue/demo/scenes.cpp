// tiershade demo: the scenes section of `tiershade demo` (`make demo`): every shipped glTF scene
// (scenes/*.gltf, docs/scenes.md) rendered as `tiershade render` does on the default backend
// (EGL surfaceless GLES 3.0 on llvmpipe), checked against the C twins on GL's own inputs, and
// by the C fallback alone; the variants each one needed and the frames are written to out/.
#include <cstdio>

#include "demo/scene_files.h"
#include "families/family.h"
#include "io/exr.h"
#include "io/png.h"
#include "scene/scene.h"
#include "scene/selection.h"
#include "scene/frame.h"

namespace {

const char *kScenes[] = {"model_lighting", "world_lighting", "hdr_atrium"};

bool run(const DemoOptions &opt, std::string *err) {
  const int w = 1280, h = 720;
  printf("%-16s %-8s %-9s %-10s %-28s %-28s %10s %10s\n", "scene", "tier", "variants", "HDR path",
         "GL = C twin (lit pixels)", "GL = C twin (post channels)", "GL ms", "C ms");
  for (const char *name : kScenes) {
    const std::string path = repo_file((std::string("scenes/") + name + ".gltf").c_str());
    Scene s;
    if (!load_scene(path, &s, err)) return false;
    SceneSelection sel;
    if (!select_scene_variants(s, Tier::SM3, "", &sel, err)) return false;
    SceneRenderConfig cfg;
    cfg.w = w;
    cfg.h = h;
    cfg.backend = Backend::EGL;
    cfg.api = Api::GLES3;
    cfg.check = true;
    SceneRenderResult gl, c;
    if (!render_scene(s, sel, cfg, &gl, err)) return false;
    cfg.backend = Backend::CPU;
    cfg.check = false;
    if (!render_scene(s, sel, cfg, &c, err)) return false;
    const std::string base = opt.dir + "/scene_" + name;
    if (!write_png(base + ".png", display_image(gl), Encode::Linear, err) || !write_exr(base + ".exr", gl.lit, err) ||
        !write_png(base + "_cpu.png", display_image(c), Encode::Linear, err))
      return false;
    char lit[64], post[64];
    snprintf(lit, sizeof lit, "%ld of %ld differ", gl.check_mismatched, gl.check_pixels);
    snprintf(post, sizeof post, "%ld of %ld differ", gl.check_post_mismatched, gl.check_post_channels);
    printf("%-16s %-8s %-9s %-10s %-28s %-28s %10.1f %10.1f\n", name, "sm3",
           (std::to_string(sel.variants.size()) + "/" + std::to_string(sel.all_combos)).c_str(), sel.hdr_path.c_str(),
           lit, post, gl.frame_ms, c.frame_ms);
    if (gl.check_mismatched != 0 || gl.check_post_mismatched != 0) {
      *err = path + ": the GL frame differs from the C twins on GL's inputs";
      return false;
    }
  }
  printf("wrote %s/scene_*.png (GL), scene_*_cpu.png (C fallback), scene_*.exr (lit passes)\n", opt.dir.c_str());
  return true;
}

const DemoSection kSection = {"scenes", run};
const DemoRegistrar kRegister(&kSection);

}  // namespace
