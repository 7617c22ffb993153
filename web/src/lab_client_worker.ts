// The second lab client: the lab in this page's own Web Worker (lab_worker.ts, the core compiled
// to WebAssembly), for the static site tools/site builds. It offers what lab_client.ts offers, by
// the same names and types (lab_client_check.ts holds the two to it), answering as the server
// does: the same bodies, refusals and stream events, with no request leaving the browser. The
// lab's own messages go on as it wrote them; the page's words where it wrote none.
import { t } from "./i18n";
import { errorWords } from "./lab_says";
import {
  LabError,
  LabFullError,
  RateLimitedError,
  SetupError,
  type SessionHandle,
  type StreamHandle,
  type StreamHandlers,
} from "./lab_errors";
import type {
  ClassTable,
  ControlAction,
  ControlReply,
  Failure,
  Lab,
  LabState,
  LiveRig,
  LiveRigEvent,
  MeasurementEstimate,
  PlaybackSpeed,
  Problem,
  Session,
  Summary,
  ReportAsk,
} from "./lab_types";
import type { WorkerAnswer, WorkerMessage, WorkerRequest } from "./lab_worker";

// The errors and stream types both clients share, offered from here as the page imports them.
export * from "./lab_errors";

/** Which lab this page talks to: its own, in this browser. */
export const LAB_PLACE: "server" | "browser" = "browser";

/** Whether GET /api/rig lists the machine's serial ports: here the browser asks when connecting. */
export const RIG_PORTS_LISTED: boolean = false;

type Ask = WorkerRequest extends infer R
  ? R extends { id: number }
    ? Omit<R, "id">
    : never
  : never;

let worker: Worker | null = null;
let nextId = 1;
const pending = new Map<number, (answer: WorkerAnswer) => void>();
const listeners = new Map<string, StreamHandlers>();

function labWorker(): Worker {
  if (worker) return worker;
  const made = new Worker(new URL("lab_worker.js", document.baseURI));
  made.addEventListener("message", (event: MessageEvent<WorkerMessage>) => {
    const message = event.data;
    if ("id" in message) {
      pending.get(message.id)?.(message.answer);
      pending.delete(message.id);
      return;
    }
    const handlers = listeners.get(message.stream);
    if (handlers) deliver(handlers, message.events);
  });
  made.addEventListener("error", (event) => {
    const answer = {
      status: 500,
      body: {
        error: t("browser-lab-stopped", { why: event.message || t("browser-lab-worker-failed") }),
      },
    };
    for (const resolve of pending.values()) resolve(answer);
    pending.clear();
  });
  worker = made;
  return made;
}

function ask(request: Ask, transfer: Transferable[] = []): Promise<WorkerAnswer> {
  const id = nextId++;
  return new Promise((resolve) => {
    pending.set(id, resolve);
    labWorker().postMessage({ ...request, id }, transfer);
  });
}

function errorOf(answer: WorkerAnswer): string {
  return errorWords(answer.body, t("lab-answered", { status: answer.status }));
}

function expectOk<T>(answer: WorkerAnswer): T {
  if (answer.status < 200 || answer.status >= 300)
    throw new LabError(errorOf(answer), answer.status);
  return answer.body as T;
}

function deliver(handlers: StreamHandlers, events: { event: string; data: unknown }[]): void {
  for (const { event, data } of events) {
    if (event === "state") handlers.state(data as LabState);
    else if (event === "done") handlers.done(data as Summary);
    else if (event === "failed") handlers.failed(data as Failure);
    else if (event === "reset") handlers.reset();
    else if (event === "rig") handlers.rig?.(data as LiveRigEvent);
  }
}

export async function getLab(): Promise<Lab> {
  return expectOk<Lab>(await ask({ op: "lab" }));
}

