//------------------------------------------------------------------------------
// common_ambient_cube.glsl: the ambient cube of the irradiance volume.
// Talk: "Model lighting: Irradiance Volume" (six colours, one per axis direction).
// Fact sheet section 3: order +X -X +Y -Y +Z -Z; colour = n.x^2 C[x sign] +
// n.y^2 C[y sign] + n.z^2 C[z sign]; the weights sum to 1 for a unit normal.
// C twin: c_ref/common/common_ambient_cube.h
//------------------------------------------------------------------------------
#ifndef TS_COMMON_AMBIENT_CUBE_GLSL
#define TS_COMMON_AMBIENT_CUBE_GLSL

vec3 ts_ambient_cube(vec3 n, vec3 px, vec3 nx, vec3 py, vec3 ny, vec3 pz, vec3 nz) {
    vec3 n2 = n * n;
    vec3 cx = n.x >= 0.0 ? px : nx;
    vec3 cy = n.y >= 0.0 ? py : ny;
    vec3 cz = n.z >= 0.0 ? pz : nz;
    return n2.x * cx + n2.y * cy + n2.z * cz;
}

#endif
