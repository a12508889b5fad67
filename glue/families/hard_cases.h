// tiershade families: the hard cases of a family as data (tests/conform/<family>.cases, embedded
// in the binary; format in docs/conformance.md): parsing and checking them against the family's
// slot names, and applying them to the records of the hard input grid.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "families/family.h"

// What a value expression of a case sees while it is evaluated.
struct CaseEval {
  Rng *rng = nullptr;  // uniform() and pick() draw from it (the grid's generator)
  int repeat_value = 0;  // the pixel's value of the file's [repeat COMBO]
};

// A function a family's cases may call besides the built-ins (docs/conformance.md),
// registered by the family's own file:
//   static const CaseFunctionRegistrar kCaseFns("color_correction", {{"lattice", {}, 1, "", fn}});
struct CaseFunction {
  std::string name;
  std::vector<int> arg_widths;  // width of each argument
  int result_width = 1;
  std::string repeat_combo;  // the combo whose [repeat] value it reads ("" = none)
  std::function<void(const float *args, const CaseEval &env, float *out)> eval;
};
struct CaseFunctionRegistrar {
  CaseFunctionRegistrar(const char *family, std::vector<CaseFunction> fns);
};

struct CaseExpr {
  enum Kind { Number, Ref, Call } kind = Number;
  float number = 0;
  int slot = -1, comps[4] = {0, 1, 2, 3};  // Ref: slot and swizzle
  std::string fn;  // Call: built-in or family function
  const CaseFunction *family_fn = nullptr;  // Call of a family function
  std::vector<CaseExpr> args;
  int width = 1;
};

// `TARGET VALUE...`: sets `width` components of one slot to the values (left to right).
struct CaseAssignment {
  int slot = -1, comps[4] = {0, 1, 2, 3}, width = 4;
  std::vector<CaseExpr> values;
  std::string where;  // file:line
};

struct HardCase {
  std::string name;
  int line = 0;
  bool random = false;  // slots the case does not set keep the random record's values
  // 'llvmpipe_only': the case puts NaN or Inf into the inputs, outside the portable contract
  // (GLSL ES leaves NaN/Inf undefined: docs/conformance.md "The portable contract"); its output
  // is only required to be what llvmpipe gives (still checked finite, in range and 0 ULP there).
  bool llvmpipe_only = false;
  std::vector<CaseAssignment> body;
};

struct HardCases {
  std::string family, file;
  std::vector<HardCase> cases;
  std::string repeat_combo;  // empty: no [repeat]
  std::vector<std::pair<int, std::string>> repeat;  // value, label
  // Pixel i of the hard grid: case i % cases.size(), repeat value (i / cases.size()) % repeat.size().
  size_t cycle() const { return cases.size() * (repeat.empty() ? 1 : repeat.size()); }
  std::string pixel_name(size_t i) const;
  // Applies pixel i's case to rec (a random record of the family), drawing from *rng.
  void apply(size_t i, Rng *rng, ts_vec4f *rec) const;
};

// Parses and checks a case file of `fam` (file: the name its messages give). Errors name file:line.
bool parse_hard_cases(const ShaderFamily &fam, const std::string &file, const std::string &text, HardCases *out,
                      std::string *err);
// The family's cases: its --cases override, else the embedded tests/conform/<family>.cases
// (parsed once). A missing or malformed file is an error.
bool family_hard_cases(const ShaderFamily &fam, const HardCases **out, std::string *err);
// Reads FILE (named <family>.cases, any directory) and makes it the cases of that family. Call it
// before the family's cases are used (it replaces what family_hard_cases returned).
bool use_hard_case_file(const std::string &path, std::string *err);
// The embedded case files (tests/conform/*.cases), by repository path.
std::vector<std::string> embedded_case_files();

// Parses one `TARGET VALUE...` line (no comment) of family `fam`. prefix_ok: a bare slot may take
// 1 to 4 values (sets the first ones: probe --input/--set); otherwise exactly its width.
bool parse_case_assignment(const ShaderFamily &fam, const std::string &line, const std::string &where, bool prefix_ok,
                           CaseAssignment *out, std::string *err);
void apply_case_assignment(const CaseAssignment &a, const CaseEval &env, ts_vec4f *rec);

// Fills out with a w x h grid of `slots`-slot records: random_pixel(rec) for every pixel, and on
// the hard set the family's case (y*w + x) applied on top of it, labelled in out->case_names.
// A hard grid of a family without a valid case file stops the program with the error.
void fill_record_grid(const char *family, InputSet set, int w, int h, int slots, Rng &r,
                      const std::function<void(ts_vec4f *rec)> &random_pixel, FamilyInputs *out);
