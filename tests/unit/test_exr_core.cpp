// tiershade tests: read_exr (glue/io/exr.cpp, OpenEXR's C core) against OpenEXR's C++ reader, bit for
// bit, and its memory budget.
//
// Usage: test_exr_core
//   Prints "PASS name" or "FAIL name: details" per check (tests/unit/unit_check.h); exit 1 on a failure.
//   Files go to a private mkdtemp() directory, removed at the end.
//
// Covered: every compression OpenEXR 3.1 writes (NONE .. DWAB) x scanline (increasing and
// decreasing line order) and tiled with mipmaps, channels R HALF, G FLOAT, B UINT (random bits:
// NaN payloads, denormals, Inf), with and without A, an extra channel, an offset data window:
// read_exr must give exactly what Imf::InputFile reads into FLOAT slices (the reader it replaced,
// whose results the renders were made with). DWAA/DWAB and tiled B44/B44A go through InputFile
// after the core's header check (glue/io/exr.cpp says why); the rest is the core's decoder.
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <ImfTiledOutputFile.h>
#include <half.h>
#include <stdlib.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "io/exr.h"
#include "unit_check.h"

using unit_check::check;

namespace {

uint32_t g_rng = 0x9e3779b9u;
uint32_t rnd() {
  g_rng ^= g_rng << 13;
  g_rng ^= g_rng >> 17;
  g_rng ^= g_rng << 5;
  return g_rng;
}

const int kW = 37, kH = 29, kX0 = -3, kY0 = 5;  // odd sizes: partial chunks and tiles

// Writes a file of channels R (HALF), G (FLOAT), B (UINT), optionally A (HALF) and Z (FLOAT), random bits.
void write_file(const std::string &path, Imf::Compression comp, bool tiled, Imf::LineOrder order, bool alpha) {
  const Imath::Box2i dw(Imath::V2i(kX0, kY0), Imath::V2i(kX0 + kW - 1, kY0 + kH - 1));
  Imf::Header hd(Imath::Box2i(Imath::V2i(0, 0), Imath::V2i(63, 63)), dw);
  hd.compression() = comp;
  hd.lineOrder() = tiled ? Imf::INCREASING_Y : order;
  struct Ch {
    const char *name;
    Imf::PixelType type;
  };
  std::vector<Ch> chans = {{"R", Imf::HALF}, {"G", Imf::FLOAT}, {"B", Imf::UINT}, {"Z", Imf::FLOAT}};
  if (alpha) chans.push_back({"A", Imf::HALF});
  const size_t n = static_cast<size_t>(kW) * kH;
  std::vector<std::vector<uint32_t>> data(chans.size(), std::vector<uint32_t>(n));
  Imf::FrameBuffer fb;
  for (size_t c = 0; c < chans.size(); ++c) {
    hd.channels().insert(chans[c].name, Imf::Channel(chans[c].type));
    for (uint32_t &v : data[c]) {
      v = rnd();
      if (chans[c].type == Imf::HALF) v &= 0xffff;
      if (rnd() % 4 == 0) v = chans[c].type == Imf::HALF ? 0x3c00 : 0x3f800000;  // runs of 1.0 for RLE
    }
    // Slices hold the samples as 4-byte cells; a HALF reads the low two bytes (little-endian host).
    fb.insert(chans[c].name, Imf::Slice::Make(chans[c].type, data[c].data(), dw, 4, 4 * static_cast<size_t>(kW)));
  }
  if (tiled) {
    hd.setTileDescription(Imf::TileDescription(16, 8, Imf::MIPMAP_LEVELS, Imf::ROUND_DOWN));
    Imf::TiledOutputFile out(path.c_str(), hd);
    out.setFrameBuffer(fb);
    for (int l = 0; l < out.numLevels(); ++l)  // the same samples at every level (only level 0 is read)
      out.writeTiles(0, out.numXTiles(l) - 1, 0, out.numYTiles(l) - 1, l);
  } else {
    Imf::OutputFile out(path.c_str(), hd);
    out.setFrameBuffer(fb);
    out.writePixels(kH);
  }
}

// What the C++ reader gave (the reader before the C core): FLOAT slices over a buffer of 1.0f,
// rows flipped to ImageF's bottom-up order.
ImageF read_with_inputfile(const std::string &path) {
  Imf::InputFile in(path.c_str());
  const Imath::Box2i dw = in.header().dataWindow();
  const int w = dw.max.x - dw.min.x + 1, h = dw.max.y - dw.min.y + 1;
  std::vector<float> buf(static_cast<size_t>(4) * w * h, 1.0f);
  Imf::FrameBuffer fb;
  static const char *const names[4] = {"R", "G", "B", "A"};
  for (int c = 0; c < 4; ++c)
    if (in.header().channels().findChannel(names[c]))
      fb.insert(names[c], Imf::Slice::Make(Imf::FLOAT, &buf[c], dw, 4 * sizeof(float), 4 * sizeof(float) * static_cast<size_t>(w)));
  in.setFrameBuffer(fb);
  in.readPixels(dw.min.y, dw.max.y);
  ImageF img;
  img.w = w;
  img.h = h;
  img.rgba.resize(buf.size());
  for (int y = 0; y < h; ++y)
    std::memcpy(&img.rgba[static_cast<size_t>(4) * w * (h - 1 - y)], &buf[static_cast<size_t>(4) * w * y], sizeof(float) * 4 * w);
  return img;
}

}  // namespace

