// tiershade families: slot names and deferred-frame uniforms from a slot table (slot_table.h).
#include "families/slot_table.h"

std::vector<std::string> slot_names_of(const SlotRow *rows, size_t n) {
  static const char *const kFaces[6] = {"+x", "-x", "+y", "-y", "+z", "-z"};
  // The TsLight fields in record order (shaders/common_lights.glsl).
  static const char *const kLightParts[5] = {"color", "dir", "pos", "spot", "atten"};
  std::vector<std::string> names;
  for (size_t i = 0; i < n; ++i) {
    const SlotRow &r = rows[i];
    for (int k = 0; k < r.count; ++k) {
      switch (r.naming) {
        case SlotNaming::one:
          names.push_back(r.name);
          break;
        case SlotNaming::cube_faces:
          names.push_back(std::string(r.name) + kFaces[k % 6]);
          break;
        case SlotNaming::light_parts:
          names.push_back(std::string(r.name) + std::to_string(k / 5) + "." + kLightParts[k % 5]);
          break;
      }
    }
  }
  return names;
}

void bind_slot_uniforms(const GlFns &gl, GLuint program, const std::vector<ts_vec4f> &shared, const SlotRow *rows,
                        size_t n, int pixel_slots) {
  for (size_t i = 0; i < n; ++i) {
    const SlotRow &r = rows[i];
    if (r.first < pixel_slots) continue;
    const GLint loc = gl.GetUniformLocation(program, r.source);
    if (loc < 0) continue;
    (void)shared.at(r.first + r.count - 1);  // std::out_of_range for a short record
    gl.Uniform4fv(loc, r.count, &shared[r.first].x);
  }
}
