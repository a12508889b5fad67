// tiershade io: the plain-text lights file (see lights_file.h).
#include "io/lights_file.h"

#include <cmath>
#include <cstdlib>
#include <sstream>

#include <glm/gtc/constants.hpp>

#include "io/text_lines.h"

bool read_lights(const std::string &path, std::vector<ts_light> *out, std::string *err) {
  TextLines f;
  if (!f.open(path, "lights", err)) return false;
  std::string line;
  while (f.next(&line)) {
    std::istringstream in(line);
    std::string type;
    if (!(in >> type)) continue;
    const std::string where = f.where() + ": ";
    std::vector<float> v;
    std::string tok;
    while (in >> tok) {
      char *end = nullptr;
      const float x = std::strtof(tok.c_str(), &end);
      if (end == tok.c_str() || *end) {
        *err = where + "'" + tok + "' is not a number";
        return false;
      }
      v.push_back(x);
    }
    ts_light l = {};
    size_t want = 0;
    if (type == "point") {
      want = 9;
      if (v.size() == want) {
        l.type = TS_LIGHT_POINT;
        for (int i = 0; i < 3; ++i) l.color[i] = v[i], l.pos[i] = v[3 + i], l.atten[i] = v[6 + i];
      }
    } else if (type == "spot") {
      want = 15;
      if (v.size() == want) {
        l.type = TS_LIGHT_SPOT;
        for (int i = 0; i < 3; ++i) l.color[i] = v[i], l.pos[i] = v[3 + i], l.dir[i] = v[6 + i], l.atten[i] = v[12 + i];
        l.spot_exponent = v[9];
        l.cos_inner = std::cos(v[10] * glm::pi<float>() / 180.f);
        l.cos_outer = std::cos(v[11] * glm::pi<float>() / 180.f);
      }
    } else if (type == "directional") {
      want = 6;
      if (v.size() == want) {
        l.type = TS_LIGHT_DIRECTIONAL;
        for (int i = 0; i < 3; ++i) l.color[i] = v[i], l.dir[i] = v[3 + i];
      }
    } else {
      *err = where + "unknown light type '" + type + "' (point, spot, directional)";
      return false;
    }
    if (v.size() != want) {
      *err = where + type + " wants " + std::to_string(want) + " numbers, got " + std::to_string(v.size());
      return false;
    }
    float packed[5][4];
    char msg[256];
    if (!ts_light_pack(&l, packed, msg, sizeof msg)) {
      *err = where + msg;
      return false;
    }
    out->push_back(l);
  }
  if (!f.finish(err)) return false;
  if (out->empty()) {
    *err = path + ": no lights";
    return false;
  }
  return true;
}
