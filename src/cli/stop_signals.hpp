// SIGINT and SIGTERM as a request to stop: a sweep hands out no more points, a run ends after its
// current step, and both keep and report what they finished. A second signal ends the process at
// once.
#pragma once

#include <atomic>

namespace fl::cli {

// Set by the first SIGINT or SIGTERM while a StopSignals lives.
const std::atomic<bool>& stop_requested();
// The signal that stopped the work (SIGINT when none has).
int stop_signal();
// The exit status for the signal that stopped the work: 130 for SIGINT, 143 for SIGTERM.
int stop_exit_status();

// Installs the handlers for its lifetime and restores the old ones after.
class StopSignals {
 public:
  StopSignals();
  ~StopSignals();
  StopSignals(const StopSignals&) = delete;
  StopSignals& operator=(const StopSignals&) = delete;

 private:
  void (*old_int_)(int);
  void (*old_term_)(int);
};

}  // namespace fl::cli
