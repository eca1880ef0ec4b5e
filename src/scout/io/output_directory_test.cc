#include "scout/io/output_directory.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <fstream>
#include <iterator>
#include <random>

#include "scout/common/atomic_file.h"
#include "scout/common/error.h"

namespace scout::io {
namespace {

namespace fs = std::filesystem;

fs::path FreshDir() {
  std::random_device rd;
  const fs::path dir = fs::temp_directory_path() / ("scout_io_test_" + std::to_string(rd()));
  fs::remove_all(dir);
  return dir;
}

// The directory's entries, the manifest aside.
std::vector<std::string> Listing(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) {
    const std::string name = e.path().filename().string();
    if (name != OutputDirectory::kManifestName) names.push_back(name);
  }
  std::sort(names.begin(), names.end());
  return names;
}

TEST(OutputDirectory, CommitMovesEveryStagedFileIntoPlace) {
  const fs::path dir = FreshDir();
  {
    OutputDirectory out(dir);
    WriteTextFileAtomically(out.Stage("a.txt"), "alpha");
    WriteTextFileAtomically(out.Stage("b.txt"), "beta");
    EXPECT_TRUE(Listing(dir).size() == 1u);  // only the staging directory so far
    out.Commit();
  }
  EXPECT_EQ(Listing(dir), (std::vector<std::string>{"a.txt", "b.txt"}));
  std::ifstream in(dir / "a.txt");
  std::string text;
  in >> text;
  EXPECT_EQ(text, "alpha");
  fs::remove_all(dir);
}

TEST(OutputDirectory, StagedNamesMayHoldSubdirectories) {
  const fs::path dir = FreshDir();
  for (const std::string content : {"first", "second"}) {
    OutputDirectory out(dir);
    WriteTextFileAtomically(out.Stage("figures/a.svg"), content);
    out.Commit();
  }
  std::ifstream in(dir / "figures" / "a.svg");
  std::string text;
  std::getline(in, text);
  EXPECT_EQ(text, "second");  // a second run replaces the file in the existing subdirectory
  fs::remove_all(dir);
}

TEST(OutputDirectory, WithoutCommitNothingIsLeftBehind) {
  const fs::path dir = FreshDir();
  fs::create_directories(dir);
  WriteTextFileAtomically(dir / "older.txt", "kept");
  try {
    OutputDirectory out(dir);
    WriteTextFileAtomically(out.Stage("summary.json"), "{}");
    throw InputError("simulated failure half-way");
  } catch (const InputError&) {
  }
  EXPECT_EQ(Listing(dir), (std::vector<std::string>{"older.txt"}));
  fs::remove_all(dir);
  // A directory the failed run created goes too.
  try {
    OutputDirectory out(dir);
    WriteTextFileAtomically(out.Stage("summary.json"), "{}");
    throw InputError("simulated failure half-way");
  } catch (const InputError&) {
  }
  EXPECT_FALSE(fs::exists(dir));
}

// Writes 'names' (each holding 'content') through one committed run.
void CommitRun(const fs::path& dir, const std::vector<std::string>& names,
               const std::string& content,
               OutputDirectory::Mode mode = OutputDirectory::Mode::kReplaceRun) {
  OutputDirectory out(dir, mode);
  for (const std::string& name : names) WriteTextFileAtomically(out.Stage(name), content);
  out.Commit();
}

std::string Contents(const fs::path& path) {
  std::ifstream in(path);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

TEST(OutputDirectory, ANewRunRemovesTheEarlierRunsOutputsItDoesNotRewrite) {
  const fs::path dir = FreshDir();
  CommitRun(dir, {"summary.json", "reference.tum", "figures/a.svg", "figures/b.svg"}, "first");
  WriteTextFileAtomically(dir / "notes.txt", "the user's");
  CommitRun(dir, {"summary.json", "figures/a.svg"}, "second");
  // Only Scout's own earlier files go; the user's stay.
  EXPECT_EQ(Listing(dir), (std::vector<std::string>{"figures", "notes.txt", "summary.json"}));
  EXPECT_EQ(Listing(dir / "figures"), std::vector<std::string>{"a.svg"});
  EXPECT_EQ(Contents(dir / "summary.json"), "second");
  // A run without figures leaves no empty figures directory behind.
  CommitRun(dir, {"summary.json"}, "third");
  EXPECT_EQ(Listing(dir), (std::vector<std::string>{"notes.txt", "summary.json"}));
  fs::remove_all(dir);
}

TEST(OutputDirectory, AddedFilesKeepTheRunAndAreRemovedByTheNextRun) {
  const fs::path dir = FreshDir();
  CommitRun(dir, {"summary.json", "map.png"}, "run");
  CommitRun(dir, {"report.html"}, "report", OutputDirectory::Mode::kAddFiles);
  EXPECT_EQ(Listing(dir), (std::vector<std::string>{"map.png", "report.html", "summary.json"}));
  CommitRun(dir, {"summary.json"}, "rerun");
  EXPECT_EQ(Listing(dir), std::vector<std::string>{"summary.json"});
  // An addition that replaces its own earlier files ("figures/") removes the
  // ones it does not rewrite, and nothing else.
  CommitRun(dir, {"figures/a.svg", "figures/b.svg"}, "report", OutputDirectory::Mode::kAddFiles);
  {
    OutputDirectory out(dir, OutputDirectory::Mode::kAddFiles);
    out.ReplaceEarlier("figures/");
    WriteTextFileAtomically(out.Stage("figures/a.svg"), "again");
    out.Commit();
  }
  EXPECT_EQ(Listing(dir), (std::vector<std::string>{"figures", "summary.json"}));
  EXPECT_EQ(Listing(dir / "figures"), std::vector<std::string>{"a.svg"});
  fs::remove_all(dir);
}

TEST(OutputDirectory, AnotherCommandsRunOrAnInputInsideIsRefusedBeforeAnythingIsWritten) {
  const fs::path dir = FreshDir();
  {
    OutputDirectory out(dir, OutputDirectory::Mode::kReplaceRun, "explore");
    WriteTextFileAtomically(out.Stage("sensor.log"), "FLASER ...");
    out.Commit();
  }
  // A report adds to the exploration and keeps it recorded as one.
  CommitRun(dir, {"report.html"}, "report", OutputDirectory::Mode::kAddFiles);
  const auto error_of = [&](const std::string& command, const std::vector<fs::path>& inputs) {
    try {
      OutputDirectory out(dir, OutputDirectory::Mode::kReplaceRun, command, inputs);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  std::string e = error_of("replay", {});
  EXPECT_NE(e.find("holds the outputs of `scout explore`"), std::string::npos) << e;
  // The exploration's own log replayed into its directory would remove it.
  e = error_of("explore", {dir / "sensor.log"});
  EXPECT_NE(e.find("holds the input '" + (dir / "sensor.log").string() + "'"), std::string::npos)
      << e;
  e = error_of("explore", {dir / "." / "sensor.log"});
  EXPECT_NE(e.find("holds the input"), std::string::npos) << e;
  // Inputs elsewhere (below the directory's own subdirectories included),
  // absent ones and the same command are fine.
  fs::create_directories(dir / "data");
  WriteTextFileAtomically(dir / "data" / "x.log", "FLASER ...");
  EXPECT_EQ(error_of("explore", {dir.parent_path() / "elsewhere.log", dir / "absent.log",
                                 dir / "data" / "x.log"}),
            "");
  fs::remove_all(dir / "data");
  EXPECT_EQ(Listing(dir), (std::vector<std::string>{"report.html", "sensor.log"}));
  fs::remove_all(dir);
}

TEST(OutputDirectory, AManifestNamingFilesOutsideTheDirectoryIsIgnored) {
  const fs::path dir = FreshDir();
  const fs::path outside = FreshDir();
  fs::create_directories(outside);
  WriteTextFileAtomically(outside / "keep.txt", "keep");
  fs::create_directories(dir);
  WriteTextFileAtomically(
      dir / OutputDirectory::kManifestName,
      "../" + outside.filename().string() + "/keep.txt\n" + (outside / "keep.txt").string() + "\n");
  CommitRun(dir, {"summary.json"}, "run");
  EXPECT_TRUE(fs::exists(outside / "keep.txt"));
  fs::remove_all(dir);
  fs::remove_all(outside);
}

TEST(OutputDirectory, RemovesStagingLeftByKilledRuns) {
  const fs::path dir = FreshDir();
  // No process has pid 2^22 + 1 (above Linux's pid_max limit of 2^22).
  const fs::path abandoned = dir / ".scout-staging-4194305";
  fs::create_directories(abandoned);
  WriteTextFileAtomically(abandoned / "summary.json", "{");
  {
    OutputDirectory out(dir);
    out.Commit();
  }
  EXPECT_FALSE(fs::exists(abandoned));
  EXPECT_TRUE(Listing(dir).empty());
  fs::remove_all(dir);
}

TEST(OutputDirectory, RejectsADirectoryThatCannotBeCreated) {
  const fs::path dir = FreshDir();
  fs::create_directories(dir);
  WriteTextFileAtomically(dir / "file", "x");
  // A path below a regular file can never be a directory.
  EXPECT_THROW(OutputDirectory(dir / "file" / "sub"), InputError);
  try {
    OutputDirectory bad(dir / "file" / "sub");
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("file/sub"), std::string::npos) << e.what();
  }
  fs::remove_all(dir);
}

TEST(OutputDirectory, ADirectoryHoldingFilesScoutDidNotWriteIsRefused) {
  const fs::path dir = FreshDir();
  fs::create_directories(dir);
  WriteTextFileAtomically(dir / "summary.json", "precious");
  try {
    OutputDirectory out(dir);
    ADD_FAILURE() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("already holds files that Scout did not write (such as "
                                         "'summary.json'"),
              std::string::npos)
        << e.what();
  }
  std::ifstream in(dir / "summary.json");
  std::string text;
  in >> text;
  EXPECT_EQ(text, "precious");
  // Adding files (a report) to a run directory without the list is allowed.
  OutputDirectory added(dir, OutputDirectory::Mode::kAddFiles);
  fs::remove_all(dir);
}

TEST(OutputDirectory, AnExistingFileIsNamedAsSuch) {
  const fs::path dir = FreshDir();
  fs::create_directories(dir);
  WriteTextFileAtomically(dir / "file", "x");
  try {
    OutputDirectory bad(dir / "file");
    ADD_FAILURE() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("is an existing file"), std::string::npos) << e.what();
  }
  fs::remove_all(dir);
}

TEST(OutputDirectory, ADirectoryInTheWayOfOneFileStopsTheCommitBeforeAnyFileIsReplaced) {
  const fs::path dir = FreshDir();
  {
    OutputDirectory out(dir);
    WriteTextFileAtomically(out.Stage("a.txt"), "old");
    out.Commit();
  }
  fs::create_directories(dir / "report.html");
  OutputDirectory out(dir);
  WriteTextFileAtomically(out.Stage("a.txt"), "new");
  WriteTextFileAtomically(out.Stage("report.html"), "page");
  try {
    out.Commit();
    ADD_FAILURE() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("is a directory; nothing was replaced"), std::string::npos)
        << e.what();
  }
  std::ifstream in(dir / "a.txt");
  std::string text;
  in >> text;
  EXPECT_EQ(text, "old");
  fs::remove_all(dir);
}

}  // namespace
}  // namespace scout::io
