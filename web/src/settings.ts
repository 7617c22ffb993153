// One set-up control each: what it shows, the scene's own value, and the `--set` entries it
// makes, only where the user changed it from the scene's value.
import { byId } from "./dom";
import { t } from "./i18n";
import { pageLocale, readNumber, showNumber } from "./locale_number";
import type { Lab, Rig } from "./lab_types";
import { materialWords } from "./material_words";

export interface Setting {
  /** The `--set` keys this control makes (problems naming them are shown beside it). */
  readonly keys: string[];
  readonly field: HTMLElement;
  readonly problem: HTMLElement;
  readonly inputs: HTMLElement[];
  entries(): string[];
  /** Takes the scene's values from a session's rig where the user did not change them. */
  adopt(rig: Rig): void;
  /** Shows a `?set=` entry as the user's change; false where this control can't show it. */
  takeEntry(key: string, value: string): boolean;
  /** Forgets the user's changes (a new scene). */
  forget(): void;
  /** Shows again what the lab last took (after a refusal), the user's changes in it kept. */
  revert(): void;
}

function fieldParts(id: string): { field: HTMLElement; problem: HTMLElement } {
  const input = byId(id);
  const field = input.closest<HTMLElement>(".field");
  const problem = field?.querySelector<HTMLElement>(".problem");
  if (!field || !problem) throw new Error(`#${id} is not in a .field with a .problem`);
  return { field, problem };
}

function escapeRegExp(text: string): string {
  return text.replace(/[.*+?^${}()|[\]\\]/g, "\\$&");
}

export interface NumberOptions {
  id: string;
  key: string;
  /** The unit the set entry's value carries: "mm", "rpm", "%", "m/s", "s/m", "". */
  unit: string;
  /** The scene's value in the control's unit, or null where the rig doesn't say. */
  fromRig: (rig: Rig) => number | null;
  /** The rig says it: a value equal to it is no change. */
  sceneValueKnown: boolean;
  decimals: number;
  /** Shown only for rigs where this holds. */
  appliesTo?: (rig: Rig) => boolean;
  /** The control's unit per SI unit of the rig's accepted range (1000 for mm); none: no range. */
  perSi?: number;
  /** The slider's own span where it is narrower than what the set-up accepts (rpm to 5000). */
  sliderSpan?: [number, number];
}

/** What a number control showed and meant when the lab last took its set-up. */
interface NumberShown {
  text: string;
  touched: boolean;
  fromLink: boolean;
}

/**
 * A number with its unit, a slider beside it where the page has `#ID-range`. Typed in the page's
 * language; offered only in the range the set-up accepts (the rig's `accepts`); a value the lab
 * refuses goes back to what the lab runs, its message beside it.
 */
export class NumberSetting implements Setting {
  readonly keys: string[];
  readonly field: HTMLElement;
  readonly problem: HTMLElement;
  readonly inputs: HTMLElement[];
  private readonly number: HTMLInputElement;
  private readonly range: HTMLInputElement | null;
  private readonly acceptsHint: HTMLElement;
  /** What the set-up accepts, in the control's unit (the rig's `accepts`); null: not said. */
  private accepted: [number, number] | null = null;
  /** Its ends and unit as the page shows them. */
  private acceptedWords = { least: "", most: "", unit: "" };
  private sceneValue: number | null = null;
  private touched = false;
  private fromLink = false;
  private applies = true;
  private taken: NumberShown = { text: "", touched: false, fromLink: false };

  constructor(
    private readonly options: NumberOptions,
    onCommit: () => void,
  ) {
    this.keys = [options.key];
    this.number = byId<HTMLInputElement>(options.id);
    this.range = document.getElementById(`${options.id}-range`) as HTMLInputElement | null;
    ({ field: this.field, problem: this.problem } = fieldParts(options.id));
    this.inputs = this.range ? [this.range, this.number] : [this.number];
    this.acceptsHint = document.createElement("p");
    this.acceptsHint.className = "hint accepts";
    this.acceptsHint.id = `${options.id}-accepts`;
    this.acceptsHint.dataset.testid = `accepts-${options.id}`;
    this.acceptsHint.hidden = true;
    this.problem.before(this.acceptsHint);
    this.number.setAttribute(
      "aria-describedby",
      `${this.acceptsHint.id} ${this.number.getAttribute("aria-describedby") ?? ""}`.trim(),
    );
    this.number.addEventListener("input", () => {
      this.touched = true;
      const reading = this.reading();
      if (this.range && reading !== null) this.range.value = String(reading);
    });
    this.number.addEventListener("change", () => {
      this.touched = true;
      const read = readNumber(this.number.value, pageLocale());
      if ("problem" in read && this.number.value.trim() !== "") {
        // Never sent: its problem beside it, the control back to what the lab runs.
        this.problem.textContent = read.problem;
        this.revert();
        return;
      }
      const beyond = "value" in read ? this.beyondAccepted(read.value) : null;
      if (beyond) {
        // The lab would refuse it (the range is its own checks'): said here, in the page's
        // language, and never sent.
        this.problem.textContent = beyond;
        this.revert();
        return;
      }
      onCommit();
    });
    this.range?.addEventListener("input", () => {
      this.touched = true;
      this.number.value = showNumber(
        Number(this.range!.value),
        this.options.decimals,
        pageLocale(),
      );
    });
    this.range?.addEventListener("change", () => onCommit());
  }

