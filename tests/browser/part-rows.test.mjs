// Sheet mode, parts as rows (issue 42 §1), in Debian's headless chromium as an operator uses it: a drawing
// of three different parts lists each with its picture, size and holes and its own quantity; the nest
// places exactly the copies asked of each (0 leaves a part out); the file's fields set every part at once;
// the same file dropped again adds one of each part instead of a new row; a drawing whose outline is open
// around its slots says, on its row, that its holes are listed as parts.
//
//   node --test tests/browser/part-rows.test.mjs

import assert from 'node:assert/strict';
import { test } from 'node:test';
import { pagePerFile, partRow, sheetVerbs } from './harness.mjs';
import { nestAndWait } from './helpers.mjs';

let app;
let page;

pagePerFile((opened) => {
  app = opened;
  page = opened.page;
});

const { dropBytes, text, nest } = sheetVerbs(() => page);
const PER = 7; // numbers per copy in lastNest.flat: part, copy, sheet, rotation, mirror, x, y

/** A DXF in mm of closed LWPOLYLINEs (`closed` false: the first one open). */
function dxf(loops, closed = true) {
  const out = ['0', 'SECTION', '2', 'HEADER', '9', '$INSUNITS', '70', '4', '0', 'ENDSEC', '0', 'SECTION', '2', 'ENTITIES'];
  loops.forEach((pts, i) => {
    out.push('0', 'LWPOLYLINE', '8', '0', '90', pts.length, '70', closed || i > 0 ? 1 : 0);
    for (const [x, y] of pts) out.push('10', x, '20', y);
  });
  out.push('0', 'ENDSEC', '0', 'EOF');
  return `${out.join('\n')}\n`;
}
const rect = (x, y, w, h) => [[x, y], [x + w, y], [x + w, y + h], [x, y + h]];

// Three different parts: 60 × 30, 40 × 40 with a 10 × 10 hole, 20 × 10.
const THREE = dxf([rect(0, 0, 60, 30), rect(100, 0, 40, 40), rect(115, 15, 10, 10), rect(200, 0, 20, 10)]);

test('each part of a drawing is its own row, and the nest places what each row asks', async () => {
  await page.click('#mode-sheet');
  await dropBytes('three.dxf', THREE);
  const row = partRow('three.dxf');
  await page.waitForSelector(`${row} .part-item`);
  const items = await page.$$eval(`${row} .part-item`, (l) => l.map((li) => ({
    name: li.dataset.part, text: li.textContent, thumb: !!li.querySelector('svg.part-thumb path[d^="M"]'),
  })));
  assert.deepEqual(items.map((i) => i.name), ['three#1', 'three#2', 'three#3']);
  assert.ok(items.every((i) => i.thumb), 'every row has its picture');
  assert.match(items[0].text, /60\.0 × 30\.0 mm · 18\.0 cm² · 0 holes/);
  assert.match(items[1].text, /40\.0 × 40\.0 mm · 15\.0 cm² · 1 hole(?!s)/);

  // Each part's own quantity: 2, 0 (left out), 5.
  const qty = (i) => `${row} .part-item:nth-child(${i}) input.qty`;
  await page.fill(qty(1), '2');
  await page.fill(qty(2), '0');
  await page.fill(qty(3), '5');
  await page.fill('#sheet-w', '300');
  await page.fill('#sheet-h', '200');
  await page.fill('#nest-time', '0');
  await nestAndWait(page);
  const n = await nest();
  const per = new Map();
  for (let k = 0; k < n.flat.length; k += PER) {
    const name = n.parts?.[n.flat[k]] ?? n.flat[k];
    per.set(name, (per.get(name) || 0) + 1);
  }
  assert.equal(n.placed, 7, JSON.stringify(n.unplaced));
  assert.deepEqual([...per.values()].sort((a, b) => a - b), [2, 5], `copies per part: ${JSON.stringify([...per])}`);

  // A quantity out of range is said at the field, and no nest starts on it.
  await page.fill(qty(3), '-1');
  assert.equal(await page.getAttribute(qty(3), 'aria-invalid'), 'true');
  assert.match(await text(`${row} .part-item:nth-child(3)`), /Quantity of three#3: enter a whole number from 0 to 10000/);

  // The file's quantity sets every part's.
  await page.fill(`${row} > .part-fields input.qty`, '4');
  assert.deepEqual(await page.$$eval(`${row} .part-item input.qty`, (l) => l.map((i) => i.value)), ['4', '4', '4']);

  // The same file again: one more of each, no second row.
  await dropBytes('three-again.dxf', THREE);
  await page.waitForFunction(() => /already in the list/.test(document.getElementById('parts-message').textContent));
  assert.equal(await page.$$eval('#parts li.part', (l) => l.length), 1);
  assert.deepEqual(await page.$$eval(`${row} .part-item input.qty`, (l) => l.map((i) => i.value)), ['5', '5', '5']);
});

test('an outline left open around its slots is said on the file row', async () => {
  const loops = [[[0, 0], [300, 0], [300, 200], [0, 200]]];
  for (let k = 0; k < 5; k++) loops.push(rect(20 + 50 * k, 50, 10, 100));
  await dropBytes('grille.dxf', dxf(loops, false));
  const row = partRow('grille.dxf');
  await page.waitForSelector(`${row} .part-item`);
  assert.equal(await page.$$eval(`${row} .part-item`, (l) => l.length), 5);
  assert.match(await text(row), /1 open contour\(s\) beside 5 part\(s\): if a part's outline is one of them, its holes are listed as parts/);
});
