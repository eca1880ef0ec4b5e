#ifndef SCOUT_IO_OUTPUT_DIRECTORY_H_
#define SCOUT_IO_OUTPUT_DIRECTORY_H_

#include <filesystem>
#include <string>
#include <vector>

namespace scout::io {

// An output directory that never shows a partial result: files are written
// into a hidden staging directory inside it and moved into place together by
// Commit(). Without Commit() (an error, an interruption) the staging
// directory is removed and the directory holds only what it held before (a
// directory the run created is removed again).
//
// A hidden manifest (kManifestName) lists the files Scout wrote there, so a
// new run into a used directory does not leave an earlier run's outputs
// beside its own (a reference.tum from a run with --reference next to a
// summary.json without one). Files Scout did not write are never touched.
// The manifest also names the command that made the run: another command's
// run there is refused rather than replaced, and so is an output directory
// that holds one of the run's own inputs (a replay of an exploration's
// sensor.log into that exploration's directory would remove the log).
class OutputDirectory {
 public:
  enum class Mode {
    kReplaceRun,  // a run's outputs: Commit() removes Scout's earlier files it did not rewrite
    kAddFiles,    // files added to a run (a report): everything else stays
  };
  static constexpr const char* kManifestName = ".scout-outputs";

  // Creates 'dir' if needed and checks that it is writable, before any long
  // computation starts. Throws InputError naming the directory otherwise,
  // and (kReplaceRun) when 'dir' holds one of 'inputs' (files the run reads;
  // absent ones are ignored) or the outputs of a command other than
  // 'command' ("replay", ...; empty: no check). Staging directories left by
  // runs that were killed are removed.
  explicit OutputDirectory(const std::filesystem::path& dir, Mode mode = Mode::kReplaceRun,
                           const std::string& command = "",
                           const std::vector<std::filesystem::path>& inputs = {});
  ~OutputDirectory();
  OutputDirectory(const OutputDirectory&) = delete;
  OutputDirectory& operator=(const OutputDirectory&) = delete;

  // Returns where to write output 'name' now; registers it for Commit().
  // 'name' may name a subdirectory ("figures/a.svg"), created as needed.
  std::filesystem::path Stage(const std::string& name);
  // kAddFiles: the earlier files whose names start with 'prefix' are this
  // commit's to replace as well (a report's "figures/": a figure it no
  // longer draws must not stay beside the new ones).
  void ReplaceEarlier(const std::string& prefix);
  // Moves every staged file into the directory, then (kReplaceRun) removes
  // the files of the manifest that were not staged, and records the
  // manifest. Throws InputError on failure.
  void Commit();

  const std::filesystem::path& path() const { return dir_; }

 private:
  std::filesystem::path dir_;
  Mode mode_;
  std::string command_;     // the manifest's: this run's, or (kAddFiles) the earlier run's
  bool created_ = false;    // the constructor made 'dir_'
  bool committed_ = false;  // Commit() finished
  std::filesystem::path staging_;
  std::vector<std::string> names_;
  std::vector<std::string> earlier_names_;  // the manifest's when the run began
  std::vector<std::string> replaced_prefixes_;
};

}  // namespace scout::io

#endif  // SCOUT_IO_OUTPUT_DIRECTORY_H_
