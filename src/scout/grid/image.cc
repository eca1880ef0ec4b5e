#include "scout/grid/image.h"

#include <png.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>

#include "scout/common/atomic_file.h"
#include "scout/common/error.h"
#include "scout/common/input_file.h"

namespace scout::grid {
namespace {

namespace fs = std::filesystem;

// Refuses images whose pixel buffer alone would exceed 1 GiB: such a header is
// corrupt or hostile, and allocating first would abort the process.
constexpr uint64_t kMaxPixelBytes = uint64_t{1} << 30;

[[noreturn]] void Fail(const fs::path& path, const std::string& what) {
  throw InputError(path.string() + ": " + what);
}

[[noreturn]] void FailWrite(const fs::path& path, const std::string& what) {
  throw InputError("cannot write '" + path.string() + "': " + what);
}

std::string ReadFileBytes(const fs::path& path) {
  // A pipe would block and /dev/zero never end.
  RequireRegularFile(path, "a PGM or PNG image");
  std::unique_ptr<FILE, int (*)(FILE*)> file(std::fopen(path.c_str(), "rb"), &std::fclose);
  if (!file) Fail(path, std::string("cannot open: ") + std::strerror(errno));
  std::string data;
  char buffer[1 << 16];
  size_t n;
  while ((n = std::fread(buffer, 1, sizeof(buffer), file.get())) > 0) data.append(buffer, n);
  if (std::ferror(file.get())) Fail(path, "read error");
  return data;
}

// ---------------------------------------------------------------- PGM

// Reads the whitespace/comment-separated unsigned integers of a PGM.
class PgmScanner {
 public:
  PgmScanner(const std::string& data, size_t pos) : data_(data), pos_(pos) {}

  // Skips whitespace and '#' comments, then reads a decimal number; false if
  // there is none (end of file or another character).
  bool Next(uint64_t* value) {
    while (pos_ < data_.size()) {
      const unsigned char c = data_[pos_];
      if (c == '#') {
        while (pos_ < data_.size() && data_[pos_] != '\n' && data_[pos_] != '\r') ++pos_;
      } else if (std::isspace(c)) {
        ++pos_;
      } else {
        break;
      }
    }
    if (pos_ >= data_.size() || !std::isdigit(static_cast<unsigned char>(data_[pos_]))) {
      return false;
    }
    uint64_t v = 0;
    while (pos_ < data_.size() && std::isdigit(static_cast<unsigned char>(data_[pos_]))) {
      v = std::min<uint64_t>(v * 10 + (data_[pos_] - '0'), uint64_t{1} << 40);
      ++pos_;
    }
    *value = v;
    return true;
  }
  size_t pos() const { return pos_; }
  void set_pos(size_t pos) { pos_ = pos; }

