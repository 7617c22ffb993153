// The set-up controls: the scene, the plate's material, the rollers, the friction law and the
// plate's start. A change starts a new session with the `--set` entries of what the user changed;
// a refused set-up shows each problem beside the control that made it.
import { byId } from "./dom";
import { appendWords, problemWords } from "./lab_says";
import { sceneWords } from "./scene_words";
import type { Lab, Problem, Rig } from "./lab_types";
import { LawSetting, MaterialSetting, NumberSetting, type Setting } from "./settings";

const COMMIT_DELAY_MS = 350;

export interface SetupHandlers {
  /** A set-up control changed: start a session with `entries()`. */
  setupChanged: () => void;
  /** Another scene was chosen: start it with no entries. */
  sceneChanged: (scene: string) => void;
}

export class SetupControls {
  private readonly form = byId<HTMLFormElement>("setup");
  private readonly sceneSelect = byId<HTMLSelectElement>("scene");
  private readonly sceneProblem: HTMLElement;
  private readonly otherProblem = byId("setup-problem");
  private readonly settings: Setting[];
  private readonly law: LawSetting;
  private readonly stribeck: NumberSetting[];
  private readonly material: MaterialSetting;
  /** `?set=` entries no control shows, sent as they came. */
  private extras: string[] = [];
  private commitTimer = 0;

  constructor(handlers: SetupHandlers) {
    const commit = () => {
      window.clearTimeout(this.commitTimer);
      this.commitTimer = window.setTimeout(() => handlers.setupChanged(), COMMIT_DELAY_MS);
    };
    const now = () => {
      window.clearTimeout(this.commitTimer);
      handlers.setupChanged();
    };
    this.sceneProblem = this.sceneSelect.closest(".field")!.querySelector<HTMLElement>(".problem")!;
    this.form.addEventListener("submit", (event) => event.preventDefault());
    this.sceneSelect.addEventListener("change", () => {
      window.clearTimeout(this.commitTimer);
      handlers.sceneChanged(this.sceneSelect.value);
    });

    this.material = new MaterialSetting(now);
    this.law = new LawSetting(() => {
      this.enableStribeck();
      now();
    });
    const number = (options: ConstructorParameters<typeof NumberSetting>[0]) =>
      new NumberSetting(options, commit);
    this.stribeck = [
      number({
        id: "mu-s",
        key: "friction.mu_s",
        unit: "",
        fromRig: () => null,
        sceneValueKnown: false,
        decimals: 4,
      }),
      number({
        id: "v-s",
        key: "friction.v_s",
        unit: "m/s",
        fromRig: () => null,
        sceneValueKnown: false,
        decimals: 6,
      }),
      number({
        id: "beta",
        key: "friction.beta",
        unit: "s/m",
        fromRig: () => null,
        sceneValueKnown: false,
        decimals: 4,
      }),
    ];
    this.settings = [
      this.material,
      number({
        id: "spacing-mm",
        key: "rollers.spacing",
        unit: "mm",
        fromRig: (rig) => rig.spacing * 1000,
        sceneValueKnown: true,
        decimals: 1,
        perSi: 1000,
      }),
      number({
        id: "speed-rpm",
        key: "rollers.speed",
        unit: "rpm",
        fromRig: (rig) => rig.roller_speed_rpm,
        sceneValueKnown: true,
        decimals: 0,
        appliesTo: (rig) => !rig.drive,
        perSi: 60 / (2 * Math.PI),
        sliderSpan: [0, 5000],
      }),
      number({
        id: "duty-pct",
        key: "drive.motor.duty",
        unit: "%",
        fromRig: () => 100,
        sceneValueKnown: false, // the rig gives the rollers' speed, not the motor's duty
        decimals: 0,
        appliesTo: (rig) => rig.drive,
        perSi: 100,
      }),
      this.law,
      ...this.stribeck,
      number({
        id: "runout-mm",
        key: "rollers.runout",
        unit: "mm",
        fromRig: () => null,
        sceneValueKnown: false,
        decimals: 3,
      }),
      number({
        id: "offset-mm",
        key: "plate.offset",
        unit: "mm",
        fromRig: (rig) => rig.offset * 1000,
        sceneValueKnown: true,
        decimals: 1,
        perSi: 1000,
      }),
      // How long the run lasts: a class timing ten periods by hand needs more than a few.
      number({
        id: "duration-s",
        key: "world.duration",
        unit: "s",
        fromRig: (rig) => rig.duration,
        sceneValueKnown: true,
        decimals: 3,
        perSi: 1,
      }),
    ];
    this.enableStribeck();
  }

