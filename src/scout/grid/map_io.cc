#include "scout/grid/map_io.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include "scout/common/atomic_file.h"
#include "scout/common/error.h"
#include "scout/common/input_file.h"
#include "scout/common/input_limits.h"
#include "scout/grid/image.h"

namespace scout::grid {
namespace {

namespace fs = std::filesystem;

// map_server's pixel values for the three states, and the thresholds that read
// them back: 205 gives p = 0.196078..., just above free_thresh, hence unknown.
constexpr uint8_t kFreePixel = 254;
constexpr uint8_t kOccupiedPixel = 0;
constexpr uint8_t kUnknownPixel = 205;
constexpr double kDefaultOccupiedThresh = 0.65;
constexpr double kDefaultFreeThresh = 0.196;
// A yaw this small rotates a 100 m map by less than a micrometre.
constexpr double kYawTolerance = 1e-9;

enum class Mode { kTrinary, kScale, kRaw };

// Reads the fields of one map_server YAML, turning every problem into an
// InputError of the form "FILE[:LINE]: field 'NAME': expected ..., got '...'".
class MapYaml {
 public:
  explicit MapYaml(const fs::path& path) : path_(path) {
    RequireRegularFile(path, "a map_server YAML file");
    std::ifstream in(path, std::ios::binary);
    if (!in) Fail("cannot open: permission denied or not a file");
    std::stringstream content;
    content << in.rdbuf();
    std::vector<YAML::Node> documents;
    try {
      documents = YAML::LoadAll(content.str());
    } catch (const YAML::ParserException& e) {
      throw InputError(path.string() + ":" + std::to_string(e.mark.line + 1) +
                       ": invalid YAML: " + e.msg);
    }
    if (documents.size() > 1) {
      Fail("holds " + std::to_string(documents.size()) +
           " YAML documents (separated by '---'); expected one");
    }
    if (!documents.empty()) root_ = documents.front();
    if (!root_.IsMap()) {
      Fail("expected a YAML mapping with 'image', 'resolution' and 'origin'");
    }
    // yaml-cpp keeps the first of two equal keys and any misspelt one without
    // a word: a map placed by the wrong origin would only show in the results.
    std::vector<std::string> seen;
    for (const auto& entry : root_) {
      const std::string key = entry.first.Scalar();
      if (std::find(seen.begin(), seen.end(), key) != seen.end()) {
        Fail("field '" + key + "' given twice; expected each field once");
      }
      seen.push_back(key);
      static const char* const kKeys[] = {"image", "resolution",      "origin",     "negate",
                                          "mode",  "occupied_thresh", "free_thresh"};
      if (std::find(std::begin(kKeys), std::end(kKeys), key) == std::end(kKeys)) {
        Fail("unknown field '" + key +
             "'; expected the map_server fields image, resolution, origin, negate, mode, "
             "occupied_thresh and free_thresh");
      }
    }
  }

  [[noreturn]] void Fail(const std::string& what) const {
    throw InputError(path_.string() + ": " + what);
  }

  [[noreturn]] void FieldError(const std::string& name, const YAML::Node& node,
                               const std::string& expected) const {
    std::string where = path_.string();
    if (node.Mark().line >= 0) where += ":" + std::to_string(node.Mark().line + 1);
    throw InputError(where + ": field '" + name + "': expected " + expected + ", got " +
                     Describe(node));
  }

  // Returns the field, or an undefined node when it is absent and optional.
  YAML::Node Field(const std::string& name, bool required, const std::string& expected) const {
    YAML::Node node = root_[name];
    if (!node.IsDefined() && required) {
      throw InputError(path_.string() + ": field '" + name + "': missing, expected " + expected);
    }
    return node;
  }

  double Number(const std::string& name, const YAML::Node& node,
                const std::string& expected) const {
    double value = 0;
    if (!node.IsScalar() || !YAML::convert<double>::decode(node, value) || !std::isfinite(value)) {
      FieldError(name, node, expected);
    }
    return value;
  }

  std::string String(const std::string& name, bool required, const std::string& expected) const {
    const YAML::Node node = Field(name, required, expected);
    if (!node.IsDefined()) return "";
    if (!node.IsScalar() || node.Scalar().empty()) FieldError(name, node, expected);
    return node.Scalar();
  }

