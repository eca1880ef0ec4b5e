#include "scout/io/output_directory.h"

#include <unistd.h>

#include <fstream>
#include <system_error>

#include "scout/common/error.h"

namespace scout::io {

OutputDirectory::OutputDirectory(const std::filesystem::path& dir) : dir_(dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir_, ec);
  if (ec || !std::filesystem::is_directory(dir_)) {
    throw InputError("cannot create output directory '" + dir_.string() +
                     "': " + (ec ? ec.message() : std::string("not a directory")));
  }
  staging_ = dir_ / (".scout-staging-" + std::to_string(::getpid()));
  std::filesystem::create_directory(staging_, ec);
  const std::filesystem::path probe = staging_ / "probe";
  std::ofstream out(probe);
  if (ec || !out) {
    std::filesystem::remove_all(staging_, ec);
    throw InputError("output directory '" + dir_.string() + "' is not writable");
  }
  out.close();
  std::filesystem::remove(probe, ec);
}

OutputDirectory::~OutputDirectory() {
  std::error_code ec;
  std::filesystem::remove_all(staging_, ec);
}

std::filesystem::path OutputDirectory::Stage(const std::string& name) {
  names_.push_back(name);
  return staging_ / name;
}

void OutputDirectory::Commit() {
  for (const std::string& name : names_) {
    std::error_code ec;
    std::filesystem::rename(staging_ / name, dir_ / name, ec);
    if (ec) {
      throw InputError("cannot move '" + name + "' into '" + dir_.string() + "': " + ec.message());
    }
  }
}

}  // namespace scout::io
