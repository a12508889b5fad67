/* tiershade offline: the ambient-cube fits (per-axis mean, least squares against E/pi or against the
 * radiance, non-negative). See ambient_cube_fit.h for what each fit minimises. */
#include "offline/ambient_cube_fit.h"

#include <math.h>
#include <string.h>

static const double k_pi = 3.14159265358979323846;

void ts_ac_basis(const double d[3], double w[6]) {
  /* Fact sheet section 3: weight n_axis^2 on the face of the axis's sign (index 0 positive). */
  for (int a = 0; a < 3; ++a) {
    const double s = d[a] * d[a];
    w[2 * a] = d[a] < 0 ? 0.0 : s;
    w[2 * a + 1] = d[a] < 0 ? s : 0.0;
  }
}

void ts_ac_eval(const float cube[6][3], const double n[3], double rgb[3]) {
  double w[6];
  ts_ac_basis(n, w);
  for (int c = 0; c < 3; ++c) {
    rgb[c] = 0;
    for (int f = 0; f < 6; ++f) rgb[c] += w[f] * cube[f][c];
  }
}

/* Legendre P_0..P_n at x by the three-term recurrence (l+1) P_{l+1} = (2l+1) x P_l - l P_{l-1}. */
static void legendre_all(double x, int n, double *p) {
  p[0] = 1;
  if (n >= 1) p[1] = x;
  for (int l = 1; l < n; ++l) p[l + 1] = ((2 * l + 1) * x * p[l] - l * p[l - 1]) / (l + 1);
}

/* Gauss-Legendre nodes and weights on [0, 1] (Newton on P_n; Abramowitz and Stegun 25.4.29). */
#define GL_N 64
static void gauss_legendre01(double *xs, double *ws) {
  double p[GL_N + 1];
  for (int i = 0; i < GL_N; ++i) {
    double x = cos(k_pi * (i + 0.75) / (GL_N + 0.5));
    double dp = 1;
    for (int it = 0; it < 100; ++it) {
      legendre_all(x, GL_N, p);
      dp = GL_N * (x * p[GL_N] - p[GL_N - 1]) / (x * x - 1);
      const double dx = p[GL_N] / dp;
      x -= dx;
      if (fabs(dx) < 1e-16) break;
    }
    legendre_all(x, GL_N, p);
    dp = GL_N * (x * p[GL_N] - p[GL_N - 1]) / (x * x - 1);
    xs[i] = 0.5 * (x + 1);
    ws[i] = 1.0 / ((1 - x * x) * dp * dp); /* 2/((1-x^2)P'^2), halved for [0,1] */
  }
}

/* h(t) = (1/pi) sum_l A_l g_l P_l(t) (Funk-Hecke): A_l = 2pi int_0^1 s P_l(s) ds is the clamped
 * cosine's coefficient (Ramamoorthi and Hanrahan 2001, eq. 8: A_0 = pi, A_1 = 2pi/3, A_2 = pi/4,
 * odd l > 1 zero), g_l = (2l+1)/2 int_0^1 s^2 P_l(s) ds the face basis' Legendre coefficient. Both
 * integrands are polynomials of degree <= 34, integrated exactly by 64-point Gauss-Legendre. */
static void kernel_coefficients(double *c) {
  double xs[GL_N], ws[GL_N], p[TS_AC_KERNEL_DEGREE + 1];
  double a[TS_AC_KERNEL_DEGREE + 1], g[TS_AC_KERNEL_DEGREE + 1];
  gauss_legendre01(xs, ws);
  memset(a, 0, sizeof a);
  memset(g, 0, sizeof g);
  for (int i = 0; i < GL_N; ++i) {
    legendre_all(xs[i], TS_AC_KERNEL_DEGREE, p);
    for (int l = 0; l <= TS_AC_KERNEL_DEGREE; ++l) {
      a[l] += ws[i] * xs[i] * p[l];
      g[l] += ws[i] * xs[i] * xs[i] * p[l];
    }
  }
  for (int l = 0; l <= TS_AC_KERNEL_DEGREE; ++l) {
    const double al = 2 * k_pi * a[l], gl = 0.5 * (2 * l + 1) * g[l];
    /* Odd l > 1: A_l is zero analytically; keep the zero exact. */
    c[l] = (l > 1 && (l & 1)) ? 0.0 : al * gl / k_pi;
  }
}

