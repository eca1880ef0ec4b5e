#ifndef SCOUT_IO_GZIP_FILE_H_
#define SCOUT_IO_GZIP_FILE_H_

// Reading files that may or may not be gzip-compressed. This header is
// included by C++17 translation units (the ROS 1 bag reader), so it must stay
// C++17-compatible.

#include <cstddef>
#include <cstdio>
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

// Reads a text file line by line, transparently decompressing gzip (several
// concatenated members too). Lines of any length are returned whole, without
// the trailing newline (and '\r'). Every byte zlib decoded before a problem is
// delivered: a stream corrupt near its end, or with a wrong checksum, loses
// nothing that was readable.
class LineReader {
 public:
  // Throws InputError naming the file if it cannot be opened.
  explicit LineReader(const std::filesystem::path& path);
  ~LineReader();
  LineReader(const LineReader&) = delete;
  LineReader& operator=(const LineReader&) = delete;

  // Reads the next line into 'line'. Returns false at the end of the content
  // or when the content stops early; then error() tells which.
  bool Next(std::string& line);

  // 1-based number of the line last returned by Next().
  std::size_t line_number() const { return line_number_; }

  // Empty after a complete stream; otherwise why the content stopped early
  // (e.g. "unexpected end of file" for a truncated gzip, zlib's message for
  // corrupt data). A line cut by the error is not returned.
  const std::string& error() const { return error_; }

  // After the end: empty, or what is odd about a stream that was read whole
  // (a checksum that does not match its data, bytes after the gzip stream).
  const std::string& notice() const { return notice_; }

 private:
  // Appends more decoded bytes to 'pending_'; false when there are none.
  bool Fill();
  bool FillGzip();

  std::FILE* file_ = nullptr;
  void* stream_ = nullptr;  // z_stream, kept opaque so zlib.h stays out of headers
  bool gzip_ = false;
  bool finished_ = false;
  std::string input_;    // compressed bytes read from the file
  std::string pending_;  // decoded bytes not yet returned
  std::size_t position_ = 0;
  std::size_t line_number_ = 0;
  std::string error_;
  std::string notice_;
};

}  // namespace scout::io

#endif  // SCOUT_IO_GZIP_FILE_H_
