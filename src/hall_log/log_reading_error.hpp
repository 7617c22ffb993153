// A Hall log the reader cannot use as told, with what might read it: each try a set of reading
// options and the words that ask for it (field_ref mentions, "--rate 1kHz" on the command line).
// Its message is the problem and the advice, as written; a caller that can estimate the log
// (lab/logs/checked_reading) tries each on the log first and gives only the advice that works.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "hall_log/hall_log_reader.hpp"
#include "io/input_error.hpp"
#include "text/said.hpp"

namespace fl {

struct ReadingTry {
  HallLogOptions options;  // in place of the request's
  std::string words;       // "--columns t,adc,_"
  std::string caveat;      // what the try assumes, said with what it gives ("" for nothing)
};

class LogReadingError : public InputError {
 public:
  LogReadingError(SourceLocation where, std::string problem, std::string advice,
                  std::vector<ReadingTry> tries)
      : InputError(where, problem + "; " + advice),
        problem_(std::move(problem)),
        advice_(std::move(advice)),
        tries_(std::move(tries)) {}
  // The same, its problem said in the catalogues (its advice, in English, is the command line's).
  LogReadingError(SourceLocation where, const Said& problem, std::string advice,
                  std::vector<ReadingTry> tries)
      : LogReadingError(std::move(where), english(problem), std::move(advice), std::move(tries)) {
    problem_said_ = problem;
  }

  const std::string& problem() const { return problem_; }
  const std::optional<Said>& problem_said() const { return problem_said_; }
  const std::string& advice() const { return advice_; }
  const std::vector<ReadingTry>& tries() const { return tries_; }

 private:
  std::string problem_;
  std::string advice_;
  std::vector<ReadingTry> tries_;
  std::optional<Said> problem_said_;
};

}  // namespace fl
