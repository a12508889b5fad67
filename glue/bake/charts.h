// tiershade bake: lightmap charts from a mesh's TEXCOORD_1 (the glTF convention for lightmap UVs):
// the primitive's [0, 1]^2 UV square becomes a w x h block of luxels at the scene's luxel density
// (luxel i spans u in [i, i + 1) / w, its centre at (i + 0.5) / w), each luxel mapped to the triangle
// that covers its centre (barycentric: position, normal, tangent frame and bumped basis), else, for
// a luxel a triangle only grazes, to that triangle's point nearest the centre ("conservative"
// coverage: every texel a triangle touches is lit, so one ring of dilation covers every texel that
// bilinear filtering reads inside a triangle; docs/baking.md, "Charts"). Bad geometry is an error
// naming the primitive and triangle: out-of-range or overlapping UVs, degenerate triangles.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "bake/content_hash.h"
#include "math/ts_math.h"

// The geometry a luxel is baked at: a point, the unit front normal and the bumped basis b0, b1, b2
// in world space (c_ref/offline/rnm_bake.h rnm_bump_basis of the luxel's tangent frame).
struct LuxelFrame {
  ts_vec3d p, n, bump[3];
  bool lit = false;  // false: no triangle touches the luxel (it holds no light; dilation fills it)
};

struct WorldChart {
  int w = 0, h = 0;  // luxels of the block (the UV square)
  std::vector<double> pos, nrm, tan, uv;  // per triangle corner: 3, 3, 4 (w: handedness), 2
  std::vector<float> vertex_tangent;  // per vertex of the primitive (4): the frame the bake used
  std::vector<int> luxel_tri;  // per luxel (j * w + i): its triangle, -1 none
  // Per luxel, the triangles that overlap it: cand[cand_at[l] .. cand_at[l + 1]) (chart_frame_at's search).
  std::vector<int> cand_at, cand;
  std::vector<LuxelFrame> frame;  // per luxel
  std::string where;  // the primitive, for messages
  int triangles() const { return static_cast<int>(uv.size() / 6); }
  const LuxelFrame &at(int i, int j) const { return frame[static_cast<size_t>(j) * w + i]; }
};

// Adds what a chart bakes from to a content hash (glue/bake/content_hash.h; the bake directory's
// staleness check): its size, the corners' positions, normals, tangents and UVs (the luxels' frames
// follow from them).
void chart_hash(ContentHash *h, const WorldChart &c);

// Luxels along one axis of a chart whose UV square spans `units` scene units at `per_unit` luxels per
// unit: lround(units * per_unit), at least 2.
int chart_luxels(double units, double per_unit);

// A chart from a primitive (world positions xyz, normals xyz, tangents xyzw or empty, TEXCOORD_1 uv,
// triangles). The UV square spans sqrt(world area / UV area) scene units (the mean scale of the
// mapping). False with a message naming `where` and the triangle for: a TEXCOORD_1 outside [0, 1], a
// triangle of zero area in space or in UV, two triangles overlapping in UV (tested at 4 x 4 points
// per luxel: an overlap smaller than a sixteenth of a luxel passes, it changes no luxel by more than
// its area share). The front is the side the vertex normals face (a zero normal: the winding's).
bool chart_build(const std::vector<float> &position, const std::vector<float> &normal,
                 const std::vector<float> &tangent, const std::vector<float> &uv1, const std::vector<uint32_t> &indices,
                 double luxels_per_unit, const std::string &where, WorldChart *out, std::string *err);

// The frame at chart point (u, v), strictly inside a luxel: the first of the luxel's triangles whose
// closed UV triangle holds it, interpolated barycentrically. False (*f untouched) when none holds it.
bool chart_frame_at(const WorldChart &c, double u, double v, LuxelFrame *f);

// The grid coordinates (a, b) = (i / (w - 1), j / (h - 1)) of the luxel holding the point of
// triangle `tri` at barycentrics (bu, bv) of its corners 1 and 2 (a ray hit, glue/bake/ray_scene.h):
// a lookup there reads that luxel alone (every luxel a triangle touches is lit).
void chart_hit_ab(const WorldChart &c, int tri, double bu, double bv, double *a, double *b);

// Dilation of one lightmap block (RGBA32F page, rows of page_w texels; the block's w x h luxels at
// (x0, y0), `lit` per luxel, and a one-texel border around it): `rings` times, every unlit texel of
// the block and its border with a lit 8-neighbour takes the mean of those neighbours and counts as
// lit for the next ring. `lit_out` (optional, (w + 2) x (h + 2), border included) receives the final
// mask.
// The rings world_bake dilates: one covers every texel bilinear filtering reads inside a triangle
// (each is an 8-neighbour of a touched, hence lit, texel); the second keeps a mip or a
// half-texel-offset read clean as well.
const int kChartDilateRings = 2;
void chart_dilate(float *rgba, int page_w, int x0, int y0, int w, int h, const std::vector<int> &lit, int rings,
                  std::vector<int> *lit_out);
