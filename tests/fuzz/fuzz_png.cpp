// The floor-image loader (libpng) on arbitrary bytes.
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "model/floor_image.h"
#include "model/model.h"

using namespace essaim;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const std::string path = "/tmp/essaim-fuzz-floor-" + std::to_string(getpid()) + ".png";
  FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) return 0;
  std::fwrite(data, 1, size, f);
  std::fclose(f);
  int w = 0, h = 0;
  std::vector<Color> pixels;
  std::string error;
  if (LoadPngBottomUp(path, LimitsDef().floor_pixels, &w, &h, &pixels, &error) &&
      pixels.size() != static_cast<size_t>(w) * h)
    __builtin_trap();
  return 0;
}
