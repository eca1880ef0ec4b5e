#ifndef SCOUT_COMMON_INPUT_LIMITS_H_
#define SCOUT_COMMON_INPUT_LIMITS_H_

namespace scout {

// Coordinates read from users' files and options (metres) beyond this are
// corrupt or typos: 1000 km. A pose that far out would make a submap grow
// without bound, and grid cell arithmetic at 5 cm loses precision there.
inline constexpr double kMaxInputCoordinateM = 1e6;

}  // namespace scout

#endif  // SCOUT_COMMON_INPUT_LIMITS_H_
