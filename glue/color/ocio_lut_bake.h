// tiershade color: colour transforms from OpenColorIO, and 3D LUTs baked from them.
//
// A transform is one of:
//   * a file OpenColorIO reads (FileTransform, trilinear for 3D tables): .cube (first read
//     by tiershade's strict reader, lut_io.h, for file:line errors), .cc/.ccc/.cdl (ASC
//     CDL), .3dl, .spi3d, ...;
//   * one or more looks of an OCIO config (LookTransform from src to dst, by default the
//     config's `default` role both ways);
//   * ASC CDL values (CDLTransform, ASC style: clamped to [0, 1]).
// The CPU processor is OCIO's own, with OPTIMIZATION_LOSSLESS (the default optimisation
// approximates pow, log and exp: OPTIMIZATION_FAST_LOG_EXP_POW), in float32; it is both
// what LUTs are baked from and the reference they are measured against (docs/color_correction.md).
// Errors name the file (and OCIO's own message, which gives the line for configs).
#pragma once
#include <cstddef>
#include <memory>
#include <string>

#include "color/lut_texture.h"

struct TransformSpec {
  enum class Kind { File, Look, Cdl };
  Kind kind = Kind::File;
  std::string file;  // File
  std::string config, looks, src, dst;  // Look (looks: "a" or "a, b"; src/dst empty: role default)
  double slope[3] = {1, 1, 1}, offset[3] = {0, 0, 0}, power[3] = {1, 1, 1}, sat = 1;  // Cdl
  std::string describe() const;
};

struct ColorTransformImpl;
class ColorTransform {
 public:
  bool open(const TransformSpec &spec, std::string *err);
  // Applies the transform in place to `count` RGB triples (float32). Thread-safe.
  void apply(float *rgb, size_t count) const;
  const std::string &description() const { return description_; }
  bool is_open() const { return impl_ != nullptr; }

 private:
  std::shared_ptr<const ColorTransformImpl> impl_;
  std::string description_;
};

// The LUT of edge n (2..256) that holds the transform at the lattice nodes (r, g, b)/(n-1),
// each node value computed as float(i) / float(n - 1).
bool bake_lut(const ColorTransform &t, int n, Lut3D *out, std::string *err);
