/* tiershade offline: fitting the six colours of an ambient cube to radiance samples over the sphere.
 *
 * The cube is Source's n^2 basis (fact sheet section 3: colour = n.x^2 C[x sign] + n.y^2 C[y sign] +
 * n.z^2 C[z sign], faces +X -X +Y -Y +Z -Z). Its value for a normal n stands for the diffuse
 * irradiance over pi, E(n)/pi (vrad's per-axis mean is exactly E(axis)/pi). Three fits:
 *  - TS_AC_FIT_MEAN: Source's cosine-weighted mean radiance per axis (fact sheet section 3,
 *    ComputeAmbientFromSphericalSamples), exact only along the six axes;
 *  - TS_AC_FIT_LSQ (the default): non-negative least squares of the basis against E(n)/pi over the
 *    sphere, weighted by solid angle. E is linear in the radiance, so the right-hand side of the
 *    6x6 normal equations is one weighted sum over the radiance samples with a zonal kernel (the
 *    cube basis convolved with the clamped cosine, Funk-Hecke), and the Gram matrix is a constant:
 *    one pass over the samples, like the mean (a Legendre series per sample and axis);
 *  - TS_AC_FIT_LSQ_RADIANCE: the same least squares against the radiance itself (the basis fitted
 *    to L, not to E/pi; kept for comparison).
 * Samples carry their solid angle, so the same accumulator serves a lat-long probe's texels and the
 * irradiance volume's ray directions. Double precision throughout; order of adds = order of calls.
 */
#ifndef TS_OFFLINE_AMBIENT_CUBE_FIT_H
#define TS_OFFLINE_AMBIENT_CUBE_FIT_H

#ifdef __cplusplus
extern "C" {
#endif

enum { TS_AC_FIT_MEAN = 0, TS_AC_FIT_LSQ = 1, TS_AC_FIT_LSQ_RADIANCE = 2 };

/* Highest Legendre degree of the irradiance kernel series (its terms fall as l^-5: the tail is about 1e-6). */
#define TS_AC_KERNEL_DEGREE 32

typedef struct ts_ac_accum {
  int fit;
  double b[6][3];  /* right-hand side (lsq) or cosine-weighted sums (mean) */
  double w[6];     /* mean: cosine weight sums; lsq: the kernel's quadrature sum (normalises b) */
  double gram[6][6];
  double kernel[TS_AC_KERNEL_DEGREE + 1]; /* lsq: coefficient of P_l in h(t) */
  double rec_a[TS_AC_KERNEL_DEGREE + 1], rec_b[TS_AC_KERNEL_DEGREE + 1]; /* (2l+1)/(l+1), l/(l+1) */
} ts_ac_accum;

/* The six basis weights of direction d (unit): index 2*axis + (d[axis] < 0). */
void ts_ac_basis(const double d[3], double w[6]);

/* The cube's colour for a unit normal n (fact sheet section 3's evaluation, in double). */
void ts_ac_eval(const float cube[6][3], const double n[3], double rgb[3]);

/* The lsq fit's zonal kernel h(t): the irradiance over pi, at a normal whose cosine to the face's
 * axis is t, of the radiance "the face's basis function" (t^2 on its half-space). b_face =
 * sum_i L_i dw_i h(d_i . axis). */
double ts_ac_irradiance_kernel(const ts_ac_accum *acc, double t);

/* Start an accumulation for one fit (TS_AC_FIT_*); returns 0 for an unknown fit. */
int ts_ac_accum_init(ts_ac_accum *acc, int fit);

/* Add one radiance sample: unit direction d, radiance rgb, solid angle dw (> 0). */
void ts_ac_accum_add(ts_ac_accum *acc, const double d[3], const double rgb[3], double dw);

/* Solve for the six colours (non-negative for the lsq fits: active-set NNLS on the normal
 * equations, Lawson and Hanson 1974, ch. 23). A face with no weight (mean) gets 0. */
void ts_ac_accum_solve(const ts_ac_accum *acc, float cube[6][3]);

/* Active-set NNLS of min x^T G x - 2 b^T x subject to x >= 0 for a 6x6 symmetric positive definite G
 * (Lawson and Hanson's algorithm on the normal equations). Deterministic; at most 3*6 outer steps. */
void ts_ac_nnls6(const double g[6][6], const double b[6], double x[6]);

#ifdef __cplusplus
}
#endif
#endif
