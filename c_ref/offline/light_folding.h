/* tiershade offline: CPU set-up for model lighting: pack a local light into the 5 vec4 the shader
 * reads (shaders/common_lights.glsl), evaluate it at a point in double, and fold
 * the lights beyond a tier's limit (ps20: 2, ps2b/sm3: 4) into the ambient cube.
 * Fact sheet section 3: DrawModelInfo_t::m_vecAmbientCube holds "ambient, and
 * lights that aren't in locallight[]" (Valve's folding code is NOT IN REPO; the
 * rule here is ours). Rule, derivation and measured errors: docs/light_folding.md.
 * Not a shader twin: plain C99, double precision inside.
 */
#ifndef TS_LIGHT_FOLDING_H
#define TS_LIGHT_FOLDING_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef enum { TS_LIGHT_POINT = 0, TS_LIGHT_SPOT = 1, TS_LIGHT_DIRECTIONAL = 2 } ts_light_type;

typedef struct {
  ts_light_type type;
  float color[3];
  float dir[3]; /* unit; spot axis, or the direction a directional light travels */
  float pos[3];
  float spot_exponent, cos_inner, cos_outer; /* spot only */
  float atten[3]; /* constant, linear, quadratic; directional lights ignore it */
} ts_light;

/* Packs a light into the 5 vec4 slots the shader reads, exactly as
 * shaders/common_lights.glsl expects:
 *   [0] color   rgb, w = 1 directional / 0 otherwise
 *   [1] dir     xyz = dir normalised (spot, directional; 0 for a point light),
 *               w = 1 spot / 0 otherwise
 *   [2] pos     xyz (0 for a directional light), w = 0
 *   [3] spot    x exponent, y 0, z cos_outer, w 1/(cos_inner - cos_outer) (all 0 unless spot)
 *   [4] atten   constant, linear, quadratic, 0; directional -> (1, 0, 0, 0)
 * Returns 1, or 0 with a message in err (if err != NULL and errlen > 0) and out
 * untouched for an invalid light: an unknown type; any non-finite float (every
 * field, even those the type ignores); for point and spot lights a negative
 * attenuation coefficient or c + l + q == 0; for spots cos_inner <= cos_outer,
 * a negative exponent or a cone so narrow that 1/(cos_inner - cos_outer)
 * overflows float; for spot and directional lights a zero-length dir. */
int ts_light_pack(const ts_light *l, float out[5][4], char *err, size_t errlen);

/* Irradiance-weighted intensity of the light at point p (color * distance
 * attenuation * spot cone, the formulas of ts_light_attenuation in
 * common_lights.glsl evaluated in double on the packed values) and the unit
 * direction towards the light. A light sitting on p (|pos - p|^2 < 1e-30)
 * gets the shader's degenerate direction (shorter than unit, 0 when exactly on
 * p). A light ts_light_pack rejects gives rgb = to_light = 0. */
void ts_light_incident(const ts_light *l, const float p[3], double rgb[3], double to_light[3]);

/* Distance x cone attenuation of a packed light (5 vec4 as ts_light_pack writes
 * them) at p: light_attenuation of c_ref/common/common_lights.h (the twin of
 * common_lights.glsl) in double, the one host-side copy of the formula. The unit
 * direction towards the light goes to to_light (when not NULL). */
double ts_packed_light_attenuation(const float packed[5][4], const double p[3], double to_light[3]);

/* Keeps the max_local lights with the largest incident luminance
 * (0.2126 R + 0.7152 G + 0.0722 B) at `center` (ties: the lower index wins) and
 * folds every other valid light into cube[6][3] (+X -X +Y -Y +Z -Z, added to what
 * is there): a folded light with incident rgb I and direction L adds
 * k * I * L_j^2 to the face on the side of sign(L_j) of each axis j, with
 * k = 3/2 (Lambert) or 2 (half_lambert != 0), which conserves the sphere
 * integral of the shading. Lights ts_light_pack rejects are neither kept nor
 * folded. Returns the number kept; kept[] (room for max_local entries, may be
 * NULL) receives their indices in ascending (original) order. cube may be NULL
 * to select only (the other lights are then dropped). n <= 0 or
 * lights == NULL returns 0; max_local < 0 counts as 0. No allocation: up to 256
 * lights, n incident-light evaluations and O(n^2) comparisons; more, O(n^2)
 * evaluations. */
int ts_fold_lights(const ts_light *lights, int n, int max_local, const float center[3], int half_lambert,
                   float cube[6][3], int *kept);

#ifdef __cplusplus
}
#endif
#endif /* TS_LIGHT_FOLDING_H */
