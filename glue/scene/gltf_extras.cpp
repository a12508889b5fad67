// tiershade scene: KHR_lights_punctual lights to ts_light (checked by ts_light_pack), and the
// scene settings of the root `extras.tiershade` object: camera, probes, ambient samples,
// HDR and lightmaps (docs/scenes.md). Unknown keys, wrong types and ranges are errors.
#include <cmath>
#include <cstring>

#include <glm/gtc/constants.hpp>

#include "base/image.h"
#include "io/exr.h"
#include "io/radiance_hdr.h"
#include "scene/gltf_util.h"

namespace scene_gltf {

bool convert_light(const tinygltf::Model &m, int li, const glm::dmat4 &world, const std::string &node_place, Scene *s,
                   Err &e) {
  const tinygltf::Light &L = m.lights[li];
  const std::string place = named("extensions.KHR_lights_punctual.lights[" + std::to_string(li) + "]", L.name);
  ts_light l;
  memset(&l, 0, sizeof l);
  if (L.type == "point")
    l.type = TS_LIGHT_POINT;
  else if (L.type == "spot")
    l.type = TS_LIGHT_SPOT;
  else if (L.type == "directional")
    l.type = TS_LIGHT_DIRECTIONAL;
  else
    return e.fail(place + ".type", quoted(L.type) + " is not point, spot or directional");
  double color[3] = {1, 1, 1};
  if (!L.color.empty()) {
    if (L.color.size() != 3) return e.fail(place + ".color", "expected 3 numbers");
    for (int k = 0; k < 3; ++k) color[k] = L.color[k];
  }
  for (double c : color)
    if (!(c >= 0 && std::isfinite(c))) return e.fail(place + ".color", "values must be finite and >= 0");
  if (!(L.intensity >= 0 && std::isfinite(L.intensity))) return e.fail(place + ".intensity", "must be finite and >= 0");
  for (int k = 0; k < 3; ++k) l.color[k] = static_cast<float>(color[k] * L.intensity);
  const glm::dvec3 dir = -glm::dvec3(world[2]);  // the node's -Z, and its origin
  const double dl = glm::length(dir);
  for (int r = 0; r < 3; ++r) {
    l.pos[r] = static_cast<float>(world[3][r]);
    l.dir[r] = static_cast<float>(dl > 0 ? dir[r] / dl : 0);
  }
  double atten[3] = {0, 0, 1}, exponent = 1;
  if (L.extras.IsObject() && L.extras.Has("source")) {
    const std::string sp = place + ".extras.source";
    const tinygltf::Value &src = L.extras.Get("source");
    if (!check_keys(src, sp, {"exponent", "constant", "linear", "quadratic"}, e)) return false;
    const char *names[3] = {"constant", "linear", "quadratic"};
    for (int k = 0; k < 3; ++k)
      if (src.Has(names[k])) {
        if (l.type == TS_LIGHT_DIRECTIONAL)
          return e.fail(sp + "." + names[k], "directional lights have no distance attenuation");
        if (!read_number(src.Get(names[k]), sp + "." + names[k], 0, 1e6, &atten[k], e)) return false;
      }
    if (src.Has("exponent")) {
      if (l.type != TS_LIGHT_SPOT) return e.fail(sp + ".exponent", "only spot lights have an exponent");
      if (!read_number(src.Get("exponent"), sp + ".exponent", 0, 1000, &exponent, e)) return false;
    }
  }
  double spread_degrees = 0;  // extras.tiershade.spread_degrees: a sun's angular radius (docs/scenes.md)
  if (L.extras.IsObject() && L.extras.Has("tiershade")) {
    const std::string tp = place + ".extras.tiershade";
    const tinygltf::Value &t = L.extras.Get("tiershade");
    if (!check_keys(t, tp, {"spread_degrees"}, e)) return false;
    if (t.Has("spread_degrees")) {
      if (l.type != TS_LIGHT_DIRECTIONAL) return e.fail(tp + ".spread_degrees", "only directional lights have a spread");
      if (!read_number(t.Get("spread_degrees"), tp + ".spread_degrees", 0, 45, &spread_degrees, e)) return false;
    }
  }
  if (l.type == TS_LIGHT_DIRECTIONAL) atten[0] = 1, atten[1] = 0, atten[2] = 0;
  for (int k = 0; k < 3; ++k) l.atten[k] = static_cast<float>(atten[k]);
  if (l.type == TS_LIGHT_SPOT) {
    const double in = L.spot.innerConeAngle, out = L.spot.outerConeAngle;
    if (!(in >= 0 && in < out && static_cast<float>(out) <= glm::half_pi<float>()))  // pi/2 as a float writer stores it
      return e.fail(place + ".spot", "needs 0 <= innerConeAngle < outerConeAngle <= pi/2");
    l.cos_inner = static_cast<float>(std::cos(in));
    l.cos_outer = static_cast<float>(std::cos(out));
    l.spot_exponent = static_cast<float>(exponent);
  }
  float packed[5][4];
  char msg[256] = {0};
  if (!ts_light_pack(&l, packed, msg, sizeof msg)) return e.fail(node_place + " light " + place, msg);
  SceneLight sl;
  sl.name = L.name.empty() ? "lights[" + std::to_string(li) + "]" : L.name;
  sl.light = l;
  sl.spread = spread_degrees * glm::pi<double>() / 180;
  s->lights.push_back(sl);
  return true;
}

namespace {

bool read_probes(const tinygltf::Value &v, const std::string &place, const std::string &dir, Scene *s, Err &e) {
  if (!v.IsArray()) return e.fail(place, "expected an array, got " + value_kind(v));
  if (v.ArrayLen() > 64) return e.fail(place, "more than 64 probes");
  for (size_t i = 0; i < v.ArrayLen(); ++i) {
    const std::string pp = place + "[" + std::to_string(i) + "]";
    const tinygltf::Value &o = v.Get(static_cast<int>(i));
    if (!check_keys(o, pp, {"name", "position", "image", "scale", "size", "source"}, e)) return false;
    SceneProbe p;
    p.name = "probes[" + std::to_string(i) + "]";
    if (o.Has("name") && !read_string(o.Get("name"), pp + ".name", &p.name, e)) return false;
    if (!o.Has("position")) return e.fail(pp, "missing \"position\"");
    if (!read_vec(o.Get("position"), pp + ".position", 3, -1e6, 1e6, p.position, e)) return false;
    double d;
    if (o.Has("scale")) {
      if (!read_number(o.Get("scale"), pp + ".scale", 0, 1e6, &d, e)) return false;
      p.scale = static_cast<float>(d);
    }
    if (o.Has("size") && !read_int(o.Get("size"), pp + ".size", 4, 512, &p.size, e)) return false;
    if (o.Has("source")) {  // a world probe's cube: rendered in-engine or ray traced (docs/scenes.md)
      std::string src;
      if (!read_string(o.Get("source"), pp + ".source", &src, e)) return false;
      if (src != "render" && src != "rays") return e.fail(pp + ".source", "expected \"render\" or \"rays\", got \"" + src + "\"");
      if (o.Has("image")) return e.fail(pp + ".source", "a probe with an image has no world source");
      p.traced = src == "rays";
    }
    if (o.Has("image")) {
      std::string rel, msg;
      if (!read_string(o.Get("image"), pp + ".image", &rel, e)) return false;
      const std::string path = join_path(dir, rel);
      if (!file_exists(path)) return e.fail(pp + ".image", "file not found: " + path);
      ImageF img;
      const bool exr = ends_with(path, ".exr"), hdr = ends_with(path, ".hdr");
      if (!exr && !hdr) return e.fail(pp + ".image", path + ": expected a .hdr or .exr file");
      if (!(exr ? read_exr(path, &img, &msg) : read_hdr(path, &img, &msg))) return e.fail(pp + ".image", msg);
      SceneImage si;
      si.path = path;
      si.w = img.w;
      si.h = img.h;
      si.rgba = std::move(img.rgba);
      p.image = static_cast<int>(s->images.size());
      s->images.push_back(std::move(si));
    }
    s->probes.push_back(p);
  }
  return true;
}

bool read_ambient(const tinygltf::Value &v, const std::string &place, Scene *s, Err &e) {
  if (!v.IsArray()) return e.fail(place, "expected an array, got " + value_kind(v));
  if (v.ArrayLen() > 4096) return e.fail(place, "more than 4096 samples");
  for (size_t i = 0; i < v.ArrayLen(); ++i) {
    const std::string ap = place + "[" + std::to_string(i) + "]";
    const tinygltf::Value &o = v.Get(static_cast<int>(i));
    if (!check_keys(o, ap, {"position", "cube", "from_probe"}, e)) return false;
    SceneAmbientSample a;
    memset(a.cube, 0, sizeof a.cube);
    if (!o.Has("position")) return e.fail(ap, "missing \"position\"");
    if (!read_vec(o.Get("position"), ap + ".position", 3, -1e6, 1e6, a.position, e)) return false;
    if (o.Has("cube") == o.Has("from_probe")) return e.fail(ap, "needs exactly one of \"cube\" and \"from_probe\"");
    if (o.Has("cube")) {
      const tinygltf::Value &c = o.Get("cube");
      if (!c.IsArray() || c.ArrayLen() != 6) return e.fail(ap + ".cube", "expected 6 [r,g,b] (+X -X +Y -Y +Z -Z)");
      for (int f = 0; f < 6; ++f) {
        double rgb[3];
        if (!read_vec(c.Get(f), ap + ".cube[" + std::to_string(f) + "]", 3, 0, 1e6, rgb, e)) return false;
        for (int k = 0; k < 3; ++k) a.cube[f][k] = static_cast<float>(rgb[k]);
      }
    } else {
      const int n = static_cast<int>(s->probes.size());
      if (n == 0) return e.fail(ap + ".from_probe", "the scene has no probes");
      if (!read_int(o.Get("from_probe"), ap + ".from_probe", 0, n - 1, &a.from_probe, e)) return false;
    }
    s->ambient.push_back(a);
  }
  return true;
}

bool read_hdr_settings(const tinygltf::Value &v, const std::string &place, const std::string &dir, SceneHdr *h,
                       Err &e) {
  if (!check_keys(v, place,
                  {"path", "tone_map_scale", "auto_exposure", "exposure_min", "exposure_max", "bloom", "luts", "msaa"}, e))
    return false;
  if (v.Has("path")) {
    if (!read_string(v.Get("path"), place + ".path", &h->path, e)) return false;
    if (h->path != "integer" && h->path != "float")
      return e.fail(place + ".path", quoted(h->path) + " is not \"integer\" or \"float\"");
  }
  const struct {
    const char *key;
    double lo, hi;
    float *out;
  } nums[] = {{"tone_map_scale", 1e-6, 1e4, &h->tone_map_scale},
              {"exposure_min", 1e-6, 1e4, &h->exposure_min},
              {"exposure_max", 1e-6, 1e4, &h->exposure_max},
              {"bloom", 0, 16, &h->bloom_amount}};
  for (const auto &n : nums)
    if (v.Has(n.key)) {
      double d;
      if (!read_number(v.Get(n.key), place + "." + n.key, n.lo, n.hi, &d, e)) return false;
      *n.out = static_cast<float>(d);
    }
  if (v.Has("auto_exposure") && !read_bool(v.Get("auto_exposure"), place + ".auto_exposure", &h->auto_exposure, e))
    return false;
  if (h->exposure_min > h->exposure_max) return e.fail(place, "exposure_min is larger than exposure_max");
  if (h->bloom_amount > 0 && h->path != "float") return e.fail(place + ".bloom", "bloom needs \"path\": \"float\"");
  if (v.Has("msaa")) {
    double d;
    if (!read_number(v.Get("msaa"), place + ".msaa", 0, 8, &d, e)) return false;
    if (d != 0 && d != 1 && d != 2 && d != 4 && d != 8)
      return e.fail(place + ".msaa", "samples per pixel are 0 or 1 (none), 2, 4 or 8, not " + std::to_string(d));
    h->msaa = static_cast<int>(d);
    if (h->msaa > 1 && h->path == "float")
      return e.fail(place + ".msaa", "MSAA is the integer path's (the float path's RGBA16F target has none: the talk's "
                                     "float path \"requires floating-point alpha blending\" and lacks MSAA)");
  }
  if (v.Has("luts")) {
    const tinygltf::Value &a = v.Get("luts");
    if (!a.IsArray()) return e.fail(place + ".luts", "expected an array, got " + value_kind(a));
    if (a.ArrayLen() > 4) return e.fail(place + ".luts", std::to_string(a.ArrayLen()) + " LUTs, at most 4");
    for (size_t i = 0; i < a.ArrayLen(); ++i) {
      const std::string lp = place + ".luts[" + std::to_string(i) + "]";
      const tinygltf::Value &o = a.Get(static_cast<int>(i));
      if (!check_keys(o, lp, {"file", "weight"}, e)) return false;
      SceneLut lut;
      std::string rel;
      if (!o.Has("file")) return e.fail(lp, "missing \"file\"");
      if (!read_string(o.Get("file"), lp + ".file", &rel, e)) return false;
      lut.path = join_path(dir, rel);
      if (!file_exists(lut.path)) return e.fail(lp + ".file", "file not found: " + lut.path);
      double w;
      if (o.Has("weight")) {
        if (!read_number(o.Get("weight"), lp + ".weight", 0, 1, &w, e)) return false;
        lut.weight = static_cast<float>(w);
      }
      h->luts.push_back(lut);
    }
  }
  return true;
}

bool read_lightmaps(const tinygltf::Value &v, const std::string &place, const std::string &dir, SceneLightmaps *l,
                    Err &e) {
  if (!check_keys(v, place,
                  {"luxels_per_unit", "encoding", "page", "image", "quality", "bounces", "gather_rays", "supersample",
                   "area_samples", "spread_samples", "threshold", "seed", "bake"},
                  e))
    return false;
  // The quality (glue/bake/bake_quality.h): a preset and the keys that override it, within the
  // ranges `tiershade bake`'s options take (glue/cli/cmd_bake.cpp).
  if (v.Has("quality")) {
    BakeQuality q;
    if (!read_string(v.Get("quality"), place + ".quality", &l->quality_preset, e)) return false;
    if (!bake_quality_preset(l->quality_preset, &q))
      return e.fail(place + ".quality", quoted(l->quality_preset) + " is not a preset (" +
                                            bake_quality_preset_names() + ")");
  }
  BakeQualityKeys &k = l->keys;
  if (v.Has("bounces") && !read_int(v.Get("bounces"), place + ".bounces", 0, 100, &k.bounces, e)) return false;
  if (v.Has("seed") && !read_int(v.Get("seed"), place + ".seed", 0, 1 << 30, &l->seed, e)) return false;
  if (v.Has("supersample") && !read_int(v.Get("supersample"), place + ".supersample", 1, 8, &k.supersample, e))
    return false;
  if (v.Has("gather_rays") && !read_int(v.Get("gather_rays"), place + ".gather_rays", 1, 1024, &k.gather_rays, e))
    return false;
  if (v.Has("area_samples") && !read_int(v.Get("area_samples"), place + ".area_samples", 0, 1024, &k.area_samples, e))
    return false;
  if (v.Has("spread_samples") &&
      !read_int(v.Get("spread_samples"), place + ".spread_samples", 1, 1024, &k.spread_samples, e))
    return false;
  if (v.Has("threshold") && !read_number(v.Get("threshold"), place + ".threshold", 0, 1, &k.threshold, e)) return false;
  if (v.Has("luxels_per_unit") &&
      !read_number(v.Get("luxels_per_unit"), place + ".luxels_per_unit", 0.01, 1024, &k.luxels_per_unit, e))
    return false;
  if (v.Has("encoding")) {
    if (!read_string(v.Get("encoding"), place + ".encoding", &l->encoding, e)) return false;
    if (l->encoding != "float" && l->encoding != "412" && l->encoding != "ldr" && l->encoding != "rgbe" &&
        l->encoding != "float32" && l->encoding != "rgbe_shader")
      return e.fail(place + ".encoding", quoted(l->encoding) +
                                             " is not \"float\", \"412\", \"ldr\", \"rgbe\", \"rgbe_shader\" or \"float32\"");
  }
  if (v.Has("page")) {
    const tinygltf::Value &p = v.Get("page");
    if (!p.IsArray() || p.ArrayLen() != 2) return e.fail(place + ".page", "expected [width, height]");
    if (!read_int(p.Get(0), place + ".page[0]", 16, 8192, &l->page_w, e) ||
        !read_int(p.Get(1), place + ".page[1]", 16, 8192, &l->page_h, e))
      return false;
  }
  if (v.Has("image")) {
    // A baked page (docs/scenes.md, "Lightmap pages"): its size is the page size.
    const std::string ip = place + ".image";
    std::string rel;
    if (!read_string(v.Get("image"), ip, &rel, e)) return false;
    const std::string path = join_path(dir, rel);
    if (!file_exists(path)) return e.fail(ip, "file not found: " + path);
    const bool exr = ends_with(path, ".exr"), hdr = ends_with(path, ".hdr");
    if (!exr && !hdr) return e.fail(ip, path + ": expected a .exr or .hdr file");
    ImageF img;
    std::string msg;
    if (!(exr ? read_exr(path, &img, &msg) : read_hdr(path, &img, &msg))) return e.fail(ip, msg);
    if (v.Has("page") && (img.w != l->page_w || img.h != l->page_h))
      return e.fail(ip,
                    path + ": " + std::to_string(img.w) + " x " + std::to_string(img.h) + " texels, but \"page\" is " +
                        std::to_string(l->page_w) + " x " + std::to_string(l->page_h));
    if (img.w < 16 || img.h < 16 || img.w > 8192 || img.h > 8192)
      return e.fail(
          ip,
          path + ": " + std::to_string(img.w) + " x " + std::to_string(img.h) + " texels, a page is 16..8192 each way");
    for (int y = 0; y < img.h; ++y)
      for (int x = 0; x < img.w; ++x)
        for (int c = 0; c < 3; ++c) {
          const float t = img.rgba[(static_cast<size_t>(y) * img.w + x) * 4 + c];
          if (!std::isfinite(t) || t < 0)
            return e.fail(
                ip,
                path + ": texel (" + std::to_string(x) + ", " + std::to_string(y) + ") channel " + "RGB"[c] + " is " +
                    (std::isfinite(t) ? std::to_string(t) : (std::isnan(t) ? std::string("NaN") : std::string("Inf"))) +
                    ": lightmap radiance must be finite and >= 0");
        }
    for (size_t i = 3; i < img.rgba.size(); i += 4) img.rgba[i] = 1.f;
    l->page_w = img.w;
    l->page_h = img.h;
    l->image = path;
    l->image_rgba = std::move(img.rgba);
  }
  if (v.Has("bake")) {  // a bake directory (docs/baking.md): checked against the scene when prepared
    std::string rel;
    if (!read_string(v.Get("bake"), place + ".bake", &rel, e)) return false;
    if (v.Has("image")) return e.fail(place + ".bake", "give \"bake\" or \"image\", not both");
    l->bake = join_path(dir, rel);
  }
  return true;
}

// extras.tiershade.sky (docs/scenes.md, "Sky"): {"image", "scale", "samples", "sun": {"direction",
// "color", "intensity", "spread_degrees"}}; the sun becomes one more directional light.
bool read_sky(const tinygltf::Value &v, const std::string &place, const std::string &dir, Scene *s, Err &e) {
  if (!check_keys(v, place, {"image", "scale", "samples", "sun"}, e)) return false;
  if (!v.Has("image")) return e.fail(place, "missing \"image\"");
  std::string rel, msg;
  if (!read_string(v.Get("image"), place + ".image", &rel, e)) return false;
  const std::string path = join_path(dir, rel);
  if (!file_exists(path)) return e.fail(place + ".image", "file not found: " + path);
  const bool exr = ends_with(path, ".exr"), hdr = ends_with(path, ".hdr");
  if (!exr && !hdr) return e.fail(place + ".image", path + ": expected a .hdr or .exr file");
  ImageF img;
  if (!(exr ? read_exr(path, &img, &msg) : read_hdr(path, &img, &msg))) return e.fail(place + ".image", msg);
  for (size_t i = 0; i < img.rgba.size(); ++i)
    if (i % 4 != 3 && !(std::isfinite(img.rgba[i]) && img.rgba[i] >= 0))
      return e.fail(place + ".image", path + ": texel " + std::to_string(i / 4) + ": radiance must be finite and >= 0");
  double d = 1;
  if (v.Has("scale")) {
    if (!read_number(v.Get("scale"), place + ".scale", 0, 1e6, &d, e)) return false;
    s->sky.scale = static_cast<float>(d);
  }
  if (v.Has("samples") &&
      !read_int(v.Get("samples"), place + ".samples", 1, 4096, &s->lightmaps.keys.sky_samples, e))
    return false;
  if (v.Has("sun")) {
    const std::string sp = place + ".sun";
    const tinygltf::Value &o = v.Get("sun");
    if (!check_keys(o, sp, {"direction", "color", "intensity", "spread_degrees"}, e)) return false;
    if (!o.Has("direction")) return e.fail(sp, "missing \"direction\"");
    double to_sun[3], color[3] = {1, 1, 1}, intensity = 1, spread = 0;
    if (!read_vec(o.Get("direction"), sp + ".direction", 3, -1e6, 1e6, to_sun, e)) return false;
    const double len = std::sqrt(to_sun[0] * to_sun[0] + to_sun[1] * to_sun[1] + to_sun[2] * to_sun[2]);
    if (!(len > 0)) return e.fail(sp + ".direction", "must not be zero");
    if ((o.Has("color") && !read_vec(o.Get("color"), sp + ".color", 3, 0, 1e6, color, e)) ||
        (o.Has("intensity") && !read_number(o.Get("intensity"), sp + ".intensity", 0, 1e9, &intensity, e)) ||
        (o.Has("spread_degrees") && !read_number(o.Get("spread_degrees"), sp + ".spread_degrees", 0, 45, &spread, e)))
      return false;
    SceneLight sun;
    sun.name = "extras.tiershade.sky.sun";
    memset(&sun.light, 0, sizeof sun.light);
    sun.light.type = TS_LIGHT_DIRECTIONAL;
    for (int k = 0; k < 3; ++k) {
      sun.light.dir[k] = static_cast<float>(-to_sun[k] / len);  // the direction the light travels
      sun.light.color[k] = static_cast<float>(color[k] * intensity);
    }
    sun.light.atten[0] = 1;
    float packed[5][4];
    char m[256] = {0};
    if (!ts_light_pack(&sun.light, packed, m, sizeof m)) return e.fail(sp, m);
    sun.spread = spread * glm::pi<double>() / 180;
    s->lights.push_back(sun);
  }
  SceneImage si;
  si.path = path;
  si.w = img.w;
  si.h = img.h;
  si.rgba = std::move(img.rgba);
  s->sky.image = static_cast<int>(s->images.size());
  s->images.push_back(std::move(si));
  return true;
}

bool read_fog(const tinygltf::Value &v, const std::string &place, SceneFog *f, Err &e) {
  if (!check_keys(v, place, {"color", "start", "end", "max_density"}, e)) return false;
  for (const char *k : {"color", "start", "end"})
    if (!v.Has(k)) return e.fail(place, std::string("missing \"") + k + "\"");
  double c[3], d = 1;
  if (!read_vec(v.Get("color"), place + ".color", 3, 0, 1e6, c, e) ||
      !read_number(v.Get("start"), place + ".start", 0, 1e6, &f->start, e) ||
      !read_number(v.Get("end"), place + ".end", 0, 1e6, &f->end, e) ||
      (v.Has("max_density") && !read_number(v.Get("max_density"), place + ".max_density", 0, 1, &d, e)))
    return false;
  if (!(f->end > f->start))
    return e.fail(place + ".end", "the fog ends (" + std::to_string(f->end) + ") before it starts (" +
                                      std::to_string(f->start) + ")");
  for (int k = 0; k < 3; ++k) f->color[k] = static_cast<float>(c[k]);
  f->max_density = static_cast<float>(d);
  f->enabled = true;
  return true;
}

bool read_volume(const tinygltf::Value &v, const std::string &place, SceneVolume *vol, Err &e) {
  if (!check_keys(v, place, {"spacing", "fit", "lookup", "bounds", "enabled"}, e)) return false;
  if (v.Has("spacing") && !read_vec(v.Get("spacing"), place + ".spacing", 3, 0.01, 1e4, vol->spacing, e)) return false;
  if (v.Has("fit")) {
    if (!read_string(v.Get("fit"), place + ".fit", &vol->fit, e)) return false;
    if (vol->fit != "lsq" && vol->fit != "mean") return e.fail(place + ".fit", quoted(vol->fit) + " is not \"lsq\" or \"mean\"");
  }
  if (v.Has("lookup")) {
    if (!read_string(v.Get("lookup"), place + ".lookup", &vol->lookup, e)) return false;
    if (vol->lookup != "trilinear" && vol->lookup != "inverse_square")
      return e.fail(place + ".lookup", quoted(vol->lookup) + " is not \"trilinear\" or \"inverse_square\"");
  }
  if (v.Has("enabled")) {
    const tinygltf::Value &b = v.Get("enabled");
    if (!b.IsBool()) return e.fail(place + ".enabled", "expected true or false, got " + value_kind(b));
    vol->enabled = b.Get<bool>();
  }
  if (v.Has("bounds")) {
    const tinygltf::Value &b = v.Get("bounds");
    if (!b.IsArray() || b.ArrayLen() != 2) return e.fail(place + ".bounds", "expected [[x,y,z], [x,y,z]]");
    if (!read_vec(b.Get(0), place + ".bounds[0]", 3, -1e6, 1e6, vol->lo, e) ||
        !read_vec(b.Get(1), place + ".bounds[1]", 3, -1e6, 1e6, vol->hi, e))
      return false;
    for (int k = 0; k < 3; ++k)
      if (!(vol->hi[k] >= vol->lo[k])) return e.fail(place + ".bounds", "the high corner is below the low one on an axis");
    vol->has_bounds = true;
  }
  return true;
}

}  // namespace

bool convert_tiershade_extras(const tinygltf::Model &m, const std::string &dir, Scene *s, Err &e) {
  const std::string place = "extras.tiershade";
  if (m.extras.IsObject() && m.extras.Has("tiershade")) {
    const tinygltf::Value &t = m.extras.Get("tiershade");
    if (!check_keys(t, place, {"camera", "probes", "ambient", "hdr", "lightmaps", "fog", "sky", "volume"}, e)) return false;
    if (t.Has("camera") &&
        !read_int(t.Get("camera"), place + ".camera", 0, static_cast<int>(s->cameras.size()) - 1, &s->camera, e))
      return false;
    if (t.Has("probes") && !read_probes(t.Get("probes"), place + ".probes", dir, s, e)) return false;
    if (t.Has("ambient") && !read_ambient(t.Get("ambient"), place + ".ambient", s, e)) return false;
    if (t.Has("hdr") && !read_hdr_settings(t.Get("hdr"), place + ".hdr", dir, &s->hdr, e)) return false;
    if (t.Has("lightmaps") && !read_lightmaps(t.Get("lightmaps"), place + ".lightmaps", dir, &s->lightmaps, e))
      return false;
    if (t.Has("fog") && !read_fog(t.Get("fog"), place + ".fog", &s->fog, e)) return false;
    if (t.Has("sky") && !read_sky(t.Get("sky"), place + ".sky", dir, s, e)) return false;
    if (t.Has("volume") && !read_volume(t.Get("volume"), place + ".volume", &s->volume, e)) return false;
  }
  // The quality at load: the scene's preset (else draft) with its own keys (glue/bake/bake_quality.h).
  BakeQuality q;
  bake_quality_preset(s->lightmaps.quality_preset.empty() ? "draft" : s->lightmaps.quality_preset, &q);
  s->lightmaps.quality = bake_quality_with(q, s->lightmaps.keys);
  for (const SceneMaterial &mat : s->materials)
    if (mat.probe >= static_cast<int>(s->probes.size()))
      return e.fail(mat.where + ".extras.source.probe",
                    "probe " + std::to_string(mat.probe) + " does not exist (" + std::to_string(s->probes.size()) +
                        " probes in extras.tiershade.probes)");
  return true;
}

}  // namespace scene_gltf
