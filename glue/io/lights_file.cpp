// tiershade io: the plain-text lights file (see lights_file.h).
#include "io/lights_file.h"

#include <sys/stat.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include <glm/gtc/constants.hpp>

bool read_lights(const std::string &path, std::vector<ts_light> *out, std::string *err) {
  struct stat st;
  if (stat(path.c_str(), &st) != 0 || !S_ISREG(st.st_mode)) {
    *err = "cannot read lights file '" + path + "' (not a readable regular file)";
    return false;
  }
  std::ifstream f(path);
  if (!f) {
    *err = "cannot read lights file '" + path + "'";
    return false;
  }
  std::string line;
  int lineno = 0;
  while (std::getline(f, line)) {
    ++lineno;
    const size_t hash = line.find('#');
    if (hash != std::string::npos) line.resize(hash);
    std::istringstream in(line);
    std::string type;
    if (!(in >> type)) continue;
    const std::string where = path + ":" + std::to_string(lineno) + ": ";
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
  if (f.bad()) {
    *err = "cannot read lights file '" + path + "' (read error after line " + std::to_string(lineno) + ")";
    return false;
  }
  if (out->empty()) {
    *err = path + ": no lights";
    return false;
  }
  return true;
}
