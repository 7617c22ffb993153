// The page in the reader's language, against tests/mock_server.mjs in headless Chromium: a French
// browser gets the page in French (<html lang="fr">, its buttons, labels and readouts), `?lang=en`
// gets English there, and the switcher opens the same address in the language chosen; a number is
// typed with a decimal comma in French and sent to the lab as a number, and the readouts, the
// regime and a plot's table show French numbers and words; axe-core finds no WCAG 2.1 A or AA
// violation on the French lab's page and class's table, and a phone shows the 3D view, T, μk and
// the position plot in its first screen in French too; a link to a set-up, and to the other page,
// carries `lang=` where the page's own address asked for its language. No console complaint (a
// message missing from every catalogue is one).
//
// Nothing here depends on the machine's pace: every wait is for a condition, with a generous
// deadline (WAIT_MS), never a sleep.
//
//   FRICTIONLAB_MOCK_RECORDING=FILE node tests/page_lang.test.mjs
import { readdirSync, readFileSync } from "node:fs";
import { dirname, join, resolve } from "node:path";
import { fileURLToPath } from "node:url";
import { FAKE_RIG_PORT, startBuiltPage } from "./mock_server.mjs";
import {
  check,
  expect,
  expectNoViolations,
  finish,
  launchChromium,
  openWatchedPage,
  skipWithoutChromium,
  WAIT_MS,
} from "./browser_checks.mjs";

const web = resolve(dirname(fileURLToPath(import.meta.url)), "..");
skipWithoutChromium();

const { base, stop } = await startBuiltPage();
const browser = await launchChromium();

/** The space French writes between a number and its unit, before a colon, in « »: unbreakable. */
const NBSP = "\u00a0";

/** A page in a browser of the language `locale`, recording console errors and warnings. */
function openPage(path, locale = "fr-FR") {
  return openWatchedPage(browser, `${base}${path}`, {
    viewport: { width: 1366, height: 768 },
    locale,
  });
}

const text = async (locator) => (await locator.textContent()).trim();
const language = (page) => page.evaluate(() => document.documentElement.lang);
const spacingLabel = (page) => text(page.locator('label[for="spacing-mm"]'));

async function creates() {
  const log = await (await fetch(`${base}/__mock/log`)).json();
  return log.filter((entry) => entry.create).map((entry) => entry.create);
}

await check("a French browser gets the page in French", async () => {
  const { page, context, complaints } = await openPage("/");
  await page
    .getByTestId("spacing")
    .filter({ hasText: `89${NBSP}mm` })
    .waitFor();
  expect((await language(page)) === "fr", `<html lang="${await language(page)}">`);
  expect((await text(page.getByTestId("play"))) === "Lecture", "the Play button");
  expect((await spacingLabel(page)) === "Entraxe des rouleaux l", "the spacing's label");
  expect((await text(page.getByTestId("status"))) === "en pause", "the run's status");
  expect((await page.title()).includes("oscillateur à frottement"), await page.title());
  const slider = await page.locator("#spacing-mm-range").getAttribute("aria-label");
  expect(slider === "Entraxe des rouleaux l, curseur (mm)", `the slider's name: ${slider}`);
  const rpm = await text(page.locator('[data-testid="speed"]'));
  expect(rpm.endsWith(`${NBSP}tr/min (entraînés par le moteur)`), `the rollers' speed: ${rpm}`);
  // The plate's material by its French name (the paper's rig's: LEGO), in the list and the readout.
  const chosen = await text(page.locator("#material option:checked"));
  expect(chosen === "Blocs LEGO, 300 K", `the material chosen: ${chosen}`);
  const polished = await page.locator('#material option[value="polished-wood@77"]').textContent();
  expect(polished === "Bois poli, 77 K", `a material offered: ${polished}`);
  const accepts = await text(page.getByTestId("accepts-spacing-mm"));
  expect(accepts === `Ce réglage accepte de 40 à 104${NBSP}mm.`, `the accepted range: ${accepts}`);
  // The switcher offers each language by its own name, this one chosen.
  const offered = await page
    .getByTestId("language")
    .evaluate((select) => Array.from(select.options, (o) => `${o.value}:${o.textContent}`));
  // Every catalogue of assets/locales, by the language's name in itself (its language-name).
  const catalogues = readdirSync(join(web, "../assets/locales"))
    .filter((name) => name.endsWith(".ftl"))
    .sort()
    .map((name) => {
      const ftl = readFileSync(join(web, "../assets/locales", name), "utf8");
      return `${name.slice(0, -4)}:${/^language-name = (.*)$/m.exec(ftl)[1]}`;
    });
  expect(catalogues.length >= 2, `only ${catalogues} in assets/locales`);
  expect(offered.join(" ") === catalogues.join(" "), `the switcher offers ${offered}`);
  expect((await page.getByTestId("language").inputValue()) === "fr", "French is not chosen");
  // A language chosen by the browser stays the browser's: the set-up's link does not carry it.
  const link = await page.getByTestId("setup-link").inputValue();
  expect(!new URL(link).searchParams.has("lang"), `the set-up's link: ${link}`);
  expect(complaints.length === 0, `console: ${complaints.join("\n")}`);
  await context.close();
});

