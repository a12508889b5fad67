// tiershade families: shader-family plumbing shared by every family (see family.h).
#include "families/family.h"
#include "families/record_family.h"

#include <cmath>

#include <algorithm>

const char *input_set_name(InputSet s) { return s == InputSet::Random ? "random" : "hard"; }

ts_vec4f FamilyInputs::slot(int x, int y, int k) const {
  if (k >= slots) return shared.at(k);
  const float *p = &records[(static_cast<size_t>(y + k * h) * w + x) * 4];
  return ts_v4f(p[0], p[1], p[2], p[3]);
}
void FamilyInputs::gather(int x, int y, int n, ts_vec4f *rec) const {
  for (int k = 0; k < n; ++k) rec[k] = slot(x, y, k);
}
void FamilyInputs::set_slot(int x, int y, int k, ts_vec4f v) {
  float *p = &records[(static_cast<size_t>(y + k * h) * w + x) * 4];
  p[0] = v.x;
  p[1] = v.y;
  p[2] = v.z;
  p[3] = v.w;
}
void FamilyInputs::resize(int w_, int h_, int slots_) {
  w = w_;
  h = h_;
  slots = slots_;
  records.assign(static_cast<size_t>(w) * h * slots * 4, 0.f);
}
TextureDesc FamilyInputs::record_texture() const {
  TextureDesc t;
  t.sampler = "ts_record";
  t.w = w;
  t.h = h * slots;
  t.rgba = records;
  return t;
}

namespace {
// Function-local statics: registrars run during static initialisation, in any order.
std::vector<const ShaderFamily *> &family_registry() {
  static std::vector<const ShaderFamily *> r;
  return r;
}
std::vector<const DemoSection *> &demo_registry() {
  static std::vector<const DemoSection *> r;
  return r;
}
std::vector<const BenchSection *> &bench_registry() {
  static std::vector<const BenchSection *> r;
  return r;
}
template <class T>
std::vector<const T *> sorted(std::vector<const T *> v) {
  std::sort(v.begin(), v.end(), [](const T *a, const T *b) { return std::string(a->name) < b->name; });
  return v;
}
}  // namespace

FamilyRegistrar::FamilyRegistrar(const ShaderFamily *f) { family_registry().push_back(f); }
DemoRegistrar::DemoRegistrar(const DemoSection *s) { demo_registry().push_back(s); }
BenchRegistrar::BenchRegistrar(const BenchSection *s) { bench_registry().push_back(s); }
std::vector<const ShaderFamily *> all_families() { return sorted(family_registry()); }
std::vector<const DemoSection *> demo_sections() { return sorted(demo_registry()); }
std::vector<const BenchSection *> bench_sections() { return sorted(bench_registry()); }

const ShaderFamily *find_family(const std::string &name) {
  for (const ShaderFamily *f : all_families())
    if (name == f->name) return f;
  return nullptr;
}

std::vector<Define> variant_defines(const Variant &v, InputMode mode) {
  std::vector<Define> d;
  switch (v.tier) {
    case Tier::PS20:
      d.push_back({"TS_TIER_PS20", "1"});
      break;
    case Tier::PS2B:
      d.push_back({"TS_TIER_PS2B", "1"});
      break;
    case Tier::SM3:
      d.push_back({"TS_TIER_SM3", "1"});
      break;
  }
  for (const auto &kv : v.values) d.push_back({kv.first, std::to_string(kv.second)});
  // A combo that does not exist in this tier is defined as 0, so `#if NAME` is always valid.
  if (v.shader)
    for (const auto &c : v.shader->combos) {
      bool present = false;
      for (const auto &kv : v.values) present = present || kv.first == c.name;
      if (!present) d.push_back({c.name, "0"});
    }
  if (mode == InputMode::Conform) d.push_back({"TS_CONFORM", "1"});
  if (mode == InputMode::Deferred) d.push_back({"TS_DEFERRED", "1"});
  return d;
}

void output_range_half(const Variant &, float *lo, float *hi) {
  *lo = 0.f;
  *hi = 65504.f;
}
void output_range_unit(const Variant &, float *lo, float *hi) {
  *lo = 0.f;
  *hi = 1.f;
}
void output_range_by_output_mode(const Variant &v, float *lo, float *hi) {
  (v.value("OUTPUT_MODE") == 0 ? output_range_half : output_range_unit)(v, lo, hi);
}

TextureDesc blank_texture(const std::string &sampler, int w, int h, bool linear, bool repeat) {
  TextureDesc t;
  t.sampler = sampler;
  t.w = w;
  t.h = h;
  t.linear = linear;
  t.repeat = repeat;
  t.rgba.assign(static_cast<size_t>(w) * h * 4, 0.f);
  return t;
}

ts_tex2d tex2d_of(const TextureDesc &t) {
  const int wrap = t.repeat ? TS_WRAP_REPEAT : TS_WRAP_CLAMP;
  ts_tex2d x = ts_tex2d_single(t.w, t.h, t.rgba.data(), wrap, wrap, t.linear ? TS_FILTER_LINEAR : TS_FILTER_NEAREST);
  if (!t.mips.empty() && t.mip_filter != TS_MIP_NONE && t.mips.size() < TS_MAX_MIP_LEVELS) {
    x.mip_levels = static_cast<int>(t.mips.size()) + 1;
    x.mip_filter = t.mip_filter;
    x.mip_w[0] = t.w;
    x.mip_h[0] = t.h;
    x.mip_texels[0] = t.rgba.data();
    for (size_t k = 0; k < t.mips.size(); ++k) {
      const int l = static_cast<int>(k) + 1;
      x.mip_w[l] = std::max(1, t.w >> l);
      x.mip_h[l] = std::max(1, t.h >> l);
      x.mip_texels[l] = t.mips[k].data();
    }
  }
  return x;
}

ts_texcube texcube_of(const TextureDesc &t) {
  ts_texcube c;
  c.size = t.w;
  for (int f = 0; f < 6; ++f) c.faces[f] = t.rgba.data() + static_cast<size_t>(f) * t.w * t.w * 4;
  c.filter = t.linear ? TS_FILTER_LINEAR : TS_FILTER_NEAREST;
  return c;
}

ts_vec3f Rng::unit_vector() {
  for (;;) {
    const float x = uniform(-1, 1), y = uniform(-1, 1), z = uniform(-1, 1);
    const float l2 = x * x + y * y + z * z;
    if (l2 > 0.01f && l2 <= 1.f) {
      const float inv = 1.0f / std::sqrt(l2);
      return ts_v3f(x * inv, y * inv, z * inv);
    }
  }
}
