#include "model/floor_image.h"

#include <png.h>

#include <cstdio>
#include <cstring>

namespace essaim {

bool LoadPngBottomUp(const std::string& path, int* width, int* height, std::vector<Color>* pixels,
                     std::string* error) {
  png_image image;
  std::memset(&image, 0, sizeof image);
  image.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&image, path.c_str())) {
    *error = std::string("cannot read PNG: ") + image.message;
    return false;
  }
  image.format = PNG_FORMAT_RGBA;
  std::vector<unsigned char> buffer(PNG_IMAGE_SIZE(image));
  if (!png_image_finish_read(&image, nullptr, buffer.data(), 0, nullptr)) {
    *error = std::string("cannot decode PNG: ") + image.message;
    png_image_free(&image);
    return false;
  }
  *width = static_cast<int>(image.width);
  *height = static_cast<int>(image.height);
  pixels->resize(static_cast<size_t>(*width) * *height);
  for (int row = 0; row < *height; ++row) {
    // PNG rows run top to bottom; we store bottom row first.
    const unsigned char* src = buffer.data() + static_cast<size_t>(*height - 1 - row) * *width * 4;
    for (int col = 0; col < *width; ++col) {
      Color& c = (*pixels)[static_cast<size_t>(row) * *width + col];
      c.r = src[col * 4 + 0];
      c.g = src[col * 4 + 1];
      c.b = src[col * 4 + 2];
      c.a = src[col * 4 + 3];
    }
  }
  return true;
}

}  // namespace essaim
