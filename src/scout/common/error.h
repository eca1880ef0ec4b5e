#ifndef SCOUT_COMMON_ERROR_H_
#define SCOUT_COMMON_ERROR_H_

#include <stdexcept>
#include <string>

namespace scout {

// Bad input from a user: a file, a field, an option or a value that is not what
// was expected. The message names the file/line/key and what was expected; the
// command line turns it into a one-line error and exit code 2.
class InputError : public std::runtime_error {
 public:
  explicit InputError(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace scout

#endif  // SCOUT_COMMON_ERROR_H_
