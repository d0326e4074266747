// Real-browser test of the web demo: Debian's Chromium, headless, driven by
// playwright-core (no browser download). Checks: no console errors, a canvas that is
// not blank, that dragging the crank slider changes the picture, that Save and Export
// download the scene and the sweep CSV, that Export diagram downloads the sheet that
// `linkage diagram` writes for the same scene and crank angle (the CLI named by
// LINKAGE_CLI, built by scripts/browser_test.sh) and PNG… a 150 dpi PNG of it, and
// that Open uploads a scene file (the saved one, then another scene, which changes
// the picture), and that the uploaded scene survives a reload and opens from the
// page's address in a new page (a share link); and that a four-bar built in the page
// (New… → four-bar template, a joint dragged) survives a reload and opens from its
// link; and that a small path search in the synthesis window runs to designs while
// frames keep coming. Measures time to first frame (the app logs it) and frames per second while
// the mechanism plays.
// Usage: node browser_test.mjs http://127.0.0.1:PORT/
import { execFileSync } from 'node:child_process';
import { readFileSync } from 'node:fs';
import { build, colouredIn, decode, differing, launchChromium, nonBackground, wrongBuild } from './common.mjs';

const url = process.argv[2] ?? 'http://127.0.0.1:8917/';
const fail = (msg) => { console.error(`FAIL: ${msg}`); process.exitCode = 1; };

const browser = await launchChromium();
const page = await browser.newPage({ viewport: { width: 1500, height: 950 }, deviceScaleFactor: 1 });
const errors = [];
const logged = [];
let firstFrameMs = null;
page.on('console', (m) => {
  const text = m.text();
  logged.push(text);
  if (m.type() === 'error') errors.push(text);
  const hit = /first frame at ([0-9.]+) ms/.exec(text);
  // The first page load only: the reload later logs its own.
  if (hit && firstFrameMs === null) firstFrameMs = Number(hit[1]);
});
page.on('pageerror', (e) => errors.push(`pageerror: ${e.message}`));
// Listening from the start makes Playwright intercept file choosers before any click:
// a listener added together with the click can come too late for a quick app.
page.on('filechooser', () => {});

const t0 = Date.now();
await page.goto(url, { waitUntil: 'load' });
while (firstFrameMs === null && Date.now() - t0 < 60000) await page.waitForTimeout(100);
if (firstFrameMs === null) fail('the app never drew a first frame');
const wrong = await wrongBuild(page);
if (wrong) fail(wrong);
await page.waitForTimeout(1500);

const canvas = page.locator('#linkage_canvas');
const shotDir = process.env.SCREENSHOT_DIR;
const shot = async (name) => {
  const buf = await canvas.screenshot();
  if (shotDir) (await import('node:fs')).writeFileSync(`${shotDir}/${name}.png`, buf);
  return decode(buf);
};
const before = await shot('loaded');
const coverage = nonBackground(before);
if (coverage < 0.2) fail(`canvas looks blank: ${(coverage * 100).toFixed(1)} % drawn`);
// The mechanism itself, drawn by the build's GPU renderer (wgpu or glow), not egui:
// coloured links, vectors and traces inside the view, where egui draws grey text only.
const loadedState = JSON.parse(await page.evaluate(() => window.wasmBindings.linkage_lab_controls()));
if (!loadedState.renderer) fail(`the ${build} build's mechanism renderer did not start`);
const gpuPixels = colouredIn(before, loadedState.controls.view);
if (gpuPixels < 500) fail(`the mechanism view shows ${gpuPixels} coloured pixels: the GPU draw is missing`);

// Drag the crank-angle slider (found through the app's control map) in small steps.
const crank = JSON.parse(await page.evaluate(() => window.wasmBindings.linkage_lab_controls()))
  .controls.entries.find((e) => e.kind === 'Crank');
