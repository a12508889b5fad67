// tiershade bake: the baker's Embree scene (ray_scene.h).
#include "bake/ray_scene.h"

#include "bake/content_hash.h"

#include <embree3/rtcore.h>

#include <glm/geometric.hpp>

#include <atomic>
#include <csignal>
#include <ctime>
#include <sys/time.h>
#include <cmath>
#include <cstring>
#include <limits>

struct RayScene::Impl {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  std::vector<int> ids;  // Embree geometry id -> mesh id
  std::string error;  // the device's last error
  bool committed = false;
};

namespace {
// Embree takes rays and vertices whose coordinates lie within +-1.844e18 (its FLT_LARGE): beyond
// that (or NaN) a query is refused here (nothing hit, nothing in the way) rather than given to it.
const double kRayLimit = 1e18;
bool ray_in_range(const glm::dvec3 &o, const glm::dvec3 &d) {
  for (int k = 0; k < 3; ++k)
    if (!(std::fabs(o[k]) <= kRayLimit && std::fabs(d[k]) <= kRayLimit)) return false;
  return true;
}
void on_error(void *user, RTCError code, const char *str) {
  *static_cast<std::string *>(user) =
      "Embree error " + std::to_string(static_cast<int>(code)) + ": " + (str ? str : "(no message)");
}
}  // namespace

RayScene::RayScene() : impl_(new Impl) {
  // One build thread: the bake's own threads are the parallelism, and a 2-core machine stays calm.
  impl_->device = rtcNewDevice("threads=1");
  if (impl_->device) {
    rtcSetDeviceErrorFunction(impl_->device, on_error, &impl_->error);
    impl_->scene = rtcNewScene(impl_->device);
  }
}

RayScene::~RayScene() {
  if (impl_->scene) rtcReleaseScene(impl_->scene);
  if (impl_->device) rtcReleaseDevice(impl_->device);
  delete impl_;
}

bool RayScene::add_mesh(const std::vector<float> &position, const std::vector<uint32_t> &indices, int id,
                        const std::string &what, std::string *err) {
  if (!impl_->scene) {
    *err = "cannot create an Embree device" + (impl_->error.empty() ? std::string() : ": " + impl_->error);
    return false;
  }
  if (impl_->committed) {
    *err = what + ": added after the ray scene was built";
    return false;
  }
  const size_t nv = position.size() / 3, nt = indices.size() / 3;
  if (nt == 0) return true;
  for (size_t i = 0; i < nt * 3; ++i)
    if (indices[i] >= nv) {
      *err = what + ": triangle " + std::to_string(i / 3) + " names vertex " + std::to_string(indices[i]) + " of " +
          std::to_string(nv);
      return false;
    }
  for (float p : position)
    if (!std::isfinite(p) || std::fabs(p) > kRayLimit) {
      *err = what + ": a vertex position is not finite or beyond 1e18 (the ray tracer's range)";
      return false;
    }
  ContentHash ch{hash_};
  ch.value(id);
  ch.values(position);
  ch.values(indices);
  hash_ = ch.h;
  RTCGeometry g = rtcNewGeometry(impl_->device, RTC_GEOMETRY_TYPE_TRIANGLE);
  auto *v = static_cast<float *>(
      rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), nv));
  auto *t = static_cast<unsigned *>(
      rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), nt));
  if (!v || !t) {
    rtcReleaseGeometry(g);
    *err = what + ": " + (impl_->error.empty() ? std::string("Embree cannot allocate the buffers") : impl_->error);
    return false;
  }
  std::memcpy(v, position.data(), nv * 3 * sizeof(float));
  for (size_t i = 0; i < nt * 3; ++i) t[i] = indices[i];
  rtcCommitGeometry(g);
  const unsigned gid = rtcAttachGeometry(impl_->scene, g);
  rtcReleaseGeometry(g);
  if (impl_->ids.size() <= gid) impl_->ids.resize(gid + 1, -1);
  impl_->ids[gid] = id;
  triangles_ += static_cast<long>(nt);
  return true;
}

bool RayScene::commit(std::string *err) {
  if (!impl_->scene) {
    *err = "cannot create an Embree device" + (impl_->error.empty() ? std::string() : ": " + impl_->error);
    return false;
  }
  impl_->error.clear();
  rtcCommitScene(impl_->scene);
  if (!impl_->error.empty()) {
    *err = "building the ray scene: " + impl_->error;
    return false;
  }
  impl_->committed = true;
  return true;
}