  populate(lab: Lab): void {
    this.sceneSelect.replaceChildren();
    for (const scene of lab.scenes) {
      const option = document.createElement("option");
      option.value = scene.name;
      option.textContent = sceneWords(scene.name, scene.title);
      option.title = scene.title;
      this.sceneSelect.append(option);
    }
    this.material.populate(lab);
  }

  get scene(): string {
    return this.sceneSelect.value;
  }

  set scene(name: string) {
    this.sceneSelect.value = name;
  }

  set busy(on: boolean) {
    this.form.setAttribute("aria-busy", String(on));
  }

  /** Takes `?set=` entries as the user's changes; keeps those no control shows as they are. */
  takeLinkEntries(entries: string[]): void {
    this.extras = [];
    for (const entry of entries) {
      const at = entry.indexOf("=");
      const key = at < 0 ? entry : entry.slice(0, at).trim();
      const value = at < 0 ? "" : entry.slice(at + 1).trim();
      if (!this.settings.some((s) => s.takeEntry(key, value))) this.extras.push(entry);
    }
    this.enableStribeck();
  }

  /** A new scene: forget the user's changes and the link's entries. */
  forgetChanges(): void {
    window.clearTimeout(this.commitTimer);
    this.extras = [];
    for (const setting of this.settings) setting.forget();
    this.enableStribeck();
  }

  adoptRig(rig: Rig): void {
    for (const setting of this.settings) setting.adopt(rig);
    this.enableStribeck();
  }

  /** The `--set` entries for what differs from the scene, in the controls' order. */
  entries(): string[] {
    const fromControls = this.settings.flatMap((s) => s.entries());
    const keysSet = new Set(fromControls.map((e) => e.slice(0, e.indexOf("="))));
    const extras = this.extras.filter((e) => !keysSet.has(e.slice(0, e.indexOf("=")).trim()));
    return [...extras, ...fromControls];
  }

  clearProblems(): void {
    for (const element of [this.sceneProblem, this.otherProblem]) element.textContent = "";
    this.sceneSelect.removeAttribute("aria-invalid");
    for (const setting of this.settings) {
      setting.problem.textContent = "";
      for (const input of setting.inputs) input.removeAttribute("aria-invalid");
    }
  }

  /**
   * Shows each problem beside the control whose set entry (or field) it names; that control goes
   * back to what the lab runs, so the other controls go on working.
   */
  showProblems(problems: Problem[], fallback: string): void {
    this.clearProblems();
    if (problems.length === 0) appendWords(this.otherProblem, { text: fallback, lang: null });
    const refused = new Set<Setting>();
    for (const problem of problems) {
      const words = problemWords(problem);
      if (problem.field === "scene") {
        appendWords(this.sceneProblem, words);
        this.sceneSelect.setAttribute("aria-invalid", "true");
        continue;
      }
      const key = (problem.value ?? "").split("=")[0]!.trim();
      const setting = this.settings.find((s) => s.keys.includes(key));
      if (!setting || setting.field.hidden) {
        appendWords(this.otherProblem, words, problem.value ? `${problem.value}: ` : "");
        continue;
      }
      appendWords(setting.problem, words);
      refused.add(setting);
    }
    for (const setting of refused) setting.revert();
    this.enableStribeck();
  }

  private enableStribeck(): void {
    for (const setting of this.stribeck) setting.enabled = this.law.law !== "coulomb";
  }
}
