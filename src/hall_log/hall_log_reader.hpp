// Reads a Hall-sensor log line by line, as a file is read or as a serial port delivers it, and
// gives its samples in time order. What comes before the first line that is the header or a
// sample (a serial monitor's banner, the bytes a board's reset leaves) is skipped and counted;
// comment lines ('#', the rig firmware's notes) are left out. After that, a line that is not a
// sample (corrupted in transit), a time that repeats the previous one (millis() read twice in one
// millisecond) and a time out of order (going back, or one that jumped ahead of the next) are
// left out, counted and located; finish() refuses a log where they are more than 10 % of the
// lines. A second header (the board restarted) starts a new segment.
//
// The columns come from the header's names, from `--columns`, or, without either, by position
// (time then value). The time's unit comes from `--time-unit`, from the column's name, or from
// the interval between samples (the unit that makes the sample rate 20 Hz to 20 kHz); with
// `--rate` the samples are timed by their count and any time column is ignored.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "hall_log/log_columns.hpp"
#include "tracking/plate_tracker.hpp"

namespace fl {

struct HallLogOptions {
  std::string columns;    // the request's `columns` ("" : the header's names, or by position)
  double rate_hz = 0.0;   // --rate (0: the log's time column)
  std::string time_unit;  // `time_unit`: "s", "ms" or "us" ("" : the name's, or inferred)
  TrackOptions video;     // how a video's plate is tracked (its region, its scale)
};

// Lines of one kind: how many, and the first few (1-based).
struct LineTally {
  static constexpr std::size_t kShown = 5;
  int count = 0;
  std::vector<int> first;
  void add(int line);
};

// How the log was read and what was left out of it.
struct HallLogReading {
  std::string format = "csv";  // "firmware" (the rig firmware's capture) or "csv"
  std::string columns_from;    // "header", "columns" (the field) or "position"
  std::string time_column;     // the names of the two columns used ("" with a rate)
  std::string adc_column;
  std::string time_unit;              // "s", "ms" or "us" ("" with a rate)
  std::string time_unit_from;         // "header", "time_unit", "inferred" or "rate" (fields)
  double rate_hz = 0.0;               // --rate, when given
  int header_line = 0;                // 1-based; 0 without a header
  int first_line = 0;                 // the header or the first sample: where the log starts
  int lines_skipped = 0;              // lines before it (a banner, reset garbage)
  int comment_lines = 0;              // '#' lines
  LineTally corrupted;                // lines after the start that are not samples
  LineTally repeated_times;           // samples whose time repeats the previous one's
  LineTally out_of_order;             // samples whose time goes back or jumped ahead
  int data_lines = 0;                 // lines after the start that should be samples
  bool ide_timestamps = false;        // the Arduino IDE's "HH:MM:SS.mmm -> " prefixes removed
  bool decimal_comma = false;         // numbers written with a decimal comma
  int clock_wraps = 0;                // a 32-bit microsecond clock wrapped around
  int segments = 0;                   // runs of samples (a header again: the board restarted)
  bool unfinished_last_line = false;  // a cut-off last line left out
};

struct LogSample {
  double t_s = 0.0;  // on the log's own time axis (wraps undone) [s]
  std::uint16_t adc = 0;
  int line = 0;
  int segment = 0;  // 0 for the first run of samples
};

class HallLogReader {
 public:
  // `name` stands for the log in messages. Throws InputError for options that cannot be used.
  HallLogReader(std::string name, HallLogOptions options);

  // The next line (without its '\n'; a trailing '\r' is allowed), numbered from 1. `unfinished`:
  // the input ended in this line without a newline. Throws InputError for a log that cannot be
  // read (a header without a value column, no way to tell the columns or the time).
  void add_line(std::string_view line, int number, bool unfinished = false);

  // The input ended: gives what is still held back. Throws InputError when no sample was read or
  // the lines left out are more than 10 % of the log.
  void finish();

  // Samples completed since the last call, in time order (a sample is held back until the next
  // one confirms its time, and while the time's unit is still being inferred).
  std::vector<LogSample> take();
  // The same appended to `into` (a caller reading many lines keeps one buffer).
  void take(std::vector<LogSample>& into);

  const HallLogReading& reading() const { return reading_; }
  const std::string& name() const { return name_; }

 private:
  struct Raw {
    double t = 0.0;        // unwrapped, in the column's unit
    double reading = 0.0;  // as written
    double offset = 0.0;   // the wrap offset in force before it
    std::uint16_t adc = 0;
    int line = 0;
    int column = 0;  // of the time field
  };

  // A line that is not a sample, or a sample whose time is out of place: where and why.
  struct Problem {
    int line = 0;
    int column = 0;
    std::string what;
  };
  // Headerless logs: lines of numbers that may begin the log, confirmed by the next ones.
  struct Candidate {
    std::string text;
    std::size_t offset = 0;  // the length of a prefix taken off it
    int number = 0;
    std::size_t fields = 0;
    char delimiter = 0;
  };

  bool start(std::string_view text, std::size_t offset, int number);
  // The Arduino IDE's Serial Plotter format, "t:0<TAB>Hall:693": the labels as a header and the
  // values as a line of the log; nothing for a line of another format.
  struct PlotterLine {
    std::string header;
    std::string values;
  };
  static std::optional<PlotterLine> plotter_line(std::string_view content);
  bool try_header(std::string_view text, int number);
  void start_by_position();
  void set_unit();
  void skip(std::string_view text);
  bool is_header_again(std::string_view content) const;
  void data_line(std::string_view text, std::size_t offset, int number, bool unfinished);
  void timed(double reading, std::uint16_t adc, int line, int column);
  void confirm(const Raw& sample);
  void emit(double t, std::uint16_t adc, int line);
  void infer_unit();
  void new_segment();
  void check_shares() const;

  std::string name_;
  HallLogOptions options_;
  HallLogReading reading_;
  bool started_ = false;
  bool plotter_ = false;  // the log is in the Serial Plotter's label:value format
  // A line before the log that reads like a header but names no time column: a banner when a
  // header or samples of another shape follow it ("Hall rig ready"), else the log's header, and
  // its message the log's error.
  struct DoubtfulHeader {
    std::string problem;
    std::string advice;
    int number = 0;
    std::size_t fields = 0;
    char delimiter = 0;
  };
  std::optional<DoubtfulHeader> doubtful_;
  [[noreturn]] void throw_doubtful() const;
  char delimiter_ = 0;
  ColumnLayout layout_;
  std::string header_text_;    // the header as written, to recognise it again
  std::string first_skipped_;  // the first line skipped before the log, for messages
  std::vector<Candidate> candidates_;
  Problem first_corrupted_;
  Problem first_repeated_;
  Problem first_out_of_order_;

  // Time order.
  std::optional<Raw> pending_;
  std::optional<Raw> confirmed_;
  double wrap_offset_ = 0.0;
  long long rate_index_ = 0;

  // Unit.
  double scale_ = 0.0;  // seconds per unit; 0 while being inferred
  std::vector<Raw> held_;

  std::vector<LogSample> out_;
  // The samples given so far and the time they span [s], for the rate the log's clock gives.
  long long emitted_ = 0;
  double span_s_ = 0.0;
  int lines_at_time_ = 1;  // lines whose time is the last one read (it and its repeats)
  double last_t_s_ = 0.0;
  int last_segment_ = 0;
  int segment_ = 0;
  int segment_samples_ = 0;
};

}  // namespace fl
