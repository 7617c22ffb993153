// A measured value with its uncertainty as the lab prints it, "0.2948 +- 0.0021": `decimals`
// after the point, more where the uncertainty would print as zero, so that it always shows two
// significant digits ("0.29482 +- 0.000013", never "0.2948 +- 0.0000").
#pragma once

#include <string>

namespace fl {

std::string plus_minus(double value, double uncertainty, int decimals);

}  // namespace fl
