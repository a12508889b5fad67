// tiershade conform: per-pixel error bounds. A family with an interval instance of its C twin
// (c_ref/math/ts_interval.h: every operation gives the interval of results GLSL ES 3.00 highp
// allows) gets, for every pixel and channel, the interval any conformant implementation must land
// in; `tiershade conform --bounds` renders the variant on GL and checks that every pixel is inside
// (docs/conformance.md "Error bounds"). The 0-ULP check (conform.h) is separate and unchanged.
#pragma once
#include <string>
#include <vector>

#include "conform/conform.h"
#include "math/ts_interval.h"

struct BoundsResult {
  std::string shader, variant, tier, backend, api, set;
  long pixels = 0, channels = 0;
  long outside = 0;  // channels of GL output outside their interval
  long c_outside = 0;  // channels of the C float twin outside (the interval instance's own check)
  long unbounded = 0;  // channels whose interval admits anything (NaN input, log2 of 0...)
  double worst_excess_ulp = 0;  // largest distance of a GL value outside its interval, float32 ULP
  double median_width_ulp = 0, max_width_ulp = 0;  // over the bounded colour channels (RGB)
  // The implementation against the references, over the bounded colour channels: its distance in
  // float32 ULP from the C double twin (rounded to float), and how many channels equal the C float
  // twin bit for bit (the llvmpipe mirror: on llvmpipe itself, all of them).
  double median_double_ulp = 0, max_double_ulp = 0;
  long compared = 0, equal_to_c = 0;
  std::vector<std::string> unbounded_cases;  // hard set: the cases with an unbounded channel
  std::vector<std::string> outside_cases;  // hard set: the cases with a channel outside its interval
  std::string error, worst;
  bool passed() const { return error.empty() && outside == 0 && c_outside == 0; }
  double share_inside() const { return channels ? 1.0 - static_cast<double>(outside) / channels : 1.0; }
};

// The interval of pixel (x, y) for family `name`'s variant v, or false when the family has no
// interval instance (every family with a C twin has one since issue 14's second step).
bool has_bounds(const std::string &family);
ts_vec4iv eval_bounds(const ShaderFamily &fam, const Variant &v, const FamilyInputs &in, int x, int y);

// Renders `in` through v's conformance program on the run's renderer and checks every channel
// against its interval (GL and the C float twin).
BoundsResult bounds_variant(const ConformRun &run, const ShaderFamily &fam, const Variant &v, const FamilyInputs &in,
                            InputSet set);
// Checks an implementation's output `img` (in.w x in.h, the variant drawn over `in`) against the
// intervals, channel by channel, and the C float twin too; fills res's counts, widths and worst pixel.
// bounds_variant draws on llvmpipe and calls it; glue/browser brings the image from a browser.
void check_bounds_image(const ShaderFamily &fam, const Variant &v, const FamilyInputs &in, const ImageF &img,
                        BoundsResult *res);
std::string bounds_result_json(const BoundsResult &r);