namespace {
// Embree's share by sampling (as a profiler does): while timing is on, an ITIMER_PROF timer sends
// SIGPROF every 1 ms of the process's CPU time to the thread that spent it, and the handler counts
// whether that thread was inside a query. CPU time, not wall time: a machine loaded by other work
// changes neither count, and a query costs two stores of a thread-local flag.
const int kSampleUs = 1000;
thread_local volatile sig_atomic_t g_inside = 0;
std::atomic<long> g_in{0}, g_out{0};
std::atomic<bool> g_timing{false};
struct sigaction g_old_action;
double g_cpu0_ms = 0;  // the process's CPU time when timing started
double process_cpu_now_ms() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return t.tv_sec * 1e3 + t.tv_nsec / 1e6;
}
void on_prof(int) {
  if (g_inside)
    g_in.fetch_add(1, std::memory_order_relaxed);
  else
    g_out.fetch_add(1, std::memory_order_relaxed);
}
void set_ray(RTCRay *r, const glm::dvec3 &o, const glm::dvec3 &d, double tnear, double tfar) {
  r->org_x = static_cast<float>(o.x);
  r->org_y = static_cast<float>(o.y);
  r->org_z = static_cast<float>(o.z);
  r->dir_x = static_cast<float>(d.x);
  r->dir_y = static_cast<float>(d.y);
  r->dir_z = static_cast<float>(d.z);
  r->tnear = static_cast<float>(tnear);
  r->tfar = std::isinf(tfar) ? std::numeric_limits<float>::infinity() : static_cast<float>(tfar);
  r->time = 0;
  r->mask = 0xFFFFFFFFu;
  r->id = 0;
  r->flags = 0;
}
}  // namespace

void RayScene::set_timing(bool on) {
  if (on == g_timing.load()) {
    if (on) g_in.store(0), g_out.store(0), g_cpu0_ms = process_cpu_now_ms();
    return;
  }
  itimerval t{};
  if (on) {
    g_in.store(0);
    g_out.store(0);
    g_cpu0_ms = process_cpu_now_ms();
    struct sigaction sa {};
    sa.sa_handler = on_prof;
    sa.sa_flags = SA_RESTART;  // a system call the signal lands in resumes
    sigemptyset(&sa.sa_mask);
    sigaction(SIGPROF, &sa, &g_old_action);
    t.it_interval.tv_usec = t.it_value.tv_usec = kSampleUs;
    g_timing.store(true);
    setitimer(ITIMER_PROF, &t, nullptr);
  } else {
    setitimer(ITIMER_PROF, &t, nullptr);  // stopped
    g_timing.store(false);
    sigaction(SIGPROF, &g_old_action, nullptr);
  }
}

// The samples' share inside times the CPU time since timing started: the timer fires on the kernel's
// ticks (250 or 1000 a second), so the count of samples is not the ms, but their split is the share.
double RayScene::timed_ms() {
  const long in = g_in.load(), all = in + g_out.load();
  return all > 0 ? sampled_ms() * static_cast<double>(in) / all : 0.0;
}
double RayScene::sampled_ms() { return process_cpu_now_ms() - g_cpu0_ms; }

bool RayScene::occluded(const glm::dvec3 &origin, const glm::dvec3 &dir, double tnear, double tfar) const {
  if (!impl_->committed || !ray_in_range(origin, dir)) return false;
  RTCRay r;
  set_ray(&r, origin, dir, tnear, tfar);
  RTCIntersectContext ctx;
  rtcInitIntersectContext(&ctx);
  g_inside = 1;
  rtcOccluded1(impl_->scene, &ctx, &r);
  g_inside = 0;
  return r.tfar == -std::numeric_limits<float>::infinity();
}

RayScene::Hit RayScene::intersect(const glm::dvec3 &origin, const glm::dvec3 &dir, double tnear, double tfar) const {
  Hit h;
  if (!impl_->committed || !ray_in_range(origin, dir)) return h;
  RTCRayHit rh;
  set_ray(&rh.ray, origin, dir, tnear, tfar);
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.primID = RTC_INVALID_GEOMETRY_ID;
  RTCIntersectContext ctx;
  rtcInitIntersectContext(&ctx);
  g_inside = 1;
  rtcIntersect1(impl_->scene, &ctx, &rh);
  g_inside = 0;
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return h;
  h.t = rh.ray.tfar;
  h.id = rh.hit.geomID < impl_->ids.size() ? impl_->ids[rh.hit.geomID] : -1;
  h.triangle = static_cast<int>(rh.hit.primID);
  h.u = rh.hit.u;
  h.v = rh.hit.v;
  const glm::dvec3 n(rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z);
  const double len = glm::length(n);
  if (len > 0) h.normal = n / len;
  return h;
}
