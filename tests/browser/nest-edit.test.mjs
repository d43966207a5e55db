// Sheet mode, the nest on its sheet (issue 18 items 3-5), in Debian's headless chromium as an operator
// uses it: two fixture parts × 5 and × 3 nested on 1000 × 500, the best nest drawn live while the search
// runs, then adjusted by hand: a copy dragged onto another turns both red, says why and blocks the
// program; Ctrl+Z undoes it and the program comes back, downloaded and read by rs274. A copy added and
// snapped against the nest, one removed; the crop line dragged right, the remnant saved as a DXF.
//
//   node --test tests/browser/nest-edit.test.mjs

import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { test } from 'node:test';
import { assertRs274Accepts, pagePerFile, partRow, sheetVerbs } from './harness.mjs';

const PLATE = 'seed000-plate-6-holes.dxf';
const CHAMFER = 'seed001-P51703.dxf';

let app;
let page;

pagePerFile((opened) => {
  app = opened;
  page = opened.page;
});

const { loadParts, text, nest, ready } = sheetVerbs(() => page);

/** A point of the screen where copy `i` is hit (its outline less its holes), found by probing its box. */
const hitPoint = (i) => page.evaluate((i) => {
  const p = document.querySelector(`.nest-copy[data-copy="${i}"]`);
  const r = p.getBoundingClientRect();
  for (let a = 1; a < 20; a++) {
    for (let b = 1; b < 20; b++) {
      const x = r.left + (r.width * a) / 20;
      const y = r.top + (r.height * b) / 20;
      if (document.elementFromPoint(x, y) === p) return { x, y };
    }
  }
  return null;
}, i);

/** Drags from one screen point to another in steps, as a hand does. */
async function drag(from, to) {
  await page.mouse.move(from.x, from.y);
  await page.mouse.down();
  for (let s = 1; s <= 5; s++) await page.mouse.move(from.x + ((to.x - from.x) * s) / 5, from.y + ((to.y - from.y) * s) / 5);
  await page.mouse.up();
}

