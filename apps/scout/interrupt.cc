#include "apps/scout/interrupt.h"

#include <signal.h>

#include <csignal>
#include <string>

namespace scout::apps {
namespace {

volatile std::sig_atomic_t g_signal = 0;

void OnSignal(int signal_number) { g_signal = signal_number; }

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
  // The default action comes back after the first signal.
  action.sa_flags = SA_RESETHAND;
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

void ThrowIfInterrupted() {
  if (g_signal != 0) throw Interrupted(g_signal);
}

}  // namespace scout::apps
