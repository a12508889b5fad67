// tiershade cli: command-line parsing (see args.h).
#include "cli/args.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>

Args::Args(const std::string &cmd, int argc, char **argv, const std::vector<std::string> &flags,
           const std::vector<std::string> &opts)
    : cmd_(cmd) {
  for (int i = 0; i < argc; ++i) {
    std::string a = argv[i];
    if (a.size() > 1 && a[0] == '-' && !(a.size() > 1 && (isdigit(static_cast<unsigned char>(a[1])) || a[1] == '.'))) {
      std::string value;
      bool has_value = false;
      const size_t eq = a.find('=');
      if (eq != std::string::npos) {
        value = a.substr(eq + 1);
        a = a.substr(0, eq);
        has_value = true;
      }
      if (std::find(flags.begin(), flags.end(), a) != flags.end()) {
        if (has_value) fail("option " + a + " takes no value");
        flags_[a] = 1;
      } else if (std::find(opts.begin(), opts.end(), a) != opts.end()) {
        if (!has_value) {
          if (i + 1 >= argc) fail("option " + a + " needs a value");
          value = argv[++i];
        }
        opts_.insert({a, value});
      } else {
        fail("unknown option '" + a + "' (see tiershade " + cmd + " --help)");
      }
    } else {
      pos_.push_back(a);
    }
  }
}

std::string Args::get(const std::string &name, const std::string &def) const {
  auto it = opts_.find(name);
  if (it == opts_.end()) return def;
  if (opts_.count(name) > 1) fail("option " + name + " given more than once");
  return it->second;
}

std::vector<std::string> Args::all(const std::string &name) const {
  std::vector<std::string> v;
  auto range = opts_.equal_range(name);
  for (auto it = range.first; it != range.second; ++it) v.push_back(it->second);
  return v;
}

int Args::get_int(const std::string &name, int def, int lo, int hi) const {
  if (!has(name)) return def;
  const std::string s = get(name);
  char *end = nullptr;
  errno = 0;
  const long v = std::strtol(s.c_str(), &end, 10);
  if (s.empty() || *end || errno || v < lo || v > hi)
    fail("option " + name + " wants an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], got '" + s +
         "'");
  return static_cast<int>(v);
}

double Args::get_number(const std::string &name, double def, double lo, double hi) const {
  if (!has(name)) return def;
  const std::string s = get(name);
  char *end = nullptr;
  errno = 0;
  const double v = std::strtod(s.c_str(), &end);
  if (s.empty() || *end || errno || !std::isfinite(v) || v < lo || v > hi) {
    char range[64];
    snprintf(range, sizeof range, "[%g, %g]", lo, hi);
    fail("option " + name + " wants a number in " + range + ", got '" + s + "'");
  }
  return v;
}

namespace {
// Digits only, at most 9 of them (no overflow of int), value in [lo, hi].
bool parse_dim(const std::string &s, int lo, int hi, int *out) {
  if (s.empty() || s.size() > 9) return false;
  long v = 0;
  for (char c : s) {
    if (c < '0' || c > '9') return false;
    v = v * 10 + (c - '0');
  }
  if (v < lo || v > hi) return false;
  *out = static_cast<int>(v);
  return true;
}
}  // namespace

bool parse_wxh(const std::string &s, int lo, int hi, int *w, int *h) {
  const size_t x = s.find_first_of("xX");
  if (x == std::string::npos) return false;
  int a = 0, b = 0;
  if (!parse_dim(s.substr(0, x), lo, hi, &a) || !parse_dim(s.substr(x + 1), lo, hi, &b)) return false;
  *w = a;
  *h = b;
  return true;
}

bool Args::help(const char *text) const {
  if (!flag("--help")) return false;
  puts(text);
  return true;
}

void Args::no_positional() const {
  if (!pos_.empty()) fail("unexpected argument '" + pos_[0] + "'");
}

void Args::fail(const std::string &msg) const {
  fprintf(stderr, "tiershade %s: %s\n", cmd_.c_str(), msg.c_str());
  std::exit(2);
}
