// tiershade tests: unit tests of the colour-correction glue (docs/color_correction.md):
//   * .cube reading (glue/io/lut_files.h): good files (comments, CRLF, TITLE, DOMAIN, Resolve's
//     1D shaper + 3D form) and bad files, each with its exact "file:line: problem" message;
//   * writers: .cube round trip bit for bit, atomic writes (a failed write leaves no file,
//     no temporary, and an existing file untouched);
//   * Source .raw: round trip, wrong sizes;
//   * the LUT textures: 3D order and the ES2 atlas layout (glue/color/lut_texture.h);
//   * baking with OpenColorIO (glue/color/ocio_lut_bake.h) against OCIO's CPU processor;
//   * CIEDE2000 (glue/color/ciede2000.h) on the 34 pairs of Sharma, Wu and Dalal (2005),
//     Table 1, and sRGB -> CIELAB anchors.
// Run from the repository root (tests/run_tests.sh does): it reads scenes/luts/.
// Usage: build/tests/test_color_correction   Prints PASS/FAIL lines; exit 1 on failure.
#include <dirent.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include "twins/color_correction.h"
#include "color/ciede2000.h"
#include "color/ocio_lut_bake.h"
#include "io/lut_files.h"
#include "color/lut_texture.h"
#include "unit_check.h"

