// What the browser scripts share: Debian's Chromium launched headless on one of the
// demo's two builds, the app opened in a page and its published state, the shipped
// scenes, waits, and the pixel measures they judge screenshots by.
import { readdirSync, readFileSync } from 'node:fs';
import { chromium } from 'playwright-core';
import { PNG } from 'pngjs';

/** The build under test (`LINKAGE_BUILD`, default webgl2): which of web/load.js's two
 * builds the browser is launched to load. */
export const build = process.env.LINKAGE_BUILD ?? 'webgl2';

/** Debian's Chromium, headless, on SwiftShader: without a WebGPU adapter (the page
 * loads the WebGL2 build), or with SwiftShader's Vulkan as WebGPU adapter (the
 * WebGPU-only build; without `--use-vulkan=swiftshader` its screenshots come out
 * blank). */
export function launchChromium() {
  const gpu = build === 'webgpu'
    ? ['--enable-unsafe-webgpu', '--enable-features=Vulkan', '--use-webgpu-adapter=swiftshader', '--use-vulkan=swiftshader']
    : ['--disable-gpu'];
  return chromium.launch({
    executablePath: '/usr/bin/chromium',
    headless: true,
    args: ['--no-sandbox', '--disable-quic', '--no-first-run',
      '--disable-background-networking', '--disable-component-update', '--disable-sync',
      '--use-angle=swiftshader', '--enable-unsafe-swiftshader', ...gpu],
  });
}

/** Why the page runs another build than the one under test, or null. */
export async function wrongBuild(page) {
  const loaded = await page.evaluate(() => window.linkageLabBuild);
  return loaded === build ? null : `the page loaded the ${loaded} build, not ${build}`;
}

/** A PNG screenshot as RGBA pixels. */
export function decode(buf) { return PNG.sync.read(buf); }

/** Pixels that differ between two shots of the same size. */
export function differing(a, b) {
  let n = 0;
  for (let i = 0; i < a.data.length; i += 4) {
    const d = Math.abs(a.data[i] - b.data[i]) + Math.abs(a.data[i + 1] - b.data[i + 1]) + Math.abs(a.data[i + 2] - b.data[i + 2]);
    if (d > 24) n++;
  }
  return n;
}

/** The fraction of pixels that differ from the page background (#1b1b1b). */
export function nonBackground(img) {
  let n = 0;
  for (let i = 0; i < img.data.length; i += 4) {
    if (Math.abs(img.data[i] - 0x1b) + Math.abs(img.data[i + 1] - 0x1b) + Math.abs(img.data[i + 2] - 0x1b) > 24) n++;
  }
  return n / (img.width * img.height);
}

/** Strongly coloured pixels (channels spread by more than 80) inside `rect`
 * ([x0, y0, x1, y1] in CSS pixels) of a screenshot taken at device scale 1. */
export function colouredIn(img, rect) {
  let n = 0;
  const [x0, y0, x1, y1] = rect.map(Math.round);
  for (let y = Math.max(0, y0); y < Math.min(img.height, y1); y++) {
    for (let x = Math.max(0, x0); x < Math.min(img.width, x1); x++) {
      const i = 4 * (y * img.width + x);
      const c = [img.data[i], img.data[i + 1], img.data[i + 2]];
      if (Math.max(...c) - Math.min(...c) > 80) n++;
    }
  }
  return n;
}

/** How long a wait may last before the test calls it a hang. Every wait is for a
 * condition (a frame drawn, a control placed, a file opened), never for a time: a
 * healthy page meets it in a frame or two at any speed, and this only ends a test
 * whose page has stopped. */
export const HANG_MS = 120000;

/** Waits until `condition()` (sync or async) holds, looking every 100 ms, for up to
 * [`HANG_MS`]; returns whether it held. `poke`, if given, runs between looks (an
 * idle egui app draws a frame only when something happens). */
export async function until(condition, poke) {
  const started = Date.now();
  while (!(await condition())) {
    if (Date.now() - started > HANG_MS) return false;
    if (poke) await poke();
    await new Promise((r) => setTimeout(r, 100));
  }
  return true;
}

