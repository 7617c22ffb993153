// The page's controller: the lab's session and the user's commands write the model (lab_model.ts);
// the 3D view, the plots, the readouts, the stopwatch and the playback buttons follow it.
import { base64Of } from "./base64";
import { SetupControls } from "./controls";
import { byId, setText } from "./dom";
import { ExportPanel } from "./export_panel";
import { t } from "./i18n";
import {
  getLab,
  LAB_PLACE,
  LabError,
  LabFullError,
  pageUrl,
  RateLimitedError,
  SetupError,
} from "./lab_client";
import { LabModel } from "./lab_model";
import { MeasurementPanel } from "./measurement_panel";
import type { Lab, PlaybackSpeed, Rig, Summary } from "./lab_types";
import { showPageLanguage, withPageLanguage } from "./page_language";
import { PeriodsTable } from "./periods_table";
import { Playback } from "./playback";
import { followWithTables } from "./plot_table";
import { HallPlot, PositionPlot } from "./plots";
import { Readouts } from "./readouts";
import { RigDescription } from "./rig_description";
import { RigPanel } from "./live_rig_panel";
import { SessionKeeper, Superseded } from "./session";
import { Stopwatch } from "./stopwatch";
import { StudentName } from "./student_name";
import { headlineOf } from "./summary";
import { RigView } from "./view3d";

const DEFAULT_SCENE = "paper-rig";

// The page's language first: the controls read and show numbers in it.
showPageLanguage();

let lab: Lab | null = null;
const model = new LabModel();

const view = new RigView(byId("view"));
const nearSide = byId<HTMLInputElement>("near-side");
nearSide.addEventListener("change", () => view.showNearSide(nearSide.checked));
byId("reset-view").addEventListener("click", () => view.resetView());
const positionPlot = new PositionPlot(byId("plot-x"));
const hallPlot = new HallPlot(byId("plot-hall"));
followWithTables(model, positionPlot, hallPlot);
new RigDescription(model, () => lab);
const hallNote = byId("hall-note");
const periods = new PeriodsTable(
  byId<HTMLTableSectionElement>("periods-body"),
  byId("periods-tally"),
  {
    newestFirst: false,
    decimals: 4,
    maxRows: 400,
    scroller: byId("periods-scroll"),
    accepted: t("periods-yes"),
    rejected: t("periods-no"),
  },
);
const readouts = new Readouts();
const pageProblem = byId("page-problem");
const refused = byId("refused");
const stopwatch = new Stopwatch(model);
const studentName = new StudentName((name) => void nameStudent(name));
const exportPanel = new ExportPanel(
  () => view.toPng(),
  async () => {
    const measured = measurement.measured;
    const file = measurement.measuredFile;
    return {
      student: studentName.name ?? "",
      stopwatch: stopwatch.timings(),
      language: document.documentElement.lang || "en",
      ...(measured ? { measurement: measured } : {}),
      ...(measured && file
        ? { measurement_file: { name: file.name, base64: await base64Of(file) } }
        : {}),
    };
  },
);

/** The class's table shows the name typed, on the session that runs now. */
async function nameStudent(name: string): Promise<void> {
  try {
    await keeper.command({ name });
  } catch (error) {
    if (error instanceof LabError && error.status === 400) studentName.refuse(error.message);
    else showPageProblem(error);
  }
}
byId<HTMLAnchorElement>("class-link").href = withPageLanguage(pageUrl("/class.html"));
// Which lab the page talks to: its own in this browser (the static site), or a server's.
setText(
  byId("lab-place"),
  LAB_PLACE === "browser" ? t("lab-place-browser") : t("lab-place-server", { host: location.host }),
);
// The class (a student's name, the class's table) is a classroom server's.
byId("class-section").hidden = LAB_PLACE === "browser";
// The static site opens offline once opened (tools/site writes sw.js beside the page).
if (LAB_PLACE === "browser" && "serviceWorker" in navigator) {
  navigator.serviceWorker.register("sw.js").catch(() => {
    // a page opened from a file, or a browser that keeps no workers: it works while online
  });
}
const rigPanel = new RigPanel({ connected: () => void runBesideRig() });
const measurement = new MeasurementPanel();

function showPageProblem(error: unknown): void {
  if (error instanceof RateLimitedError) {
    setText(pageProblem, error.message); // the lab's own words: too many requests, wait
    return;
  }
  const message = error instanceof Error ? error.message : String(error);
  setText(pageProblem, message ? t("page-problem-unexpected", { message }) : "");
}

function showRun(): void {
  playback.show({
    playing: model.playing.value,
    done: model.done.value,
    ready: keeper.current !== null,
  });
}

// The views follow the model.
model.rig.lazyLink((rig) => {
  if (!rig) return;
  view.setRig(rig);
  positionPlot.setRig(rig);
  if (lab) readouts.setRig(rig, lab);
  hallNote.hidden = rig.sensor !== null;
  measurement.setSpacing(rig.spacing);
});
model.state.lazyLink((state) => {
  if (state === null) {
    // Back to t = 0: empty plots, periods and estimate.
    positionPlot.clear();
    hallPlot.clear();
    periods.clear();
    readouts.reset();
    exportPanel.disableFiles();
    return;
  }
  view.setState(state);
  positionPlot.push(state);
  hallPlot.push(state);
  periods.add(state.periods);
  readouts.setState(state);
  playback.showSpeed(state.speed);
});
model.playing.lazyLink((playing) => {
  if (!model.done.value) readouts.setStatus(playing ? "playing" : "paused");
  showRun();
});
model.done.lazyLink((done) => {
  if (done) {
    readouts.setDone(model.headline.value);
    const session = keeper.current;
    if (session) void exportPanel.enableFiles(session);
  }
  showRun();
});

