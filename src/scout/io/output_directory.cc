#include "scout/io/output_directory.h"

#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <fstream>
#include <system_error>

#include "scout/common/error.h"

namespace scout::io {
namespace {

const std::string kStagingPrefix = ".scout-staging-";

// A run killed by a signal cannot clean up after itself: remove staging
// directories whose process no longer exists.
void RemoveAbandonedStaging(const std::filesystem::path& dir) {
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(dir, ec)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind(kStagingPrefix, 0) != 0) continue;
    const std::string pid_text = name.substr(kStagingPrefix.size());
    if (pid_text.empty() || pid_text.find_first_not_of("0123456789") != std::string::npos) continue;
    const pid_t pid = static_cast<pid_t>(std::stol(pid_text));
    if (::kill(pid, 0) != 0 && errno == ESRCH) std::filesystem::remove_all(entry.path(), ec);
  }
}

}  // namespace

OutputDirectory::OutputDirectory(const std::filesystem::path& dir) : dir_(dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir_, ec);
  if (ec || !std::filesystem::is_directory(dir_)) {
    throw InputError("cannot create output directory '" + dir_.string() +
                     "': " + (ec ? ec.message() : std::string("not a directory")));
  }
  RemoveAbandonedStaging(dir_);
  staging_ = dir_ / (kStagingPrefix + std::to_string(::getpid()));
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
  // Names may hold subdirectories ("figures/a.svg"); the writer expects them.
  std::error_code ec;
  std::filesystem::create_directories((staging_ / name).parent_path(), ec);
  return staging_ / name;
}

void OutputDirectory::Commit() {
  for (const std::string& name : names_) {
    std::error_code ec;
    std::filesystem::create_directories((dir_ / name).parent_path(), ec);
    std::filesystem::rename(staging_ / name, dir_ / name, ec);
    if (ec) {
      throw InputError("cannot move '" + name + "' into '" + dir_.string() + "': " + ec.message());
    }
  }
}

}  // namespace scout::io
