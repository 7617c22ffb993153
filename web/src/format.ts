// Numbers as the page shows them.

/**
 * "0.7912 ± 0.0012": the lab's one rule for a value with its uncertainty (src/io/plus_minus.hpp,
 * held with this one to tests/data/plus_minus_cases.json): the uncertainty to one significant
 * digit, two where that digit is a 1, after rounding; the value to the same decimals; at least
 * `minDecimals`. A missing uncertainty shows the value alone.
 */
export function withError(value: number, error: number | null, minDecimals = 2): string {
  if (error === null || !Number.isFinite(error) || error <= 0) {
    return value.toFixed(Math.max(minDecimals, 3));
  }
  return withErrorSign(value, error, minDecimals, "±");
}

/** The same with the sign given ("+-" as the lab's text files have it). */
export function withErrorSign(
  value: number,
  error: number,
  minDecimals: number,
  sign: string,
): string {
  let decimals = minDecimals;
  if (error > 0 && Number.isFinite(error)) {
    // Rounded to two significant digits, 0.0999 is 0.10: a leading 1 keeps both digits.
    let exponent = Math.floor(Math.log10(error));
    if (Math.round(error / 10 ** (exponent - 1)) >= 100) exponent += 1;
    const leadingOne = Math.round(error / 10 ** (exponent - 1)) < 20;
    decimals = Math.min(15, Math.max(0, Math.max(minDecimals, -exponent + (leadingOne ? 1 : 0))));
  }
  return `${value.toFixed(decimals)} ${sign} ${error.toFixed(decimals)}`;
}

export function fixed(value: number | null | undefined, decimals: number): string {
  return value === null || value === undefined || !Number.isFinite(value)
    ? "—"
    : value.toFixed(decimals);
}

/** Up to `decimals` decimals, trailing zeros dropped: 89, 0.1, 1600. */
export function trimmed(value: number, decimals = 3): string {
  return String(Number(value.toFixed(decimals)));
}

/** Two significant digits however small: a standard error of 4.1e-5 s is 0.000041, never 0.0000. */
export function significant(value: number | null | undefined, digits = 2): string {
  if (value === null || value === undefined || !Number.isFinite(value)) return "—";
  if (value === 0) return "0";
  const decimals = Math.max(0, digits - 1 - Math.floor(Math.log10(Math.abs(value))));
  return value.toFixed(Math.min(decimals, 15));
}
