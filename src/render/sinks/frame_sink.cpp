#include "render/sinks/frame_sink.hpp"

#include <chrono>
#include <stdexcept>

#include "render/sinks/png.hpp"

namespace fl::render {

ThreadedSink::ThreadedSink(std::unique_ptr<FrameSink> inner, std::size_t queue_frames)
    : inner_(std::move(inner)), slots_(queue_frames == 0 ? 1 : queue_frames) {
  if (!inner_) throw std::invalid_argument("ThreadedSink needs a sink to run");
  for (std::size_t i = 0; i < slots_.size(); ++i) free_.push_back(i);
  worker_ = std::thread([this] { run(); });
}

ThreadedSink::~ThreadedSink() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
    ready_.clear();
  }
  changed_.notify_all();
  if (worker_.joinable()) worker_.join();
}

void ThreadedSink::rethrow_error_locked() {
  if (error_) {
    std::exception_ptr e = error_;
    std::rethrow_exception(e);
  }
}

void ThreadedSink::write(const ImageView& frame) {
  std::size_t slot = 0;
  {
    std::unique_lock lock(mutex_);
    if (finished_) throw std::logic_error("a frame was written after the sink was finished");
    rethrow_error_locked();
    if (free_.empty()) {
      const auto start = std::chrono::steady_clock::now();
      changed_.wait(lock, [&] { return !free_.empty() || error_; });
      waiting_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      rethrow_error_locked();
    }
    slot = free_.back();
    free_.pop_back();
  }
  // Copy outside the lock; the slot keeps its buffer from frame to frame.
  copy_into(slots_[slot], frame);
  {
    std::lock_guard lock(mutex_);
    ready_.push_back(slot);
    ++frames_;
  }
  changed_.notify_all();
}

void ThreadedSink::run() {
  for (;;) {
    std::size_t slot = 0;
    {
      std::unique_lock lock(mutex_);
      changed_.wait(lock, [&] { return stopping_ || !ready_.empty(); });
      if (ready_.empty()) return;  // stopping, nothing left
      slot = ready_.front();
      ready_.pop_front();
    }
    try {
      inner_->write(slots_[slot].view());
    } catch (...) {
      std::lock_guard lock(mutex_);
      error_ = std::current_exception();
      ready_.clear();
      changed_.notify_all();
      return;
    }
    {
      std::lock_guard lock(mutex_);
      free_.push_back(slot);
    }
    changed_.notify_all();
  }
}

void ThreadedSink::finish() {
  {
    std::unique_lock lock(mutex_);
    if (finished_) return;
    finished_ = true;
    // Wait for the worker to take every queued frame (or fail).
    changed_.wait(lock, [&] { return free_.size() == slots_.size() || error_; });
    stopping_ = true;
  }
  changed_.notify_all();
  worker_.join();
  {
    std::lock_guard lock(mutex_);
    rethrow_error_locked();
  }
  inner_->finish();
}

std::size_t ThreadedSink::frame_count() const {
  std::lock_guard lock(mutex_);
  return frames_;
}

double ThreadedSink::seconds_waiting() const {
  std::lock_guard lock(mutex_);
  return waiting_;
}

// Here rather than in png.cpp: it is plain text, and a build without PNG still names files.
std::string png_frame_name(const PngSinkOptions& options, int index) {
  std::string number = std::to_string(index);
  if (static_cast<int>(number.size()) < options.digits)
    number.insert(0, static_cast<std::size_t>(options.digits) - number.size(), '0');
  return options.prefix + number + ".png";
}

}  // namespace fl::render