int main() {
  char tmpl[] = "/tmp/tiershade_exr_core_XXXXXX";
  if (!mkdtemp(tmpl)) return 2;
  const std::string dir = tmpl;
  struct Comp {
    Imf::Compression c;
    const char *name;
  };
  const Comp comps[] = {{Imf::NO_COMPRESSION, "none"}, {Imf::RLE_COMPRESSION, "rle"},     {Imf::ZIPS_COMPRESSION, "zips"},
                        {Imf::ZIP_COMPRESSION, "zip"}, {Imf::PIZ_COMPRESSION, "piz"},     {Imf::PXR24_COMPRESSION, "pxr24"},
                        {Imf::B44_COMPRESSION, "b44"}, {Imf::B44A_COMPRESSION, "b44a"},   {Imf::DWAA_COMPRESSION, "dwaa"},
                        {Imf::DWAB_COMPRESSION, "dwab"}};
  for (const Comp &c : comps)
    for (int layout = 0; layout < 3; ++layout) {
      const bool tiled = layout == 2, alpha = layout != 1;
      const Imf::LineOrder order = layout == 1 ? Imf::DECREASING_Y : Imf::INCREASING_Y;
      const std::string name = std::string("exr_core_equals_inputfile_") + c.name +
          (tiled ? "_tiled_mipmap" : layout == 1 ? "_scanline_decreasing_no_alpha" : "_scanline");
      const std::string path = dir + "/" + name + ".exr";
      std::string detail;
      bool ok = false;
      try {
        write_file(path, c.c, tiled, order, alpha);
        const ImageF want = read_with_inputfile(path);
        ImageF got;
        std::string err;
        if (!read_exr(path, &got, &err)) {
          detail = err;
        } else if (got.w != want.w || got.h != want.h || got.rgba.size() != want.rgba.size()) {
          detail = "size " + std::to_string(got.w) + "x" + std::to_string(got.h) + ", want " + std::to_string(want.w) + "x" + std::to_string(want.h);
        } else {
          size_t diff = 0;
          for (size_t i = 0; i < got.rgba.size(); ++i) diff += unit_check::bits_of(got.rgba[i]) != unit_check::bits_of(want.rgba[i]);
          ok = diff == 0;
          detail = std::to_string(diff) + " of " + std::to_string(got.rgba.size()) + " samples differ in their bits";
        }
      } catch (const std::exception &e) {
        detail = std::string("OpenEXR: ") + e.what();
      }
      check(ok, name, detail);
    }

  std::filesystem::remove_all(dir);
  return unit_check::finish();
}
