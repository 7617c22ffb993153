// The headline of a finished run, read from its summary (the same object as summary.json):
// `period_s` with `period_std_s` and `period_std_error_s`, `mu_k_recovered` with
// `mu_k_err_quadrature`, and `regime` (docs/web-api.md).
import type { Summary } from "./lab_types";

export interface Headline {
  period: number;
  /** The periods' standard deviation. */
  periodSd: number | null;
  /** The standard error of their mean. */
  periodSe: number | null;
  muK: number | null;
  muKErr: number | null;
  regime: string | null;
}

function numberOr(value: unknown): number | null {
  return typeof value === "number" && Number.isFinite(value) ? value : null;
}

function regimeOf(value: unknown): string | null {
  if (typeof value === "string") return value;
  if (typeof value === "object" && value !== null) {
    const name = (value as Record<string, unknown>).name;
    if (typeof name === "string") return name;
  }
  return null;
}

/** The run's headline, or null where it measured no period. */
export function headlineOf(summary: Summary): Headline | null {
  const period = numberOr(summary.period_s);
  if (period === null) return null;
  return {
    period,
    periodSd: numberOr(summary.period_std_s),
    periodSe: numberOr(summary.period_std_error_s),
    muK: numberOr(summary.mu_k_recovered),
    muKErr: numberOr(summary.mu_k_err_quadrature),
    regime: regimeOf(summary.regime),
  };
}
