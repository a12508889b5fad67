// tiershade io: colour LUT files (see lut_io.h).
// .cube facts: Adobe "Cube LUT Specification 1.0" (keywords TITLE, LUT_1D_SIZE 2..65536,
// LUT_3D_SIZE 2..256, DOMAIN_MIN/MAX defaulting to 0 and 1, keywords before the table, '#'
// comments, red fastest) and the DaVinci Resolve variant (LUT_1D_INPUT_RANGE,
// LUT_3D_INPUT_RANGE, a 1D shaper table followed by a 3D table in one file).
#include "io/lut_files.h"

#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>

#include "io/atomic_file.h"
#include "io/memory_limit.h"

namespace {

std::string at(const std::string &path, int line) { return path + ":" + std::to_string(line) + ": "; }

std::vector<std::string> tokens(const std::string &s) {
  std::vector<std::string> v;
  std::istringstream in(s);
  std::string t;
  while (in >> t) v.push_back(t);
  return v;
}

// A whole token as a finite float.
bool parse_finite(const std::string &tok, float *out) {
  char *end = nullptr;
  errno = 0;
  const float f = std::strtof(tok.c_str(), &end);
  if (end == tok.c_str() || *end || !std::isfinite(f)) return false;
  *out = f;
  return true;
}

bool parse_size(const std::string &tok, long lo, long hi, long *out) {
  char *end = nullptr;
  errno = 0;
  const long v = std::strtol(tok.c_str(), &end, 10);
  if (tok.empty() || *end || errno || v < lo || v > hi) return false;
  *out = v;
  return true;
}

// The whole of a regular file of at most max_bytes (a FIFO or /dev/zero would block or never end).
bool read_all(const std::string &path, long long max_bytes, std::string *bytes, std::string *err) {
  std::string why;
  if (!regular_file_within(path, max_bytes, nullptr, &why)) {
    if (why.rfind("cannot open: ", 0) == 0) why = "cannot open (" + why.substr(13) + ")";
    *err = path + ": " + why;
    return false;
  }
  std::ifstream f(path, std::ios::binary);
  if (!f) {
    *err = path + ": cannot open (" + std::string(std::strerror(errno)) + ")";
    return false;
  }
  std::ostringstream ss;
  ss << f.rdbuf();
  if (f.bad()) {
    *err = path + ": read error";
    return false;
  }
  *bytes = ss.str();
  if (static_cast<long long>(bytes->size()) > max_bytes) {  // the file grew while it was read
    *err = path + ": more than " + std::to_string(max_bytes) + " bytes";
    return false;
  }
  return true;
}

bool ends_with(const std::string &s, const std::string &suffix) {
  if (s.size() < suffix.size()) return false;
  for (size_t i = 0; i < suffix.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(s[s.size() - suffix.size() + i])) != suffix[i]) return false;
  return true;
}

}  // namespace

