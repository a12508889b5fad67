// tiershade scene: the C fallback's shading of visibility rows, shared by its passes
// (glue/scene/cpu_renderer.cpp: the two passes, G-buffer records; band_pass.cpp: the banded lit
// pass): per draw the twin's variant and views, llvmpipe's plane set-ups cached per worker, a row's
// visibility, and shade_row. Private to glue/scene's C fallback.
#pragma once
#include <cstdint>
#include <vector>

#include "scene/lp_interp.h"
#include "scene/prepare.h"
#include "twins/model_lighting.h"
#include "twins/world_lighting.h"

// Per draw: the twin's variant, texture views and the record's shared slots.
struct DrawCtx {
  bool world = false;
  ml_variant ml;
  wl_variant wl;
  ts_tex2d t2[4];
  ts_texcube cube;
  ml_textures mt;
  wl_textures wt;
  std::vector<ts_vec4f> rec;  // shared slots (pixel slots overwritten per pixel)
  // The pixel slots the variant reads (world_lighting_impl.h: the normal, tangent, binormal
  // and eye vectors only for ENVMAP, the tangent frame only with a bump map); the others are
  // not interpolated.
  int used[6];
  int nused = 0;
  // A texture the variant samples at the uv has a mip chain: the pixels get their quad's uv
  // derivatives (uv_grad_run) for llvmpipe's level of detail.
  bool mips = false;
  int uv_slot = 0;
};

void make_ctx(const PreparedScene &p, std::vector<DrawCtx> *out);

// A worker's set-ups of the triangles it interpolated last (llvmpipe's, glue/scene/lp_interp.h),
// direct-mapped by triangle: the rows of a small triangle meet it again and again.
struct PlaneCache {
  struct Entry {
    int draw = -1, tri = -1;
    LpTriSet set;
  };
  static const unsigned kEntries = 64;
  std::vector<Entry> e = std::vector<Entry>(kEntries);
  Entry &at(int draw, int tri) {
    return e[(static_cast<unsigned>(tri) * 2654435761u + static_cast<unsigned>(draw)) % kEntries];
  }
};

// One row's visibility (pointers to its first pixel; at: MSAA's layers, else nullptr).
struct RowVis {
  const int32_t *draw, *tri;
  const uint8_t *sub;  // nullptr: found by lp_covering
  const float *b1, *b2;
  const int32_t *at;
};

// Shades row y of the frame into orow (RGBA floats): runs of pixels of one draw are shaded together
// by the batched twins (8 pixels per instruction where the host has AVX2; the same bits as one
// pixel at a time). in_group (nullptr: every draw): the draws shaded by this pass; first: the
// background (draw < 0) is written as 0 here; planes: interpolated with llvmpipe's planes. False
// when a pixel needs the rasteriser's barycentrics and r has none (r.b1 == nullptr): the row is
// not finished.
bool shade_row(const PreparedScene &p, const std::vector<DrawCtx> &ctx, const std::vector<std::vector<float>> &vary,
               const char *in_group, bool first, bool planes, int y, const RowVis &r, std::vector<ts_vec4f> &pix,
               PlaneCache *cache, float *orow);