  double Probability(const std::string& name, double default_value) const {
    const std::string expected = "a number in [0, 1]";
    const YAML::Node node = Field(name, false, expected);
    if (!node.IsDefined()) return default_value;
    const double value = Number(name, node, expected);
    if (value < 0.0 || value > 1.0) FieldError(name, node, expected);
    return value;
  }

  const fs::path& path() const { return path_; }

 private:
  static std::string Describe(const YAML::Node& node) {
    if (node.IsSequence()) return "a sequence";
    if (node.IsMap()) return "a mapping";
    if (node.IsNull()) return "nothing";
    return "'" + node.Scalar() + "'";
  }

  fs::path path_;
  YAML::Node root_;
};

bool ReadNegate(const MapYaml& yaml) {
  const std::string expected = "0 or 1";
  const YAML::Node node = yaml.Field("negate", false, expected);
  if (!node.IsDefined()) return false;
  int as_int = -1;
  bool as_bool = false;
  if (node.IsScalar() && YAML::convert<int>::decode(node, as_int) && (as_int == 0 || as_int == 1)) {
    return as_int == 1;
  }
  if (node.IsScalar() && YAML::convert<bool>::decode(node, as_bool)) return as_bool;
  yaml.FieldError("negate", node, expected);
}

Mode ReadMode(const MapYaml& yaml) {
  const std::string expected = "'trinary', 'scale' or 'raw'";
  const std::string mode = yaml.String("mode", false, expected);
  if (mode.empty() || mode == "trinary") return Mode::kTrinary;
  if (mode == "scale") return Mode::kScale;
  if (mode == "raw") return Mode::kRaw;
  yaml.FieldError("mode", yaml.Field("mode", false, expected), expected);
}

Eigen::Vector2d ReadOrigin(const MapYaml& yaml) {
  const std::string expected = "[x, y, yaw] with three numbers";
  const YAML::Node node = yaml.Field("origin", true, expected);
  if (!node.IsSequence() || node.size() != 3) yaml.FieldError("origin", node, expected);
  const double x = yaml.Number("origin", node[0], expected);
  const double y = yaml.Number("origin", node[1], expected);
  if (std::abs(x) > kMaxInputCoordinateM) yaml.FieldError("origin", node[0], "x within +-1e6 m");
  if (std::abs(y) > kMaxInputCoordinateM) yaml.FieldError("origin", node[1], "y within +-1e6 m");
  const double yaw = yaml.Number("origin", node[2], expected);
  // A rotated map would need resampling onto Scout's axis-aligned grid.
  if (std::abs(yaw) > kYawTolerance) {
    yaml.FieldError("origin", node[2], "yaw 0 (rotated maps are not supported)");
  }
  return {x, y};
}

// The state of one pixel by map_server's rules. 'v' is the (RGB-averaged) value.
CellState PixelState(double v, bool negate, Mode mode, double occupied_thresh, double free_thresh) {
  if (negate) v = 255.0 - v;
  double p;
  if (mode == Mode::kRaw) {
    // Raw mode (ROS semantics): the value is the occupancy in percent; anything
    // above 100 (255 = -1 in ROS) is unknown. The percentages are then
    // thresholded like the other modes, because OccupancyMap is ternary.
    if (v > 100.0) return CellState::kUnknown;
    p = v / 100.0;
  } else {
    // Scale mode differs from trinary only between the thresholds, where a
    // ternary map has no graded value: both read as unknown there.
    p = (255.0 - v) / 255.0;
  }
  if (p > occupied_thresh) return CellState::kOccupied;
  if (p < free_thresh) return CellState::kFree;
  return CellState::kUnknown;
}

std::string FormatNumber(double value) {
  // Shortest text that reads back to the same double.
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof(buffer), value);
  return std::string(buffer, result.ptr);
}

std::string YamlQuotedIfNeeded(const std::string& text) {
  const bool plain = !text.empty() && text.find_first_not_of(
                                          "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz"
                                          "0123456789._-+") == std::string::npos;
  if (plain) return text;
  std::string quoted = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') quoted += '\\';
    quoted += c;
  }
  return quoted + "\"";
}

}  // namespace

