/* tiershade twins: the declarations every twin header makes, written once. A twin <name> has
 * <name>_f (float32, bit-exact with llvmpipe) and <name>_d (double, the accuracy reference), each
 * shading one pixel from its input record; a batch twin adds <name>_f_batch (many pixels a call,
 * the same bits as one <name>_f call per pixel) and, for some, <name>_f_records. */
#ifndef TS_TWIN_API_H
#define TS_TWIN_API_H
#include "math/ts_math.h"

/* C linkage for the twins' functions when a C++ file includes their header */
#ifdef __cplusplus
#define TS_C_API extern "C"
#else
#define TS_C_API
#endif

/* name_f and name_d, both with the parameter list params (the variant, the record, the textures) */
#define TS_TWIN_DECLARE(name, params) \
  TS_C_API ts_vec4f name##_f params;  \
  TS_C_API ts_vec4d name##_d params;

/* input_t, a batch of records of nslots slots: slot k of pixel i is slot[k][i * stride[k]]
 * (stride in ts_vec4f, >= 0; 0 = one value for every pixel, e.g. a production uniform), and
 * name_f_batch(v, in, tex, out, count): out[i] = name_f(v, record of pixel i, tex) for i < count.
 * Any count >= 0 works (a multiple of 8 is fastest); call ts_math_init() on the thread first. */
#define TS_BATCH_DECLARE(name, input_t, nslots, variant_t, tex_t) \
  typedef struct {                                                \
    const ts_vec4f *slot[nslots];                                 \
    int stride[nslots];                                           \
  } input_t;                                                      \
  TS_C_API void name##_f_batch(const variant_t *v, const input_t *in, const tex_t *tex, ts_vec4f *out, int count);

/* name_f_records(v, recs, tex, out, count): the same for whole records stored one after the
 * other, recs[i * <its nslots> + k] is slot k of pixel i */
#define TS_BATCH_DECLARE_RECORDS(name, variant_t, tex_t) \
  TS_C_API void name##_f_records(const variant_t *v, const ts_vec4f *recs, const tex_t *tex, ts_vec4f *out, int count);
#endif
