#include "scout/grid/image.h"

#include <gtest/gtest.h>
#include <png.h>
#include <rapidcheck/gtest.h>
#include <sys/stat.h>

#include <fstream>
#include <string>

#include "scout/common/error.h"
#include "scout/grid/test_temp_directory.h"

namespace scout::grid {
namespace {

namespace fs = std::filesystem;

std::string ReadBytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// Writes a PNG through libpng's simplified API, which can produce 16-bit and
// palette files that WriteImage (8-bit only) never writes.
void WritePngWithLibpng(const fs::path& path, uint32_t format, int width, int height,
                        const void* pixels, const void* colormap = nullptr, int entries = 0) {
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  image.width = width;
  image.height = height;
  image.format = format;
  image.colormap_entries = entries;
  ASSERT_TRUE(png_image_write_to_file(&image, path.c_str(), 0, pixels, 0, colormap))
      << image.message;
}

TEST(Image, PngRoundTripKeepsEveryChannelCount) {
  const TestTempDirectory dir;
  for (int channels = 1; channels <= 4; ++channels) {
    Image image{.width = 7, .height = 3, .channels = channels, .pixels = {}};
    for (int i = 0; i < 7 * 3 * channels; ++i) image.pixels.push_back(static_cast<uint8_t>(i * 37));
    const fs::path path = dir.path() / ("c" + std::to_string(channels) + ".png");
    WriteImage(image, path);
    const Image back = ReadImage(path);
    EXPECT_EQ(back.width, 7);
    EXPECT_EQ(back.height, 3);
    EXPECT_EQ(back.channels, channels);
    EXPECT_EQ(back.pixels, image.pixels);
  }
}

RC_GTEST_PROP(Image, PgmAndPngRoundTripRandomGrayImages, ()) {
  const TestTempDirectory dir;
  Image image;
  image.width = *rc::gen::inRange(1, 40);
  image.height = *rc::gen::inRange(1, 40);
  image.pixels = *rc::gen::container<std::vector<uint8_t>>(image.width * image.height,
                                                           rc::gen::arbitrary<uint8_t>());
  for (const char* name : {"g.pgm", "g.PGM", "g.png"}) {
    WriteImage(image, dir.path() / name);
    const Image back = ReadImage(dir.path() / name);
    RC_ASSERT(back.width == image.width && back.height == image.height && back.channels == 1);
    RC_ASSERT(back.pixels == image.pixels);
  }
  RC_ASSERT(ReadBytes(dir.path() / "g.pgm").substr(0, 3) == "P5\n");
}

TEST(Image, ReadsSixteenBitPngScaledTo8Bit) {
  const TestTempDirectory dir;
  const uint16_t pixels[] = {0, 65535, 205 * 257, 128 * 257};
  WritePngWithLibpng(dir.path() / "deep.png", PNG_FORMAT_LINEAR_Y, 4, 1, pixels);
  const Image image = ReadImage(dir.path() / "deep.png");
  EXPECT_EQ(image.channels, 1);
  EXPECT_EQ(image.pixels, (std::vector<uint8_t>{0, 255, 205, 128}));
}

TEST(Image, ReadsPaletteAndPaletteWithTransparency) {
  const TestTempDirectory dir;
  const uint8_t indices[] = {0, 1, 2, 1};
  const uint8_t rgb[] = {0, 0, 0, 254, 254, 254, 10, 20, 30};
  WritePngWithLibpng(dir.path() / "p.png", PNG_FORMAT_RGB_COLORMAP, 2, 2, indices, rgb, 3);
  const Image image = ReadImage(dir.path() / "p.png");
  EXPECT_EQ(image.channels, 3);
  EXPECT_EQ(image.pixels,
            (std::vector<uint8_t>{0, 0, 0, 254, 254, 254, 10, 20, 30, 254, 254, 254}));

  const uint8_t rgba[] = {0, 0, 0, 255, 254, 254, 254, 0, 10, 20, 30, 255};
  WritePngWithLibpng(dir.path() / "pa.png", PNG_FORMAT_RGBA_COLORMAP, 2, 2, indices, rgba, 3);
  const Image with_alpha = ReadImage(dir.path() / "pa.png");
  EXPECT_EQ(with_alpha.channels, 4);
  EXPECT_EQ(with_alpha.at(1, 0)[3], 0);
  EXPECT_EQ(with_alpha.at(0, 1)[2], 30);
}

TEST(Image, PgmSamplesAreScaledFromMaxval) {
  const TestTempDirectory dir;
  const Image image = ReadImage(dir.Write("m.pgm", "P2\n3 1\n# low maxval\n4\n0 2 4\n"));
  EXPECT_EQ(image.pixels, (std::vector<uint8_t>{0, 128, 255}));
}

TEST(Image, ErrorsNameTheFileAndWhatWasExpected) {
  const TestTempDirectory dir;
  const auto expect_error = [](auto&& f, const std::string& a, const std::string& b) {
    try {
      f();
      ADD_FAILURE() << "expected InputError mentioning " << a;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(a), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(b), std::string::npos) << e.what();
    }
  };
  expect_error([&] { ReadImage(dir.path() / "none.png"); }, "none.png", "no such file");
  expect_error([&] { ReadImage(dir.Write("bad.pgm", "P2 2 1 255 25x 3")); }, "bad.pgm",
               "PGM sample 2: expected a decimal number, found 'x 3'");
  // A pipe would block for ever, /dev/zero never end.
  ASSERT_EQ(::mkfifo((dir.path() / "fifo.pgm").c_str(), 0600), 0);
  expect_error([&] { ReadImage(dir.path() / "fifo.pgm"); }, "fifo.pgm", "not a regular file");
  expect_error([&] { ReadImage(dir.Write("x.pgm", "P6\n1 1\n255\nabc")); }, "x.pgm", "PGM");
  expect_error([&] { ReadImage(dir.Write("big.pgm", "P2 1 1 255 300")); }, "big.pgm", "maxval");
  expect_error([&] { ReadImage(dir.Write("z.pgm", "P5 0 3 255 ")); }, "z.pgm", ">= 1");
  expect_error([&] { ReadImage(dir.Write("h.pgm", "P5 3")); }, "h.pgm", "header");
  expect_error([&] { ReadImage(dir.Write("huge.pgm", "P5 1099511627776 1099511627776 255 ")); },
               "huge.pgm", "too large");

  Image image{.width = 16, .height = 16, .channels = 3, .pixels = {}};
  image.pixels.assign(16 * 16 * 3, 7);
  WriteImage(image, dir.path() / "full.png");
  const std::string bytes = ReadBytes(dir.path() / "full.png");
  dir.Write("cut.png", bytes.substr(0, bytes.size() / 2));
  expect_error([&] { ReadImage(dir.path() / "cut.png"); }, "cut.png", "PNG");

  expect_error([&] { WriteImage(image, dir.path() / "rgb.pgm"); }, "rgb.pgm", "1-channel");
  image.pixels.pop_back();
  expect_error([&] { WriteImage(image, dir.path() / "short.png"); }, "short.png", "pixel bytes");
  expect_error([&] { WriteImage(Image{}, dir.path() / "empty.png"); }, "empty.png", "non-empty");
}

}  // namespace
}  // namespace scout::grid