bool read_cube(const std::string &path, CubeFile *out, std::string *err) {
  std::string bytes;
  if (!read_all(path, kMaxCubeBytes, &bytes, err)) return false;
  *out = CubeFile();
  CubeFile &c = *out;
  bool seen_title = false, seen_dmin = false, seen_dmax = false, seen_r1 = false, seen_r3 = false;
  int data_lines = 0, first_data_line = 0;
  long expected = -1;
  std::vector<float> data;
  std::istringstream in(bytes);
  std::string line;
  int lineno = 0;
  while (std::getline(in, line)) {
    ++lineno;
    if (!line.empty() && line.back() == '\r') line.pop_back();  // CRLF files
    if (line.find('\0') != std::string::npos) {
      *err = at(path, lineno) + "binary data (a NUL byte) in a text file";
      return false;
    }
    if (line.size() > 250) {  // the Adobe spec's line limit
      *err = at(path, lineno) + "line longer than 250 characters";
      return false;
    }
    const size_t first = line.find_first_not_of(" \t");
    if (first == std::string::npos || line[first] == '#') continue;
    const std::vector<std::string> t = tokens(line);
    if (t.empty()) continue;  // other white space alone (a vertical tab, a form feed): a blank line
    const std::string &key = t[0];
    std::string lower = key;
    for (char &ch : lower) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    const bool is_number = key[0] == '-' || key[0] == '+' || key[0] == '.' ||
        std::isdigit(static_cast<unsigned char>(key[0])) || lower.rfind("nan", 0) == 0 || lower.rfind("inf", 0) == 0;
    if (is_number) {
      if (!data_lines) {
        if (!c.size_1d && !c.size_3d) {
          *err = at(path, lineno) + "table data before LUT_1D_SIZE or LUT_3D_SIZE";
          return false;
        }
        expected = static_cast<long>(c.size_1d) + static_cast<long>(c.size_3d) * c.size_3d * c.size_3d;
        first_data_line = lineno;
      }
      if (t.size() != 3) {
        *err = at(path, lineno) + "a table line holds 3 numbers (R G B), this one has " + std::to_string(t.size());
        return false;
      }
      if (data_lines >= expected) {
        *err = at(path, lineno) + "more table lines than the " + std::to_string(expected) + " the sizes declare";
        return false;
      }
      for (int k = 0; k < 3; ++k) {
        float v;
        if (!parse_finite(t[k], &v)) {
          *err = at(path, lineno) + "'" + t[k] + "' is not a finite number";
          return false;
        }
        data.push_back(v);
      }
      ++data_lines;
      continue;
    }
    if (data_lines) {
      *err = at(path, lineno) + "keyword " + key + " after the table data (line " + std::to_string(first_data_line) +
          "); keywords come first";
      return false;
    }
    auto once = [&](bool *seen) {
      if (*seen) {
        *err = at(path, lineno) + key + " given twice";
        return false;
      }
      *seen = true;
      return true;
    };
    if (key == "TITLE") {
      if (!once(&seen_title)) return false;
      const size_t q0 = line.find('"'), q1 = line.rfind('"');
      if (q0 == std::string::npos || q1 == q0 || line.find_first_not_of(" \t", q1 + 1) != std::string::npos ||
          line.find_first_not_of(" \t", first + 5) != q0) {
        *err = at(path, lineno) + "TITLE wants a text in double quotes";
        return false;
      }
      c.title = line.substr(q0 + 1, q1 - q0 - 1);
    } else if (key == "LUT_1D_SIZE" || key == "LUT_3D_SIZE") {
      const bool is3 = key == "LUT_3D_SIZE";
      int &size = is3 ? c.size_3d : c.size_1d;
      if (size) {
        *err = at(path, lineno) + key + " given twice";
        return false;
      }
      long v;
      if (t.size() != 2 || !parse_size(t[1], 2, is3 ? 256 : 65536, &v)) {
        *err = at(path, lineno) + key + " wants one integer in [2, " + (is3 ? "256" : "65536") + "]";
        return false;
      }
      // The table is held three times (parsed, CubeFile, Lut3D), 12 bytes an entry.
      std::string why;
      if (is3 && !memory_fits(36.0 * v * v * v, "LUT_3D_SIZE " + std::to_string(v), &why)) {
        *err = at(path, lineno) + why;
        return false;
      }
      size = static_cast<int>(v);
    } else if (key == "DOMAIN_MIN" || key == "DOMAIN_MAX") {
      const bool is_min = key == "DOMAIN_MIN";
      if (!once(is_min ? &seen_dmin : &seen_dmax)) return false;
      float *d = is_min ? c.domain_min : c.domain_max;
      if (t.size() != 4 || !parse_finite(t[1], &d[0]) || !parse_finite(t[2], &d[1]) || !parse_finite(t[3], &d[2])) {
        *err = at(path, lineno) + key + " wants 3 finite numbers (R G B)";
        return false;
      }
    } else if (key == "LUT_1D_INPUT_RANGE" || key == "LUT_3D_INPUT_RANGE") {
      if (!once(key == "LUT_1D_INPUT_RANGE" ? &seen_r1 : &seen_r3)) return false;
      float lo, hi;
      if (t.size() != 3 || !parse_finite(t[1], &lo) || !parse_finite(t[2], &hi)) {
        *err = at(path, lineno) + key + " wants 2 finite numbers (min max)";
        return false;
      }
      for (int k = 0; k < 3; ++k) {
        c.domain_min[k] = lo;
        c.domain_max[k] = hi;
      }
    } else {
      *err = at(path, lineno) + "unknown keyword '" + key + "'";
      return false;
    }
    if ((seen_dmin || seen_dmax) && (seen_r1 || seen_r3)) {
      *err = at(path, lineno) + "DOMAIN_MIN/MAX (Adobe) and LUT_*_INPUT_RANGE (Resolve) cannot be mixed";
      return false;
    }
    if (seen_r1 && seen_r3) {
      *err = at(path, lineno) + "different input ranges for the 1D and 3D tables are not supported";
      return false;
    }
  }
  if (in.bad()) {
    *err = path + ": read error";
    return false;
  }
  if (!c.size_1d && !c.size_3d) {
    *err = path + ": no LUT_1D_SIZE or LUT_3D_SIZE";
    return false;
  }
  if (c.size_1d && c.size_3d && (seen_dmin || seen_dmax)) {
    *err = path + ": a 1D and a 3D table in one file (Resolve form) take LUT_*_INPUT_RANGE, not DOMAIN_MIN/MAX";
    return false;
  }
  for (int k = 0; k < 3; ++k) {
    if (!(c.domain_min[k] < c.domain_max[k])) {
      *err = path + ": the domain is empty on channel " + "RGB"[k] + " (min " + std::to_string(c.domain_min[k]) +
          " >= max " + std::to_string(c.domain_max[k]) + ")";
      return false;
    }
  }
  if (expected < 0) expected = static_cast<long>(c.size_1d) + static_cast<long>(c.size_3d) * c.size_3d * c.size_3d;
  if (data_lines != expected) {
    *err = path + ": the table ends after " + std::to_string(data_lines) + " of " + std::to_string(expected) + " lines";
    return false;
  }
  c.table_1d.assign(data.begin(), data.begin() + 3 * static_cast<long>(c.size_1d));
  c.table_3d.assign(data.begin() + 3 * static_cast<long>(c.size_1d), data.end());
  return true;
}

