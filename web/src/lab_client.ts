// The one module that speaks to the lab (docs/web-api.md): nothing else in the page calls fetch
// or EventSource, so a build of the core for the browser can take the server's place here. The
// lab's own messages go on as it wrote them; the page's words where it wrote none.
import { t } from "./i18n";
import {
  LabError,
  LabFullError,
  RateLimitedError,
  SetupError,
  type SessionHandle,
  type StreamHandle,
  type StreamHandlers,
} from "./lab_errors";
import { errorWords } from "./lab_says";
import type {
  ClassTable,
  Closed,
  ControlAction,
  ControlReply,
  Failure,
  Lab,
  LabState,
  LiveRig,
  MeasurementEstimate,
  PlaybackSpeed,
  Problem,
  LiveRigEvent,
  Session,
  Summary,
  ReportAsk,
} from "./lab_types";

// The errors and stream types both clients share, offered from here as the page imports them.
export * from "./lab_errors";

/** Which lab this page talks to: a frictionlab server. */
export const LAB_PLACE: "server" | "browser" = "server";

/** Whether GET /api/rig lists the machine's serial ports: the server's, by name. */
export const RIG_PORTS_LISTED: boolean = true;

/** A shared server's token, from the page's own address (`?token=...`), sent with every call. */
const token = new URLSearchParams(location.search).get("token");

/** An API address, with the token when the page has one, and `extra` query parameters. */
function api(path: string, extra: Record<string, string> = {}): string {
  const query = new URLSearchParams(extra);
  if (token !== null) query.set("token", token);
  const text = query.toString();
  return text === "" ? path : `${path}?${text}`;
}

function sessionPath(session: SessionHandle): string {
  return `/api/sessions/${encodeURIComponent(session.id)}`;
}

/** A session's address that carries its key in the query: a stream's or a download's, which a
 * browser opens without headers of the page's choosing. */
function keyedUrl(session: SessionHandle, path: string): string {
  return api(`${sessionPath(session)}${path}`, { key: session.key });
}

/** The header that carries a session's key with a fetch. */
function keyHeader(session: SessionHandle): Record<string, string> {
  return { "X-Session-Key": session.key };
}

async function readJson<T>(response: Response): Promise<T> {
  const text = await response.text();
  try {
    return JSON.parse(text) as T;
  } catch {
    throw new LabError(t("lab-no-json", { status: response.status }), response.status);
  }
}

/** The lab's message in a refusal's body ({"error": "..."}), else `fallback`. */
async function refusalMessage(response: Response, fallback: string): Promise<string> {
  try {
    return errorWords(await readJson<unknown>(response), fallback);
  } catch {
    // keep the fallback
  }
  return fallback;
}

async function rateLimited(response: Response): Promise<RateLimitedError> {
  const retry = Number(response.headers.get("Retry-After"));
  const retryAfterS = Number.isFinite(retry) && retry > 0 ? retry : null;
  const fallback =
    retryAfterS === null ? t("lab-busy") : t("lab-busy-seconds", { seconds: retryAfterS });
  return new RateLimitedError(await refusalMessage(response, fallback), retryAfterS);
}

async function expectOk<T>(response: Response): Promise<T> {
  if (response.status === 429) throw await rateLimited(response);
  if (!response.ok) {
    const message = await refusalMessage(response, t("lab-answered", { status: response.status }));
    throw new LabError(message, response.status);
  }
  return readJson<T>(response);
}

export async function getLab(): Promise<Lab> {
  return expectOk<Lab>(await fetch(api("/api/lab")));
}

/** Starts a session paused at t = 0; a refused set-up throws SetupError with its problems.
 * `name`: who runs it, for the class's table (left out when not given). */
export async function createSession(scene: string, set: string[], name?: string): Promise<Session> {
  const response = await fetch(api("/api/sessions"), {
    method: "POST",
    headers: { "Content-Type": "application/json" },
    body: JSON.stringify(name ? { scene, set, name } : { scene, set }),
  });
  if (response.status === 400) {
    const body = await readJson<{ error?: string; problems?: Problem[] }>(response);
    throw new SetupError(body.error ?? t("lab-setup-problems"), body.problems ?? []);
  }
  if (response.status === 503) {
    throw new LabFullError(errorWords(await readJson<unknown>(response), t("lab-full")));
  }
  return expectOk<Session>(response);
}

function parseEvent<T>(event: Event): T | null {
  if (!(event instanceof MessageEvent) || typeof event.data !== "string") return null;
  try {
    return JSON.parse(event.data) as T;
  } catch {
    return null;
  }
}

/** How often, and how long after, a stream the browser gave up on (an answer other than 200: the
 * lab asking the page to slow down, 429) is opened again. EventSource retries a dropped
 * connection by itself, but not a refused one. */
const STREAM_RETRIES = 5;
const STREAM_RETRY_MS = 2000;

