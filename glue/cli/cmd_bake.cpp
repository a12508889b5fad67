// tiershade cli: `bake` subcommand: writes the lightmap page of a scene's LightmappedGeneric faces
// (radiosity-normal-mapped, c_ref/offline/rnm_bake.c, laid out by c_ref/offline/lightmap_page.c) as a float32
// EXR, the page `tiershade render` bakes at load. A scene names such a page in
// extras.tiershade.lightmaps.image to skip the bake, or to bring lightmaps baked elsewhere
// in the same layout (docs/scenes.md, "Lightmap pages").
#include <cstdio>

#include "cli/args.h"
#include "cli/memory_estimate.h"
#include "base/image.h"
#include "io/exr.h"
#include "scene/scene.h"
#include "scene/selection.h"
#include "scene/prepare.h"

// `tiershade bake --help`.
const char kHelp[] = R"(usage: tiershade bake SCENE.gltf -o PAGE.exr [--max-memory MIB]
Bakes the scene's lightmap page (flat and three RNM lightmaps per LightmappedGeneric face, from
its lights) and writes it as RGBA float32 EXR, rows as GL texture rows (row 0 at the bottom).
Name it in the scene's extras.tiershade.lightmaps.image to render without baking (docs/scenes.md).)";

int cmd_bake(int argc, char **argv) {
  Args a("bake", argc, argv, {"--help"}, {"-o", "--max-memory"});
  if (a.help(kHelp)) return 0;
  apply_max_memory(a);  // --max-memory MIB: what the scene's files may take (docs/reliability.md)
  if (a.positional().size() != 1) a.fail("expected one scene file (tiershade bake SCENE.gltf -o PAGE.exr)");
  if (!a.has("-o")) a.fail("-o PAGE.exr is required");
  const std::string out = a.get("-o");
  if (out.size() <= 4 || out.compare(out.size() - 4, 4, ".exr") != 0) a.fail("-o '" + out + "': expected a .exr file");
  Scene scene;
  std::string err;
  if (!load_scene(a.positional()[0], &scene, &err)) {
    fprintf(stderr, "tiershade bake: %s\n", err.c_str());
    return 1;
  }
  if (!scene.lightmaps.image.empty()) {  // bake from the lights all the same
    printf("note: %s reads its page from %s; this bakes the page from the scene's lights\n", scene.path.c_str(),
           scene.lightmaps.image.c_str());
    scene.lightmaps.image.clear();
    scene.lightmaps.image_rgba.clear();
  }
  if (!render_fits_memory(scene, 1, 1, false, false, &err)) {  // the page's bake, checked before it starts
    fprintf(stderr, "tiershade bake: %s: %s\n", scene.path.c_str(), err.c_str());
    return 1;
  }
  SceneSelection sel;
  PreparedScene ps;
  // The page does not depend on the tier or the frame size: faces, density and page size only.
  if (!select_scene_variants(scene, Tier::SM3, "", &sel, &err) ||
      !prepare_scene(scene, sel, 16, 16, Api::GL33, 1.f, &ps, &err)) {
    fprintf(stderr, "tiershade bake: %s: %s\n", scene.path.c_str(), err.c_str());
    return 1;
  }
  if (ps.lightmap_page.empty()) {
    fprintf(stderr, "tiershade bake: %s: no LightmappedGeneric primitive: the scene has no lightmap page\n",
            scene.path.c_str());
    return 1;
  }
  ImageF img;
  img.w = ps.lightmap_w;
  img.h = ps.lightmap_h;
  img.rgba = ps.lightmap_page;
  if (!write_exr(out, img, &err)) {
    fprintf(stderr, "tiershade bake: %s\n", err.c_str());
    return 1;
  }
  printf("wrote %s: %d x %d lightmap page, %.1f ms to bake\n", out.c_str(), img.w, img.h, ps.bake_ms);
  return 0;
}
