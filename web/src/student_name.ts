// Who runs the page's sessions, for the class's table: a name kept in this browser
// (localStorage) and sent with the next session the page starts (docs/web-api.md: up to 40
// letters, digits, spaces and . - _ ' , ( ), by the server's rule). A name the page or the lab refuses
// is shown beside the field and left out: the lab runs without it.
import { byId, byTestId, setText } from "./dom";
import { t } from "./i18n";

const STORED = "frictionlab.student-name";
const MOST_CHARACTERS = 40;
/** The pause in typing after which the name is sent [ms]. */
const TYPING_PAUSE_MS = 600;

/** A letter or digit by the server's rule: ASCII letters and digits, and U+00C0 to U+DFFF but
 * U+2000 to U+2FFF (the letters of Latin, Greek, Cyrillic, Arabic, Indic and CJK scripts). */
function letterOrDigit(codePoint: number): boolean {
  if (codePoint < 0x80) return /[A-Za-z0-9]/.test(String.fromCodePoint(codePoint));
  return codePoint >= 0xc0 && codePoint <= 0xdfff && !(codePoint >= 0x2000 && codePoint <= 0x2fff);
}

function stored(): string {
  try {
    return localStorage.getItem(STORED) ?? "";
  } catch {
    return ""; // storage refused (a private window): the field starts empty
  }
}

function store(name: string): void {
  try {
    if (name) localStorage.setItem(STORED, name);
    else localStorage.removeItem(STORED);
  } catch {
    // kept for this page only
  }
}

/**
 * Why the name cannot be sent, or null when it can (or is empty): the server's rule
 * (src/serve/api_requests.hpp, is_student_name), both held to tests/data/student_names.json.
 * Letters and digits, spaces and . - _ ' , ( ), beginning with a letter or digit (so that no
 * spreadsheet reads the class's CSV cell as a formula).
 */
export function problemOf(name: string): string | null {
  if (name === "") return null;
  const characters = [...name];
  if (characters.length > MOST_CHARACTERS) {
    return t("student-name-too-long", { most: MOST_CHARACTERS });
  }
  const allowed = characters.every((character, i) => {
    const codePoint = character.codePointAt(0) ?? 0;
    return letterOrDigit(codePoint) || (i > 0 && " .-_',()".includes(character));
  });
  return allowed ? null : t("student-name-characters");
}

export class StudentName {
  private readonly input = byTestId<HTMLInputElement>("student-name");
  private readonly problem = byId("student-name-problem");
  /** The name the lab refused, left out until the field changes. */
  private refused: string | null = null;

  private typing = 0;

  /** `changed`: the name to show in the class's table now ("" for none), called once the
   * student stops typing for a moment, so that a name typed while a run plays reaches the
   * table without starting the run again. */
  constructor(changed: (name: string) => void = () => {}) {
    this.input.maxLength = MOST_CHARACTERS;
    this.input.value = stored();
    this.input.addEventListener("input", () => {
      this.refused = null;
      store(this.value);
      this.check();
      window.clearTimeout(this.typing);
      this.typing = window.setTimeout(() => {
        if (problemOf(this.value) === null) changed(this.value);
      }, TYPING_PAUSE_MS);
    });
    this.check();
  }

  /** The name to send with the next session: undefined when empty or refused. */
  get name(): string | undefined {
    const name = this.value;
    if (name === "" || name === this.refused || problemOf(name) !== null) return undefined;
    return name;
  }

  /** The lab refused the name (`message` says why): the next sessions go without it. */
  refuse(message: string): void {
    this.refused = this.value;
    this.show(message);
  }

  private get value(): string {
    return this.input.value.normalize("NFC").trim();
  }

  private check(): void {
    const problem = problemOf(this.value);
    this.show(problem === null ? "" : t("student-name-not-sent", { problem }));
  }

  private show(message: string): void {
    setText(this.problem, message);
    if (message) this.input.setAttribute("aria-invalid", "true");
    else this.input.removeAttribute("aria-invalid");
  }
}