double ts_ac_irradiance_kernel(const ts_ac_accum *acc, double t) {
  double p[TS_AC_KERNEL_DEGREE + 1], h = 0;
  legendre_all(t, TS_AC_KERNEL_DEGREE, p);
  for (int l = TS_AC_KERNEL_DEGREE; l >= 0; --l) h += acc->kernel[l] * p[l];
  return h;
}

int ts_ac_accum_init(ts_ac_accum *acc, int fit) {
  memset(acc, 0, sizeof *acc);
  if (fit != TS_AC_FIT_MEAN && fit != TS_AC_FIT_LSQ && fit != TS_AC_FIT_LSQ_RADIANCE) return 0;
  acc->fit = fit;
  if (fit == TS_AC_FIT_LSQ) {
    kernel_coefficients(acc->kernel);
    for (int l = 0; l <= TS_AC_KERNEL_DEGREE; ++l) {
      acc->rec_a[l] = (2.0 * l + 1) / (l + 1);
      acc->rec_b[l] = (double)l / (l + 1);
    }
    /* Gram matrix of the basis over the whole sphere (solid angle): int_{x>0} x^4 = 2pi/5; opposite
     * faces of one axis are disjoint; faces of two axes share a quadrant: int x^2 y^2 / 4 = pi/15. */
    for (int i = 0; i < 6; ++i)
      for (int j = 0; j < 6; ++j)
        acc->gram[i][j] = i == j ? 2 * k_pi / 5 : (i / 2 == j / 2 ? 0.0 : k_pi / 15);
  }
  return 1;
}

void ts_ac_accum_add(ts_ac_accum *acc, const double d[3], const double rgb[3], double dw) {
  if (acc->fit == TS_AC_FIT_MEAN) {
    /* Fact sheet section 3: side_j = sum max(0, d.axis_j) L / sum max(0, d.axis_j) (here with the
     * sample's solid angle, which is a constant for vrad's 162 directions). */
    for (int f = 0; f < 6; ++f) {
      const double c = (f & 1) ? -d[f / 2] : d[f / 2];
      if (c <= 0) continue;
      acc->w[f] += c * dw;
      for (int k = 0; k < 3; ++k) acc->b[f][k] += c * dw * rgb[k];
    }
  } else if (acc->fit == TS_AC_FIT_LSQ) {
    /* b_f = int a_f(n) E(n)/pi dn = int L(w) h(w . axis_f) dw; the negative face is h(-t). */
    for (int a = 0; a < 3; ++a) {
      /* h(t) and h(-t) in one pass of the Legendre recurrence (P_l(-t) = (-1)^l P_l(t)). */
      const double t = d[a];
      double p0 = 1, p1 = t;
      double hp = acc->kernel[0] + acc->kernel[1] * t, hn = acc->kernel[0] - acc->kernel[1] * t;
      for (int l = 1; l < TS_AC_KERNEL_DEGREE; ++l) {
        const double p2 = acc->rec_a[l] * t * p1 - acc->rec_b[l] * p0;
        const double c = acc->kernel[l + 1] * p2;
        hp += c;
        hn += ((l + 1) & 1) ? -c : c;
        p0 = p1;
        p1 = p2;
      }
      acc->w[2 * a] += hp * dw;
      acc->w[2 * a + 1] += hn * dw;
      for (int k = 0; k < 3; ++k) {
        acc->b[2 * a][k] += hp * dw * rgb[k];
        acc->b[2 * a + 1][k] += hn * dw * rgb[k];
      }
    }
  } else {
    /* Least squares against the radiance: the Gram matrix and right-hand side from the samples. */
    double w[6];
    ts_ac_basis(d, w);
    for (int i = 0; i < 6; ++i) {
      for (int j = 0; j < 6; ++j) acc->gram[i][j] += w[i] * w[j] * dw;
      for (int k = 0; k < 3; ++k) acc->b[i][k] += w[i] * dw * rgb[k];
    }
  }
}