if (!crank) fail('no crank slider');
const y = 0.5 * (crank.rect[1] + crank.rect[3]), x0 = crank.rect[0] + 4, x1 = crank.rect[0] + 90;
await page.mouse.move(x0, y);
await page.waitForTimeout(50);
await page.mouse.down();
for (let x = x0; x <= x1; x += 5) {
  await page.mouse.move(x, y);
  await page.waitForTimeout(30);
}
await page.mouse.up();
await page.waitForTimeout(800);
const after = await shot('dragged');
const changed = differing(before, after);
if (changed < 2000) fail(`dragging the crank slider changed only ${changed} pixels`);

// Press Play, count the page's animation frames for 3 s, then wait, on a slow
// machine, until the picture has moved.
const playButton = JSON.parse(await page.evaluate(() => window.wasmBindings.linkage_lab_controls()))
  .controls.entries.find((e) => e.kind === 'Play');
const PLAY = [0.5 * (playButton.rect[0] + playButton.rect[2]), 0.5 * (playButton.rect[1] + playButton.rect[3])];
await page.mouse.click(...PLAY);
const fps = await page.evaluate(() => new Promise((resolve) => {
  let n = 0; const start = performance.now();
  const tick = () => { n++; if (performance.now() - start < 3000) requestAnimationFrame(tick); else resolve(n / ((performance.now() - start) / 1000)); };
  requestAnimationFrame(tick);
}));
let played = 0;
for (let i = 0; i < 20 && played < 2000; i++) {
  played = differing(after, await shot('played'));
  if (played < 2000) await page.waitForTimeout(500);
}
await page.mouse.click(...PLAY); // pause
if (played < 2000) fail(`playing changed only ${played} pixels`);

// The top bar's file buttons, from the control map.
const lastControls = JSON.parse(await page.evaluate(() => window.wasmBindings.linkage_lab_controls()));
const fileButton = (label) => {
  const b = lastControls.controls.entries.find((e) => e.kind === 'FileButton' && e.label === label);
  if (!b) { fail(`no ${label} button`); return [0, 0]; }
  return [0.5 * (b.rect[0] + b.rect[2]), 0.5 * (b.rect[1] + b.rect[3])];
};
const OPEN = fileButton('Open scene…'), SAVE = fileButton('Save scene…'), EXPORT = fileButton('Export CSV…');
const download = async ([x, y]) => {
  const [dl] = await Promise.all([page.waitForEvent('download', { timeout: 20000 }), page.mouse.click(x, y)]);
  return { name: dl.suggestedFilename(), text: readFileSync(await dl.path(), 'utf8') };
};
const waitForLog = async (needle) => {
  for (let i = 0; i < 100; i++) {
    if (logged.some((t) => t.includes(needle))) return true;
    await page.waitForTimeout(100);
  }
  return false;
};
const upload = async (name, text) => {
  // The app opens the file picker in the frame after the click; the browser allows
  // that only within its user-activation window (about 5 s). On a loaded machine at a
  // frame or two a second the frame can come later: then a user clicks again.
  let chooser;
  for (let attempt = 0; attempt < 3 && !chooser; attempt++) {
    [chooser] = await Promise.all([
      page.waitForEvent('filechooser', { timeout: 20000 }).catch(() => undefined),
      page.mouse.click(...OPEN),
    ]);
  }
  if (!chooser) { fail(`Open never showed the file picker (three clicks)`); return; }
  await chooser.setFiles({ name, mimeType: 'text/plain', buffer: Buffer.from(text) });
  if (!(await waitForLog(`opened ${name}`))) fail(`uploading ${name} did not open it`);
};

