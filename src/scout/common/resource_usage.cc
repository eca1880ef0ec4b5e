#include "scout/common/resource_usage.h"

#include <sys/resource.h>

namespace scout {

double PeakResidentSetMiB() {
  rusage usage{};
  if (getrusage(RUSAGE_SELF, &usage) != 0) return 0.0;
  return static_cast<double>(usage.ru_maxrss) / 1024.0;
}

}  // namespace scout
