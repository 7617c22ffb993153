// A Hall log read for an estimate, with advice that is checked before it is given. When the log
// cannot be read as the request says, each way of reading it the reader's message would suggest
// (hall_log/log_reading_error.hpp: other columns, a sample rate, a time unit) is tried on the same
// text: read, estimated on the request's rig, held to periods and to a rig's T and mu_k. The
// message then names the ways that work with what each gives ("with --columns t,_,adc: T = 0.7900
// s, mu_k 0.287 from 12 periods"), or, when none does, says what was tried instead of advising it.
#pragma once

#include <cstddef>
#include <string>

#include "hall_log/hall_log.hpp"
#include "lab/logs/log_estimate.hpp"

namespace fl {

// A log longer than this is tried on its first kTriedBytes (cut at a line's end), and the advice
// says so ("... from 2652 periods in its first 8 MiB"): 9 minutes of a 1 kHz log of "t_us,adc"
// lines, 35 of values alone, enough periods for any rig, and a dozen ways of reading it cost a few
// seconds however long the log.
inline constexpr std::size_t kTriedBytes = std::size_t{8} << 20;

// As read_hall_log; throws InputError, located as the reader located it, with checked advice.
HallLog read_hall_log_checked(const std::string& path, const HallLogOptions& options,
                              const LogSetUp& set_up);

}  // namespace fl