const csv = await download(EXPORT);
const csvRows = csv.text.trim().split('\n').length;
if (csv.name !== 'die_cutter_sweep.csv') fail(`CSV download named ${csv.name}`);
if (!csv.text.startsWith('input_rad,') || csvRows < 100) fail(`CSV download: ${csvRows} rows, starts ${csv.text.slice(0, 40)}`);
// The diagram sheet: found through the app's control map, compared with the CLI's.
const controls = JSON.parse(await page.evaluate(() => window.wasmBindings.linkage_lab_controls()));
const exportDiagram = controls.controls.entries.find((e) => e.kind === 'FileButton' && e.label === 'Export diagram…');
let sheetBytes = 0;
if (!exportDiagram) fail('no Export diagram button');
else {
  const sheet = await download([0.5 * (exportDiagram.rect[0] + exportDiagram.rect[2]), 0.5 * (exportDiagram.rect[1] + exportDiagram.rect[3])]);
  sheetBytes = sheet.text.length;
  const deg = controls.input_deg;
  if (sheet.name !== `die_cutter_at_${deg.toFixed(0)}deg.svg`) fail(`diagram download named ${sheet.name} at ${deg}°`);
  const cli = process.env.LINKAGE_CLI ?? 'target/debug/linkage';
  const scene = new URL('../../assets/scenes/die_cutter.ron', import.meta.url).pathname;
  let expected = '';
  try {
    expected = execFileSync(cli, ['diagram', scene, '--input-deg', String(deg)], { encoding: 'utf8' });
  } catch (e) {
    fail(`linkage diagram (${cli}) did not run: ${e.message}`);
  }
  if (expected && sheet.text !== expected) {
    const a = sheet.text.split('\n'), b = expected.split('\n');
    const i = a.findIndex((line, k) => line !== b[k]);
    fail(`the downloaded sheet differs from linkage diagram at line ${i + 1}:\n  ${a[i]}\n  ${b[i]}`);
  }
}
// The same sheet as PNG, rasterised by the browser: A4 at 150 dpi is 1240 px wide.
const pngButton = controls.controls.entries.find((e) => e.kind === 'FileButton' && e.label === 'PNG…');
let pngWidth = 0;
if (!pngButton) fail('no PNG export button');
else {
  const [dl] = await Promise.all([
    page.waitForEvent('download', { timeout: 20000 }),
    page.mouse.click(0.5 * (pngButton.rect[0] + pngButton.rect[2]), 0.5 * (pngButton.rect[1] + pngButton.rect[3])),
  ]);
  const bytes = readFileSync(await dl.path());
  if (!dl.suggestedFilename().endsWith('deg.png')) fail(`PNG download named ${dl.suggestedFilename()}`);
  if (bytes.subarray(1, 4).toString() !== 'PNG') fail('the PNG download is no PNG');
  else pngWidth = bytes.readUInt32BE(16);
  if (Math.abs(pngWidth - 1240) > 1) fail(`the PNG sheet is ${pngWidth} px wide, not 1240`);
}
const saved = await download(SAVE);
if (saved.name !== 'die_cutter.ron') fail(`scene download named ${saved.name}`);
if (!/\bname:/.test(saved.text)) fail(`scene download is no scene: ${saved.text.slice(0, 80)}`);

// The saved scene opens again; then another shipped scene changes the picture.
await upload('saved_cutter.ron', saved.text);
await page.waitForTimeout(800);
const cutter = await shot('reopened');
const sliderCrank = readFileSync(new URL('../../assets/scenes/slider_crank.ron', import.meta.url), 'utf8');
await upload('slider_crank.ron', sliderCrank);
let reopened = 0;
for (let i = 0; i < 20 && reopened < 2000; i++) {
  await page.waitForTimeout(400);
  reopened = differing(cutter, await shot('uploaded'));
}
if (reopened < 2000) fail(`opening slider_crank.ron changed only ${reopened} pixels`);

