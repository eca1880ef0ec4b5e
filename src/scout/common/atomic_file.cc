#include "scout/common/atomic_file.h"

#include <unistd.h>

#include <fstream>
#include <system_error>

#include "scout/common/error.h"

namespace scout {

void WriteFileAtomically(const std::filesystem::path& path,
                         const std::function<void(const std::filesystem::path& tmp)>& write) {
  std::filesystem::path tmp = path;
  tmp += ".tmp." + std::to_string(::getpid());
  try {
    write(tmp);
  } catch (...) {
    std::error_code ignored;
    std::filesystem::remove(tmp, ignored);
    throw;
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) {
    std::filesystem::remove(tmp, ec);
    throw InputError("cannot write '" + path.string() + "': " + ec.message());
  }
}

void WriteTextFileAtomically(const std::filesystem::path& path, const std::string& content) {
  WriteFileAtomically(path, [&](const std::filesystem::path& tmp) {
    std::ofstream out(tmp, std::ios::binary);
    if (!out) throw InputError("cannot write '" + path.string() + "': directory not writable");
    out << content;
    out.close();
    if (!out) throw InputError("cannot write '" + path.string() + "': write failed");
  });
}

}  // namespace scout
