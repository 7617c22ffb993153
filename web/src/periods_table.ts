// The periods as an estimator judges them, one row each: the simulation's, newest last in a
// scrolling table that follows the newest while it is in view; the live rig's, newest first (its
// panel is short: the latest stays in sight without scrolling), the period to the microsecond as
// `frictionlab estimate` prints it.
import { t } from "./i18n";
import { fixed } from "./page_numbers";
import type { PeriodRow } from "./lab_types";

export interface PeriodsLayout {
  newestFirst: boolean;
  /** The period's decimals. */
  decimals: number;
  maxRows: number;
  /** The data-testid of each period's cell, when the tests read them. */
  periodTestId?: string;
  /** The scrolling box of a newest-last table, kept at its end while it was there. */
  scroller?: HTMLElement;
  accepted: string;
  rejected: string;
}

export class PeriodsTable {
  private count = 0;
  private accepted = 0;

  constructor(
    private readonly body: HTMLTableSectionElement,
    private readonly tally: HTMLElement,
    private readonly layout: PeriodsLayout,
  ) {
    this.clear();
  }

  clear(): void {
    this.body.replaceChildren();
    this.count = 0;
    this.accepted = 0;
    this.tally.textContent = t("periods-none");
  }

  add(rows: PeriodRow[]): void {
    if (rows.length === 0) return;
    const { newestFirst, decimals, maxRows, periodTestId, scroller } = this.layout;
    const stick =
      scroller !== undefined &&
      scroller.scrollTop + scroller.clientHeight >= scroller.scrollHeight - 4;
    for (const [start, , period, accepted] of rows) {
      this.count += 1;
      if (accepted) this.accepted += 1;
      const row = document.createElement("tr");
      if (!accepted) row.className = "rejected";
      const cells: [string, string | undefined][] = [
        [String(this.count), undefined],
        [fixed(start, 3), undefined],
        [fixed(period, decimals), periodTestId],
        [accepted ? this.layout.accepted : this.layout.rejected, undefined],
      ];
      for (const [text, testId] of cells) {
        const cell = document.createElement("td");
        cell.textContent = text;
        if (testId) cell.dataset["testid"] = testId;
        row.append(cell);
      }
      if (newestFirst) this.body.prepend(row);
      else this.body.append(row);
    }
    while (this.body.rows.length > maxRows) this.body.deleteRow(newestFirst ? -1 : 0);
    this.tally.textContent = t("periods-tally", { accepted: this.accepted, count: this.count });
    if (stick) scroller.scrollTop = scroller.scrollHeight;
  }
}