// A scene opened from a file travels whole in the URL (doc=1.…): a reload keeps it,
// and the address opened in a new page (a shared link) shows the same mechanism.
const appState = async (p) => JSON.parse(await p.evaluate(() => window.wasmBindings.linkage_lab_controls()));
const uploadedName = (await appState(page)).scene_name;
let hash = '';
for (let i = 0; i < 50 && !hash.includes('doc=1.'); i++) {
  await page.waitForTimeout(100);
  hash = await page.evaluate(() => location.hash);
}
if (!hash.includes('doc=1.')) fail(`the URL does not carry the opened file: ${hash.slice(0, 60)}`);
const afterReload = async (p) => {
  for (let i = 0; i < 600; i++) {
    // The bindings exist before the wasm is ready: a call then throws.
    const ready = await p.evaluate(() => {
      try { return Boolean(window.wasmBindings?.linkage_lab_controls?.()); } catch { return false; }
    });
    if (ready) return appState(p);
    await p.waitForTimeout(100);
  }
  return {};
};
await page.reload({ waitUntil: 'load' });
const reloaded = await afterReload(page);
if (reloaded.scene_name !== uploadedName) fail(`after a reload the app shows ${reloaded.scene_name}, not ${uploadedName}`);
const shared = await browser.newPage({ viewport: { width: 1500, height: 950 }, deviceScaleFactor: 1 });
shared.on('pageerror', (e) => errors.push(`pageerror (shared link): ${e.message}`));
await shared.goto(page.url(), { waitUntil: 'load' });
const there = await afterReload(shared);
if (there.scene_name !== uploadedName) fail(`the shared link opens ${there.scene_name}, not ${uploadedName}`);
await shared.close();

// A four-bar built in the page: New… → the four-bar template, "move points", C
// dragged to a new place; a reload keeps the edited mechanism, and its address opened
// in a new page shows the same one (every joint where it was, to 1e-9 m).
// A control where two different frames drew it in the same place: a frame's layout
// can move it (a status line that grows as the edit of the same frame lands), and at
// SwiftShader's 2 frames a second a click aimed by one frame lands in the next.
const entry = async (p, kind, label) => {
  let seen;
  for (let i = 0; i < 100; i++) {
    const st = await appState(p);
    const e = st.controls?.entries?.find((c) => c.kind === kind && (label === undefined || c.label === label));
    if (e?.visible) {
      if (seen && st.frame > seen.frame && seen.e.rect.every((v, k) => Math.abs(v - e.rect[k]) < 0.5)) return e;
      if (!seen || st.frame > seen.frame) seen = { e, frame: st.frame };
    } else seen = undefined;
    await p.mouse.move(20 + (i % 2), 10); // an idle app draws on a pointer move
    await p.waitForTimeout(100);
  }
  return undefined;
};
/** Drags with the mouse from `from` along `path` (screen points), a step per frame
 * or so; returns the CPU of each edit frame seen ([frame ms, edit ms], the app's own
 * performance.now() figures) — at SwiftShader's few frames a second nearly every one. */
const dragTimed = async (p, from, path) => {
  await p.mouse.move(...from);
  await p.mouse.down();
  let frames = (await appState(p)).edit_timing.frames;
  const seen = [];
  for (const at of path) {
    await p.mouse.move(...at);
    await p.waitForTimeout(60);
    const t = (await appState(p)).edit_timing;
    if (t.frames > frames) seen.push([Number(t.last_ms.toFixed(2)), Number(t.last_edit_ms.toFixed(2))]);
    frames = t.frames;
  }
  // The last place lands before the release: SwiftShader may take 500 ms a frame.
  await p.waitForTimeout(600);
  await p.mouse.up();
  return seen;
};
const dragFrames = {};
const middle = (e) => [0.5 * (e.rect[0] + e.rect[2]), 0.5 * (e.rect[1] + e.rect[3])];
const samePlaces = (a, b) => a.length === b.length && a.every((j, k) => j.name === b[k].name
  && Math.abs(j.world[0] - b[k].world[0]) < 1e-9 && Math.abs(j.world[1] - b[k].world[1]) < 1e-9);
