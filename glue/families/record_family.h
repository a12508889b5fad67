// tiershade families: one definition of the scaffolding every family file shared (record
// gathering, input generation, slot names, deferred uniforms, the ShaderFamily itself); a family
// file gives only its own parts: its slot table, its random record, its textures, its twin.
#pragma once
#include <cstddef>
#include <type_traits>

#include "families/family.h"
#include "families/hard_cases.h"
#include "families/slot_table.h"

// Allowed output ranges shared by the families (ShaderFamily::output_range).
void output_range_half(const Variant &v, float *lo, float *hi);  // [0, 65504]: an fp16 target
void output_range_unit(const Variant &v, float *lo, float *hi);  // [0, 1]: saturated (8-bit display)
void output_range_by_output_mode(const Variant &v, float *lo, float *hi);  // OUTPUT_MODE 0: half, else unit

// What is data about a family: its name, record size, slot table (shaders/<family>_slots.glsl,
// included by the family file) and output range. A family file declares it constexpr:
//   constexpr RecordLayout kLayout = {"bloom_blur", BB_SLOTS, BB_PIXEL_SLOTS, kSlotRows, ..., output_range_half};
struct RecordLayout {
  const char *name;
  int slots, pixel_slots;
  const SlotRow *rows;
  size_t row_count;
  void (*output_range)(const Variant &v, float *lo, float *hi);
};

// The twin of a family without textures takes (variant, record): its ViewsOf returns this.
struct NoTextures {};
inline NoTextures no_textures(const FamilyInputs &) { return {}; }
inline void clear_textures(Rng &, InputSet, FamilyInputs *out) { out->textures.clear(); }
// The single 2D texture of the bloom and tone-map families (make_inputs' textures[0]).
inline ts_tex2d first_tex2d(const FamilyInputs &in) { return tex2d_of(in.textures.at(0)); }

// Pixel (x, y)'s record through a twin: Twin(&VariantOf(v), rec[, &ViewsOf(in)]) where Twin is the
// family's NAME_f or NAME_d (c_ref/twins/NAME.h).
template <const RecordLayout &L, auto VariantOf, auto ViewsOf, auto Twin>
auto eval_twin(const Variant &v, const FamilyInputs &in, int x, int y) {
  ts_vec4f rec[L.slots];
  in.gather(x, y, L.slots, rec);
  const auto &m = VariantOf(v);
  const auto &t = ViewsOf(in);
  if constexpr (std::is_same<std::decay_t<decltype(t)>, NoTextures>::value)
    return Twin(&m, rec);
  else
    return Twin(&m, rec, &t);
}

// make_inputs: the records of fill_record_grid (RandomPixel(r, set, rec) for each pixel, then the
// hard cases of tests/conform/<name>.cases on the hard set), then Textures(r, set, out) from the
// same generator.
template <const RecordLayout &L, auto RandomPixel, auto Textures>
void record_inputs(InputSet set, int w, int h, uint32_t seed, FamilyInputs *out) {
  Rng r(seed);
  fill_record_grid(
      L.name, set, w, h, L.slots, r, [&](ts_vec4f *rec) { RandomPixel(r, set, rec); }, out);
  Textures(r, set, out);
}

template <const RecordLayout &L>
void bind_layout_uniforms(const GlFns &gl, GLuint program, const std::vector<ts_vec4f> &shared) {
  bind_slot_uniforms(gl, program, shared, L.rows, L.row_count, L.pixel_slots);
}

// The ShaderFamily of layout L; a table that breaks the rules of slot_rows_valid does not compile.
template <const RecordLayout &L>
ShaderFamily family_of(decltype(ShaderFamily::make_inputs) make_inputs, decltype(ShaderFamily::eval_f) eval_f,
                       decltype(ShaderFamily::eval_d) eval_d, decltype(ShaderFamily::eval_row_f) eval_row_f = nullptr) {
  static_assert(slot_rows_valid(L.rows, L.row_count, L.slots, L.pixel_slots),
                "the family's shaders/<family>_slots.glsl breaks the row rules of families/slot_table.h");
  return {L.name,         L.slots,       slot_names_of(L.rows, L.row_count),
          make_inputs,    eval_f,        eval_d,
          L.output_range, L.pixel_slots, bind_layout_uniforms<L>,
          eval_row_f};
}

// A family whose twin is a pure function of (variant, record[, texture views]).
template <const RecordLayout &L, auto VariantOf, auto ViewsOf, auto TwinF, auto TwinD, auto RandomPixel, auto Textures>
ShaderFamily twin_family() {
  return family_of<L>(record_inputs<L, RandomPixel, Textures>, eval_twin<L, VariantOf, ViewsOf, TwinF>,
                      eval_twin<L, VariantOf, ViewsOf, TwinD>);
}
