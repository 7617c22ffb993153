// Numbers as the page shows them.

/**
 * "0.7912 ± 0.0012": the value to the decimals of its error's leading digit (two digits where
 * that one is a 1), at least `minDecimals`.
 */
export function withError(value: number, error: number | null, minDecimals = 2): string {
  if (error === null || !Number.isFinite(error) || error <= 0) {
    return value.toFixed(Math.max(minDecimals, 3));
  }
  const magnitude = Math.floor(Math.log10(error));
  const leadingOne = Math.floor(error / 10 ** magnitude) === 1;
  const decimals = Math.min(8, Math.max(minDecimals, -magnitude + (leadingOne ? 1 : 0)));
  return `${value.toFixed(decimals)} ± ${error.toFixed(decimals)}`;
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
