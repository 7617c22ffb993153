// The live rig (docs/web-api.md, "The live rig"): the rig's board, an Arduino sending Hall samples
// over one serial port, read on its own thread as
// `frictionlab estimate --follow` reads it. Every line received is kept as received (the raw log
// the page downloads, and written line by line into a record folder when the server has one),
// and read as a Hall log; the samples of the board's current run are kept for the pages, each of
// which runs the rig's estimator on them with its own spacing (serve/board_watch.hpp).
#pragma once

#include <atomic>
#include <cstddef>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "hall_log/hall_log_reader.hpp"
#include "hall_log/serial_port.hpp"
#include "io/appending_file.hpp"
#include "lab/logs/live_capture.hpp"
#include "text/said.hpp"

namespace fl::serve {

// The most bytes of a rig's log a lab keeps, unless told otherwise: about 55 minutes of the
// firmware's 1 kHz lines.
inline constexpr std::size_t kMostRigLogBytes = std::size_t{64} << 20;

struct BoardFeedStatus {
  std::string port;
  int baud = 0;
  // "waiting" (open, nothing yet), "receiving", "unplugged" (the port went away), "failed" (it
  // could not be opened, or its lines are not a Hall log), "closed" (closed by a page or the
  // server's end), "full" (the log reached its size limit).
  std::string state;
  std::optional<std::string> message;  // what happened and what to do; none while all is well
  std::optional<Said> said;            // the message as the catalogues say it, where they do
  int lines = 0;
  std::string log_name;  // the raw log's name for its download ("" before a line came)
};

class BoardFeed {
 public:
  // Opens `port` at `baud` and reads it until close() or the port going away. `record_dir`: a
  // folder the raw log is also written into, line by line as it comes ("" : none). A port that
  // cannot be opened gives a feed in state "failed" saying why. `most_log_bytes` bounds the log
  // kept (and so the samples): past it the feed closes the port, saying so.
  BoardFeed(std::string port, int baud, std::string record_dir, std::size_t most_log_bytes);
  // A port read by someone else (the page's Web Serial, in the browser's build), whose bytes come
  // through feed(); `port` names it for the page.
  struct FedFromOutside {};
  BoardFeed(FedFromOutside, std::string port, int baud, std::size_t most_log_bytes);
  ~BoardFeed();
  BoardFeed(const BoardFeed&) = delete;
  BoardFeed& operator=(const BoardFeed&) = delete;

  // Stops reading and closes the port and the record file; the log and samples stay.
  void close();
  // The bytes a port fed from outside gave (`ended`: the port went away after them). False, and
  // nothing taken, once the feed has ended (closed, unplugged, full); false too when these bytes
  // filled the log or ended the port.
  bool feed(std::string_view bytes, bool ended);

  BoardFeedStatus status() const;
  // Every line received, as received.
  std::string raw_log() const;
  // Where the raw log is being written ("" : nowhere).
  std::string record_path() const;

  // The current run's samples from index `from` on (from 0 when `run` is not the current run:
  // the board restarted), with the run's number and its sample count.
  struct Slice {
    int run = 0;
    std::size_t first = 0;  // the index of samples[0] in the run
    std::vector<LogSample> samples;
  };
  Slice samples_from(int run, std::size_t from) const;

 private:
  void read_port();
  // The bytes of one read, the feed ended when the port `ended` or the log is full (saying so);
  // false when it has ended.
  bool take(std::string_view bytes, bool ended);
  // The bytes a read gave into the log, the record and the capture (lab/logs/live_capture.hpp:
  // complete lines; all of them when the port `ended`); false when the log is full.
  bool lines_in(std::string_view bytes, bool ended);
  void record(std::string_view bytes);
  void end(const std::string& state, const Said& message);

  mutable std::mutex mutex_;
  BoardFeedStatus status_;
  std::string log_;
  std::size_t most_log_bytes_;
  std::string record_dir_;
  std::string record_path_;
  std::unique_ptr<AppendingFile> record_;
  bool record_failed_ = false;
  LiveCapture capture_;  // the lines read into samples (the current run's kept)
  std::unique_ptr<SerialPort> port_;
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

}  // namespace fl::serve