/** Listens to a session's events until close(). */
export function stream(session: SessionHandle, handlers: StreamHandlers): StreamHandle {
  let source: EventSource;
  let retries = 0;
  let retryTimer = 0;
  let ended = false;
  const end = () => {
    ended = true;
    window.clearTimeout(retryTimer);
    source.close();
  };
  const open = () => {
    source = new EventSource(keyedUrl(session, "/stream"));
    source.addEventListener("open", () => (retries = 0));
    source.addEventListener("state", (event) => {
      const state = parseEvent<LabState>(event);
      if (state) handlers.state(state);
    });
    source.addEventListener("done", (event) => {
      const summary = parseEvent<Summary>(event);
      if (summary) handlers.done(summary);
    });
    source.addEventListener("failed", (event) => {
      const failure = parseEvent<Failure>(event);
      if (failure) handlers.failed(failure);
    });
    source.addEventListener("reset", () => handlers.reset());
    source.addEventListener("rig", (event) => {
      const rig = parseEvent<LiveRigEvent>(event);
      if (rig) handlers.rig?.(rig);
    });
    source.addEventListener("closed", (event) => {
      // The server is going away: EventSource would otherwise try it again and again.
      end();
      const closed = parseEvent<Closed>(event);
      handlers.closed?.(closed?.message || t("lab-stopped"));
    });
    source.addEventListener("error", () => {
      handlers.error?.();
      if (ended || source.readyState !== EventSource.CLOSED || retries >= STREAM_RETRIES) return;
      retries += 1;
      retryTimer = window.setTimeout(() => {
        if (!ended) open();
      }, STREAM_RETRY_MS);
    });
  };
  open();
  return { close: end };
}

export async function control(
  session: SessionHandle,
  command: ControlAction | { speed: PlaybackSpeed } | { name: string },
): Promise<ControlReply> {
  const body = typeof command === "string" ? { action: command } : command;
  const response = await fetch(api(`${sessionPath(session)}/control`), {
    method: "POST",
    headers: { "Content-Type": "application/json", ...keyHeader(session) },
    body: JSON.stringify(body),
  });
  return expectOk<ControlReply>(response);
}

/** A measurement file the student chose, read by the lab's readers with the set-up's spacing
 * [m]. A file that gives no period is refused with the reader's message, located in the file. */
export async function estimateFile(
  file: Blob,
  name: string,
  spacing: number,
): Promise<MeasurementEstimate> {
  const response = await fetch(api("/api/estimate", { name, spacing: String(spacing) }), {
    method: "POST",
    headers: { "Content-Type": "application/octet-stream" },
    body: file,
  });
  if (response.status === 429) throw await rateLimited(response);
  if (!response.ok) {
    const body = await readJson<{ error?: unknown; problems?: Problem[] }>(response).catch(
      () => null,
    );
    const first = body?.problems?.[0];
    throw new LabError(
      first?.message ?? errorWords(body, t("lab-answered", { status: response.status })),
      response.status,
      first ?? null,
    );
  }
  return readJson<MeasurementEstimate>(response);
}

/** Where a finished run's file downloads from (summary.json, trajectory.csv, hall.csv, ...). */
export async function fileHref(session: SessionHandle, name: string): Promise<string> {
  return keyedUrl(session, `/files/${encodeURIComponent(name)}`);
}

/** The finished run's lab report, a self-contained HTML page. */
export async function reportHtml(session: SessionHandle, ask: ReportAsk): Promise<string> {
  const response = await fetch(api(`${sessionPath(session)}/report`), {
    method: "POST",
    headers: { "Content-Type": "application/json", ...keyHeader(session) },
    body: JSON.stringify(ask),
  });
  if (response.status === 429) throw await rateLimited(response);
  if (!response.ok) {
    const message = await refusalMessage(response, t("lab-answered", { status: response.status }));
    throw new LabError(message, response.status);
  }
  return response.text();
}

export async function endSession(session: SessionHandle): Promise<void> {
  try {
    await fetch(api(sessionPath(session)), {
      method: "DELETE",
      headers: keyHeader(session),
      keepalive: true,
    });
  } catch {
    // the session ends by itself when nobody streams from it
  }
}

/** Where a LEGO part's mesh is served (glTF binary, y up), beside the page. */
export function partUrl(name: string): string {
  return `parts/${encodeURIComponent(name)}.glb`;
}

/** The live rig: the serial ports the server sees and the one open. */
export async function getRig(): Promise<LiveRig> {
  return expectOk<LiveRig>(await fetch(api("/api/rig")));
}

async function postRig(body: { port: string } | { action: "close" }): Promise<LiveRig> {
  const response = await fetch(api("/api/rig"), {
    method: "POST",
    headers: { "Content-Type": "application/json" },
    body: JSON.stringify(body),
  });
  return expectOk<LiveRig>(response);
}

/** Opens one of `getRig()`'s ports (closing the one open, starting a new log). */
export async function openRig(port: string): Promise<LiveRig> {
  return postRig({ port });
}

export async function closeRig(): Promise<LiveRig> {
  return postRig({ action: "close" });
}

/** Where the rig's raw log downloads (every line as received; 404 before a line came). */
export async function rigLogHref(): Promise<string> {
  return api("/api/rig/log");
}

/** Every open session's set-up and result, and the live rig: the class's table. */
export async function getClass(): Promise<ClassTable> {
  return expectOk<ClassTable>(await fetch(api("/api/class")));
}

/** The class's table as CSV (class.csv). */
export function classCsvUrl(): string {
  return api("/api/class.csv");
}

/** One of the lab's pages (`/`, `/class.html`), with the token when this page has one. */
export function pageUrl(path: string): string {
  return api(path);
}
