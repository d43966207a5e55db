// The process technology panel (issue 20) in Debian's headless chromium, as a user would: type a
// setting, let the page re-run, download the program and read it — tabs, the height lock, depth
// passes, small holes, the controller's compensation, each layer's operation, and the verification's
// figures shown. Every downloaded program through rs274.
//
//   node --test tests/browser/process.test.mjs

import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { after, before, test } from 'node:test';
import { assertRs274Accepts, clearFiles, downloadProgram, openApp, untilReady } from './harness.mjs';

let app;
let page;
let dir;

before(async () => {
  app = await openApp();
  page = app.page;
  dir = app.downloadDir; // removed by app.close()
});

after(async () => {
  await app?.close();
});

/** A 100 × 50 plate with a Ø6 hole on layer CUT and a line on layer SCRIBE. */
function plate() {
  const out = ['0', 'SECTION', '2', 'HEADER', '9', '$INSUNITS', '70', '4', '0', 'ENDSEC', '0', 'SECTION', '2', 'ENTITIES'];
  const line = (layer, x0, y0, x1, y1) => out.push('0', 'LINE', '8', layer, '10', x0, '20', y0, '11', x1, '21', y1);
  line('CUT', 0, 0, 100, 0);
  line('CUT', 100, 0, 100, 50);
  line('CUT', 100, 50, 0, 50);
  line('CUT', 0, 50, 0, 0);
  out.push('0', 'CIRCLE', '8', 'CUT', '10', 30, '20', 25, '40', 3);
  line('SCRIBE', 60, 10, 90, 10);
  out.push('0', 'ENDSEC', '0', 'EOF');
  const file = path.join(dir, 'process-plate.dxf');
  fs.writeFileSync(file, out.join('\n') + '\n');
  return file;
}

/** The program the Download button gives. */
const downloaded = () => downloadProgram(page, dir);

/**
 * Types a value the engine refuses on its own (a half of a pair) and waits for the page to say so at the
 * field `marked` (the pair's other half, or this one), the last good program kept.
 */
async function typeRefused(id, value, marked) {
  await page.evaluate(() => (window.kerfcam.lastReport = null));
  await page.click(`#${id}`, { clickCount: 3 });
  await page.keyboard.type(String(value));
  await page.keyboard.press('Tab');
  await page.waitForSelector(`#${marked}[aria-invalid="true"]`);
  assert.notEqual(await page.$eval('#status', (e) => e.dataset.state), 'error');
}

/** After a refused value: types the other half and waits for a new finished job (not the old error). */
async function typeReady(id, value) {
  await page.evaluate(() => (window.kerfcam.lastReport = null));
  await page.click(`#${id}`, { clickCount: 3 });
  await page.keyboard.type(String(value));
  await page.keyboard.press('Tab');
  await page.waitForFunction(
    () => document.getElementById('status').dataset.state === 'ready' && window.kerfcam.lastReport !== null,
  );
  assert.equal(await page.$eval('#error', (e) => (e.hidden ? '' : e.textContent)), '');
}

/** Types `value` into the field as a user does (select all, type, Tab away) and waits for the re-run. */
async function type(id, value) {
  await untilReady(page, async () => {
    await page.click(`#${id}`, { clickCount: 3 });
    await page.keyboard.type(String(value));
    await page.keyboard.press('Tab');
  });
}

test('tabs, the height lock, depth passes and small holes typed in the panel reach the downloaded program', async () => {
  await clearFiles(page);
  await untilReady(page, () => page.setInputFiles('#file-input', plate()));
  // No tabs by default.
  let g = fs.readFileSync(await downloaded(), 'utf8');
  assert.ok(!g.includes('(tab)'));
  await type('tabs', 2);
  await type('tab-width', '2,5'); // the Portuguese decimal sign is understood too
  const file = await downloaded();
  g = fs.readFileSync(file, 'utf8');
  assert.equal(g.match(/\(tab\)/g)?.length, 2, g);
  const report = await page.evaluate(() => window.kerfcam.lastReport);
  assert.deepEqual(report.plan.tabs_per_part, [{ part: 1, tabs: 2 }]);
  assertRs274Accepts(file);
  await type('tabs', 0);
  // Small holes below 10 mm at 50 %: the Ø6 hole's feed is half the cut's.
  await type('small-hole', 10);
  await type('small-hole-speed', 50);
  g = fs.readFileSync(await downloaded(), 'utf8');
  assert.ok(/small hole/.test(g), g);
  assert.ok(g.includes('F1000'), 'the small hole at 50 % of 2000 mm/min');
  await type('small-hole', 0);
  // Depth passes on the plain LinuxCNC post: Z words at each depth. The depth alone is refused
  // (it needs the deepest pass too) and said at the deepest pass; with both, the program has them.
  await typeRefused('depth', 6, 'pass-depth');
  await typeReady('pass-depth', 3);
  g = fs.readFileSync(await downloaded(), 'utf8');
  assert.ok(g.includes('G1 Z-3') && g.includes('G1 Z-6'), g);
  await typeRefused('depth', 0, 'depth');
  await typeReady('pass-depth', 0);
});

