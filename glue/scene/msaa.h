// tiershade scene: MSAA on the integer HDR path (talk: the integer path is "compatible with
// MSAA", "32-bit RGBA render targets"; the float path "requires floating-point alpha blending"
// and has no MSAA on that hardware). What a multisampled frame may be (msaa_refusal), the
// sample patterns (llvmpipe's lp_sample_pos_4x for 4; the standard D3D/Vulkan 2x and 8x
// patterns, which llvmpipe lacks, for the C fallback), the resolve as llvmpipe's blit does it
// for RGBA8, and the C fallback's multisampled frame: its rasteriser tests coverage and depth
// at every sample, shades each triangle once per pixel at the pixel centre (no sample shading,
// no centroid: llvmpipe interpolates at the centre), stores RGBA8 codes per sample and resolves.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "gl/context.h"
#include "scene/prepare.h"

// Sample offsets of an n-sample pattern (n = 2, 4, 8) in pixels from the pixel's corner of
// lowest x and y (GL window coordinates), or nullptr for another n.
const float (*msaa_pattern(int n))[2];

// Empty if a frame of p may be multisampled with `samples` (> 1) on this path and backend;
// else why not (the float path; GLES 2.0; a draw whose output the integer path encodes on
// the host, which a multisampled RGBA8 target cannot: ps20 and world draws write linear colour).
std::string msaa_refusal(const PreparedScene &p, bool float_path, bool cpu, Api api, int samples);

// llvmpipe's resolve of one RGBA8 channel over n samples (stride bytes apart): the codes as
// floats (c / 255), summed in sample order, times 1 / n in float, stored as unorm8 (round to
// nearest: ts_unorm8_from_float). Equal codes resolve to themselves.
uint8_t msaa_resolve_unorm8(const uint8_t *codes, int n, int stride);

// The C fallback's multisampled frame of p (every draw display-encoded, msaa_refusal empty).
struct MsaaFrameC {
  int w = 0, h = 0, samples = 0;
  std::vector<uint8_t> display;  // resolved RGBA8 codes, rows bottom-up (alpha as resolved)
  // 1 where one triangle covers every sample of the pixel robustly (each sample inside each
  // edge by at least the edge's change when its vertices move 2/256 pixel in x and y): pixels
  // another rasteriser's snapping and tie rules cannot turn into edge pixels.
  std::vector<uint8_t> interior;
  // 1 where the samples hold background and a triangle, or triangles of two draws: the pixels
  // of silhouettes and draw boundaries (geometric edges, what MSAA is for).
  std::vector<uint8_t> silhouette;
  size_t sample_bytes = 0;  // the per-sample buffers' bytes (codes, depth, triangle)
};
void scene_render_msaa_cpu(const PreparedScene &p, int samples, MsaaFrameC *out, int threads = 0);

// --check with MSAA: GL's resolved frame against the C twin shaded on GL's own G-buffer drawn
// with the multisampled state (SceneGl::gbuffer_msaa: sample 0's records, interpolated at the
// pixel centre by the same multisample shader variant) on interior pixels (MsaaFrameC::interior),
// where every sample holds that one fragment: any difference is a shading or resolve mismatch
// (tolerance 0). On the other (edge) pixels GL's frame is compared with the C fallback's
// multisampled frame: there the two rasterisers' coverage and interpolation differ.
struct MsaaCheck {
  long interior = 0, interior_mismatched = 0;  // pixels (RGB compared)
  long background = 0, background_mismatched = 0;  // no sample covered in either frame
  long edge = 0, edge_over_1 = 0, edge_over_64 = 0;  // edge pixels; channel differences beyond 1 / 64 codes
  int edge_max = 0, interior_max = 0;
};
void msaa_compare(const std::vector<uint8_t> &gl_resolved, const std::vector<uint8_t> &twin_codes,
                  const MsaaFrameC &cfb, MsaaCheck *out);
