/// @file interrupt.cpp
#include "scene/interrupt.h"

#include <csignal>

namespace impulse2d::demos {
namespace {

volatile std::sig_atomic_t received_signal = 0;

void record_signal(int signal_number) { received_signal = signal_number; }

}  // namespace

void install_interrupt_handlers() {
  struct sigaction action {};
  action.sa_handler = record_signal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = 0;
  for (const int each : {SIGINT, SIGTERM, SIGHUP}) sigaction(each, &action, nullptr);
}

void check_interrupt() {
  const int signal_number = received_signal;
  if (signal_number != 0) {
    throw Interrupted(signal_number, "interrupted by " + signal_name(signal_number));
  }
}

int pending_signal() { return received_signal; }

std::string signal_name(int signal_number) {
  switch (signal_number) {
    case SIGINT:
      return "SIGINT";
    case SIGTERM:
      return "SIGTERM";
    case SIGHUP:
      return "SIGHUP";
    default:
      return "signal " + std::to_string(signal_number);
  }
}

}  // namespace impulse2d::demos