test('the height lock on the QtPlasmaC post, the controller compensation, and the verification shown', async () => {
  await untilReady(page, () => page.selectOption('#post', 'preset:qtplasmac'));
  await type('thc-corner', 5);
  let g = fs.readFileSync(await downloaded(), 'utf8');
  assert.ok((g.match(/^M62 P2$/gm) || []).length >= 4, g);
  await type('thc-corner', 0);
  await untilReady(page, () => page.selectOption('#post', ''));
  await untilReady(page, () => page.check('#controller-comp'));
  g = fs.readFileSync(await downloaded(), 'utf8');
  assert.ok(/G41\.1|G42\.1/.test(g), g);
  await untilReady(page, () => page.uncheck('#controller-comp'));
  await untilReady(page, () => page.check('#verify'));
  const text = await page.textContent('#verify-result');
  assert.match(text, /Checked: the kerf takes nothing from the parts/);
  // Tabs: held, and said so.
  await type('tabs', 1);
  assert.match(await page.textContent('#verify-result'), /1 held by tabs/);
  await type('tabs', 0);
  await untilReady(page, () => page.uncheck('#verify'));
  assert.equal(await page.isHidden('#verify-result'), true);
});

test('a layer set to mark in the layers panel is marked first with the post\'s marking codes', async () => {
  await untilReady(page, () => page.selectOption('#post', 'preset:qtplasmac'));
  const scribe = page.locator('#layers li', { hasText: 'SCRIBE' }).locator('select.layer-op');
  // SCRIBE is marked by its name; set to cut, it is cut like the rest.
  await untilReady(page, () => scribe.selectOption('cut'));
  let g = fs.readFileSync(await downloaded(), 'utf8');
  assert.ok(!g.includes('M3 $1 S1'), 'no scribe codes once the layer is cut');
  await untilReady(page, () => scribe.selectOption('mark'));
  g = fs.readFileSync(await downloaded(), 'utf8');
  const mark = g.indexOf('M3 $1 S1');
  assert.ok(mark > 0 && mark < g.indexOf('M3 $0 S1'), 'marked before any cut');
  // Keyboard reachable: the select has a name that says which layer.
  assert.equal(await scribe.getAttribute('aria-label'), 'Operation of layer SCRIBE');
  await untilReady(page, () => scribe.selectOption(''));
  await untilReady(page, () => page.selectOption('#post', ''));
});

/** A lopsided bow tie: one closed polyline crossing itself at (24, 24) (a symmetric one encloses no signed area:
 * unrepaired it is an open contour, not a refused one). */
function bowTie() {
  const out = ['0', 'SECTION', '2', 'HEADER', '9', '$INSUNITS', '70', '4', '0', 'ENDSEC', '0', 'SECTION', '2', 'ENTITIES'];
  out.push('0', 'LWPOLYLINE', '8', 'CUT', '90', 4, '70', 1);
  for (const [x, y] of [[0, 0], [40, 40], [40, 0], [0, 60]]) out.push('10', x, '20', y);
  out.push('0', 'ENDSEC', '0', 'EOF');
  const file = path.join(dir, 'process-bow-tie.dxf');
  fs.writeFileSync(file, out.join('\n') + '\n');
  return file;
}

test('self-crossing outlines are repaired by default; the switch leaves them uncut and is kept', async () => {
  await clearFiles(page);
  await untilReady(page, () => page.setInputFiles('#file-input', bowTie()));
  assert.equal(await page.isChecked('#repair'), true, 'on by default');
  let report = await page.evaluate(() => window.kerfcam.lastReport);
  const codes = (r) => r.warnings.map((w) => w.code);
  assert.ok(codes(report).includes('self-crossing-repaired'), codes(report).join(' '));
  assert.equal(report.plan.parts, 2, 'the two triangles');
  await untilReady(page, () => page.uncheck('#repair'));
  report = await page.evaluate(() => window.kerfcam.lastReport);
  assert.ok(!codes(report).includes('self-crossing-repaired'), codes(report).join(' '));
  assert.ok(codes(report).includes('self-crossing'), 'refused by the kerf stage, as --no-repair');
  const kept = await page.evaluate(() => JSON.parse(localStorage.getItem('kerfcam.settings')).values.repair);
  assert.equal(kept, false, 'kept for the next visit like the other switches');
  await untilReady(page, () => page.check('#repair'));
  report = await page.evaluate(() => window.kerfcam.lastReport);
  assert.ok(codes(report).includes('self-crossing-repaired'));
});