/** Starts a session paused at t = 0; a refused set-up throws SetupError with its problems. */
export async function createSession(scene: string, set: string[], name?: string): Promise<Session> {
  const answer = await ask({
    op: "create",
    body: JSON.stringify(name ? { scene, set, name } : { scene, set }),
  });
  if (answer.status === 400) {
    const body = answer.body as { error?: string; problems?: Problem[] };
    throw new SetupError(body.error ?? t("lab-setup-problems"), body.problems ?? []);
  }
  if (answer.status === 503) throw new LabFullError(errorOf(answer));
  return expectOk<Session>(answer);
}

/** Listens to a session's events until close(). */
export function stream(session: SessionHandle, handlers: StreamHandlers): StreamHandle {
  listeners.set(session.id, handlers);
  void ask({ op: "stream", session: session.id });
  return {
    close: () => {
      if (listeners.get(session.id) !== handlers) return;
      listeners.delete(session.id);
      void ask({ op: "unstream", session: session.id });
    },
  };
}

export async function control(
  session: SessionHandle,
  command: ControlAction | { speed: PlaybackSpeed } | { name: string },
): Promise<ControlReply> {
  const body = typeof command === "string" ? { action: command } : command;
  return expectOk<ControlReply>(
    await ask({ op: "control", session: session.id, body: JSON.stringify(body) }),
  );
}

/** A measurement file the student chose, read by the lab's readers in this browser with the
 * set-up's spacing [m]; a file that gives no period is refused with the reader's message. */
export async function estimateFile(
  file: Blob,
  name: string,
  spacing: number,
): Promise<MeasurementEstimate> {
  const bytes = await file.arrayBuffer();
  const answer = await ask({ op: "estimate", name, bytes, spacing }, [bytes]);
  if (answer.status !== 200) {
    const body = answer.body as { problems?: Problem[] } | null;
    const first = body?.problems?.[0];
    throw new LabError(first?.message ?? errorOf(answer), answer.status, first ?? null);
  }
  return answer.body as MeasurementEstimate;
}

/** A finished run's file, as a link the browser downloads from (a Blob's address). */
export async function fileHref(session: SessionHandle, name: string): Promise<string> {
  const body = expectOk<{ text: string }>(await ask({ op: "file", session: session.id, name }));
  const type = name.endsWith(".json") ? "application/json" : "text/csv";
  return URL.createObjectURL(new Blob([body.text], { type }));
}

/** The finished run's lab report, a self-contained HTML page, made in this browser. */
export async function reportHtml(session: SessionHandle, wanted: ReportAsk): Promise<string> {
  const answer = await ask({ op: "report", session: session.id, body: JSON.stringify(wanted) });
  return expectOk<{ html: string }>(answer).html;
}

export async function endSession(session: SessionHandle): Promise<void> {
  listeners.delete(session.id);
  await ask({ op: "end", session: session.id });
}

/** Where a LEGO part's mesh is (glTF binary, y up), beside the page. */
export function partUrl(name: string): string {
  return `parts/${encodeURIComponent(name)}.glb`;
}

// The live rig: the page opens the rig's port through the browser's Web Serial (its own port
// chooser), reads it, and gives the bytes to the lab in the worker, which keeps the log and runs
// the rig's estimator for each session's stream, as the server does with a port of its own.

/** Web Serial's part the page uses (the DOM library's types do not have it yet). */
interface WebSerialPort {
  open(options: { baudRate: number }): Promise<void>;
  close(): Promise<void>;
  getInfo(): { usbVendorId?: number; usbProductId?: number };
  readonly readable: ReadableStream<Uint8Array> | null;
}
interface WebSerial {
  requestPort(): Promise<WebSerialPort>;
}

function webSerial(): WebSerial | null {
  const serial = (navigator as Navigator & { serial?: WebSerial }).serial;
  return serial ?? null;
}

let open: { port: WebSerialPort; reader: ReadableStreamDefaultReader<Uint8Array> | null } | null =
  null;
let closing = false;

