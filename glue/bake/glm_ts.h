// tiershade bake: glm::dvec3 <-> ts_vec3d (the c_ref offline bakers' vector type), for the bake's
// host-side geometry written with GLM.
#pragma once
#include <glm/glm.hpp>

#include "math/ts_math.h"

inline glm::dvec3 to_glm(ts_vec3d v) { return glm::dvec3(v.x, v.y, v.z); }
inline ts_vec3d to_ts(const glm::dvec3 &v) { return ts_v3d(v.x, v.y, v.z); }
