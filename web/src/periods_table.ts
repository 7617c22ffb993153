// The periods as the estimator judges them, one row each, newest last.
import { fixed } from "./format";
import type { PeriodRow } from "./lab_types";

const MAX_ROWS = 400;

export class PeriodsTable {
  private count = 0;
  private accepted = 0;

  constructor(
    private readonly body: HTMLTableSectionElement,
    private readonly scroller: HTMLElement,
    private readonly tally: HTMLElement,
  ) {
    this.clear();
  }

  clear(): void {
    this.body.replaceChildren();
    this.count = 0;
    this.accepted = 0;
    this.tally.textContent = "none yet";
  }

  add(rows: PeriodRow[]): void {
    if (rows.length === 0) return;
    const stick =
      this.scroller.scrollTop + this.scroller.clientHeight >= this.scroller.scrollHeight - 4;
    for (const [start, , period, accepted] of rows) {
      this.count += 1;
      if (accepted) this.accepted += 1;
      const row = document.createElement("tr");
      if (!accepted) row.className = "rejected";
      for (const text of [
        String(this.count),
        fixed(start, 3),
        fixed(period, 4),
        accepted ? "✓ yes" : "✗ no",
      ]) {
        const cell = document.createElement("td");
        cell.textContent = text;
        row.append(cell);
      }
      this.body.append(row);
    }
    while (this.body.rows.length > MAX_ROWS) this.body.deleteRow(0);
    this.tally.textContent = `${this.accepted} of ${this.count} accepted`;
    if (stick) this.scroller.scrollTop = this.scroller.scrollHeight;
  }
}
