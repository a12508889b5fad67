// tiershade glue: colour correction of an RGBA8 frame by the C twin (glue/cc_cpu.h).
#include "cc_cpu.h"

#include "hdr_formats.h"
#include "parallel_rows.h"

void cc_apply_rgba8_c(const cc_variant &v, const ts_vec4f *shared, const cc_luts &luts, int w, int h,
                      std::vector<uint8_t> *frame, int threads) {
  scene_parallel_rows(h, threads, [&](int y) {
    for (int x = 0; x < w; ++x) {
      uint8_t *c8 = &(*frame)[(static_cast<size_t>(y) * w + x) * 4];
      ts_vec4f rec[CC_SLOTS];
      for (int k = 0; k < CC_SLOTS; ++k) rec[k] = shared[k];
      rec[CC_SLOT_COLOR] = ts_v4f(ts_unorm8_to_float(c8[0]), ts_unorm8_to_float(c8[1]), ts_unorm8_to_float(c8[2]),
                                  ts_unorm8_to_float(c8[3]));
      const ts_vec4f c = color_correction_f(&v, rec, &luts);
      c8[0] = ts_unorm8_from_float(c.x);
      c8[1] = ts_unorm8_from_float(c.y);
      c8[2] = ts_unorm8_from_float(c.z);
      c8[3] = ts_unorm8_from_float(c.w);
    }
  });
}
