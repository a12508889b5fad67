// tiershade base: base64 encode and decode (RFC 4648 section 4).
#include "base/base64.h"

namespace {
const char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";

int value_of(char c) {
  if (c >= 'A' && c <= 'Z') return c - 'A';
  if (c >= 'a' && c <= 'z') return c - 'a' + 26;
  if (c >= '0' && c <= '9') return c - '0' + 52;
  if (c == '+') return 62;
  if (c == '/') return 63;
  return -1;
}
}  // namespace

std::string base64_encode(const void *data, size_t n) {
  const uint8_t *p = static_cast<const uint8_t *>(data);
  std::string s;
  s.reserve((n + 2) / 3 * 4);
  for (size_t i = 0; i < n; i += 3) {
    const uint32_t b0 = p[i], b1 = i + 1 < n ? p[i + 1] : 0, b2 = i + 2 < n ? p[i + 2] : 0;
    const uint32_t v = b0 << 16 | b1 << 8 | b2;
    s += kAlphabet[v >> 18 & 63];
    s += kAlphabet[v >> 12 & 63];
    s += i + 1 < n ? kAlphabet[v >> 6 & 63] : '=';
    s += i + 2 < n ? kAlphabet[v & 63] : '=';
  }
  return s;
}

bool base64_decode(const std::string &s, std::vector<uint8_t> *out) {
  out->clear();
  if (s.size() % 4 != 0) return false;
  out->reserve(s.size() / 4 * 3);
  for (size_t i = 0; i < s.size(); i += 4) {
    const bool last = i + 4 == s.size();
    int v[4];
    int pad = 0;
    for (int k = 0; k < 4; ++k) {
      const char c = s[i + k];
      if (c == '=' && last && k >= 2) {
        v[k] = 0;
        ++pad;
        continue;
      }
      if (pad) return false;  // a character after padding
      v[k] = value_of(c);
      if (v[k] < 0) return false;
    }
    const uint32_t w = static_cast<uint32_t>(v[0]) << 18 | static_cast<uint32_t>(v[1]) << 12 |
                       static_cast<uint32_t>(v[2]) << 6 | static_cast<uint32_t>(v[3]);
    out->push_back(static_cast<uint8_t>(w >> 16));
    if (pad < 2) out->push_back(static_cast<uint8_t>(w >> 8 & 255));
    if (pad < 1) out->push_back(static_cast<uint8_t>(w & 255));
  }
  return true;
}
