// A laptop's screen, 1366x768, in real headless Chromium with a mouse, as a student
// with the die-cutter project or a cam exercise uses it. The actions that used to
// collapse the mechanism view to a strip 50 to 130 px high and push the plot tabs
// off screen (the vector equations opened, "enlarge", the "Cam s v a j" tab, then
// "narrower" and "Reset layout"): after each, the view's rectangle and the plot
// tab row are read from the app's control map, reported, and must hold: the view
// keeps at least 35 % of the window, no side of it under a quarter of the window's,
// and every plot tab on screen. Then every shipped scene is opened through the
// address and photographed (SCREENSHOT_DIR, if set), to be looked at.
// Usage: node laptop.mjs http://127.0.0.1:PORT/
import { writeFileSync } from 'node:fs';
import { appState as state, build, launchChromium, nonBackground, decode, openApp, settledControl, shippedScenes, until } from './common.mjs';

const base = (process.argv[2] ?? 'http://127.0.0.1:8917/').replace(/#.*$/, '');
const fail = (msg) => { console.error(`FAIL: ${msg}`); process.exitCode = 1; };
const shotDir = process.env.SCREENSHOT_DIR;
const W = 1366, H = 768;

const centre = (r) => [0.5 * (r[0] + r[2]), 0.5 * (r[1] + r[3])];
const area = (r) => Math.max(0, r[2] - r[0]) * Math.max(0, r[3] - r[1]);
const round = (r) => r.map((v) => Math.round(v));

const browser = await launchChromium();
const context = await browser.newContext({ viewport: { width: W, height: H }, deviceScaleFactor: 1 });
const page = await context.newPage();
// An idle egui app draws a frame only on input: a pointer move asks for one.
let wiggle = 0;
const poke = () => page.mouse.move(20 + (wiggle++ % 2), 10);
const control = (kind, label) => settledControl(page, kind, label, poke);

/** Waits for two more frames, so that a layout change has settled (a pane's size
 * is remembered from the frame before). */
async function settle() {
  const frame = (await state(page)).frame;
  await until(async () => (await state(page)).frame >= frame + 3, poke);
}

/** Scrolls the pane under the control of `kind` and `label` (it is drawn, but
 * scrolled out of its pane's view) until it shows, as a user turns the wheel. */
async function reveal(kind, label) {
  for (let tries = 0; tries < 12; tries++) {
    const st = await state(page);
    const c = st.controls.entries.find((e) => e.kind === kind && e.label === label);
    if (!c || c.visible) return;
    const pane = st.controls.entries.find((e) => e.kind === 'Pane' && e.rect[0] <= c.rect[0] && c.rect[0] <= e.rect[2]);
    if (!pane) return;
    await page.mouse.move(...centre(pane.rect));
    await page.mouse.wheel(0, c.rect[1] > pane.rect[3] ? 150 : -150);
    await settle();
  }
}

/** Clicks the control of `kind` and `label`; returns whether it was there. */
async function click(kind, label) {
  await reveal(kind, label);
  const c = await control(kind, label);
  if (!c) { fail(`no ${kind} "${label}" to click`); return false; }
  await page.mouse.click(...centre(c.rect));
  await settle();
  return true;
}

/** The view and the tab row after `action`, reported and checked. */
async function check(scene, action) {
  const st = await state(page);
  const view = st.controls.view;
  const tabs = st.controls.entries.filter((e) => e.kind === 'PlotTab');
  const share = area(view) / (W * H);
  const row = {
    scene, action,
    view: round(view),
    view_share: Number(share.toFixed(3)),
    tab_row: tabs.length ? round([Math.min(...tabs.map((t) => t.rect[0])), Math.min(...tabs.map((t) => t.rect[1])), Math.max(...tabs.map((t) => t.rect[2])), Math.max(...tabs.map((t) => t.rect[3]))]) : null,
  };
  if (share < 0.35) fail(`${scene} after ${action}: the view has ${(share * 100).toFixed(1)} % of the window`);
  if (view[2] - view[0] < W / 4 || view[3] - view[1] < H / 4) fail(`${scene} after ${action}: the view is a strip ${round(view)}`);
  if (!tabs.length) fail(`${scene} after ${action}: no plot tabs`);
  for (const t of tabs) {
    const r = t.rect;
    if (!t.visible || r[0] < 0 || r[1] < 0 || r[2] > W || r[3] > H) fail(`${scene} after ${action}: the tab ${t.label} is off screen at ${round(r)}`);
  }
  console.log(JSON.stringify(row));
  return row;
}

const errors = await openApp(page, base);
const rows = [];
for (const scene of ['die_cutter', 'paper_cup_cam_feed']) {
  await page.goto(`${base}#scene=${scene}`);
  await until(async () => (await page.evaluate(() => location.hash)).startsWith(`#scene=${scene}&`), poke);
  await settle();
  rows.push(await check(scene, 'opening'));
  for (const section of ['Velocity polygon: vector equations', 'Acceleration polygon: vector equations']) {
    if (await click('Section', section)) rows.push(await check(scene, `opening "${section}"`));
  }
  if (await click('PolygonLayout', 'enlarge')) rows.push(await check(scene, 'enlarge'));
  if (scene === 'paper_cup_cam_feed' && (await click('PlotTab', 'Cam s v a j'))) rows.push(await check(scene, 'the Cam s v a j tab'));
  if (await click('PolygonLayout', 'narrower')) rows.push(await check(scene, 'narrower'));
  if (await click('ResetLayout', 'Reset layout')) rows.push(await check(scene, 'reset layout'));
}

// Every scene at the laptop's size, to be looked at.
const shots = [];
for (const scene of shippedScenes()) {
  await page.goto(`${base}#scene=${scene.key}`);
  await until(async () => (await page.evaluate(() => location.hash)).startsWith(`#scene=${scene.key}&`), poke);
  await settle();
  const buf = await page.screenshot();
  if (shotDir) writeFileSync(`${shotDir}/laptop_1366x768_${scene.key}.png`, buf);
  const drawn = nonBackground(decode(buf));
  if (drawn < 0.2) fail(`${scene.key} at ${W}x${H}: the page is ${(drawn * 100).toFixed(0)} % drawn`);
  shots.push({ scene: scene.key, drawn: Number(drawn.toFixed(3)) });
}
if (errors.length) fail(`console errors:\n  ${errors.join('\n  ')}`);
await browser.close();
console.log(JSON.stringify({ build, window: [W, H], layout: rows, screenshots: shots }, null, 1));
