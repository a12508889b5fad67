// tiershade color: sRGB -> CIELAB and CIEDE2000 (see color_difference.h). Written from
// the published formulas; equation numbers are Sharma, Wu and Dalal (2005).
#include "color/ciede2000.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/constants.hpp>

#include "base/srgb.h"

namespace {

double rad(double deg) { return deg * glm::pi<double>() / 180.0; }
double deg(double r) { return r * 180.0 / glm::pi<double>(); }

// CIE 15:2004 L*a*b* companding: t^(1/3) above (6/29)^3, else t / (3 (6/29)^2) + 4/29.
double lab_f(double t) {
  const double d = 6.0 / 29.0;
  return t > d * d * d ? std::cbrt(t) : t / (3.0 * d * d) + 4.0 / 29.0;
}

double pow7(double x) {
  const double x2 = x * x, x3 = x2 * x;
  return x3 * x3 * x;
}

}  // namespace

Lab srgb_to_lab(double r, double g, double b) {
  auto clamp01 = [](double v) { return std::isnan(v) ? 0.0 : std::min(1.0, std::max(0.0, v)); };
  const double R = srgb_decode(clamp01(r)), G = srgb_decode(clamp01(g)), B = srgb_decode(clamp01(b));
  // Linear sRGB -> XYZ: the matrix of the Rec. 709 primaries and the D65 white (x, y) =
  // (0.3127, 0.3290) to 7 digits (IEC 61966-2-1 prints it rounded to 4); the white is the
  // sum of each row, so that (1, 1, 1) is exactly neutral.
  const double X = 0.4124564 * R + 0.3575761 * G + 0.1804375 * B;
  const double Y = 0.2126729 * R + 0.7151522 * G + 0.0721750 * B;
  const double Z = 0.0193339 * R + 0.1191920 * G + 0.9503041 * B;
  const double Xn = 0.4124564 + 0.3575761 + 0.1804375;
  const double Yn = 0.2126729 + 0.7151522 + 0.0721750;
  const double Zn = 0.0193339 + 0.1191920 + 0.9503041;
  const double fx = lab_f(X / Xn), fy = lab_f(Y / Yn), fz = lab_f(Z / Zn);
  return {116.0 * fy - 16.0, 500.0 * (fx - fy), 200.0 * (fy - fz)};
}

double ciede2000(const Lab &x, const Lab &y) {
  // (2)-(4): chroma, the a* stretch G, a', C'.
  const double C1 = std::hypot(x.a, x.b), C2 = std::hypot(y.a, y.b);
  const double Cbar7 = pow7(0.5 * (C1 + C2));
  const double G = 0.5 * (1.0 - std::sqrt(Cbar7 / (Cbar7 + pow7(25.0))));
  const double a1 = (1.0 + G) * x.a, a2 = (1.0 + G) * y.a;
  const double C1p = std::hypot(a1, x.b), C2p = std::hypot(a2, y.b);
  // (7): hue angle in [0, 360), 0 when a' = b = 0.
  auto hue = [](double b, double ap) {
    if (b == 0.0 && ap == 0.0) return 0.0;
    const double h = deg(std::atan2(b, ap));
    return h < 0.0 ? h + 360.0 : h;
  };
  const double h1 = hue(x.b, a1), h2 = hue(y.b, a2);
  // (8)-(11): differences.
  const double dL = y.L - x.L, dC = C2p - C1p;
  const double CC = C1p * C2p;
  double dh = 0.0;
  if (CC != 0.0) {
    dh = h2 - h1;
    if (dh > 180.0)
      dh -= 360.0;
    else if (dh < -180.0)
      dh += 360.0;
  }
  const double dH = 2.0 * std::sqrt(CC) * std::sin(rad(dh) / 2.0);
  // (12)-(14): means; the mean hue goes the short way round the circle.
  const double Lbar = 0.5 * (x.L + y.L), Cbarp = 0.5 * (C1p + C2p);
  double hbar = h1 + h2;
  if (CC != 0.0) {
    if (std::fabs(h1 - h2) <= 180.0)
      hbar = 0.5 * (h1 + h2);
    else if (h1 + h2 < 360.0)
      hbar = 0.5 * (h1 + h2 + 360.0);
    else
      hbar = 0.5 * (h1 + h2 - 360.0);
  }
  // (15)-(21): weighting functions and the rotation term.
  const double T = 1.0 - 0.17 * std::cos(rad(hbar - 30.0)) + 0.24 * std::cos(rad(2.0 * hbar)) +
      0.32 * std::cos(rad(3.0 * hbar + 6.0)) - 0.20 * std::cos(rad(4.0 * hbar - 63.0));
  const double dtheta = 30.0 * std::exp(-((hbar - 275.0) / 25.0) * ((hbar - 275.0) / 25.0));
  const double Cbarp7 = pow7(Cbarp);
  const double RC = 2.0 * std::sqrt(Cbarp7 / (Cbarp7 + pow7(25.0)));
  const double L50 = (Lbar - 50.0) * (Lbar - 50.0);
  const double SL = 1.0 + 0.015 * L50 / std::sqrt(20.0 + L50);
  const double SC = 1.0 + 0.045 * Cbarp;
  const double SH = 1.0 + 0.015 * Cbarp * T;
  const double RT = -std::sin(rad(2.0 * dtheta)) * RC;
  // (22), kL = kC = kH = 1.
  const double l = dL / SL, c = dC / SC, h = dH / SH;
  return std::sqrt(l * l + c * c + h * h + RT * c * h);
}
