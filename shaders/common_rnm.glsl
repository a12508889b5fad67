//------------------------------------------------------------------------------
// common_rnm.glsl: radiosity normal mapping (talk: "Radiosity Normal Mapping";
// fact sheet section 1). Three lightmaps baked along a tangent-space basis
//   b0 = (sqrt(2/3), 0, 1/sqrt3), b1 = (-1/sqrt6, 1/sqrt2, 1/sqrt3),
//   b2 = (-1/sqrt6, -1/sqrt2, 1/sqrt3)        (bumpvects.h, common_fxc.h)
// are blended per pixel by the normal-map normal n = 2 tex - 1 (not renormalised):
//   d_k = saturate(n . b_k)^2 (clamped, then squared),
//   diffuse = sum(d_k L_k) / sum(d_k)          (lightmappedgeneric_ps2_3_x.h).
// A zero weight sum (n pointing away from all three, or a zero-length texel)
// would be 0/0: every weight gets TS_RNM_MIN_WEIGHT added, which leaves any
// weight above ~1e-23 unchanged and turns 0/0 into the mean of the three maps.
// Self-shadowed bump maps (ssbump): the texel rgb are the weights themselves, no
// decode, no saturate, no division; the normal for reflections is
// normalize(sum t_k b_k) (fact sheet section 1, SSBUMP).
// C twin: c_ref/common/common_rnm.h
//------------------------------------------------------------------------------
#ifndef TS_COMMON_RNM_GLSL
#define TS_COMMON_RNM_GLSL

// sqrt(2/3), 1/sqrt6, 1/sqrt2, 1/sqrt3 (fact sheet section 1, table of b0..b2).
#define TS_RNM_SQRT_2_OVER_3 0.816496580927726
#define TS_RNM_OO_SQRT_6 0.408248290463863
#define TS_RNM_OO_SQRT_2 0.707106781186548
#define TS_RNM_OO_SQRT_3 0.577350269189626

// Added to every weight: a normal float, so 3 x it is never flushed to zero.
// fp16: NOT a half-float number; in fp16 (mediump) it is 0, so three zero weights give
// 0 / 0 = NaN in ts_rnm_blend. world_lighting has no mediump variant.
#define TS_RNM_MIN_WEIGHT 1.0e-30

// The three weights of a tangent-space normal n. b0.y = 0, so its dot product
// has two terms (NIR drops the zero lane of a constant vector; the twin mirrors it).
vec3 ts_rnm_weights(vec3 n) {
    vec3 d = vec3(n.x * TS_RNM_SQRT_2_OVER_3 + n.z * TS_RNM_OO_SQRT_3,
                  dot(n, vec3(-TS_RNM_OO_SQRT_6, TS_RNM_OO_SQRT_2, TS_RNM_OO_SQRT_3)),
                  dot(n, vec3(-TS_RNM_OO_SQRT_6, -TS_RNM_OO_SQRT_2, TS_RNM_OO_SQRT_3)));
    d = saturate(d);
    return d * d + TS_RNM_MIN_WEIGHT;
}

// sum(d_k L_k) / sum(d_k).
vec3 ts_rnm_blend(vec3 d, vec3 l0, vec3 l1, vec3 l2) {
    vec3 s = d.x * l0 + d.y * l1 + d.z * l2;
    return s / dot(d, vec3(1.0));
}

// ssbump: the weights are the texel (no division by their sum).
vec3 ts_ssbump_blend(vec3 t, vec3 l0, vec3 l1, vec3 l2) {
    return t.x * l0 + t.y * l1 + t.z * l2;
}

// ssbump: sum t_k b_k, the direction of the normal used for reflections, written
// lane by lane with the shared basis constants factored out (NIR factors
// a*c + b*c into (a + b)*c by itself, so the written form has to be the factored one).
vec3 ts_ssbump_direction(vec3 t) {
    return vec3(t.x * TS_RNM_SQRT_2_OVER_3 - (t.y + t.z) * TS_RNM_OO_SQRT_6,
                (t.y - t.z) * TS_RNM_OO_SQRT_2,
                (t.x + t.y + t.z) * TS_RNM_OO_SQRT_3);
}

// ssbump: the tangent-space normal used for reflections, normalize(sum t_k b_k).
vec3 ts_ssbump_normal(vec3 t) {
    return ts_safe_normalize(ts_ssbump_direction(t));
}

#endif
