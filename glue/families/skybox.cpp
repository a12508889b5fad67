// tiershade families: the skybox family (the HDR skybox, shaders/skybox.fs): input records
// (random camera vectors and fragment positions, and the hard cases of tests/conform/skybox.cases),
// the sky's test cube map (fp16 values, as the scene's sky is uploaded: glue/scene/skybox_pass.h),
// and the bridge to its C twin (c_ref/twins/skybox.c).
#include <iterator>

#include "families/hdr_inputs.h"
#include "families/record_family.h"
#include "math/hdr_formats.h"
#include "twins/skybox.h"

namespace {

// The record layout: shaders/skybox_slots.glsl, the one table (slot_table.h).
#define TS_SLOT_FILE "../../shaders/skybox_slots.glsl"
#include "families/slot_rows.inc"
constexpr RecordLayout kLayout = {"skybox", SB_SLOTS, SB_PIXEL_SLOTS, kSlotRows, std::size(kSlotRows),
                                  output_range_half};

sb_variant to_sb(const Variant &v) { return {tier_id(v.tier)}; }

// The frame the random positions fall in, and the cube's face size (small, so that the
// directions cross many texels and every face edge).
constexpr int kFrameW = 64, kFrameH = 48, kFace = 8;

ts_vec4f v3_slot(const ts_vec3f &v, float s) { return ts_v4f(v.x * s, v.y * s, v.z * s, 0.f); }

void random_pixel(Rng &r, InputSet, ts_vec4f rec[SB_SLOTS]) {
  rec[SB_SLOT_POS] = random_fragment_position(r, kFrameW, kFrameH);
  rec[SB_SLOT_SIZE] = size_slot(kFrameW, kFrameH);
  // A camera of any orientation and field of view: forward of any length, right and up up to
  // twice as long (a wide view), not orthogonal to it (any projection matrix).
  rec[SB_SLOT_FORWARD] = v3_slot(r.unit_vector(), r.uniform(0.1f, 4.f));
  rec[SB_SLOT_RIGHT] = v3_slot(r.unit_vector(), r.uniform(0.f, 2.f));
  rec[SB_SLOT_UP] = v3_slot(r.unit_vector(), r.uniform(0.f, 2.f));
  // The sky's scale (its radiance multiplier), and the tone-map scale (1 on the float path).
  const float tone = r.next() % 2 ? 1.f : r.uniform(0.05f, 4.f);
  rec[SB_SLOT_COLOR] = ts_v4f(r.uniform(0.f, 3.f), r.uniform(0.f, 3.f), r.uniform(0.f, 3.f), tone);
}

// The sky's cube: six kFace x kFace faces of HDR values an fp16 texture holds (zeros, 65504s,
// half denormals, 1e-3 .. 64), LINEAR (conform turns it NEAREST on GLES: docs/conformance.md).
void sky_cube(Rng &r, InputSet, FamilyInputs *out) {
  TextureDesc cube = hdr_test_texture(r, "u_sky", kFace, kFace * 6, true);
  cube.kind = TexKind::Cube;
  cube.h = kFace;
  out->textures = {cube};
}

ts_texcube first_texcube(const FamilyInputs &in) { return texcube_of(in.textures.at(0)); }

}  // namespace

const ShaderFamily kSkyboxFamily =
    twin_family<kLayout, to_sb, first_texcube, skybox_f, skybox_d, random_pixel, sky_cube>();
const FamilyRegistrar kRegisterSkybox(&kSkyboxFamily);