/** The worker's status of the port, with what this browser offers to open. */
function offered(rig: LiveRig): LiveRig {
  // What the port list shows: the browser asks which port when Connect is pressed.
  if (webSerial()) return { ...rig, ports: [t("serial-choose")], may_choose: true };
  const never = rig.port === null && rig.state === "closed";
  return {
    ...rig,
    ports: [],
    may_choose: true,
    message: never ? t("serial-missing") : rig.message,
    said: never ? { id: "serial-missing", args: [] } : rig.said,
  };
}

function portName(port: WebSerialPort): string {
  const { usbVendorId, usbProductId } = port.getInfo();
  const hex = (n: number) => n.toString(16).padStart(4, "0");
  return usbVendorId === undefined || usbProductId === undefined
    ? t("serial-chosen-port")
    : `USB ${hex(usbVendorId)}:${hex(usbProductId)}`;
}

/** Reads the port until it ends or is closed, each piece to the worker as it comes. */
async function readPort(port: WebSerialPort): Promise<void> {
  let ended = true;
  try {
    while (port.readable && open?.port === port) {
      const reader = port.readable.getReader();
      open.reader = reader;
      try {
        for (;;) {
          const { value, done } = await reader.read();
          if (done) break;
          const bytes = value.slice().buffer;
          void ask({ op: "rig_bytes", bytes, ended: false }, [bytes]);
        }
      } finally {
        reader.releaseLock();
      }
      if (closing) ended = false;
      break;
    }
  } catch {
    // the port went away (unplugged): said below
  }
  if (ended && open?.port === port)
    void ask({ op: "rig_bytes", bytes: new ArrayBuffer(0), ended: true });
}

async function closePort(): Promise<void> {
  const was = open;
  if (!was) return;
  closing = true;
  try {
    await was.reader?.cancel();
    await was.port.close();
  } catch {
    // already gone
  } finally {
    closing = false;
    open = null;
  }
}

/** The live rig: the port this page opened and its state, and what the browser offers. */
export async function getRig(): Promise<LiveRig> {
  return offered(expectOk<LiveRig>(await ask({ op: "rig" })));
}

/** Asks the browser for the rig's port (its own chooser), opens it at the firmware's rate and
 * starts a new log; the one open before is closed. */
export async function openRig(_port: string): Promise<LiveRig> {
  const serial = webSerial();
  if (!serial) throw new LabError(t("serial-missing"), 400);
  const { baud } = expectOk<LiveRig>(await ask({ op: "rig" }));
  if (baud === null) throw new LabError(t("serial-no-baud"), 500);
  let port: WebSerialPort;
  try {
    port = await serial.requestPort();
  } catch {
    throw new LabError(t("serial-none-chosen"), 400);
  }
  await closePort();
  try {
    await port.open({ baudRate: baud });
  } catch (error) {
    const why = error instanceof Error ? error.message : String(error);
    throw new LabError(t("serial-not-opened", { why }), 400);
  }
  const rig = expectOk<LiveRig>(await ask({ op: "rig_open", port: portName(port), baud }));
  open = { port, reader: null };
  void readPort(port);
  return offered(rig);
}

export async function closeRig(): Promise<LiveRig> {
  await closePort();
  return offered(expectOk<LiveRig>(await ask({ op: "rig_close" })));
}

let rigLog: string | null = null;

/** Where the rig's raw log downloads from: every line as received, as a Blob's address. */
export async function rigLogHref(): Promise<string> {
  const body = expectOk<{ text: string }>(await ask({ op: "rig_log" }));
  if (rigLog) URL.revokeObjectURL(rigLog);
  rigLog = URL.createObjectURL(new Blob([body.text], { type: "text/plain" }));
  return rigLog;
}

export async function getClass(): Promise<ClassTable> {
  throw new LabError(t("browser-lab-no-class"), 404);
}

export function classCsvUrl(): string {
  return "";
}

/** One of the lab's pages, beside this one. */
export function pageUrl(path: string): string {
  return path.replace(/^\//, "") || "./";
}
