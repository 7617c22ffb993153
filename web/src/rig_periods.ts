// The live rig's periods as its estimator judges them, one row each, newest first (the panel is
// short: the latest stays in sight without scrolling). The period shows to the microsecond, as
// `frictionlab estimate` prints it.
import { fixed } from "./format";
import type { PeriodRow } from "./lab_types";

const MAX_ROWS = 300;

export class RigPeriods {
  private count = 0;
  private accepted = 0;

  constructor(
    private readonly body: HTMLTableSectionElement,
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
    for (const [start, , period, accepted] of rows) {
      this.count += 1;
      if (accepted) this.accepted += 1;
      const row = document.createElement("tr");
      if (!accepted) row.className = "rejected";
      const cells: [string, string | null][] = [
        [String(this.count), null],
        [fixed(start, 3), null],
        [fixed(period, 6), "rig-period"],
        [accepted ? "accepted" : "rejected", null],
      ];
      for (const [text, testId] of cells) {
        const cell = document.createElement("td");
        cell.textContent = text;
        if (testId) cell.dataset["testid"] = testId;
        row.append(cell);
      }
      this.body.prepend(row);
    }
    while (this.body.rows.length > MAX_ROWS) this.body.deleteRow(-1);
    this.tally.textContent = `${this.accepted} of ${this.count} accepted`;
  }
}
