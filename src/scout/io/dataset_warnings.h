#ifndef SCOUT_IO_DATASET_WARNINGS_H_
#define SCOUT_IO_DATASET_WARNINGS_H_

// Internal to the dataset readers (C++17-compatible: the bag reader uses it).

#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include "scout/common/format.h"

namespace scout::io {

// Collects reader warnings into a Dataset's list, keeping the first few of
// each kind verbatim and summarising the rest: a log whose every tenth line
// is odd should not produce thousands of warnings.
class DatasetWarnings {
 public:
  explicit DatasetWarnings(std::vector<std::string>* out, std::size_t listed_per_kind = 10)
      : out_(out), listed_per_kind_(listed_per_kind) {}

  // Records 'message' under 'kind' (a short plural noun phrase, e.g.
  // "malformed lines"); listed only while fewer than the cap of that kind were.
  void Add(const std::string& kind, const std::string& message) {
    if (counts_[kind]++ < listed_per_kind_) out_->push_back(message);
  }

  // Returns how many warnings of 'kind' were recorded, listed or not.
  std::size_t Count(const std::string& kind) const {
    const auto it = counts_.find(kind);
    return it == counts_.end() ? 0 : it->second;
  }

  // Appends "<source>: N more <kind> not listed (M in total)" for every kind
  // that exceeded the cap.
  void Finish(const std::string& source) {
    for (const auto& [kind, count] : counts_) {
      if (count <= listed_per_kind_) continue;
      out_->push_back(source + ": " + std::to_string(count - listed_per_kind_) + " more " + kind +
                      " not listed (" + std::to_string(count) + " in total)");
    }
  }

 private:
  std::vector<std::string>* out_;
  std::size_t listed_per_kind_;
  std::map<std::string, std::size_t> counts_;
};

}  // namespace scout::io

#endif  // SCOUT_IO_DATASET_WARNINGS_H_
