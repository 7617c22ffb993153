// What a front end gives a long job (a comparison's rows, a study's points or cases) beyond its
// request: a flag that asks it to stop (Ctrl-C, SIGTERM), and a call the job makes now and then on
// the thread that started it, on which a front end may look for that signal (Python hears a
// signal on its main thread only). A job asked to stop starts nothing more, keeps what it
// finished, and says it was interrupted.
#pragma once

#include <atomic>
#include <functional>

namespace fl {

struct JobControl {
  const std::atomic<bool>* stop = nullptr;
  std::function<void()> poll;  // on the job's calling thread only; may set `stop`

  // Whether the job has been asked to stop (read from any thread).
  bool stopping() const { return stop != nullptr && stop->load(std::memory_order_relaxed); }
  // On the calling thread: polls, then says whether to stop.
  bool poll_stopping() const {
    if (poll) poll();
    return stopping();
  }
};

}  // namespace fl
