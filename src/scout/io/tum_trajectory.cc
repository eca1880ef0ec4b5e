#include "scout/io/tum_trajectory.h"

#include <array>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include "scout/common/atomic_file.h"
#include "scout/common/error.h"
#include "scout/common/input_file.h"

namespace scout::io {
namespace {

constexpr int kTumColumns = 8;

// Parses the 8 numbers of a TUM line into 'values'; returns false unless the
// line holds exactly 8 finite numbers.
bool ParseTumLine(const std::string& line, std::array<double, kTumColumns>& values) {
  const char* p = line.c_str();
  for (int i = 0; i < kTumColumns; ++i) {
    char* end = nullptr;
    errno = 0;
    const double v = std::strtod(p, &end);
    if (end == p || errno == ERANGE || !std::isfinite(v)) return false;
    values[i] = v;
    p = end;
  }
  while (*p == ' ' || *p == '\t' || *p == '\r') ++p;
  return *p == '\0';
}

}  // namespace

void WriteTumTrajectory(const std::vector<StampedPose>& trajectory,
                        const std::filesystem::path& path) {
  std::string text = "# timestamp tx ty tz qx qy qz qw\n";
  char line[256];
  for (const StampedPose& s : trajectory) {
    const double half_yaw = 0.5 * s.pose.theta();
    std::snprintf(line, sizeof(line), "%.6f %.6f %.6f %.6f %.9f %.9f %.9f %.9f\n", s.time_s,
                  s.pose.x(), s.pose.y(), 0.0, 0.0, 0.0, std::sin(half_yaw), std::cos(half_yaw));
    text += line;
  }
  WriteTextFileAtomically(path, text);
}

std::vector<StampedPose> ReadTumTrajectory(const std::filesystem::path& path) {
  RequireRegularFile(path, "a TUM trajectory file");
  std::ifstream in(path);
  if (!in) throw InputError(path.string() + ": cannot open TUM trajectory file");
  std::vector<StampedPose> trajectory;
  std::string line;
  int line_number = 0;
  while (std::getline(in, line)) {
    ++line_number;
    const size_t first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == '#') continue;
    const std::string where = path.string() + ":" + std::to_string(line_number) + ": ";
    std::array<double, kTumColumns> v{};
    if (!ParseTumLine(line, v)) {
      throw InputError(where + "expected 8 finite numbers 'stamp x y z qx qy qz qw', got '" + line +
                       "'");
    }
    const double qx = v[4], qy = v[5], qz = v[6], qw = v[7];
    const double norm = std::sqrt(qx * qx + qy * qy + qz * qz + qw * qw);
    if (norm < 1e-9) throw InputError(where + "expected a non-zero quaternion qx qy qz qw");
    // Yaw of the normalised quaternion (ZYX Euler convention); dividing both
    // atan2 arguments by norm^2 would not change the angle.
    const double yaw =
        std::atan2(2.0 * (qw * qz + qx * qy), norm * norm - 2.0 * (qy * qy + qz * qz));
    trajectory.push_back({v[0], geometry::Rigid2d(v[1], v[2], yaw)});
  }
  return trajectory;
}

}  // namespace scout::io
