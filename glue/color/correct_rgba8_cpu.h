// tiershade color: colour correction of an RGBA8 display frame by the C twin of
// color_correction.fs, as the GL pass computes it: the colour is the RGBA8 texel fetched as
// float (ts_unorm8_to_float), the result is written to an RGBA8 target (ts_unorm8_from_float).
#pragma once
#include <cstdint>
#include <vector>

#include "twins/color_correction.h"

// frame: w x h RGBA8 codes (rows bottom-up), corrected in place; shared: the CC_SLOTS record
// (its colour slot is ignored); threads: 0 = all cores.
void cc_apply_rgba8_c(const cc_variant &v, const ts_vec4f *shared, const cc_luts &luts, int w, int h,
                      std::vector<uint8_t> *frame, int threads = 0);