const places = (st) => JSON.stringify((st.joints ?? []).map((j) => [j.name, ...j.world.map((v) => Number(v.toFixed(6)))]));
/** A mechanism built in the page (`built`: the app's state then) survives a reload
 * of its address (once that carries `wantUrl`), and the address opened in a new page
 * shows the same one: every joint where it was, to 1e-9 m. */
const keptAndShared = async (built, what, wantUrl) => {
  let url = '';
  for (let i = 0; i < 50 && !url.includes(wantUrl); i++) {
    await page.waitForTimeout(100);
    url = page.url();
  }
  await page.reload({ waitUntil: 'load' });
  const kept = await afterReload(page);
  if (kept.scene_name !== built.scene_name || !samePlaces(kept.joints ?? [], built.joints)) {
    fail(`after a reload ${what} is not the same: ${kept.scene_name} ${places(kept)}, built ${built.scene_name} ${places(built)} (${url.slice(0, 80)})`);
  }
  const other = await browser.newPage({ viewport: { width: 1500, height: 950 }, deviceScaleFactor: 1 });
  other.on('pageerror', (e) => errors.push(`pageerror (${what}'s link): ${e.message}`));
  await other.goto(url, { waitUntil: 'load' });
  const seen = await afterReload(other);
  if (!samePlaces(seen.joints ?? [], built.joints)) fail(`${what}'s link opens another mechanism: ${places(seen)}, built ${places(built)}`);
  await other.close();
};
let built = {};
const newMenu = await entry(page, 'FileButton', 'New…');
if (!newMenu) fail('no New… menu');
else {
  await page.mouse.click(...middle(newMenu));
  const item = await entry(page, 'TemplateItem', 'Four-bar (template)');
  if (!item) fail('no four-bar template in New…');
  else await page.mouse.click(...middle(item));
  for (let i = 0; i < 50 && (await appState(page)).scene_name !== 'Four-bar (template)'; i++) await page.waitForTimeout(100);
  if ((await appState(page)).scene_name !== 'Four-bar (template)') fail(`New… → four-bar opened ${(await appState(page)).scene_name}`);
  const toggle = await entry(page, 'Layer', 'move points');
  if (toggle) await page.mouse.click(...middle(toggle));
  await page.waitForTimeout(300);
  const before = await appState(page);
  const c = before.joints.find((j) => j.name === 'C');
  const [cx, cy] = c.screen;
  const path = Array.from({ length: 8 }, (_, i) => [cx + 5 * (i + 1), cy - 3 * (i + 1)]);
  dragFrames.viewer_point = await dragTimed(page, [cx, cy], path);
  await page.waitForTimeout(500);
  built = await appState(page);
  const moved = built.joints.find((j) => j.name === 'C');
  if (Math.hypot(moved.world[0] - c.world[0], moved.world[1] - c.world[1]) < 1e-3) fail(`dragging C did not move it: ${built.message ?? ''}`);
  if (!built.dirty) fail('the built four-bar is not marked as edited');
  await keptAndShared(built, 'the built four-bar', 'file=four_bar.ron&doc=1.');
}