 private:
  const std::string& data_;
  size_t pos_;
};

uint8_t ScaleTo8Bit(uint64_t v, uint64_t maxval) {
  return static_cast<uint8_t>((v * 255 + maxval / 2) / maxval);
}

Image DecodePgm(const std::string& data, const fs::path& path) {
  const bool binary = data[1] == '5';
  PgmScanner scanner(data, 2);
  uint64_t width = 0, height = 0, maxval = 0;
  if (!scanner.Next(&width) || !scanner.Next(&height) || !scanner.Next(&maxval)) {
    Fail(path, "malformed PGM header: expected 'P2' or 'P5' followed by width, height, maxval");
  }
  if (width == 0 || height == 0) Fail(path, "PGM width and height must be >= 1");
  if (maxval == 0 || maxval > 65535) {
    Fail(path, "PGM maxval must be in 1..65535, got " + std::to_string(maxval));
  }
  // Each side first, so that the product below cannot overflow.
  if (width > kMaxPixelBytes || height > kMaxPixelBytes || width * height > kMaxPixelBytes) {
    Fail(path, "PGM image is too large: " + std::to_string(width) + " x " + std::to_string(height));
  }
  Image image;
  image.width = static_cast<int>(width);
  image.height = static_cast<int>(height);
  image.channels = 1;
  const uint64_t num_pixels = width * height;

  if (binary) {
    // Exactly one whitespace character separates maxval from the raster.
    size_t pos = scanner.pos();
    if (pos >= data.size() || !std::isspace(static_cast<unsigned char>(data[pos]))) {
      Fail(path, "truncated PGM: expected a whitespace and pixel data after the header");
    }
    ++pos;
    const uint64_t bytes_per_sample = maxval < 256 ? 1 : 2;
    const uint64_t expected = num_pixels * bytes_per_sample;
    if (data.size() - pos < expected) {
      Fail(path, "truncated PGM: expected " + std::to_string(expected) +
                     " bytes of pixel data, got " + std::to_string(data.size() - pos));
    }
    image.pixels.resize(num_pixels);
    const auto* raster = reinterpret_cast<const uint8_t*>(data.data() + pos);
    for (uint64_t i = 0; i < num_pixels; ++i) {
      // 16-bit samples are big-endian (Netpbm).
      const uint64_t v =
          bytes_per_sample == 1 ? raster[i] : (raster[2 * i] << 8) | raster[2 * i + 1];
      if (v > maxval) {
        Fail(path, "PGM sample " + std::to_string(i) + " is " + std::to_string(v) +
                       ", above maxval " + std::to_string(maxval));
      }
      image.pixels[i] = ScaleTo8Bit(v, maxval);
    }
    return image;
  }

  // Every ASCII sample needs at least one byte; checked before allocating.
  if (data.size() - scanner.pos() < num_pixels) {
    Fail(path, "truncated PGM: expected " + std::to_string(num_pixels) + " samples");
  }
  image.pixels.resize(num_pixels);
  for (uint64_t i = 0; i < num_pixels; ++i) {
    uint64_t v = 0;
    if (!scanner.Next(&v)) {
      if (scanner.pos() < data.size()) {  // stopped at a character, not at the end
        Fail(path,
             "PGM sample " + std::to_string(i + 1) + ": expected a decimal number, found '" +
                 data.substr(scanner.pos(), std::min<size_t>(8, data.size() - scanner.pos())) +
                 "'");
      }
      Fail(path, "truncated PGM: expected " + std::to_string(num_pixels) + " ASCII samples, got " +
                     std::to_string(i));
    }
    if (v > maxval) {
      Fail(path, "PGM sample " + std::to_string(i) + " is " + std::to_string(v) +
                     ", above maxval " + std::to_string(maxval));
    }
    image.pixels[i] = ScaleTo8Bit(v, maxval);
  }
  return image;
}

std::string EncodePgm(const Image& image) {
  std::string bytes =
      "P5\n" + std::to_string(image.width) + " " + std::to_string(image.height) + "\n255\n";
  bytes.append(reinterpret_cast<const char*>(image.pixels.data()), image.pixels.size());
  return bytes;
}

// ---------------------------------------------------------------- PNG
// libpng reports errors by longjmp. The functions that call setjmp below hold
// only trivially destructible locals and touch C++ objects only through
// pointers owned by their callers, so a longjmp back skips no destructor.

struct PngErrorState {
  char message[256] = "";
};

void OnPngError(png_structp png, png_const_charp message) {
  auto* state = static_cast<PngErrorState*>(png_get_error_ptr(png));
  std::snprintf(state->message, sizeof(state->message), "%s", message);
  png_longjmp(png, 1);
}

// Warnings (e.g. about colour profiles) do not affect the pixels we read.
void OnPngWarning(png_structp, png_const_charp) {}

struct PngSource {
  const std::string* data;
  size_t pos;
};

void ReadFromMemory(png_structp png, png_bytep out, png_size_t length) {
  auto* source = static_cast<PngSource*>(png_get_io_ptr(png));
  if (source->data->size() - source->pos < length) png_error(png, "truncated PNG data");
  std::memcpy(out, source->data->data() + source->pos, length);
  source->pos += length;
}

void AppendToString(png_structp png, png_bytep in, png_size_t length) {
  auto* sink = static_cast<std::string*>(png_get_io_ptr(png));
  bool ok = true;
  try {
    sink->append(reinterpret_cast<const char*>(in), length);
  } catch (...) {
    ok = false;
  }
  if (!ok) png_error(png, "out of memory");
}

void FlushNothing(png_structp) {}

bool DecodePngWithLibpng(png_structp png, png_infop info, Image* image,
                         std::vector<png_bytep>* rows) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_read_info(png, info);
  const int color_type = png_get_color_type(png, info);
  const int bit_depth = png_get_bit_depth(png, info);
  // Expand to 8-bit samples but keep the channel structure: gray stays gray,
  // palettes become RGB, transparency becomes an alpha channel. No gamma
  // correction: pixel values are map data, not colours.
  if (color_type == PNG_COLOR_TYPE_PALETTE) png_set_palette_to_rgb(png);
  if (color_type == PNG_COLOR_TYPE_GRAY && bit_depth < 8) png_set_expand_gray_1_2_4_to_8(png);
  if (png_get_valid(png, info, PNG_INFO_tRNS)) png_set_tRNS_to_alpha(png);
  if (bit_depth == 16) png_set_scale_16(png);
  png_set_interlace_handling(png);
  png_read_update_info(png, info);

