// The lab in this page's Web Worker (tools/site): the core compiled to WebAssembly
// (frictionlab-lab.js and .wasm, src/browser/) answering the web API's requests as the server
// would, so that the page never waits on the physics. lab_client_worker.ts is the page's side:
// it sends {id, op, ...} and gets {id, answer: {status, body}}; a session's stream comes as
// {stream: ID, events: [{event, data}, ...]} about 30 times a second while the page listens.

import { decodeVideo, videoContainer, VideoNotDecoded } from "./video_decoding";

/** The module's calls (src/browser/browser_main.cpp): each answers JSON {status, body}. */
interface LabModule {
  open_lab(scenesDir: string, assetDir: string): void;
  lab(): string;
  create_session(body: string): string;
  events(id: string): string;
  control(id: string, body: string): string;
  file(id: string, name: string): string;
  report(id: string, body: string): string;
  end(id: string): string;
  estimate(
    name: string,
    bytes: Uint8Array,
    spacing: string,
    hasSpacing: boolean,
    hC: string,
    hasHC: boolean,
  ): string;
  rig(): string;
  rig_open(port: string, baud: number): string;
  rig_bytes(bytes: Uint8Array, ended: boolean): string;
  rig_close(): string;
  rig_log(): string;
  video_begin(
    container: string,
    codec: string,
    width: number,
    height: number,
    fps: number,
    scale: number,
    failure: string,
  ): void;
  video_frame(tS: number, width: number, height: number, levels: Uint8Array): void;
  video_end(name: string): string;
  forget_videos(): void;
  tracked_width(): number;
}

/** What the page asks. */
export type WorkerRequest = { id: number } & (
  | { op: "lab" }
  | { op: "create"; body: string }
  | { op: "control"; session: string; body: string }
  | { op: "file"; session: string; name: string }
  | { op: "report"; session: string; body: string }
  | { op: "end"; session: string }
  | { op: "estimate"; name: string; bytes: ArrayBuffer; spacing: number | null }
  | { op: "stream"; session: string }
  | { op: "unstream"; session: string }
  | { op: "rig" }
  | { op: "rig_open"; port: string; baud: number }
  | { op: "rig_bytes"; bytes: ArrayBuffer; ended: boolean }
  | { op: "rig_close" }
  | { op: "rig_log" }
);

export interface WorkerAnswer {
  status: number;
  body: unknown;
}

export type WorkerMessage =
  | { id: number; answer: WorkerAnswer }
  | { stream: string; events: { event: string; data: unknown }[] };

declare function importScripts(...urls: string[]): void;
declare function createLab(options: object): Promise<LabModule>;

/** The stream's frame interval, as the server's (about 30 events a second). */
const FRAME_MS = 33;

const scope = self as unknown as {
  postMessage(message: WorkerMessage): void;
  onmessage: ((event: MessageEvent<WorkerRequest>) => void) | null;
};

const ready: Promise<LabModule> = (async () => {
  importScripts("frictionlab-lab.js");
  const lab = await createLab({ print: () => {}, printErr: (text: string) => console.warn(text) });
  lab.open_lab("/lab/scenes", "/lab/assets");
  return lab;
})();

const streams = new Map<string, number>();

function answered(text: string): WorkerAnswer {
  return JSON.parse(text) as WorkerAnswer;
}

function listen(lab: LabModule, session: string): void {
  if (streams.has(session)) return;
  const frame = () => {
    const answer = answered(lab.events(session));
    if (answer.status !== 200) {
      stop(session);
      return;
    }
    const events = answer.body as { event: string; data: unknown }[];
    // A paused run says nothing new: nothing is posted.
    if (events.length > 0) scope.postMessage({ stream: session, events });
  };
  streams.set(session, setInterval(frame, FRAME_MS) as unknown as number);
  frame();
}

function stop(session: string): void {
  clearInterval(streams.get(session));
  streams.delete(session);
}

/** The video's frames, decoded with the browser's own decoder, given to the lab under the file's
 * name; or why it could not be decoded, which the lab then says in its answer. */
async function giveVideo(lab: LabModule, name: string, bytes: ArrayBuffer): Promise<WorkerAnswer> {
  try {
    const video = await decodeVideo(bytes, lab.tracked_width());
    lab.video_begin(
      video.container,
      video.codec,
      video.width,
      video.height,
      video.fps,
      video.scale,
      "",
    );
    for (const frame of video.frames)
      lab.video_frame(frame.tS, frame.width, frame.height, frame.levels);
  } catch (error) {
    const why = error instanceof Error ? error.message : String(error);
    lab.video_begin(
      "",
      "",
      0,
      0,
      0,
      1,
      error instanceof VideoNotDecoded ? why : `the browser's decoder failed: ${why}`,
    );
  }
  return answered(lab.video_end(name));
}

async function handle(request: WorkerRequest): Promise<WorkerAnswer> {
  let lab: LabModule;
  try {
    lab = await ready;
  } catch (error) {
    const why = error instanceof Error ? error.message : String(error);
    return { status: 500, body: { error: `the lab in this browser did not start: ${why}` } };
  }
  switch (request.op) {
    case "lab":
      return answered(lab.lab());
    case "create":
      return answered(lab.create_session(request.body));
    case "control":
      return answered(lab.control(request.session, request.body));
    case "file":
      return answered(lab.file(request.session, request.name));
    case "report":
      return answered(lab.report(request.session, request.body));
    case "end":
      stop(request.session);
      return answered(lab.end(request.session));
    case "estimate": {
      const spacing = request.spacing === null ? "" : String(request.spacing);
      const bytes = new Uint8Array(request.bytes);
      // A video is decoded here first: the lab's tracker reads the frames the browser decoded.
      if (videoContainer(bytes) !== null) {
        const given = await giveVideo(lab, request.name, request.bytes);
        if (given.status !== 200) return given;
      }
      try {
        return answered(
          lab.estimate(request.name, bytes, spacing, request.spacing !== null, "", false),
        );
      } finally {
        lab.forget_videos();
      }
    }
    case "stream":
      listen(lab, request.session);
      return { status: 200, body: {} };
    case "unstream":
      stop(request.session);
      return { status: 200, body: {} };
    case "rig":
      return answered(lab.rig());
    case "rig_open":
      return answered(lab.rig_open(request.port, request.baud));
    case "rig_bytes":
      return answered(lab.rig_bytes(new Uint8Array(request.bytes), request.ended));
    case "rig_close":
      return answered(lab.rig_close());
    case "rig_log":
      return answered(lab.rig_log());
  }
}

scope.onmessage = (event) => {
  const request = event.data;
  void handle(request).then((answer) => scope.postMessage({ id: request.id, answer }));
};
