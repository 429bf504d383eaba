// PNG through libpng, the one adapter for it: floor images read from files, stored bottom
// row first (the image's bottom-left pixel sits at the arena's min corner, as in ARGoS), and
// images written to memory (a recording's floor).
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "core/math.h"

namespace essaim {

/// Loads `path` as RGB(A); false with `error` set when it cannot be read. A FIFO or a
/// device is refused as such before it is opened, and an image of more than `max_pixels`
/// (read from its header) before anything is decoded: a small file can declare billions.
bool LoadPngBottomUp(const std::string& path, long long max_pixels, int* width, int* height, std::vector<Color>* pixels,
                     std::string* error);
/// `rgb` (8-bit RGB, top row first, width x height) as PNG bytes in `png`; false when
/// libpng refuses it.
bool EncodePngRgb(const std::vector<uint8_t>& rgb, int width, int height, std::string* png);

}  // namespace essaim