  const uint64_t width = png_get_image_width(png, info);
  const uint64_t height = png_get_image_height(png, info);
  const int channels = png_get_channels(png, info);
  if (png_get_bit_depth(png, info) != 8 || channels < 1 || channels > 4) {
    png_error(png, "unsupported pixel format");
  }
  if (width * height * channels > kMaxPixelBytes) png_error(png, "image is too large");
  image->width = static_cast<int>(width);
  image->height = static_cast<int>(height);
  image->channels = channels;
  image->pixels.resize(width * height * channels);
  rows->resize(height);
  for (uint64_t y = 0; y < height; ++y) {
    (*rows)[y] = image->pixels.data() + y * width * channels;
  }
  png_read_image(png, rows->data());
  png_read_end(png, nullptr);
  return true;
}

Image DecodePng(const std::string& data, const fs::path& path) {
  PngErrorState error;
  png_structp png =
      png_create_read_struct(PNG_LIBPNG_VER_STRING, &error, &OnPngError, &OnPngWarning);
  if (png == nullptr) Fail(path, "cannot initialise libpng");
  png_infop info = png_create_info_struct(png);
  struct Destroy {
    png_structp* png;
    png_infop* info;
    ~Destroy() { png_destroy_read_struct(png, info, nullptr); }
  } destroy{&png, &info};
  if (info == nullptr) Fail(path, "cannot initialise libpng");
  PngSource source{&data, 0};
  png_set_read_fn(png, &source, &ReadFromMemory);
  Image image;
  std::vector<png_bytep> rows;
  if (!DecodePngWithLibpng(png, info, &image, &rows)) {
    Fail(path, std::string("invalid PNG: ") + error.message);
  }
  return image;
}

bool EncodePngWithLibpng(png_structp png, png_infop info, const Image* image,
                         std::vector<png_bytep>* rows) {
  if (setjmp(png_jmpbuf(png))) return false;
  static constexpr int kColorTypes[] = {PNG_COLOR_TYPE_GRAY, PNG_COLOR_TYPE_GRAY_ALPHA,
                                        PNG_COLOR_TYPE_RGB, PNG_COLOR_TYPE_RGB_ALPHA};
  png_set_IHDR(png, info, image->width, image->height, 8, kColorTypes[image->channels - 1],
               PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  png_write_image(png, rows->data());
  png_write_end(png, nullptr);
  return true;
}

std::string EncodePng(const Image& image, const fs::path& path) {
  PngErrorState error;
  png_structp png =
      png_create_write_struct(PNG_LIBPNG_VER_STRING, &error, &OnPngError, &OnPngWarning);
  if (png == nullptr) FailWrite(path, "cannot initialise libpng");
  png_infop info = png_create_info_struct(png);
  struct Destroy {
    png_structp* png;
    png_infop* info;
    ~Destroy() { png_destroy_write_struct(png, info); }
  } destroy{&png, &info};
  if (info == nullptr) FailWrite(path, "cannot initialise libpng");
  std::string bytes;
  png_set_write_fn(png, &bytes, &AppendToString, &FlushNothing);
  std::vector<png_bytep> rows(image.height);
  const size_t stride = static_cast<size_t>(image.width) * image.channels;
  for (int y = 0; y < image.height; ++y) {
    // libpng's row type is non-const but png_write_image only reads it.
    rows[y] = const_cast<png_bytep>(image.pixels.data() + y * stride);
  }
  if (!EncodePngWithLibpng(png, info, &image, &rows)) {
    FailWrite(path, std::string("PNG encoding failed: ") + error.message);
  }
  return bytes;
}

std::string LowercaseExtension(const fs::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

}  // namespace

Image ReadImage(const std::filesystem::path& path) {
  const std::string data = ReadFileBytes(path);
  if (data.size() >= 2 && data[0] == 'P' && (data[1] == '2' || data[1] == '5')) {
    return DecodePgm(data, path);
  }
  if (data.size() >= 8 && png_sig_cmp(reinterpret_cast<png_const_bytep>(data.data()), 0, 8) == 0) {
    return DecodePng(data, path);
  }
  Fail(path, "expected a PGM (P2/P5) or PNG image, found neither signature");
}

void WriteImage(const Image& image, const std::filesystem::path& path) {
  if (image.channels < 1 || image.channels > 4) {
    FailWrite(path, "expected 1 to 4 channels, got " + std::to_string(image.channels));
  }
  if (image.width < 1 || image.height < 1) {
    FailWrite(path, "expected a non-empty image, got " + std::to_string(image.width) + " x " +
                        std::to_string(image.height));
  }
  const size_t expected =
      static_cast<size_t>(image.width) * static_cast<size_t>(image.height) * image.channels;
  if (image.pixels.size() != expected) {
    FailWrite(path, "expected " + std::to_string(expected) + " pixel bytes, got " +
                        std::to_string(image.pixels.size()));
  }
  const bool pgm = LowercaseExtension(path) == ".pgm";
  // PNG bytes under a .pgm name would confuse every other reader of the file.
  if (pgm && image.channels != 1) {
    FailWrite(path, "a .pgm file needs a 1-channel image, got " + std::to_string(image.channels) +
                        " channels");
  }
  WriteTextFileAtomically(path, pgm ? EncodePgm(image) : EncodePng(image, path));
}

}  // namespace scout::grid