  /** What is wrong with `value` for the set-up's accepted range, or null where it lies in it. */
  private beyondAccepted(value: number): string | null {
    if (!this.accepted) return null;
    const [least, most] = this.accepted;
    const slack = 1e-9 * Math.max(1, Math.abs(least), Math.abs(most));
    if (value >= least - slack && value <= most + slack) return null;
    return t("setup-beyond", {
      ...this.acceptedWords,
      found: showNumber(value, this.options.decimals + 3, pageLocale()),
    });
  }

  /** The number the control shows, or null where it shows none (or none it can read). */
  private reading(): number | null {
    const read = readNumber(this.number.value, pageLocale());
    return "value" in read ? read.value : null;
  }

  set enabled(on: boolean) {
    for (const input of this.inputs) (input as HTMLInputElement).disabled = !on;
  }

  private changed(): boolean {
    const value = this.reading();
    if (value === null) return false;
    if (this.fromLink) return true;
    if (!this.touched) return false;
    return !this.options.sceneValueKnown || value !== this.sceneValue;
  }

  entries(): string[] {
    if (!this.changed() || (!this.applies && !this.fromLink)) return [];
    return [`${this.options.key}=${String(this.reading())}${this.options.unit}`];
  }

  private show(value: number | null): void {
    this.number.value =
      value === null ? "" : showNumber(value, this.options.decimals, pageLocale());
    if (this.range && value !== null) this.range.value = String(value);
  }

  adopt(rig: Rig): void {
    this.applies = this.options.appliesTo?.(rig) ?? true;
    this.field.hidden = !this.applies;
    this.limit(rig);
    if (!this.changed()) {
      const value = this.options.fromRig(rig);
      this.sceneValue = value === null ? null : Number(value.toFixed(this.options.decimals));
      this.touched = false;
      this.show(this.sceneValue);
    }
    this.taken = { text: this.number.value, touched: this.touched, fromLink: this.fromLink };
  }

  /** Offers only what the set-up accepts: the slider's ends, and the range said beside it. */
  private limit(rig: Rig): void {
    const perSi = this.options.perSi;
    const accepted = perSi ? rig.accepts.find((r) => r.key === this.options.key) : undefined;
    this.acceptsHint.hidden = !accepted;
    this.accepted = null;
    if (!accepted || !perSi) return;
    const least = accepted.least * perSi;
    const most = accepted.most * perSi;
    this.accepted = [least, most];
    const locale = pageLocale();
    const decimals = this.options.decimals;
    // Rounded inward: the hint's ends are accepted values too.
    const inward = (value: number, up: boolean) => {
      const scale = 10 ** decimals;
      return (up ? Math.ceil(value * scale - 1e-9) : Math.floor(value * scale + 1e-9)) / scale;
    };
    this.acceptedWords = {
      least: showNumber(inward(least, true), decimals, locale),
      most: showNumber(inward(most, false), decimals, locale),
      unit: this.options.unit === "rpm" ? t("unit-rpm") : this.options.unit,
    };
    this.acceptsHint.textContent = t("setup-accepts", this.acceptedWords);
    if (!this.range) return;
    const step = Number(this.range.step) || 1;
    const [spanLeast, spanMost] = this.options.sliderSpan ?? [least, most];
    // A slider's value lies on its steps from min: its ends are accepted values on them.
    this.range.min = String(Math.ceil(Math.max(least, spanLeast) / step - 1e-9) * step);
    this.range.max = String(Math.floor(Math.min(most, spanMost) / step + 1e-9) * step);
  }

  revert(): void {
    this.number.value = this.taken.text;
    const value = this.reading();
    if (this.range && value !== null) this.range.value = String(value);
    this.touched = this.taken.touched;
    this.fromLink = this.taken.fromLink;
  }

  takeEntry(key: string, value: string): boolean {
    if (key !== this.options.key) return false;
    const unit = escapeRegExp(this.options.unit);
    const match = new RegExp(
      `^\\s*([-+]?(?:\\d+\\.?\\d*|\\.\\d+)(?:[eE][-+]?\\d+)?)\\s*${unit}\\s*$`,
    ).exec(value);
    if (!match) return false;
    this.show(Number(match[1]!));
    this.fromLink = true;
    return true;
  }

  forget(): void {
    this.touched = false;
    this.fromLink = false;
  }
}

