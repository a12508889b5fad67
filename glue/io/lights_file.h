// tiershade io: the plain-text lights file (scenes/*.lights), read by `fold` and `demo`.
#pragma once
#include <string>
#include <vector>

#include "offline/light_folding.h"

// One light per line, '#' comments; errors name the file and line:
//   point       R G B  X Y Z  C L Q
//   spot        R G B  X Y Z  DX DY DZ  EXPONENT INNER_DEG OUTER_DEG  C L Q
//   directional R G B  DX DY DZ            (the direction the light travels)
bool read_lights(const std::string &path, std::vector<ts_light> *out, std::string *err);
