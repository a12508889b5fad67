// tiershade cli: `lut` subcommand: colour-correction LUT files. inspect a .cube or Source
// .raw; bake a 3D LUT from an OpenColorIO transform (a LUT/CDL file, config looks, CDL
// values); convert between .cube and .raw. Bad input files: "tiershade lut: <file>[:<line>]:
// <problem>", exit status 2, nothing written (glue/io/lut_files.h writes atomically).
#include <sys/stat.h>

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

#include "cli/args.h"
#include "color/ocio_lut_bake.h"
#include "io/lut_files.h"

namespace {

const char kHelp[] = R"(usage: tiershade lut inspect FILE
       tiershade lut bake SOURCE --size N -o OUT.cube|OUT.raw
       tiershade lut convert IN OUT          (.cube <-> .raw)

inspect: kind, edge, title, domain and value range of a .cube (1D or 3D) or a Source .raw.
bake: evaluates a colour transform with OpenColorIO's CPU processor at the n^3 lattice
nodes (r, g, b)/(n-1) and writes the 3D LUT (.cube; .raw needs --size 32). SOURCE is one of
  --file F                      a LUT or CDL file OpenColorIO reads (.cube, .cc, .ccc, .cdl,
                                .3dl, .spi3d, ...), trilinear for 3D tables
  --config C --look L[,L2]      looks of an OCIO config, from --src to --dst (default: the
       [--src S] [--dst D]      config's `default` role both ways)
  --slope r,g,b --offset r,g,b  ASC CDL values (any of the four; the others default to
  --power r,g,b --sat s         slope 1, offset 0, power 1, sat 1), ASC style (clamped)
convert: a .cube 3D table on the unit domain to a Source .raw (edge 32, 8-bit codes),
or a .raw to a .cube. Source .raw: 32^3 RGB8, red fastest (INFERRED; docs/color_correction.md).
Errors in input files name the file and line; the output is written atomically, so a
failure leaves no output file. Exit status: 0 ok, 1 cannot write, 2 bad arguments or input.)";

bool parse_triple(const std::string &s, double v[3]) {
  std::string t = s;
  for (char &c : t)
    if (c == ',') c = ' ';
  std::istringstream in(t);
  std::string tok;
  int n = 0;
  while (in >> tok) {
    if (n >= 3) return false;
    char *end = nullptr;
    v[n] = std::strtod(tok.c_str(), &end);
    if (end == tok.c_str() || *end || !std::isfinite(v[n])) return false;
    ++n;
  }
  return n == 3;
}

void inspect(const Args &a, const std::string &path) {
  std::string err;
  std::vector<float> values;
  std::string lower = path;
  for (char &c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  const bool raw = lower.size() >= 4 && lower.compare(lower.size() - 4, 4, ".raw") == 0;
  if (raw) {
    Lut3D l;
    if (!read_source_raw(path, &l, &err)) a.fail(err);
    printf("%s: Source .raw, 3D LUT edge %d (%d entries, RGB8, red fastest)\n", path.c_str(), l.n, l.n * l.n * l.n);
    values = l.rgb;
  } else {
    CubeFile c;
    if (!read_cube(path, &c, &err)) a.fail(err);
    printf("%s: .cube", path.c_str());
    if (c.size_1d) printf(", 1D table of %d entries", c.size_1d);
    if (c.size_3d) printf(", 3D table of edge %d (%d entries)", c.size_3d, c.size_3d * c.size_3d * c.size_3d);
    printf("\n  title: \"%s\"\n  domain: [%g %g %g] .. [%g %g %g]\n", c.title.c_str(), c.domain_min[0], c.domain_min[1],
           c.domain_min[2], c.domain_max[0], c.domain_max[1], c.domain_max[2]);
    values = c.table_1d;
    values.insert(values.end(), c.table_3d.begin(), c.table_3d.end());
    Lut3D l;
    printf("  usable as a texture as is: %s\n", cube_as_lut3d(path, c, &l, &err) ? "yes" : err.c_str());
  }
  float lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
  for (size_t i = 0; i < values.size(); ++i) {
    lo[i % 3] = std::fmin(lo[i % 3], values[i]);
    hi[i % 3] = std::fmax(hi[i % 3], values[i]);
  }
  printf("  values: min %g %g %g, max %g %g %g\n", lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]);
}

bool has_ext(const std::string &path, const char *ext) {
  const std::string e = ext;
  if (path.size() <= e.size()) return false;
  for (size_t i = 0; i < e.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(path[path.size() - e.size() + i])) != e[i]) return false;
  return true;
}

// True when both paths name one existing file (hard links and symlinks included).
bool same_file(const std::string &x, const std::string &y) {
  struct stat a, b;
  return stat(x.c_str(), &a) == 0 && stat(y.c_str(), &b) == 0 && a.st_dev == b.st_dev && a.st_ino == b.st_ino;
}