/* Solve G_PP z = b_P for the passive set (mask) by Gaussian elimination with partial pivoting. */
static int solve_subset(const double g[6][6], const double b[6], const int *passive, double z[6]) {
  int idx[6], n = 0;
  double m[6][7];
  for (int i = 0; i < 6; ++i) {
    z[i] = 0;
    if (passive[i]) idx[n++] = i;
  }
  for (int r = 0; r < n; ++r) {
    for (int c = 0; c < n; ++c) m[r][c] = g[idx[r]][idx[c]];
    m[r][n] = b[idx[r]];
  }
  for (int c = 0; c < n; ++c) {
    int piv = c;
    for (int r = c + 1; r < n; ++r)
      if (fabs(m[r][c]) > fabs(m[piv][c])) piv = r;
    if (fabs(m[piv][c]) < 1e-300) return 0;
    if (piv != c)
      for (int k = 0; k <= n; ++k) {
        const double t = m[c][k];
        m[c][k] = m[piv][k];
        m[piv][k] = t;
      }
    for (int r = c + 1; r < n; ++r) {
      const double f = m[r][c] / m[c][c];
      for (int k = c; k <= n; ++k) m[r][k] -= f * m[c][k];
    }
  }
  for (int r = n - 1; r >= 0; --r) {
    double s = m[r][n];
    for (int k = r + 1; k < n; ++k) s -= m[r][k] * z[idx[k]];
    z[idx[r]] = s / m[r][r];
  }
  return 1;
}

void ts_ac_nnls6(const double g[6][6], const double b[6], double x[6]) {
  int passive[6] = {0};
  double scale = 0;
  for (int i = 0; i < 6; ++i) {
    x[i] = 0;
    if (fabs(b[i]) > scale) scale = fabs(b[i]);
  }
  const double tol = 1e-13 * (scale > 0 ? scale : 1);
  for (int outer = 0; outer < 18; ++outer) {
    /* w = b - G x: the descent direction; stop when no zero variable can grow. */
    int best = -1;
    double wbest = tol;
    for (int i = 0; i < 6; ++i) {
      if (passive[i]) continue;
      double w = b[i];
      for (int j = 0; j < 6; ++j) w -= g[i][j] * x[j];
      if (w > wbest) {
        wbest = w;
        best = i;
      }
    }
    if (best < 0) return;
    passive[best] = 1;
    for (int inner = 0; inner < 6; ++inner) {
      double z[6];
      if (!solve_subset(g, b, passive, z)) return;
      int feasible = 1;
      for (int i = 0; i < 6; ++i)
        if (passive[i] && z[i] <= 0) feasible = 0;
      if (feasible) {
        for (int i = 0; i < 6; ++i) x[i] = z[i];
        break;
      }
      /* Step from x toward z until the first passive variable reaches zero; drop it. */
      double alpha = 1;
      for (int i = 0; i < 6; ++i)
        if (passive[i] && z[i] <= 0) {
          const double a = x[i] / (x[i] - z[i]);
          if (a < alpha) alpha = a;
        }
      for (int i = 0; i < 6; ++i) {
        x[i] += alpha * (z[i] - x[i]);
        if (passive[i] && x[i] <= tol * 1e-3) {
          passive[i] = 0;
          x[i] = 0;
        }
      }
    }
  }
}

void ts_ac_accum_solve(const ts_ac_accum *acc, float cube[6][3]) {
  if (acc->fit == TS_AC_FIT_MEAN) {
    for (int f = 0; f < 6; ++f)
      for (int k = 0; k < 3; ++k) cube[f][k] = acc->w[f] > 0 ? (float)(acc->b[f][k] / acc->w[f]) : 0.f;
    return;
  }
  /* lsq: the samples' quadrature of int h_f = 2pi/3 (the face's b for unit radiance) is w[f]; scaling
   * b_f by (2pi/3) / w[f] makes the rule exact on a constant radiance (162 ray directions would
   * otherwise leave an error of order 1e-3 on a uniform sky). */
  double norm[6];
  for (int f = 0; f < 6; ++f)
    norm[f] = (acc->fit == TS_AC_FIT_LSQ && acc->w[f] > 0) ? (2 * k_pi / 3) / acc->w[f] : 1.0;
  for (int k = 0; k < 3; ++k) {
    double b[6], x[6];
    for (int f = 0; f < 6; ++f) b[f] = acc->b[f][k] * norm[f];
    ts_ac_nnls6(acc->gram, b, x);
    for (int f = 0; f < 6; ++f) cube[f][k] = (float)x[f];
  }
}
