#ifndef SCOUT_GRID_IMAGE_H_
#define SCOUT_GRID_IMAGE_H_

#include <array>
#include <cstdint>
#include <filesystem>
#include <vector>

namespace scout::grid {

// An 8-bit image, row-major from the TOP row (image convention), with 1
// (gray), 2 (gray+alpha), 3 (RGB) or 4 (RGBA) channels.
struct Image {
  int width = 0;
  int height = 0;
  int channels = 1;
  std::vector<uint8_t> pixels;

  uint8_t* at(int x, int y) { return &pixels[(static_cast<size_t>(y) * width + x) * channels]; }
  const uint8_t* at(int x, int y) const {
    return &pixels[(static_cast<size_t>(y) * width + x) * channels];
  }
};

// Reads a PGM (P2 or P5, maxval up to 65535, scaled to 8 bit) or PNG (any bit
// depth/colour type, converted to 8 bit). Throws InputError naming the file.
Image ReadImage(const std::filesystem::path& path);

// Writes 'image' as PNG or (for 1 channel and a .pgm suffix) binary PGM,
// through a temporary file and rename. Throws InputError on failure.
void WriteImage(const Image& image, const std::filesystem::path& path);

}  // namespace scout::grid

#endif  // SCOUT_GRID_IMAGE_H_
