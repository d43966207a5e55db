// The verification's heat map (issue 20 §9) in Debian's headless chromium: with "Check the cut" on,
// a drawing whose parts stand closer than the kerf (the torch eats into the neighbour, as nests
// exported with zero spacing do) shows overcut squares over the preview, as many as the report's
// area says; the same parts far apart show none; a switch hides it.
//
//   node --test tests/browser/verify-heat.test.mjs

import assert from 'node:assert/strict';
import { after, before, test } from 'node:test';
import { openApp, untilReady } from './harness.mjs';

let app;
let page;

before(async () => {
  app = await openApp();
  page = app.page;
});

after(async () => {
  await app?.close();
});

/** Two 40 × 30 squares `gap` mm apart, in mm. */
function twoSquares(gap) {
  const out = ['0', 'SECTION', '2', 'HEADER', '9', '$INSUNITS', '70', '4', '0', 'ENDSEC', '0', 'SECTION', '2', 'ENTITIES'];
  for (const x0 of [0, 40 + gap]) {
    const p = [[x0, 0], [x0 + 40, 0], [x0 + 40, 30], [x0, 30], [x0, 0]];
    for (let i = 0; i < 4; i++) out.push('0', 'LINE', '8', '0', '10', p[i][0], '20', p[i][1], '11', p[i + 1][0], '21', p[i + 1][1]);
  }
  out.push('0', 'ENDSEC', '0', 'EOF');
  return { name: `two-squares-${gap}.dxf`, mimeType: 'application/dxf', buffer: Buffer.from(out.join('\n') + '\n') };
}

/** Overlay pixels of the heat map's colour (255, 0, 110 at any strength), and of its "not freed" violet. */
function heatPixels() {
  return page.evaluate(() => {
    const c = document.getElementById('overlay');
    const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
    let overcut = 0;
    let attached = 0;
    for (let i = 0; i < d.length; i += 4) {
      if (d[i + 3] === 0) continue;
      if (d[i] > 200 && d[i + 1] < 40 && d[i + 2] > 80 && d[i + 2] < 140) overcut++;
      if (d[i] > 90 && d[i] < 120 && d[i + 1] < 20 && d[i + 2] > 220) attached++;
    }
    return { overcut, attached };
  });
}

test('parts closer than the kerf show overcut on the preview; parts apart show none', async () => {
  await untilReady(page, () => page.setInputFiles('#file-input', twoSquares(0.5)));
  // Before the check, the closeness check's marks are on the preview (issue 45 §3, losses.test.mjs), not the sweep's.
  assert.equal(await page.evaluate(() => window.kerfcam.heat()), null, 'no sweep before the check is asked for');
  assert.equal(await page.isChecked('#verify-heat'), true, 'shown by default');
  await untilReady(page, () => page.check('#verify'));
  const report = await page.evaluate(() => window.kerfcam.lastReport);
  assert.ok(report.verification.overcut_mm2 > 0, JSON.stringify(report.verification));
  const near = await heatPixels();
  assert.ok(near.overcut > 20, `overcut pixels: ${near.overcut}`);
  assert.equal(await page.isVisible('#legend-overcut'), true);
  // The squares drawn are the report's cells: their area is the report's.
  const area = await page.evaluate(() => {
    const h = window.kerfcam.heat();
    return h ? ((h.squares.length - 1) / 3) * h.squares[0] ** 2 : 0;
  });
  assert.ok(Math.abs(area - report.verification.overcut_mm2) < 1e-6, `${area} vs ${report.verification.overcut_mm2}`);
  // Hidden by its switch, without a new run.
  await page.uncheck('#verify-heat');
  assert.equal((await heatPixels()).overcut, 0);
  assert.equal(await page.isVisible('#legend-overcut'), false);
  await page.check('#verify-heat');
  // The same squares 20 mm apart: a correct cut, nothing drawn.
  await untilReady(page, () => page.setInputFiles('#file-input', twoSquares(20)));
  const apart = await page.evaluate(() => window.kerfcam.lastReport.verification);
  assert.equal(apart.overcut_mm2, 0);
  assert.deepEqual(await heatPixels(), { overcut: 0, attached: 0 });
  assert.equal(await page.isVisible('#legend-overcut'), false);
  await untilReady(page, () => page.uncheck('#verify'));
  assert.deepEqual(app.pageErrors, []);
});