await check("?lang=en gives English in a French browser; fr-CA gets French", async () => {
  const { page, context, complaints } = await openPage("/?lang=en");
  await page.getByTestId("spacing").filter({ hasText: "89 mm" }).waitFor();
  expect((await language(page)) === "en", `<html lang="${await language(page)}">`);
  expect((await text(page.getByTestId("play"))) === "Play", "the Play button");
  expect((await spacingLabel(page)) === "Roller spacing l", "the spacing's label");
  expect((await page.getByTestId("language").inputValue()) === "en", "English is not chosen");
  expect(complaints.length === 0, `console: ${complaints.join("\n")}`);
  await context.close();
  const canadian = await openPage("/", "fr-CA");
  await canadian.page
    .getByTestId("spacing")
    .filter({ hasText: `89${NBSP}mm` })
    .waitFor();
  expect((await language(canadian.page)) === "fr", "fr-CA is not French");
  await canadian.context.close();
});

await check("the switcher opens the same address in French", async () => {
  const { page, context, complaints } = await openPage(
    "/?scene=minimal&set=world.duration%3D60s",
    "en-US",
  );
  await page.getByTestId("status").filter({ hasText: "playing" }).waitFor();
  expect((await spacingLabel(page)) === "Roller spacing l", "not English at first");
  await Promise.all([
    page.waitForURL((url) => url.searchParams.get("lang") === "fr"),
    page.getByTestId("language").selectOption("fr"),
  ]);
  const address = new URL(page.url());
  expect(address.searchParams.get("scene") === "minimal", `the address: ${address}`);
  expect(address.searchParams.get("set") === "world.duration=60s", `the address: ${address}`);
  await page.getByTestId("status").filter({ hasText: "en cours" }).waitFor();
  expect((await language(page)) === "fr", `<html lang="${await language(page)}">`);
  expect((await spacingLabel(page)) === "Entraxe des rouleaux l", "the spacing's label");
  expect((await text(page.getByTestId("play"))) === "Pause", "the Pause button");
  expect(complaints.length === 0, `console: ${complaints.join("\n")}`);
  await context.close();
});

