#include "scout/common/input_file.h"

#include <system_error>

#include "scout/common/error.h"

namespace scout {

void RequireRegularFile(const std::filesystem::path& path, const std::string& what) {
  std::error_code ec;
  const std::filesystem::file_status status = std::filesystem::status(path, ec);
  const std::string name = path.string();
  if (status.type() == std::filesystem::file_type::not_found) {
    throw InputError(name + ": cannot open (no such file); expected " + what);
  }
  if (ec) throw InputError(name + ": cannot read (" + ec.message() + "); expected " + what);
  if (status.type() == std::filesystem::file_type::directory) {
    throw InputError(name + ": is a directory; expected " + what);
  }
  if (status.type() != std::filesystem::file_type::regular) {
    throw InputError(name + ": is not a regular file (a pipe, socket or device); expected " + what +
                     " (save a stream to a file first)");
  }
}

}  // namespace scout
