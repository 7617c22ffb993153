// A pool of worker threads that run numbered tasks: each worker takes the next
// queued index when it finishes one, so long and short tasks balance themselves. Threads sleep on
// a condition variable when there is nothing to do; the caller collects results as they finish.
#pragma once

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <deque>
#include <exception>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>
#include <utility>
#include <vector>

namespace fl {

// The number of hardware threads, at least 1.
inline int hardware_workers() {
  return std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

// A lazily read input (a table, an index) made safe to share between workers: the source is
// asked at most once; an empty source stays empty.
template <class T>
std::function<const T&()> shared_once(const std::function<const T&()>& source) {
  if (!source) return source;
  struct State {
    std::once_flag flag;
    const T* value = nullptr;
  };
  auto state = std::make_shared<State>();
  return [state, source]() -> const T& {
    std::call_once(state->flag, [&] { state->value = &source(); });
    return *state->value;
  };
}

template <class Result>
class WorkPool {
 public:
  using Task = std::function<Result(std::size_t)>;

  WorkPool(int threads, Task task) : task_(std::move(task)) {
    threads = std::max(1, threads);
    for (int i = 0; i < threads; ++i) threads_.emplace_back([this] { work(); });
  }
  // The running tasks finish; the queued ones are not started. (std::thread rather than
  // std::jthread: Emscripten's libc++ 13, the browser's build, has no std::jthread.)
  ~WorkPool() {
    {
      std::lock_guard lock(m_);
      closed_ = true;
      stopping_ = true;
    }
    work_cv_.notify_all();
    done_cv_.notify_all();
    for (std::thread& t : threads_) t.join();
  }
  WorkPool(const WorkPool&) = delete;
  WorkPool& operator=(const WorkPool&) = delete;

  int threads() const { return static_cast<int>(threads_.size()); }

  void push(std::size_t index) {
    {
      std::lock_guard lock(m_);
      queue_.push_back(index);
    }
    work_cv_.notify_one();
  }
  // No more tasks will come: the workers end once the queue is empty.
  void close() {
    {
      std::lock_guard lock(m_);
      closed_ = true;
    }
    work_cv_.notify_all();
    done_cv_.notify_all();
  }
  // Forgets the tasks not started (an interrupt); the running ones finish.
  void drop_queued() {
    std::lock_guard lock(m_);
    queue_.clear();
  }
  // Tasks queued or running.
  std::size_t busy() const {
    std::lock_guard lock(m_);
    return queue_.size() + running_;
  }
  // Closed, with nothing queued, running or left to take.
  bool finished() const {
    std::lock_guard lock(m_);
    return closed_ && queue_.empty() && running_ == 0 && results_.empty();
  }

  // Waits up to `timeout` for a result (returns at once if there are some, or if the pool is
  // finished) and takes every result ready. Rethrows a task's exception.
  std::vector<Result> take(std::chrono::milliseconds timeout) {
    std::unique_lock lock(m_);
    done_cv_.wait_for(lock, timeout, [this] {
      return !results_.empty() || error_ || (closed_ && queue_.empty() && running_ == 0);
    });
    if (error_) std::rethrow_exception(std::exchange(error_, nullptr));
    return std::exchange(results_, {});
  }

 private:
  void work() {
    while (true) {
      std::size_t index = 0;
      {
        std::unique_lock lock(m_);
        work_cv_.wait(lock, [this] { return !queue_.empty() || closed_; });
        if (stopping_ || queue_.empty()) return;
        index = queue_.front();
        queue_.pop_front();
        ++running_;
      }
      std::optional<Result> result;
      std::exception_ptr error;
      try {
        result.emplace(task_(index));
      } catch (...) {
        error = std::current_exception();
      }
      {
        std::lock_guard lock(m_);
        --running_;
        if (result) results_.push_back(std::move(*result));
        if (error && !error_) {
          error_ = error;
          queue_.clear();
        }
      }
      done_cv_.notify_all();
    }
  }

  mutable std::mutex m_;
  std::condition_variable work_cv_;
  std::condition_variable done_cv_;
  std::deque<std::size_t> queue_;
  std::size_t running_ = 0;
  bool closed_ = false;
  bool stopping_ = false;  // the pool is being destroyed: workers take no more tasks
  std::vector<Result> results_;
  std::exception_ptr error_;
  Task task_;
  std::vector<std::thread> threads_;  // last: joined (by the destructor) before the rest goes
};

}  // namespace fl
