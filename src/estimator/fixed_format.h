// Decimal text of integers and of floats at a fixed number of decimals, the way the rig's
// firmware prints them. Portable C++11 like period_estimator.h: the firmware and the host use the
// same code, so a number the host formats from the same float reads exactly as the firmware's.
#ifndef FRICTIONLAB_ESTIMATOR_FIXED_FORMAT_H
#define FRICTIONLAB_ESTIMATOR_FIXED_FORMAT_H

#include <stdint.h>

namespace fl_estimator {

// Writes v in decimal, at least `min_digits` digits (zero-padded, up to 10), and a terminating
// NUL; returns the number of digits (out: 11 chars). Subtracts powers of ten rather than dividing,
// which an 8-bit AVR does in a few hundred cycles instead of thousands.
inline uint8_t format_uint(char* out, uint32_t v, uint8_t min_digits = 1) {
  static const uint32_t kPowers[10] = {1000000000u, 100000000u, 10000000u, 1000000u, 100000u,
                                       10000u,      1000u,      100u,      10u,      1u};
  if (min_digits > 10) min_digits = 10;
  uint8_t i = 0;
  while (i < 9 && v < kPowers[i] && 10 - i > min_digits) ++i;  // leading zeros
  uint8_t n = 0;
  for (; i < 10; ++i) {
    char digit = '0';
    while (v >= kPowers[i]) {
      v -= kPowers[i];
      ++digit;
    }
    out[n++] = digit;
  }
  out[n] = '\0';
  return n;
}

// Writes v rounded to `decimals` (0..6) digits after the point, and a NUL; returns the length
// (out: 20 chars). The rounding is done in float: |v| * 10^decimals + 0.5, truncated. Values
// beyond 4e9 / 10^decimals print as "ovf", NaN as "nan".
inline uint8_t format_fixed(char* out, float v, uint8_t decimals) {
  if (decimals > 6) decimals = 6;
  if (!(v == v)) {
    out[0] = 'n';
    out[1] = 'a';
    out[2] = 'n';
    out[3] = '\0';
    return 3;
  }
  uint8_t n = 0;
  if (v < 0.0f) {
    out[n++] = '-';
    v = -v;
  }
  float scale = 1.0f;
  for (uint8_t i = 0; i < decimals; ++i) scale *= 10.0f;
  const float scaled = v * scale + 0.5f;
  if (!(scaled < 4.0e9f)) {
    out[n++] = 'o';
    out[n++] = 'v';
    out[n++] = 'f';
    out[n] = '\0';
    return n;
  }
  const uint8_t digits =
      format_uint(out + n, static_cast<uint32_t>(scaled), static_cast<uint8_t>(decimals + 1));
  n = static_cast<uint8_t>(n + digits);
  if (decimals == 0) return n;
  // Open a gap for the point before the last `decimals` digits.
  for (uint8_t i = 0; i < decimals; ++i) out[n - i] = out[n - 1 - i];
  out[n - decimals] = '.';
  ++n;
  out[n] = '\0';
  return n;
}

}  // namespace fl_estimator

#endif  // FRICTIONLAB_ESTIMATOR_FIXED_FORMAT_H
