// An exercise in the page, as a class meets it (desktop, 1366x768): the link
// `#exercise=die_cutter_slider&student=2026001` opens the desk with that student's
// variant; an answer typed in the page gives an answer code; thirty students' codes
// made in the page (the desk's own code, `linkage_lab_exercise_code`) from answers
// worked out from the teacher's key, half of them with one answer wrong, are graded
// by the command line (`linkage exercise grade`), and each student's dimensions in
// the page are the command line's to the last bit (`linkage exercise variants`).
// Usage: node exercise.mjs http://127.0.0.1:PORT/   (LINKAGE_CLI: the command line)
import { execFileSync } from 'node:child_process';
import { mkdtempSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { appState, launchChromium, openApp, settledControl, until } from './common.mjs';

const base = (process.argv[2] ?? 'http://127.0.0.1:8917/').replace(/#.*$/, '');
const fail = (msg) => { console.error(`FAIL: ${msg}`); process.exitCode = 1; };
const cli = process.env.LINKAGE_CLI ?? 'target/debug/linkage';
const exercise = new URL('../../assets/exercises/die_cutter_slider.ron', import.meta.url).pathname;
const dir = mkdtempSync(join(tmpdir(), 'linkage-exercise-'));
const students = Array.from({ length: 30 }, (_, i) => `2026${String(i + 1).padStart(3, '0')}`);
writeFileSync(join(dir, 'class.csv'), `student\n${students.join('\n')}\n`);

// The teacher's key: student, draws, AB, BC, crank speed, then the six truths.
const key = execFileSync(cli, ['exercise', 'variants', exercise, '--students', join(dir, 'class.csv')], { encoding: 'utf8' })
  .trim().split('\n').slice(1).map((l) => l.split(','));

const browser = await launchChromium();
const page = await browser.newPage({ viewport: { width: 1366, height: 768 }, deviceScaleFactor: 1 });
const errors = await openApp(page, `${base}#exercise=die_cutter_slider&student=2026001`);
let pokes = 0;
const poke = () => page.mouse.move(900 + (pokes++ % 2), 5);
const state = () => appState(page);

if (!(await until(async () => (await state()).exercise?.student === '2026001', poke))) {
  fail(`the link opened no desk for student 2026001: ${JSON.stringify((await state()).exercise)}`);
}
const shown = (await state()).exercise;
const first = key[0].slice(2, 5).map(Number);
if (JSON.stringify(shown?.values) !== JSON.stringify(first)) fail(`student 2026001 in the page ${shown?.values}, the key ${first}`);

// An answer typed into the first box, in mm/s: the code carries it in m/s.
const box = await settledControl(page, 'Exercise', 'answer 1', poke);
if (!box) fail('no answer box');
else {
  await page.mouse.click(0.5 * (box.rect[0] + box.rect[2]), 0.5 * (box.rect[1] + box.rect[3]));
  await page.keyboard.type('105 mm/s', { delay: 30 });
  const typed = await until(async () => (await state()).exercise?.code?.includes(':2026001:0.105/'), poke);
  if (!typed) fail(`the typed answer is not in the code: ${(await state()).exercise?.code}`);
}
await page.screenshot({ path: join(process.env.SCREENSHOT_DIR ?? dir, 'exercise_desk.png') });

// Thirty students: dimensions against the key, codes made in the page.
const codes = ['code'];
for (const [i, row] of key.entries()) {
  const [student] = row;
  const variant = JSON.parse(await page.evaluate(([k, s]) => window.wasmBindings.linkage_lab_exercise_variant(k, s), ['die_cutter_slider', student]));
  const expected = row.slice(2, 5).map(Number);
  if (JSON.stringify(variant.values) !== JSON.stringify(expected)) fail(`${student}: the page ${variant.values}, the command line ${expected}`);
  const truths = row.slice(5).map(Number);
  // Odd students give the acceleration 20 % too large; speeds typed in mm/s.
  const answers = truths.map((t, q) => (q === 1 && i % 2 === 1 ? `${t * 1.2}` : `${t}`));
  answers[0] = `${truths[0] * 1000} mm/s`;
  const code = await page.evaluate(([k, s, a]) => window.wasmBindings.linkage_lab_exercise_code(k, s, a), ['die_cutter_slider', student, answers.join('|')]);
  if (!code.startsWith('LX1:')) fail(`${student}: ${code}`);
  codes.push(code);
}
writeFileSync(join(dir, 'codes.csv'), `${codes.join('\n')}\n`);
const grades = execFileSync(cli, ['exercise', 'grade', exercise, '--answers', join(dir, 'codes.csv'), '--students', join(dir, 'class.csv')], { encoding: 'utf8' });
console.log('grades of 30 students from codes made in the page:');
console.log(grades.trim());
const header = grades.split('\n')[0].split(',');
const scoreAt = header.indexOf('score');
for (const [i, line] of grades.trim().split('\n').slice(1).entries()) {
  const score = Number(line.split(',')[scoreAt]);
  if (score !== (i % 2 === 1 ? 5 : 6)) fail(`${students[i]} scored ${score}: ${line}`);
}
for (const e of errors) fail(e);
await browser.close();
console.log(process.exitCode ? 'exercise: FAILED' : 'exercise: ok (30 students graded from codes made in the page)');
