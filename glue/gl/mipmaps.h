// tiershade gl: mip chains of 2D textures (scene materials, conformance textures), built on the
// host so that GL and the C twins sample identical texels (docs/rendering.md, "Mipmaps"). Scene
// texels are already linear (colour images are sRGB-decoded at load, glue/scene/prepare.cpp), so
// a box filter here is filtering in linear light; a normal map is decoded, averaged, renormalised
// and encoded again per level, so that no level shortens its normals (the alpha mask is averaged).
#pragma once
#include "gl/float_target.h"

enum class MipContent { Color, NormalMap };

// Levels 1 .. n - 1 of t (level 0: t.rgba) into t.mips: each max(1, size >> k) a side, down to
// 1 x 1 (a complete chain, as GL's mipmap completeness asks); texel (x, y) of a level is the mean
// of texels (2x .. 2x + 1, 2y .. 2y + 1) of the level above, clamped to its edge (an odd side
// drops its last row or column from the next level, as a 2x2 box generator does), summed in
// double.
void build_mip_chain(TextureDesc *t, MipContent content);

// A texture of more levels (a side beyond 32768 texels) keeps one level: the C sampler's chain
// holds at most this many (TS_MAX_MIP_LEVELS, c_ref/math/ts_sampler.h).
const int kMaxMipLevels = 16;

// The number of levels of a complete chain for a w x h level 0.
int mip_level_count(int w, int h);