// A four-bar drawn from nothing: New… → Empty, then clicks with the drawing tools at
// world places (the app publishes its camera), Driver, Done; a reload keeps it, and
// its address opened in a new page shows the same mechanism.
let drawn = {};
const toScreen = (st, [x, y]) => {
  const [x0, y0, x1, y1] = st.controls.view;
  const [cx, cy, ppm] = st.camera;
  return [0.5 * (x0 + x1) + (x * 1e-3 - cx) * ppm, 0.5 * (y0 + y1) - (y * 1e-3 - cy) * ppm];
};
const clickMm = async (xy) => {
  await page.mouse.click(...toScreen(await appState(page), xy));
  await page.waitForTimeout(300);
};
const useTool = async (label) => {
  const t = await entry(page, 'DrawTool', label);
  if (!t) { fail(`no drawing tool ${label}`); return; }
  await page.mouse.click(...middle(t));
  await page.waitForTimeout(300);
};
const menu = await entry(page, 'FileButton', 'New…');
if (menu) {
  await page.mouse.click(...middle(menu));
  const empty = await entry(page, 'TemplateItem', 'Empty: draw your own');
  if (!empty) fail('no empty drawing in New…');
  else await page.mouse.click(...middle(empty));
  for (let i = 0; i < 30 && !(await appState(page)).drawing; i++) await page.waitForTimeout(100);
  if (!(await appState(page)).drawing) {
    // The four-bar above has unsaved edits: the app asks before drawing over them.
    const dropping = await entry(page, 'FileButton', 'Drop the edits and open');
    if (dropping) await page.mouse.click(...middle(dropping));
  }
  for (let i = 0; i < 50 && !(await appState(page)).drawing; i++) await page.waitForTimeout(100);
  if (!(await appState(page)).drawing) fail(`New… → Empty did not start a drawing: ${(await appState(page)).message ?? ''}`);
  else {
    await useTool('Pivot');
    for (const xy of [[0, 0], [300, 0]]) await clickMm(xy);
    await useTool('Link');
    for (const xy of [[0, 0], [0, 50], [0, 50], [200, 200], [200, 200], [300, 0]]) await clickMm(xy);
    await useTool('Driver');
    await clickMm([0, 25]);
    for (let i = 0; i < 30 && !(await appState(page)).drawing?.complete; i++) await page.waitForTimeout(100);
    const st = await appState(page);
    if (!st.drawing?.complete) fail(`the drawn four-bar is not a mechanism: ${JSON.stringify(st.drawing)}`);
    // The Move tool: D dragged out along x and back to where it was drawn (the grid
    // is 10 mm), an edit per frame that remakes and reopens the mechanism.
    await useTool('Move');
    const d = toScreen(await appState(page), [200, 200]);
    const out = Array.from({ length: 6 }, (_, i) => toScreen(st, [200 + 10 * (i + 1), 200]));
    dragFrames.drawing_point = await dragTimed(page, d, [...out, ...out.reverse().slice(1), d]);
    await page.waitForTimeout(300);
    await useTool('Done');
    for (let i = 0; i < 30 && (await appState(page)).drawing; i++) await page.waitForTimeout(100);
    drawn = await appState(page);
    const want = [['A', 0, 0], ['B', 0.3, 0], ['C', 0, 0.05], ['D', 0.2, 0.2]];
    const at = (st, name) => st.joints?.find((j) => j.name === name)?.world ?? [NaN, NaN];
    const off = want.map(([n, x, y]) => Math.hypot(at(drawn, n)[0] - x, at(drawn, n)[1] - y));
    if (drawn.drawing || off.some((d) => !(d < 1e-9))) fail(`the drawn four-bar is not as drawn: ${JSON.stringify(drawn.joints)}`);
    await keptAndShared(drawn, 'the drawn four-bar', 'doc=1.');
  }
}

// An unfinished drawing (two pivots, no links) survives a reload: the page keeps it
// in local storage with its address.
let unfinishedPoints = 0;
const again = await entry(page, 'FileButton', 'New…');
if (again) {
  await page.mouse.click(...middle(again));
  const empty = await entry(page, 'TemplateItem', 'Empty: draw your own');
  if (empty) await page.mouse.click(...middle(empty));
  for (let i = 0; i < 30 && !(await appState(page)).drawing; i++) await page.waitForTimeout(100);
  if (!(await appState(page)).drawing) {
    const dropping = await entry(page, 'FileButton', 'Drop the edits and open');
    if (dropping) await page.mouse.click(...middle(dropping));
    for (let i = 0; i < 30 && !(await appState(page)).drawing; i++) await page.waitForTimeout(100);
  }
  await useTool('Pivot');
  for (const xy of [[0, 0], [300, 0]]) await clickMm(xy);
  const before = (await appState(page)).drawing?.points;
  if (before !== 2) fail(`two pivots placed, the drawing has ${before} points`);
  await page.waitForTimeout(500);
  await page.reload({ waitUntil: 'load' });
  unfinishedPoints = (await afterReload(page)).drawing?.points ?? 0;
  if (unfinishedPoints !== 2) fail(`after a reload the unfinished drawing has ${unfinishedPoints} points, not 2`);
}

