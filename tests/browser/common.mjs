// What both browser scripts share: Debian's Chromium launched headless on WebGL2, and
// the pixel measures they judge screenshots by.
import { chromium } from 'playwright-core';
import { PNG } from 'pngjs';

/** Debian's Chromium, headless, rendering WebGL2 through SwiftShader (headless WebGPU
 * screenshots come out blank here). */
export function launchChromium() {
  return chromium.launch({
    executablePath: '/usr/bin/chromium',
    headless: true,
    args: ['--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
      '--disable-background-networking', '--disable-component-update', '--disable-sync',
      '--use-angle=swiftshader', '--enable-unsafe-swiftshader'],
  });
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
