#include "scout/common/resource_usage.h"

#include <sys/resource.h>

#include <cerrno>
#include <system_error>

namespace scout {

double PeakResidentSetMiB() {
  rusage usage{};
  if (getrusage(RUSAGE_SELF, &usage) != 0) {
    throw std::system_error(errno, std::generic_category(), "getrusage");
  }
  return static_cast<double>(usage.ru_maxrss) / 1024.0;
}

}  // namespace scout
