// tiershade scene: the C fallback's vertex stage (see cpu_vertex.h).
#include "scene/cpu_vertex.h"

#include <cstring>

#include <glm/glm.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "families/model_lighting.h"
#include "families/world_lighting.h"
#include "offline/light_folding.h"
#include "scene/lp_interp.h"
#include "scene/raster_tri.h"

// The production vertex shaders' outputs (model_lighting.vs, world_lighting.vs) in float.
void vertex_stage(const PreparedScene &p, const PreparedDraw &d, std::vector<float> *clip, std::vector<float> *vary) {
  const DrawGeometry &g = *d.geo;
  const size_t n = g.vertices();
  clip->assign(n * 4, 0.f);
  vary->assign(n * kVStride, 0.f);
  const float *m = p.view_proj;
  const bool ps20 = !d.world && d.variant->tier == Tier::PS20;
  const int nl = ps20 ? d.variant->value("NUM_LIGHTS") : 0;
  for (size_t i = 0; i < n; ++i) {
    const float *P = &g.position[i * 3], *N = &g.normal[i * 3], *T = &g.tangent[i * 4], *UV = &g.uv[i * 2];
    float Pw[3], Nw[3], Tw[4];
    if (d.instanced) {  // object space: the world vectors as u_model makes them
      model_point(d.model, P, Pw);
      model_direction(d.model, N, Nw);
      model_direction(d.model, T, Tw);
      Tw[3] = T[3];
      P = Pw, N = Nw, T = Tw;
    }
    float *c = &(*clip)[i * 4];
    // u_view_proj * vec4(P, 1) in float, summed left to right as llvmpipe's vertex shader
    // does (the visibility must match GL's): not glm's mat4 * vec4, which sums in pairs.
    for (int r = 0; r < 4; ++r) c[r] = m[r] * P[0] + m[4 + r] * P[1] + m[8 + r] * P[2] + m[12 + r];
    float *v = &(*vary)[i * kVStride];
    lp_window_pos(c, static_cast<float>(p.w), static_cast<float>(p.h), v + kWin);
    std::memcpy(v + kClip, c, 4 * sizeof(float));
    v[kClipMask] = static_cast<float>(lp_clipmask(c));
    const glm::vec3 B = glm::cross(glm::make_vec3(N), glm::make_vec3(T)) * T[3];  // cross(N, T) * w: the same products
    auto put = [&](int slot, float x, float y, float z, float w) {
      v[slot * 4 + 0] = x;
      v[slot * 4 + 1] = y;
      v[slot * 4 + 2] = z;
      v[slot * 4 + 3] = w;
    };
    if (d.world) {
      const float *L = &g.lightmap[i * 4];
      put(WL_SLOT_UV, UV[0], UV[1], L[0], L[1]);
      put(WL_SLOT_LM_OFFSET, L[2], L[3], c[3], 0);
      put(WL_SLOT_NORMAL, N[0], N[1], N[2], 0);
      put(WL_SLOT_TANGENT, T[0], T[1], T[2], 0);
      put(WL_SLOT_BINORMAL, B[0], B[1], B[2], 0);
      put(WL_SLOT_EYE, p.eye[0] - P[0], p.eye[1] - P[1], p.eye[2] - P[2], 0);
    } else {
      put(ML_SLOT_NORMAL, N[0], N[1], N[2], 0);
      put(ML_SLOT_POSITION, P[0], P[1], P[2], 1);
      put(ML_SLOT_UV, UV[0], UV[1], 0, 0);
      put(ML_SLOT_TANGENT, T[0], T[1], T[2], 0);
      put(ML_SLOT_BITANGENT, B[0], B[1], B[2], 0);
      float att[4] = {0, 0, 0, 0};
      for (int l = 0; l < nl && l < 2; ++l) {
        // The per-vertex value: ts_light_attenuation of common_lights.glsl in double.
        const ts_vec4f *L = &d.shared[ML_SLOT_LIGHT0 + 5 * l];
        float pk[5][4];
        for (int k = 0; k < 5; ++k) pk[k][0] = L[k].x, pk[k][1] = L[k].y, pk[k][2] = L[k].z, pk[k][3] = L[k].w;
        const double pd[3] = {P[0], P[1], P[2]};
        const double a = ts_packed_light_attenuation(pk, pd, nullptr);
        att[l] = static_cast<float>(a);
      }
      put(ML_SLOT_VERTEX_ATTEN, att[0], att[1], att[2], att[3]);
    }
  }
}
