// tiershade base: the display encoding of a linear image (base/srgb.h).
#include "base/srgb.h"

ImageF srgb_display(ImageF img) {
  for (size_t p = 0; p < img.rgba.size(); ++p)
    if (p % 4 != 3) img.rgba[p] = srgb_encode_clamped(img.rgba[p]);
  return img;
}
