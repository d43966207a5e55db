// A real greyed row (issue 42 §1 and its bad input), in Debian's headless chromium: a drawing with a plate and an
// outline the nester cannot place — a 20 × 10 rectangle whose right side is an arc of bulge −3, which sweeps back
// across it; the contour stage repairs it into a loop of 6.8 mm² whose collision polygon, grown by half the
// spacing, vanishes. Its row is greyed with the reason and left out of the nest; a quantity typed on it is said at
// the field, and the last good nest and quote are kept.
//
//   node --test tests/browser/greyed-row.test.mjs

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

/** The drawing, built here: the bowed outline, then a 60 × 40 plate. */
function drawing() {
  const out = ['0', 'SECTION', '2', 'HEADER', '9', '$INSUNITS', '70', '4', '0', 'ENDSEC', '0', 'SECTION', '2', 'ENTITIES'];
  out.push('0', 'LWPOLYLINE', '8', '0', '90', '4', '70', '1',
    '10', '0', '20', '0', '10', '20', '20', '0', '42', '-3', '10', '20', '20', '10', '10', '0', '20', '10');
  out.push('0', 'LWPOLYLINE', '8', '0', '90', '4', '70', '1',
    '10', '100', '20', '0', '10', '160', '20', '0', '10', '160', '20', '40', '10', '100', '20', '40');
  out.push('0', 'ENDSEC', '0', 'EOF');
  return `${out.join('\n')}\n`;
}

const PRICES = {
  currency: 'EUR', machine_per_hour: '90', per_pierce: '0.05', per_metre: '0.2', material_price: '40',
  setup_per_sheet: '10', markup_percent: '20',
};

test('a part the nester cannot place is greyed with its reason, left out, and takes no quantity', async () => {
  await page.click('#mode-sheet');
  await page.selectOption('#cost-material_unit', 'm2');
  for (const [field, value] of Object.entries(PRICES)) await page.fill(`#cost-${field}`, value);
  await dropBytes('bow.dxf', drawing());
  const row = partRow('bow.dxf');
  await page.waitForSelector(`${row} .part-item`);
  const items = await page.$$eval(`${row} .part-item`, (l) => l.map((li) => ({
    name: li.dataset.part, grey: li.classList.contains('not-part'), text: li.textContent, qty: li.querySelector('input.qty').value,
  })));
  assert.equal(items.length, 2, JSON.stringify(items));
  const grey = items.filter((i) => i.grey);
  assert.equal(grey.length, 1, JSON.stringify(items));
  assert.match(grey[0].text, /its outline encloses no area: not nestable/);
  assert.equal(grey[0].qty, '0');
  const good = items.find((i) => !i.grey);

  // Left out of the nest: the plate alone is placed.
  await page.fill('#sheet-w', '300');
  await page.fill('#sheet-h', '200');
  await page.fill('#nest-time', '0');
  await nestAndWait(page);
  const n = await nest();
  assert.equal(n.placed, 1, JSON.stringify(n.unplaced));
  assert.equal(n.flat[0], items.indexOf(good), 'the placed copy is the plate (parts in the file\'s order)');
  const q = await page.waitForFunction(() => window.kerfcam.quote?.()?.copies.length === 1 && window.kerfcam.quote())
    .then((h) => h.jsonValue());
  assert.deepEqual(q.parts.map((p) => p.name), [good.name]);

  // A quantity typed on the greyed row: said at its field; Nest starts nothing; the last nest and quote stay.
  const i = items.indexOf(grey[0]) + 1;
  const qty = `${row} .part-item:nth-child(${i}) input.qty`;
  await page.fill(qty, '2');
  assert.equal(await page.getAttribute(qty, 'aria-invalid'), 'true');
  const said = await text(`${row} .part-item:nth-child(${i}) .error-text`);
  assert.match(said, new RegExp(`Quantity of ${grey[0].name.replace('#', '#')}: 0 only, the nester cannot place it \\(its outline encloses no area`));
  const before = JSON.stringify(n.flat);
  await page.click('#nest-run');
  await page.waitForTimeout(1500);
  const after = await nest();
  assert.ok(after, 'the last nest is kept');
  assert.equal(JSON.stringify(after.flat), before);
  assert.equal((await page.evaluate(() => window.kerfcam.quote())).job.price, q.job.price);

  // Back to 0: nothing said.
  await page.fill(qty, '0');
  assert.equal(await page.getAttribute(qty, 'aria-invalid'), 'false');
  assert.deepEqual(app.pageErrors, []);
});

test('an open line beside a part is said as contours left out, not as copies missing, in both languages', async () => {
  const out = ['0', 'SECTION', '2', 'HEADER', '9', '$INSUNITS', '70', '4', '0', 'ENDSEC', '0', 'SECTION', '2', 'ENTITIES'];
  out.push('0', 'LWPOLYLINE', '8', '0', '90', '4', '70', '1',
    '10', '0', '20', '0', '10', '60', '20', '0', '10', '60', '20', '40', '10', '0', '20', '40');
  out.push('0', 'LINE', '8', '0', '10', '0', '20', '60', '11', '60', '21', '60');
  out.push('0', 'ENDSEC', '0', 'EOF');
  await dropBytes('plate-and-line.dxf', `${out.join('\n')}\n`);
  const row = partRow('plate-and-line.dxf');
  await page.waitForSelector(`${row} [data-units]`);
  await page.fill(`${row} input.qty`, '3');
  await nestAndWait(page);
  const n = await nest();
  const mine = n.unplaced.filter((u) => u.part.startsWith('plate-and-line'));
  assert.deepEqual(mine.map((u) => [u.copies, u.reason]), [[0, '1 open contour(s) left out: not nestable (an open outline encloses no part)']]);
  const line = async () => (await page.$$eval('#nest-unplaced li', (l) => l.map((e) => e.textContent))).find((s) => s.startsWith('plate-and-line'));
  assert.equal(await line(), 'plate-and-line: 1 open contour(s) left out: not nestable (an open outline encloses no part)');
  await page.selectOption('#lang', 'pt-BR');
  assert.equal(await line(), 'plate-and-line: 1 contorno(s) aberto(s) deixado(s) de fora: não pode(m) ser encaixado(s) (um contorno aberto não encerra peça)');
  await page.selectOption('#lang', 'en');
  assert.deepEqual(app.pageErrors, []);
});
