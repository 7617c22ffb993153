#include "lab/logs/live_capture.hpp"

#include <utility>

namespace fl {

LiveCapture::LiveCapture(std::string name, const HallLogOptions& reading)
    : reader_(std::move(name), reading) {}

void LiveCapture::take(const SampleSink& on_sample) {
  for (const LogSample& s : reader_.take()) {
    const bool new_run = s.segment != run_;
    if (new_run) {
      run_ = s.segment;
      samples_.clear();
    }
    samples_.push_back(s);
    if (on_sample) on_sample(s, new_run);
  }
}

bool LiveCapture::line(std::string_view text, bool unfinished, const LineSink& on_line,
                       const SampleSink& on_sample, const ErrorSink& on_error) {
  if (on_line && !on_line(text)) return false;
  ++lines_;
  if (!reading_) return true;
  std::string_view content = text;
  if (content.ends_with('\n')) content.remove_suffix(1);
  try {
    reader_.add_line(content, lines_, unfinished);
  } catch (const InputError& e) {
    if (!on_error) throw;
    reading_ = false;
    on_error(e);
    return true;
  }
  take(on_sample);
  return true;
}

bool LiveCapture::add(std::string_view bytes, bool ended, const LineSink& on_line,
                      const SampleSink& on_sample, const ErrorSink& on_error) {
  pending_.append(bytes);
  std::size_t done = 0;
  bool going = true;
  for (std::size_t end; going && (end = pending_.find('\n', done)) != std::string::npos;
       done = end + 1)
    going = line(std::string_view(pending_).substr(done, end + 1 - done), false, on_line, on_sample,
                 on_error);
  pending_.erase(0, done);
  if (!going) return false;
  // A line that never ends is read once it passes a log line's limit: the reader leaves it out as
  // a line that is no sample, and counts it.
  if (pending_.size() > kMostLogLineBytes || (ended && !pending_.empty())) {
    const std::string rest = std::exchange(pending_, std::string());
    return line(rest, ended, on_line, on_sample, on_error);
  }
  return true;
}

void LiveCapture::finish(const SampleSink& on_sample) {
  if (!reading_) return;
  reader_.finish();
  take(on_sample);
}

}  // namespace fl
