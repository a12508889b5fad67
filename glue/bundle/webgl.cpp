// tiershade bundle: the WebGL extensions a variant needs (see webgl.h; the rules are the table of
// docs/bundles.md, "Extensions"). Facts: WebGL 1.0 spec section 5.14.14 and the Khronos WebGL
// extension registry (OES_texture_float, OES_texture_float_linear, WEBGL_color_buffer_float,
// EXT_color_buffer_half_float, EXT_sRGB, OES_element_index_uint, OES_standard_derivatives,
// EXT_frag_depth, EXT_shader_texture_lod); WebGL 2 has float textures (not their linear
// filtering), sRGB targets, 32-bit indices, derivatives and 3D textures in core, and float colour
// targets through EXT_color_buffer_float. No browser exposes OES_texture_3D.
#include "bundle/webgl.h"

#include <set>

#include "families/family.h"

namespace {

bool assemble_ids(const Variant &v, Target target, Stage stage, std::set<std::string> *ids, std::string *err) {
  Assembled a;
  const std::string &entry = stage == Stage::Vertex ? v.shader->vertex : v.shader->fragment;
  if (!assemble(entry, target, stage, variant_defines(v, InputMode::Production), &a, err)) return false;
  if (!preprocessed_identifiers(a.text, stage == Stage::Vertex, ids, err)) {
    *err = map_compile_log(*err, a);
    return false;
  }
  return true;
}

std::string join_names(const std::vector<InterfaceVar> &vars) {
  std::string s;
  for (const auto &x : vars) s += (s.empty() ? "" : ", ") + x.name;
  return s;
}

// The variant writes linear values (no display encoding in the shader): model_lighting and
// hdr_tonemap with OUTPUT_MODE 0 and every family without OUTPUT_MODE but color_correction, whose
// output is the saturated display colour (docs/color_correction.md).
bool linear_output(const Variant &v) {
  if (v.shader->name == "color_correction") return false;
  return v.value("OUTPUT_MODE", 0) == 0;
}

}  // namespace

bool extension_unavailable(Target target, const std::string &name) {
  return target == Target::ESSL100 && name == "OES_texture_3D";
}

bool variant_extensions(const Variant &v, Target target, const ProgramInterface *iface, std::vector<ExtensionNeed> *out,
                        std::string *err) {
  out->clear();
  if (target == Target::GLSL330) return true;
  std::set<std::string> vs, fs;
  if (!assemble_ids(v, target, Stage::Vertex, &vs, err) || !assemble_ids(v, target, Stage::Fragment, &fs, err)) return false;
  auto has = [&](const char *id) { return vs.count(id) || fs.count(id); };
  const bool es2 = target == Target::ESSL100;
  if (es2 && has("sampler3D"))
    out->push_back({"OES_texture_3D", {}, "declares a sampler3D: WebGL 1 has no 3D textures (no browser exposes OES_texture_3D)"});
  if (es2 && (fs.count("dFdx") || fs.count("dFdy") || fs.count("fwidth")))
    out->push_back({"OES_standard_derivatives", {}, "uses dFdx, dFdy or fwidth"});
  if (es2 && fs.count("gl_FragDepthEXT")) out->push_back({"EXT_frag_depth", {}, "writes gl_FragDepthEXT"});
  if (es2 && (has("texture2DLodEXT") || has("textureCubeLodEXT") || has("texture2DGradEXT")))
    out->push_back({"EXT_shader_texture_lod", {}, "samples with an explicit level of detail"});
  if (!iface) return true;
  if (!iface->samplers.empty()) {
    const std::string s = join_names(iface->samplers);
    if (es2) out->push_back({"OES_texture_float", {}, "samples " + s + ": the bundle's textures are RGBA32F (docs/bundles.md)"});
    out->push_back({"OES_texture_float_linear", {},
                    "samples " + s + ": RGBA32F textures filtered with GL_LINEAR (glTF samplers other than NEAREST)"});
  }
  if (linear_output(v)) {
    if (es2)
      out->push_back({"WEBGL_color_buffer_float",
                      {"EXT_color_buffer_half_float", "EXT_sRGB"},
                      "writes linear values: a float colour target keeps them (RGBA32F, the replay's; RGBA16F with "
                      "EXT_color_buffer_half_float), or an sRGB RGBA8 target encodes them (EXT_sRGB; docs/tiers.md)"});
    else
      out->push_back({"EXT_color_buffer_float",
                      {"SRGB8_ALPHA8 (core)"},
                      "writes linear values: a float colour target keeps them (RGBA32F, the replay's), or a core "
                      "SRGB8_ALPHA8 target encodes them"});
  }
  bool mesh = false;
  for (const auto &a : iface->attributes) mesh = mesh || a.name == "a_position";
  if (es2 && mesh)
    out->push_back({"OES_element_index_uint", {}, "a mesh draw: the draw dumps' indices are 32-bit (docs/bundles.md)"});
  return true;
}

bool target_offers(const Variant &v, Target target, bool *offered, std::string *why_not, std::string *err) {
  if (!v.shader->has_target(target_name(target))) {
    *offered = false;
    *why_not = std::string("the shader has no ") + target_name(target) + " program (its .variants 'targets')";
    return true;
  }
  std::vector<ExtensionNeed> needs;
  if (!variant_extensions(v, target, nullptr, &needs, err)) return false;
  *offered = true;
  why_not->clear();
  for (const auto &n : needs)
    if (extension_unavailable(target, n.name) && n.alternatives.empty()) {
      *offered = false;
      *why_not = n.why;
    }
  return true;
}
