// Floor images: PNG files read with libpng, stored bottom row first (spec §4.3: the
// image's bottom-left pixel sits at the arena's min corner).
#pragma once
#include <string>
#include <vector>

#include "core/math.h"

namespace essaim {

/// Loads `path` as RGB(A); false with `error` set when it cannot be read. A FIFO or a
/// device is refused as such before it is opened, and an image of more than `max_pixels`
/// (read from its header) before anything is decoded: a small file can declare billions.
bool LoadPngBottomUp(const std::string& path, long long max_pixels, int* width, int* height,
                     std::vector<Color>* pixels, std::string* error);

}  // namespace essaim
