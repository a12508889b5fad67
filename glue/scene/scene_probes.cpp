// tiershade scene: a scene's probes as its draws use them (glue/scene/scene_probes.h).
#include "scene/scene_probes.h"

#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>

#include "bake/ray_scene.h"
#include "scene/textures.h"

bool SceneProbeSet::cube(int p, TextureDesc *out, float amb[6][3], std::string *err) {
  if (!cubes.count(p)) {
    const SceneProbe &pr = s.probes.at(p);
    TextureDesc c;
    float a[6][3] = {};
    if (pr.image >= 0) {
      if (!cube_from_probe(s.images.at(pr.image).path, "u_envmap", pr.size, &c, a, err)) {
        *err = s.path + ": probes[" + std::to_string(p) + "]: " + *err;
        return false;
      }
    } else if (!have_world) {
      *err = s.path + ": probes[" + std::to_string(p) + "] (\"" + pr.name +
          "\") has no image and the scene has no world geometry to render it from";
      return false;
    } else if (p < static_cast<int>(traced.size()) && traced[p].w > 0) {
      c = traced[p];
      // The traced cube's irradiance: the mean of each face (a coarse ambient for models).
      for (int f = 0; f < 6; ++f) {
        double m[3] = {0, 0, 0};
        const int n = c.w * c.w;
        for (int i = 0; i < n; ++i)
          for (int k = 0; k < 3; ++k) m[k] += c.rgba[(static_cast<size_t>(f) * n + i) * 4 + k];
        for (int k = 0; k < 3; ++k) a[f][k] = static_cast<float>(m[k] / n);
      }
    } else {
      // Rendered in-engine after preparation (glue/scene/probe_render.h): a black cube of its size.
      c.sampler = "u_envmap";
      c.kind = TexKind::Cube;
      c.w = c.h = pr.size;
      c.linear = true;
      c.rgba.assign(static_cast<size_t>(6) * pr.size * pr.size * 4, 0.f);
      for (size_t i = 3; i < c.rgba.size(); i += 4) c.rgba[i] = 1.f;
      pending.insert(p);
    }
    for (float &v : c.rgba) v *= pr.scale;
    std::array<std::array<float, 3>, 6> aa;
    for (int f = 0; f < 6; ++f)
      for (int k = 0; k < 3; ++k) aa[f][k] = a[f][k] * pr.scale;
    cubes[p] = c;
    ambient[p] = aa;
  }
  if (out) *out = cubes[p];
  if (amb)
    for (int f = 0; f < 6; ++f)
      for (int k = 0; k < 3; ++k) amb[f][k] = ambient[p][f][k];
  return true;
}

bool probe_traced(const Scene &s, int p) {
  if (s.probes.at(p).traced) return true;
  for (const SceneAmbientSample &a : s.ambient)
    if (a.from_probe == p) return true;
  return false;
}

int best_probe(const Scene &s, const RayScene *rays, const double centre[3], const double normal[3],
               int explicit_index) {
  if (explicit_index >= 0) return explicit_index;
  const glm::dvec3 c(centre[0], centre[1], centre[2]);
  glm::dvec3 n(normal[0], normal[1], normal[2]);
  const double nl = glm::length(n);
  n = nl > 0 ? n / nl : glm::dvec3(0.0);
  const glm::dvec3 o = c + n * 1e-4;
  int best = -1, best_seen = -1;
  double bd = 0, bd_seen = 0;
  for (size_t i = 0; i < s.probes.size(); ++i) {
    const glm::dvec3 q(s.probes[i].position[0], s.probes[i].position[1], s.probes[i].position[2]);
    const double dd = glm::dot(q - c, q - c);
    if (best < 0 || dd < bd) best = static_cast<int>(i), bd = dd;
    if (best_seen >= 0 && dd >= bd_seen) continue;
    // The segment o -> q, t in (0, 1): a hit short of the probe hides it.
    if (rays && rays->occluded(o, q - o, 0.0, 1.0)) continue;
    best_seen = static_cast<int>(i), bd_seen = dd;
  }
  return rays && best_seen >= 0 ? best_seen : best;
}