/** The plate's material at 300 K, or at 77 K where Table I has it. */
export class MaterialSetting implements Setting {
  readonly keys = ["plate.material", "friction.temperature"];
  readonly field: HTMLElement;
  readonly problem: HTMLElement;
  readonly inputs: HTMLElement[];
  private readonly select: HTMLSelectElement;
  private sceneMaterial = "";
  private sceneTemperature: number | null = null;
  private touched = false;
  private linkKeys = new Set<string>();
  private taken = { value: "", touched: false, linkKeys: [] as string[] };

  constructor(onCommit: () => void) {
    this.select = byId<HTMLSelectElement>("material");
    ({ field: this.field, problem: this.problem } = fieldParts("material"));
    this.inputs = [this.select];
    this.select.addEventListener("change", () => {
      this.touched = true;
      onCommit();
    });
  }

  populate(lab: Lab): void {
    this.select.replaceChildren();
    for (const material of lab.materials) {
      for (const kelvin of material.temperatures_k) {
        const option = document.createElement("option");
        option.value = `${material.key}@${kelvin}`;
        option.textContent = `${materialWords(material.key, material.name)}, ${kelvin} K`;
        this.select.append(option);
      }
    }
  }

  private chosen(): { material: string; kelvin: number } {
    const [material = "", kelvin = "300"] = this.select.value.split("@");
    return { material, kelvin: Number(kelvin) };
  }

  private choose(material: string, kelvin: number): void {
    const value = `${material}@${kelvin}`;
    if (!Array.from(this.select.options).some((o) => o.value === value)) {
      const option = document.createElement("option");
      option.value = value;
      option.textContent = `${material}, ${kelvin} K`;
      this.select.append(option);
    }
    this.select.value = value;
  }

  entries(): string[] {
    if (!this.touched && this.linkKeys.size === 0) return [];
    const { material, kelvin } = this.chosen();
    const out: string[] = [];
    if (material !== this.sceneMaterial || this.linkKeys.has("plate.material")) {
      out.push(`plate.material=${material}`);
    }
    // The rig may not say the scene's temperature: then a chosen one is always sent.
    if (
      (this.touched && (this.sceneTemperature === null || kelvin !== this.sceneTemperature)) ||
      this.linkKeys.has("friction.temperature")
    ) {
      out.push(`friction.temperature=${kelvin}K`);
    }
    return out;
  }

  adopt(rig: Rig): void {
    if (!this.touched && this.linkKeys.size === 0) {
      const extra = rig as unknown as { temperature_k?: unknown };
      this.sceneMaterial = rig.plate.material;
      this.sceneTemperature = typeof extra.temperature_k === "number" ? extra.temperature_k : null;
      this.choose(rig.plate.material, this.sceneTemperature ?? 300);
    }
    this.taken = {
      value: this.select.value,
      touched: this.touched,
      linkKeys: Array.from(this.linkKeys),
    };
  }

  revert(): void {
    this.select.value = this.taken.value;
    this.touched = this.taken.touched;
    this.linkKeys = new Set(this.taken.linkKeys);
  }

  takeEntry(key: string, value: string): boolean {
    const { material, kelvin } = this.chosen();
    if (key === "plate.material" && /^[a-z0-9-]+$/.test(value)) {
      this.choose(value, kelvin);
    } else if (key === "friction.temperature") {
      const match = /^\s*(\d+(?:\.\d+)?)\s*K\s*$/.exec(value);
      if (!match) return false;
      this.choose(material, Number(match[1]));
    } else {
      return false;
    }
    this.linkKeys.add(key);
    return true;
  }

  forget(): void {
    this.touched = false;
    this.linkKeys.clear();
  }
}

/** Coulomb or Stribeck friction; "as the scene" sends nothing. */
export class LawSetting implements Setting {
  readonly keys = ["friction.law"];
  readonly field: HTMLElement;
  readonly problem: HTMLElement;
  readonly inputs: HTMLElement[];
  readonly select: HTMLSelectElement;
  private fromLink = false;
  private taken = "";

  constructor(onCommit: () => void) {
    this.select = byId<HTMLSelectElement>("law");
    ({ field: this.field, problem: this.problem } = fieldParts("law"));
    this.inputs = [this.select];
    this.select.addEventListener("change", () => onCommit());
  }

  get law(): string {
    return this.select.value;
  }

  entries(): string[] {
    return this.select.value === "" ? [] : [`friction.law=${this.select.value}`];
  }

  adopt(): void {
    // The rig does not name its law: "as the scene" stays until the user picks one.
    this.taken = this.select.value;
  }

  revert(): void {
    this.select.value = this.taken;
  }

  takeEntry(key: string, value: string): boolean {
    if (key !== "friction.law" || !["coulomb", "stribeck"].includes(value)) return false;
    this.select.value = value;
    this.fromLink = true;
    return true;
  }

  forget(): void {
    this.fromLink = false;
    this.select.value = "";
  }
}
