// tiershade tests: the small shared helpers of glue/base and glue/base/srgb.h: median()
// (base/stats.h) and the host sRGB curve (base/srgb.h) against IEC 61966-2-1 values, the
// float and double evaluations and the display encoding of an image.
#include <cmath>
#include <cstring>
#include <cstdio>
#include <vector>

#include "base/base64.h"
#include "base/image.h"
#include "base/stats.h"
#include "base/srgb.h"
#include "unit_check.h"

namespace {

void test_median() {
  check(median({3, 1, 2}) == 2, "median.odd");
  check(median({4, 1, 3, 2}) == 3, "median.even_upper_middle");
  check(median({}) == 0, "median.empty");
  check(median({7.5}) == 7.5, "median.single");
}

void test_srgb() {
  // IEC 61966-2-1: the curves meet at the thresholds (to the precision of the rounded constants).
  check(std::fabs(12.92 * 0.0031308 - (1.055 * std::pow(0.0031308, 1 / 2.4) - 0.055)) < 1e-7 &&
            std::fabs(srgb_encode(0.0031308) - 0.0031308 * 12.92) < 1e-7,
        "srgb.encode_threshold_continuous");
  check(std::fabs(srgb_decode(0.04045) - 0.04045 / 12.92) < 1e-9, "srgb.decode_threshold");
  check(srgb_encode(0.0) == 0 && std::fabs(srgb_encode(1.0) - 1) < 1e-15 && std::fabs(srgb_decode(1.0) - 1) < 1e-15,
        "srgb.end_points");
  // 0.5 encodes to 0.735357 and 0.5 decodes to 0.214041 (the curve's usual check values).
  check(std::fabs(srgb_encode(0.5) - 0.7353569830524495) < 1e-12, "srgb.encode_half", std::to_string(srgb_encode(0.5)));
  check(std::fabs(srgb_decode(0.5) - 0.21404114048223255) < 1e-12, "srgb.decode_half",
        std::to_string(srgb_decode(0.5)));
  double worst = 0;
  for (int i = 0; i <= 1000; ++i) {
    const double v = i / 1000.0;
    worst = std::max(worst, std::fabs(srgb_decode(srgb_encode(v)) - v));
  }
  check(worst < 1e-12, "srgb.round_trip", std::to_string(worst));
  // The float version evaluates in float: within a few float ulps of the double curve.
  float fworst = 0;
  for (int i = 0; i <= 1000; ++i) {
    const float v = i / 1000.f;
    fworst = std::max(fworst, std::fabs(srgb_encode(v) - static_cast<float>(srgb_encode<double>(v))));
  }
  check(fworst < 4e-7f, "srgb.float_close_to_double", std::to_string(fworst));
  check(srgb_encode_clamped(NAN) == 0 && srgb_encode_clamped(-1.0) == 0 && srgb_encode_clamped(2.f) == srgb_encode(1.f),
        "srgb.clamped");
  ImageF img;
  img.w = 2;
  img.h = 1;
  img.rgba = {0.5f, 0.f, 2.f, 0.25f, -1.f, 1.f, NAN, 0.75f};
  const ImageF d = srgb_display(img);
  check(d.w == 2 && d.h == 1 && d.rgba[0] == srgb_encode(0.5f) && d.rgba[1] == 0 && d.rgba[2] == srgb_encode(1.f) &&
            d.rgba[3] == 0.25f && d.rgba[4] == 0 && d.rgba[5] == srgb_encode(1.f) && d.rgba[6] == 0 &&
            d.rgba[7] == 0.75f,
        "srgb.display_image_alpha_kept");
}

// RFC 4648 section 10's test vectors, a float array round trip (what the WebGL page exchanges), and
// the malformed inputs refused.
void test_base64() {
  const char *plain[] = {"", "f", "fo", "foo", "foob", "fooba", "foobar"};
  const char *coded[] = {"", "Zg==", "Zm8=", "Zm9v", "Zm9vYg==", "Zm9vYmE=", "Zm9vYmFy"};
  bool enc = true, dec = true;
  for (int i = 0; i < 7; ++i) {
    const std::string p = plain[i];
    enc = enc && base64_encode(p.data(), p.size()) == coded[i];
    std::vector<uint8_t> b;
    dec = dec && base64_decode(coded[i], &b) && std::string(b.begin(), b.end()) == p;
  }
  check(enc, "base64.rfc4648_vectors_encode");
  check(dec, "base64.rfc4648_vectors_decode");
  std::vector<float> f = {0.0f, -0.0f, 1.5f, 65504.0f, 1e-45f, NAN, INFINITY, 0.113141268f};
  std::vector<uint8_t> b;
  const bool ok = base64_decode(base64_encode(f.data(), f.size() * 4), &b) && b.size() == f.size() * 4 &&
                  std::memcmp(b.data(), f.data(), b.size()) == 0;
  check(ok, "base64.float_bits_round_trip");
  const char *bad[] = {"Zg=", "Zg=a", "Z===", "Zm9v!A==", "Zg==Zg==", "Zm\n8="};
  bool refused = true;
  for (const char *s : bad) refused = refused && !base64_decode(s, &b);
  check(refused, "base64.malformed_refused");
}

}  // namespace

int main() {
  test_base64();
  test_median();
  test_srgb();
  return finish();
}
