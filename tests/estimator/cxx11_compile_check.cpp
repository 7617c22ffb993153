// Compiled by the estimator_cxx11 test as C++11 without exceptions or RTTI, warnings as errors:
// the estimator's headers must stay in the subset the Arduino firmware can use.
#include "estimator/fixed_format.h"
#include "estimator/period_estimator.h"

template class fl_estimator::BasicPeriodEstimator<8, 8, 7>;
template class fl_estimator::BasicPeriodEstimator<16, 4, 3>;

int main() {
  fl_estimator::PeriodEstimator estimator(0.089f, 0.002f, 9.81f);
  uint8_t events = 0;
  for (uint32_t i = 0; i < 100; ++i)
    events = static_cast<uint8_t>(events | estimator.add_sample(i * 1000u, 512));
  events = static_cast<uint8_t>(events | estimator.finish());
  char text[24];
  fl_estimator::format_fixed(text, estimator.stats().period_s, 3);
  fl_estimator::format_uint(text, estimator.pulse_count());
  return events;
}
