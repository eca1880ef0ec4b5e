#include "scout/io/replay_reference.h"

#include <fstream>
#include <string>
#include <string_view>
#include <vector>

#include "scout/common/error.h"
#include "scout/common/input_file.h"
#include "scout/io/trajectory_association.h"
#include "scout/io/tum_trajectory.h"

namespace scout::io {
namespace {

// True if the first non-comment line of 'path' starts like a number (CARMEN
// lines start with a message name), or if there is no such line: then the TUM
// reader names the line and says what it expected (8 numbers), whatever the
// line holds.
bool LooksLikeTum(const std::filesystem::path& path) {
  RequireRegularFile(path, "a reference trajectory (TUM file or CARMEN log)");
  std::ifstream in(path);
  if (!in) throw InputError(path.string() + ": cannot open reference trajectory");
  char magic[2] = {0, 0};
  in.read(magic, 2);
  if (in.gcount() == 2 && static_cast<unsigned char>(magic[0]) == 0x1f &&
      static_cast<unsigned char>(magic[1]) == 0x8b) {
    return false;  // gzip: a compressed log or bag
  }
  in.clear();
  in.seekg(0);
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("#ROSBAG", 0) == 0) return false;
    const size_t first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == '#') continue;
    return std::string_view("0123456789+-.%").find(line[first]) != std::string_view::npos;
  }
  return true;
}

std::vector<std::vector<float>> Ranges(const Dataset& d) {
  std::vector<std::vector<float>> ranges;
  ranges.reserve(d.scans.size());
  for (const sensor::LaserScan& s : d.scans) ranges.push_back(s.ranges);
  return ranges;
}

ScanReference FromTum(const Dataset& dataset, const std::filesystem::path& reference,
                      double max_dt_s) {
  const std::vector<StampedPose> poses = ReadTumTrajectory(reference);
  std::vector<StampedPose> scans;
  scans.reserve(dataset.scans.size());
  for (const sensor::LaserScan& s : dataset.scans) scans.push_back({s.time_s, {}});
  ScanReference result;
  result.association = "tum";
  result.poses.resize(dataset.scans.size());
  // AssociateByTime keeps estimate order; scans are time-ordered, so pairs map
  // back to scan indices by a forward walk over equal times.
  const std::vector<PosePair> pairs = AssociateByTime(scans, poses, max_dt_s);
  size_t scan = 0;
  for (const PosePair& p : pairs) {
    while (scan < dataset.scans.size() && dataset.scans[scan].time_s != p.time_s) ++scan;
    if (scan == dataset.scans.size()) break;
    result.poses[scan] = p.reference;
    ++result.matched;
    ++scan;
  }
  return result;
}

ScanReference FromScanRanges(const Dataset& dataset, const std::filesystem::path& reference,
                             double range_resolution_m) {
  const Dataset ref = LoadDataset(reference);
  if (ref.scan_poses.size() != ref.scans.size()) {
    throw InputError(reference.string() +
                     ": reference has no per-scan poses (expected a CARMEN log with poses in its "
                     "laser lines, or a TUM trajectory)");
  }
  ScanReference result;
  result.association = "scan-ranges";
  result.poses.resize(dataset.scans.size());
  for (const auto& [i, j] : MatchScansByRanges(Ranges(dataset), Ranges(ref), range_resolution_m)) {
    result.poses[i] = ref.scan_poses[j];
    ++result.matched;
  }
  return result;
}

}  // namespace

ScanReference LoadScanReference(const Dataset& dataset, const std::filesystem::path& reference,
                                double max_dt_s, double range_resolution_m) {
  ScanReference result = LooksLikeTum(reference)
                             ? FromTum(dataset, reference, max_dt_s)
                             : FromScanRanges(dataset, reference, range_resolution_m);
  if (result.matched == 0) {
    throw InputError(reference.string() + ": no scan of " + dataset.name +
                     " could be paired with a reference pose (" + result.association + ")");
  }
  return result;
}

}  // namespace scout::io
