// tiershade color: colour correction of an RGBA8 frame by the C twin (glue/color/correct_rgba8_cpu.h), a row at
// a time through the batch twin (c_ref/twins/color_correction_batch.h: 8 or 4 pixels per SIMD call,
// color_correction_f's bits): the colours are the row's texels fetched as float, the other
// slots are the shared record (stride 0).
#include "color/correct_rgba8_cpu.h"

#include <cstring>

#include "twins/color_correction_batch.h"
#include "math/hdr_formats.h"
#include "twins/hdr_post_batch.h"
#include "base/parallel_rows.h"

namespace {

// A worker's corrected colours: the pass is a function of the pixel's RGBA8 code alone (its one
// pixel slot, shaders/color_correction_slots.glsl; the LUTs and weights are shared), so a colour
// met before is looked up (direct-mapped by its 32 bits); only new colours go through the twin.
struct CcCache {
  static const int kBits = 14;
  struct Entry {
    uint32_t key = 0, val = 0;
    bool full = false;
  };
  std::vector<Entry> e = std::vector<Entry>(size_t(1) << kBits);
  static size_t slot(uint32_t key) { return (key * 2654435761u) >> (32 - kBits); }
};

}  // namespace

void cc_apply_rgba8_c(const cc_variant &v, const ts_vec4f *shared, const cc_luts &luts, int w, int h,
                      std::vector<uint8_t> *frame, int threads) {
  float code[256];  // the RGBA8 texel fetch, code by code
  for (int c = 0; c < 256; ++c) code[c] = ts_unorm8_to_float(static_cast<uint8_t>(c));
  std::vector<CcCache> caches(static_cast<size_t>(parallel_workers(h, threads)));
  parallel_rows_by_worker(h, threads, [&](int t, int y) {
    CcCache &cache = caches[static_cast<size_t>(t)];
    uint8_t *c8 = &(*frame)[static_cast<size_t>(y) * w * 4];
    // The row's colours not in the cache (the first pixel of each, in row order).
    std::vector<ts_vec4f> colour, out;
    std::vector<int> miss;
    colour.reserve(static_cast<size_t>(w));
    miss.reserve(static_cast<size_t>(w));
    for (int x = 0; x < w; ++x) {
      const uint8_t *p = c8 + static_cast<size_t>(x) * 4;
      uint32_t key;
      std::memcpy(&key, p, 4);
      const CcCache::Entry &en = cache.e[CcCache::slot(key)];
      if (en.full && en.key == key) {
        std::memcpy(c8 + static_cast<size_t>(x) * 4, &en.val, 4);
        continue;
      }
      miss.push_back(x);
      colour.push_back(ts_v4f(code[p[0]], code[p[1]], code[p[2]], code[p[3]]));
    }
    if (miss.empty()) return;
    cc_batch_input in;
    for (int k = 0; k < CC_SLOTS; ++k) {
      in.slot[k] = &shared[k];
      in.stride[k] = 0;
    }
    in.slot[CC_SLOT_COLOR] = colour.data();
    in.stride[CC_SLOT_COLOR] = 1;
    out.resize(colour.size());
    color_correction_f_batch(&v, &in, &luts, out.data(), static_cast<int>(out.size()));
    std::vector<uint8_t> codes(out.size() * 4);
    ts_unorm8_from_float_batch(&out[0].x, codes.data(), out.size() * 4);
    for (size_t i = 0; i < miss.size(); ++i) {
      uint8_t *p = c8 + static_cast<size_t>(miss[i]) * 4;
      CcCache::Entry &en = cache.e[CcCache::slot([&] {
        uint32_t k;
        std::memcpy(&k, p, 4);
        return k;
      }())];
      std::memcpy(&en.key, p, 4);
      std::memcpy(&en.val, &codes[i * 4], 4);
      en.full = true;
      std::memcpy(p, &codes[i * 4], 4);
    }
  });
}
