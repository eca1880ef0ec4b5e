#ifndef SCOUT_IO_REPLAY_REFERENCE_H_
#define SCOUT_IO_REPLAY_REFERENCE_H_

#include <filesystem>
#include <optional>
#include <vector>

#include "scout/geometry/rigid_transform.h"
#include "scout/io/dataset.h"

namespace scout::io {

// The reference pose of every scan of a replayed dataset, where known.
struct ScanReference {
  // Same size as the dataset's scans; nullopt where no reference pose matched.
  std::vector<std::optional<geometry::Rigid2d>> poses;
  int matched = 0;
  // "tum" or "scan-ranges" (how scans were paired with the reference).
  std::string association;
};

// Reads the reference trajectory 'reference' for 'dataset':
// - a TUM file: each scan gets the reference pose nearest in time, within
//   'max_dt_s' (both files must share a time base);
// - a dataset with per-scan poses (a CARMEN log, e.g. a "-corrected" log):
//   scans are paired by identical range readings (ranges printed to
//   'range_resolution_m'), because recordings of one run converted by
//   different tools keep the readings but not the time base.
// The format is detected from the content (a TUM line is eight numbers).
// Throws InputError naming the file when it cannot be read, has no poses, or
// no scan could be paired.
ScanReference LoadScanReference(const Dataset& dataset, const std::filesystem::path& reference,
                                double max_dt_s = 0.02, double range_resolution_m = 0.01);

}  // namespace scout::io

#endif  // SCOUT_IO_REPLAY_REFERENCE_H_
