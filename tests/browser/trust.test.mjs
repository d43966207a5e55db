// Issue 13 in the browser: numbers typed the local way, sizes and the program origin in view, the
// assumed unit as a control, truncated files marked, grouped warnings. Debian's chromium through
// playwright-core (harness.mjs); every downloaded program is read by LinuxCNC's rs274.
//
//   node --test tests/browser/trust.test.mjs

import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { after, before, test } from 'node:test';
import { dropInPage, rs274 } from './helpers.mjs';
import { assertRs274Accepts, clearFiles, corpus, fixture, openApp, untilReady } from './harness.mjs';

let app;
let page;

before(async () => {
  app = await openApp();
  page = app.page;
});

after(async () => {
  await app?.close();
});

// --- helpers ---------------------------------------------------------------------------------------

/**
 * A small ASCII DXF (R12 style: ENTITIES only, or with a HEADER when `header` lists variables) of
 * LINEs: `rects` are [x0, y0, x1, y1] rectangles. No $INSUNITS unless `header` gives one.
 */
function dxf({ rects = [], lines = [], header = [], tail = 'EOF' }) {
  const out = [];
  const pair = (code, value) => out.push(String(code), String(value));
  if (header.length) {
    pair(0, 'SECTION');
    pair(2, 'HEADER');
    for (const [name, code, value] of header) {
      pair(9, name);
      pair(code, value);
    }
    pair(0, 'ENDSEC');
  }
  pair(0, 'SECTION');
  pair(2, 'ENTITIES');
  for (const [x0, y0, x1, y1] of rects) {
    const corners = [[x0, y0], [x1, y0], [x1, y1], [x0, y1]];
    corners.forEach(([ax, ay], i) => {
      const [bx, by] = corners[(i + 1) % 4];
      pair(0, 'LINE');
      pair(8, '0');
      pair(10, ax);
      pair(20, ay);
      pair(30, 0);
      pair(11, bx);
      pair(21, by);
      pair(31, 0);
    });
  }
  for (const [ax, ay, bx, by] of lines) {
    pair(0, 'LINE');
    pair(8, '0');
    pair(10, ax);
    pair(20, ay);
    pair(11, bx);
    pair(21, by);
  }
  if (tail === 'EOF') {
    pair(0, 'ENDSEC');
    pair(0, 'EOF');
  }
  return Buffer.from(`${out.join('\n')}\n`, 'latin1');
}

const drop = (name, bytes) => page.evaluate(dropInPage, { name, base64: Buffer.from(bytes).toString('base64') });
const gcode = () => page.evaluate(() => window.kerfcam.lastGcode);
const report = () => page.evaluate(() => window.kerfcam.lastReport);

async function setField(selector, value) {
  await page.fill(selector, String(value));
  await page.press(selector, 'Tab'); // commits: fires `change`
}

async function setLang(lang) {
  await page.selectOption('#lang', lang);
  await page.waitForFunction((l) => document.documentElement.lang === l, lang);
}

/** Clicks Download, saves the program, checks it is the page's and that rs274 reads it; returns its text. */
async function downloadProgram() {
  const [download] = await Promise.all([page.waitForEvent('download'), page.click('#download')]);
  const file = path.join(app.downloadDir, `${Date.now()}-${download.suggestedFilename()}`);
  await download.saveAs(file);
  const text = fs.readFileSync(file, 'utf8');
  assert.equal(text, await gcode(), 'the download is the program the page shows');
  assertRs274Accepts(file);
  downloadProgram.file = file;
  return text;
}

/** Every X and Y word of the program's moves (comments removed), as numbers. */
function coordinates(program) {
  const xs = [];
  const ys = [];
  for (const line of program.replace(/\([^)]*\)/g, '').replace(/;.*$/gm, '').split('\n')) {
    for (const [, axis, v] of line.matchAll(/([XY])\s*(-?\d+(?:\.\d*)?|-?\.\d+)/g)) (axis === 'X' ? xs : ys).push(Number(v));
  }
  return { xs, ys };
}

