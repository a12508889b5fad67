// tiershade families: a family's input record layout as read from its slot table
// (shaders/<family>_slots.glsl, row format in shaders/ts_slot_table.glsl): the slot names and
// the production uniforms of deferred frames, generated from the rows instead of written again.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "gl/fns.h"
#include "math/ts_math.h"

// How a run of slots is named (the `naming` column).
enum class SlotNaming {
  one,  // name (a run of one slot)
  cube_faces,  // name+x name-x name+y name-y name+z name-z
  light_parts,  // name0.color name0.dir name0.pos name0.spot name0.atten name1.color ... (TsLight)
};

struct SlotRow {
  int first, count;
  const char *name;
  SlotNaming naming;
  const char *source;  // production uniform (or, per pixel, the varying/texture)
};

// Turns a table row into a SlotRow. A family file gets its table as `kSlotRows` from
// families/slot_rows.inc (and names it in its RecordLayout, families/record_family.h).
#define TS_SLOT_ROW(ID, first, count, name, naming, source) {first, count, #name, SlotNaming::naming, #source},

// Slots per element of a naming (0: any count).
constexpr int slot_naming_period(SlotNaming n) {
  return n == SlotNaming::cube_faces ? 6 : n == SlotNaming::light_parts ? 5 : 1;
}

// The rows are in slot order with no gap or overlap, cover [0, slots), no row straddles the
// per-pixel boundary, and each row's count suits its naming. Checked by a static_assert for
// every family (families/record_family.h: family_of), so a table edit that breaks the layout
// does not compile.
constexpr bool slot_rows_valid(const SlotRow *rows, size_t n, int slots, int pixel_slots) {
  int next = 0;
  for (size_t i = 0; i < n; ++i) {
    const SlotRow &r = rows[i];
    if (r.first != next || r.count < 1) return false;
    if (r.first < pixel_slots && r.first + r.count > pixel_slots) return false;
    if (r.count % slot_naming_period(r.naming) != 0) return false;
    if (r.naming == SlotNaming::one && r.count != 1) return false;
    next = r.first + r.count;
  }
  return next == slots && pixel_slots >= 0 && pixel_slots <= slots;
}

// One name per slot, in slot order.
std::vector<std::string> slot_names_of(const SlotRow *rows, size_t n);

// Deferred frames: sets each shared row's uniform (vec4 or vec4 array) from `shared`; rows below
// pixel_slots are per pixel and skipped. A uniform the program does not use is skipped too.
void bind_slot_uniforms(const GlFns &gl, GLuint program, const std::vector<ts_vec4f> &shared, const SlotRow *rows,
                        size_t n, int pixel_slots);
