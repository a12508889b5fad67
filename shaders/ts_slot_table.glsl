//------------------------------------------------------------------------------
// ts_slot_table.glsl: how a shader reads a family's slot table (shaders/<family>_slots.glsl).
// A table is one row per slot, or per run of slots that one uniform array holds:
//   TS_SLOT(ID, first, count, name, naming, source)
//     ID      the index constant (GLSL int constant, C enum member)
//     first   its slot index; rows are in slot order and leave no gap (checked when the
//             glue compiles: glue/families/slot_table.h)
//     count   slots in the row (a uniform array: the array length)
//     name    slot name for conform reports, probe --set and --input files; naming says how a
//             run of slots is named: one (name), cube_faces (name+x name-x ... name-z),
//             light_parts (name0.color name0.dir name0.pos name0.spot name0.atten name1.color ...)
//     source  where the production shader takes the value: the uniform the glue sets in
//             deferred frames (bind_uniforms), or for per-pixel slots (first < *_PIXEL_SLOTS)
//             the varying or texture, for the reader only
// Each includer defines TS_SLOT its own way before including the table: the C twin's enum
// (c_ref/twins/<family>.h), the glue's row array (glue/families/<family>.cpp). A shader
// defines nothing and gets the definition below: each ID an int constant. Counts such as
// *_SLOTS, *_PIXEL_SLOTS, ML_MAX_LIGHTS are plain #defines in the table, the same text in
// GLSL and C. GLSL has no string literals, so names are identifiers (C stringifies them).
//------------------------------------------------------------------------------
#ifndef TS_SLOT
#define TS_SLOT(ID, first, count, name, naming, source) const int ID = first;
#endif