/** The end points of the program's cutting moves as rs274 (LinuxCNC's interpreter) executes them. */
function rs274Feeds(file) {
  const rs = rs274(file);
  const points = [];
  for (const [, x, y] of rs.stdout.matchAll(/(?:STRAIGHT_FEED|ARC_FEED)\((-?[\d.]+), (-?[\d.]+)/g)) points.push([Number(x), Number(y)]);
  assert.ok(points.length > 0, `rs274 executed no cutting move:\n${rs.stdout.slice(-1000)}`);
  return points;
}
const boxOf = (points) => ({
  min: [Math.min(...points.map((p) => p[0])), Math.min(...points.map((p) => p[1]))],
  max: [Math.max(...points.map((p) => p[0])), Math.max(...points.map((p) => p[1]))],
});

/** Plain cutting: no kerf, no leads, so the program's coordinates are the drawing's. */
async function plainCutting() {
  await page.fill('#kerf', '0');
  await page.selectOption('#lead', 'none');
}

const SQUARE = dxf({ rects: [[10, 10, 60, 40]] });

// --- numbers typed the local way -------------------------------------------------------------------

test('"1,5" and "1.5" in the kerf field both give a 1.5 mm kerf, in English and in Portuguese', async () => {
  await untilReady(page, () => drop('square.dxf', SQUARE));
  for (const lang of ['en', 'pt-BR']) {
    await setLang(lang);
    await untilReady(page, () => setField('#kerf', '15'));
    const fifteen = await gcode();
    await untilReady(page, () => setField('#kerf', '1.5'));
    const point = await gcode();
    assert.notEqual(point, fifteen, `${lang}: a 1.5 mm kerf is not a 15 mm one`);
    await untilReady(page, () => setField('#kerf', '2'));
    await untilReady(page, () => setField('#kerf', '1,5'));
    assert.equal(await gcode(), point, `${lang}: "1,5" is 1.5`);
    // The 50 × 30 square's torch path, 0.75 mm outside with round corners: 160 + π × 1.5 mm long.
    const cut = (await report()).plan.cut_length;
    assert.ok(Math.abs(cut - (160 + Math.PI * 1.5)) < 0.01, `${lang}: cut length ${cut} is a 1.5 mm kerf's`);
    assert.equal(await page.getAttribute('#kerf', 'aria-invalid'), 'false');
  }
  await setLang('en');
});

test('a negative or zero feed marks the field with its label and range and keeps the preview and program', async () => {
  assert.equal(await page.inputValue('#feed'), '2000');
  const program = await gcode();
  for (const [lang, label] of [['en', 'Feed rate'], ['pt-BR', 'Velocidade de corte']]) {
    await setLang(lang);
    for (const bad of ['-100', '0', '1,2,3']) {
      await setField('#feed', bad);
      await page.waitForFunction(() => document.getElementById('feed').getAttribute('aria-invalid') === 'true');
      await page.waitForTimeout(600); // a re-run, if one were started, would have begun
      const problem = await page.textContent('#settings-problems');
      assert.match(problem, new RegExp(`${label}: .*\\b1\\b.*1000000 mm/min`), `${lang} ${bad}: ${problem}`);
      assert.doesNotMatch(problem, /'feed'|setting|configuração '/);
      assert.equal(await page.isHidden('#placeholder'), true, 'the preview stays');
      assert.equal(await page.isDisabled('#download'), false, 'the program stays');
      assert.equal(await gcode(), program);
      assert.notEqual(await page.getAttribute('#feed', 'aria-describedby'), null);
      assert.equal(await page.$eval('#status', (s) => s.dataset.state), 'ready');
    }
  }
  await setLang('en');
  await untilReady(page, () => setField('#feed', '2500'));
  assert.equal(await page.getAttribute('#feed', 'aria-invalid'), 'false');
  assert.equal(await page.isHidden('#settings-problems'), true);
  assert.notEqual(await gcode(), program);
  await untilReady(page, () => setField('#feed', '2000'));
  assert.equal(await gcode(), program);
});

test('arrow keys step each field by its own step, onto the step\'s grid', async () => {
  const steps = async (selector, start, keys) => {
    await page.fill(selector, start);
    const seen = [];
    for (const key of keys) {
      await page.press(selector, key);
      seen.push(await page.inputValue(selector));
    }
    return seen;
  };
  assert.deepEqual(await steps('#feed', '2000', ['ArrowUp', 'ArrowDown', 'ArrowDown']), ['2100', '2000', '1900']);
  assert.deepEqual(await steps('#feed', '2001', ['ArrowUp', 'ArrowDown']), ['2100', '2000']);
  assert.deepEqual(await steps('#rapid', '10000', ['ArrowUp', 'PageDown']), ['11000', '1000']);
  assert.deepEqual(await steps('#kerf', '1.5', ['ArrowUp', 'ArrowUp', 'ArrowDown']), ['1.6', '1.7', '1.6']);
  assert.deepEqual(await steps('#kerf', '0.1', ['ArrowDown', 'ArrowDown']), ['0', '0'], 'not below the range');
  assert.deepEqual(await steps('#kerf', '2', ['f', 'x', ',', '5']), ['2', '2', '2,', '2,5'], 'letters type nothing');
  await setLang('pt-BR');
  assert.deepEqual(await steps('#kerf', '0,2', ['ArrowUp']), ['0,3']);
  await setLang('en');
  // The mouse's spinner (▲ ▼ in the field) steps the same way, and the page re-runs once it stops.
  await page.fill('#kerf', '1.5');
  await page.fill('#feed', '2000');
  await untilReady(page, async () => {
    const arrow = (dir) => page.click(`.number-field:has(#feed) .stepper [data-dir="${dir}"]`);
    await arrow(1);
    await arrow(1);
    await arrow(-1);
  });
  assert.equal(await page.inputValue('#feed'), '2100');
  // A run started by the fields typed above can end first and satisfy untilReady: wait for the
  // program of the stepped value (it fails by timing out if that program never comes).
  await page.waitForFunction(() => /F2100\b/.test(window.kerfcam.lastGcode ?? ''), null, { timeout: 30_000 });
  assert.match(await page.evaluate(() => window.kerfcam.lastGcode), /F2100\b/);
  await untilReady(page, async () => {
    await page.fill('#kerf', '1.5');
    await page.fill('#feed', '2000');
    await page.fill('#rapid', '10000');
    await page.press('#rapid', 'Tab');
  });
});

// --- sizes, units and origin (these need the engine of issue 13: report.size, units_assumed, origin) ---

test('the unit switch beside the units-assumed warning re-runs, scales the program by exactly 25.4, and is kept with the file', async () => {
  await clearFiles(page);
  await plainCutting();
  await page.selectOption('#origin', 'drawing');
  await untilReady(page, () => drop('no-units.dxf', SQUARE));
  const r = await report();
  assert.equal(r.units_assumed, true, 'a file without $INSUNITS: the unit is assumed');
  assert.equal(r.units_source, 'assumed');
  await page.waitForSelector('#warnings li[data-code="units-assumed"] .unit-switch');
  assert.match(await page.textContent('#summary dd[data-key="units"] .assumed'), /assumed/);
  assert.match(await page.textContent('#jobs li[data-name="no-units.dxf"] .job-status'), /units assumed \(mm\)/);
  assert.match(await page.textContent('#summary dd[data-key="size"]'), /^50(\.0)? × 30(\.0)? mm \(1\.97 × 1\.18 in\)$/);

  await untilReady(page, () => page.click('#warnings li[data-code="units-assumed"] button[data-unit="mm"]'));
  const inMm = coordinates(await downloadProgram());
  assert.equal((await report()).units, 'mm');
  assert.equal(await page.locator('#warnings li[data-code="units-assumed"]').count(), 0, 'chosen: no longer assumed');
  await untilReady(page, () => page.click('#summary .unit-switch button[data-unit="in"]'));
  assert.equal((await report()).units, 'in');
  const inInch = coordinates(await downloadProgram());
  assert.equal(inInch.xs.length, inMm.xs.length);
  assert.ok(inMm.xs.length >= 4);
  for (const axis of ['xs', 'ys']) {
    inMm[axis].forEach((v, i) => assert.ok(Math.abs(inInch[axis][i] - 25.4 * v) < 1e-6, `${axis}[${i}]: ${inInch[axis][i]} is not 25.4 × ${v}`));
  }
  assert.match(await page.textContent('#summary dd[data-key="size"]'), /^1270(\.0)? × 762(\.0)? mm \(50\.00 × 30\.00 in\)$/);
  assert.match(await page.textContent('#summary dd[data-key="units"]'), /chosen for this file/);

  // Kept with the file: a reload opens it in inches again.
  await page.reload();
  await page.waitForFunction(() => window.kerfcam?.lastReport?.units === 'in', null, { timeout: 60_000 });
  assert.equal(await page.getAttribute('#summary .unit-switch button[data-unit="in"]', 'aria-pressed'), 'true');
});

test('origin lower-left puts the parts\' box corner at (0,0) of the program (rs274), and the preview marks it', async () => {
  await clearFiles(page);
  await plainCutting();
  await page.selectOption('#origin', 'drawing');
  await untilReady(page, () => drop('square.dxf', dxf({ rects: [[10, 10, 60, 40]], header: [['$INSUNITS', 70, 4]] })));
  await downloadProgram();
  assert.deepEqual(boxOf(rs274Feeds(downloadProgram.file)), { min: [10, 10], max: [60, 40] }, 'the drawing\'s own zero');
  // A start point moved to the right edge's middle, (60, 25) of the drawing: pierced there.
  await page.click('#set-start');
  const [sx, sy] = await page.evaluate(() => window.kerfcam.screenOf(60, 25));
  await untilReady(page, () => page.click('#preview', { position: { x: sx, y: sy } }));
  assert.match(await gcode(), /G0 X60 Y25\b/);

  await untilReady(page, () => page.selectOption('#origin', 'lower-left'));
  // The start point moved with the drawing: the same drawing point, now (50, 15) of the program.
  await page.waitForFunction(() => /G0 X50 Y15\b/.test(window.kerfcam.lastGcode ?? ''), null, { timeout: 30_000 });
  const r = await report();
  assert.equal(r.origin.mode, 'lower-left');
  assert.deepEqual(r.origin.at, [10, 10]);
  assert.deepEqual(r.extent, { min: [0, 0], max: [50, 30] });
  await downloadProgram();
  assert.deepEqual(boxOf(rs274Feeds(downloadProgram.file)), { min: [0, 0], max: [50, 30] });
  assert.match(await page.textContent('#summary dd[data-key="origin"]'), /lower-left/);
  assert.equal(await page.textContent('#summary dd[data-key="extent"]'), 'X 0.0 … 50.0, Y 0.0 … 30.0 mm');
  // The job sheet gives the size in mm and inches, and where X0 Y0 is.
  await page.click('#job-sheet');
  await page.waitForFunction(() => !document.getElementById('sheet-view').hidden);
  assert.equal(await page.textContent('#sheet dd[data-key="size"]'), '50.0 × 30.0 mm (1.97 × 1.18 in)');
  assert.match(await page.textContent('#sheet dd[data-key="origin"]'), /^lower-left corner of the parts: drawing point 10\.00, 10\.00$/);
  await page.keyboard.press('Escape');

  // The origin mark is drawn where the scene's (0,0) is on the preview.
  const green = await page.evaluate(() => {
    const [x, y] = window.kerfcam.screenOf(0, 0);
    const c = document.getElementById('overlay');
    const k = c.width / c.getBoundingClientRect().width;
    const d = c.getContext('2d').getImageData(Math.round(x * k) - 3, Math.round(y * k) - 3, 7, 7).data;
    let n = 0;
    for (let i = 0; i < d.length; i += 4) if (d[i + 3] > 200 && d[i + 1] > d[i] + 40 && d[i + 1] > d[i + 2] + 20) n++;
    return n;
  });
  assert.ok(green >= 5, `origin mark at (0,0): ${green} green pixels`);
  // The scale bar is as long on screen as the length it is labelled with.
  const bar = await page.evaluate(() => ({ ...window.kerfcam.scaleBar, k: window.kerfcam.screenOf(1, 0)[0] - window.kerfcam.screenOf(0, 0)[0] }));
  assert.ok(Math.abs(bar.px - bar.mm * bar.k) < 0.01 && bar.px > 30 && bar.px <= 121, JSON.stringify(bar));

  // A picked point: the square's upper-right corner (snapped) becomes the program's zero.
  await untilReady(page, () => page.selectOption('#origin', 'point')); // no point yet: automatic meanwhile
  assert.equal(await page.getAttribute('#pick-origin', 'aria-pressed'), 'true');
  const corner = (await report()).extent.max; // the drawing's (60, 40) where the automatic origin put it
  const [px, py] = await page.evaluate(([x, y]) => window.kerfcam.screenOf(x, y), corner);
  const box = await page.locator('#preview').boundingBox();
  await untilReady(page, () => page.mouse.click(box.x + px + 3, box.y + py - 2));
  assert.deepEqual((await report()).origin.at, [60, 40]);
  await page.waitForFunction(() => /G0 X0 Y-15\b/.test(window.kerfcam.lastGcode ?? ''), null, { timeout: 30_000 });
  await downloadProgram();
  assert.deepEqual(boxOf(rs274Feeds(downloadProgram.file)), { min: [-50, -30], max: [0, 0] });
  await page.selectOption('#origin', 'auto');
});

test('a truncated file is marked in the files list, not a plain "done"', async () => {
  await clearFiles(page);
  const plate = fs.readFileSync(fixture('seed000-plate-6-holes.dxf'));
  const cut = plate.subarray(0, Math.floor(plate.length * 0.7));
  await untilReady(page, () => drop('cut-off.dxf', cut));
  const w = (await report()).warnings.find((x) => x.code === 'file-truncated');
  assert.ok(w, 'a file-truncated warning');
  assert.equal(await page.getAttribute('#jobs li[data-name="cut-off.dxf"]', 'data-status'), 'truncated');
  assert.match(await page.textContent('#jobs li[data-name="cut-off.dxf"] .job-status'), /truncated/);
  assert.equal(await page.getAttribute('#warnings li:first-child', 'data-code'), 'file-truncated', 'the most serious first');

  // A corpus drawing cut off mid-file, as a failed copy from a USB stick leaves it.
  const real = fs.readFileSync(corpus('dxf2gcode-plasma', 'pumpenteile.dxf'));
  await untilReady(page, () => drop('pumpenteile-cut.dxf', real.subarray(0, Math.floor(real.length / 2))));
  assert.ok((await report()).warnings.some((x) => x.code === 'file-truncated'), 'the cut corpus file warns');
  assert.equal(await page.getAttribute('#jobs li[data-name="pumpenteile-cut.dxf"]', 'data-status'), 'truncated');

  await untilReady(page, () => drop('whole.dxf', SQUARE));
  assert.equal(await page.getAttribute('#jobs li[data-name="whole.dxf"]', 'data-status'), 'done');
  assert.equal(await page.getAttribute('#jobs li[data-name="cut-off.dxf"]', 'data-status'), 'truncated', 'still marked');
});

test('identical warnings come grouped with a count and their places; information is not counted', async () => {
  await clearFiles(page);
  await setField('#kerf', '2');
  // A plate with three holes far too small for a 2 mm kerf: three identical "vanishes" warnings.
  const holes = [10, 30, 50].map((x) => [x, 10, x + 0.5, 10.5]);
  await untilReady(page, () => drop('tiny-holes.dxf', dxf({ rects: [[0, 0, 100, 60], ...holes], header: [['$INSUNITS', 70, 4]] })));
  const r = await report();
  const grouped = r.warnings.find((w) => w.count > 1);
  assert.ok(grouped, `a grouped warning: ${JSON.stringify(r.warnings.map((w) => [w.code, w.count]))}`);
  const li = page.locator(`#warnings li[data-code="${grouped.code}"]`);
  assert.equal(await li.getAttribute('data-count'), String(grouped.count));
  assert.match(await li.textContent(), new RegExp(`${grouped.count} times`));
  if (grouped.places.length > 1) {
    const show = li.locator('button.show-at');
    assert.equal(await show.textContent(), `show 1 of ${grouped.places.length}`);
    await show.click();
    assert.equal(await show.textContent(), `show 2 of ${grouped.places.length}`);
  }
  const counted = r.warnings.filter((w) => w.severity !== 'info').length;
  assert.equal(await page.textContent('#warning-count'), counted ? `(${counted})` : '');
  assert.equal(await page.locator('#warnings li[data-severity="info"]').count(), 0, 'information is listed apart');
  const ranks = { error: 0, warning: 1, info: 2 };
  const order = r.warnings.map((w) => ranks[w.severity]);
  assert.deepEqual(order, [...order].sort((a, b) => a - b), 'the report lists the most serious first');
  assert.equal(grouped.count, 3, 'the three holes');
  await setLang('pt-BR');
  assert.match(await li.textContent(), new RegExp(`${grouped.count} vezes`));
  await setLang('en');
  await setField('#kerf', '1.5');
});

test('no uncaught errors in the page', () => {
  assert.deepEqual(app.pageErrors.map((e) => e.message), []);
});
