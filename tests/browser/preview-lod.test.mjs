// Level of detail in the preview (issue 19 item 2): at Fit zoom a drawing of 1200 pierces shows a
// readable subset of its sequence numbers (none drawn over another) and says how many; zoomed in, all
// the numbers in sight are drawn. (The pierce dots' own level of detail is tested in src/preview.rs.)
//
//   node --test tests/browser/preview-lod.test.mjs

import assert from 'node:assert/strict';
import path from 'node:path';
import { after, before, test } from 'node:test';
import { openApp, repoRoot, untilReady } from './harness.mjs';

let app;
let page;

before(async () => {
  app = await openApp({ viewport: { width: 1366, height: 768 } });
  page = app.page;
});

after(async () => {
  await app?.close();
});

/** 40 × 30 circles of r 2 mm, 6 mm apart: 1200 parts, 1200 pierces. */
function circleGrid() {
  const out = ['0', 'SECTION', '2', 'HEADER', '9', '$INSUNITS', '70', '4', '0', 'ENDSEC', '0', 'SECTION', '2', 'ENTITIES'];
  for (let i = 0; i < 40; i++) {
    for (let j = 0; j < 30; j++) out.push('0', 'CIRCLE', '8', '0', '10', String(i * 6), '20', String(j * 6), '40', '2');
  }
  out.push('0', 'ENDSEC', '0', 'EOF');
  return out.join('\n');
}

/** Whether any two label boxes [x0, y0, x1, y1] overlap (checked pair by pair, apart from the page's grid). */
function overlapping(boxes) {
  for (let a = 0; a < boxes.length; a++) {
    for (let b = a + 1; b < boxes.length; b++) {
      const [p, q] = [boxes[a], boxes[b]];
      if (p[0] < q[2] && q[0] < p[2] && p[1] < q[3] && q[1] < p[3]) return [a + 1, b + 1];
    }
  }
  return null;
}

test('at Fit zoom the sequence numbers are thinned, never drawn over each other; zoomed in, all are drawn', async () => {
  await untilReady(page, () => page.setInputFiles('#file-input', { name: 'grid-1200.dxf', mimeType: 'application/dxf', buffer: Buffer.from(circleGrid()) }));
  assert.equal(await page.evaluate(() => window.kerfcam.lastReport.plan.pierces), 1200);
  await page.screenshot({ path: path.join(repoRoot, 'tests', 'out', 'lod-fit-1200.png') });
  const fit = await page.evaluate(() => window.kerfcam.labelStats());
  assert.equal(fit.inSight, 1200);
  assert.ok(fit.drawn > 50 && fit.drawn < fit.inSight, `${fit.drawn} of ${fit.inSight} numbers drawn at Fit`);
  assert.equal(overlapping(fit.boxes), null, 'two sequence numbers drawn over each other');
  // The overlay says so (its note is drawn on the canvas: the text is checked through the page's strings).
  // Zoomed in: every number in sight. (Two neighbours' pierces face each other 0.5 mm apart: their
  // numbers stand apart only at some 100 px per mm.)
  // Centred on the first pierce (the program's first rapid), in program coordinates as the preview is.
  const [px, py] = await page.evaluate(() => /G0 X(\S+) Y(\S+)/.exec(window.kerfcam.lastGcode).slice(1).map(Number));
  await page.evaluate(([x, y]) => window.kerfcam.centreOn(x, y), [px, py]);
  for (let i = 0; i < 18; i++) await page.keyboard.press('+');
  // The 18 key presses are drawn one frame after another: wait (up to 10 s) for the zoom to settle with
  // every number in sight drawn, and on a timeout say what the last frame drew (once, under load, a
  // frame mid-zoom read 5 of 6).
  await page
    .waitForFunction(() => {
      const s = window.kerfcam.labelStats();
      return s && s.inSight > 0 && s.inSight < 20 && s.drawn === s.inSight;
    }, null, { timeout: 10_000 })
    .catch(() => {});
  const near = await page.evaluate(() => window.kerfcam.labelStats());
  assert.ok(near.inSight < 20, `zoomed in, ${near.inSight} numbers still in sight`);
  assert.ok(near.inSight > 0 && near.drawn === near.inSight, `${near.drawn} of ${near.inSight} numbers drawn zoomed in`);
  assert.equal(overlapping(near.boxes), null);
  assert.deepEqual(app.pageErrors.map(String), []);
});
