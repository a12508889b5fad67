/* c_ref/model_lighting_impl.h: generic body of the model_lighting twin; mirrors
 * shaders/model_lighting.fs statement by statement. Instantiated by model_lighting.c. */

static V4 FN(model_lighting_impl)(const ml_variant *v, const ts_vec4f rec[ML_SLOTS], const ts_tex2d *albedo_tex) {
  V3 N = FN(safe_normalize)(FN(xyz)(rec[ML_SLOT_NORMAL]));
  V3 P = FN(xyz)(rec[ML_SLOT_POSITION]);
  V4 uvw = FN(vec4_in)(rec[ML_SLOT_UV]);
  V4 params = FN(vec4_in)(rec[ML_SLOT_PARAMS]);
  V3 cube[6];
  for (int k = 0; k < 6; ++k) cube[k] = FN(xyz)(rec[ML_SLOT_AMBIENT + k]);
  V3 diffuse = FN(ambient_cube)(N, cube);

  int loop = v->num_lights;
  if (v->tier == TS_TIER_ID_SM3) {
    loop = (int)M(clamp)(params.y, K(0.0), (TS_REAL)ML_MAX_LIGHTS);
  }
  for (int i = 0; i < loop && i < ML_MAX_LIGHTS; ++i) {
    V4 l[5];
    for (int k = 0; k < 5; ++k) l[k] = FN(vec4_in)(rec[ML_SLOT_LIGHT0 + 5 * i + k]);
    V3 L;
    TS_REAL att;
    if (v->tier == TS_TIER_ID_PS20) {
      L = FN(light_direction)(l, P);
      att = i == 0 ? (TS_REAL)rec[ML_SLOT_VERTEX_ATTEN].x : (TS_REAL)rec[ML_SLOT_VERTEX_ATTEN].y;
    } else {
      att = FN(light_attenuation)(l, P, &L);
    }
    TS_REAL NdotL = M(dot3)(N, L);
    TS_REAL term = v->half_lambert ? FN(half_lambert)(NdotL) : FN(lambert)(NdotL);
    diffuse = M(add3)(diffuse, M(scale3)(FN(xyz4)(l[0]), att * term));
  }

  V3 albedo;
  if (v->albedo_texture) {
    V4 t = FN(sample_albedo)(albedo_tex, uvw.x, uvw.y);
    albedo = M(v3)(t.x, t.y, t.z);
  } else {
    albedo = FN(xyz)(rec[ML_SLOT_ALBEDO]);
  }
  V3 c = FN(final_output)(M(mul3)(albedo, diffuse), params.x, v->output_mode);
  return M(v4)(c.x, c.y, c.z, K(1.0));
}