await check("French numbers: a decimal comma typed, read and shown", async () => {
  const { page, context, complaints } = await openPage("/?scene=minimal");
  await page.getByTestId("status").filter({ hasText: "en cours" }).waitFor();
  // A number the page cannot read: refused beside the control in the page's words, never sent.
  const before = (await creates()).length;
  await page.fill("#spacing-mm", "70,5 mm");
  await page.press("#spacing-mm", "Enter");
  const problem = page.getByTestId("problem-spacing");
  await problem.filter({ hasText: "un nombre est attendu" }).waitFor();
  const refused = await text(problem);
  expect(refused.includes("par exemple 89,5"), `the problem: ${refused}`);
  expect((await creates()).length === before, "a number the page cannot read was sent");
  // 70,5 is 70.5 mm: the lab is sent the number, and the readout shows it back in French.
  await page.fill("#spacing-mm", "70,5");
  await page.press("#spacing-mm", "Enter");
  await page.getByTestId("spacing").filter({ hasText: "70,5" }).waitFor();
  expect((await text(page.getByTestId("spacing"))) === `70,5${NBSP}mm`, "the spacing's readout");
  const made = (await creates()).at(-1);
  expect(
    made.scene === "minimal" && JSON.stringify(made.set) === '["rollers.spacing=70.5mm"]',
    `created ${JSON.stringify(made)}`,
  );
  expect((await page.locator("#spacing-mm").inputValue()) === "70,5", "the control");
  expect((await text(problem)) === "", "the problem stays after a good value");
  // The run goes on with the new spacing: its period, μk, time and regime in French.
  const periodText = new RegExp(`^T = \\d+,(\\d+) ± \\d+,(\\d+)${NBSP}s$`);
  await page.waitForFunction(
    (pattern) =>
      new RegExp(pattern).test(document.querySelector('[data-testid="period"]').textContent),
    periodText.source,
  );
  // Read together: the next estimate changes both.
  const [period, value] = await page
    .getByTestId("period")
    .evaluate((element) => [element.textContent.trim(), Number(element.dataset.value)]);
  const [, valueDigits, errorDigits] = periodText.exec(period);
  expect(valueDigits.length === errorDigits.length, `the period: ${period}`);
  // The period shown is the estimator's (data-value, in seconds), to its last digit.
  const shown = Number(/^T = (\d+,\d+)/.exec(period)[1].replace(",", "."));
  expect(
    Math.abs(shown - value) <= 0.5 * 10 ** -valueDigits.length + 1e-12,
    `the period ${period}, the estimator's ${value} s`,
  );
  const muK = await text(page.getByTestId("mu-k"));
  expect(/^μₖ = 0,\d+ ± 0,\d+$/.test(muK), `μk: ${muK}`);
  const time = await text(page.getByTestId("time"));
  expect(new RegExp(`^t = \\d+,\\d{3}${NBSP}s$`).test(time), `the time: ${time}`);
  await page.getByTestId("regime").filter({ hasText: "oscille" }).waitFor();
  const detail = await text(page.getByTestId("period-detail"));
  expect(detail.startsWith("± est l’écart-type de "), `the period's detail: ${detail}`);
  // Paused, the position plot's table holds French numbers.
  await page.getByTestId("play").click();
  await page.getByTestId("status").filter({ hasText: "en pause" }).waitFor();
  await page.locator("#table-x > summary").click();
  await page.locator('[data-testid="table-x"] tr').first().waitFor();
  const row = await page
    .locator('[data-testid="table-x"] tr')
    .first()
    .evaluate((tr) => Array.from(tr.cells, (td) => td.textContent));
  expect(/^\d+,\d{3}$/.test(row[0]) && /^-?\d+,\d{2}$/.test(row[1]), `a row: ${row}`);
  const caption = await text(page.locator("#table-x caption"));
  expect(caption.startsWith("La position x de la plaque (mm), t de "), `caption: ${caption}`);
  const others = complaints.filter((c) => !c.includes("400 (Bad Request)"));
  expect(others.length === 0, `console: ${others.join("\n")}`);
  await context.close();
});

await check("axe: the French lab's page and class's table", async () => {
  const { page, context, complaints } = await openPage("/?scene=minimal&set=world.duration%3D60s");
  await page.getByTestId("status").filter({ hasText: "en cours" }).waitFor();
  await page.waitForFunction(() =>
    /T = \d/.test(document.querySelector('[data-testid="period"]').textContent),
  );
  await expectNoViolations(page, "on the French lab's page, during a run");
  const teacher = await context.newPage();
  await teacher.goto(`${base}/class.html`);
  await teacher.getByTestId("class-table").locator("tbody tr").first().waitFor();
  await teacher.locator("#class-count").filter({ hasText: "session" }).waitFor();
  expect((await language(teacher)) === "fr", "the class's table is not in French");
  expect((await text(teacher.getByTestId("lab-link"))) === "Retour au labo", "the lab's link");
  await expectNoViolations(teacher, "on the French class's table");
  expect(complaints.length === 0, `console: ${complaints.join("\n")}`);
  await context.close();
});

