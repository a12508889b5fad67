// tiershade scene: the draws' vertex arrays (glue/scene/draw_geometry.h).
#include "scene/draw_geometry.h"

#include <cmath>
#include <set>

DrawGeometry DrawGeometryCache::copy_of(const SceneGeometry &p) {
  DrawGeometry d;
  const size_t n = p.position.size() / 3;
  d.position = p.position;
  d.normal = p.normal;
  d.uv = p.uv;
  d.uv.resize(n * 2, 0.f);
  d.normal.resize(n * 3, 0.f);
  d.tangent = p.tangent;
  if (d.tangent.size() != n * 4) {
    d.tangent.assign(n * 4, 0.f);
    for (size_t i = 0; i < n; ++i) d.tangent[i * 4 + 3] = 1.f;
  }
  d.indices = p.indices;
  return d;
}

void DrawGeometryCache::set(const ScenePrimitive &p, PreparedDraw *d) {
  if (!p.shared) {
    d->geo = std::make_shared<const DrawGeometry>(copy_of(p));
    return;
  }
  std::shared_ptr<const DrawGeometry> &g = shared_[p.shared.get()];
  if (!g) g = std::make_shared<const DrawGeometry>(copy_of(*p.shared));
  d->geo = g;
  for (int i = 0; i < 16; ++i) d->model[i] = p.model[i];
  d->instanced = true;
}

void primitive_center(const Scene &s, const ScenePrimitive &p, double c[3]) {
  const std::vector<float> pos = scene_world_positions(s, p);
  double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
  for (size_t i = 0; i + 2 < pos.size(); i += 3)
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::fmin(lo[k], pos[i + k]);
      hi[k] = std::fmax(hi[k], pos[i + k]);
    }
  for (int k = 0; k < 3; ++k) c[k] = 0.5 * (lo[k] + hi[k]);
}

size_t PreparedScene::geometry_bytes() const {
  size_t bytes = 0;
  std::set<const DrawGeometry *> seen;
  for (const PreparedDraw &d : draws)
    if (d.geo && seen.insert(d.geo.get()).second) bytes += d.geo->bytes();
  return bytes;
}

int PreparedScene::geometries() const {
  std::set<const DrawGeometry *> seen;
  for (const PreparedDraw &d : draws)
    if (d.geo) seen.insert(d.geo.get());
  return static_cast<int>(seen.size());
}
