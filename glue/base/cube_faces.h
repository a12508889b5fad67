// tiershade base: the direction through a point of a cube-map face, by GL's face table (OpenGL 4.6
// core profile, table 8.19: major axis and the face's sc, tc), for cube maps made on the host.
#pragma once
#include <glm/glm.hpp>

// The face's axes (unnormalised direction = forward + sc * right + tc * up): face 0..5 = +X -X +Y
// -Y +Z -Z (GL's face order), table 8.19 read backwards: +X (sc, tc) = (-z, -y), -X (z, -y),
// +Y (x, z), -Y (x, -z), +Z (x, -y), -Z (-x, -y). right x up = -forward on every face: a
// right-handed camera looking along forward with `up` up sees sc to its right, tc upwards.
inline void cube_face_axes(int face, glm::dvec3 *forward, glm::dvec3 *right, glm::dvec3 *up) {
  static const double t[6][3][3] = {
      {{1, 0, 0}, {0, 0, -1}, {0, -1, 0}}, {{-1, 0, 0}, {0, 0, 1}, {0, -1, 0}}, {{0, 1, 0}, {1, 0, 0}, {0, 0, 1}},
      {{0, -1, 0}, {1, 0, 0}, {0, 0, -1}}, {{0, 0, 1}, {1, 0, 0}, {0, -1, 0}}, {{0, 0, -1}, {-1, 0, 0}, {0, -1, 0}}};
  const int f = face < 0 || face > 5 ? 5 : face;
  *forward = glm::dvec3(t[f][0][0], t[f][0][1], t[f][0][2]);
  *right = glm::dvec3(t[f][1][0], t[f][1][1], t[f][1][2]);
  *up = glm::dvec3(t[f][2][0], t[f][2][1], t[f][2][2]);
}

// Face 0..5 = +X -X +Y -Y +Z -Z (GL's face order); (sc, tc) in [-1, 1]; the unit direction.
inline glm::dvec3 cube_face_direction(int face, double sc, double tc) {
  // +X (-z, -y), -X (z, -y), +Y (x, z), -Y (x, -z), +Z (x, -y), -Z (-x, -y).
  const glm::dvec3 d[6] = {{1, -tc, -sc}, {-1, -tc, sc}, {sc, 1, tc}, {sc, -1, -tc}, {sc, -tc, 1}, {-sc, -tc, -1}};
  return glm::normalize(d[face < 0 || face > 5 ? 5 : face]);
}
