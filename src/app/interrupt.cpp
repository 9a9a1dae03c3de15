// Signal handlers that only record the signal; the render loop polls it between passes.
#include "app/interrupt.h"

#include <signal.h>

#include <cstring>
#include <initializer_list>

namespace wp {

namespace {

volatile sig_atomic_t received = 0;

void onSignal(int signal) {
  if (received != 0) {
    // Asked twice: stop now, the way the signal itself would have.
    struct sigaction action;
    std::memset(&action, 0, sizeof(action));
    action.sa_handler = SIG_DFL;
    sigaction(signal, &action, nullptr);
    raise(signal);
    return;
  }
  received = signal;
}

}  // namespace

int exitCodeInterrupted(int signal) { return 128 + signal; }

void catchInterrupts() {
  struct sigaction action;
  std::memset(&action, 0, sizeof(action));
  action.sa_handler = onSignal;
  action.sa_flags = SA_RESTART;  // the render goes on to the end of its pass undisturbed
  sigemptyset(&action.sa_mask);
  for (int signal : {SIGINT, SIGTERM}) sigaction(signal, &action, nullptr);
}

int interruptSignal() { return received; }

const char* signalName(int signal) { return signal == SIGINT ? "SIGINT" : signal == SIGTERM ? "SIGTERM" : "a signal"; }

}  // namespace wp
