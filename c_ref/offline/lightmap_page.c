/* tiershade offline: lightmap page packing and addressing (see lightmap_page.h). */
#include "offline/lightmap_page.h"

#include "offline/lightmap_encoding.h"

#include <stdio.h>
#include <string.h>

int lm_page_pack(int page_w, int page_h, const lm_face_size *faces, int n, lm_face_place *out, char *err,
                 size_t errlen) {
  int pages;
  return lm_page_pack_pages(page_w, page_h, 1, faces, n, out, &pages, err, errlen);
}

int lm_page_pack_pages(int page_w, int page_h, int max_pages, const lm_face_size *faces, int n, lm_face_place *out,
                       int *pages, char *err, size_t errlen) {
  if (page_w < 1 || page_h < 1 || page_w > 16384 || page_h > 16384 || n < 0 || max_pages < 1 || max_pages > 256) {
    snprintf(err, errlen, "lm_page_pack: page %dx%d (up to %d) with %d faces", page_w, page_h, max_pages, n);
    return -1;
  }
  int x = 0, y = 0, shelf_h = 0, page = 0;
  *pages = 1;
  for (int f = 0; f < n; ++f) {
    const lm_face_size *s = &faces[f];
    if (s->luxels_w < 2 || s->luxels_h < 2 || s->luxels_w > 1024 || s->luxels_h > 1024) {
      snprintf(err, errlen, "lm_page_pack: face %d has %dx%d luxels (2..1024 each)", f, s->luxels_w, s->luxels_h);
      return -1;
    }
    lm_face_place *p = &out[f];
    memset(p, 0, sizeof *p);
    p->block_w = s->luxels_w + 2;
    p->block_h = s->luxels_h + 2;
    p->count = s->bumped ? 4 : 1;
    const int w = p->block_w * p->count;
    if (x + w > page_w) { /* next shelf */
      x = 0;
      y += shelf_h;
      shelf_h = 0;
    }
    if (w <= page_w && y + p->block_h > page_h && page + 1 < max_pages && p->block_h <= page_h) {
      ++page; /* the next page */
      x = y = shelf_h = 0;
    }
    if (w > page_w || y + p->block_h > page_h) {
      if (max_pages > 1 && w <= page_w && p->block_h <= page_h)
        snprintf(err, errlen, "lm_page_pack: face %d (%dx%d luxels, %d lightmaps) does not fit in %d pages of %dx%d", f,
                 s->luxels_w, s->luxels_h, p->count, max_pages, page_w, page_h);
      else
        snprintf(err, errlen, "lm_page_pack: face %d (%dx%d luxels, %d lightmaps) does not fit in the %dx%d page", f,
                 s->luxels_w, s->luxels_h, p->count, page_w, page_h);
      return -1;
    }
    p->x = x;
    p->y = page * page_h + y;
    p->page = page;
    if (page + 1 > *pages) *pages = page + 1;
    p->offset[0] = (float)((double)p->block_w / page_w);
    p->offset[1] = 0.0f;
    x += w;
    if (p->block_h > shelf_h) shelf_h = p->block_h;
  }
  return 0;
}

void lm_page_texel(const lm_face_place *p, int k, int i, int j, int *tx, int *ty) {
  *tx = p->x + k * p->block_w + 1 + i;
  *ty = p->y + 1 + j;
}

void lm_page_uv(const lm_face_place *p, int page_w, int page_h, double a, double b, float uv[2]) {
  const double lw = p->block_w - 2, lh = p->block_h - 2;
  uv[0] = (float)((p->x + 1 + 0.5 + a * (lw - 1)) / page_w);
  uv[1] = (float)((p->y - p->page * page_h + 1 + 0.5 + b * (lh - 1)) / page_h);
}

void lm_page_chart_uv(const lm_face_place *p, int page_w, int page_h, double u, double v, float uv[2]) {
  uv[0] = (float)((p->x + 1 + u * (p->block_w - 2)) / page_w);
  uv[1] = (float)((p->y - p->page * page_h + 1 + v * (p->block_h - 2)) / page_h);
}

void lm_page_fill_borders(const lm_face_place *p, int page_w, float *rgba) {
  for (int k = 0; k < p->count; ++k) {
    const int x0 = p->x + k * p->block_w, y0 = p->y, w = p->block_w, h = p->block_h;
    for (int y = y0; y < y0 + h; ++y) {
      for (int x = x0; x < x0 + w; ++x) {
        int sx = x, sy = y;
        if (sx == x0) sx = x0 + 1;
        if (sx == x0 + w - 1) sx = x0 + w - 2;
        if (sy == y0) sy = y0 + 1;
        if (sy == y0 + h - 1) sy = y0 + h - 2;
        if (sx != x || sy != y)
          memcpy(&rgba[((size_t)y * page_w + x) * 4], &rgba[((size_t)sy * page_w + sx) * 4], 4 * sizeof(float));
      }
    }
  }
}

void lm_page_put_bsp_face(const lm_face_place *p, int page_w, const unsigned char *rgbe, float *rgba) {
  const int lw = p->block_w - 2, lh = p->block_h - 2;
  for (int k = 0; k < p->count; ++k) {
    for (int j = 0; j < lh; ++j) {
      for (int i = 0; i < lw; ++i) {
        const unsigned char *c = &rgbe[(((size_t)k * lh + j) * lw + i) * 4];
        ts_rgbe v;
        double lin[3];
        v.r = c[0];
        v.g = c[1];
        v.b = c[2];
        v.exponent = (signed char)c[3];
        ts_rgbe_decode(v, lin);
        int tx, ty;
        lm_page_texel(p, k, i, j, &tx, &ty);
        float *t = &rgba[((size_t)ty * page_w + tx) * 4];
        t[0] = (float)lin[0];
        t[1] = (float)lin[1];
        t[2] = (float)lin[2];
        t[3] = 1.0f;
      }
    }
  }
  lm_page_fill_borders(p, page_w, rgba);
}
