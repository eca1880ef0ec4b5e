#include "scout/io/output_directory.h"

#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <fstream>
#include <system_error>

#include "scout/common/atomic_file.h"
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

const std::string kCommandLinePrefix = "# scout ";

struct Manifest {
  std::string command;  // empty: not recorded
  std::vector<std::string> names;
};

// The manifest in 'dir' (empty without one).
Manifest ReadManifest(const std::filesystem::path& dir) {
  Manifest manifest;
  std::ifstream in(dir / OutputDirectory::kManifestName);
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind(kCommandLinePrefix, 0) == 0) {
      manifest.command = line.substr(kCommandLinePrefix.size());
    } else if (!line.empty() && line[0] != '#') {
      manifest.names.push_back(line);
    }
  }
  return manifest;
}

// True if 'path' lies where a run's outputs go: directly in 'dir', or in
// its figures/ (symbolic links resolved). A dataset deeper down, as in
// `--out .` with data/x.log, is out of a run's reach.
bool IsWhereOutputsGo(const std::filesystem::path& path, const std::filesystem::path& dir) {
  std::error_code ec;
  const std::filesystem::path file = std::filesystem::weakly_canonical(path, ec);
  if (ec) return false;
  const std::filesystem::path root = std::filesystem::weakly_canonical(dir, ec);
  if (ec) return false;
  const std::filesystem::path parent = file.parent_path();
  return parent == root || parent == root / "figures";
}

// Only plain relative names below the directory: a manifest edited by hand
// must not make a run delete files elsewhere.
bool IsSafeName(const std::string& name) {
  const std::filesystem::path path(name);
  if (name.empty() || path.is_absolute()) return false;
  for (const std::filesystem::path& part : path) {
    if (part == ".." || part == ".") return false;
  }
  return true;
}

bool Contains(const std::vector<std::string>& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

}  // namespace

OutputDirectory::OutputDirectory(const std::filesystem::path& dir, Mode mode,
                                 const std::string& command,
                                 const std::vector<std::filesystem::path>& inputs)
    : dir_(dir), mode_(mode), command_(command) {
  std::error_code ec;
  const Manifest earlier = ReadManifest(dir_);
  earlier_names_ = earlier.names;
  if (mode_ == Mode::kAddFiles) {
    command_ = earlier.command;
  } else {
    for (const std::filesystem::path& input : inputs) {
      if (!input.empty() && std::filesystem::exists(input, ec) && IsWhereOutputsGo(input, dir_)) {
        throw InputError("output directory '" + dir_.string() + "' holds the input '" +
                         input.string() + "', which the run's outputs could replace or remove; " +
                         "choose another --out");
      }
    }
    // Without Scout's list of what it wrote there, every file in the way is
    // the user's: a run into such a directory (or into '/') would replace them.
    if (std::filesystem::is_directory(dir_, ec) &&
        !std::filesystem::exists(dir_ / kManifestName, ec)) {
      for (const auto& entry : std::filesystem::directory_iterator(dir_, ec)) {
        if (entry.path().filename().string().rfind(".scout-", 0) == 0) continue;
        throw InputError("output directory '" + dir_.string() + "' already holds files that " +
                         "Scout did not write (such as '" + entry.path().filename().string() +
                         "'; it has no " + kManifestName +
                         " list), which the run could replace; choose a new or empty --out");
      }
    }
    if (!command_.empty() && !earlier.command.empty() && earlier.command != command_) {
      throw InputError("output directory '" + dir_.string() + "' holds the outputs of `scout " +
                       earlier.command + "` (listed in its " + kManifestName + "), which `scout " +
                       command_ + "` would replace; choose another --out, or delete them first");
    }
  }
  if (std::filesystem::exists(dir_, ec) && !std::filesystem::is_directory(dir_, ec)) {
    throw InputError("output directory '" + dir_.string() +
                     "' is an existing file; expected a directory, or a path to create one");
  }
  created_ = !std::filesystem::exists(dir_, ec);
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
  // A run that failed leaves no trace: not even the directory it made.
  if (!committed_ && created_ && std::filesystem::is_empty(dir_, ec)) {
    std::filesystem::remove(dir_, ec);
  }
}

void OutputDirectory::ReplaceEarlier(const std::string& prefix) {
  replaced_prefixes_.push_back(prefix);
}

std::filesystem::path OutputDirectory::Stage(const std::string& name) {
  names_.push_back(name);
  // Names may hold subdirectories ("figures/a.svg"); the writer expects them.
  std::error_code ec;
  std::filesystem::create_directories((staging_ / name).parent_path(), ec);
  return staging_ / name;
}

void OutputDirectory::Commit() {
  // Check every destination before moving the first file, so that one in the
  // way does not leave the directory half old, half new.
  for (const std::string& name : names_) {
    std::error_code ec;
    const std::filesystem::path destination = dir_ / name;
    const std::filesystem::path parent = destination.parent_path();
    if (std::filesystem::exists(parent, ec) && !std::filesystem::is_directory(parent, ec)) {
      throw InputError("cannot move '" + name + "' into '" + dir_.string() + "': '" +
                       parent.string() + "' is a file, not a directory; nothing was replaced");
    }
    if (std::filesystem::is_directory(std::filesystem::symlink_status(destination, ec))) {
      throw InputError("cannot move '" + name + "' into '" + dir_.string() + "': '" +
                       destination.string() + "' is a directory; nothing was replaced");
    }
  }
  for (const std::string& name : names_) {
    std::error_code ec;
    std::filesystem::create_directories((dir_ / name).parent_path(), ec);
    std::filesystem::rename(staging_ / name, dir_ / name, ec);
    if (ec) {
      throw InputError("cannot move '" + name + "' into '" + dir_.string() + "': " + ec.message());
    }
  }
  std::vector<std::string> manifest = names_;
  for (const std::string& name : earlier_names_) {
    if (Contains(manifest, name) || !IsSafeName(name)) continue;
    const bool replaced =
        std::any_of(replaced_prefixes_.begin(), replaced_prefixes_.end(),
                    [&name](const std::string& prefix) { return name.rfind(prefix, 0) == 0; });
    if (mode_ == Mode::kAddFiles && !replaced) {
      manifest.push_back(name);
      continue;
    }
    std::error_code ec;
    const std::filesystem::path stale = dir_ / name;
    if (!std::filesystem::is_regular_file(std::filesystem::symlink_status(stale, ec))) continue;
    std::filesystem::remove(stale, ec);
    // A subdirectory the earlier run made ("figures") goes when left empty.
    const std::filesystem::path parent = stale.parent_path();
    if (parent != dir_ && std::filesystem::is_empty(parent, ec)) {
      std::filesystem::remove(parent, ec);
    }
  }
  std::string text = command_.empty() ? "" : kCommandLinePrefix + command_ + "\n";
  for (const std::string& name : manifest) text += name + "\n";
  WriteTextFileAtomically(dir_ / kManifestName, text);
  committed_ = true;
}

}  // namespace scout::io
