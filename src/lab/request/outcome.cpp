#include "lab/request/outcome.hpp"

namespace fl {
namespace {

int severity(Outcome o) {
  switch (o) {
    case Outcome::kDone:
      return 0;
    case Outcome::kIncomplete:
      return 1;
    case Outcome::kFailed:
      return 2;
    case Outcome::kBadInput:
      return 3;
    case Outcome::kInterrupted:
      return 4;
  }
  return 0;
}

}  // namespace

int exit_status(Outcome outcome, int signal) {
  switch (outcome) {
    case Outcome::kDone:
      return 0;
    case Outcome::kIncomplete:
      return 1;
    case Outcome::kBadInput:
      return 2;
    case Outcome::kFailed:
      return 3;
    case Outcome::kInterrupted:
      return 128 + signal;
  }
  return 1;
}

std::string_view outcome_name(Outcome outcome) {
  switch (outcome) {
    case Outcome::kDone:
      return "done";
    case Outcome::kIncomplete:
      return "incomplete";
    case Outcome::kBadInput:
      return "bad input";
    case Outcome::kFailed:
      return "failed";
    case Outcome::kInterrupted:
      return "interrupted";
  }
  return "done";
}

Outcome worse(Outcome a, Outcome b) {
  return severity(a) >= severity(b) ? a : b;
}

}  // namespace fl