test('the best nest is drawn live, then a copy dragged onto another blocks the program until undone', async () => {
  await loadParts({ [PLATE]: 5, [CHAMFER]: 3 }, { sheet: [1000, 500], time: 3 });

  // Every drawing of the sheet while the search runs: how many copies, and whether it was live.
  await page.evaluate(() => {
    window.liveDrawings = [];
    const box = document.getElementById('nest-canvas');
    new MutationObserver(() => {
      const svg = box.querySelector('svg');
      if (svg?.dataset.live === 'true') window.liveDrawings.push({ updates: Number(svg.dataset.updates), paths: svg.querySelectorAll('.nest-copy').length });
    }).observe(box, { subtree: true, attributes: true, attributeFilter: ['data-updates'] });
    window.kerfcam.lastNest = null;
  });
  await page.click('#nest-run');
  await page.waitForFunction(() => window.liveDrawings.length > 0, null, { timeout: 30_000 });
  assert.equal(await page.isVisible('#nest-view'), true, 'the sheet is shown while the search runs');
  await page.waitForFunction(() => window.kerfcam.lastNest !== null, null, { timeout: 60_000 });
  await ready();
  const live = await page.evaluate(() => window.liveDrawings);
  assert.ok(live.length >= 1 && live.every((d) => d.paths > 0 && d.paths <= 8), JSON.stringify(live));
  assert.deepEqual(live.map((d) => d.updates), live.map((_, i) => i + 1), 'each better nest drawn once');

  // The finished nest on the sheet: 8 copies, none in conflict, the program ready.
  const n0 = await nest();
  assert.equal(n0.placed, 8);
  assert.deepEqual(n0.conflicts, []);
  assert.equal(await page.$$eval('#nest-canvas .nest-copy', (l) => l.length), 8);
  assert.equal(await page.$eval('#nest-canvas svg', (e) => e.dataset.live), 'false');
  assert.match(await text('#nest-edit-message'), /keeps the spacing and the margin/);
  assert.match(await text('#nest-view-figures'), /Used length [\d.,]+ mm · utilisation [\d.]+ %/);
  assert.equal(await page.isEnabled('#download'), true);

  // Copy 1 dragged onto copy 0: both red, the reason listed, nothing to download.
  const [a, b] = [await hitPoint(0), await hitPoint(1)];
  assert.ok(a && b, 'both copies can be picked');
  await drag(b, a);
  await page.waitForFunction(() => Number(document.getElementById('nest-view').dataset.conflicts) >= 2);
  assert.ok(await page.$$eval('#nest-canvas .nest-copy.conflict', (l) => l.length) >= 2);
  assert.match(await text('#nest-conflicts'), /overlaps/);
  assert.match(await text('#nest-edit-message'), /break the rules: fix them \(or Undo\) to cut the sheet/);
  await page.waitForFunction(() => document.getElementById('download').disabled);
  assert.ok((await nest()).conflicts.length >= 2);
  assert.equal(await page.isVisible('#nest-view'), true);

  // Ctrl+Z: back as nested, the program cut again.
  await page.evaluate(() => (window.kerfcam.lastReport = null));
  await page.keyboard.press('Control+z');
  await page.waitForFunction(() => document.getElementById('nest-view').dataset.conflicts === '0');
  await ready();
  assert.equal(await page.isEnabled('#download'), true);
  assert.deepEqual((await nest()).flat, n0.flat);
  // Ctrl+Y brings the mistake back, Undo (the button) takes it away again.
  await page.keyboard.press('Control+y');
  await page.waitForFunction(() => Number(document.getElementById('nest-view').dataset.conflicts) >= 2);
  // The worker fails the undo once (as when Cancel restarts it mid-edit): said, the step kept, and the
  // next Undo works (a failed step used to stop every later edit without a word).
  await page.evaluate(() => {
    const edit = window.kerfcam.sheet.edit;
    const engine = edit.hooks.engine;
    edit.hooks.engine = () => ({
      call: () => {
        edit.hooks.engine = engine;
        return Promise.reject(new Error('worker gone'));
      },
    });
  });
  await page.click('#nest-undo');
  await page.waitForFunction(() => /The edit failed: worker gone/.test(document.getElementById('nest-edit-message').textContent));
  assert.ok(Number(await page.$eval('#nest-view', (e) => e.dataset.conflicts)) >= 2);
  assert.equal(await page.isEnabled('#nest-undo'), true);
  await page.evaluate(() => (window.kerfcam.lastReport = null));
  await page.click('#nest-undo');
  await page.waitForFunction(() => document.getElementById('nest-view').dataset.conflicts === '0');
  await ready();

  const [download] = await Promise.all([page.waitForEvent('download'), page.click('#download')]);
  const file = path.join(app.downloadDir, download.suggestedFilename());
  await download.saveAs(file);
  const gcode = fs.readFileSync(file, 'utf8');
  assert.equal(gcode, await page.evaluate(() => window.kerfcam.lastGcode));
  assertRs274Accepts(file);
  assert.deepEqual(app.pageErrors, []);
});