await check(
  "the lab's refusals in French, and its English-only ones marked as English",
  async () => {
    // A link with a spacing the rollers cannot take: the lab's own message, said from the French
    // catalogue with the lab's numbers, beside the spacing's control.
    const { page, context, complaints } = await openPage(
      "/?scene=minimal&set=rollers.spacing%3D15mm",
    );
    const problem = page.getByTestId("problem-spacing");
    await problem.filter({ hasText: "chevauchent" }).waitFor();
    const said = await text(problem);
    expect(
      said ===
        "les rouleaux se chevauchent : l = 15 mm ne dépasse pas la somme de leurs rayons, 20 mm",
      `the spacing's problem: ${said}`,
    );
    expect((await problem.locator("[lang]").count()) === 0, "the French message is marked");
    // Every check of a scene is said so: the run-out's too, beside its control.
    await page.goto(`${base}/?scene=minimal&set=rollers.runout%3D-1mm`);
    const runout = page.getByTestId("problem-runout");
    await runout.filter({ hasText: "rayon du rouleau" }).waitFor();
    const refused = await text(runout);
    expect(
      refused === "doit être ≥ 0 et inférieur à la moitié du rayon du rouleau (5 mm), trouvé -1 mm",
      `the run-out's problem: ${refused}`,
    );
    // A message the catalogues do not hold (an unknown friction law's) is shown as the lab wrote
    // it, in a span marked lang="en".
    await page.goto(`${base}/?scene=minimal&set=friction.law%3Dwobbly`);
    const english = page.locator('.problem span[lang="en"]');
    await english.filter({ hasText: "expected coulomb or stribeck" }).waitFor();
    expect((await language(page)) === "fr", "the page is not French");
    await expectNoViolations(page, "with the lab's problems shown on the French page");
    // The browser says each refusal (400) on the console; nothing else may be said.
    const keeps = complaints.filter((c) => !c.includes("400 (Bad Request)"));
    expect(keeps.length === 0, `console: ${keeps.join("\n")}`);
    await context.close();
  },
);

await check("the live rig's port unplugged: the lab's message in French", async () => {
  const { page, context, complaints } = await openPage("/?scene=minimal");
  await page.getByTestId("status").filter({ hasText: "en cours" }).waitFor();
  const port = page.getByTestId("rig-port");
  await port.locator("option", { hasText: FAKE_RIG_PORT }).waitFor({ state: "attached" });
  await page.getByTestId("rig-connect").click();
  const state = page.getByTestId("rig-state");
  await state.filter({ hasText: "réception depuis" }).waitFor();
  await fetch(`${base}/__mock/rig-unplug`);
  await state.filter({ hasText: "a disparu" }).waitFor();
  const said = await text(state);
  expect(
    /^débranché.*\. \/dev\/ttyFAKE0 a disparu à \d\d:\d\d:\d\d \(carte débranchée \?\) : les \d+ lignes reçues sont gardées/.test(
      said,
    ),
    `the port's state: ${said}`,
  );
  expect((await state.locator('[lang="en"]').count()) === 0, "the message is marked English");
  expect(complaints.length === 0, `console: ${complaints.join("\n")}`);
  await context.close();
});

