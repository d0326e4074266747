// Pictures to look at, not a test: every shipped scene in Chinese in real headless
// Chromium, at a laptop's 1366x768 and a phone's 390x844, opened by its link with
// lang=zh-CN, written to $LINKAGE_SCREENS (default target/screens/browser). Fails
// only on a console error or a page that never draws.
// Usage: node screens_zh.mjs http://127.0.0.1:PORT/
import { mkdirSync, writeFileSync } from 'node:fs';
import { build, launchChromium, openApp, shippedScenes, until } from './common.mjs';

const base = (process.argv[2] ?? 'http://127.0.0.1:8917/').replace(/#.*$/, '');
const dir = process.env.LINKAGE_SCREENS ?? 'target/screens/browser';
mkdirSync(dir, { recursive: true });
const browser = await launchChromium();
for (const [w, h] of [[1366, 768], [390, 844]]) {
  for (const scene of shippedScenes()) {
    const context = await browser.newContext({ viewport: { width: w, height: h }, deviceScaleFactor: 1 });
    const page = await context.newPage();
    const errors = await openApp(page, `${base}#scene=${scene.key}&lang=zh-CN`);
    if (errors.length) {
      console.error(`FAIL: ${scene.key} ${w}x${h}: ${errors.join('; ')}`);
      process.exitCode = 1;
    }
    // The Chinese face arrives a few frames after the first: wait for it.
    await until(async () => (await page.evaluate(() => performance.getEntriesByType('resource')
      .filter((r) => r.name.includes('fonts/')).length)) > 0, async () => page.mouse.move(w / 2, h / 2));
    await page.waitForTimeout(1500);
    const file = `${dir}/${scene.key}_${w}x${h}_zh-CN_${build}.png`;
    writeFileSync(file, await page.screenshot());
    console.log(file);
    await context.close();
  }
}
await browser.close();
