// What both lab clients share (lab_client.ts, which asks a server; lab_client_worker.ts, which asks
// the lab in this page's Web Worker): the errors they throw and the stream's handlers, so that
// the page catches and listens the same way whichever lab it talks to.
import type { Failure, LabState, LiveRigEvent, Problem, Session, Summary } from "./lab_types";

/** What a session's controls need: its id, and the key only this page holds. */
export type SessionHandle = Pick<Session, "id" | "key">;

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

/** The lab asks this page to slow down (429: more requests a second than it takes from one
 * address); `message` is the lab's, `retryAfterS` its Retry-After where it gave one. */
export class RateLimitedError extends Error {
  readonly retryAfterS: number | null;
  constructor(message: string, retryAfterS: number | null) {
    super(message);
    this.name = "RateLimitedError";
    this.retryAfterS = retryAfterS;
  }
}

/** The lab refused a request, or answered something other than what the API promises;
 * `problem` is the lab's own problem where it gave one (a file's, located in it). */
export class LabError extends Error {
  readonly status: number;
  readonly problem: Problem | null;
  constructor(message: string, status: number, problem: Problem | null = null) {
    super(message);
    this.name = "LabError";
    this.status = status;
    this.problem = problem;
  }
}

export interface StreamHandlers {
  state: (state: LabState) => void;
  done: (summary: Summary) => void;
  failed: (failure: Failure) => void;
  /** The session was started again from t = 0 (the page clears its plots). */
  reset: () => void;
  /** The live rig's samples, periods and estimate since the last event (`event: rig`). */
  rig?: (event: LiveRigEvent) => void;
  /** The server is stopping (`event: closed`): the stream is closed, nothing more comes. */
  closed?: (message: string) => void;
  /** The connection dropped (EventSource retries by itself until closed). */
  error?: () => void;
}

export interface StreamHandle {
  close: () => void;
}
