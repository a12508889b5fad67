// tiershade bake: the irradiance volume in the bake directory (docs/irradiance_volume.md, "In the bake
// directory"): DIR/volume.bin (a little-endian binary file: a header, then each sample's position,
// validity, back-face share and six colours) and the manifest's "volume" entry (file, size, the
// bytes' content hash, the inputs' hash and its parts, the grid); the content hash of what the samples depend on,
// so that a stale volume is refused; reading it back with every error naming the file and the place
// (JSON place in the manifest, byte offset and sample in volume.bin).
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "bake/irradiance_volume.h"

// What the samples depend on, in parts (irradiance_volume.h: VolumeInputs): the box, the settings
// (spacing, fit, validity threshold, whether models occlude), the geometry (the world faces' frames and
// every triangle the rays see: RayScene::content_hash), the faces' materials (reflectivity, emission),
// their flat lightmaps (the grids' values) and the sky (`sky_hash`: the caller's hash of its image,
// scale and samples; 0 without one). glue/bake/content_hash.h.
VolumeInputs volume_inputs(const double lo[3], const double hi[3], const VolumeSettings &set,
                           const std::vector<WorldFace> &faces, const std::vector<LuxelGrid> &grids,
                           uint64_t rays_hash, uint64_t sky_hash);
// The one hash of the parts (the manifest's /volume/inputs_hash and volume.bin's header).
uint64_t volume_inputs_hash(const VolumeInputs &in);
// The parts of `was` that differ from `now`, in words with the box's and settings' values
// ("the volume's settings (spacing [1.2192,2.4384,1.2192] -> [0.6096,1.2192,0.6096])"); empty when equal.
std::string volume_inputs_changed(const VolumeInputs &was, const VolumeInputs &now);

extern const char kVolumeFile[];  // "volume.bin"

// The file's bytes and the manifest entry describing them (write_bake_dir writes both).
std::string volume_file_bytes(const IrradianceVolume &v);
nlohmann::ordered_json volume_manifest_entry(const IrradianceVolume &v, const std::string &bytes);

// Reads DIR's volume: the manifest's /volume entry and DIR/volume.bin. Refused (false, *err naming the
// file and the place) when the entry is missing, its inputs hash is not `inputs`' (stale: naming what
// changed from the entry's /volume/inputs record, volume_inputs_changed), the
// file's size or content hash is not the manifest's, or a field is out of range (header, a sample's
// position off the grid, validity not 0 or 1, a colour negative or not finite).
bool read_volume_dir(const std::string &dir, const VolumeInputs &inputs, IrradianceVolume *out, std::string *err);
