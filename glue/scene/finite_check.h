// tiershade scene: the host's half of the portable contract on NaN and Inf (docs/conformance.md
// "The portable contract"): GLSL ES cannot detect NaN or Inf portably, so values are checked before
// they are uploaded. Texels: NaN is refused (no value to put in its place); +-Inf and finite values
// beyond the fp16 range are clamped to +-65504, as an fp16 texture would store an overflowed value
// (Source's HDR textures are fp16; fact sheet section 7, maxfloat16bits). Uniform values: refused
// unless finite.
#pragma once
#include <cstddef>
#include <string>

// The largest finite half float: the clamp of every texel (shaders/common_math.glsl TS_FP16_MAX).
constexpr float kFp16Max = 65504.0f;

// Clamps the n floats at v into [-65504, 65504] (+-Inf included). Refuses a NaN: *err = "WHERE:
// value i is NaN". Returns the number of values clamped through *clamped (may be null).
bool clamp_texels_to_fp16(float *v, size_t n, const std::string &where, size_t *clamped, std::string *err);

// Every one of the n values at v finite, else *err = "WHERE: value i is NaN/Inf/-Inf".
bool check_finite(const float *v, size_t n, const std::string &where, std::string *err);
