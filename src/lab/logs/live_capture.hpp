// Bytes from the rig's serial port turned into its log's samples as they come: what
// `frictionlab estimate --follow` and the server's live rig both read a port through. Each
// complete line goes, as received, to the caller (for the raw log kept beside), then to the log
// reader (hall_log/hall_log_reader.hpp); the samples of the run being received are kept (a board
// that restarts begins a new run, and the samples before it are dropped). A line that never ends
// (bytes at a wrong baud rate) is read as it stands once it passes a log line's limit, so the
// capture's memory stays bounded however the port misbehaves.
#pragma once

#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "hall_log/hall_log.hpp"
#include "hall_log/hall_log_reader.hpp"
#include "io/input_error.hpp"

namespace fl {

class LiveCapture {
 public:
  // `name` locates the reader's messages (the raw log's file, else the port).
  LiveCapture(std::string name, const HallLogOptions& reading);

  // A line as received ('\n' included, but for an unfinished last one); false stops the capture
  // there (the raw log is full): the line and what follows it are not taken.
  using LineSink = std::function<bool(std::string_view line)>;
  // A sample of the run being received, and whether it begins a new run.
  using SampleSink = std::function<void(const LogSample& sample, bool new_run)>;

  // Why the lines are no Hall log (the reader's located InputError), once.
  using ErrorSink = std::function<void(const InputError& error)>;

  // Takes the bytes a read gave (`ended`: the port closed, and an unfinished last line is read
  // too). Returns false when `on_line` stopped it. When the lines prove to be no Hall log, the
  // reader's InputError (located at the line, which went to `on_line` first) is thrown; or, given
  // `on_error`, handed to it, and the lines after are only handed on, not read.
  bool add(std::string_view bytes, bool ended, const LineSink& on_line, const SampleSink& on_sample,
           const ErrorSink& on_error = {});
  // The end of the capture: the reader's last word (a run it held back), into `on_sample`.
  void finish(const SampleSink& on_sample);
  // From now on lines are only handed to `on_line`, not read (they proved not to be a log).
  void stop_reading() { reading_ = false; }

  const std::vector<LogSample>& samples() const { return samples_; }  // the current run's
  int run() const { return run_; }      // the current run (0: the first)
  int lines() const { return lines_; }  // received so far
  const HallLogReading& reading() const { return reader_.reading(); }

 private:
  void take(const SampleSink& on_sample);
  bool line(std::string_view text, bool unfinished, const LineSink& on_line,
            const SampleSink& on_sample, const ErrorSink& on_error);

  HallLogReader reader_;
  bool reading_ = true;
  std::string pending_;  // the bytes of a line not yet complete
  int lines_ = 0;
  int run_ = 0;
  std::vector<LogSample> samples_;
};

}  // namespace fl
