// The teacher's page (class.html): every open session's set-up and result as the class's table
// (GET /api/class, docs/web-api.md "The class's table"), the live rig's line, and the table as
// class.csv; asked again every 2 s.
import { byId, byTestId, setText } from "./dom";
import { fixed, trimmed, withError } from "./format";
import { classCsvUrl, getClass, pageUrl, RateLimitedError } from "./lab_client";
import type { ClassRow, ClassTable } from "./lab_types";

const REFRESH_MS = 2000;
const NONE = "—";

const rows = byId<HTMLTableSectionElement>("class-rows");
const count = byId("class-count");
const rigLine = byTestId("class-rig");
const updated = byId("class-updated");
const problem = byId("page-problem");
byTestId<HTMLAnchorElement>("class-csv").href = classCsvUrl();
byTestId<HTMLAnchorElement>("lab-link").href = pageUrl("/");

/** A value ± its uncertainty, rounded to it; the value alone where there is none. */
function measured(value: number | null, error: number | null, minDecimals: number): string {
  return value === null ? NONE : withError(value, error, minDecimals);
}

/** The row's cells, in the table's columns. */
function cellsOf(row: ClassRow): string[] {
  return [
    row.name ?? NONE,
    row.scene,
    row.material ?? NONE,
    row.temperature_k === null ? NONE : trimmed(row.temperature_k, 1),
    trimmed(row.spacing * 1000, 1),
    row.state,
    fixed(row.t, 2),
    measured(row.period, row.period_err, 3) +
      (row.period_from === "trajectory" ? " (motion fit)" : ""),
    measured(row.mu_k, row.mu_k_err, 2),
    row.paper_mu_k === null ? NONE : trimmed(row.paper_mu_k, 3),
  ];
}

function showTable(table: ClassTable): void {
  const made = table.sessions.map((session) => {
    const tr = document.createElement("tr");
    tr.dataset["session"] = session.session;
    for (const text of cellsOf(session)) {
      const td = document.createElement("td");
      td.textContent = text;
      tr.append(td);
    }
    return tr;
  });
  if (made.length === 0) {
    const tr = document.createElement("tr");
    const td = document.createElement("td");
    td.colSpan = 10;
    td.className = "empty";
    td.textContent = "No session is open.";
    tr.append(td);
    made.push(tr);
  }
  rows.replaceChildren(...made);
  const n = table.sessions.length;
  setText(count, `${n} session${n === 1 ? "" : "s"}`);
  const rig = table.rig;
  rigLine.hidden = rig === null;
  if (rig !== null) {
    setText(
      rigLine,
      `The live rig: ${rig.port ?? "no port"}, ${rig.state}, ${rig.lines} line${rig.lines === 1 ? "" : "s"} received`,
    );
  }
}

async function refresh(): Promise<number> {
  try {
    showTable(await getClass());
    setText(problem, "");
    setText(updated, `updated ${new Date().toLocaleTimeString()}`);
  } catch (error) {
    if (error instanceof RateLimitedError) {
      setText(problem, error.message);
      return Math.max(REFRESH_MS, (error.retryAfterS ?? 0) * 1000);
    }
    const message = error instanceof Error ? error.message : String(error);
    setText(problem, `The lab did not answer as expected: ${message}`);
  }
  return REFRESH_MS;
}

let timer = 0;
let asking = false;
async function keepRefreshing(): Promise<void> {
  if (asking) return;
  window.clearTimeout(timer);
  asking = true;
  const wait = await refresh();
  asking = false;
  timer = window.setTimeout(() => {
    if (!document.hidden) void keepRefreshing();
  }, wait);
}

// A hidden tab asks nothing; shown again, it asks at once.
document.addEventListener("visibilitychange", () => {
  if (!document.hidden) void keepRefreshing();
});
void keepRefreshing();
