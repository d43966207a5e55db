// Sheet mode, sheets of several sizes (issue 16 item 6, "a list"), in Debian's headless chromium as an
// operator uses it: one 450 × 180 sheet and, added below it, three 250 × 150 ones; five plates fill the
// big sheet (two) and then the small ones (one each). A size typed wrong is named with its row; each
// sheet is drawn, exported and cut at its own size; the nest saved and opened again brings the list back.
//
//   node --test tests/browser/nest-sizes.test.mjs

import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { test } from 'node:test';
import { pagePerFile, sheetVerbs } from './harness.mjs';
import { nestAndWait } from './helpers.mjs';

const PLATE = 'seed000-plate-6-holes.dxf'; // 200 × 120, six holes (../shared/fixtures/EXPECTED.md)

let app;
let page;

pagePerFile((opened) => {
  app = opened;
  page = opened.page;
});

const { loadParts, text, ready } = sheetVerbs(() => page);

/** The X and Y words of a program's moves, read here (not by kerfcam): [minX, minY, maxX, maxY]. */
function extent(ngc) {
  const box = [Infinity, Infinity, -Infinity, -Infinity];
  for (const line of ngc.split(/\r?\n/)) {
    const code = line.replace(/\(.*?\)|;.*$/g, '');
    const x = /X(-?[\d.]+)/.exec(code);
    const y = /Y(-?[\d.]+)/.exec(code);
    if (x) [box[0], box[2]] = [Math.min(box[0], +x[1]), Math.max(box[2], +x[1])];
    if (y) [box[1], box[3]] = [Math.min(box[1], +y[1]), Math.max(box[3], +y[1])];
  }
  return box;
}

test('a list of sheet sizes: filled in order, each sheet drawn and cut at its size, kept in the nest file', async () => {
  // 450 × 180 less the default 5 mm margin holds two plates side by side; 250 × 150 holds one.
  await loadParts({ [PLATE]: 5 }, { sheet: [450, 180], time: 3 });
  await page.fill('#sheet-count', '1');
  await page.click('#sheet-size-add');
  assert.equal(await page.evaluate(() => document.activeElement.id), 'sheet-size-1-width', 'the new row is focused');
  await page.fill('#sheet-size-1-width', '250');
  await page.fill('#sheet-size-1-height', 'abc');
  await page.fill('#sheet-size-1-count', '3');

  // A size typed wrong: nothing runs, and the message names the row and the field.
  await page.click('#nest-run');
  await page.waitForSelector('#nest-message:not([hidden])');
  assert.match(await text('#nest-message'), /Size 2: Height/);
  assert.equal(await page.$eval('#sheet-size-1-height', (e) => e.getAttribute('aria-invalid')), 'true');
  await page.fill('#sheet-size-1-height', '150');

  await nestAndWait(page);
  await ready();
  const n = await page.evaluate(() => window.kerfcam.lastNest);
  assert.equal(n.placed, 5);
  assert.deepEqual(n.sheets.map((s) => [s.width, s.height, s.parts]), [[450, 180, 2], [250, 150, 1], [250, 150, 1], [250, 150, 1]]);
  assert.equal(await page.$$eval('#nest-tabs [role="tab"]', (l) => l.length), 4);

  // Sheet 3 drawn at its own size, and its program cuts inside 250 × 150.
  await page.click('#nest-tab-2');
  await page.waitForFunction(() => document.querySelector('#nest-canvas svg')?.dataset.sheet === '2');
  await ready();
  const rect = await page.$eval('#nest-canvas svg .nest-sheet', (e) => [e.getAttribute('width'), e.getAttribute('height')]);
  assert.deepEqual(rect, ['250', '150']);
  const [dl] = await Promise.all([page.waitForEvent('download'), page.click('#download')]);
  const file = path.join(app.downloadDir, 'sheet3.ngc');
  await dl.saveAs(file);
  const [x0, y0, x1, y1] = extent(fs.readFileSync(file, 'utf8'));
  assert.ok(x0 >= -5 && y0 >= -5 && x1 <= 255 && y1 <= 155, `sheet 3's moves inside 250 × 150: ${[x0, y0, x1, y1]}`);
  assert.ok(x1 - x0 > 150, 'a plate is cut on it');

  // Saved and opened again: the second size is back in its row, and the same nest is drawn.
  const [saved] = await Promise.all([page.waitForEvent('download'), page.click('#nest-save')]);
  const nestFile = path.join(app.downloadDir, 'sizes.kerfcam-nest.json');
  await saved.saveAs(nestFile);
  assert.deepEqual(JSON.parse(fs.readFileSync(nestFile, 'utf8')).settings.sheet_list,
    [{ width: 450, height: 180, count: 1 }, { width: 250, height: 150, count: 3 }]);
  await page.click('#sheet-size-add');
  await page.fill('#sheet-size-2-width', '999');
  await page.evaluate(() => (window.kerfcam.lastNest = null));
  await page.setInputFiles('#nest-open-input', nestFile);
  await page.waitForFunction(() => window.kerfcam.lastNest !== null, null, { timeout: 30_000 });
  await ready();
  assert.equal(await page.$$eval('#sheet-sizes li', (l) => l.length), 1, 'the file\'s list, not what was typed since');
  // Width, height, sheets, and the cost left blank (no costs: the sheets filled in order).
  assert.deepEqual(await page.$$eval('#sheet-sizes li input', (l) => l.map((e) => e.value)), ['250', '150', '3', '']);
  const back = await page.evaluate(() => window.kerfcam.lastNest);
  assert.deepEqual(back.flat, n.flat);
  assert.deepEqual(app.pageErrors, []);
});
