// tiershade bake: the checkpoints of a bake directory being written (bake_dir.h): DIR.partial/pass.bin
// holds the latest finished pass (BakePassState: the grids, what the next bounce starts from, the
// stats so far), written atomically, with the bake's hash and a trailing hash of its bytes so that a
// file of another bake, an older format or a torn write is never resumed from.
//
// Layout (native little-endian): "TSBAKEPS" | u32 version | u64 bake hash | i32 pass | i32 stopped |
// f64 total | f64 direct_ms | i64 direct_rays | i32 passes | i64 rays | i64 skipped_black |
// vec<f64> added | vec<i64> pass_rays | vec<f64> pass_ms | u32 faces | per face: i32 w, i32 h,
// w h 4 x 3 f64 | u32 send faces | per face: vec<f64> | u64 hash of all the bytes before.
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "bake/bake_dir.h"
#include "bake/content_hash.h"
#include "io/atomic_file.h"

namespace fs = std::filesystem;

namespace {

const char kMagic[8] = {'T', 'S', 'B', 'A', 'K', 'E', 'P', 'S'};
const uint32_t kVersion = 1;
const uint64_t kMaxBytes = 1ull << 32;  // a checkpoint past 4 GB is refused, never read whole

struct Out {
  std::string b;
  template <class T>
  void put(const T &v) {
    b.append(reinterpret_cast<const char *>(&v), sizeof v);
  }
  template <class T>
  void vec(const std::vector<T> &v) {
    put(static_cast<uint64_t>(v.size()));
    if (!v.empty()) b.append(reinterpret_cast<const char *>(v.data()), v.size() * sizeof(T));
  }
};

struct In {
  const std::string &b;
  size_t at = 0;
  bool ok = true;
  template <class T>
  T get() {
    T v{};
    if (!ok || b.size() - at < sizeof v) {
      ok = false;
      return v;
    }
    std::memcpy(&v, b.data() + at, sizeof v);
    at += sizeof v;
    return v;
  }
  template <class T>
  std::vector<T> vec() {
    const uint64_t n = get<uint64_t>();
    std::vector<T> v;
    if (!ok || n > (b.size() - at) / sizeof(T)) {  // bounded by the bytes left
      ok = false;
      return v;
    }
    v.resize(n);
    if (n) std::memcpy(v.data(), b.data() + at, n * sizeof(T));
    at += n * sizeof(T);
    return v;
  }
};

std::string file_of(const std::string &dir) { return bake_checkpoint_dir(dir) + "/pass.bin"; }

}  // namespace

std::string bake_checkpoint_dir(const std::string &dir) {
  std::string d = dir;
  while (d.size() > 1 && d.back() == '/') d.pop_back();
  return d + ".partial";
}

bool save_checkpoint(const std::string &dir, const BakeHash &hash, const BakePassState &st, std::string *err) {
  std::error_code ec;
  fs::create_directories(bake_checkpoint_dir(dir), ec);
  if (ec) {
    *err = "cannot create the checkpoint directory " + bake_checkpoint_dir(dir) + ": " + ec.message();
    return false;
  }
  Out o;
  o.b.append(kMagic, sizeof kMagic);
  o.put(kVersion);
  o.put(hash.all());
  o.put(static_cast<int32_t>(st.pass));
  o.put(static_cast<int32_t>(st.stopped));
  o.put(st.total);
  o.put(st.direct_ms);
  o.put(static_cast<int64_t>(st.direct_rays));
  o.put(static_cast<int32_t>(st.report.passes));
  o.put(static_cast<int64_t>(st.report.rays));
  o.put(static_cast<int64_t>(st.report.skipped_black));
  o.vec(st.report.added);
  std::vector<int64_t> pr(st.report.pass_rays.begin(), st.report.pass_rays.end());
  o.vec(pr);
  o.vec(st.report.pass_ms);
  o.put(static_cast<uint32_t>(st.grids.size()));
  for (const LuxelGrid &g : st.grids) {
    o.put(static_cast<int32_t>(g.w));
    o.put(static_cast<int32_t>(g.h));
    for (const ts_vec3d &v : g.v) {
      o.put(v.x);
      o.put(v.y);
      o.put(v.z);
    }
  }
  o.put(static_cast<uint32_t>(st.send.size()));
  for (const std::vector<ts_vec3d> &s : st.send) {
    std::vector<double> d;
    for (const ts_vec3d &v : s) d.insert(d.end(), {v.x, v.y, v.z});
    o.vec(d);
  }
  ContentHash h;
  h.bytes(o.b.data(), o.b.size());
  o.put(h.h);
  return write_file_atomic(file_of(dir), o.b, err);
}

