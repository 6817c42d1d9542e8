#pragma once
/// @file interrupt.h
/// SIGINT, SIGTERM and SIGHUP stop a run cleanly: the handler only records the signal, and
/// the long loops (stepping, rendering) call `check_interrupt`, which throws `Interrupted`;
/// unwinding removes what the run created, and the command line exits with 128 + signal.

#include <stdexcept>
#include <string>

namespace impulse2d::demos {

/// A run stopped by a signal. The message says what was removed.
class Interrupted : public std::runtime_error {
 public:
  /// `signal_number` arrived; `message` says what the run had done and what was removed.
  Interrupted(int signal_number, const std::string& message)
      : std::runtime_error(message), signal_number_(signal_number) {}
  /// SIGINT, SIGTERM or SIGHUP.
  int signal_number() const { return signal_number_; }
  /// 128 + the signal number (130 for SIGINT, 143 for SIGTERM, 129 for SIGHUP).
  int exit_status() const { return 128 + signal_number_; }

 private:
  int signal_number_;
};

/// Installs the recording handler for SIGINT, SIGTERM and SIGHUP (idempotent).
void install_interrupt_handlers();
/// Throws `Interrupted` when one of those signals arrived since the handlers were installed.
void check_interrupt();
/// The signal that arrived (0 when none did).
int pending_signal();
/// "SIGINT", "SIGTERM", "SIGHUP" or "signal N".
std::string signal_name(int signal_number);

}  // namespace impulse2d::demos
