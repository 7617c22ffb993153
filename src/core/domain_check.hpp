// The core's refusals of inputs where a formula means nothing: fl::DomainError with a sentence
// naming the quantity, its value and its unit (never a NaN). Shared by the core's formulas.
#pragma once

#include <cmath>
#include <string>

#include "core/analytic_model.hpp"
#include "text/describe.hpp"

namespace fl {

inline void require_domain(bool ok, const std::string& message) {
  if (!ok) throw DomainError(message);
}

inline void check_positive(double value, const char* name, const char* unit) {
  if (!(std::isfinite(value) && value > 0.0))
    throw DomainError(describe(name, " must be a finite positive number, got ", value, " ", unit));
}

inline void check_non_negative(double value, const char* name, const char* unit) {
  if (!(std::isfinite(value) && value >= 0.0))
    throw DomainError(describe(name, " must be a finite number >= 0, got ", value, " ", unit));
}

}  // namespace fl
