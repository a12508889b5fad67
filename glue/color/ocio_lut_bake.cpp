// tiershade color: openColorIO transforms and LUT baking (see lut_bake.h).
// OCIO API facts from its headers (OpenColorIO 2.1.2): Config::CreateRaw/CreateFromFile,
// FileTransform, LookTransform, CDLTransform, Processor::getOptimizedCPUProcessor,
// CPUProcessor::applyRGB; every failure is an OCIO::Exception.
#include "color/ocio_lut_bake.h"

#include <sys/stat.h>

#include <OpenColorIO/OpenColorIO.h>

#include <climits>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <vector>

#include "io/lut_files.h"

namespace OCIO = OCIO_NAMESPACE;

struct ColorTransformImpl {
  OCIO::ConstCPUProcessorRcPtr cpu;
};

namespace {

std::string triple(const double v[3]) {
  std::ostringstream o;
  o << v[0] << "," << v[1] << "," << v[2];
  return o.str();
}

bool readable_file(const std::string &path, std::string *err) {
  struct stat st;
  if (stat(path.c_str(), &st) != 0) {
    *err = path + ": cannot open (no such file)";
    return false;
  }
  if (!S_ISREG(st.st_mode)) {
    *err = path + ": not a regular file";
    return false;
  }
  FILE *f = std::fopen(path.c_str(), "rb");
  if (!f) {
    *err = path + ": cannot open (not readable)";
    return false;
  }
  std::fclose(f);
  return true;
}

// OpenColorIO 2.1 picks its ASC CDL reader by searching the text for "<ColorCorrectionCollection"
// or "<ColorDecisionList" anywhere in it (a comment included) and then dereferences the
// collection or list a file whose root is another element does not have: SIGSEGV inside
// Config::getProcessor (both found by fuzz_ocio, tests/fuzz/regressions/ocio/). A file that
// mentions either element other than as its root is refused here, before OpenColorIO reads it.
bool cdl_collection_mention_ok(const std::string &path, std::string *err) {
  FILE *f = std::fopen(path.c_str(), "rb");
  if (!f) {
    *err = path + ": cannot open (not readable)";
    return false;
  }
  std::string text;
  char buf[65536];
  size_t n;
  const size_t kMaxScan = size_t(64) << 20;  // LUT files beyond 64 MiB: only their start is scanned
  while (text.size() < kMaxScan && (n = std::fread(buf, 1, sizeof buf, f)) > 0) text.append(buf, n);
  std::fclose(f);
  // The root element: the first "<name" after the prolog, comments and declarations.
  size_t root = 0;
  while (root < text.size()) {
    root = text.find('<', root);
    if (root == std::string::npos) break;
    if (text.compare(root, 4, "<!--") == 0) {
      const size_t e = text.find("-->", root + 4);
      root = e == std::string::npos ? e : e + 3;
    } else if (text.compare(root, 2, "<?") == 0 || text.compare(root, 2, "<!") == 0) {
      const size_t e = text.find('>', root + 2);
      root = e == std::string::npos ? e : e + 1;
    } else {
      break;
    }
  }
  for (const std::string tag : {"<ColorCorrectionCollection", "<ColorDecisionList"}) {
    const size_t mention = text.find(tag);
    if (mention == std::string::npos) continue;
    if (root != std::string::npos && root == mention) {
      const char after = mention + tag.size() < text.size() ? text[mention + tag.size()] : '\0';
      if (after == '>' || after == ' ' || after == '\t' || after == '\n' || after == '\r' || after == '/') continue;
    }
    size_t line = 1;
    for (size_t k = 0; k < mention; ++k) line += text[k] == '\n';
    *err = path + ":" + std::to_string(line) + ": mentions " + tag +
        " but that is not the file's root element (OpenColorIO 2.1 crashes on such a file; refused)";
    return false;
  }
  return true;
}

bool ends_with(const std::string &s, const char *suffix) {
  const std::string x(suffix);
  if (s.size() < x.size()) return false;
  for (size_t i = 0; i < x.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(s[s.size() - x.size() + i])) != x[i]) return false;
  return true;
}

std::string absolute(const std::string &path) {
  char buf[PATH_MAX];
  return realpath(path.c_str(), buf) ? std::string(buf) : path;
}

// "a, b" -> {"a", "b"}
std::vector<std::string> split_looks(const std::string &s) {
  std::vector<std::string> v;
  std::string cur;
  for (char c : s + ",") {
    if (c == ',') {
      const size_t b = cur.find_first_not_of(" \t"), e = cur.find_last_not_of(" \t");
      if (b != std::string::npos) v.push_back(cur.substr(b, e - b + 1));
      cur.clear();
    } else {
      cur += c;
    }
  }
  return v;
}

}  // namespace

std::string TransformSpec::describe() const {
  switch (kind) {
    case Kind::File:
      return "file " + file;
    case Kind::Look:
      return "look '" + looks + "' of " + config + (src.empty() ? "" : " from " + src) +
          (dst.empty() ? "" : " to " + dst);
    case Kind::Cdl:
      return "ASC CDL slope " + triple(slope) + " offset " + triple(offset) + " power " + triple(power) + " sat " +
          std::to_string(sat);
  }
  return "?";
}

