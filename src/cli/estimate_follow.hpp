// frictionlab estimate --follow PORT: the live rig. Reads the firmware's serial output (or any
// sketch's lines the log reader reads) from the port as it comes, runs the rig's estimator on
// each sample, prints each period as it is judged with the running T +- dT and mu_k, and writes
// the lines received to --log FILE as they come; at Ctrl-C (or --duration, or the port going
// away) prints the same summary as `estimate LOG` on what was received.
#pragma once

#include <functional>
#include <optional>
#include <string>

#include "hall_log/hall_log.hpp"
#include "hall_log/serial_port.hpp"
#include "lab/logs/log_estimate.hpp"

namespace fl::cli {

struct FollowRequest {
  std::string port;
  double baud = kFirmwareBaud;
  std::string raw_log;               // --log: the lines received ("" : none)
  std::optional<double> duration_s;  // --duration
  LogSetUp set_up;
  HallLogOptions reading;
  bool json = false;
  std::string plot;
  std::function<void(const HallLog&, const LogEstimate&, const std::string&)> draw_plot;
};

// Returns the exit status: 0 with a period, 2 (an InputError thrown) without.
int follow_rig(const FollowRequest& request);

}  // namespace fl::cli