OccupancyMap ReadMapServerMap(const std::filesystem::path& yaml_path) {
  try {
    const MapYaml yaml(yaml_path);
    const std::string image_name = yaml.String("image", true, "an image file name");
    // Metres per pixel; a building map coarser than 10 m per pixel is a typo.
    const std::string positive = "a positive number of metres per pixel, at most 10";
    const YAML::Node resolution_node = yaml.Field("resolution", true, positive);
    const double resolution = yaml.Number("resolution", resolution_node, positive);
    if (resolution <= 0.0 || resolution > 10.0) {
      yaml.FieldError("resolution", resolution_node, positive);
    }
    const Eigen::Vector2d origin = ReadOrigin(yaml);
    const bool negate = ReadNegate(yaml);
    const double occupied_thresh = yaml.Probability("occupied_thresh", kDefaultOccupiedThresh);
    const double free_thresh = yaml.Probability("free_thresh", kDefaultFreeThresh);
    if (free_thresh > occupied_thresh) {
      yaml.Fail("field 'free_thresh': expected at most occupied_thresh (" +
                FormatNumber(occupied_thresh) + "), got '" + FormatNumber(free_thresh) + "'");
    }
    const Mode mode = ReadMode(yaml);

    const fs::path image_path = yaml_path.parent_path() / image_name;
    Image image;
    try {
      image = ReadImage(image_path);
    } catch (const InputError& e) {
      yaml.Fail(std::string("field 'image': ") + e.what());
    }

    OccupancyMap map;
    map.limits = MapLimits(resolution, origin, image.width, image.height);
    map.cells.assign(static_cast<size_t>(map.limits.num_cells()), CellState::kUnknown);
    const bool has_alpha = image.channels == 2 || image.channels == 4;
    const int color_channels = image.channels >= 3 ? 3 : 1;
    for (int row = 0; row < image.height; ++row) {
      // Image rows run top-down; map rows run up from the min corner.
      const int y = image.height - 1 - row;
      for (int x = 0; x < image.width; ++x) {
        const uint8_t* px = image.at(x, row);
        // A fully transparent pixel says nothing about the world: unknown.
        if (has_alpha && px[image.channels - 1] == 0) continue;
        double sum = 0;
        for (int c = 0; c < color_channels; ++c) sum += px[c];
        map.set({x, y},
                PixelState(sum / color_channels, negate, mode, occupied_thresh, free_thresh));
      }
    }
    return map;
  } catch (const YAML::Exception& e) {
    // Anything yaml-cpp rejects that the checks above did not anticipate.
    throw InputError(yaml_path.string() + ": invalid YAML: " + e.what());
  }
}

void WriteMapServerMap(const OccupancyMap& map, const std::filesystem::path& yaml_path) {
  const MapLimits& limits = map.limits;
  if (map.cells.size() != static_cast<size_t>(limits.num_cells())) {
    throw InputError("cannot write '" + yaml_path.string() + "': map has " +
                     std::to_string(map.cells.size()) + " cells, its limits " +
                     std::to_string(limits.num_cells()));
  }
  const fs::path image_name = yaml_path.stem().string() + ".pgm";
  const fs::path image_path = yaml_path.parent_path() / image_name;
  if (yaml_path.stem().empty() || image_path == yaml_path) {
    throw InputError("cannot write '" + yaml_path.string() +
                     "': expected a YAML file name such as map.yaml");
  }

  Image image;
  image.width = limits.width();
  image.height = limits.height();
  image.channels = 1;
  image.pixels.resize(map.cells.size());
  for (int y = 0; y < limits.height(); ++y) {
    for (int x = 0; x < limits.width(); ++x) {
      const CellState state = map.at({x, y});
      *image.at(x, limits.height() - 1 - y) = state == CellState::kFree       ? kFreePixel
                                              : state == CellState::kOccupied ? kOccupiedPixel
                                                                              : kUnknownPixel;
    }
  }
  // The image first: a YAML on disk never names an image that is not there yet.
  WriteImage(image, image_path);

  std::string yaml = "image: " + YamlQuotedIfNeeded(image_name.string()) + "\n";
  yaml += "resolution: " + FormatNumber(limits.resolution()) + "\n";
  yaml += "origin: [" + FormatNumber(limits.origin().x()) + ", " +
          FormatNumber(limits.origin().y()) + ", 0.0]\n";
  yaml += "negate: 0\n";
  yaml += "occupied_thresh: " + FormatNumber(kDefaultOccupiedThresh) + "\n";
  yaml += "free_thresh: " + FormatNumber(kDefaultFreeThresh) + "\n";
  WriteTextFileAtomically(yaml_path, yaml);
}

}  // namespace scout::grid
