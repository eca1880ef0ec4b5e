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

namespace {

constexpr std::size_t kChunkBytes = 256 * 1024;

z_stream* Stream(void* stream) { return static_cast<z_stream*>(stream); }

}  // namespace

LineReader::LineReader(const fs::path& path) {
  RequireRegularFile(path, "a dataset or trajectory file");
  gzip_ = IsGzipFile(path);
  file_ = std::fopen(path.c_str(), "rb");
  if (file_ == nullptr) {
    throw InputError(path.string() + ": cannot open for reading (" + std::strerror(errno) + ")");
  }
  if (gzip_) {
    auto* stream = new z_stream{};
    // 16 + MAX_WBITS: a gzip wrapper, whose checksum inflate verifies.
    if (inflateInit2(stream, 16 + MAX_WBITS) != Z_OK) {
      delete stream;
      std::fclose(file_);
      throw InputError(path.string() + ": cannot start gzip decompression");
    }
    stream_ = stream;
  }
}

LineReader::~LineReader() {
  if (stream_ != nullptr) {
    inflateEnd(Stream(stream_));
    delete Stream(stream_);
  }
  if (file_ != nullptr) std::fclose(file_);
}

bool LineReader::Next(std::string& line) {
  for (;;) {
    const std::size_t newline = pending_.find('\n', position_);
    if (newline != std::string::npos) {
      line.assign(pending_, position_, newline - position_);
      position_ = newline + 1;
      break;
    }
    // Keep only the unfinished line before decoding more.
    pending_.erase(0, position_);
    position_ = 0;
    if (Fill()) continue;
    // The end: a last line without a newline counts, one cut by an error not.
    if (pending_.empty() || !error_.empty()) {
      pending_.clear();
      return false;
    }
    line.swap(pending_);
    pending_.clear();
    break;
  }
  while (!line.empty() && (line.back() == '\n' || line.back() == '\r')) line.pop_back();
  ++line_number_;
  return true;
}

bool LineReader::Fill() {
  if (finished_) return false;
  if (gzip_) return FillGzip();
  const std::size_t before = pending_.size();
  pending_.resize(before + kChunkBytes);
  const std::size_t n = std::fread(pending_.data() + before, 1, kChunkBytes, file_);
  pending_.resize(before + n);
  if (n == 0) {
    finished_ = true;
    if (std::ferror(file_)) error_ = std::strerror(errno);
  }
  return n > 0;
}

bool LineReader::FillGzip() {
  z_stream* stream = Stream(stream_);
  const std::size_t before = pending_.size();
  while (pending_.size() == before && !finished_) {
    if (stream->avail_in == 0) {
      input_.resize(kChunkBytes);
      const std::size_t n = std::fread(input_.data(), 1, kChunkBytes, file_);
      if (n == 0) {
        finished_ = true;
        error_ = std::ferror(file_) ? std::strerror(errno) : "unexpected end of file";
        break;
      }
      stream->next_in = reinterpret_cast<Bytef*>(input_.data());
      stream->avail_in = static_cast<uInt>(n);
    }
    pending_.resize(before + kChunkBytes);
    stream->next_out = reinterpret_cast<Bytef*>(pending_.data() + before);
    stream->avail_out = static_cast<uInt>(kChunkBytes);
    const int result = inflate(stream, Z_NO_FLUSH);
    // Whatever was decoded counts, also when inflate then reports an error.
    pending_.resize(before + kChunkBytes - stream->avail_out);
    if (result == Z_STREAM_END) {
      // Another member may follow (concatenated gzip files); anything else
      // after the stream is reported, not read.
      if (stream->avail_in == 0) {
        input_.resize(kChunkBytes);
        stream->avail_in = static_cast<uInt>(std::fread(input_.data(), 1, kChunkBytes, file_));
        stream->next_in = reinterpret_cast<Bytef*>(input_.data());
      }
      if (stream->avail_in == 0) {
        finished_ = true;
      } else if (stream->avail_in >= 2 && stream->next_in[0] == 0x1f &&
                 stream->next_in[1] == 0x8b) {
        inflateReset(stream);
      } else {
        std::size_t trailing = stream->avail_in;
        char buffer[4096];
        while (const std::size_t n = std::fread(buffer, 1, sizeof(buffer), file_)) trailing += n;
        notice_ = std::to_string(trailing) + " bytes after the end of the gzip stream ignored";
        finished_ = true;
      }
    } else if (result == Z_DATA_ERROR) {
      const std::string message = stream->msg != nullptr ? stream->msg : "corrupt data";
      finished_ = true;
      // The trailer's checks come after all of the data: nothing is missing,
      // but something in it may be wrong.
      if (message == "incorrect data check" || message == "incorrect length check") {
        notice_ = "gzip " + message +
                  " at the end of the stream: every line was read, but "
                  "some may be damaged";
      } else {
        error_ = message;
      }
    } else if (result != Z_OK && result != Z_BUF_ERROR) {
      finished_ = true;
      error_ = stream->msg != nullptr ? stream->msg : "zlib error " + std::to_string(result);
    }
  }
  return pending_.size() > before;
}

}  // namespace scout::io
