// Columns of samples keyed by time, keeping only the last `span` seconds.

export class SlidingWindow {
  readonly columns: number[][];
  private start = 0;

  constructor(
    columnCount: number,
    readonly span: number,
  ) {
    this.columns = Array.from({ length: columnCount }, () => []);
  }

  get times(): number[] {
    return this.columns[0]!;
  }

  get lastTime(): number | null {
    const t = this.times;
    return t.length > this.start ? t[t.length - 1]! : null;
  }

  push(row: readonly number[]): void {
    for (let i = 0; i < this.columns.length; i++) this.columns[i]!.push(row[i] ?? NaN);
  }

  clear(): void {
    for (const column of this.columns) column.length = 0;
    this.start = 0;
  }

  /** Drops what fell out of the window; returns the columns as uPlot takes them. */
  view(): number[][] {
    const t = this.times;
    const last = this.lastTime;
    if (last !== null) {
      while (this.start < t.length && t[this.start]! < last - this.span) this.start++;
    }
    if (this.start > 4096 && this.start > t.length / 2) {
      for (const column of this.columns) column.splice(0, this.start);
      this.start = 0;
    }
    return this.columns.map((column) => column.slice(this.start));
  }
}
