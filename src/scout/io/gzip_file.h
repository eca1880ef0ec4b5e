#ifndef SCOUT_IO_GZIP_FILE_H_
#define SCOUT_IO_GZIP_FILE_H_

// Reading files that may or may not be gzip-compressed. This header is
// included by C++17 translation units (the ROS 1 bag reader), so it must stay
// C++17-compatible.

#include <cstddef>
#include <filesystem>
#include <string>

namespace scout::io {

// Returns true if 'path' starts with the gzip magic bytes (1f 8b). Throws
// InputError naming the file if it cannot be opened.
bool IsGzipFile(const std::filesystem::path& path);

// Returns the first 'count' bytes of the content of 'path' (fewer if the
// content is shorter), decompressed if the file is gzip. Throws InputError
// naming the file if it cannot be opened or its gzip header is corrupt.
std::string ReadLeadingBytes(const std::filesystem::path& path, std::size_t count);

// Decompresses the gzip file 'path' into 'destination' (overwritten). Throws
// InputError naming 'path' when the stream is corrupt or truncated, or when
// 'destination' cannot be written.
void DecompressGzipFile(const std::filesystem::path& path,
                        const std::filesystem::path& destination);

// An empty file created exclusively (mkstemp) in the system temp directory,
// removed when this object is destroyed, also during exception unwinding.
class TemporaryFile {
 public:
  // Throws InputError if the temp directory is not writable.
  explicit TemporaryFile(const std::string& name_prefix);
  ~TemporaryFile();
  TemporaryFile(const TemporaryFile&) = delete;
  TemporaryFile& operator=(const TemporaryFile&) = delete;

  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

// Reads a text file line by line, transparently decompressing gzip. Lines of
// any length are returned whole, without the trailing newline (and '\r').
class LineReader {
 public:
  // Throws InputError naming the file if it cannot be opened.
  explicit LineReader(const std::filesystem::path& path);
  ~LineReader();
  LineReader(const LineReader&) = delete;
  LineReader& operator=(const LineReader&) = delete;

  // Reads the next line into 'line'. Returns false at the end of the content
  // or on a read error; then error() tells which.
  bool Next(std::string& line);

  // 1-based number of the line last returned by Next().
  std::size_t line_number() const { return line_number_; }

  // Empty after a clean end of file; otherwise zlib's description of why
  // reading stopped (e.g. "unexpected end of file" for a truncated gzip).
  // A line cut by the error is not returned.
  const std::string& error() const { return error_; }

 private:
  void* file_ = nullptr;  // gzFile, kept opaque so zlib.h stays out of headers
  std::size_t line_number_ = 0;
  std::string error_;
};

}  // namespace scout::io

#endif  // SCOUT_IO_GZIP_FILE_H_
