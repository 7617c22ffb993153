// A plot's data as a table, for who cannot see the plot: a <details> under it ("Data as a
// table") holds the samples the plot shows, thinned evenly in time to at most MAX_ROWS rows
// (decimate.ts). The table is written when the run pauses (and again for each state a paused run
// moves on to: a step, the states still on their way when it paused) or ends, and when it is
// opened, never at the stream's pace; a run back at t = 0 empties it.
import { decimate, type Pick } from "./decimate";
import { byId, setText } from "./dom";
import { t } from "./i18n";
import { fixed } from "./page_numbers";
import type { LabModel } from "./lab_model";
import type { HallPlot, PositionPlot } from "./plots";

const MAX_ROWS = 200;

export interface TableColumns {
  /** What the samples are, for the caption: "the plate's position x (mm)". */
  what: string;
  /** The value's decimals (t has 3). */
  decimals: number;
  pick: Pick;
  /** The plotted samples: times [s] and values. */
  read: () => [number[], number[]];
}

export class PlotTable {
  private readonly body: HTMLTableSectionElement;
  private readonly caption: HTMLElement;

  constructor(
    private readonly details: HTMLDetailsElement,
    private readonly columns: TableColumns,
  ) {
    this.body = details.querySelector("tbody")!;
    this.caption = details.querySelector("caption")!;
    details.addEventListener("toggle", () => {
      if (details.open) this.write();
    });
    this.clear();
  }

  /** The plot's samples now, thinned. */
  write(): void {
    const [times, values] = this.columns.read();
    const rows = decimate(times, values, MAX_ROWS, this.columns.pick);
    const { what, decimals } = this.columns;
    this.body.replaceChildren(
      ...rows.map(([time, v]) => {
        const row = document.createElement("tr");
        for (const text of [fixed(time, 3), fixed(v, decimals)]) {
          const cell = document.createElement("td");
          cell.textContent = text;
          row.append(cell);
        }
        return row;
      }),
    );
    if (rows.length === 0) {
      setText(this.caption, t("plot-table-empty", { what }));
      return;
    }
    const span = {
      what: `${what.charAt(0).toUpperCase()}${what.slice(1)}`,
      from: fixed(times[0], 3),
      to: fixed(times.at(-1), 3),
      rows: rows.length,
    };
    setText(
      this.caption,
      rows.length === times.length
        ? t("plot-table-every", span)
        : t("plot-table-some", { ...span, samples: times.length }),
    );
  }

  clear(): void {
    this.body.replaceChildren();
    setText(this.caption, t("plot-table-empty", { what: this.columns.what }));
  }
}

/** The position and Hall plots' tables (index.html's #table-x and #table-hall). */
export function followWithTables(
  model: LabModel,
  position: PositionPlot,
  hall: HallPlot,
): PlotTable[] {
  const tables = [
    new PlotTable(byId<HTMLDetailsElement>("table-x"), {
      what: t("plot-table-position-what"),
      decimals: 2,
      pick: "first",
      read: () => position.samples(),
    }),
    new PlotTable(byId<HTMLDetailsElement>("table-hall"), {
      what: t("plot-table-hall-what"),
      decimals: 0,
      pick: "farthest",
      read: () => hall.samples(),
    }),
  ];
  let written: number | null = null; // the t of the state last written
  // Once the plots have taken the state (they hear it in the same task, perhaps after this).
  const write = (t: number) => {
    written = t;
    queueMicrotask(() => {
      for (const table of tables) table.write();
    });
  };
  model.state.lazyLink((state) => {
    if (state === null) {
      written = null;
      for (const table of tables) table.clear();
    } else if (!state.playing && state.t !== written) write(state.t);
  });
  model.done.lazyLink((done) => {
    const state = model.state.value;
    if (done && state) write(state.t);
  });
  return tables;
}