namespace {

std::string g_dir;

std::string write_text(const std::string &name, const std::string &text) {
  const std::string path = g_dir + "/" + name;
  std::ofstream f(path, std::ios::binary);
  f << text;
  return path;
}

bool exists(const std::string &path) { return access(path.c_str(), F_OK) == 0; }

// Files in g_dir whose name contains ".tmp." (left-over temporaries of atomic writes).
int temporaries() {
  int n = 0;
  if (DIR *d = opendir(g_dir.c_str())) {
    while (dirent *e = readdir(d))
      if (std::strstr(e->d_name, ".tmp.")) ++n;
    closedir(d);
  }
  return n;
}

// A 2^3 table, red fastest.
const char kTable2[] =
    "0 0 0\n1 0 0\n0 1 0\n1 1 0\n"
    "0 0 1\n1 0 1\n0 1 1\n1 1 1\n";

// ---- .cube: good files ----------------------------------------------------------
void test_cube_good() {
  CubeFile c;
  std::string err;
  const std::string p =
      write_text("good.cube",
                 "# a comment\r\n"
                 "TITLE \"Good \"\"one\"\r\n"
                 "\r\n"
                 "  # indented comment\r\n"
                 "LUT_3D_SIZE 2\r\n"
                 "DOMAIN_MIN 0 0 0\r\n"
                 "DOMAIN_MAX 1 1 1\r\n"
                 "0 0 0\r\n1e-1 0 0\r\n0 1 0\r\n1 1 0\r\n0 0 1\r\n1 0 1\r\n0 1 1\r\n 1.0  1.0\t1.0 \r\n");
  const bool ok = read_cube(p, &c, &err);
  check(ok, "cube.good.read", err);
  check(ok && c.size_3d == 2 && c.size_1d == 0 && c.table_3d.size() == 24, "cube.good.sizes");
  check(ok && c.title == "Good \"\"one", "cube.good.title (text between the first and last quote)", c.title);
  check(ok && c.table_3d[3] == 0.1f && c.table_3d[23] == 1.f, "cube.good.values");
  Lut3D l;
  check(ok && cube_as_lut3d(p, c, &l, &err) && l.n == 2 && l.at(1, 0, 0)[0] == 0.1f && l.at(0, 1, 1)[1] == 1.f,
        "cube.good.as_lut3d (red fastest)", err);

  const std::string r = write_text("resolve.cube",
                                   "LUT_1D_SIZE 2\nLUT_3D_SIZE 2\nLUT_3D_INPUT_RANGE -0.5 1.5\n"
                                   "0 0 0\n1 1 1\n" +
                                       std::string(kTable2));
  check(read_cube(r, &c, &err) && c.size_1d == 2 && c.size_3d == 2 && c.domain_min[1] == -0.5f &&
            c.domain_max[2] == 1.5f && c.table_1d.size() == 6 && c.table_3d.size() == 24,
        "cube.good.resolve_1d_shaper_plus_3d", err);
  check(!cube_as_lut3d(r, c, &l, &err) &&
            err == r + ": a 1D shaper before the 3D table; bake it into one 3D LUT (tiershade lut bake --file)",
        "cube.as_lut3d.rejects_shaper", err);

  const std::string one = write_text("one.cube", "LUT_1D_SIZE 3\n0 0 0\n0.5 0.5 0.5\n1 1 1\n");
  check(read_cube(one, &c, &err) && c.size_1d == 3 && !c.size_3d, "cube.good.1d", err);
  check(!cube_as_lut3d(one, c, &l, &err) &&
            err == one + ": a 1D LUT, not a 3D one; bake it into a 3D LUT (tiershade lut bake --file)",
        "cube.as_lut3d.rejects_1d", err);
  const std::string dom = write_text("dom.cube", "LUT_3D_SIZE 2\nDOMAIN_MAX 2 1 1\n" + std::string(kTable2));
  check(read_cube(dom, &c, &err) && !cube_as_lut3d(dom, c, &l, &err) &&
            err == dom + ": the domain is not [0, 1]; bake it on the unit cube (tiershade lut bake --file)",
        "cube.as_lut3d.rejects_domain", err);
}

// ---- .cube: bad files, exact messages ---------------------------------------------
void test_cube_bad() {
  struct Bad {
    const char *name, *text, *message;  // message after "<path>"
  };
  const std::string t2 = kTable2;
  const std::vector<Bad> bad = {
      {"unknown_keyword", "LUT_3D_SIZE 2\nLUT_3D_SIZ 2\n", ":2: unknown keyword 'LUT_3D_SIZ'"},
      {"size_too_big", "LUT_3D_SIZE 257\n", ":1: LUT_3D_SIZE wants one integer in [2, 256]"},
      {"size_one", "# c\nLUT_3D_SIZE 1\n", ":2: LUT_3D_SIZE wants one integer in [2, 256]"},
      {"size_not_integer", "LUT_3D_SIZE 2.5\n", ":1: LUT_3D_SIZE wants one integer in [2, 256]"},
      {"size_1d_too_big", "LUT_1D_SIZE 65537\n", ":1: LUT_1D_SIZE wants one integer in [2, 65536]"},
      {"size_twice", "LUT_3D_SIZE 2\nLUT_3D_SIZE 2\n", ":2: LUT_3D_SIZE given twice"},
      {"title_twice", "TITLE \"a\"\nTITLE \"b\"\n", ":2: TITLE given twice"},
      {"title_unquoted", "TITLE hello\n", ":1: TITLE wants a text in double quotes"},
      {"two_numbers", "LUT_3D_SIZE 2\n0 0 0\n1 0\n", ":3: a table line holds 3 numbers (R G B), this one has 2"},
      {"four_numbers", "LUT_3D_SIZE 2\n0 0 0 0\n", ":2: a table line holds 3 numbers (R G B), this one has 4"},
      {"nan_value", "LUT_3D_SIZE 2\n0 0 0\nnan 0 0\n", ":3: 'nan' is not a finite number"},
      {"inf_value", "LUT_3D_SIZE 2\n0 -inf 0\n", ":2: '-inf' is not a finite number"},
      {"garbage_value", "LUT_3D_SIZE 2\n0 0.5x 0\n", ":2: '0.5x' is not a finite number"},
      {"overflow_value", "LUT_3D_SIZE 2\n0 1e39 0\n", ":2: '1e39' is not a finite number"},
      {"data_before_size", "# c\n0 0 0\n", ":2: table data before LUT_1D_SIZE or LUT_3D_SIZE"},
      {"keyword_after_data", "LUT_3D_SIZE 2\n0 0 0\nTITLE \"late\"\n",
       ":3: keyword TITLE after the table data (line 2); keywords come first"},
      {"domain_two_values", "DOMAIN_MIN 0 0\n", ":1: DOMAIN_MIN wants 3 finite numbers (R G B)"},
      {"range_three_values", "LUT_3D_INPUT_RANGE 0 1 2\n", ":1: LUT_3D_INPUT_RANGE wants 2 finite numbers (min max)"},
      {"domain_and_range", "DOMAIN_MIN 0 0 0\nLUT_3D_INPUT_RANGE 0 1\n",
       ":2: DOMAIN_MIN/MAX (Adobe) and LUT_*_INPUT_RANGE (Resolve) cannot be mixed"},
      {"long_line", nullptr, ":1: line longer than 250 characters"},
      {"too_many_lines", nullptr, ":10: more table lines than the 8 the sizes declare"},
      {"too_few_lines", "LUT_3D_SIZE 2\n0 0 0\n1 0 0\n", ": the table ends after 2 of 8 lines"},
      {"no_size", "TITLE \"x\"\n# nothing else\n", ": no LUT_1D_SIZE or LUT_3D_SIZE"},
      {"empty", "", ": no LUT_1D_SIZE or LUT_3D_SIZE"},
      {"empty_domain", "LUT_3D_SIZE 2\nDOMAIN_MIN 0 1 0\nDOMAIN_MAX 1 1 1\n",
       ": the domain is empty on channel G (min 1.000000 >= max 1.000000)"},
      {"shaper_with_domain", "LUT_1D_SIZE 2\nLUT_3D_SIZE 2\nDOMAIN_MIN 0 0 0\n",
       ": a 1D and a 3D table in one file (Resolve form) take LUT_*_INPUT_RANGE, not DOMAIN_MIN/MAX"},
  };
  for (const Bad &b : bad) {
    std::string text = b.text ? b.text : "LUT_3D_SIZE 2\n" + t2 + "0 0 0\n";
    if (std::string(b.name) == "long_line") text = "# " + std::string(250, 'a') + "\nLUT_3D_SIZE 2\n" + t2;
    if (std::string(b.name) == "empty_domain" || std::string(b.name) == "shaper_with_domain") text += t2;
    const std::string p = write_text(std::string(b.name) + ".cube", text);
    CubeFile c;
    std::string err;
    const bool ok = read_cube(p, &c, &err);
    check(!ok && err == p + b.message, std::string("cube.bad.") + b.name, "got '" + err + "'");
  }
  // A NUL byte (a binary file named .cube).
  const std::string nul = write_text("nul.cube", std::string("LUT_3D_SIZE 2\n0 0\0 0\n", 21));
  CubeFile c;
  std::string err;
  check(!read_cube(nul, &c, &err) && err == nul + ":2: binary data (a NUL byte) in a text file", "cube.bad.nul_byte",
        err);
  const std::string missing = g_dir + "/missing.cube";
  check(!read_cube(missing, &c, &err) && err == missing + ": cannot open (No such file or directory)",
        "cube.bad.missing_file", err);
  check(!read_cube(g_dir, &c, &err) && err.rfind(g_dir + ": ", 0) == 0, "cube.bad.directory", err);
}

Lut3D ramp_lut(int n, float scale) {
  Lut3D l = identity_lut(n);
  for (size_t i = 0; i < l.rgb.size(); ++i) l.rgb[i] = l.rgb[i] * scale + static_cast<float>(i % 7) * 1e-3f;
  l.title = "ramp";
  return l;
}

// ---- writers ----------------------------------------------------------------------
void test_writers() {
  std::string err;
  Lut3D l = ramp_lut(5, 0.7f);
  l.rgb[4] = 0.1f;  // not exactly representable in decimal
  l.rgb[5] = 1.17549435e-38f;  // FLT_MIN
  l.rgb[6] = -3.40282347e38f;  // -FLT_MAX
  const std::string p = g_dir + "/out.cube";
  check(write_cube(p, l, &err), "write_cube.ok", err);
  CubeFile c;
  Lut3D back;
  const bool ok = read_cube(p, &c, &err) && cube_as_lut3d(p, c, &back, &err);
  check(ok && back.n == 5 && back.rgb == l.rgb && c.title == "ramp", "write_cube.round_trip_bit_exact", err);
  check(temporaries() == 0, "write_cube.no_temporary_left");

  // A failed write leaves the existing file untouched and no temporary.
  std::ifstream before_f(p, std::ios::binary);
  const std::string before((std::istreambuf_iterator<char>(before_f)), std::istreambuf_iterator<char>());
  Lut3D badlut = l;
  badlut.rgb[10] = NAN;
  check(!write_cube(p, badlut, &err) && err == p + ": not written: the LUT holds a non-finite value",
        "write_cube.rejects_nan", err);
  std::ifstream after_f(p, std::ios::binary);
  const std::string after((std::istreambuf_iterator<char>(after_f)), std::istreambuf_iterator<char>());
  check(before == after && temporaries() == 0, "write_cube.failure_leaves_file_untouched");
  badlut = l;
  badlut.title = "bad \"title\"";
  const std::string q = g_dir + "/never.cube";
  check(!write_cube(q, badlut, &err) && !exists(q) &&
            err == q + ": not written: the title holds a double quote or a line break",
        "write_cube.rejects_quote_in_title", err);
  const std::string nodir = g_dir + "/no/such/dir/x.cube";
  check(
      !write_cube(nodir, l, &err) && err == nodir + ": cannot write (No such file or directory)" && temporaries() == 0,
      "write_cube.unwritable_directory", err);

  // Source .raw: 8-bit codes survive a round trip exactly.
  Lut3D r = identity_lut(kSourceRawEdge);
  for (size_t i = 0; i < r.rgb.size(); ++i) r.rgb[i] = static_cast<float>((i * 37) % 256) / 255.f;
  const std::string rp = g_dir + "/out.raw";
  Lut3D rb;
  check(write_source_raw(rp, r, &err) && read_source_raw(rp, &rb, &err) && rb.n == 32 && rb.rgb == r.rgb,
        "raw.round_trip_exact", err);
  std::ifstream rf(rp, std::ios::binary | std::ios::ate);
  check(static_cast<long>(rf.tellg()) == kSourceRawBytes, "raw.size_98304");
  // Entry order: red fastest (INFERRED layout; docs/color_correction.md).
  {
    std::ifstream in(rp, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const size_t idx = 3 * ((static_cast<size_t>(5) * 32 + 3) * 32 + 7);  // r=7, g=3, b=5
    const float *e = r.at(7, 3, 5);
    check(static_cast<unsigned char>(bytes[idx]) == std::lround(e[0] * 255.f) &&
              static_cast<unsigned char>(bytes[idx + 2]) == std::lround(e[2] * 255.f),
          "raw.entry_order_red_fastest");
  }
  // Quantisation: clamped to [0, 1], nearest code.
  Lut3D q8 = identity_lut(32);
  q8.rgb[0] = -0.3f;
  q8.rgb[1] = 1.7f;
  q8.rgb[2] = 0.5f / 255.f + 1e-4f;
  const std::string qp = g_dir + "/q.raw";
  check(write_source_raw(qp, q8, &err) && read_source_raw(qp, &rb, &err) && rb.rgb[0] == 0.f && rb.rgb[1] == 1.f &&
            rb.rgb[2] == 1.f / 255.f,
        "raw.clamp_and_round", err);
  const std::string wrong = write_text("short.raw", std::string(98303, 'x'));
  check(!read_source_raw(wrong, &rb, &err) &&
            err == wrong + ": 98303 bytes; a Source colour-correction .raw is 32 x 32 x 32 RGB8 = 98304 bytes",
        "raw.bad_size", err);
  const std::string e17 = g_dir + "/e17.raw";
  check(!write_source_raw(e17, identity_lut(17), &err) && !exists(e17) &&
            err == e17 + ": not written: a Source .raw holds a 32^3 LUT, this one has edge 17 (bake it at --size 32)",
        "raw.write_rejects_other_edges", err);
  Lut3D any;
  const std::string png = write_text("x.png", "not a lut");
  check(
      !read_lut_file(png, &any, &err) && err == png + ": unknown LUT file type (tiershade reads .cube and Source .raw)",
      "read_lut_file.unknown_extension", err);
  check(read_lut_file(rp, &any, &err) && any.n == 32 && read_lut_file(p, &any, &err) && any.n == 5,
        "read_lut_file.by_extension", err);
}

// ---- textures ------------------------------------------------------------------------
void test_textures() {
  const Lut3D l = ramp_lut(5, 1.f);
  const TextureDesc v = lut_volume_texture(l, "u_lut0", true);
  const TextureDesc a = lut_atlas_texture(l, "u_lut_atlas0", false);
  bool vol_ok = v.kind == TexKind::Tex3D && v.w == 5 && v.h == 5 && v.d == 5 && v.linear;
  bool atl_ok = a.kind == TexKind::Tex2D && a.w == 25 && a.h == 5 && !a.linear;
  for (int b = 0; b < 5; ++b)
    for (int g = 0; g < 5; ++g)
      for (int r = 0; r < 5; ++r) {
        const float *e = l.at(r, g, b);
        const float *tv = &v.rgba[4 * ((static_cast<size_t>(b) * 5 + g) * 5 + r)];
        const float *ta = &a.rgba[4 * (static_cast<size_t>(g) * 25 + b * 5 + r)];
        for (int k = 0; k < 3; ++k) {
          vol_ok = vol_ok && tv[k] == e[k];
          atl_ok = atl_ok && ta[k] == e[k];
        }
        vol_ok = vol_ok && tv[3] == 1.f;
        atl_ok = atl_ok && ta[3] == 1.f;
      }
  check(vol_ok, "texture.volume_order (x red, y green, z blue)");
  check(atl_ok, "texture.atlas_layout (texel (b*N + r, g))");
  const ts_vec4f p = cc_lut_params(32);
  check(p.x == 31.f / 32.f && p.y == 0.5f / 32.f && p.z == 31.f && p.w == 1.f / 32.f,
        "cc_lut_params(32) = (31/32, 0.5/32, 31, 1/32) (fact sheet section 9)");
}

// Double-precision trilinear lookup of a LUT with the shader's texel-centre addressing.
void lut_lookup(const Lut3D &l, const float in[3], float out[3]) {
  const TextureDesc v = lut_volume_texture(l, "u", true);
  const ts_tex3d t = tex3d_of(v);
  const double n = l.n;
  const ts_vec4d s = ts_texture3Dd(
      &t, ts_v3d(in[0] * (n - 1) / n + 0.5 / n, in[1] * (n - 1) / n + 0.5 / n, in[2] * (n - 1) / n + 0.5 / n));
  out[0] = static_cast<float>(s.x);
  out[1] = static_cast<float>(s.y);
  out[2] = static_cast<float>(s.z);
}

uint32_t g_rng = 12345;
float urand() {
  g_rng ^= g_rng << 13;
  g_rng ^= g_rng >> 17;
  g_rng ^= g_rng << 5;
  return static_cast<float>(g_rng >> 8) / 16777216.f;
}

// ---- baking with OpenColorIO -----------------------------------------------------------
void test_bake() {
  std::string err;
  // An affine CDL inside [0, 1] (no clamping): slope 0.8, offset 0.05, power 1, sat 1.
  TransformSpec cdl;
  cdl.kind = TransformSpec::Kind::Cdl;
  cdl.slope[0] = 0.8;
  cdl.slope[1] = 0.7;
  cdl.slope[2] = 0.9;
  cdl.offset[0] = cdl.offset[1] = cdl.offset[2] = 0.05;
  ColorTransform t;
  check(t.open(cdl, &err), "bake.cdl.open", err);
  Lut3D l;
  check(bake_lut(t, 9, &l, &err) && l.n == 9, "bake.cdl.bake", err);
  // Nodes: exactly what OCIO's processor gives for the node colour (same float inputs).
  bool nodes = l.n == 9;
  for (int b = 0; nodes && b < 9; b += 4)
    for (int g = 0; g < 9; g += 3)
      for (int r = 0; r < 9; ++r) {
        float c[3] = {static_cast<float>(r) / 8.f, static_cast<float>(g) / 8.f, static_cast<float>(b) / 8.f};
        t.apply(c, 1);
        const float *e = l.at(r, g, b);
        nodes = nodes && c[0] == e[0] && c[1] == e[1] && c[2] == e[2];
      }
  check(nodes, "bake.cdl.nodes_equal_ocio (tolerance 0: the same processor on the same float inputs)");
  // Between nodes: trilinear reproduces an affine map; what is left is float rounding of
  // the stored nodes (1/2 ulp, 6e-8 near 1) and of OCIO's own float arithmetic: 1e-6
  // (about 16 ulp near 1) covers both with margin and is 100x below an 8-bit code step.
  double worst = 0;
  for (int i = 0; i < 2000; ++i) {
    float c[3] = {urand(), urand(), urand()}, ref[3] = {c[0], c[1], c[2]}, got[3];
    t.apply(ref, 1);
    lut_lookup(l, c, got);
    for (int k = 0; k < 3; ++k) worst = std::fmax(worst, std::fabs(static_cast<double>(got[k]) - ref[k]));
  }
  check(worst <= 1e-6, "bake.cdl.affine_between_nodes (<= 1e-6)", "max error " + std::to_string(worst));

  // The committed example LUT is what the config's look gives (tolerance 0: %.9g prints
  // a float exactly, so a re-bake must reproduce the file bit for bit).
  TransformSpec look;
  look.kind = TransformSpec::Kind::Look;
  look.config = "scenes/luts/looks.ocio";
  look.looks = "day_for_night";
  ColorTransform dfn;
  Lut3D baked, file;
  check(dfn.open(look, &err) && bake_lut(dfn, 17, &baked, &err), "bake.look.day_for_night", err);
  check(read_lut_file("scenes/luts/day_for_night.cube", &file, &err) && file.n == 17 && file.rgb == baked.rgb,
        "bake.look.matches_committed_scenes_luts_day_for_night_cube", err);
  // A 32^3 LUT of the look against OCIO's processor, in CIEDE2000 on random colours: below
  // 1.0, the usual just-noticeable difference (the measured values: docs/accuracy_cost.md).
  Lut3D l32;
  double de_max = 0;
  if (bake_lut(dfn, 32, &l32, &err)) {
    for (int i = 0; i < 4000; ++i) {
      float c[3] = {urand(), urand(), urand()}, ref[3] = {c[0], c[1], c[2]}, got[3];
      dfn.apply(ref, 1);
      lut_lookup(l32, c, got);
      de_max = std::fmax(de_max, ciede2000(srgb_to_lab(ref[0], ref[1], ref[2]), srgb_to_lab(got[0], got[1], got[2])));
    }
  }
  check(de_max > 0 && de_max < 1.0, "bake.look.lut32_within_one_jnd (CIEDE2000 < 1)", "max " + std::to_string(de_max));
  printf("info: day_for_night, 32^3 LUT, double trilinear vs OCIO: CIEDE2000 max %.4f over 4000 colours\n", de_max);

  // A .cube through OCIO's FileTransform, baked at its own edge: the nodes come back.
  // Tolerance 0: node (i/16) lands exactly on a lattice point (16 = 2^4), fraction 0.
  TransformSpec cube;
  cube.file = "scenes/luts/desaturate.cube";
  ColorTransform des;
  Lut3D des17, des_file;
  check(des.open(cube, &err) && bake_lut(des, 17, &des17, &err) && read_lut_file(cube.file, &des_file, &err) &&
            des17.rgb == des_file.rgb,
        "bake.file.cube_nodes_round_trip", err);
  // A .cc (ASC CDL XML) through FileTransform.
  TransformSpec cc;
  cc.file = "scenes/luts/warm.cc";
  ColorTransform warm;
  Lut3D w;
  check(warm.open(cc, &err) && bake_lut(warm, 4, &w, &err) && w.at(3, 3, 3)[0] > w.at(3, 3, 3)[2],
        "bake.file.cdl_xml (warm: red above blue on white)", err);

  // Errors name the file (and the line, for .cube files read by tiershade first).
  const std::string badcube = write_text("bad_for_ocio.cube", "LUT_3D_SIZE 2\n0 0 0\n0 zero 0\n");
  TransformSpec bc;
  bc.file = badcube;
  ColorTransform x;
  check(!x.open(bc, &err) && err == badcube + ":3: 'zero' is not a finite number", "bake.error.cube_file_line", err);
  bc.file = g_dir + "/none.cube";
  check(!x.open(bc, &err) && err == bc.file + ": cannot open (no such file)", "bake.error.missing_file", err);
  const std::string badcc = write_text("bad.cc", "<ColorCorrection id=\"x\"><SOPNode><Slope>1 1</Slope>");
  bc.file = badcc;
  check(!x.open(bc, &err) && err.rfind(badcc + ": OpenColorIO: ", 0) == 0, "bake.error.bad_cdl_xml_names_file", err);
  TransformSpec nolook = look;
  nolook.looks = "nope";
  check(!x.open(nolook, &err) &&
            err == "scenes/luts/looks.ocio: no look 'nope' (the config has: day_for_night, desaturate)",
        "bake.error.unknown_look", err);
  nolook.looks = "day_for_night";
  nolook.src = "xyz";
  check(!x.open(nolook, &err) && err == "scenes/luts/looks.ocio: no colour space or role 'xyz'",
        "bake.error.unknown_colour_space", err);
  const std::string badcfg = write_text(
      "bad.ocio", "ocio_profile_version: 2\nroles:\n  default: a\ncolorspaces:\n  - !<ColorSpace>\n    name: [\n");
  TransformSpec bl = look;
  bl.config = badcfg;
  check(!x.open(bl, &err) && err.rfind(badcfg + ": OpenColorIO: ", 0) == 0, "bake.error.bad_config_names_file", err);
  TransformSpec badcdl;
  badcdl.kind = TransformSpec::Kind::Cdl;
  badcdl.power[1] = 0;
  check(!x.open(badcdl, &err) && err.rfind("CDL values: slope must be >= 0, power > 0", 0) == 0,
        "bake.error.cdl_power_zero", err);
  Lut3D none;
  check(!bake_lut(t, 1, &none, &err) && err == "bake: the LUT edge must be in [2, 256], got 1", "bake.error.edge_1",
        err);
}

// ---- CIEDE2000 -----------------------------------------------------------------------------
void test_ciede2000() {
  // Sharma, Wu, Dalal (2005), Table 1: L1 a1 b1 L2 a2 b2 dE00 (published to 4 decimals).
  static const double kPairs[34][7] = {
      {50.0000, 2.6772, -79.7751, 50.0000, 0.0000, -82.7485, 2.0425},
      {50.0000, 3.1571, -77.2803, 50.0000, 0.0000, -82.7485, 2.8615},
      {50.0000, 2.8361, -74.0200, 50.0000, 0.0000, -82.7485, 3.4412},
      {50.0000, -1.3802, -84.2814, 50.0000, 0.0000, -82.7485, 1.0000},
      {50.0000, -1.1848, -84.8006, 50.0000, 0.0000, -82.7485, 1.0000},
      {50.0000, -0.9009, -85.5211, 50.0000, 0.0000, -82.7485, 1.0000},
      {50.0000, 0.0000, 0.0000, 50.0000, -1.0000, 2.0000, 2.3669},
      {50.0000, -1.0000, 2.0000, 50.0000, 0.0000, 0.0000, 2.3669},
      {50.0000, 2.4900, -0.0010, 50.0000, -2.4900, 0.0009, 7.1792},
      {50.0000, 2.4900, -0.0010, 50.0000, -2.4900, 0.0010, 7.1792},
      {50.0000, 2.4900, -0.0010, 50.0000, -2.4900, 0.0011, 7.2195},
      {50.0000, 2.4900, -0.0010, 50.0000, -2.4900, 0.0012, 7.2195},
      {50.0000, -0.0010, 2.4900, 50.0000, 0.0009, -2.4900, 4.8045},
      {50.0000, -0.0010, 2.4900, 50.0000, 0.0010, -2.4900, 4.8045},
      {50.0000, -0.0010, 2.4900, 50.0000, 0.0011, -2.4900, 4.7461},
      {50.0000, 2.5000, 0.0000, 50.0000, 0.0000, -2.5000, 4.3065},
      {50.0000, 2.5000, 0.0000, 73.0000, 25.0000, -18.0000, 27.1492},
      {50.0000, 2.5000, 0.0000, 61.0000, -5.0000, 29.0000, 22.8977},
      {50.0000, 2.5000, 0.0000, 56.0000, -27.0000, -3.0000, 31.9030},
      {50.0000, 2.5000, 0.0000, 58.0000, 24.0000, 15.0000, 19.4535},
      {50.0000, 2.5000, 0.0000, 50.0000, 3.1736, 0.5854, 1.0000},
      {50.0000, 2.5000, 0.0000, 50.0000, 3.2972, 0.0000, 1.0000},
      {50.0000, 2.5000, 0.0000, 50.0000, 1.8634, 0.5757, 1.0000},
      {50.0000, 2.5000, 0.0000, 50.0000, 3.2592, 0.3350, 1.0000},
      {60.2574, -34.0099, 36.2677, 60.4626, -34.1751, 39.4387, 1.2644},
      {63.0109, -31.0961, -5.8663, 62.8187, -29.7946, -4.0864, 1.2630},
      {61.2901, 3.7196, -5.3901, 61.4292, 2.2480, -4.9620, 1.8731},
      {35.0831, -44.1164, 3.7933, 35.0232, -40.0716, 1.5901, 1.8645},
      {22.7233, 20.0904, -46.6940, 23.0331, 14.9730, -42.5619, 2.0373},
      {36.4612, 47.8580, 18.3852, 36.2715, 50.5065, 21.2231, 1.4146},
      {90.8027, -2.0831, 1.4410, 91.1528, -1.6435, 0.0447, 1.4441},
      {90.9257, -0.5406, -0.9208, 88.6381, -0.8985, -0.7239, 1.5381},
      {6.7747, -0.2908, -2.4247, 5.8714, -0.0985, -2.2286, 0.6377},
      {2.0776, 0.0795, -1.1350, 0.9033, -0.0636, -0.5514, 0.9082},
  };
  // Tolerance 5e-5: the table is rounded to 4 decimals (half a unit in the last place).
  int ok = 0;
  std::string first;
  for (int i = 0; i < 34; ++i) {
    const Lab a{kPairs[i][0], kPairs[i][1], kPairs[i][2]}, b{kPairs[i][3], kPairs[i][4], kPairs[i][5]};
    const double d1 = ciede2000(a, b), d2 = ciede2000(b, a);
    if (std::fabs(d1 - kPairs[i][6]) <= 5e-5 && std::fabs(d2 - kPairs[i][6]) <= 5e-5) {
      ++ok;
    } else if (first.empty()) {
      first = "pair " + std::to_string(i + 1) + ": " + std::to_string(d1) + " / " + std::to_string(d2) + " vs " +
          std::to_string(kPairs[i][6]);
    }
  }
  check(ok == 34, "ciede2000.sharma_2005_table1_34_pairs_both_orders", std::to_string(ok) + "/34; " + first);
  check(ciede2000(Lab{52, 10, -30}, Lab{52, 10, -30}) == 0.0, "ciede2000.identical_is_zero");
  // sRGB -> CIELAB anchors: white (exact by construction of the white point) and the sRGB
  // primaries' published values (53.24, 80.09, 67.20), (87.73, -86.18, 83.18), (32.30, 79.19,
  // -107.86); 0.006 = the references' rounding to 2 decimals (0.005) and the matrix's 7th digit.
  const Lab w = srgb_to_lab(1, 1, 1), k = srgb_to_lab(0, 0, 0);
  check(
      std::fabs(w.L - 100) < 1e-9 && std::fabs(w.a) < 1e-9 && std::fabs(w.b) < 1e-9 && k.L == 0 && k.a == 0 && k.b == 0,
      "srgb_to_lab.white_and_black");
  const Lab r = srgb_to_lab(1, 0, 0), g = srgb_to_lab(0, 1, 0), b = srgb_to_lab(0, 0, 1);
  auto near = [](const Lab &x, double L, double a, double bb) {
    return std::fabs(x.L - L) <= 0.006 && std::fabs(x.a - a) <= 0.006 && std::fabs(x.b - bb) <= 0.006;
  };
  check(near(r, 53.24, 80.09, 67.20) && near(g, 87.73, -86.18, 83.18) && near(b, 32.30, 79.19, -107.86),
        "srgb_to_lab.primaries", std::to_string(r.L) + " " + std::to_string(r.a) + " " + std::to_string(r.b));
  const Lab c = srgb_to_lab(-0.5, 2.0, NAN);
  const Lab c2 = srgb_to_lab(0, 1, 0);
  check(c.L == c2.L && c.a == c2.a && c.b == c2.b, "srgb_to_lab.clamps_outside_0_1_and_nan");
}

}  // namespace

int main() {
  char tmpl[] = "/tmp/tiershade_cc.XXXXXX";
  if (!mkdtemp(tmpl)) {
    printf("FAIL setup: mkdtemp\n");
    return 1;
  }
  g_dir = tmpl;
  if (access("scenes/luts/looks.ocio", R_OK) != 0) {
    printf("FAIL setup: run from the repository root (scenes/luts/looks.ocio not found)\n");
    return 1;
  }
  ts_math_init();
  test_cube_good();
  test_cube_bad();
  test_writers();
  test_textures();
  test_bake();
  test_ciede2000();
  const std::string rm = "rm -rf '" + g_dir + "'";
  if (std::system(rm.c_str()) != 0) printf("FAIL cleanup: %s\n", rm.c_str());
  return finish();
}