bool cube_as_lut3d(const std::string &path, const CubeFile &cube, Lut3D *out, std::string *err) {
  if (!cube.size_3d) {
    *err = path + ": a 1D LUT, not a 3D one; bake it into a 3D LUT (tiershade lut bake --file)";
    return false;
  }
  if (cube.size_1d) {
    *err = path + ": a 1D shaper before the 3D table; bake it into one 3D LUT (tiershade lut bake --file)";
    return false;
  }
  for (int k = 0; k < 3; ++k) {
    if (cube.domain_min[k] != 0.f || cube.domain_max[k] != 1.f) {
      *err = path + ": the domain is not [0, 1]; bake it on the unit cube (tiershade lut bake --file)";
      return false;
    }
  }
  out->n = cube.size_3d;
  out->rgb = cube.table_3d;
  out->title = cube.title.empty() ? path : cube.title;
  return true;
}

bool write_cube(const std::string &path, const Lut3D &lut, std::string *err) {
  if (lut.n < 2 || lut.n > 256 || lut.rgb.size() != static_cast<size_t>(lut.n) * lut.n * lut.n * 3) {
    *err = path + ": not written: the LUT edge must be in [2, 256] with n^3 entries";
    return false;
  }
  if (lut.title.find_first_of("\"\r\n") != std::string::npos) {
    *err = path + ": not written: the title holds a double quote or a line break";
    return false;
  }
  for (float v : lut.rgb) {
    if (!std::isfinite(v)) {
      *err = path + ": not written: the LUT holds a non-finite value";
      return false;
    }
  }
  std::string s;
  s.reserve(lut.rgb.size() * 14 + 128);
  s += "# written by tiershade (docs/color_correction.md)\n";
  if (!lut.title.empty()) s += "TITLE \"" + lut.title + "\"\n";
  s += "LUT_3D_SIZE " + std::to_string(lut.n) + "\nDOMAIN_MIN 0 0 0\nDOMAIN_MAX 1 1 1\n";
  char b[96];
  for (size_t i = 0; i < lut.rgb.size(); i += 3) {
    snprintf(b, sizeof b, "%.9g %.9g %.9g\n", lut.rgb[i], lut.rgb[i + 1], lut.rgb[i + 2]);
    s += b;
  }
  return write_file_atomic(path, s, err);
}

bool read_source_raw(const std::string &path, Lut3D *out, std::string *err) {
  std::string bytes;
  if (!read_all(path, 16 * kSourceRawBytes, &bytes, err)) return false;
  if (static_cast<long>(bytes.size()) != kSourceRawBytes) {
    *err = path + ": " + std::to_string(bytes.size()) +
        " bytes; a Source colour-correction .raw is 32 x 32 x 32 RGB8 = " + std::to_string(kSourceRawBytes) + " bytes";
    return false;
  }
  out->n = kSourceRawEdge;
  out->rgb.resize(bytes.size());
  for (size_t i = 0; i < bytes.size(); ++i)
    out->rgb[i] = static_cast<float>(static_cast<unsigned char>(bytes[i])) / 255.f;
  out->title = path;
  return true;
}

bool write_source_raw(const std::string &path, const Lut3D &lut, std::string *err) {
  if (lut.n != kSourceRawEdge || lut.rgb.size() != static_cast<size_t>(kSourceRawBytes)) {
    *err = path + ": not written: a Source .raw holds a 32^3 LUT, this one has edge " + std::to_string(lut.n) +
        " (bake it at --size 32)";
    return false;
  }
  std::string s(lut.rgb.size(), '\0');
  for (size_t i = 0; i < lut.rgb.size(); ++i) {
    const float v = lut.rgb[i];
    const float c = std::isnan(v) ? 0.f : std::fmin(std::fmax(v, 0.f), 1.f);
    s[i] = static_cast<char>(static_cast<unsigned char>(std::lround(c * 255.f)));
  }
  return write_file_atomic(path, s, err);
}

bool read_lut_file(const std::string &path, Lut3D *out, std::string *err) {
  if (ends_with(path, ".raw")) return read_source_raw(path, out, err);
  if (ends_with(path, ".cube")) {
    CubeFile c;
    return read_cube(path, &c, err) && cube_as_lut3d(path, c, out, err);
  }
  *err = path + ": unknown LUT file type (tiershade reads .cube and Source .raw)";
  return false;
}
