// Phones and tablets in real headless Chromium with touch emulation (hasTouch, and
// isMobile for the phone): 390x844 (a phone held upright), 820x1180 (a tablet
// upright) and 1024x768 (lying). On each: the mechanism view has at least half
// the screen, the touch targets are at least 40 px high, no control runs off the
// screen's sides; then every scene in assets/scenes (on the tablets, the scenes with
// the most panes) is opened through the scene picker with a finger, the crank turned by dragging its slider with a finger, the
// polygons shown (their tab of the sheet), and the view pinch-zoomed with two
// fingers. Each screenshot is checked (the canvas drawn, the mechanism coloured in
// the view, the polygons in the sheet) and, with SCREENSHOT_DIR set, saved there.
// Fingers move through Chrome's DevTools protocol (Input.dispatchTouchEvent), each
// step once the app has drawn the frame that took the one before.
// Usage: node every_device.mjs http://127.0.0.1:PORT/
import { writeFileSync } from 'node:fs';
import { appState as state, build, colouredIn, decode, differing, launchChromium, nonBackground, openApp, settledControl, shippedScenes, until } from './common.mjs';

const base = (process.argv[2] ?? 'http://127.0.0.1:8917/').replace(/#.*$/, '');
const fail = (msg) => { console.error(`FAIL: ${msg}`); process.exitCode = 1; };
const shotDir = process.env.SCREENSHOT_DIR;

/** The devices: name, screen in CSS pixels, whether a phone (isMobile), and the
 * arrangement the app must choose. */
const DEVICES = [
  { name: 'phone_390x844', width: 390, height: 844, mobile: true, arrangement: 'Tall' },
  // Upright, the tablet has the phone's arrangement: here touch on the scenes with
  // the most panes (tests/app/layout_grid.rs walks them natively at 820x1180 after
  // every panel action), the die cutter's machine tabs, the cam feed's cam tabs and
  // the flipper's dynamic run (all seven scenes took 76 s here, 2026-11-28).
  { name: 'tablet_820x1180', width: 820, height: 1180, mobile: false, arrangement: 'Tall', scenes: ['die_cutter', 'paper_cup_cam_feed', 'gravity_flipper'] },
  // Lying, the tablet has the laptop's arrangement (laptop.mjs, every scene at
  // 1366x768; natively tests/app/layout_grid.rs at 1024x768 after every panel
  // action): here touch on the six-bar die cutter and on the cam feed, the scene with
  // the most controls (all seven scenes took 104 s here, 2026-11-27).
  { name: 'tablet_1024x768', width: 1024, height: 768, mobile: false, arrangement: 'Broad', scenes: ['die_cutter', 'paper_cup_cam_feed'] },
];
/** Controls a finger must hit: at least 40 px high (as tests/ui.rs asks natively). */
const TOUCHED = ['Play', 'Crank', 'Length', 'Branch', 'SheetTab', 'Menu', 'History', 'ScenePicker'];
const TOUCH_PX = 40;

const scenes = shippedScenes();

const centre = (r) => [0.5 * (r[0] + r[2]), 0.5 * (r[1] + r[3])];
const area = (r) => Math.max(0, r[2] - r[0]) * Math.max(0, r[3] - r[1]);

/** Waits until the app has drawn a frame after `frame`. */
const frameAfter = (page, frame) => until(async () => (await state(page)).frame > frame);

/** Fingers on the screen: `points` ([x, y] each) for a touchStart or touchMove, none
 * for touchEnd; resolves once the app has drawn the frame that took them. */
async function touch(page, cdp, type, points) {
  const frame = (await state(page)).frame;
  await fingers(cdp, type, points);
  await frameAfter(page, frame);
}

/** Fingers on the screen at `points` ([x, y] each), none for touchEnd. */
function fingers(cdp, type, points) {
  return cdp.send('Input.dispatchTouchEvent', {
    type, touchPoints: points.map(([x, y], id) => ({ x, y, id, radiusX: 4, radiusY: 4, force: 1 })),
  });
}

/** How long a finger rests on the glass in a tap, ms: a person's tap, whatever the
 * frame rate. */
const TAP_MS = 80;

/** A tap, then the frame that took it. The finger is lifted after TAP_MS, not after
 * the app's next frame: egui counts a press held longer than 0.8 s of its frame
 * clock as a long press, not a click, and on a loaded machine a frame took that long
 * (a CI run, 2026-11-26: the tablet's Polygons tab went unanswered; with the CPU
 * throttled 8 times, the scene picker did not open at all, and does now). */
async function tap(page, cdp, at) {
  const frame = (await state(page)).frame;
  await fingers(cdp, 'touchStart', [at]);
  await new Promise((r) => setTimeout(r, TAP_MS));
  await fingers(cdp, 'touchEnd', []);
  await frameAfter(page, frame);
}

/** A finger dragged from `from` to `to` in `steps` moves. */
async function swipe(page, cdp, from, to, steps = 4) {
  await touch(page, cdp, 'touchStart', [from]);
  for (let k = 1; k <= steps; k++) {
    const f = k / steps;
    await touch(page, cdp, 'touchMove', [[from[0] + f * (to[0] - from[0]), from[1] + f * (to[1] - from[1])]]);
  }
  await touch(page, cdp, 'touchEnd', []);
}

/** Two fingers about `at`, spread from `r0` to `r1` px apart each side. */
async function pinch(page, cdp, at, r0, r1, steps = 4) {
  const fingers = (r) => [[at[0] - r, at[1]], [at[0] + r, at[1]]];
  await touch(page, cdp, 'touchStart', fingers(r0));
  for (let k = 1; k <= steps; k++) await touch(page, cdp, 'touchMove', fingers(r0 + (k / steps) * (r1 - r0)));
  await touch(page, cdp, 'touchEnd', []);
}

/** The control of `kind` (and `label`) once two frames show it in the same place;
 * an idle app draws a frame on a pointer move. */
const control = (page, kind, label) => settledControl(page, kind, label, () => page.mouse.move(2, 2));

/** The sheet's part of the screen: below the view when the screen stands, right of
 * it when it lies. */
function sheetRect(st, device) {
  const [x0, y0, x1, y1] = st.controls.view;
  return st.arrangement === 'Broad' ? [x1, y0, device.width, device.height] : [x0, y1, x1, device.height];
}

/** Saves `img` as `name` under SCREENSHOT_DIR (if set) and returns it decoded. */
async function shot(page, name) {
  const buf = await page.screenshot();
  if (shotDir) writeFileSync(`${shotDir}/${name}.png`, buf);
  return decode(buf);
}

/** The layout's promises on this screen: the arrangement, the view's share, touch
 * targets, nothing off the sides. */
function checkLayout(st, device, what) {
  if (st.arrangement !== device.arrangement) fail(`${what}: arrangement ${st.arrangement}, not ${device.arrangement}`);
  const share = area(st.controls.view) / (device.width * device.height);
  if (!(share >= 0.5)) fail(`${what}: the view has ${(share * 100).toFixed(0)} % of the screen`);
  for (const e of st.controls.entries.filter((c) => c.visible)) {
    const h = e.rect[3] - e.rect[1];
    if (TOUCHED.includes(e.kind) && h < TOUCH_PX - 0.5) fail(`${what}: ${e.kind} "${e.label}" is ${h.toFixed(0)} px high`);
    if (e.rect[0] < -0.5 || e.rect[2] > device.width + 0.5) fail(`${what}: ${e.kind} "${e.label}" runs off the screen: ${e.rect.map(Math.round)}`);
  }
  return share;
}

/** Opens `scene` through the picker with a finger; returns whether it opened. */
async function openScene(page, cdp, scene) {
  const picker = await control(page, 'ScenePicker');
  if (!picker) return false;
  await tap(page, cdp, centre(picker.rect));
  const item = await control(page, 'SceneItem', scene.name);
  if (!item) return false;
  await tap(page, cdp, centre(item.rect));
  return until(async () => (await page.evaluate(() => location.hash)).startsWith(`#scene=${scene.key}&`));
}

/** Shows the sheet's `tab` with one tap; returns whether it is shown. */
async function showTab(page, cdp, tab) {
  const c = await control(page, 'SheetTab', tab);
  if (!c) return false;
  await tap(page, cdp, centre(c.rect));
  return until(async () => (await state(page)).sheet_tab === tab);
}

/** One scene on one device: opened, crank turned, polygons shown, view pinched. */
async function exercise(page, cdp, device, scene) {
  const what = `${device.name} ${scene.key}`;
  const out = { scene: scene.key };
  if (!(await openScene(page, cdp, scene))) { fail(`${what}: the scene did not open from the picker`); return out; }
  if (!(await showTab(page, cdp, 'Controls'))) fail(`${what}: no Controls tab`);
  let st = await state(page);
  const opened = await shot(page, `${what.replace(' ', '_')}`);
  out.drawn = Number(nonBackground(opened).toFixed(3));
  out.view_share = Number(checkLayout(st, device, what).toFixed(3));
  if (out.drawn < 0.2) fail(`${what}: the page is ${(out.drawn * 100).toFixed(0)} % drawn`);
  const coloured = colouredIn(opened, st.controls.view);
  if (coloured < 300) fail(`${what}: the view shows ${coloured} coloured pixels: no mechanism`);

  // The crank turned by a finger on its slider.
  const crank = await control(page, 'Crank');
  if (!crank) fail(`${what}: no crank slider`);
  else {
    // The entry's rectangle is the whole row (slider, value, label); a slider is at
    // least 180 px long on every device, so the finger stays on it from 30 to 90 px.
    const x0 = crank.rect[0], y = centre(crank.rect)[1];
    const before = (await state(page)).input_deg;
    await swipe(page, cdp, [x0 + 30, y], [x0 + 90, y]);
    const after = await state(page);
    out.crank_deg = [Number(before.toFixed(1)), Number(after.input_deg.toFixed(1))];
    if (Math.abs(after.input_deg - before) < 1) fail(`${what}: dragging the crank slider with a finger turned it ${after.input_deg - before} deg`);
    if (!after.pose_finite) fail(`${what}: non-finite pose after turning the crank`);
  }

  // The polygons, in their tab of the sheet.
  st = await state(page);
  const sheetBefore = await shot(page, `${what.replace(' ', '_')}_crank`);
  if (!(await showTab(page, cdp, 'Polygons'))) fail(`${what}: no Polygons tab`);
  else {
    let polygons, px = 0;
    const sheet = sheetRect(st, device);
    await until(async () => {
      polygons = await shot(page, `${what.replace(' ', '_')}_polygons`);
      px = colouredIn(polygons, sheet);
      return px >= 300 && differing(sheetBefore, polygons) > 500;
    }, () => page.mouse.move(2, 2));
    out.polygon_pixels = px;
    if (px < 300) fail(`${what}: the Polygons tab shows ${px} coloured pixels`);
  }

  // Two fingers spread apart in the view: it zooms in about them.
  st = await state(page);
  const zoom0 = st.camera[2];
  await pinch(page, cdp, centre(st.controls.view), 30, 90);
  const zoomed = (await state(page)).camera[2] / zoom0;
  out.pinch_zoom = Number(zoomed.toFixed(2));
  if (!(zoomed > 1.5)) fail(`${what}: pinching out zoomed the view by ${zoomed}`);
  await shot(page, `${what.replace(' ', '_')}_pinched`);
  return out;
}

const browser = await launchChromium();
const results = [];
for (const device of DEVICES) {
  const began = Date.now();
  const context = await browser.newContext({
    viewport: { width: device.width, height: device.height },
    deviceScaleFactor: 1, isMobile: device.mobile, hasTouch: true,
  });
  const page = await context.newPage();
  const cdp = await context.newCDPSession(page);
  const errors = await openApp(page, base);
  if (errors.length) fail(`${device.name}: ${errors.splice(0).join('\n  ')}`);
  const size = await page.evaluate(() => [innerWidth, innerHeight]);
  if (size[0] !== device.width || size[1] !== device.height) fail(`${device.name}: the page is ${size}`);
  const outcomes = [];
  for (const scene of scenes.filter((sc) => !device.scenes || device.scenes.includes(sc.key))) {
    outcomes.push(await exercise(page, cdp, device, scene));
  }
  if (errors.length) fail(`${device.name}: console errors:\n  ${errors.join('\n  ')}`);
  results.push({ device: device.name, seconds: Math.round((Date.now() - began) / 1000), scenes: outcomes });
  await context.close();
}
await browser.close();
console.log(JSON.stringify({ build, devices: results }, null, 1));
