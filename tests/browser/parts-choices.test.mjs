// Sheet mode, the parts list's choices (issue 18 item 1), in Debian's headless chromium as an operator
// uses them: a grain lock on a part that fits the sheet only turned by 90° leaves it out with the reason
// (unlocked, the engine turns it), a locked part is never turned but by 180° in a nest nor by R; a file
// with no units in its header is read as mm with a warning and one click on "inch" reads it at 25.4×,
// which the nest then uses (the used length is the inch part's).
// (A drawing under 10 units a side with no units is taken as inches already: src/dxf/units.rs.)
//
//   node --test tests/browser/parts-choices.test.mjs

import assert from 'node:assert/strict';
import { test } from 'node:test';
import { pagePerFile, partRow, sheetVerbs } from './harness.mjs';
import { nestAndWait } from './helpers.mjs';

const PLATE = 'seed000-plate-6-holes.dxf'; // 200 × 120 (../shared/fixtures/EXPECTED.md)

let app;
let page;

pagePerFile((opened) => {
  app = opened;
  page = opened.page;
});

const { dropBytes, drop, text, nest } = sheetVerbs(() => page);
const PER = 7; // numbers per copy in lastNest.flat: part, copy, sheet, rotation, mirror, x, y
const rotations = (n) => Array.from({ length: n.flat.length / PER }, (_, i) => n.flat[i * PER + 3]);

/** A DXF with no header (no $INSUNITS): one rectangle of LINEs, x0..x1 × y0..y1 in the file's numbers. */
function unitless([x0, y0, x1, y1]) {
  const corners = [[x0, y0], [x1, y0], [x1, y1], [x0, y1]];
  const out = ['0', 'SECTION', '2', 'ENTITIES'];
  corners.forEach(([ax, ay], i) => {
    const [bx, by] = corners[(i + 1) % 4];
    out.push('0', 'LINE', '8', '0', '10', ax, '20', ay, '30', 0, '11', bx, '21', by, '31', 0);
  });
  out.push('0', 'ENDSEC', '0', 'EOF');
  return `${out.join('\n')}\n`;
}

async function sheet(w, h, time = '2') {
  await page.fill('#sheet-w', w);
  await page.fill('#sheet-h', h);
  await page.fill('#nest-margin', '10');
  await page.fill('#nest-time', time);
}

test('grain lock: a part is turned by 0° or 180° only, in the nest and by hand', async () => {
  await page.click('#mode-sheet');
  await drop(PLATE);
  await page.waitForSelector(`${partRow(PLATE)} [data-units]`);
  await page.fill(`${partRow(PLATE)} input.qty`, '2');
  // 160 wide less the margins: the plate (200 × 120) fits only turned (120 × 200), twice up the sheet.
  await sheet('160', '460');
  await nestAndWait(page);
  const turned = await nest();
  assert.equal(turned.placed, 2, JSON.stringify(turned.unplaced));
  assert.ok(rotations(turned).every((r) => r === 90 || r === 270), `unlocked, it is turned: ${rotations(turned)}`);

  // Locked (by keyboard): the rotation menu offers none or 180° only, the help says why.
  await page.focus(`${partRow(PLATE)} input[id$="-grain"]`);
  await page.keyboard.press('Space');
  assert.equal(await page.isChecked(`${partRow(PLATE)} input[id$="-grain"]`), true);
  assert.deepEqual(await page.$$eval(`${partRow(PLATE)} select option`, (l) => l.map((o) => o.value)), ['none', '180']);
  assert.equal(await page.$eval(`${partRow(PLATE)} select`, (e) => e.value), '180');
  assert.match(await text(`${partRow(PLATE)} [id$="-grain-help"]`), /keeps the grain: turns by 180° only/);
  await page.waitForSelector('#nest-stale:not([hidden])');
  // Nothing placed, so no sheet to cut: wait for the nest alone.
  await page.evaluate(() => (window.kerfcam.lastNest = null));
  await page.click('#nest-run');
  await page.waitForFunction(() => window.kerfcam.lastNest !== null, null, { timeout: 60_000 });
  const locked = await nest();
  assert.equal(locked.placed, 0);
  assert.match(await text('#nest-unplaced'), /seed000-plate-6-holes: 2 copies: larger than the sheet 160 × 460 mm at every allowed rotation/);

  // On a sheet where it fits as drawn: placed, never turned but by 180°; R turns a copy by 180°.
  await page.fill(`${partRow(PLATE)} input.qty`, '6');
  await sheet('1000', '500');
  await nestAndWait(page);
  const n = await nest();
  assert.equal(n.placed, 6);
  assert.ok(rotations(n).every((r) => r === 0 || r === 180), `locked: ${rotations(n)}`);
  await page.selectOption('#nest-copy', '0');
  await page.focus('#nest-canvas svg');
  await page.keyboard.press('r');
  await page.waitForFunction((r) => window.kerfcam.lastNest.flat[3] !== r, n.flat[3]);
  assert.equal((await nest()).flat[3], (n.flat[3] + 180) % 360);
  // Unlocked again: 90° steps come back.
  await page.click(`${partRow(PLATE)} input[id$="-grain"]`);
  assert.deepEqual(await page.$$eval(`${partRow(PLATE)} select option`, (l) => l.map((o) => o.value)), ['none', '180', '90', 'free']);
  await page.click(`${partRow(PLATE)} button:text("Remove")`);
  assert.deepEqual(app.pageErrors, []);
});

test('units per file: a file without units is read as mm and flagged, one click reads it in inches', async () => {
  // A 30 × 15 in plate drawn with no units: 30 is a plausible mm size, so it is read as mm (and flagged).
  const NAME = 'plate-30x15in.dxf';
  await dropBytes(NAME, unitless([0, 0, 30, 15]));
  await page.waitForSelector(`${partRow(NAME)} [data-units]`);
  const units = `${partRow(NAME)} [data-units]`;
  assert.equal(await page.$eval(units, (e) => e.dataset.units), 'mm');
  assert.match(await text(units), /^units assumed: mm\. Check the size!/);
  assert.equal(await page.$eval(`${units} button[data-unit="mm"]`, (e) => e.getAttribute('aria-pressed')), 'true');
  await page.fill(`${partRow(NAME)} input.qty`, '1');
  await page.selectOption(`${partRow(NAME)} select`, 'none');
  await sheet('1000', '500');
  await nestAndWait(page);
  const asMm = await nest();
  assert.equal(asMm.placed, 1);
  assert.ok(Math.abs(asMm.sheets[0].used_length - (10 + 30)) < 1e-6, `read as mm: ${asMm.sheets[0].used_length}`);

  // Inches, by keyboard: the row says so, the nest is stale, and the next nest uses 762 × 381 mm.
  await page.focus(`${units} button[data-unit="in"]`);
  await page.keyboard.press('Enter');
  await page.waitForFunction((sel) => document.querySelector(sel)?.dataset.units === 'in', units);
  assert.match(await text(units), /^units: in \(chosen for this file\)/);
  assert.equal(await page.$eval(`${units} button[data-unit="in"]`, (e) => e.getAttribute('aria-pressed')), 'true');
  await page.waitForSelector('#nest-stale:not([hidden])');
  await nestAndWait(page);
  const asInch = await nest();
  assert.equal(asInch.placed, 1);
  assert.ok(Math.abs(asInch.sheets[0].used_length - (10 + 30 * 25.4)) < 1e-6, `read in inches: ${asInch.sheets[0].used_length}`);
  assert.deepEqual(app.pageErrors, []);
});
