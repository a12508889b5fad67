/* tiershade twins: the one tier enum. The twins' variant records store it
 * (ml_variant.tier, wl_variant.tier); glue's enum class Tier (shaderlib/variants.h)
 * takes its values from it; the shaders see it as TS_TIER_PS20 / PS2B / SM3 defines. */
#ifndef TS_TIER_ID_H
#define TS_TIER_ID_H
enum ts_tier_id { TS_TIER_ID_PS20 = 0, TS_TIER_ID_PS2B = 1, TS_TIER_ID_SM3 = 2 };
#endif
