#include "lab/logs/checked_reading.hpp"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "hall_log/log_reading_error.hpp"
#include "io/input_error.hpp"
#include "text/said.hpp"

namespace fl {
namespace {

// The first `most` bytes of a log's text, cut after a line's end (a UTF-16 one's two bytes), or
// the whole text when it is no longer.
std::string_view first_lines(std::string_view bytes, std::size_t most) {
  if (bytes.size() <= most) return bytes;
  std::size_t end = bytes.rfind('\n', most - 1);
  if (end == std::string_view::npos) return bytes.substr(0, most);
  ++end;
  if (end < bytes.size() && bytes[end] == '\0' && end % 2 == 1) ++end;  // UTF-16LE's "\n\0"
  return bytes.substr(0, end);
}

// What one way of reading gives, or nothing when it gives no rig's estimate. A long log is tried
// on its first kTriedBytes, so that a dozen ways cost a few reads of that, not of the whole.
std::optional<std::string> outcome_of(const LogText& text, const ReadingTry& reading,
                                      const LogSetUp& set_up) {
  try {
    const std::string_view tried = first_lines(text.bytes, kTriedBytes);
    const HallLog log = parse_hall_log(tried, text.file, reading.options);
    const LogEstimate est = estimate_log(log, set_up, false);
    require_periods(log, est, "");
    require_plausible(log, est, "");
    const fl_estimator::Stats& s = est.stats;
    return fmt::format("with {}: T = {:.4f} s, mu_k {:.3f} from {} period{}{}{}", reading.words,
                       static_cast<double>(s.period_s), static_cast<double>(s.mu_k), s.periods_used,
                       s.periods_used == 1 ? "" : "s",
                       tried.size() < text.bytes.size()
                           ? fmt::format(" in its first {} MiB", kTriedBytes >> 20)
                           : std::string(),
                       reading.caveat.empty() ? "" : " (" + reading.caveat + ")");
  } catch (const InputError&) {
    return std::nullopt;
  }
}

}  // namespace

HallLog read_hall_log_checked(const std::string& path, const HallLogOptions& options,
                              const LogSetUp& set_up) {
  if (std::optional<HallLog> other = read_if_not_text(path, options)) return std::move(*other);
  const LogText text = read_log_text(path);
  try {
    HallLog log = parse_hall_log(text.bytes, text.file, options);
    if (path != "-") log.path = path;
    return log;
  } catch (const LogReadingError& e) {
    if (e.tries().empty()) throw;
    std::vector<std::string> working;
    std::vector<std::string> tried;
    for (const ReadingTry& t : e.tries()) {
      tried.push_back(t.words);
      if (std::optional<std::string> found = outcome_of(text, t, set_up))
        working.push_back(std::move(*found));
    }
    if (!working.empty())
      throw InputError(
          e.where(), fmt::format("{}; the log reads {}", e.problem(), fmt::join(working, "; or ")));
    const std::string words = fmt::format("{}", fmt::join(tried, ", "));
    if (e.problem_said())
      throw InputError(e.where(), said(tried.size() == 1 ? "reading-tried-one" : "reading-tried",
                                       {arg("problem", *e.problem_said()), arg("tried", words)}));
    throw InputError(e.where(),
                     fmt::format("{}; tried {} on it: {} of a rig; is it the rig's Hall log, "
                                 "captured whole?",
                                 e.problem(), words,
                                 tried.size() == 1 ? "it gives no period" : "none gives a period"));
  }
}

}  // namespace fl
