// Every scene file in assets/scenes (read from the directory, not listed here), in
// real headless Chromium, as a user meets it: opened through the scene picker and
// through a URL fragment; for each: no console error or panic, the canvas drawn,
// Play for a second changes the picture, and every kind of control the scene offers
// is moved with the mouse (crank, a length, a spring constant, a mass, the
// integrator, its tolerance, a branch flip, the instant centres, the polygon pane's
// size). The URL after those edits, opened in a
// new page, must reopen the same state. Each edit's click-to-frame time is printed
// (performance.now()); under SwiftShader it is set by the rasteriser's few frames a
// second, not by the edit.
// The app says where its controls are: window.wasmBindings.linkage_lab_controls().
// The WebGPU build's pass over the scenes is in browser_test.mjs
// (LINKAGE_BROWSER_CHECKS=drawn): the controls are the same code in both builds.
// Usage: node every_scene.mjs http://127.0.0.1:PORT/
import { EDIT_CPU_HEADING, appState as state, build, decode, differing, editCpuRow, launchChromium, nonBackground, openApp, quiet, shippedScenes, until } from './common.mjs';

const base = (process.argv[2] ?? 'http://127.0.0.1:8917/').replace(/#.*$/, '');
const fail = (msg) => { console.error(`FAIL: ${msg}`); process.exitCode = 1; };

// LINKAGE_SCENES=key,key runs those scenes alone (while working on one).
const only = process.env.LINKAGE_SCENES?.split(',');
const scenes = shippedScenes().filter((s) => !only || only.includes(s.key));
if (scenes.length < 6) fail(`only ${scenes.length} scene files found`);

const browser = await launchChromium();

/** A desktop window of a common size. SwiftShader's frame time grows with the
 * pixels drawn (156 ms a frame at 1366x768, 76 ms at a quarter of that, playing):
 * a smaller window than browser_test.mjs's 1500x950 makes this pass, hundreds of
 * frames, faster by a quarter. */
const WINDOW = { width: 1280, height: 720 };

/** A page with its console watched; resolves once the app has drawn its first frame. */
async function openPage(url) {
  const page = await browser.newPage({ viewport: WINDOW, deviceScaleFactor: 1 });
  const errors = await openApp(page, url);
  return { page, errors };
}

const shot = async (page) => decode(await page.locator('#linkage_canvas').screenshot());
const hash = (page) => page.evaluate(() => location.hash);
const centre = (c, fx = 0.5) => [c.rect[0] + fx * (c.rect[2] - c.rect[0]), 0.5 * (c.rect[1] + c.rect[3])];

/** Waits until no dynamic run is being computed: the accuracy panel's lines change
 * when one ends, which can scroll the panel under a control. */
async function runDone(page) {
  await until(async () => !(await state(page)).run_pending);
}

/** The first control of `kind` (and label, if given), scrolled into view, once the
 * layout has stopped changing: after a dynamic run, and with its place the same in
 * two different frames (egui's scroll is animated, and a panel's lines can change
 * under a control between the look and the click; at two frames a second, two looks
 * 100 ms apart can read the same frame). */
async function find(page, kind, label) {
  await runDone(page);
  let seen, found, absent = false, i = 0;
  await until(async () => {
    const st = await state(page);
    const c = st.controls.entries.find((e) => e.kind === kind && (label === undefined || e.label === label));
    if (!c) return (absent = true);
    if (c.visible) {
      if (seen && st.frame > seen.frame) {
        if (seen.c.rect.every((v, k) => Math.abs(v - c.rect[k]) < 0.5)) return (found = c);
        seen = { c, frame: st.frame };
      } else if (!seen) seen = { c, frame: st.frame };
      // An idle egui app draws no frame until something happens: a pointer move
      // over the top bar's title asks for one.
      await page.mouse.move(20 + (i++ % 2), 10);
      return false;
    }
    seen = undefined;
    // Scroll the control panel towards it; the scroll's animation runs meanwhile.
    await page.mouse.move(120, 500);
    await page.mouse.wheel(0, c.rect[1] > 500 ? 150 : -150);
    return false;
  });
  return absent ? undefined : found ?? seen?.c;
}

/** Clicks at (x, y) and returns the ms from the click to the next frame drawn after it. */
async function timedClick(page, [x, y]) {
  await page.evaluate(() => { window.__edit = performance.now(); window.__shown = null; requestAnimationFrame(() => requestAnimationFrame(() => { window.__shown = performance.now(); })); });
  await page.mouse.click(x, y);
  let ms = null;
  await until(async () => (ms = await page.evaluate(() => (window.__shown === null ? null : window.__shown - window.__edit))) !== null);
  return ms ?? NaN;
}

/** Two fragments carry the same state: same keys, numbers equal to 1e-9 relative
 * (a length is re-derived from point coordinates, so it may differ in the last bit). */
function sameFragment(a, b) {
  const parse = (h) => new Map(h.replace(/^#/, '').split('&').map((kv) => kv.split('=')));
  const [x, y] = [parse(a), parse(b)];
  if (x.size !== y.size) return false;
  for (const [k, v] of x) {
    const w = y.get(k);
    if (w === undefined) return false;
    const [p, q] = [Number(v), Number(w)];
    const same = Number.isFinite(p) && Number.isFinite(q) ? Math.abs(p - q) <= 1e-9 * Math.max(1, Math.abs(p)) : v === w;
    if (!same) return false;
  }
  return true;
}

/** Waits until the URL differs from `before`, the picture from `picture` (if given),
 * or the app shows a refusal; returns the app's state then. */
async function settle(page, before, picture) {
  let st;
  await until(async () => {
    st = await state(page);
    if ((await hash(page)) !== before || st.message) return true;
    return picture !== undefined && differing(picture, await shot(page)) > 200;
  });
  return st;
}

/** Opens `page`'s URL in a new page: it must show the same state (the fragment's
 * numbers and the crank angle); its console errors join `errors`. */
async function reopens(page, what, errors) {
  const here = await state(page);
  const again = await openPage(page.url());
  const there = await state(again.page);
  if (!sameFragment(await hash(again.page), await hash(page))) fail(`${what}: reopened as ${await hash(again.page)}, not ${await hash(page)}`);
  if (Math.abs(there.input_deg - here.input_deg) > 1e-3) fail(`${what}: reopened at ${there.input_deg} deg, not ${here.input_deg}`);
  errors.push(...again.errors);
  await again.page.close();
}

const SLIDERS = ['Crank', 'Length', 'Spring', 'Mass', 'Tolerance'];
const results = [];
// The scenes open through the picker and through a URL fragment in turn (both routes
// are the same code for every scene); LINKAGE_ROUTES=all opens each both ways.
const allRoutes = process.env.LINKAGE_ROUTES === 'all';
const routesFor = (i) => {
  const both = ['picker', 'fragment'];
  if (allRoutes) return both;
  return [both[i % 2]];
};
for (const [i, scene] of scenes.entries()) {
  for (const route of routesFor(i)) {
    const what = `${scene.file} via ${route}`;
    const { page, errors } = await openPage(route === 'fragment' ? `${base}#scene=${scene.key}` : base);
    if (route === 'picker') {
      const picker = await find(page, 'ScenePicker');
      if (!picker) { fail(`${what}: no scene picker`); await page.close(); continue; }
      await page.mouse.click(...centre(picker));
      // The popup's first frame only sizes it: wait until its items are placed.
      let item;
      await until(async () => (item = (await state(page)).controls.entries.find((e) => e.kind === 'SceneItem' && e.label === scene.name))?.visible);
      if (!item?.visible) { fail(`${what}: "${scene.name}" is not shown in the picker`); await page.close(); continue; }
      await page.mouse.click(...centre(item));
      await until(async () => (await hash(page)).startsWith(`#scene=${scene.key}&`));
    }
    if (!(await hash(page)).startsWith(`#scene=${scene.key}&`)) fail(`${what}: the URL says ${await hash(page)}`);
    const opened = await shot(page);
    const drawn = nonBackground(opened);
    if (drawn < 0.2) fail(`${what}: canvas ${(drawn * 100).toFixed(1)} % drawn`);

    // Play for a second.
    const play = await find(page, 'Play');
    await page.mouse.click(...centre(play));
    // Until the picture has moved (the die cutter turns at 50 rpm).
    let played = 0;
    await until(async () => (played = differing(opened, await shot(page))) >= 2000);
    await page.mouse.click(...centre(await find(page, 'Play')));
    if (played < 2000) fail(`${what}: playing changed only ${played} pixels`);

    // Every kind of control present, moved with the mouse.
    const kinds = new Set((await state(page)).controls.entries.map((e) => e.kind));
    const moved = {};
    // A click on an egui slider's rail sets the value there (the rail is the widget's
    // left part, 100 points wide by default). Lengths are also pulled to the rail's
    // far end, where some chains no longer assemble (a refused edit).
    // A slider's rail spans its rectangle: 23 points in, and 2 points short of its
    // far end.
    const moves = SLIDERS.filter((k) => kinds.has(k)).map((k) => [k, k, (r) => r[0] + 23]);
    if (kinds.has('Length')) moves.push(['Length', 'Length at max', (r) => r[2] - 2]);
    for (const [kind, name, at] of moves) {
      const c = await find(page, kind);
      const urlBefore = await hash(page);
      const picBefore = await shot(page);
      const timedBefore = (await state(page)).edit_timing.frames;
      const ms = await timedClick(page, [at(c.rect), centre(c)[1]]);
      const after = await settle(page, urlBefore, picBefore);
      const changed = (await hash(page)) !== urlBefore || differing(picBefore, await shot(page)) > 200;
      if (!changed && !after.message) fail(`${what}: moving ${name} "${c.label}" changed nothing`);
      if (!after.pose_finite) fail(`${what}: non-finite pose after ${name}`);
      if (after.edit_timing.frames <= timedBefore) fail(`${what}: no frame carried the ${name} edit`);
      moved[name] = {
        edit_frame_ms: Number(after.edit_timing.last_ms.toFixed(2)),
        edit_ms: Number(after.edit_timing.last_edit_ms.toFixed(2)),
        click_to_frame_ms: Number(ms.toFixed(1)),
        refused: Boolean(after.message),
      };
    }
    if (kinds.has('Branch')) {
      const c = await find(page, 'Branch');
      const urlBefore = await hash(page);
      const ms = await timedClick(page, centre(c, 0.1));
      const after = await settle(page, urlBefore);
      if ((await hash(page)) === urlBefore && !after.message) fail(`${what}: the branch flip "${c.label}" at ${c.rect} changed nothing (${urlBefore})`);
      moved.Branch = { edit_frame_ms: Number(after.edit_timing.last_ms.toFixed(2)), edit_ms: Number(after.edit_timing.last_edit_ms.toFixed(2)), click_to_frame_ms: Number(ms.toFixed(1)), refused: Boolean(after.message) };
    }
    if (kinds.has('Integrator')) {
      const picBefore = await shot(page);
      await page.mouse.click(...centre(await find(page, 'Integrator')));
      const rk4 = await find(page, 'IntegratorItem', 'rk4');
      if (!rk4) fail(`${what}: no rk4 in the integrator menu`);
      else {
        const ms = await timedClick(page, centre(rk4));
        let px = 0;
        await until(async () => (px = differing(picBefore, await shot(page))) >= 50);
        if (px < 50) fail(`${what}: choosing rk4 changed nothing on screen`);
        const timing = (await state(page)).edit_timing;
        moved.Integrator = { edit_frame_ms: Number(timing.last_ms.toFixed(2)), edit_ms: Number(timing.last_edit_ms.toFixed(2)), click_to_frame_ms: Number(ms.toFixed(1)), refused: false };
      }
    }
    // The instant centres shown and hidden, the polygon pane enlarged and narrowed:
    // each changes the picture (waited for: SwiftShader draws a few frames a second).
    for (const [kind, label] of [['Layer', 'instant centres'], ['PolygonLayout', undefined]]) {
      const name = label ?? kind;
      for (const turn of ['on', 'off']) {
        const c = await find(page, kind, label);
        if (!c) { fail(`${what}: no ${name} control`); break; }
        const picBefore = await shot(page);
        const ms = await timedClick(page, centre(c));
        let px = 0;
        await until(async () => (px = differing(picBefore, await shot(page))) >= 200);
        if (px < 200) fail(`${what}: turning ${name} ${turn} changed only ${px} pixels`);
        moved[`${name} ${turn}`] = { click_to_frame_ms: Number(ms.toFixed(1)), pixels_changed: px };
      }
    }
    for (const k of ['Crank', 'Length']) if (!moved[k]) fail(`${what}: no ${k} control`);

    // The URL after the edits reopens the same state.
    await reopens(page, what, errors);

    // The edit's own CPU, measured in the page: the median of repeated length
    // edits of the scene, valid and refused (session::edit_cost), once the page has
    // drawn its last frame (SwiftShader's drawing shares the CPUs).
    if (!(await quiet(page))) fail(`${what}: the app kept drawing frames with nothing to do`);
    const cpu = JSON.parse(await page.evaluate((key) => window.wasmBindings.linkage_lab_edit_cpu(key), scene.key));
    if (!cpu) fail(`${what}: no edit CPU measured`);
    if (errors.length) fail(`${what}: console errors:\n  ${errors.join('\n  ')}`);
    results.push({ scene: scene.key, route, drawn: Number(drawn.toFixed(3)), played, edits: moved, edit_cpu: cpu });
    await page.close();
  }
}
await browser.close();
console.log(JSON.stringify({ build, scenes: scenes.length, results }, null, 1));

// The CPU time of the frame that carried each edit (the app's own performance.now()
// figure: the edit, the panels and plots), and of the edit alone (applied to the
// session: what `cargo bench --bench edit` measures natively), slowest per scene,
// valid and refused.
console.log(`edit CPU, ${build} build, ms (slowest over the routes run): scene | valid frame | valid edit | refused frame | refused edit`);
for (const scene of scenes) {
  const edits = results.filter((r) => r.scene === scene.key).flatMap((r) => Object.values(r.edits));
  const worst = (refused, field) => {
    const ms = edits.filter((e) => e.refused === refused && field in e).map((e) => e[field]);
    return ms.length ? Math.max(...ms).toFixed(2) : '-';
  };
  console.log(`${scene.key} | ${worst(false, 'edit_frame_ms')} | ${worst(false, 'edit_ms')} | ${worst(true, 'edit_frame_ms')} | ${worst(true, 'edit_ms')}`);
}
// The edit alone, measured in the page.
console.log(EDIT_CPU_HEADING);
for (const scene of scenes) console.log(editCpuRow(scene.key, results.find((r) => r.scene === scene.key)?.edit_cpu));
