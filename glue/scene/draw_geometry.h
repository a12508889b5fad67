// tiershade scene: the draws' vertex arrays (DrawGeometry, glue/scene/prepare.h) from the scene's
// primitives: a flattened primitive's own arrays per draw; a shared mesh primitive's once, for
// every draw that instances it (docs/rendering.md, "Scenes of real size").
#pragma once
#include <map>
#include <memory>

#include "scene/prepare.h"

class DrawGeometryCache {
 public:
  // The arrays of p as a draw takes them (uv and normal padded, tangent 0,0,0,1 where absent);
  // for an instance of shared geometry, the same object on every call. Sets d->geo, d->model and
  // d->instanced.
  void set(const ScenePrimitive &p, PreparedDraw *d);
  // A flattened primitive's arrays in a new DrawGeometry (world draws add their lightmap arrays).
  static DrawGeometry copy_of(const SceneGeometry &g);

 private:
  std::map<const SceneGeometry *, std::shared_ptr<const DrawGeometry>> shared_;
};

// The centre of a primitive's world-space box.
void primitive_center(const Scene &s, const ScenePrimitive &p, double c[3]);
