#ifndef SCOUT_COMMON_RESOURCE_USAGE_H_
#define SCOUT_COMMON_RESOURCE_USAGE_H_

namespace scout {

// Returns the peak resident set size of this process so far, in MiB
// (getrusage's ru_maxrss, which Linux reports in KiB). Throws
// std::system_error if the kernel refuses the query.
double PeakResidentSetMiB();

}  // namespace scout

#endif  // SCOUT_COMMON_RESOURCE_USAGE_H_
