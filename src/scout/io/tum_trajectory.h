#ifndef SCOUT_IO_TUM_TRAJECTORY_H_
#define SCOUT_IO_TUM_TRAJECTORY_H_

#include <filesystem>
#include <vector>

#include "scout/io/trajectory.h"

namespace scout::io {

// TUM RGB-D trajectory format, the input of the usual evaluation tools
// (evo, rpg_trajectory_evaluation): one line per pose,
//   stamp x y z qx qy qz qw
// with z = 0 and the yaw as a rotation about z. Stamps and positions carry 6
// decimals (microseconds, micrometres), the quaternion 9.

// Writes 'trajectory' to 'path' through a temporary file and rename, with a
// leading '#' comment naming the columns. Throws InputError when the directory
// is not writable.
void WriteTumTrajectory(const std::vector<StampedPose>& trajectory,
                        const std::filesystem::path& path);

// Reads a TUM trajectory. Lines starting with '#' and blank lines are skipped.
// The quaternion is normalised (files rounded to few digits are not exactly
// unit) and its yaw kept; z, roll and pitch are ignored. Throws InputError
// naming file:line and what was expected on a line without exactly 8 finite
// numbers or with a zero quaternion, and when the file cannot be opened.
std::vector<StampedPose> ReadTumTrajectory(const std::filesystem::path& path);

}  // namespace scout::io

#endif  // SCOUT_IO_TUM_TRAJECTORY_H_
