// Real-browser test of the web demo: Debian's Chromium, headless, driven by
// playwright-core (no browser download). Checks: no console errors, a canvas that is
// not blank, that dragging the crank slider changes the picture, that Save and Export
// download the scene and the sweep CSV, that Export diagram downloads the sheet's first
// A4 page as `linkage diagram --svg` writes it for the same scene and crank angle (the CLI named by
// LINKAGE_CLI, built by scripts/browser_test.sh) and PNG… a 150 dpi PNG of it, and
// that Open uploads a scene file (the saved one, then another scene, which changes
// the picture), and that the uploaded scene survives a reload and opens from the
// page's address in a new page (a share link); and that a four-bar built in the page
// (New… → four-bar template, a joint dragged) survives a reload and opens from its
// link; and that a small path search in the synthesis window runs to designs, and a
// long one keeps frames coming (frames.mjs) and stops when asked. Measures time to first frame (the app logs it) and frames per second while
// the mechanism plays. With LINKAGE_BROWSER_CHECKS=drawn (the WebGPU build's pass) only
// what the renderer decides: the first frame, the canvas drawn, the drag and play, then
// every shipped scene opened by its link and drawn, with its edit's CPU measured.
// Usage: node browser_test.mjs http://127.0.0.1:PORT/
import { execFileSync } from 'node:child_process';
import { mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { EDIT_CPU_HEADING, appState, build, colouredIn, decode, differing, editCpuRow, launchChromium, nonBackground, quiet, settledControl, shippedScenes, until, wrongBuild } from './common.mjs';
import { framesKeptComing, framesSpanned, slicesKeptTheirBudget } from './frames.mjs';

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

await page.goto(url, { waitUntil: 'load' });
await until(() => firstFrameMs !== null || errors.length > 0);
if (firstFrameMs === null) fail('the app never drew a first frame');
const wrong = await wrongBuild(page);
if (wrong) fail(wrong);

const canvas = page.locator('#linkage_canvas');
const shotDir = process.env.SCREENSHOT_DIR;
const shot = async (name) => {
  const buf = await canvas.screenshot();
  if (shotDir) (await import('node:fs')).writeFileSync(`${shotDir}/${name}.png`, buf);
  return decode(buf);
};
// A control where two different frames drew it in the same place (common.mjs); an
// idle app draws on a pointer move.
let pokes = 0;
const entry = (p, kind, label) => settledControl(p, kind, label, () => p.mouse.move(20 + (pokes++ % 2), 10));
/** Waits until the app has drawn a frame after now (`poke`: how to make it draw). */
const nextFrame = async (p, poke) => {
  const frame = (await appState(p)).frame;
  await until(async () => (await appState(p)).frame > frame, poke);
};
// The mechanism itself, drawn by the build's GPU renderer (wgpu or glow), not egui:
// coloured links, vectors and traces inside the view, where egui draws grey text only.
// Waited for: the renderer may start a few frames after the first.
let before, coverage, loadedState, gpuPixels;
await until(async () => {
  before = await shot('loaded');
  coverage = nonBackground(before);
  loadedState = await appState(page);
  gpuPixels = colouredIn(before, loadedState.controls.view ?? [0, 0, 0, 0]);
  return coverage >= 0.2 && loadedState.renderer && gpuPixels >= 500;
}, () => page.mouse.move(21, 10));
if (coverage < 0.2) fail(`canvas looks blank: ${(coverage * 100).toFixed(1)} % drawn`);
if (!loadedState.renderer) fail(`the ${build} build's mechanism renderer did not start`);
if (gpuPixels < 500) fail(`the mechanism view shows ${gpuPixels} coloured pixels: the GPU draw is missing`);

// Drag the crank-angle slider (found through the app's control map) in small steps.
const crank = (await appState(page))
  .controls.entries.find((e) => e.kind === 'Crank');
if (!crank) fail('no crank slider');
const y = 0.5 * (crank.rect[1] + crank.rect[3]), x0 = crank.rect[0] + 4, x1 = crank.rect[0] + 90;
// Each step once the app has drawn the frame that took the one before: a fast
// machine may otherwise see the whole drag between two frames, as a click.
await page.mouse.move(x0, y);
await nextFrame(page);
await page.mouse.down();
await nextFrame(page);
for (let x = x0; x <= x1; x += 5) {
  await page.mouse.move(x, y);
  await nextFrame(page);
}
await page.mouse.up();
let after = await shot('dragged');
let changed = 0;
await until(async () => (after = await shot('dragged'), changed = differing(before, after)) >= 2000);
if (changed < 2000) fail(`dragging the crank slider changed only ${changed} pixels`);

// Press Play, count the page's animation frames for 3 s, then wait, on a slow
// machine, until the picture has moved.
const playButton = (await appState(page))
  .controls.entries.find((e) => e.kind === 'Play');
const PLAY = [0.5 * (playButton.rect[0] + playButton.rect[2]), 0.5 * (playButton.rect[1] + playButton.rect[3])];
await page.mouse.click(...PLAY);
const fps = await page.evaluate(() => new Promise((resolve) => {
  let n = 0; const start = performance.now();
  const tick = () => { n++; if (performance.now() - start < 3000) requestAnimationFrame(tick); else resolve(n / ((performance.now() - start) / 1000)); };
  requestAnimationFrame(tick);
}));
let played = 0;
await until(async () => (played = differing(after, await shot('played'))) >= 2000);
await page.mouse.click(...PLAY); // pause
if (played < 2000) fail(`playing changed only ${played} pixels`);

// The rest is the same code in both builds, and what it draws goes through the same
// instanced shapes as the mechanism above: files, links, the editor and the path
// search run in the WebGL2 build; the WebGPU build (LINKAGE_BROWSER_CHECKS=drawn) is
// checked for what its renderer decides, above: 39 s here, where the whole script
// took 143 s in CI's WebGPU pass (2026-11-27), at SwiftShader's Vulkan speed.
const checks = process.env.LINKAGE_BROWSER_CHECKS ?? 'all';
const pageActions = checks === 'all' ? await filesLinksEditorAndSearch() : { checks, scenes_drawn: await everySceneDrawn() };

/** Every shipped scene opened in this page by its link (a hashchange), each drawn by
 * the renderer (the page covered, the mechanism coloured in the view), and the CPU of
 * its length edit measured in the page once it is quiet: the WebGPU build's pass over
 * the scenes (every_scene.mjs opens each in a new page, every control moved, in the
 * WebGL2 build). */
async function everySceneDrawn() {
  const drawn = [];
  console.log(EDIT_CPU_HEADING);
  for (const scene of shippedScenes()) {
    await page.evaluate((key) => { location.hash = `#scene=${key}`; }, scene.key);
    const opened = await until(async () => (await page.evaluate(() => location.hash)).startsWith(`#scene=${scene.key}&`), () => page.mouse.move(21, 10));
    if (!opened) { fail(`${scene.key}: its link did not open it`); continue; }
    let img, st, px = 0;
    await until(async () => {
      st = await appState(page);
      img = await shot(`scene_${scene.key}`);
      px = colouredIn(img, st.controls.view ?? [0, 0, 0, 0]);
      return st.scene_name === scene.name && px >= 300 && nonBackground(img) >= 0.2;
    }, () => page.mouse.move(21, 10));
    if (st.scene_name !== scene.name) fail(`${scene.key}: the app shows ${st.scene_name}`);
    if (px < 300) fail(`${scene.key}: the view shows ${px} coloured pixels: no mechanism drawn`);
    if (!st.pose_finite) fail(`${scene.key}: non-finite pose`);
    // SwiftShader draws the last frames on the same two cores as the page's
    // WebAssembly: measured once the page is quiet (common.mjs).
    if (!(await quiet(page))) fail(`${scene.key}: the app kept drawing frames with nothing to do`);
    const cpu = JSON.parse(await page.evaluate((key) => window.wasmBindings.linkage_lab_edit_cpu(key), scene.key));
    if (!cpu) fail(`${scene.key}: no edit CPU measured`);
    console.log(editCpuRow(scene.key, cpu));
    drawn.push({ scene: scene.key, view_pixels: px, edit_cpu: cpu });
  }
  return drawn;
}

/** The page's doors and tools: Save, Export (CSV, diagram, PNG), Open (an upload),
 * a reload and a share link, a four-bar built and one drawn in the page, an unfinished
 * drawing kept, and the path searches. Returns what the summary reports. */
async function filesLinksEditorAndSearch() {
  // The top bar's file buttons, from the control map.
  const lastControls = await appState(page);
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
  const waitForLog = (needle) => until(() => logged.some((t) => t.includes(needle)));
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
  if (!csv.text.startsWith('input (deg),') || csvRows < 100) fail(`CSV download: ${csvRows} rows, starts ${csv.text.slice(0, 40)}`);
  // The diagram sheet: found through the app's control map, compared with the CLI's.
  const controls = await appState(page);
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
    // The sheet is A4 pages, a file each: the first download is the first page, as
    // the CLI writes it to the file named (the others to name-2.svg, …).
    let expected = '';
    const dir = mkdtempSync(join(tmpdir(), 'linkage-sheet-'));
    try {
      execFileSync(cli, ['diagram', scene, '--input-deg', String(deg), '--svg', join(dir, 'sheet.svg')]);
      expected = readFileSync(join(dir, 'sheet.svg'), 'utf8');
    } catch (e) {
      fail(`linkage diagram (${cli}) did not run: ${e.message}`);
    } finally {
      rmSync(dir, { recursive: true, force: true });
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
    // A picture a page, each drawn when its image has loaded: in any order. The first
    // page is the one named like the sheet.
    const downloads = [];
    const take = (d) => downloads.push(d);
    page.on('download', take);
    await page.mouse.click(0.5 * (pngButton.rect[0] + pngButton.rect[2]), 0.5 * (pngButton.rect[1] + pngButton.rect[3]));
    const first = () => downloads.find((d) => d.suggestedFilename().endsWith('deg.png'));
    await until(async () => first() !== undefined, () => page.mouse.move(700, 6));
    page.off('download', take);
    const dl = first() ?? downloads[0];
    if (!dl) fail('no PNG download');
    const bytes = dl ? readFileSync(await dl.path()) : Buffer.alloc(0);
    if (dl && !dl.suggestedFilename().endsWith('deg.png')) fail(`PNG download named ${dl.suggestedFilename()}`);
    if (bytes.subarray(1, 4).toString() !== 'PNG') fail('the PNG download is no PNG');
    else pngWidth = bytes.readUInt32BE(16);
    if (Math.abs(pngWidth - 1240) > 1) fail(`the PNG sheet is ${pngWidth} px wide, not 1240`);
  }
  // PDF…: the pages printed through a hidden frame, A4 without margins; the browser's
  // print dialog saves the PDF (headless Chromium prints nowhere).
  const pdfButton = controls.controls.entries.find((e) => e.kind === 'FileButton' && e.label === 'PDF…');
  let printedPages = 0;
  if (!pdfButton) fail('no PDF export button');
  else {
    await page.mouse.click(0.5 * (pdfButton.rect[0] + pdfButton.rect[2]), 0.5 * (pdfButton.rect[1] + pdfButton.rect[3]));
    await until(async () => (await page.$$('iframe')).length > 0, () => page.mouse.move(700, 6));
    const doc = await page.evaluate(() => [...document.querySelectorAll('iframe')].map((f) => f.srcdoc).pop() ?? '');
    printedPages = (doc.match(/class="page"/g) ?? []).length;
    if (!doc.includes('@page { size: A4; margin: 0 }') || printedPages < 2) fail(`the print frame holds ${printedPages} pages: ${doc.slice(0, 200)}`);
    const said = (await appState(page)).status ?? '';
    if (!said.includes('Save as PDF')) fail(`after PDF… the status says ${said}`);
  }
  const saved = await download(SAVE);
  if (saved.name !== 'die_cutter.ron') fail(`scene download named ${saved.name}`);
  if (!/\bname:/.test(saved.text)) fail(`scene download is no scene: ${saved.text.slice(0, 80)}`);

  // The saved scene opens again; then another shipped scene changes the picture.
  await upload('saved_cutter.ron', saved.text);
  await nextFrame(page, () => page.mouse.move(21, 10));
  const cutter = await shot('reopened');
  const sliderCrank = readFileSync(new URL('../../assets/scenes/slider_crank.ron', import.meta.url), 'utf8');
  await upload('slider_crank.ron', sliderCrank);
  let reopened = 0;
  await until(async () => (reopened = differing(cutter, await shot('uploaded'))) >= 2000);
  if (reopened < 2000) fail(`opening slider_crank.ron changed only ${reopened} pixels`);

  // A scene opened from a file travels whole in the URL (doc=1.…): a reload keeps it,
  // and the address opened in a new page (a shared link) shows the same mechanism.
  const uploadedName = (await appState(page)).scene_name;
  let hash = '';
  await until(async () => (hash = await page.evaluate(() => location.hash)).includes('doc=1.'));
  if (!hash.includes('doc=1.')) fail(`the URL does not carry the opened file: ${hash.slice(0, 60)}`);
  const afterReload = async (p) => {
    // The bindings exist before the wasm is ready: a call then throws.
    const ready = await until(() => p.evaluate(() => {
      try { return Boolean(window.wasmBindings?.linkage_lab_controls?.()); } catch { return false; }
    }));
    return ready ? appState(p) : {};
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
  /** Drags with the mouse from `from` along `path` (screen points), each step once the
   * app has drawn the frame that took the one before; returns the CPU of each edit
   * frame ([frame ms, edit ms], the app's own performance.now() figures). */
  const dragTimed = async (p, from, path) => {
    await p.mouse.move(...from);
    await p.mouse.down();
    let timing = (await appState(p)).edit_timing;
    const seen = [];
    for (const at of path) {
      const frame = (await appState(p)).frame;
      await p.mouse.move(...at);
      await until(async () => (await appState(p)).frame > frame);
      const t = (await appState(p)).edit_timing;
      if (t.frames > timing.frames) seen.push([Number(t.last_ms.toFixed(2)), Number(t.last_edit_ms.toFixed(2))]);
      timing = t;
    }
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
    await until(() => (url = page.url()).includes(wantUrl));
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
    await until(async () => (await appState(page)).scene_name === 'Four-bar (template)');
    if ((await appState(page)).scene_name !== 'Four-bar (template)') fail(`New… → four-bar opened ${(await appState(page)).scene_name}`);
    const toggle = await entry(page, 'Layer', 'move points');
    if (toggle) await page.mouse.click(...middle(toggle));
    await nextFrame(page);
    const before = await appState(page);
    const c = before.joints.find((j) => j.name === 'C');
    const [cx, cy] = c.screen;
    const path = Array.from({ length: 8 }, (_, i) => [cx + 5 * (i + 1), cy - 3 * (i + 1)]);
    dragFrames.viewer_point = await dragTimed(page, [cx, cy], path);
    await nextFrame(page, () => page.mouse.move(21, 10));
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
  /** Clicks at a world place (mm) and waits for the frame that took the click. */
  const clickMm = async (xy) => {
    const st = await appState(page);
    await page.mouse.click(...toScreen(st, xy));
    await until(async () => (await appState(page)).frame > st.frame);
  };
  const useTool = async (label) => {
    const t = await entry(page, 'DrawTool', label);
    if (!t) { fail(`no drawing tool ${label}`); return; }
    const frame = (await appState(page)).frame;
    await page.mouse.click(...middle(t));
    await until(async () => (await appState(page)).frame > frame);
  };
  /** After New… → Empty: waits until the drawing starts, answering the question the
   * app asks first over unsaved edits; returns whether it started. */
  const drawingStarts = async () => {
    const question = async () => (await appState(page)).controls.entries
      .some((e) => e.kind === 'FileButton' && e.label === 'Drop the edits and open' && e.visible);
    await until(async () => (await appState(page)).drawing || question());
    if (!(await appState(page)).drawing) {
      const dropping = await entry(page, 'FileButton', 'Drop the edits and open');
      if (dropping) await page.mouse.click(...middle(dropping));
    }
    return until(async () => (await appState(page)).drawing);
  };
  const menu = await entry(page, 'FileButton', 'New…');
  if (menu) {
    await page.mouse.click(...middle(menu));
    const empty = await entry(page, 'TemplateItem', 'Empty: draw your own');
    if (!empty) fail('no empty drawing in New…');
    else await page.mouse.click(...middle(empty));
    // The four-bar above has unsaved edits: the app asks before drawing over them.
    if (!(await drawingStarts())) fail(`New… → Empty did not start a drawing: ${(await appState(page)).message ?? ''}`);
    else {
      await useTool('Pivot');
      for (const xy of [[0, 0], [300, 0]]) await clickMm(xy);
      await useTool('Link');
      for (const xy of [[0, 0], [0, 50], [0, 50], [200, 200], [200, 200], [300, 0]]) await clickMm(xy);
      await useTool('Driver');
      await clickMm([0, 25]);
      await until(async () => (await appState(page)).drawing?.complete);
      const st = await appState(page);
      if (!st.drawing?.complete) fail(`the drawn four-bar is not a mechanism: ${JSON.stringify(st.drawing)}`);
      // The Move tool: D dragged out along x and back to where it was drawn (the grid
      // is 10 mm), an edit per frame that remakes and reopens the mechanism.
      await useTool('Move');
      const d = toScreen(await appState(page), [200, 200]);
      const out = Array.from({ length: 6 }, (_, i) => toScreen(st, [200 + 10 * (i + 1), 200]));
      dragFrames.drawing_point = await dragTimed(page, d, [...out, ...out.reverse().slice(1), d]);
      await useTool('Done');
      await until(async () => !(await appState(page)).drawing);
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
    await drawingStarts();
    await useTool('Pivot');
    for (const xy of [[0, 0], [300, 0]]) await clickMm(xy);
    const before = (await appState(page)).drawing?.points;
    if (before !== 2) fail(`two pivots placed, the drawing has ${before} points`);
    // The page stores the drawing in the frame after the change.
    await nextFrame(page, () => page.mouse.move(21, 10));
    await page.reload({ waitUntil: 'load' });
    unfinishedPoints = (await afterReload(page)).drawing?.points ?? 0;
    if (unfinishedPoints !== 2) fail(`after a reload the unfinished drawing has ${unfinishedPoints} points, not 2`);
  }

  // Path searches in the page: Synthesis… → path, the targets cleared and clicked on its
  // canvas, Search. The browser has no threads here: the search runs a slice of a few
  // milliseconds per frame. A small search (four targets) ends with designs; a long
  // one (twelve targets round a square, which no four-bar's coupler meets) runs until
  // its work spans many of the page's frames, then Stop is pressed. That frames kept
  // coming is judged by frames.mjs against the search's own duration and the page's
  // own frames, never by a count of frames or a wall time.
  let pathSearch = {};
  const startGaps = () => page.evaluate(() => {
    window.rafTimes = []; window.rafStop = false;
    const tick = (t) => { window.rafTimes.push(t); if (!window.rafStop) requestAnimationFrame(tick); };
    requestAnimationFrame(tick);
  });
  const stopGaps = async () => {
    const times = await page.evaluate(() => { window.rafStop = true; return window.rafTimes; });
    return times.slice(1).map((t, k) => t - times[k]);
  };
  /** Clears the targets and clicks `at` (fractions of the canvas) on the path canvas. */
  const placeTargets = async (at) => {
    const clear = await entry(page, 'FileButton', 'Clear targets');
    if (clear) await page.mouse.click(...middle(clear));
    const board = await entry(page, 'SynthesisCanvas', 'path targets');
    if (!board) { fail('no path canvas'); return false; }
    const [x0, y0, x1, y1] = board.rect;
    for (const [fx, fy] of at) {
      const before = (await appState(page)).path_targets;
      await page.mouse.click(x0 + fx * (x1 - x0), y0 + fy * (y1 - y0));
      await until(async () => (await appState(page)).path_targets > before);
    }
    return true;
  };
  const searchState = async () => (await appState(page)).path_search;
  const synth = await entry(page, 'FileButton', 'Synthesis…');
  const pathTab = synth && (await page.mouse.click(...middle(synth)), await entry(page, 'SynthesisTab', 'path'));
  if (!pathTab) fail('no Synthesis… button or no path tab');
  else {
    await page.mouse.click(...middle(pathTab));
    if (await placeTargets([[0.2, 0.7], [0.4, 0.25], [0.65, 0.2], [0.85, 0.6]])) {
      const search = await entry(page, 'FileButton', 'Search');
      if (search) await page.mouse.click(...middle(search));
      await until(async () => (await searchState())?.running === false);
      const small = await searchState();
      if (!small) fail('Search started no path search');
      else if (small.running) fail(`the path search did not end: ${JSON.stringify(small)}`);
      else if (small.targets !== 4 || small.solutions < 1) fail(`the path search: ${JSON.stringify(small)}`);
      pathSearch.small = small;
    }
    const square = [0, 1, 2, 3].flatMap((side) => [0, 1 / 3, 2 / 3].map((f) => {
      const corners = [[0.25, 0.25], [0.75, 0.25], [0.75, 0.75], [0.25, 0.75]];
      const [a, b] = [corners[side], corners[(side + 1) % 4]];
      return [a[0] + f * (b[0] - a[0]), a[1] + f * (b[1] - a[1])];
    }));
    if (await placeTargets(square)) {
      const search = await entry(page, 'FileButton', 'Search');
      if (shotDir) await shot('before_long_search');
      const before = await searchState();
      await startGaps();
      if (search) await page.mouse.click(...middle(search));
      // The new search under way: its own evaluations, not the small one's.
      const started = await until(async () => {
        const st = await appState(page);
        return st.path_refused || (st.path_search?.running && st.path_search.evaluations !== before?.evaluations);
      });
      const refused = (await appState(page)).path_refused;
      // Until the search has spanned 20 of the page's frames (or ended).
      if (started && !refused) {
        await until(async () => {
          const st = await searchState();
          const gaps = await page.evaluate(() => window.rafTimes.slice(1).map((t, k) => t - window.rafTimes[k]));
          return !st.running || framesSpanned(gaps) >= 20;
        });
      }
      const stop = started && !refused && (await searchState()).running && await entry(page, 'FileButton', 'Stop');
      if (stop) await page.mouse.click(...middle(stop));
      await until(async () => (await searchState())?.running === false);
      const gaps = await stopGaps();
      const long = await searchState();
      if (refused) fail(`the long search was refused: ${refused}`);
      else if (!started) fail(`Search started no new search: ${JSON.stringify(long)}`);
      if (long.evaluations === before?.evaluations) fail(`the long search did no work: ${JSON.stringify(long)}`);
      const frames = framesKeptComing(gaps);
      const slices = slicesKeptTheirBudget(long);
      pathSearch.long = { ...long, max_frame_gap_ms: Number(Math.max(...gaps).toFixed(1)), frames: frames.why, slicing: slices.why };
      if (long.running) fail(`Stop did not stop the search: ${JSON.stringify(long)}`);
      if (!frames.judged) fail(`the long search was too short to judge: ${frames.why}`);
      if (!frames.ok) fail(`the page froze during the path search: ${frames.why}`);
      if (!slices.ok) fail(`a search slice overran its budget: ${slices.why}`);
    }
  }
  return {
    csv_download_rows: csvRows, scene_download_bytes: saved.text.length,
    sheet_download_bytes: sheetBytes, sheet_png_width: pngWidth, printed_pages: printedPages,
    pixels_changed_by_upload: reopened, link_chars: page.url().length,
    editor_drag_frames_ms: dragFrames,
    built_four_bar_joints: built.joints?.length ?? 0,
    drawn_four_bar_joints: drawn.joints?.length ?? 0,
    unfinished_drawing_points_after_reload: unfinishedPoints,
    path_search: pathSearch,
  };
}


if (errors.length) fail(`console errors:\n  ${errors.join('\n  ')}`);
console.log(JSON.stringify({
  url, build, first_frame_ms: firstFrameMs, canvas_drawn_fraction: Number(coverage.toFixed(3)),
  pixels_changed_by_slider_drag: changed, pixels_changed_by_play: played,
  fps_playing: Number(fps.toFixed(1)), ...pageActions,
  console_errors: errors.length,
}));
await browser.close();