function showRig(rig: Rig): void {
  model.rig.value = rig;
  model.clearRun();
  model.playing.value = false;
  readouts.setStatus("paused");
  showRun();
}

const keeper = new SessionKeeper({
  state(state) {
    model.setState(state);
  },
  done(summary: Summary) {
    if (!model.done.value) model.finish(headlineOf(summary));
  },
  failed(failure) {
    readouts.setFailure(failure.message);
  },
  reset() {
    model.clearRun();
    readouts.setStatus("paused");
    showRun();
  },
  rig(event) {
    rigPanel.showEvent(event);
  },
  closed(message) {
    // The server is stopping: its message in the page's problem line, nothing more asked.
    keeper.drop();
    rigPanel.stop();
    model.playing.value = false;
    readouts.setStatus("no session");
    setText(pageProblem, message);
    showRun();
  },
});

async function command(action: Parameters<SessionKeeper["command"]>[0]): Promise<void> {
  try {
    const reply = await keeper.command(action);
    if (!reply) return;
    model.playing.value = reply.playing;
    showRun();
  } catch (error) {
    showPageProblem(error);
  }
}

async function reset(): Promise<void> {
  await command("reset");
  model.clearRun();
  readouts.setStatus("paused");
  showRun();
}

const playback = new Playback({
  toggle: () => {
    if (model.done.value) void reset().then(() => command("play"));
    else void command(model.playing.value ? "pause" : "play");
  },
  step: () => void command("step"),
  reset: () => void reset(),
  speed: (speed: PlaybackSpeed) => void command({ speed }),
});

/** A port was connected: the simulation of the same set-up from t = 0 at 1x, beside the rig. */
async function runBesideRig(): Promise<void> {
  if (!keeper.current) return;
  playback.showSpeed(1);
  await command({ speed: 1 });
  await reset();
  await command("play");
}

/** Starts the set-up's session (ending the one before); false where it was refused. */
async function openSetup(scene: string, entries: string[], play: boolean): Promise<boolean> {
  controls.busy = true;
  const name = studentName.name;
  try {
    const session = await keeper.open(scene, entries, name);
    showPageProblem("");
    setText(refused, "");
    controls.clearProblems();
    controls.scene = scene;
    controls.adoptRig(session.rig);
    showRig(session.rig);
    rigPanel.clearRun(); // the rig's estimate is made again with this session's spacing
    exportPanel.showLink(scene, entries);
    if (playback.speed !== 1) await command({ speed: playback.speed });
    if (play) await command("play");
    return true;
  } catch (error) {
    if (error instanceof Superseded) return false;
    if (error instanceof SetupError && name !== undefined && isNameRefusal(error)) {
      // The name alone was refused: say so beside it and run the set-up without it.
      studentName.refuse(error.problems.find((p) => p.field === "name")?.message ?? error.message);
      return openSetup(scene, entries, play);
    }
    if (error instanceof SetupError) controls.showProblems(error.problems, error.message);
    else if (error instanceof LabFullError) setText(refused, error.message);
    else showPageProblem(error);
    return false;
  } finally {
    controls.busy = false;
  }
}

/** The lab refused the session for its name only: its problems are all of the field "name". */
function isNameRefusal(error: SetupError): boolean {
  return error.problems.length > 0 && error.problems.every((p) => p.field === "name");
}

const controls = new SetupControls({
  setupChanged: () => void openSetup(controls.scene, controls.entries(), model.playing.value),
  sceneChanged: (scene) => {
    controls.forgetChanges();
    void openSetup(scene, [], model.playing.value);
  },
});

async function boot(): Promise<void> {
  try {
    lab = await getLab();
  } catch (error) {
    showPageProblem(error);
    return;
  }
  setText(byId("version"), lab.version);
  rigPanel.start();
  controls.populate(lab);
  const names = lab.scenes.map((s) => s.name);
  const fallback = names.includes(DEFAULT_SCENE) ? DEFAULT_SCENE : names[0];
  const params = new URLSearchParams(location.search);
  const linked = params.get("scene");
  if (linked) {
    // A link plays its set-up at once; a refused one keeps its problems shown beside the
    // controls and opens the scene as it is (or the default scene), paused.
    if (names.includes(linked)) controls.scene = linked;
    controls.takeLinkEntries(params.getAll("set"));
    if (await openSetup(linked, controls.entries(), true)) return;
    const problems = snapshotProblems();
    controls.forgetChanges();
    const scene = names.includes(linked) ? linked : fallback;
    if (scene && (await openSetup(scene, [], false))) problems();
    return;
  }
  if (fallback) await openSetup(fallback, [], false);
}

/** Keeps the messages beside the controls to show them again after another session opens. */
function snapshotProblems(): () => void {
  const shown = Array.from(document.querySelectorAll<HTMLElement>(".problem")).map(
    (element) => [element, Array.from(element.childNodes, (node) => node.cloneNode(true))] as const,
  );
  return () => {
    for (const [element, nodes] of shown) if (nodes.length > 0) element.replaceChildren(...nodes);
  };
}

void boot();