/** Waits until the app has drawn no frame over `quietMs` (its frame count unchanged
 * over the looks that long), or for up to [`HANG_MS`]; returns whether it went quiet.
 * Before a CPU figure is measured in the page: SwiftShader draws the last frames on
 * the same two cores as the page's WebAssembly (the WebGPU build a frame in 0.75 s),
 * and a figure taken while it draws counts its work as the page's. */
export async function quiet(page, quietMs = 1500) {
  let last = -1;
  let since = Date.now();
  return until(async () => {
    const frame = (await appState(page)).frame;
    if (frame !== last) {
      last = frame;
      since = Date.now();
    }
    return Date.now() - since >= quietMs;
  });
}

/** Every scene file in assets/scenes (read from the directory, not listed anywhere),
 * sorted: its file name, key, text and the name the app shows. */
export function shippedScenes() {
  const dir = new URL('../../assets/scenes/', import.meta.url);
  return readdirSync(dir).filter((f) => f.endsWith('.ron')).sort().map((file) => {
    const text = readFileSync(new URL(file, dir), 'utf8');
    // RON string escapes (\' in "paper\'s") are not part of the name shown.
    const name = /\bname:\s*"((?:[^"\\]|\\.)*)"/.exec(text)?.[1]?.replace(/\\(.)/g, '$1');
    return { file, key: file.replace(/\.ron$/, ''), text, name };
  });
}

/** Loads the app at `url` in `page` with its console watched, and waits for its
 * first frame. Returns the list of what went wrong, which keeps growing while the
 * page lives: console errors, page errors, no first frame, the wrong build. */
export async function openApp(page, url) {
  const errors = [];
  let drawn = false;
  page.on('console', (m) => {
    if (m.type() === 'error') errors.push(m.text());
    if (m.text().includes('first frame at')) drawn = true;
  });
  page.on('pageerror', (e) => errors.push(`pageerror: ${e.message}`));
  await page.goto(url, { waitUntil: 'load' });
  await until(() => drawn || errors.length > 0);
  if (!drawn) errors.push(`no first frame at ${url}`);
  const wrong = await wrongBuild(page);
  if (wrong) errors.push(wrong);
  return errors;
}

/** The heading of the table of edit CPU measured in the page (the app's
 * `linkage_lab_edit_cpu`: the median of 15 length edits; a figure, not asserted: the
 * goal is 4 ms). */
export const EDIT_CPU_HEADING = `edit CPU in the page, ${build} build, median of 15 length edits, ms: scene | valid | refused, too long | refused, too short`;

/** One scene's row of that table. */
export function editCpuRow(key, cpu) {
  const ms = (v) => (v == null ? '-' : v.toFixed(2));
  return `${key} | ${ms(cpu?.valid_ms)} | ${ms(cpu?.refused_long_ms)} | ${ms(cpu?.refused_short_ms)}`;
}

/** What the app publishes for tests (src/web.rs): its frame, controls, scene, ... */
export async function appState(page) {
  return JSON.parse(await page.evaluate(() => window.wasmBindings.linkage_lab_controls()));
}

/** The control of `kind` (and `label`, if given) once two different frames show it
 * in the same place: a frame's layout can move it (a status line that grows as an
 * edit lands), and at SwiftShader's few frames a second a click aimed by one frame
 * lands in the next. `poke` makes an idle app draw (a pointer move). Undefined if it
 * is not shown. */
export async function settledControl(page, kind, label, poke) {
  let seen, settled;
  await until(async () => {
    const st = await appState(page);
    const c = st.controls?.entries?.find((e) => e.kind === kind && (label === undefined || e.label === label));
    if (c?.visible) {
      if (seen && st.frame > seen.frame && seen.c.rect.every((v, k) => Math.abs(v - c.rect[k]) < 0.5)) settled = c;
      if (!seen || st.frame > seen.frame) seen = { c, frame: st.frame };
    } else seen = undefined;
    return settled !== undefined;
  }, poke);
  return settled;
}
