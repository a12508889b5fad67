// tiershade bake: a 64-bit content hash (FNV-1a, Fowler-Noll-Vo; the 64-bit offset basis and prime of
// the published parameters) of what a bake depends on: the bake directory's manifest and its
// checkpoints compare it with the scene (glue/bake/bake_dir.h). Not cryptographic: it tells a stale
// bake from a current one, it does not defend against a forged one.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

struct ContentHash {
  uint64_t h = 0xcbf29ce484222325ull;
  void bytes(const void *p, size_t n) {
    const unsigned char *c = static_cast<const unsigned char *>(p);
    for (size_t i = 0; i < n; ++i) h = (h ^ c[i]) * 0x100000001b3ull;
  }
  template <class T>
  void value(const T &v) {
    bytes(&v, sizeof v);
  }
  template <class T>
  void values(const std::vector<T> &v) {
    value(v.size());
    if (!v.empty()) bytes(v.data(), v.size() * sizeof(T));
  }
  void text(const std::string &s) {
    value(s.size());
    bytes(s.data(), s.size());
  }
};
