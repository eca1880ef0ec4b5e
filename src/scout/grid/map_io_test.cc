#include "scout/grid/map_io.h"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "scout/common/error.h"
#include "scout/grid/image.h"
#include "scout/grid/test_temp_directory.h"

namespace scout::grid {
namespace {

namespace fs = std::filesystem;
using S = CellState;

// Runs 'f' and checks it throws InputError whose message contains every needle.
template <typename F>
void ExpectInputError(F&& f, const std::vector<std::string>& needles) {
  try {
    f();
    ADD_FAILURE() << "expected an InputError";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    for (const std::string& needle : needles) {
      EXPECT_NE(message.find(needle), std::string::npos)
          << "'" << needle << "' not in: " << message;
    }
  }
}

std::string ReadText(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// A 3 x 2 ASCII PGM; top row first: 0 254 205 / 255 100 128.
constexpr char kAsciiPgm[] =
    "P2\n# written by hand\n3 2\n# maxval next\n255\n0 254 205\n255 100 # comment\n128\n";

TEST(MapIo, WriteThenReadPreservesStatesLimitsAndOrigin) {
  const TestTempDirectory dir;
  OccupancyMap map;
  map.limits = MapLimits(0.05, {-12.345678901234, 0.1 + 0.2}, 37, 23);
  map.cells.resize(map.limits.num_cells());
  for (size_t i = 0; i < map.cells.size(); ++i) map.cells[i] = static_cast<S>((i * 7 + i / 5) % 3);
  const fs::path yaml = dir.path() / "office.yaml";
  WriteMapServerMap(map, yaml);

  const OccupancyMap back = ReadMapServerMap(yaml);
  EXPECT_EQ(back.cells, map.cells);
  EXPECT_EQ(back.limits.width(), 37);
  EXPECT_EQ(back.limits.height(), 23);
  EXPECT_EQ(back.limits.resolution(), 0.05);
  EXPECT_EQ(back.limits.origin(), map.limits.origin());

  // map_server layout: the PGM beside the YAML, and no temporary file left over.
  const std::string text = ReadText(yaml);
  EXPECT_NE(text.find("image: office.pgm\n"), std::string::npos) << text;
  EXPECT_NE(text.find("negate: 0\n"), std::string::npos) << text;
  EXPECT_NE(text.find("occupied_thresh: 0.65\n"), std::string::npos) << text;
  EXPECT_NE(text.find("free_thresh: 0.196\n"), std::string::npos) << text;
  EXPECT_NE(text.find(", 0.0]\n"), std::string::npos) << text;
  EXPECT_EQ(std::distance(fs::directory_iterator(dir.path()), fs::directory_iterator()), 2);
  const Image pgm = ReadImage(dir.path() / "office.pgm");
  EXPECT_EQ(ReadText(dir.path() / "office.pgm").substr(0, 2), "P5");
  // Top image row is the max-y map row; map_server's pixel values.
  EXPECT_EQ(*pgm.at(0, 0), map.at({0, 22}) == S::kFree       ? 254
                           : map.at({0, 22}) == S::kOccupied ? 0
                                                             : 205);
}

RC_GTEST_PROP(MapIo, RoundTripPreservesRandomMaps, ()) {
  const TestTempDirectory dir;
  OccupancyMap map;
  map.limits =
      MapLimits(*rc::gen::element(0.05, 0.1, 0.025),
                {*rc::gen::inRange(-5000, 5000) * 0.0137, *rc::gen::inRange(-5000, 5000) * 0.0071},
                *rc::gen::inRange(1, 30), *rc::gen::inRange(1, 30));
  map.cells = *rc::gen::container<std::vector<S>>(
      map.limits.num_cells(), rc::gen::element(S::kUnknown, S::kFree, S::kOccupied));
  WriteMapServerMap(map, dir.path() / "m.yaml");
  const OccupancyMap back = ReadMapServerMap(dir.path() / "m.yaml");
  RC_ASSERT(back.cells == map.cells);
  RC_ASSERT(back.limits.origin() == map.limits.origin());
  RC_ASSERT(back.limits.resolution() == map.limits.resolution());
}

TEST(MapIo, ReadsHandWrittenAsciiPgmWithNegateAndThresholds) {
  const TestTempDirectory dir;
  dir.Write("images/hand.pgm", kAsciiPgm);
  const auto read = [&](const std::string& extra) {
    return ReadMapServerMap(dir.Write(
        "hand.yaml", "image: images/hand.pgm\nresolution: 0.1\norigin: [1.0, -2.0, 0]\n" + extra));
  };
  // Map row 1 is the image's top row.
  const OccupancyMap plain = read("");
  EXPECT_EQ(plain.limits.width(), 3);
  EXPECT_EQ(plain.limits.height(), 2);
  EXPECT_EQ(plain.limits.resolution(), 0.1);
  EXPECT_EQ(plain.limits.origin(), Eigen::Vector2d(1.0, -2.0));
  EXPECT_EQ(plain.cells, (std::vector<S>{S::kFree, S::kUnknown, S::kUnknown,      // 255 100 128
                                         S::kOccupied, S::kFree, S::kUnknown}));  // 0 254 205

  EXPECT_EQ(read("negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n").cells, plain.cells);
  EXPECT_EQ(read("negate: 1\n").cells,
            (std::vector<S>{S::kOccupied, S::kUnknown, S::kUnknown,   // 255 100 128
                            S::kFree, S::kOccupied, S::kOccupied}));  // 0 254 205
  EXPECT_EQ(read("occupied_thresh: 0.5\nfree_thresh: 0.45\nmode: trinary\n").cells,
            (std::vector<S>{S::kFree, S::kOccupied, S::kUnknown,  // 255 100 128
                            S::kOccupied, S::kFree, S::kFree}));  // 0 254 205
}

TEST(MapIo, ReadsSixteenBitBinaryPgm) {
  const TestTempDirectory dir;
  // Big-endian samples 0, 65535, 52685 (= 205 * 257).
  dir.Write("deep.pgm",
            "P5\n# sixteen bit\n3 1\n65535\n" + std::string("\x00\x00\xff\xff\xcd\xcd", 6));
  const OccupancyMap map = ReadMapServerMap(
      dir.Write("deep.yaml", "image: deep.pgm\nresolution: 0.05\norigin: [0, 0, 0]\n"));
  EXPECT_EQ(map.cells, (std::vector<S>{S::kOccupied, S::kFree, S::kUnknown}));
}

TEST(MapIo, ReadsColourPngAveragingRgbAndTreatingTransparencyAsUnknown) {
  const TestTempDirectory dir;
  Image image{.width = 5, .height = 1, .channels = 4, .pixels = {}};
  image.pixels = {0,   0,   0,   255,   // black: occupied
                  255, 255, 255, 255,   // white: free
                  0,   0,   0,   0,     // transparent: unknown
                  255, 0,   0,   255,   // red: mean 85, p = 0.67: occupied
                  255, 255, 0,   255};  // yellow: mean 170, p = 0.33: unknown
  WriteImage(image, dir.path() / "colour.png");
  const OccupancyMap map = ReadMapServerMap(
      dir.Write("colour.yaml", "image: colour.png\nresolution: 0.05\norigin: [0, 0, 0.0]\n"));
  EXPECT_EQ(map.cells,
            (std::vector<S>{S::kOccupied, S::kFree, S::kUnknown, S::kOccupied, S::kUnknown}));
}

TEST(MapIo, RawModeReadsOccupancyPercent) {
  const TestTempDirectory dir;
  dir.Write("raw.pgm", "P2 4 1 255 0 100 255 50\n");
  const OccupancyMap map = ReadMapServerMap(
      dir.Write("raw.yaml", "image: raw.pgm\nmode: raw\nresolution: 0.05\norigin: [0, 0, 0]\n"));
  EXPECT_EQ(map.cells, (std::vector<S>{S::kFree, S::kOccupied, S::kUnknown, S::kUnknown}));
}

TEST(MapIo, BadInputsNameTheFileAndField) {
  const TestTempDirectory dir;
  dir.Write("ok.pgm", kAsciiPgm);
  const std::string good_rest = "resolution: 0.05\norigin: [0, 0, 0]\n";
  const auto expect = [&](const std::string& yaml_text, const std::vector<std::string>& needles) {
    SCOPED_TRACE(yaml_text);
    const fs::path yaml = dir.Write("bad.yaml", yaml_text);
    std::vector<std::string> all = needles;
    all.push_back("bad.yaml");
    ExpectInputError([&] { ReadMapServerMap(yaml); }, all);
  };
  ExpectInputError([&] { ReadMapServerMap(dir.path() / "absent.yaml"); }, {"absent.yaml"});
  expect("image: ok.pgm\norigin: [0, 0, 0]\n", {"'resolution'", "missing"});
  expect("image: ok.pgm\nresolution: 0\norigin: [0, 0, 0]\n", {"'resolution'", "positive"});
  expect("image: ok.pgm\nresolution: -0.05\norigin: [0, 0, 0]\n", {"'resolution'", "'-0.05'"});
  expect("image: ok.pgm\nresolution: fine\norigin: [0, 0, 0]\n", {"'resolution'", "'fine'"});
  expect("image: ok.pgm\nresolution: 1e9\norigin: [0, 0, 0]\n", {"'resolution'", "at most 10"});
  expect("image: ok.pgm\nresolution: 0.05\norigin: [1e300, 0, 0]\n", {"'origin'", "1e6"});
  expect("image: ok.pgm\nresolution: 0.05\norigin: [0, zero, 0]\n", {"'origin'", "'zero'"});
  expect("image: ok.pgm\nresolution: 0.05\norigin: [0, 0]\n", {"'origin'", "[x, y, yaw]"});
  expect("image: ok.pgm\nresolution: 0.05\norigin: [0, 0, 0.5]\n", {"'origin'", "yaw", "0.5"});
  expect(good_rest, {"'image'", "missing"});
  expect("image: nowhere.pgm\n" + good_rest, {"'image'", "nowhere.pgm"});
  expect("image: ok.pgm\nnegate: 2\n" + good_rest, {"'negate'", "'2'"});
  expect("image: ok.pgm\nmode: fancy\n" + good_rest, {"'mode'", "'fancy'"});
  expect("image: ok.pgm\noccupied_thresh: 1.5\n" + good_rest, {"'occupied_thresh'"});
  expect("image: ok.pgm\nfree_thresh: 0.7\n" + good_rest, {"'free_thresh'"});
  expect("image: ok.pgm\nresolution: [0.05\n", {"invalid YAML"});
  expect("- just\n- a list\n", {"mapping"});
  expect("image: ok.pgm\n" + good_rest + "---\nresolution: 0.1\n", {"holds 2 YAML documents"});
  // yaml-cpp would keep the first origin, and drop a misspelt key, silently.
  expect("image: ok.pgm\n" + good_rest + "origin: [1, 1, 0]\n", {"field 'origin' given twice"});
  expect("image: ok.pgm\nresolutoin: 0.1\n" + good_rest, {"unknown field 'resolutoin'"});
  ExpectInputError([&] { ReadMapServerMap(dir.path()); }, {"is a directory"});

  dir.Write("short.pgm", "P5\n4 4\n255\nabc");
  expect("image: short.pgm\n" + good_rest, {"'image'", "short.pgm", "truncated"});
  dir.Write("short2.pgm", "P2\n2 2\n255\n1 2 3");
  expect("image: short2.pgm\n" + good_rest, {"short2.pgm", "truncated"});
  dir.Write("text.pgm", "hello");
  expect("image: text.pgm\n" + good_rest, {"text.pgm", "PGM"});
}

TEST(MapIo, WriteIntoMissingDirectoryFailsNamingTheFile) {
  const TestTempDirectory dir;
  OccupancyMap map;
  map.limits = MapLimits(0.05, {0, 0}, 2, 2);
  map.cells.assign(4, S::kFree);
  ExpectInputError([&] { WriteMapServerMap(map, dir.path() / "no" / "such" / "map.yaml"); },
                   {"map.pgm"});
  map.cells.pop_back();
  ExpectInputError([&] { WriteMapServerMap(map, dir.path() / "map.yaml"); }, {"map.yaml"});
}

}  // namespace
}  // namespace scout::grid
