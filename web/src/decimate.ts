// A record thinned for reading as a table: at most `rows` of its samples, evenly in time. The
// record's time span is cut into `rows` equal slices and each slice gives one of its own samples
// (never an average): the first, or, for a signal of pulses such as the Hall sensor's, the one
// farthest from the record's mean, so that a pulse shows in the table as it shows in the plot.

export type Pick = "first" | "farthest";

/** Rows [t, value] in time order; `times` ascending, `values` beside them. */
export function decimate(
  times: readonly number[],
  values: readonly number[],
  rows: number,
  pick: Pick,
): [number, number][] {
  const n = Math.min(times.length, values.length);
  if (n <= rows) return Array.from({ length: n }, (_, i) => [times[i]!, values[i]!]);
  const start = times[0]!;
  const width = (times[n - 1]! - start) / rows;
  const mean = values.slice(0, n).reduce((sum, v) => sum + v, 0) / n;
  const chosen: [number, number][] = [];
  let slice = -1;
  for (let i = 0; i < n; i++) {
    const t = times[i]!;
    const v = values[i]!;
    const at = width > 0 ? Math.min(rows - 1, Math.floor((t - start) / width)) : 0;
    if (at !== slice) {
      slice = at;
      chosen.push([t, v]);
    } else if (pick === "farthest" && Math.abs(v - mean) > Math.abs(chosen.at(-1)![1] - mean)) {
      chosen[chosen.length - 1] = [t, v];
    }
  }
  return chosen;
}
