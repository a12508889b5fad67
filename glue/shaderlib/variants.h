// tiershade shaderlib: shader variants = tier x static combos x dynamic combos, minus skip rules.
// Each shader declares its combos in shaders/<shader>.variants (format: docs/tiers.md).
#pragma once
#include <map>
#include <string>
#include <vector>

#include "twins/tier_id.h"

// The tier, with the values of the twins' enum ts_tier_id (tier_id() gives that value).
enum class Tier { PS20 = TS_TIER_ID_PS20, PS2B = TS_TIER_ID_PS2B, SM3 = TS_TIER_ID_SM3 };
inline int tier_id(Tier t) { return static_cast<int>(t); }
// Local lights a tier shades per pixel (fact sheet section 4): ps20 2, ps2b and sm3 4.
inline int max_local_lights(Tier t) { return t == Tier::PS20 ? 2 : 4; }
const char *tier_name(Tier t);
bool parse_tier(const std::string &s, Tier *out);
std::vector<Tier> all_tiers();

struct Combo {
  std::string name;
  bool dynamic = false;
  int min = 0, max = 0;
  std::vector<Tier> tiers;  // tiers where the combo exists (empty = all)
};

struct SkipRule {
  std::vector<Tier> tiers;  // empty = all
  std::string expr;
  int line = 0;
};

struct ShaderDecl {
  std::string name;
  std::string fragment, vertex;
  std::string file;  // the .variants file, for messages
  std::vector<Tier> tiers;
  std::vector<Combo> combos;
  std::vector<SkipRule> skips;
  // `targets essl300 glsl330`: the assembler targets (target_name) the shader exists for; empty =
  // all three. texture_grad has no essl100 program: llvmpipe's ES contexts lack
  // EXT_shader_texture_lod.
  std::vector<std::string> targets;
  bool has_target(const char *target_name) const;
};

struct Variant {
  const ShaderDecl *shader = nullptr;
  Tier tier = Tier::SM3;
  std::vector<std::pair<std::string, int>> values;  // combo name -> value, declaration order
  int value(const std::string &combo, int fallback = 0) const;
  std::string name() const;  // "ps20:ALBEDO_TEXTURE=1,HALF_LAMBERT=0,..."
};

// Evaluates an integer expression over combo values (== != < <= > >= && || ! + - * and parentheses).
bool eval_expr(const std::string &expr, const std::map<std::string, int> &vars, int *out, std::string *err);

bool parse_shader_decl(const std::string &file, const std::string &text, ShaderDecl *out, std::string *err);
// Every shader declared in the library (shaders/*.variants), sorted by name.
bool load_shader_decls(std::vector<ShaderDecl> *out, std::string *err);
std::vector<Variant> enumerate_variants(const ShaderDecl &s, const std::vector<Tier> &tiers, std::string *err);
// Finds a variant by its name() or by its index in enumerate_variants(all tiers).
bool find_variant(const std::vector<ShaderDecl> &decls, const std::string &shader, const std::string &variant,
                  Variant *out, std::string *err);

// A set of variants and the declarations they point to (owned here, so the set can be moved).
struct Selection {
  std::vector<ShaderDecl> decls;
  std::vector<Variant> variants;
};
