// tiershade color: perceptual colour difference for the colour-correction accuracy study:
// display-encoded sRGB -> CIELAB (D65) and the CIEDE2000 colour difference.
#pragma once

struct Lab {
  double L, a, b;
};

// sRGB display values (IEC 61966-2-1 curve, Rec. 709 primaries, D65) -> CIE 1976 L*a*b*
// (CIE 15:2004) with the D65 white of the same matrix, so that (1, 1, 1) gives L* = 100, a* = b* = 0.
// Inputs outside [0, 1] are clamped first (what an 8-bit display target shows).
Lab srgb_to_lab(double r, double g, double b);

// CIEDE2000 with kL = kC = kH = 1 (Sharma, Wu, Dalal, "The CIEDE2000 color-difference
// formula: implementation notes, supplementary test data, and mathematical observations",
// Color Research and Application 30(1), 2005, equations 1-22). Symmetric in its arguments.
double ciede2000(const Lab &x, const Lab &y);
