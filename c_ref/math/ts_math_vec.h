/* tiershade math: the vector functions of ts_math.c whose float32 and double forms are the same
 * component-wise code: included by ts_math.c once per precision (ts_generic.h: M(add3) is ts_add3f
 * or ts_add3d). dot3, dot4 and normalize3, whose operation order differs, stay in ts_math.c.
 * No include guard on purpose. */

/* The constructors M(v2), M(v3), M(v4) are static inline in ts_math.h. */

TS_REAL M(dot2)(V2 a, V2 b) { return a.x * b.x + a.y * b.y; }

V3 M(add3)(V3 a, V3 b) { return M(v3)(a.x + b.x, a.y + b.y, a.z + b.z); }
V3 M(sub3)(V3 a, V3 b) { return M(v3)(a.x - b.x, a.y - b.y, a.z - b.z); }
V3 M(mul3)(V3 a, V3 b) { return M(v3)(a.x * b.x, a.y * b.y, a.z * b.z); }
V3 M(scale3)(V3 v, TS_REAL s) { return M(v3)(v.x * s, v.y * s, v.z * s); }
/* GLSL length(v) = sqrt(dot(v,v)) */
TS_REAL M(length3)(V3 v) { return M(sqrt)(M(dot3)(v, v)); }
V3 M(max3)(V3 a, V3 b) { return M(v3)(M(max)(a.x, b.x), M(max)(a.y, b.y), M(max)(a.z, b.z)); }
V3 M(min3)(V3 a, V3 b) { return M(v3)(M(min)(a.x, b.x), M(min)(a.y, b.y), M(min)(a.z, b.z)); }
V3 M(saturate3)(V3 v) { return M(v3)(M(saturate)(v.x), M(saturate)(v.y), M(saturate)(v.z)); }
V3 M(pow3)(V3 a, V3 b) { return M(v3)(M(pow)(a.x, b.x), M(pow)(a.y, b.y), M(pow)(a.z, b.z)); }
V3 M(neg3)(V3 v) { return M(v3)(-v.x, -v.y, -v.z); }

V4 M(add4)(V4 a, V4 b) { return M(v4)(a.x + b.x, a.y + b.y, a.z + b.z, a.w + b.w); }
V4 M(sub4)(V4 a, V4 b) { return M(v4)(a.x - b.x, a.y - b.y, a.z - b.z, a.w - b.w); }
V4 M(mul4)(V4 a, V4 b) { return M(v4)(a.x * b.x, a.y * b.y, a.z * b.z, a.w * b.w); }
V4 M(scale4)(V4 v, TS_REAL s) { return M(v4)(v.x * s, v.y * s, v.z * s, v.w * s); }
V4 M(saturate4)(V4 v) { return M(v4)(M(saturate)(v.x), M(saturate)(v.y), M(saturate)(v.z), M(saturate)(v.w)); }
