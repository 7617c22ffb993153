// The teacher's page (class.html): every open session's set-up and result as the class's table
// (GET /api/class, docs/web-api.md "The class's table"), the live rig's line, and the table as
// class.csv; asked again every 2 s. The teacher sorts the rows by a column's heading and hides
// rows from this page (kept in this browser); the sessions themselves are the students'.
import { byId, byTestId, setText } from "./dom";
import { pageLanguage, t } from "./i18n";
import { classCsvUrl, getClass, pageUrl, RateLimitedError } from "./lab_client";
import type { ClassRow, ClassTable } from "./lab_types";
import { showPageLanguage, withPageLanguage } from "./page_language";
import { fixed, trimmed, withError } from "./page_numbers";

showPageLanguage();

const REFRESH_MS = 2000;
const NONE = "—";
const HIDDEN = "frictionlab.class-hidden";

const rows = byId<HTMLTableSectionElement>("class-rows");
const count = byId("class-count");
const rigLine = byTestId("class-rig");
const updated = byId("class-updated");
const problem = byId("page-problem");
byTestId<HTMLAnchorElement>("class-csv").href = classCsvUrl();
byTestId<HTMLAnchorElement>("lab-link").href = withPageLanguage(pageUrl("/"));

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
    t("session-state", { state: row.state }),
    fixed(row.t, 2),
    row.period_from === "trajectory"
      ? t("class-motion-fit", { period: measured(row.period, row.period_err, 3) })
      : measured(row.period, row.period_err, 3),
    measured(row.mu_k, row.mu_k_err, 2),
    row.paper_mu_k === null ? NONE : trimmed(row.paper_mu_k, 3),
  ];
}

/** What each column sorts by: a text or a number; null (none yet) sorts last either way. */
const SORT_KEYS: Record<string, (row: ClassRow) => string | number | null> = {
  name: (row) => row.name,
  scene: (row) => row.scene,
  material: (row) => row.material,
  temperature: (row) => row.temperature_k,
  spacing: (row) => row.spacing,
  state: (row) => row.state,
  t: (row) => row.t,
  period: (row) => row.period,
  mu_k: (row) => row.mu_k,
  paper: (row) => row.paper_mu_k,
};
let sortBy: string | null = null;
let ascending = true;

function sorted(sessions: ClassRow[]): ClassRow[] {
  const key = sortBy === null ? null : SORT_KEYS[sortBy];
  if (!key) return sessions; // the order they began
  const sign = ascending ? 1 : -1;
  return [...sessions].sort((a, b) => {
    const x = key(a);
    const y = key(b);
    if (x === null || y === null) return x === y ? 0 : x === null ? 1 : -1;
    if (typeof x === "number" && typeof y === "number") return sign * (x - y);
    return sign * String(x).localeCompare(String(y), pageLanguage(), { numeric: true });
  });
}

function hiddenIds(): Set<string> {
  try {
    return new Set(JSON.parse(localStorage.getItem(HIDDEN) ?? "[]") as string[]);
  } catch {
    return new Set();
  }
}

function keepHidden(ids: Set<string>): void {
  try {
    localStorage.setItem(HIDDEN, JSON.stringify([...ids]));
  } catch {
    // kept for this page only
  }
}

let hidden = hiddenIds();
let last: ClassTable | null = null;
const showHidden = byTestId<HTMLButtonElement>("class-show-hidden");

function showTable(table: ClassTable): void {
  last = table;
  // A hidden session that has ended is forgotten.
  const open = new Set(table.sessions.map((s) => s.session));
  hidden = new Set([...hidden].filter((id) => open.has(id)));
  const shown = sorted(table.sessions.filter((s) => !hidden.has(s.session)));
  const made = shown.map((session) => {
    const tr = document.createElement("tr");
    tr.dataset["session"] = session.session;
    for (const text of cellsOf(session)) {
      const td = document.createElement("td");
      td.textContent = text;
      tr.append(td);
    }
    const hide = document.createElement("button");
    hide.type = "button";
    hide.textContent = t("class-hide");
    hide.setAttribute(
      "aria-label",
      session.name === null
        ? t("class-hide-unnamed")
        : t("class-hide-named", { name: session.name }),
    );
    hide.addEventListener("click", () => {
      hidden.add(session.session);
      keepHidden(hidden);
      if (last) showTable(last);
    });
    const td = document.createElement("td");
    td.append(hide);
    tr.append(td);
    return tr;
  });
  if (made.length === 0) {
    const tr = document.createElement("tr");
    const td = document.createElement("td");
    td.colSpan = 11;
    td.className = "empty";
    td.textContent = t(table.sessions.length === 0 ? "class-no-session" : "class-all-hidden");
    tr.append(td);
    made.push(tr);
  }
  rows.replaceChildren(...made);
  const n = table.sessions.length;
  const off = table.sessions.length - shown.length;
  setText(
    count,
    off > 0
      ? t("class-count-hidden", { sessions: n, hidden: off })
      : t("class-count", { sessions: n }),
  );
  showHidden.hidden = off === 0;
  setText(showHidden, t("class-show-hidden-count", { hidden: off }));
  const rig = table.rig;
  rigLine.hidden = rig === null;
  if (rig !== null) {
    setText(
      rigLine,
      t("class-rig", {
        port: rig.port ?? t("class-rig-no-port"),
        state: t("rig-port-state", { state: rig.state }),
        lines: t("rig-lines", { lines: rig.lines }),
      }),
    );
  }
}

async function refresh(): Promise<number> {
  try {
    showTable(await getClass());
    setText(problem, "");
    setText(updated, t("class-updated", { time: new Date().toLocaleTimeString(pageLanguage()) }));
  } catch (error) {
    if (error instanceof RateLimitedError) {
      setText(problem, error.message);
      return Math.max(REFRESH_MS, (error.retryAfterS ?? 0) * 1000);
    }
    const message = error instanceof Error ? error.message : String(error);
    setText(problem, t("page-problem-unexpected", { message }));
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

showHidden.addEventListener("click", () => {
  hidden.clear();
  keepHidden(hidden);
  if (last) showTable(last);
});
for (const button of document.querySelectorAll<HTMLButtonElement>("th button[data-sort]")) {
  button.addEventListener("click", () => {
    const key = button.dataset["sort"] ?? null;
    ascending = key === sortBy ? !ascending : true;
    sortBy = key;
    for (const th of document.querySelectorAll("th")) th.removeAttribute("aria-sort");
    button.closest("th")?.setAttribute("aria-sort", ascending ? "ascending" : "descending");
    if (last) showTable(last);
  });
}

// A hidden tab asks nothing; shown again, it asks at once.
document.addEventListener("visibilitychange", () => {
  if (!document.hidden) void keepRefreshing();
});
void keepRefreshing();