bool ColorTransform::open(const TransformSpec &spec, std::string *err) {
  impl_.reset();
  description_ = spec.describe();
  // The file whose name goes in front of OCIO's message.
  const std::string subject = spec.kind == TransformSpec::Kind::File ? spec.file
      : spec.kind == TransformSpec::Kind::Look                       ? spec.config
                                                                     : std::string("CDL values");
  try {
    OCIO::ConstConfigRcPtr config;
    OCIO::ConstTransformRcPtr transform;
    switch (spec.kind) {
      case TransformSpec::Kind::File: {
        if (!readable_file(spec.file, err)) return false;
        if (ends_with(spec.file, ".cube")) {  // tiershade's strict reader first: file:line errors
          CubeFile cube;
          if (!read_cube(spec.file, &cube, err)) return false;
        }
        if (!cdl_collection_mention_ok(spec.file, err)) return false;
        OCIO::ClearAllCaches();  // OCIO caches files by path; a rewritten file must be re-read
        auto ft = OCIO::FileTransform::Create();
        ft->setSrc(absolute(spec.file).c_str());
        ft->setInterpolation(OCIO::INTERP_LINEAR);
        ft->setDirection(OCIO::TRANSFORM_DIR_FORWARD);
        transform = ft;
        config = OCIO::Config::CreateRaw();
        break;
      }
      case TransformSpec::Kind::Look: {
        if (!readable_file(spec.config, err)) return false;
        OCIO::ClearAllCaches();
        config = OCIO::Config::CreateFromFile(spec.config.c_str());
        config->validate();
        const std::vector<std::string> names = split_looks(spec.looks);
        if (names.empty()) {
          *err = spec.config + ": no look named (give --look NAME)";
          return false;
        }
        for (const std::string &n : names) {
          if (!config->getLook(n.c_str())) {
            std::string have;
            for (int i = 0; i < config->getNumLooks(); ++i)
              have += std::string(i ? ", " : "") + config->getLookNameByIndex(i);
            *err = spec.config + ": no look '" + n + "' (the config has: " + (have.empty() ? "none" : have) + ")";
            return false;
          }
        }
        const std::string src = spec.src.empty() ? "default" : spec.src;
        const std::string dst = spec.dst.empty() ? "default" : spec.dst;
        for (const std::string &cs : {src, dst}) {
          if (!config->getColorSpace(cs.c_str())) {
            *err = spec.config + ": no colour space or role '" + cs + "'" +
                (cs == "default" ? " (give --src and --dst)" : "");
            return false;
          }
        }
        auto lt = OCIO::LookTransform::Create();
        lt->setSrc(src.c_str());
        lt->setDst(dst.c_str());
        lt->setLooks(spec.looks.c_str());
        transform = lt;
        break;
      }
      case TransformSpec::Kind::Cdl: {
        for (int k = 0; k < 3; ++k) {
          if (!(spec.slope[k] >= 0) || !(spec.power[k] > 0) || !std::isfinite(spec.offset[k]) ||
              !std::isfinite(spec.slope[k]) || !std::isfinite(spec.power[k])) {
            *err = "CDL values: slope must be >= 0, power > 0, every value finite (" + spec.describe() + ")";
            return false;
          }
        }
        if (!(spec.sat >= 0) || !std::isfinite(spec.sat)) {
          *err = "CDL values: saturation must be a finite number >= 0";
          return false;
        }
        auto cdl = OCIO::CDLTransform::Create();
        cdl->setStyle(OCIO::CDL_ASC);
        cdl->setSlope(spec.slope);
        cdl->setOffset(spec.offset);
        cdl->setPower(spec.power);
        cdl->setSat(spec.sat);
        transform = cdl;
        config = OCIO::Config::CreateRaw();
        break;
      }
    }
    OCIO::ConstProcessorRcPtr proc = config->getProcessor(transform);
    auto impl = std::make_shared<ColorTransformImpl>();
    impl->cpu = proc->getOptimizedCPUProcessor(OCIO::OPTIMIZATION_LOSSLESS);
    impl_ = impl;
  } catch (const OCIO::Exception &e) {
    *err = subject + ": OpenColorIO: " + e.what();
    return false;
  }
  return true;
}

void ColorTransform::apply(float *rgb, size_t count) const {
  for (size_t i = 0; i < count; ++i) impl_->cpu->applyRGB(rgb + 3 * i);
}

bool bake_lut(const ColorTransform &t, int n, Lut3D *out, std::string *err) {
  if (!t.is_open()) {
    *err = "bake: no transform";
    return false;
  }
  if (n < 2 || n > 256) {
    *err = "bake: the LUT edge must be in [2, 256], got " + std::to_string(n);
    return false;
  }
  Lut3D l;
  l.n = n;
  l.rgb.resize(static_cast<size_t>(n) * n * n * 3);
  const float d = static_cast<float>(n - 1);
  for (int b = 0; b < n; ++b)
    for (int g = 0; g < n; ++g)
      for (int r = 0; r < n; ++r) {
        float *p = l.at(r, g, b);
        p[0] = static_cast<float>(r) / d;
        p[1] = static_cast<float>(g) / d;
        p[2] = static_cast<float>(b) / d;
      }
  t.apply(l.rgb.data(), l.rgb.size() / 3);
  for (float v : l.rgb) {
    if (!std::isfinite(v)) {
      *err = "bake: " + t.description() + " gives a non-finite value on the unit cube";
      return false;
    }
  }
  l.title = t.description();
  *out = std::move(l);
  return true;
}
