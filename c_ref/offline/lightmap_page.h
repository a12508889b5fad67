/* tiershade offline: the engine's lightmap page layout (fact sheet section 1,
 * lightmappedgeneric_vs20.fxc): the lightmaps of a bumped face sit side by side,
 * flat first, then the ones along b0, b1, b2, and the shader finds lightmap k at
 * uv + k * offset with offset = (block width / page width, 0). Each block has a
 * one-texel border (a copy of its edge) so bilinear filtering never reads the
 * neighbouring block. Faces are packed in shelves, left to right, top to bottom; when a page
 * is full, on the next page. The pages are stacked: page k's rows follow page k - 1's in one
 * page_w x (pages * page_h) array, so a texel's row is k * page_h + its row in the page. */
#ifndef TS_LIGHTMAP_PAGE_H
#define TS_LIGHTMAP_PAGE_H
#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct {
  int luxels_w, luxels_h; /* lightmap samples of the face, >= 2 each */
  int bumped; /* 1: four lightmaps (flat, b0, b1, b2); 0: the flat one only */
} lm_face_size;

typedef struct {
  int x, y; /* top-left texel of the face's first block (its border included), y in the stacked pages */
  int page; /* the page holding it (y / page_h) */
  int block_w, block_h; /* luxels + 2 */
  int count; /* 4 or 1 lightmaps */
  float offset[2]; /* uv offset from one lightmap of the face to the next */
} lm_face_place;

/* Packs the faces into a page_w x page_h page. Returns 0, or -1 with a message naming
 * the face when a size is out of range or the page is full. */
int lm_page_pack(int page_w, int page_h, const lm_face_size *faces, int n, lm_face_place *out, char *err,
                 size_t errlen);

/* The same on up to max_pages pages (>= 1): a face that does not fit the rest of a page starts
 * the next one. *pages receives the pages used (at least 1). Returns 0, or -1 with a message naming
 * the face when a size is out of range, a face does not fit an empty page, or max_pages are full. */
int lm_page_pack_pages(int page_w, int page_h, int max_pages, const lm_face_size *faces, int n, lm_face_place *out,
                       int *pages, char *err, size_t errlen);

/* The texel of luxel (i, j) of lightmap k (0 = flat) of a placed face. */
void lm_page_texel(const lm_face_place *p, int k, int i, int j, int *tx, int *ty);

/* The lightmap uv (of the flat lightmap, k = 0) of face point (a, b) in [0, 1]^2: a = 0
 * and 1 are the centres of the first and last luxel columns. */
void lm_page_uv(const lm_face_place *p, int page_w, int page_h, double a, double b, float uv[2]);

/* The lightmap uv (k = 0) of TEXCOORD_1 point (u, v) in [0, 1]^2 of a chart's block
 * (glue/bake/charts.h): luxel i spans u in [i, i + 1) / luxels_w, so u maps to texel
 * x + 1 + u * luxels_w of the page. */
void lm_page_chart_uv(const lm_face_place *p, int page_w, int page_h, double u, double v, float uv[2]);

/* A face's luxels as a BSP stores them for one light style (fact sheet section 1,
 * PrecompLightmapOffsets/FinalLightFace): `count` blocks one after another (flat, then b0,
 * b1, b2 for a bumped face), each luxels_w * luxels_h ColorRGBExp32 values, row by row (s
 * fastest; the row order is INFERRED, the fact sheet gives only the block offsets). Decodes
 * them (TexLightToLinear, c 2^e / 255) into the float32 page (rgb; alpha set to 1) at the
 * face's place and fills its borders. `rgbe` holds 4 bytes per luxel: r, g, b, exponent. */
void lm_page_put_bsp_face(const lm_face_place *p, int page_w, const unsigned char *rgbe, float *rgba);

/* Copies each block's edge luxels into its border (RGBA32F page, rows in GL order). */
void lm_page_fill_borders(const lm_face_place *p, int page_w, float *rgba);

#ifdef __cplusplus
}
#endif
#endif