test('by keyboard: a copy nudged, added and snapped at the spacing, removed; the program follows', async () => {
  const n0 = await nest();
  // Pick copy 2 from the menu, nudge it up 10 mm with Shift+ArrowUp on the sheet, and back down by 1 mm steps.
  await page.selectOption('#nest-copy', '2');
  await page.focus('#nest-canvas svg');
  const y0 = n0.flat[2 * 7 + 6];
  await page.keyboard.press('Shift+ArrowUp');
  await page.waitForFunction((y) => window.kerfcam.lastNest.flat[2 * 7 + 6] !== y, y0);
  assert.ok(Math.abs((await nest()).flat[2 * 7 + 6] - (y0 + 10)) < 1e-9);
  for (let k = 0; k < 10; k++) await page.keyboard.press('ArrowDown');
  await page.waitForFunction((y) => Math.abs(window.kerfcam.lastNest.flat[2 * 7 + 6] - y) < 1e-9, y0);
  assert.deepEqual((await nest()).conflicts, []);
  // Added: a ninth copy of the plate beyond the nest (butted against it where the nest reaches the sheet's
  // margin, so Snap could not move it), taken 50 mm further right by keyboard, then snapped left and down
  // against the nest.
  await page.selectOption('#nest-add-part', { label: 'seed000-plate-6-holes' });
  await page.click('#nest-add');
  await page.waitForFunction(() => window.kerfcam.lastNest.placed === 9);
  const beyond = (await nest()).flat[8 * 7 + 5];
  await page.focus('#nest-canvas svg');
  for (let k = 0; k < 5; k++) await page.keyboard.press('Shift+ArrowRight');
  await page.waitForFunction((x) => Math.abs(window.kerfcam.lastNest.flat[8 * 7 + 5] - x) < 1e-9, beyond + 50);
  const added = (await nest()).flat.slice(8 * 7);
  await page.click('#nest-snap');
  await page.waitForFunction((x) => window.kerfcam.lastNest.flat[8 * 7 + 5] !== x, added[5]);
  const n1 = await nest();
  assert.ok(n1.flat[8 * 7 + 5] < added[5], 'snapped to the left');
  assert.deepEqual(n1.conflicts, [], 'butted at the spacing, not into the nest');
  assert.match(await text('#nest-figures [data-key="placed"]'), /^9 of 8$/);
  // Snapped again it stays, and says why (no undo step for nothing).
  const undoSteps = await page.evaluate(() => window.kerfcam.sheet.edit.undo.length);
  await page.click('#nest-snap');
  await page.waitForFunction(() => /did not move: Snap slides a copy only through free places/.test(document.getElementById('nest-edit-message').textContent));
  assert.equal(await page.evaluate(() => window.kerfcam.sheet.edit.undo.length), undoSteps);
  assert.deepEqual((await nest()).flat, n1.flat);
  await ready();
  assert.equal((await page.evaluate(() => window.kerfcam.lastReport)).plan.parts, 9, 'the program cuts the copy added');
  // R turns it a quarter (the plate turns in 90° steps), Delete removes it.
  await page.focus('#nest-canvas svg');
  await page.keyboard.press('r');
  await page.waitForFunction(() => window.kerfcam.lastNest.flat[8 * 7 + 3] === 90);
  await page.keyboard.press('Delete');
  await page.waitForFunction(() => window.kerfcam.lastNest.placed === 8);
  await ready();
  assert.equal((await page.evaluate(() => window.kerfcam.lastReport)).plan.parts, 8);
  assert.deepEqual(app.pageErrors, []);
});

test('the crop line dragged right: the remnant shrinks, is saved as a DXF and the program crops there', async () => {
  const n0 = await nest();
  const x0 = n0.sheets[0].crop_x;
  assert.ok(Number.isFinite(x0), 'a remnant is kept after the nest');
  const [lo, hi] = n0.crop_range;
  const grip = await page.$eval('#nest-canvas .nest-crop-grip', (e) => {
    const r = e.getBoundingClientRect();
    return { x: r.left + r.width / 2, y: r.top + r.height / 2 };
  });
  const scale = await page.$eval('#nest-canvas svg > g', (g) => g.getScreenCTM().a); // px per mm
  await page.evaluate(() => (window.kerfcam.lastReport = null));
  await drag(grip, { x: grip.x + 100 * scale, y: grip.y });
  await page.waitForFunction((x) => window.kerfcam.lastNest.sheets[0].crop_x !== x, x0);
  const n1 = await nest();
  const x1 = n1.sheets[0].crop_x;
  assert.ok(Math.abs(x1 - Math.min(hi, x0 + 100)) < 2, `${x0} → ${x1}`);
  assert.ok(n1.sheets[0].utilisation < n0.sheets[0].utilisation, 'less remnant kept: less of the sheet is counted as used well');
  assert.ok(Math.abs(n1.remnant_area - (1000 - x1) * 500) < 1e-6, String(n1.remnant_area));
  assert.match(await text('#nest-view-figures'), new RegExp(`remnant ${((1000 - x1) * 500 / 1e6).toFixed(3)} m² beyond x = `));
  // Never into the parts: typed left of them, the line stops at the last part plus the margin.
  await page.fill('#nest-crop', String(lo - 50));
  await page.press('#nest-crop', 'Enter');
  await page.waitForFunction((x) => window.kerfcam.lastNest.sheets[0].crop_x !== x, x1);
  assert.ok(Math.abs((await nest()).sheets[0].crop_x - lo) < 1e-9);
  await ready(); // the sheet cut for the line at the parts, before the line goes back (no run in flight)
  await page.evaluate(() => (window.kerfcam.lastReport = null));
  await page.fill('#nest-crop', String(x1));
  await page.press('#nest-crop', 'Enter');
  await page.waitForFunction((x) => window.kerfcam.lastNest.sheets[0].crop_x === x, x1);
  await ready();
  // The program's crop cut is where the line is (once the sheet is cut again).
  await page.waitForFunction((x) => [...(window.kerfcam.lastGcode || '').matchAll(/X(-?[\d.]+)/g)].some((m) => Math.abs(Number(m[1]) - x) < 0.01), x1);
  const gcode = await page.evaluate(() => window.kerfcam.lastGcode);
  const xs = [...gcode.matchAll(/X(-?[\d.]+)/g)].map((m) => Number(m[1]));
  assert.ok(xs.some((x) => Math.abs(x - x1) < 0.01), `crop at ${x1}: ${xs.filter((x) => x > x1 - 100).join(' ')}`);
  assert.ok(!xs.some((x) => Math.abs(x - x0) < 0.01), `no crop left at ${x0}`);
  // Save remnant: the piece beyond the line as a sheet DXF.
  const [download] = await Promise.all([page.waitForEvent('download'), page.click('#nest-save-remnant')]);
  assert.equal(download.suggestedFilename(), 'nest-remnant.dxf');
  const file = path.join(app.downloadDir, 'nest-remnant.dxf');
  await download.saveAs(file);
  const dxf = fs.readFileSync(file, 'utf8');
  assert.match(dxf, /\nSHEET\n/);
  assert.ok(dxf.includes(`10\n${x1}\n`), 'the remnant starts at the crop line');
  assert.deepEqual(app.pageErrors, []);
});

