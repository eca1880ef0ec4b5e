#include "apps/scout/interrupt.h"

#include <signal.h>
#include <time.h>

#include <csignal>
#include <string>

namespace scout::apps {
namespace {

volatile std::sig_atomic_t g_signal = 0;
timespec g_first_signal_time{};

double SecondsSince(const timespec& then) {
  timespec now{};
  clock_gettime(CLOCK_MONOTONIC, &now);  // async-signal-safe
  return static_cast<double>(now.tv_sec - then.tv_sec) + 1e-9 * (now.tv_nsec - then.tv_nsec);
}

// The first signal only sets the flag. A second one ends the process at once,
// as without the handler, unless it comes within a second of the first:
// timeout(1) and kill(1) with a process group deliver one request twice
// (to the process and to its group), which must not cut the run's ending.
void OnSignal(int signal_number) {
  if (g_signal == 0) {
    clock_gettime(CLOCK_MONOTONIC, &g_first_signal_time);
    g_signal = signal_number;
    return;
  }
  if (SecondsSince(g_first_signal_time) < 1.0) return;
  std::signal(signal_number, SIG_DFL);
  std::raise(signal_number);
}

}  // namespace

Interrupted::Interrupted(int signal_number)
    : std::runtime_error(std::string("interrupted by ") + SignalName(signal_number)),
      signal_number_(signal_number) {}

const char* SignalName(int signal_number) { return signal_number == SIGINT ? "SIGINT" : "SIGTERM"; }

int PendingSignal() { return g_signal; }

void InstallInterruptHandler() {
  struct sigaction action {};
  action.sa_handler = OnSignal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = 0;
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

void ThrowIfInterrupted() {
  if (g_signal != 0) throw Interrupted(g_signal);
}

}  // namespace scout::apps
