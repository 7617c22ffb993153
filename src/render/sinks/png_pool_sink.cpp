// PNG frames encoded on a pool of threads, each frame to its own numbered file
// (render/sinks/png.hpp).
#include <algorithm>
#include <condition_variable>
#include <deque>
#include <exception>
#include <filesystem>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <utility>
#include <vector>

#include "render/sinks/png.hpp"

namespace fl::render {
namespace {

class PngPoolSink final : public FrameSink {
 public:
  PngPoolSink(PngSinkOptions options, unsigned threads) : options_(std::move(options)) {
    // The sequential sink prepares the folder: made if missing, an earlier run's frames refused
    // or removed.
    make_png_sink(options_);
    const unsigned n = threads != 0 ? threads : std::max(1u, std::thread::hardware_concurrency());
    slots_.resize(2 * static_cast<std::size_t>(n));
    for (std::size_t i = 0; i < slots_.size(); ++i) free_.push_back(i);
    for (unsigned i = 0; i < n; ++i) workers_.emplace_back([this] { run(); });
  }

  ~PngPoolSink() override {
    {
      std::lock_guard lock(mutex_);
      stopping_ = true;
      queue_.clear();  // destroyed without finish(): the frames not begun are not written
    }
    changed_.notify_all();
    for (std::thread& w : workers_)
      if (w.joinable()) w.join();
  }

  void write(const ImageView& frame) override {
    std::size_t slot = 0;
    int index = 0;
    {
      std::unique_lock lock(mutex_);
      if (finished_) throw std::logic_error("a frame was written after the sink was finished");
      rethrow_error_locked();
      changed_.wait(lock, [&] { return !free_.empty() || error_; });
      rethrow_error_locked();
      slot = free_.back();
      free_.pop_back();
      index = options_.first_index + static_cast<int>(count_++);
    }
    // Copy outside the lock; the slot keeps its buffer from frame to frame.
    copy_into(slots_[slot], frame);
    {
      std::lock_guard lock(mutex_);
      queue_.push_back({slot, index});
    }
    changed_.notify_all();
  }

  void finish() override {
    {
      std::unique_lock lock(mutex_);
      finished_ = true;
      changed_.wait(lock, [&] { return (queue_.empty() && busy_ == 0) || error_; });
      stopping_ = true;
      queue_.clear();
    }
    changed_.notify_all();
    for (std::thread& w : workers_)
      if (w.joinable()) w.join();
    std::lock_guard lock(mutex_);
    rethrow_error_locked();
  }

  std::size_t frame_count() const override {
    std::lock_guard lock(mutex_);
    return count_;
  }

 private:
  struct Job {
    std::size_t slot = 0;
    int index = 0;
  };

  void rethrow_error_locked() const {
    if (error_) std::rethrow_exception(error_);
  }

  void run() {
    for (;;) {
      Job job;
      {
        std::unique_lock lock(mutex_);
        changed_.wait(lock, [&] { return stopping_ || !queue_.empty(); });
        if (queue_.empty()) return;  // stopping, nothing left
        job = queue_.front();
        queue_.pop_front();
        ++busy_;
      }
      std::exception_ptr failed;
      try {
        const std::string name = png_frame_name(options_, job.index);
        write_png((std::filesystem::path(options_.directory) / name).string(),
                  slots_[job.slot].view(), options_.compression);
      } catch (...) {
        failed = std::current_exception();
      }
      {
        std::lock_guard lock(mutex_);
        --busy_;
        free_.push_back(job.slot);
        if (failed && !error_) {
          error_ = failed;
          queue_.clear();
        }
      }
      changed_.notify_all();
    }
  }

  PngSinkOptions options_;
  std::vector<Image> slots_;
  std::vector<std::size_t> free_;
  std::deque<Job> queue_;
  std::vector<std::thread> workers_;
  mutable std::mutex mutex_;
  std::condition_variable changed_;
  std::exception_ptr error_;
  std::size_t count_ = 0;
  int busy_ = 0;
  bool stopping_ = false;
  bool finished_ = false;
};

}  // namespace

std::unique_ptr<FrameSink> make_png_pool_sink(const PngSinkOptions& options, unsigned threads) {
  return std::make_unique<PngPoolSink>(options, threads);
}

}  // namespace fl::render
