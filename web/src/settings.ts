// One set-up control each: what it shows, the scene's own value, and the `--set` entries it
// makes, only where the user changed it from the scene's value.
import { byId } from "./dom";
import { trimmed } from "./format";
import type { Lab, Rig } from "./lab_types";

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
}

function fieldParts(id: string): { field: HTMLElement; problem: HTMLElement } {
  const input = byId(id);
  const field = input.closest<HTMLElement>(".field");
  const problem = field?.querySelector<HTMLElement>(".problem");
  if (!field || !problem) throw new Error(`#${id} is not in a .field with a .problem`);
  return { field, problem };
}

function sameNumber(a: string, b: string): boolean {
  return a.trim() !== "" && b.trim() !== "" && Number(a) === Number(b);
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
}

/** A number with its unit, a slider beside it where the page has `#ID-range`. */
export class NumberSetting implements Setting {
  readonly keys: string[];
  readonly field: HTMLElement;
  readonly problem: HTMLElement;
  readonly inputs: HTMLElement[];
  private readonly number: HTMLInputElement;
  private readonly range: HTMLInputElement | null;
  private sceneValue = "";
  private touched = false;
  private fromLink = false;
  private applies = true;

  constructor(
    private readonly options: NumberOptions,
    onCommit: () => void,
  ) {
    this.keys = [options.key];
    this.number = byId<HTMLInputElement>(options.id);
    this.range = document.getElementById(`${options.id}-range`) as HTMLInputElement | null;
    ({ field: this.field, problem: this.problem } = fieldParts(options.id));
    this.inputs = this.range ? [this.range, this.number] : [this.number];
    this.number.addEventListener("input", () => {
      this.touched = true;
      if (this.range && this.number.value !== "") this.range.value = this.number.value;
    });
    this.number.addEventListener("change", () => {
      this.touched = true;
      onCommit();
    });
    this.range?.addEventListener("input", () => {
      this.touched = true;
      this.number.value = this.range!.value;
    });
    this.range?.addEventListener("change", () => onCommit());
  }

  get value(): string {
    return this.number.value.trim();
  }

  set enabled(on: boolean) {
    for (const input of this.inputs) (input as HTMLInputElement).disabled = !on;
  }

  private changed(): boolean {
    if (this.value === "") return false;
    if (this.fromLink) return true;
    if (!this.touched) return false;
    return !this.options.sceneValueKnown || !sameNumber(this.value, this.sceneValue);
  }

  entries(): string[] {
    if (!this.changed() || (!this.applies && !this.fromLink)) return [];
    return [`${this.options.key}=${this.value}${this.options.unit}`];
  }

  private show(value: string): void {
    this.number.value = value;
    if (this.range && value !== "") this.range.value = value;
  }

  adopt(rig: Rig): void {
    this.applies = this.options.appliesTo?.(rig) ?? true;
    this.field.hidden = !this.applies;
    if (this.changed()) return;
    const value = this.options.fromRig(rig);
    this.sceneValue = value === null ? "" : trimmed(value, this.options.decimals);
    this.touched = false;
    this.show(this.sceneValue);
  }

  takeEntry(key: string, value: string): boolean {
    if (key !== this.options.key) return false;
    const unit = escapeRegExp(this.options.unit);
    const match = new RegExp(
      `^\\s*([-+]?(?:\\d+\\.?\\d*|\\.\\d+)(?:[eE][-+]?\\d+)?)\\s*${unit}\\s*$`,
    ).exec(value);
    if (!match) return false;
    this.show(match[1]!);
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
        option.textContent = `${material.name}, ${kelvin} K`;
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
    if (this.touched || this.linkKeys.size > 0) return;
    const extra = rig as unknown as { temperature_k?: unknown };
    this.sceneMaterial = rig.plate.material;
    this.sceneTemperature = typeof extra.temperature_k === "number" ? extra.temperature_k : null;
    this.choose(rig.plate.material, this.sceneTemperature ?? 300);
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
