// How a job ended, and the one exit status every front end gives for it (docs/cli.md): the
// command returns it, the Python module raises or returns by it, the server reports it.
#pragma once

#include <string_view>

namespace fl {

enum class Outcome {
  kDone,         // 0: every result there
  kIncomplete,   // 1: every result there, an extra (a plot) could not be drawn
  kBadInput,     // 2: refused before any work (InputError)
  kFailed,       // 3: a guard stopped a run; a point, a row or a log gave no result
  kInterrupted,  // 128 + the signal: asked to stop, what was done kept
};

// The exit status; `signal` is the one that stopped an interrupted job (SIGINT 2, SIGTERM 15).
int exit_status(Outcome outcome, int signal = 2);

// "done", "incomplete", "bad input", "failed", "interrupted".
std::string_view outcome_name(Outcome outcome);

// The worse of two (a job of many parts ends as its worst part): interrupted, bad input, failed,
// incomplete, done.
Outcome worse(Outcome a, Outcome b);

}  // namespace fl
