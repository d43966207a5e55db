// Labels on the nested parts (issue 42 §2), in Debian's headless chromium as an operator uses them: a plate
// with holes × 4 nested on 1000 × 500 with labels on (short codes): every copy with room carries its label in
// the nest view and on the cut preview (the job sheet's map), drawn from the engine's strokes; scribing them puts marks before the cuts in the program,
// which rs274 reads; the nest DXF carries them on layer LABELS; a bad height is said at its field and the
// last good labels are kept.
//
//   node --test tests/browser/labels.test.mjs

import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { test } from 'node:test';
import { assertRs274Accepts, pagePerFile, sheetVerbs } from './harness.mjs';

const PLATE = 'seed000-plate-6-holes.dxf';

let app;
let page;

pagePerFile((opened) => {
  app = opened;
  page = opened.page;
});

const { loadParts, nest, ready } = sheetVerbs(() => page);

test('labels are drawn on the nest, scribed before the cuts when asked, and kept when a field is bad', async () => {
  await loadParts({ [PLATE]: 4 }, { sheet: [1000, 500], time: 0 });
  await page.check('#labels-on');
  await page.selectOption('#labels-naming', 'code');
  await page.evaluate(() => (window.kerfcam.lastNest = null));
  await page.click('#nest-run');
  await page.waitForFunction(() => window.kerfcam.lastNest !== null, null, { timeout: 60_000 });
  await ready();
  const n = await nest();
  assert.equal(n.placed, 4);
  assert.ok(n.labels, 'the nest state carries its labels');
  assert.equal(n.labels.labels.length + n.labels.left_out.length, 4);
  assert.ok(n.labels.labels.length > 0, 'the plate has room for a short code');
  const drawn = await page.$$eval('#nest-canvas .nest-label', (l) => l.map((p) => p.dataset.label));
  assert.deepEqual(drawn.sort(), n.labels.labels.filter((l) => l.sheet === 0).map((l) => l.text).sort());
  assert.ok(drawn.every((t) => /^A\d$/.test(t)), drawn.join());
  const plain = await page.evaluate(() => window.kerfcam.lastGcode);
  // On the cut preview's overlay too (the job sheet's map is that picture): red where the strokes run.
  const onPreview = (l) => {
    const c = document.getElementById('overlay');
    const ctx = c.getContext('2d');
    const dpr = c.width / c.clientWidth;
    let hits = 0;
    for (const p of l.strokes) {
      for (let j = 0; j + 3 < p.length; j += 2) {
        const at = window.kerfcam.screenOf((p[j] + p[j + 2]) / 2, (p[j + 1] + p[j + 3]) / 2);
        if (!at) continue;
        const d = ctx.getImageData(Math.round(at[0] * dpr), Math.round(at[1] * dpr), 1, 1).data;
        if (d[3] > 0 && d[0] > d[1] + 40 && d[0] > d[2] + 40) hits++;
      }
    }
    return hits > 0;
  };
  await page.waitForFunction(onPreview, n.labels.labels.find((l) => l.sheet === 0), { timeout: 10_000 });

  // Scribed: marks before the first cut, the program read by rs274.
  await page.evaluate(() => (window.kerfcam.lastReport = null));
  await page.check('#labels-mark');
  await ready();
  const gcode = await page.evaluate(() => window.kerfcam.lastGcode);
  assert.notEqual(gcode, plain);
  const marks = gcode.split('\n').filter((l) => /mark/.test(l)).length;
  assert.ok(marks >= n.labels.labels.length, `${marks} marks`);
  const [download] = await Promise.all([page.waitForEvent('download'), page.click('#download')]);
  const file = path.join(app.downloadDir, download.suggestedFilename());
  await download.saveAs(file);
  assert.equal(fs.readFileSync(file, 'utf8'), gcode);
  assertRs274Accepts(file);

  // A height that is not a number: said at its field, the labels kept as they were.
  await page.fill('#label-height-min', 'abc');
  await page.dispatchEvent('#label-height-min', 'change');
  assert.equal(await page.getAttribute('#label-height-min', 'aria-invalid'), 'true');
  assert.equal(await page.isVisible('#labels-message'), true);
  assert.equal(await page.$$eval('#nest-canvas .nest-label', (l) => l.length), drawn.length);
  assert.deepEqual(app.pageErrors, []);
});
