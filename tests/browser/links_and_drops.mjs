// The page's doors other than its own buttons, in real headless Chromium (desktop,
// 1500x950): a link pasted into the address bar of the open page (a hashchange), back
// and forward, and a scene file dropped on the canvas. The Chinese face is not fetched
// until a scene named in Chinese is dropped; then it is, and the app draws with it. Over unsaved edits each asks
// first and the scene stays until the answer: "Keep editing" keeps it with its edits,
// "Drop the edits and open" opens. A file that is not a scene is refused with its
// cause in the status line, and the scene shown stays.
// Usage: node links_and_drops.mjs http://127.0.0.1:PORT/
import { readFileSync } from 'node:fs';
import { appState, build, launchChromium, openApp, quiet, settledControl, shippedScenes, until } from './common.mjs';

const base = (process.argv[2] ?? 'http://127.0.0.1:8917/').replace(/#.*$/, '');
const fail = (msg) => { console.error(`FAIL: ${msg}`); process.exitCode = 1; };

const scenes = Object.fromEntries(shippedScenes().map((s) => [s.key, s]));
const [slider, shaper, flipper, cutter] = ['slider_crank', 'quick_return', 'gravity_flipper', 'die_cutter'].map((k) => scenes[k]);

const browser = await launchChromium();
const page = await browser.newPage({ viewport: { width: 1500, height: 950 }, deviceScaleFactor: 1 });

const state = () => appState(page);
let pokes = 0;
/** An idle app draws a frame on a pointer move. */
const poke = () => page.mouse.move(700 + (pokes++ % 2), 5);
/** Waits for a frame after now; then the state it published. */
const nextState = async () => {
  const frame = (await state()).frame;
  await until(async () => (await state()).frame > frame, poke);
  return state();
};
const middle = (r) => [0.5 * (r[0] + r[2]), 0.5 * (r[1] + r[3])];
/** The control of `kind` and `label` once two frames show it in the same place. */
const control = (kind, label) => settledControl(page, kind, label, poke);
const showing = async (s) => (await state()).scene_name === s.name;
const asking = async () => (await state()).controls.entries
  .some((e) => e.kind === 'FileButton' && e.label === 'Drop the edits and open' && e.visible);

/** An unsaved edit: a click on the first length slider's track, a little past its
 * handle (the scene's own length sits 0.68 of the way along the logarithmic track,
 * from a twentieth to four times itself; 0.72 is about 1.2 times it). */
async function edit() {
  // A dynamic scene's run, while it is computed, shows its progress above the sliders.
  await until(async () => !(await state()).run_pending, poke);
  const length = await control('Length');
  if (!length) { fail('no length slider to edit'); return; }
  await page.mouse.click(length.rect[0] + 0.72 * (length.rect[2] - length.rect[0]), middle(length.rect)[1]);
  if (!(await until(async () => (await state()).dirty, poke))) fail('a click on a length slider made no edit');
}

/** Answers the question over unsaved edits. */
async function answer(label) {
  const button = await control('FileButton', label);
  if (!button) { fail(`no "${label}" button`); return; }
  await page.mouse.click(...middle(button.rect));
  await nextState();
}

/** Checks that `doing` over unsaved edits asks first, keeps the scene and its edits
 * on "Keep editing", and opens `next` on "Drop the edits and open". */
async function asksFirst(what, doing, next) {
  const before = (await state()).scene_name;
  await edit();
  await doing();
  if (!(await until(asking, poke))) { fail(`${what} over unsaved edits did not ask first`); return; }
  let st = await state();
  if (st.scene_name !== before) fail(`${what} replaced "${before}" before the answer`);
  await answer('Keep editing');
  st = await nextState();
  if (st.scene_name !== before || !st.dirty) fail(`"Keep editing" after ${what} lost the scene or its edits: ${st.scene_name}, dirty ${st.dirty}`);
  await doing();
  if (!(await until(asking, poke))) { fail(`${what} again did not ask`); return; }
  await answer('Drop the edits and open');
  if (!(await until(() => showing(next), poke))) fail(`"Drop the edits and open" after ${what} did not open ${next.name}: ${(await state()).scene_name}`);
}

/** Drops a file named `name` holding `text` on the canvas, as a file manager does. */
async function drop(name, text) {
  await page.evaluate(([name, text]) => {
    const canvas = document.getElementById('linkage_canvas');
    const data = new DataTransfer();
    data.items.add(new File([text], name, { type: 'application/octet-stream' }));
    const at = { clientX: 700, clientY: 400, bubbles: true, cancelable: true, dataTransfer: data };
    for (const type of ['dragenter', 'dragover', 'drop']) canvas.dispatchEvent(new DragEvent(type, at));
  }, [name, text]);
}

/** Sets the page's fragment as a link pasted into the address bar does. */
const go = (fragment) => page.evaluate((f) => { location.hash = f; }, fragment);

const errors = await openApp(page, base);
if (errors.length) fail(errors.splice(0).join('\n'));
const first = (await state()).scene_name;
const out = { build, first };

// A link pasted into the open page.
await go(`scene=${slider.key}`);
if (!(await until(() => showing(slider), poke))) fail(`a pasted link did not open ${slider.name}: ${(await state()).scene_name}`);
// The address follows the app again: the opened scene's own fragment.
if (!(await until(async () => (await page.evaluate(() => location.hash)).startsWith(`#scene=${slider.key}&`), poke))) {
  fail(`the address did not follow the opened scene: ${await page.evaluate(() => location.hash)}`);
}
// Back and forward.
await page.goBack();
if (!(await until(async () => (await state()).scene_name === first, poke))) fail(`back did not reopen "${first}": ${(await state()).scene_name}`);
await page.goForward();
if (!(await until(() => showing(slider), poke))) fail(`forward did not reopen ${slider.name}: ${(await state()).scene_name}`);
out.link_back_forward = (await state()).scene_name;

// A link over unsaved edits.
await asksFirst('a pasted link', () => go(`scene=${shaper.key}`), shaper);
// A link that names no scene: said, and the scene stays.
await go('scene=no_such_scene');
await until(async () => /link/.test((await state()).status ?? ''), poke);
let st = await state();
if (!/no_such_scene/.test(st.status ?? '')) fail(`a link to no scene was not refused by name: ${st.status}`);
if (st.scene_name !== shaper.name) fail(`a link to no scene replaced the scene: ${st.scene_name}`);
out.bad_link = st.status;

// A scene file dropped on the canvas.
await drop(`${flipper.key}.ron`, flipper.text);
if (!(await until(() => showing(flipper), poke))) fail(`a dropped ${flipper.key}.ron did not open: ${(await state()).scene_name}`);
await asksFirst('a dropped file', () => drop(`${cutter.key}.ron`, cutter.text), cutter);
// A file that is not a scene: refused, naming the file and the cause.
await drop('notes.ron', 'this is not a scene (');
await until(async () => /notes\.ron/.test((await state()).status ?? ''), poke);
st = await state();
if (!/notes\.ron: .+/.test(st.status ?? '')) fail(`a malformed drop was not refused with its cause: ${st.status}`);
if (st.scene_name !== cutter.name) fail(`a malformed drop replaced the scene: ${st.scene_name}`);
out.bad_drop = st.status;

// The Chinese face: not part of an English user's download, fetched once Chinese
// text is shown (src/web_font.rs).
const fontRequests = () => page.evaluate(() => performance.getEntriesByType('resource')
  .filter((e) => e.name.includes('NotoSansSC')).map((e) => ({ name: e.name, bytes: e.encodedBodySize })));
if ((await fontRequests()).length) fail(`the Chinese face was fetched before any Chinese text: ${JSON.stringify(await fontRequests())}`);
const zh = readFileSync(new URL('../../docs/examples/slider_crank_zh.ron', import.meta.url), 'utf8');
await drop('曲柄滑块.ron', zh);
const zhShown = async () => (await state()).scene_name === '对心曲柄滑块机构';
await until(async () => (await zhShown()) || (await asking()), poke);
if (await asking()) await answer('Drop the edits and open');
if (!(await until(zhShown, poke))) fail(`the Chinese scene did not open: ${(await state()).scene_name}`);
if (!(await until(async () => (await fontRequests()).length > 0, poke))) fail('the Chinese face was not fetched for a scene named in Chinese');
out.chinese_font = await fontRequests();
if (process.env.LINKAGE_SHOTS) {
  await quiet(page); // the frames after the face arrived
  await page.screenshot({ path: `${process.env.LINKAGE_SHOTS}/chinese_names_${build}.png` });
}
// A link that asks for Chinese: the app speaks it, and the address keeps asking.
await go(`scene=${slider.key}&lang=zh-CN`);
if (!(await until(async () => (await state()).language === 'zh-CN' && (await showing(slider)), poke))) {
  fail(`a link with lang=zh-CN did not switch the language: ${(await state()).language}, ${(await state()).scene_name}`);
}
if (!(await until(async () => (await page.evaluate(() => location.hash)).endsWith('&lang=zh-CN'), poke))) {
  fail(`the address dropped the language: ${await page.evaluate(() => location.hash)}`);
}
out.language_from_link = (await state()).language;
if (process.env.LINKAGE_SHOTS) {
  await quiet(page);
  await page.screenshot({ path: `${process.env.LINKAGE_SHOTS}/chinese_ui_${build}.png` });
}

if (errors.length) fail(`console errors:\n  ${errors.join('\n  ')}`);
out.console_errors = errors.length;
console.log(JSON.stringify(out));
await browser.close();
