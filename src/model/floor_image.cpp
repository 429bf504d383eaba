#include "model/floor_image.h"

#include <png.h>

#include <cstdio>
#include <cstring>

#include "core/paths.h"

namespace essaim {

bool LoadPngBottomUp(const std::string& path, long long max_pixels, int* width, int* height, std::vector<Color>* pixels,
                     std::string* error) {
  const std::string kind = SpecialFileKind(path);
  if (!kind.empty()) {
    *error = "is " + kind + ", not a PNG file";
    return false;
  }
  png_image image;
  std::memset(&image, 0, sizeof image);
  image.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&image, path.c_str())) {
    *error = std::string("cannot read PNG: ") + image.message;
    return false;
  }
  const double pixel_count = static_cast<double>(image.width) * image.height;
  if (pixel_count > static_cast<double>(max_pixels)) {
    *error = std::to_string(image.width) + " x " + std::to_string(image.height) + " pixels is over the limit of " +
             std::to_string(max_pixels) + " pixels (<system max_floor_pixels>)";
    png_image_free(&image);
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

bool EncodePngRgb(const std::vector<uint8_t>& rgb, int width, int height, std::string* png) {
  png_image image;
  std::memset(&image, 0, sizeof image);
  image.version = PNG_IMAGE_VERSION;
  image.width = static_cast<png_uint_32>(width);
  image.height = static_cast<png_uint_32>(height);
  image.format = PNG_FORMAT_RGB;
  png_alloc_size_t bytes = 0;
  if (!png_image_write_to_memory(&image, nullptr, &bytes, 0, rgb.data(), 0, nullptr)) return false;
  png->resize(bytes);
  if (!png_image_write_to_memory(&image, &(*png)[0], &bytes, 0, rgb.data(), 0, nullptr)) return false;
  png->resize(bytes);
  return true;
}

}  // namespace essaim