int write_lut(const Args &a, const std::string &out, const Lut3D &l) {
  std::string lower = out;
  for (char &c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  const bool raw = lower.size() >= 4 && lower.compare(lower.size() - 4, 4, ".raw") == 0;
  const bool cube = lower.size() >= 5 && lower.compare(lower.size() - 5, 5, ".cube") == 0;
  if (!raw && !cube) a.fail(out + ": the output must end in .cube or .raw");
  if (raw && l.n != kSourceRawEdge)
    a.fail(out + ": a Source .raw holds a 32^3 LUT, this one has edge " + std::to_string(l.n));
  std::string err;
  if (!(raw ? write_source_raw(out, l, &err) : write_cube(out, l, &err))) {
    fprintf(stderr, "tiershade lut: %s\n", err.c_str());
    return 1;
  }
  printf("wrote %s (3D LUT edge %d, %s)\n", out.c_str(), l.n, l.title.c_str());
  return 0;
}

}  // namespace

int cmd_lut(int argc, char **argv) {
  Args a("lut", argc, argv, {"--help"},
         {"-o", "--size", "--file", "--config", "--look", "--src", "--dst", "--slope", "--offset", "--power", "--sat"});
  if (a.help(kHelp)) return 0;
  const auto &pos = a.positional();
  if (pos.empty()) a.fail("wants a subcommand: inspect, bake or convert (see tiershade lut --help)");
  const std::string sub = pos[0];
  if (sub == "inspect") {
    if (pos.size() != 2) a.fail("inspect wants one FILE");
    inspect(a, pos[1]);
    return 0;
  }
  if (sub == "convert") {
    if (pos.size() != 3) a.fail("convert wants IN and OUT");
    // .cube <-> .raw only: the same format would only rewrite the file (or its own input).
    const bool in_raw = has_ext(pos[1], ".raw"), out_raw = has_ext(pos[2], ".raw");
    if ((in_raw || has_ext(pos[1], ".cube")) && (out_raw || has_ext(pos[2], ".cube")) && in_raw == out_raw)
      a.fail("convert turns a .cube into a .raw or a .raw into a .cube; " + pos[1] + " and " + pos[2] +
             " are both " + (in_raw ? ".raw" : ".cube") + (same_file(pos[1], pos[2]) ? " (and the same file)" : ""));
    if (same_file(pos[1], pos[2])) a.fail(pos[1] + " and " + pos[2] + " are the same file");
    Lut3D l;
    std::string err;
    if (!read_lut_file(pos[1], &l, &err)) a.fail(err);
    return write_lut(a, pos[2], l);
  }
  if (sub != "bake") a.fail("unknown subcommand '" + sub + "' (inspect, bake, convert)");
  if (pos.size() != 1) a.fail("bake takes no positional argument, got '" + pos[1] + "'");
  if (!a.has("-o")) a.fail("bake wants -o OUT.cube or OUT.raw");
  if (!a.has("--size")) a.fail("bake wants --size N (2..256)");
  const int n = a.get_int("--size", 32, 2, 256);
  TransformSpec spec;
  const bool cdl = a.has("--slope") || a.has("--offset") || a.has("--power") || a.has("--sat");
  const int kinds = (a.has("--file") ? 1 : 0) + (a.has("--config") ? 1 : 0) + (cdl ? 1 : 0);
  if (kinds != 1) a.fail("bake wants exactly one source: --file, --config with --look, or CDL values");
  if (a.has("--file")) {
    spec.kind = TransformSpec::Kind::File;
    spec.file = a.get("--file");
  } else if (a.has("--config")) {
    if (!a.has("--look")) a.fail("--config wants --look NAME");
    spec.kind = TransformSpec::Kind::Look;
    spec.config = a.get("--config");
    spec.looks = a.get("--look");
    spec.src = a.get("--src");
    spec.dst = a.get("--dst");
  } else {
    spec.kind = TransformSpec::Kind::Cdl;
    const char *names[3] = {"--slope", "--offset", "--power"};
    double *dst[3] = {spec.slope, spec.offset, spec.power};
    for (int i = 0; i < 3; ++i)
      if (a.has(names[i]) && !parse_triple(a.get(names[i]), dst[i]))
        a.fail(std::string(names[i]) + " wants 3 finite numbers r,g,b, got '" + a.get(names[i]) + "'");
    if (a.has("--sat")) {
      double v[3];
      const std::string s = a.get("--sat");
      char *end = nullptr;
      v[0] = std::strtod(s.c_str(), &end);
      if (s.empty() || *end || !std::isfinite(v[0])) a.fail("--sat wants a finite number, got '" + s + "'");
      spec.sat = v[0];
    }
  }
  if ((a.has("--src") || a.has("--dst") || a.has("--look")) && spec.kind != TransformSpec::Kind::Look)
    a.fail("--look, --src and --dst go with --config");
  ColorTransform t;
  std::string err;
  if (!t.open(spec, &err)) a.fail(err);
  Lut3D l;
  if (!bake_lut(t, n, &l, &err)) a.fail(err);
  return write_lut(a, a.get("-o"), l);
}
