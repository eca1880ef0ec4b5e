#include "scout/io/gzip_file.h"

#include <unistd.h>
#include <zlib.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <memory>
#include <vector>

#include "scout/common/error.h"
#include "scout/common/input_file.h"

namespace scout::io {
namespace {

namespace fs = std::filesystem;

struct GzCloser {
  void operator()(gzFile_s* file) const { gzclose(file); }
};
using GzHandle = std::unique_ptr<gzFile_s, GzCloser>;

GzHandle OpenGz(const fs::path& path) {
  // zlib would open a directory and fail only on the first read, with a
  // message that suggests a corrupt file; a pipe would be read up to the
  // format detection's bytes and then lose them.
  RequireRegularFile(path, "a dataset or trajectory file");
  gzFile file = gzopen(path.c_str(), "rb");
  if (file == nullptr) {
    throw InputError(path.string() + ": cannot open for reading (" + std::strerror(errno) + ")");
  }
  // zlib's default 8 KiB buffers make reading a 16 MB bag noticeably slower.
  gzbuffer(file, 256 * 1024);
  return GzHandle(file);
}

// Returns zlib's error text if 'file' stopped on an error, else "".
std::string GzErrorText(gzFile file) {
  int errnum = Z_OK;
  const char* message = gzerror(file, &errnum);
  if (errnum == Z_OK || errnum == Z_STREAM_END) return "";
  if (errnum == Z_ERRNO) return std::strerror(errno);
  return message != nullptr && *message != '\0' ? message : "zlib error " + std::to_string(errnum);
}

}  // namespace

bool IsGzipFile(const fs::path& path) {
  RequireRegularFile(path, "a dataset or trajectory file");
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    throw InputError(path.string() + ": cannot open for reading (" + std::strerror(errno) + ")");
  }
  unsigned char magic[2] = {0, 0};
  in.read(reinterpret_cast<char*>(magic), 2);
  return in.gcount() == 2 && magic[0] == 0x1f && magic[1] == 0x8b;
}

std::string ReadLeadingBytes(const fs::path& path, std::size_t count) {
  GzHandle file = OpenGz(path);
  std::string bytes(count, '\0');
  const int n = gzread(file.get(), bytes.data(), static_cast<unsigned>(count));
  if (n < 0) {
    throw InputError(path.string() + ": corrupt gzip data (" + GzErrorText(file.get()) + ")");
  }
  bytes.resize(static_cast<std::size_t>(n));
  return bytes;
}

void DecompressGzipFile(const fs::path& path, const fs::path& destination) {
  GzHandle file = OpenGz(path);
  std::unique_ptr<FILE, int (*)(FILE*)> out(std::fopen(destination.c_str(), "wb"), &std::fclose);
  if (out == nullptr) {
    throw InputError(destination.string() + ": cannot write the decompressed copy of " +
                     path.string() + " (" + std::strerror(errno) + ")");
  }
  std::vector<char> buffer(1 << 20);
  for (;;) {
    const int n = gzread(file.get(), buffer.data(), static_cast<unsigned>(buffer.size()));
    const std::string error = n <= 0 ? GzErrorText(file.get()) : "";
    if (n < 0 || !error.empty()) {
      throw InputError(path.string() + ": corrupt or truncated gzip data (" + error +
                       "); expected a complete gzip stream");
    }
    if (n == 0) break;
    if (std::fwrite(buffer.data(), 1, static_cast<std::size_t>(n), out.get()) !=
        static_cast<std::size_t>(n)) {
      throw InputError(destination.string() + ": write failed while decompressing " +
                       path.string() + " (" + std::strerror(errno) + ")");
    }
  }
  if (std::fflush(out.get()) != 0) {
    throw InputError(destination.string() + ": write failed while decompressing " + path.string() +
                     " (" + std::strerror(errno) + ")");
  }
}

TemporaryFile::TemporaryFile(const std::string& name_prefix) {
  std::string pattern = (fs::temp_directory_path() / (name_prefix + "XXXXXX")).string();
  const int fd = ::mkstemp(pattern.data());
  if (fd < 0) {
    throw InputError(pattern + ": cannot create a temporary file (" + std::strerror(errno) + ")");
  }
  ::close(fd);
  path_ = pattern;
}

TemporaryFile::~TemporaryFile() {
  std::error_code ignored;
  fs::remove(path_, ignored);
}

LineReader::LineReader(const fs::path& path) : file_(OpenGz(path).release()) {}

LineReader::~LineReader() { gzclose(static_cast<gzFile>(file_)); }

bool LineReader::Next(std::string& line) {
  gzFile file = static_cast<gzFile>(file_);
  line.clear();
  char chunk[64 * 1024];
  for (;;) {
    if (gzgets(file, chunk, sizeof(chunk)) == nullptr) {
      error_ = GzErrorText(file);
      if (!error_.empty()) {
        line.clear();  // possibly cut mid-number: not trustworthy
        return false;
      }
      if (line.empty()) return false;
      break;  // last line without a newline
    }
    const std::size_t length = std::strlen(chunk);
    line.append(chunk, length);
    if (length > 0 && chunk[length - 1] == '\n') break;
  }
  while (!line.empty() && (line.back() == '\n' || line.back() == '\r')) line.pop_back();
  ++line_number_;
  return true;
}

}  // namespace scout::io
