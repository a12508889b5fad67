// tiershade scene: the banded lit pass's slabs (scene_render_cpu, glue/scene/cpu_renderer.cpp): runs
// of bands whose live draws (vertex outputs and set-up triangles) fit a memory budget, so that a
// scene of many draws holds a slab's draws at a time instead of every draw's (docs/rendering.md,
// "Memory"). One slab: every draw's vertex stage and set-up at once. Several: a draw's vertex
// stage runs once, when its first slab starts (its outputs freed after its last), its triangles
// are set up per slab, those whose rows reach the slab.
#pragma once
#include <cstddef>
#include <vector>

#include "scene/prepare.h"

struct BandSlabs {
  std::vector<int> first_band;  // slab s: bands first_band[s] .. first_band[s + 1] - 1
  // Per draw: its first and last slab (first -1: off the frame, never processed).
  std::vector<int> draw_first, draw_last;
  size_t peak_bytes = 0;  // the largest slab's estimated bytes
};

// The bytes one draw holds while live: its vertex outputs and (an estimate: one set-up triangle
// an index triple) its set-up triangles; tri_bytes = sizeof(ScreenTri).
size_t band_draw_bytes(const PreparedDraw &d, size_t tri_bytes);

// The slabs of p's frame in bands of `band` rows. Every draw's bytes summed within `budget`:
// one slab of every draw (no pass over the clip positions). Else each draw's window rows are
// bounded from its clip positions (every vertex in front of the eye: the rows of their window
// positions, lp_window_pos, widened by 2 rows, which hold every triangle llvmpipe draws for it;
// else every row) and bands are added to a slab while its live draws' bytes stay within budget
// (a slab has at least a band a worker, whatever its draws take): a draw's vertex outputs, clip
// positions and triangle rows while its bands last, its set-up triangles spread over its bands.
BandSlabs plan_band_slabs(const PreparedScene &p, int band, size_t budget, size_t tri_bytes, int threads);

// Per triangle of draw di (clip: its clip positions, scene_clip_stage's), the rows that hold every
// triangle llvmpipe draws for it, packed y0 | y1 << 16 (y0 > y1: none): with its three vertices
// in front of the eye and finite, the rows of their window y widened by 2 (as for a draw above);
// else every row.
void triangle_rows(const PreparedScene &p, int di, const std::vector<float> &clip, std::vector<float> *win_y,
                   std::vector<uint32_t> *rows);
inline bool rows_reach(uint32_t r, int y0, int y1) {
  return static_cast<int>(r & 0xffffu) <= y1 && static_cast<int>(r >> 16) >= y0;
}
