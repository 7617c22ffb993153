// Where finished frames go: PNG files, an MP4 file, or another thread in front of either.
// Every frame given to one sink has the same size.
#pragma once

#include <condition_variable>
#include <cstddef>
#include <deque>
#include <exception>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

#include "render/image.hpp"

namespace fl::render {

class FrameSink {
 public:
  FrameSink() = default;
  FrameSink(const FrameSink&) = delete;
  FrameSink& operator=(const FrameSink&) = delete;
  virtual ~FrameSink() = default;

  // Takes one frame (copied or written before returning; the view may be reused at once).
  virtual void write(const ImageView& frame) = 0;
  // Flushes everything and closes the output; a sink destroyed without finish() leaves no
  // partial output under the final name. Throws on failure.
  virtual void finish() = 0;
  // Frames taken so far.
  virtual std::size_t frame_count() const = 0;
};

// Runs another sink on its own thread behind a bounded queue, so that rendering the next frame
// overlaps encoding the last. write() copies the frame into a free slot, waiting while all
// `queue_frames` slots are full; an error of the inner sink is rethrown by the next write() or
// by finish().
class ThreadedSink final : public FrameSink {
 public:
  ThreadedSink(std::unique_ptr<FrameSink> inner, std::size_t queue_frames = 4);
  ~ThreadedSink() override;

  void write(const ImageView& frame) override;
  void finish() override;
  std::size_t frame_count() const override;

  // How long write() has waited for a free slot in total, seconds (render waiting on encode).
  double seconds_waiting() const;

 private:
  void run();
  void rethrow_error_locked();

  std::unique_ptr<FrameSink> inner_;
  std::vector<Image> slots_;
  std::vector<std::size_t> free_;
  std::deque<std::size_t> ready_;
  mutable std::mutex mutex_;
  std::condition_variable changed_;
  std::exception_ptr error_;
  bool stopping_ = false;
  bool finished_ = false;
  std::size_t frames_ = 0;
  double waiting_ = 0.0;
  std::thread worker_;
};

}  // namespace fl::render