bool load_checkpoint(const std::string &dir, const BakeHash &hash, BakePassState *st, std::string *note) {
  note->clear();
  const std::string path = file_of(dir);
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) return false;
  auto discard = [&](const std::string &why) {
    *note = path + ": " + why + "; discarded, baking every pass";
    fs::remove(path, ec);
    return false;
  };
  const uint64_t size = fs::file_size(path, ec);
  if (ec || size > kMaxBytes) return discard("unreadable or too large");
  std::ifstream f(path, std::ios::binary);
  std::stringstream ss;
  ss << f.rdbuf();
  const std::string b = ss.str();
  if (b.size() < sizeof kMagic + 8 || std::memcmp(b.data(), kMagic, sizeof kMagic) != 0)
    return discard("not a tiershade bake checkpoint");
  ContentHash h;
  h.bytes(b.data(), b.size() - 8);
  uint64_t tail;
  std::memcpy(&tail, b.data() + b.size() - 8, 8);
  if (tail != h.h) return discard("torn or corrupt (its trailing hash does not match)");
  const std::string body = b.substr(0, b.size() - 8);
  In in{body, sizeof kMagic};
  if (in.get<uint32_t>() != kVersion) return discard("another checkpoint format");
  if (in.get<uint64_t>() != hash.all())
    return discard("from a bake of another scene, settings or seed (its hash differs)");
  BakePassState s;
  s.pass = in.get<int32_t>();
  s.stopped = in.get<int32_t>() != 0;
  s.total = in.get<double>();
  s.direct_ms = in.get<double>();
  s.direct_rays = static_cast<long>(in.get<int64_t>());
  s.report.passes = in.get<int32_t>();
  s.report.rays = static_cast<long>(in.get<int64_t>());
  s.report.skipped_black = static_cast<long>(in.get<int64_t>());
  s.report.added = in.vec<double>();
  for (int64_t r : in.vec<int64_t>()) s.report.pass_rays.push_back(static_cast<long>(r));
  s.report.pass_ms = in.vec<double>();
  const uint32_t nf = in.get<uint32_t>();
  for (uint32_t i = 0; in.ok && i < nf; ++i) {
    LuxelGrid g;
    g.w = in.get<int32_t>();
    g.h = in.get<int32_t>();
    const uint64_t n = static_cast<uint64_t>(g.w) * static_cast<uint64_t>(g.h) * 4;
    if (g.w < 2 || g.h < 2 || g.w > 8192 || g.h > 8192 || n * 24 > body.size() - in.at) {
      in.ok = false;
      break;
    }
    g.v.resize(n);
    for (ts_vec3d &v : g.v) {
      v.x = in.get<double>();
      v.y = in.get<double>();
      v.z = in.get<double>();
    }
    s.grids.push_back(std::move(g));
  }
  const uint32_t ns = in.get<uint32_t>();
  for (uint32_t i = 0; in.ok && i < ns; ++i) {
    const std::vector<double> d = in.vec<double>();
    std::vector<ts_vec3d> v;
    for (size_t k = 0; k + 2 < d.size(); k += 3) v.push_back(ts_v3d(d[k], d[k + 1], d[k + 2]));
    s.send.push_back(std::move(v));
  }
  if (!in.ok || in.at != body.size() || s.pass < 0 || s.report.passes != s.pass ||
      (s.pass > 0 && s.send.size() != s.grids.size()))
    return discard("inconsistent contents");
  for (size_t i = 0; i < s.send.size(); ++i)
    if (s.send[i].size() != static_cast<size_t>(s.grids[i].w) * s.grids[i].h) return discard("inconsistent contents");
  *st = std::move(s);
  return true;
}