test('the remnant saved reopens as the sheet and is nested again; a sheet DXF with no closed outline is refused', async () => {
  const file = path.join(app.downloadDir, 'nest-remnant.dxf'); // saved by the test before
  const crop = (await nest()).sheets[0].crop_x;
  await page.setInputFiles('#sheet-dxf-input', file);
  assert.match(await text('#sheet-dxf-name'), /sheet: nest-remnant\.dxf/);
  assert.equal(await page.isDisabled('#sheet-w'), true, 'the remnant has its own size');
  await page.fill(`${partRow(PLATE)} input.qty`, '2');
  await page.fill(`${partRow(CHAMFER)} input.qty`, '1');
  await page.fill('#nest-time', '0');
  await page.evaluate(() => (window.kerfcam.lastNest = null));
  await page.click('#nest-run');
  await page.waitForFunction(() => window.kerfcam.lastNest !== null, null, { timeout: 60_000 });
  await ready();
  const n = await nest();
  assert.equal(n.placed, 3, JSON.stringify(n.unplaced));
  assert.deepEqual(n.conflicts, []);
  assert.equal(n.sheet_shape.kind, 'remnant');
  assert.ok(Math.abs(n.sheet_shape.box[0] - crop) < 1e-6, 'the remnant lies where it was cut off');
  // Every copy drawn on the remnant: none reaches left of its edge (where the crop line was).
  const lefts = await page.evaluate(() => {
    const sheet = document.querySelector('#nest-canvas path.nest-sheet').getBoundingClientRect();
    return [...document.querySelectorAll('#nest-canvas .nest-copy')].map((c) => c.getBoundingClientRect().left - sheet.left);
  });
  assert.ok(lefts.every((d) => d > 0), lefts.join(' '));
  assert.equal(await page.$$eval('#nest-canvas .nest-copy', (l) => l.length), 3);
  assert.equal(await page.$eval('#nest-canvas path.nest-sheet', (e) => e.getAttribute('d').startsWith('M')), true);
  // Its program, through rs274.
  const [download] = await Promise.all([page.waitForEvent('download'), page.click('#download')]);
  const prog = path.join(app.downloadDir, 'remnant-sheet.ngc');
  await download.saveAs(prog);
  assert.equal(fs.readFileSync(prog, 'utf8'), await page.evaluate(() => window.kerfcam.lastGcode));
  assertRs274Accepts(prog);

  // A "sheet" drawn as one open line: refused with the reason, nothing nested.
  const open = path.join(app.downloadDir, 'open-line.dxf');
  fs.writeFileSync(open, '0\nSECTION\n2\nENTITIES\n0\nLINE\n8\n0\n10\n0\n20\n0\n11\n100\n21\n0\n0\nENDSEC\n0\nEOF\n');
  await page.setInputFiles('#sheet-dxf-input', open);
  await page.click('#nest-run');
  await page.waitForFunction(() => !document.getElementById('nest-message').hidden);
  assert.match(await text('#nest-message'), /no closed outline/);
  // Back to the size fields.
  await page.click('#sheet-dxf-clear');
  assert.equal(await page.isEnabled('#sheet-w'), true);
  assert.deepEqual(app.pageErrors, []);
});

