// tiershade color: colour correction of an RGBA8 frame by the C twin (glue/color/correct_rgba8_cpu.h), a row at
// a time through the batch twin (c_ref/twins/color_correction_batch.h: 8 or 4 pixels per SIMD call,
// color_correction_f's bits): the colours are the row's texels fetched as float, the other
// slots are the shared record (stride 0).
#include "color/correct_rgba8_cpu.h"

#include "twins/color_correction_batch.h"
#include "math/hdr_formats.h"
#include "twins/hdr_post_batch.h"
#include "base/parallel_rows.h"

void cc_apply_rgba8_c(const cc_variant &v, const ts_vec4f *shared, const cc_luts &luts, int w, int h,
                      std::vector<uint8_t> *frame, int threads) {
  float code[256];  // the RGBA8 texel fetch, code by code
  for (int c = 0; c < 256; ++c) code[c] = ts_unorm8_to_float(static_cast<uint8_t>(c));
  parallel_rows(h, threads, [&](int y) {
    uint8_t *c8 = &(*frame)[static_cast<size_t>(y) * w * 4];
    std::vector<ts_vec4f> colour(static_cast<size_t>(w)), out(static_cast<size_t>(w));
    for (int x = 0; x < w; ++x) {
      const uint8_t *p = c8 + static_cast<size_t>(x) * 4;
      colour[x].x = code[p[0]];
      colour[x].y = code[p[1]];
      colour[x].z = code[p[2]];
      colour[x].w = code[p[3]];
    }
    cc_batch_input in;
    for (int k = 0; k < CC_SLOTS; ++k) {
      in.slot[k] = &shared[k];
      in.stride[k] = 0;
    }
    in.slot[CC_SLOT_COLOR] = colour.data();
    in.stride[CC_SLOT_COLOR] = 1;
    color_correction_f_batch(&v, &in, &luts, out.data(), w);
    ts_unorm8_from_float_batch(&out[0].x, c8, out.size() * 4);
  });
}
