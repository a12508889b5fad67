// tiershade base: the direction through a point of a cube-map face, by GL's face table (OpenGL 4.6
// core profile, table 8.19: major axis and the face's sc, tc), for cube maps made on the host.
#pragma once
#include <glm/glm.hpp>

// Face 0..5 = +X -X +Y -Y +Z -Z (GL's face order); (sc, tc) in [-1, 1]; the unit direction.
inline glm::dvec3 cube_face_direction(int face, double sc, double tc) {
  // +X (-z, -y), -X (z, -y), +Y (x, z), -Y (x, -z), +Z (x, -y), -Z (-x, -y).
  const glm::dvec3 d[6] = {{1, -tc, -sc}, {-1, -tc, sc}, {sc, 1, tc}, {sc, -1, -tc}, {sc, -tc, 1}, {-sc, -tc, -1}};
  return glm::normalize(d[face < 0 || face > 5 ? 5 : face]);
}