test('a nest file saves the nest as edited and opens it again, parts, sheet and all, without a search', async () => {
  await page.fill('#sheet-w', '1000');
  await page.fill('#sheet-h', '500');
  await page.fill(`${partRow(PLATE)} input.qty`, '5');
  await page.fill(`${partRow(CHAMFER)} input.qty`, '3');
  await page.evaluate(() => (window.kerfcam.lastNest = null));
  await page.click('#nest-run');
  await page.waitForFunction(() => window.kerfcam.lastNest !== null, null, { timeout: 60_000 });
  await ready();
  // Edited: the crop line 30 mm right of the parts.
  const lo = (await nest()).crop_range[0];
  await page.fill('#nest-crop', String(lo + 30));
  await page.press('#nest-crop', 'Enter');
  await page.waitForFunction((x) => Math.abs(window.kerfcam.lastNest.sheets[0].crop_x - x) < 1e-9, lo + 30);
  const saved = await nest();
  const [download] = await Promise.all([page.waitForEvent('download'), page.click('#nest-save')]);
  assert.equal(download.suggestedFilename(), 'nest.kerfcam-nest.json');
  const file = path.join(app.downloadDir, 'nest.kerfcam-nest.json');
  await download.saveAs(file);
  const doc = JSON.parse(fs.readFileSync(file, 'utf8'));
  assert.equal(doc.format, 'kerfcam-nest');
  assert.deepEqual(doc.parts.map((p) => [p.name, p.quantity]), [[PLATE, 5], [CHAMFER, 3]]);
  assert.equal(doc.placements.length, 8);

  // Something else on the page, then the file opened: the same nest, the same figures.
  await page.fill(`${partRow(PLATE)} input.qty`, '1');
  await page.fill('#sheet-w', '700');
  await page.evaluate(() => (window.kerfcam.lastNest = null));
  await page.click('#nest-run');
  await page.waitForFunction(() => window.kerfcam.lastNest !== null, null, { timeout: 60_000 });
  await ready();
  await page.evaluate(() => (window.kerfcam.lastNest = null));
  await page.setInputFiles('#nest-open-input', file);
  await page.waitForFunction(() => window.kerfcam.lastNest !== null);
  await ready();
  const opened = await nest();
  for (const key of ['flat', 'sheets', 'conflicts', 'remnant_area']) assert.deepEqual(opened[key], saved[key], key);
  assert.equal(await page.inputValue(`${partRow(PLATE)} input.qty`), '5');
  assert.equal(await page.inputValue('#sheet-w'), '1000');
  assert.match(await text('#nest-progress'), /Opened nest\.kerfcam-nest\.json: 8 copies on 1 sheet/);
  const [prog] = await Promise.all([page.waitForEvent('download'), page.click('#download')]);
  const ngc = path.join(app.downloadDir, 'opened.ngc');
  await prog.saveAs(ngc);
  assert.equal(fs.readFileSync(ngc, 'utf8'), await page.evaluate(() => window.kerfcam.lastGcode));
  assertRs274Accepts(ngc);
  // Not a nest file: said so, nothing changed.
  const junk = path.join(app.downloadDir, 'junk.json');
  fs.writeFileSync(junk, '{"format": "something-else"}');
  await page.setInputFiles('#nest-open-input', junk);
  await page.waitForFunction(() => !document.getElementById('nest-message').hidden);
  assert.match(await text('#nest-message'), /junk\.json is not a kerfcam nest file/);
  assert.deepEqual((await nest()).flat, saved.flat);
  assert.deepEqual(app.pageErrors, []);
});
