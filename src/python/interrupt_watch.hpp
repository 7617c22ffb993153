// Ctrl-C during a long call: Python's own handler only notes the signal, and only the main
// thread with the GIL can see it. The call, having released the GIL, asks now and then (check());
// the first time Python has an exception (KeyboardInterrupt) the work is told to stop, and the
// exception is raised (raise()) once the work has kept what it did.
#pragma once

#include <atomic>
#include <memory>

#include <pybind11/pybind11.h>

#include "lab/run/job_control.hpp"

namespace fl::python {

namespace py = pybind11;

class InterruptWatch {
 public:
  void check() {
    if (interrupted_) return;
    const py::gil_scoped_acquire gil;
    if (PyErr_CheckSignals() != 0) {
      error_ = std::make_unique<py::error_already_set>();
      interrupted_ = true;
      stop_.store(true);
    }
  }
  const std::atomic<bool>* flag() const { return &stop_; }
  // The flag, and check() as the job's poll.
  JobControl control() {
    return JobControl{&stop_, [this] { check(); }};
  }
  // Raises what Python had (KeyboardInterrupt), if it had anything.
  void raise() {
    if (error_) {
      error_->restore();
      error_.reset();
      throw py::error_already_set();
    }
  }

 private:
  std::atomic<bool> stop_{false};
  bool interrupted_ = false;
  std::unique_ptr<py::error_already_set> error_;
};

}  // namespace fl::python
