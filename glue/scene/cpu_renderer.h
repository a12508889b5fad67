// tiershade scene: scene frames in C. The C fallback rasterises the draws itself (vertex
// stage, near-plane clipping, 8-bit sub-pixel edge functions with the top-left rule,
// perspective-correct interpolation, depth test LESS) into a small visibility buffer (draw,
// triangle, barycentrics), then shades each visible pixel once with the bit-exact C twin
// of its draw's variant, on every core. The same shading runs on GL's own G-buffer records
// (glue/scene/gl_renderer.h), which is how the C twin is checked against a GL scene frame bit for bit.
#pragma once
#include <cstdint>
#include <functional>
#include <vector>

#include "base/image.h"
#include "scene/prepare.h"

// A buffer passed again at the same size is reused (reset by the rasteriser's bands, not
// reallocated).
struct SceneVisibility {
  int w = 0, h = 0;
  std::vector<int32_t> draw, tri;  // -1: background
  // Which of the triangles llvmpipe draws for tri covers the pixel (LpTriSet's index,
  // glue/scene/lp_interp.h); empty: found by lp_covering.
  std::vector<uint8_t> sub;
  std::vector<float> b1, b2;  // perspective-correct barycentrics of vertices 1 and 2
  std::vector<float> depth;  // llvmpipe's 24-bit depth values, as floats (lp_depth24_span)
  // true (set by scene_rasterize_cpu): pixel i of the buffer is the pixel (i % w, i / w), so
  // that a triangle llvmpipe draws unclipped is interpolated with llvmpipe's plane equations
  // there (glue/scene/lp_interp.h); false (e.g. MSAA's fragment layers): from b1, b2 alone.
  bool pixel_planes = false;
  // With pixel_planes, when not empty (MSAA's fragment layers, glue/scene/msaa.cpp): the frame
  // pixel (y * w + x) whose centre record i is interpolated at, instead of pixel i.
  std::vector<int32_t> at;
};

// Rasterises every draw (threads: 0 = all cores).
void scene_rasterize_cpu(const PreparedScene &p, SceneVisibility *vis, int threads = 0);

// Shades a visibility buffer: the C fallback's frame (RGBA32F, background 0).
// progress (optional) is called with the fraction of rows done.
void scene_shade_cpu(const PreparedScene &p, const SceneVisibility &vis, ImageF *out, int threads = 0,
                     const std::function<void(double)> &progress = nullptr);

// The lit pass in bands of rows (tiles as wide as the frame): each worker rasterises a band
// into a band-sized visibility buffer and shades it at once, the same pixels with the same bits
// as scene_rasterize_cpu then scene_shade_cpu, without a frame-sized visibility buffer; the
// draws' vertex outputs and set-up triangles held a slab of bands at a time (band_slabs.h).
// linear (optional): per pixel 1 where it holds a linear value (its draw is not display-encoded,
// or it is background and the scene has a skybox), else 0: what the integer path's post encodes.
void scene_render_cpu(const PreparedScene &p, ImageF *out, std::vector<uint8_t> *linear, int threads = 0,
                      const std::function<void(double)> &progress = nullptr);
// The slabs' budget in bytes (0: the default, 2 bytes a pixel or 8 MiB), for the tests.
void scene_cpu_band_budget(size_t bytes);
// Tests only: every band of scene_render_cpu is shaded without the barycentrics, then found to
// need them at its last row and rasterised and shaded again with them (the path a band takes
// when a pixel is not interpolated with llvmpipe's planes).
void scene_render_cpu_force_redo(bool on);

// Shades GL's G-buffer (per pixel draw index and 6 slots, glue/scene/gl_renderer.h) with the C twin;
// grads (4 floats a pixel, SceneGl::gbuffer's or scene_records_cpu's): the uv's quad derivatives,
// for the level of detail of mipmapped textures (none: every texture's level 0).
void scene_shade_records(const PreparedScene &p, const std::vector<int> &draw, const std::vector<float> &slots,
                         ImageF *out, int threads = 0, const std::vector<float> *grads = nullptr);

// The C fallback's G-buffer: per pixel the draw index (-1 background) and the 6 pixel slots
// (24 floats, every slot, interpolated as scene_shade_cpu interpolates them), the same layout
// as SceneGl::gbuffer, for scene_shade_records and scene_reference_linear.
void scene_records_cpu(const PreparedScene &p, const SceneVisibility &vis, std::vector<int> *draw,
                       std::vector<float> *slots, int threads = 0, std::vector<float> *grads = nullptr);
