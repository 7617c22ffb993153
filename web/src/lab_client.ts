// The one module that speaks to the lab (docs/web-api.md): nothing else in the page calls fetch
// or EventSource, so a build of the core for the browser can take the server's place here.
import type {
  ControlAction,
  ControlReply,
  Failure,
  Lab,
  LabState,
  PlaybackSpeed,
  Problem,
  Session,
  Summary,
} from "./lab_types";

/** The lab refused a set-up (400): every problem, by field. */
export class SetupError extends Error {
  readonly problems: Problem[];
  constructor(message: string, problems: Problem[]) {
    super(message);
    this.name = "SetupError";
    this.problems = problems;
  }
}

/** The lab is full (503): it runs as many sessions as it may; `message` says so. */
export class LabFullError extends Error {
  constructor(message: string) {
    super(message);
    this.name = "LabFullError";
  }
}

/** The lab answered something other than what the API promises. */
export class LabError extends Error {
  readonly status: number;
  constructor(message: string, status: number) {
    super(message);
    this.name = "LabError";
    this.status = status;
  }
}

export interface StreamHandlers {
  state: (state: LabState) => void;
  done: (summary: Summary) => void;
  failed: (failure: Failure) => void;
  /** The session was started again from t = 0 (the page clears its plots). */
  reset: () => void;
  /** The connection dropped (EventSource retries by itself until closed). */
  error?: () => void;
}

export interface StreamHandle {
  close: () => void;
}

/** A shared server's token, from the page's own address (`?token=...`), sent with every call. */
const token = new URLSearchParams(location.search).get("token");

/** An API address, with the token when the page has one. */
function api(path: string): string {
  return token === null ? path : `${path}?token=${encodeURIComponent(token)}`;
}

function sessionPath(id: string): string {
  return `/api/sessions/${encodeURIComponent(id)}`;
}

async function readJson<T>(response: Response): Promise<T> {
  const text = await response.text();
  try {
    return JSON.parse(text) as T;
  } catch {
    throw new LabError(`the lab answered ${response.status} with no JSON`, response.status);
  }
}

async function expectOk<T>(response: Response): Promise<T> {
  if (!response.ok) {
    let message = `the lab answered ${response.status}`;
    try {
      const body = await readJson<{ error?: string }>(response);
      if (body.error) message = body.error;
    } catch {
      // keep the status line
    }
    throw new LabError(message, response.status);
  }
  return readJson<T>(response);
}

export async function getLab(): Promise<Lab> {
  return expectOk<Lab>(await fetch(api("/api/lab")));
}

/** Starts a session paused at t = 0; a refused set-up throws SetupError with its problems. */
export async function createSession(scene: string, set: string[]): Promise<Session> {
  const response = await fetch(api("/api/sessions"), {
    method: "POST",
    headers: { "Content-Type": "application/json" },
    body: JSON.stringify({ scene, set }),
  });
  if (response.status === 400) {
    const body = await readJson<{ error?: string; problems?: Problem[] }>(response);
    throw new SetupError(body.error ?? "the set-up has problems", body.problems ?? []);
  }
  if (response.status === 503) {
    const body = await readJson<{ error?: string }>(response);
    throw new LabFullError(body.error ?? "the lab is full: try again when a session ends");
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

/** Listens to a session's events until close(). */
export function stream(id: string, handlers: StreamHandlers): StreamHandle {
  const source = new EventSource(api(`${sessionPath(id)}/stream`));
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
  source.addEventListener("error", () => handlers.error?.());
  return { close: () => source.close() };
}

export async function control(
  id: string,
  command: ControlAction | { speed: PlaybackSpeed },
): Promise<ControlReply> {
  const body = typeof command === "string" ? { action: command } : command;
  const response = await fetch(api(`${sessionPath(id)}/control`), {
    method: "POST",
    headers: { "Content-Type": "application/json" },
    body: JSON.stringify(body),
  });
  return expectOk<ControlReply>(response);
}

/** Where a finished run's file is served (summary.json, trajectory.csv, hall.csv, ...). */
export function fileUrl(id: string, name: string): string {
  return api(`${sessionPath(id)}/files/${encodeURIComponent(name)}`);
}

export async function endSession(id: string): Promise<void> {
  try {
    await fetch(api(sessionPath(id)), { method: "DELETE", keepalive: true });
  } catch {
    // the session ends by itself when nobody streams from it
  }
}

/** Where a LEGO part's mesh is served (glTF binary, y up). */
export function partUrl(name: string): string {
  return `/parts/${encodeURIComponent(name)}.glb`;
}