// A small path search in the page: Synthesis… → path, the targets cleared and four
// clicked on its canvas, Search. The browser has no threads here: the search runs a
// slice of a few milliseconds per frame, so frames keep coming while it runs (the
// page's own requestAnimationFrame gaps are measured), and it ends with designs.
let pathSearch = {};
const synth = await entry(page, 'FileButton', 'Synthesis…');
const pathTab = synth && (await page.mouse.click(...middle(synth)), await entry(page, 'SynthesisTab', 'path'));
if (!pathTab) fail('no Synthesis… button or no path tab');
else {
  await page.mouse.click(...middle(pathTab));
  const clear = await entry(page, 'FileButton', 'Clear targets');
  if (clear) await page.mouse.click(...middle(clear));
  await page.waitForTimeout(300);
  const board = await entry(page, 'SynthesisCanvas', 'path targets');
  if (!board) fail('no path canvas');
  else {
    const [x0, y0, x1, y1] = board.rect;
    for (const [fx, fy] of [[0.2, 0.7], [0.4, 0.25], [0.65, 0.2], [0.85, 0.6]]) {
      await page.mouse.click(x0 + fx * (x1 - x0), y0 + fy * (y1 - y0));
      await page.waitForTimeout(400);
    }
    const search = await entry(page, 'FileButton', 'Search');
    await page.evaluate(() => {
      window.rafTimes = [];
      const tick = (t) => { window.rafTimes.push(t); if (!window.rafStop) requestAnimationFrame(tick); };
      requestAnimationFrame(tick);
    });
    const started = Date.now();
    if (search) await page.mouse.click(...middle(search));
    let st = await appState(page);
    for (let i = 0; i < 1800 && !(st.path_search && !st.path_search.running); i++) {
      await page.waitForTimeout(100);
      st = await appState(page);
    }
    const times = await page.evaluate(() => { window.rafStop = true; return window.rafTimes; });
    const gaps = times.slice(1).map((t, k) => t - times[k]);
    pathSearch = { ...st.path_search, seconds: (Date.now() - started) / 1000, frames: times.length,
      max_frame_gap_ms: Number(Math.max(...gaps).toFixed(1)) };
    if (!st.path_search) fail('Search started no path search');
    else if (st.path_search.running) fail(`the path search did not end in 180 s: ${JSON.stringify(pathSearch)}`);
    else if (st.path_search.targets !== 4 || st.path_search.solutions < 1) fail(`the path search: ${JSON.stringify(pathSearch)}`);
    if (!(pathSearch.frames >= 10 && pathSearch.max_frame_gap_ms < 3000)) fail(`the page froze during the path search: ${JSON.stringify(pathSearch)}`);
  }
}

if (errors.length) fail(`console errors:\n  ${errors.join('\n  ')}`);
console.log(JSON.stringify({
  url, build, first_frame_ms: firstFrameMs, canvas_drawn_fraction: Number(coverage.toFixed(3)),
  pixels_changed_by_slider_drag: changed, pixels_changed_by_play: played,
  fps_playing: Number(fps.toFixed(1)), csv_download_rows: csvRows,
  scene_download_bytes: saved.text.length, sheet_download_bytes: sheetBytes, sheet_png_width: pngWidth,
  pixels_changed_by_upload: reopened, link_chars: page.url().length,
  editor_drag_frames_ms: dragFrames,
  built_four_bar_joints: built.joints?.length ?? 0,
  drawn_four_bar_joints: drawn.joints?.length ?? 0,
  unfinished_drawing_points_after_reload: unfinishedPoints,
  path_search: pathSearch,
  console_errors: errors.length,
}));
await browser.close();
