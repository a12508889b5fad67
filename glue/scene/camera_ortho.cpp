// tiershade scene: orthographic cameras (see camera_ortho.h): the glTF camera's fields and its
// view-projection, both with GLM (glm::lookAt, glm::ortho: right-handed, depth -1..1 as GL).
#include "scene/camera_ortho.h"

#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "scene/gltf_util.h"

void ortho_view_projection(const SceneCamera &c, double aspect, double out[16]) {
  const glm::dvec3 eye = glm::make_vec3(c.eye), fwd = glm::make_vec3(c.forward), up = glm::make_vec3(c.up);
  // Half extents of the output: the larger of xmag and ymag x aspect across, square pixels.
  const double sx = std::max(c.xmag, c.ymag * aspect), sy = sx / aspect;
  const glm::dmat4 vp = glm::ortho(-sx, sx, -sy, sy, c.znear, c.zfar) * glm::lookAt(eye, eye + fwd, up);
  const double *p = glm::value_ptr(vp);
  std::copy(p, p + 16, out);
}

namespace scene_gltf {

// glTF 2.0 section 5.13: xmag, ymag (half extents, non-zero), zfar > znear >= 0. A negative
// magnification (a mirrored view) is not supported.
bool read_orthographic(const tinygltf::Camera &c, const std::string &place, SceneCamera *sc, Err &e) {
  const tinygltf::OrthographicCamera &o = c.orthographic;
  if (!(o.xmag > 0 && std::isfinite(o.xmag))) return e.fail(place + ".orthographic.xmag", "must be > 0");
  if (!(o.ymag > 0 && std::isfinite(o.ymag))) return e.fail(place + ".orthographic.ymag", "must be > 0");
  if (!(o.znear >= 0 && std::isfinite(o.znear))) return e.fail(place + ".orthographic.znear", "must be >= 0");
  if (!(o.zfar > o.znear && std::isfinite(o.zfar))) return e.fail(place + ".orthographic.zfar", "must be > znear");
  sc->orthographic = true;
  sc->xmag = o.xmag;
  sc->ymag = o.ymag;
  sc->znear = o.znear;
  sc->zfar = o.zfar;
  return true;
}

}  // namespace scene_gltf
