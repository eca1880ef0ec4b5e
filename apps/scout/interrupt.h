#ifndef SCOUT_APPS_SCOUT_INTERRUPT_H_
#define SCOUT_APPS_SCOUT_INTERRUPT_H_

#include <stdexcept>

namespace scout::apps {

// Thrown by ThrowIfInterrupted once SIGINT or SIGTERM arrived: the command
// unwinds like on any error, so its staging directory (and an output
// directory it created) is removed and nothing half-written stays.
class Interrupted : public std::runtime_error {
 public:
  explicit Interrupted(int signal_number);
  int signal_number() const { return signal_number_; }

 private:
  int signal_number_;
};

// SIGINT and SIGTERM set a flag that the long loops poll; a second one of
// either, a second or more after the first, ends the process at once, as
// without the handler (sooner, it is the same request delivered twice).
void InstallInterruptHandler();
void ThrowIfInterrupted();
// The signal that arrived (SIGINT or SIGTERM), or 0: for a command that ends
// its run early and keeps what it has instead of throwing.
int PendingSignal();
// "SIGINT" or "SIGTERM".
const char* SignalName(int signal_number);

}  // namespace scout::apps

#endif  // SCOUT_APPS_SCOUT_INTERRUPT_H_