await check("the lab asking the page to slow down, in French", async () => {
  const { page, context, complaints } = await openPage("/?scene=minimal");
  await page.getByTestId("status").filter({ hasText: "en cours" }).waitFor();
  await fetch(`${base}/__mock/refuse?path=/api/sessions&count=1`);
  await page.fill("#spacing-mm", "75");
  await page.press("#spacing-mm", "Enter");
  const problem = page.locator("#page-problem");
  await problem.filter({ hasText: "trop de requêtes" }).waitFor();
  const said = await text(problem);
  expect(
    said === "trop de requêtes de 127.0.0.1 : au plus 20 par seconde ; attendez 1 s",
    `the page's problem: ${said}`,
  );
  const keeps = complaints.filter((c) => !c.includes("429 (Too Many Requests)"));
  expect(keeps.length === 0, `console: ${keeps.join("\n")}`);
  await context.close();
});

await check("a French phone: the view, T, μk and the plot in the first screen", async () => {
  const context = await browser.newContext({
    viewport: { width: 390, height: 844 },
    isMobile: true,
    hasTouch: true,
    deviceScaleFactor: 2,
    locale: "fr-FR",
  });
  context.setDefaultTimeout(WAIT_MS);
  const page = await context.newPage();
  await page.goto(`${base}/?scene=minimal&set=world.duration%3D60s`);
  await page.waitForFunction(() =>
    /T = \d/.test(document.querySelector('[data-testid="period"]').textContent),
  );
  await page.evaluate(() => window.scrollTo(0, 0));
  const screen = await page.evaluate(() => {
    const box = (selector) => {
      const r = document.querySelector(selector).getBoundingClientRect();
      return { top: r.top, bottom: r.bottom, left: r.left, right: r.right };
    };
    return {
      scrollWidth: document.documentElement.scrollWidth,
      width: innerWidth,
      height: innerHeight,
      canvas: box("#view canvas"),
      period: box('[data-testid="period"]'),
      muK: box('[data-testid="mu-k"]'),
      plot: box("#plot-x"),
      language: box('[data-testid="language"]'),
    };
  });
  const { width, height, canvas, period, muK, plot, language } = screen;
  const boxes = JSON.stringify(screen);
  expect(screen.scrollWidth <= width, `it scrolls sideways: ${boxes}`);
  const seen = (box) => Math.min(box.bottom, height) - Math.max(box.top, 0);
  const whole = (box) =>
    box.top >= 0 && box.bottom <= height && box.left >= 0 && box.right <= width;
  expect(seen(canvas) >= 100, `the 3D view is not in sight: ${boxes}`);
  expect(whole(period) && whole(muK), `T or μk is not wholly in the first screen: ${boxes}`);
  expect(whole(language), `the switcher is not wholly in the first screen: ${boxes}`);
  expect(seen(plot) >= 120, `less than 120 px of the position plot in sight: ${boxes}`);
  await context.close();
});

await check("?lang=fr goes with the set-up's link and the links between the pages", async () => {
  const { page, context, complaints } = await openPage("/?scene=minimal&lang=fr", "en-US");
  await page.getByTestId("status").filter({ hasText: "en cours" }).waitFor();
  expect((await language(page)) === "fr", `<html lang="${await language(page)}">`);
  const link = new URL(await page.getByTestId("setup-link").inputValue());
  expect(link.searchParams.get("lang") === "fr", `the set-up's link: ${link}`);
  expect(link.searchParams.get("scene") === "minimal", `the set-up's link: ${link}`);
  const classLink = await page.getByTestId("class-link").getAttribute("href");
  expect(classLink === "/class.html?lang=fr", `the class's table's link: ${classLink}`);
  // The link opens the set-up in French in an English browser.
  const other = await context.newPage();
  await other.goto(link.toString());
  await other.getByTestId("status").filter({ hasText: "en cours" }).waitFor();
  expect((await language(other)) === "fr", "the link's page is not in French");
  await other.goto(`${base}${classLink}`);
  await other.locator("#class-count").filter({ hasText: "session" }).waitFor();
  const back = await other.getByTestId("lab-link").getAttribute("href");
  expect(back === "/?lang=fr", `the lab's link: ${back}`);
  expect(complaints.length === 0, `console: ${complaints.join("\n")}`);
  await context.close();
});

await browser.close();
await stop();
finish();
