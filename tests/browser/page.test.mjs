// End-to-end test of www/ in Debian's headless Chromium, driven by playwright-core (no browser download).
// Needs www/pkg (scripts/build-wasm.sh), `chromium` and LinuxCNC's `rs274` on PATH
// (KERFCAM_NO_RS274=1 skips the rs274 check; CHROMIUM=/path overrides the browser).
//
//   node --test tests/browser/

import assert from 'node:assert/strict';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { after, before, test } from 'node:test';
import { fileURLToPath } from 'node:url';
import { chromium } from 'playwright-core';
import { startServer } from '../../scripts/serve.mjs';
import { assertRs274Accepts, clearFiles as clearFilesOf, untilReady as untilReadyOf, which } from './harness.mjs';

const repoRoot = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..', '..');
const shared = path.resolve(repoRoot, '..', 'shared');
const PLATE = path.join(shared, 'fixtures', 'seed000-plate-6-holes.dxf');
const corpus = (...parts) => path.join(shared, 'corpus', ...parts);
const BINARY_R14 = corpus('ezdxf', 'bin_dxf_r14.dxf');
const SPLINES = corpus('dxf2gcode-plasma', 'Inkspace_dxf_export_kreis_splines.dxf');
// Geometry on four layers (0 and three "MILL: …" layers with closed contours), $INSUNITS mm.
// (2-test-layers-nested.dxf has all its geometry on one layer, so it cannot show a pierce count drop.)
const MULTI_LAYER = corpus('dxf2gcode-plasma', 'pumpenteile.dxf');
// Timed, not asserted: the largest corpus file (3.3 MB) and the largest plain-drawing one.
// KERFCAM_TIMED_DXF=a.dxf,b.dxf (relative to ../shared/corpus) overrides.
const TIMED = (process.env.KERFCAM_TIMED_DXF || 'dxf2gcode-plasma/rumpfseiten b2 01 2004.dxf,visicut/draft1.dxf')
  .split(',')
  .map((f) => path.join(shared, 'corpus', f.trim()));

const ARGS = [
  '--headless', '--no-sandbox', '--disable-gpu', '--disable-background-networking', '--disable-component-update',
  '--no-first-run', '--disable-sync', '--disable-quic',
];
const COLOURS = { background: [255, 255, 255], partFill: [0xcf, 0xe3, 0xf7], kerf: [0xd6, 0x28, 0x28] };

let server;
let context;
let page;
let userDataDir;
let downloadDir;
const pageErrors = [];

before(async () => {
  assert.ok(fs.existsSync(path.join(repoRoot, 'www', 'pkg', 'kerfcam_bg.wasm')), 'www/pkg missing: run scripts/build-wasm.sh');
  const executablePath = process.env.CHROMIUM || which('chromium');
  assert.ok(executablePath, 'chromium is not on PATH: run scripts/setup.sh test');
  server = await startServer(0);
  userDataDir = fs.mkdtempSync(path.join(os.tmpdir(), 'kerfcam-chromium-'));
  downloadDir = fs.mkdtempSync(path.join(os.tmpdir(), 'kerfcam-downloads-'));
  context = await chromium.launchPersistentContext(userDataDir, {
    executablePath,
    headless: true,
    args: ARGS,
    acceptDownloads: true,
    downloadsPath: downloadDir,
    viewport: { width: 1280, height: 800 },
  });
  page = context.pages()[0] ?? (await context.newPage());
  page.on('pageerror', (e) => pageErrors.push(e));
  page.on('console', (m) => m.type() === 'error' && pageErrors.push(new Error(m.text())));
  await page.goto(server.url);
  await page.waitForFunction(() => document.getElementById('status').textContent !== 'loading');
});

after(async () => {
  await context?.close();
  await server?.close();
  for (const dir of [userDataDir, downloadDir]) if (dir) fs.rmSync(dir, { recursive: true, force: true });
});

// --- helpers ---------------------------------------------------------------------------------------

/** Runs `trigger` and waits until the page has rendered a new job; returns the milliseconds it took. */
const untilReady = (trigger, timeout = 30_000) => untilReadyOf(page, trigger, timeout);

const openWithPicker = (file) => page.setInputFiles('#file-input', file);

/** Drops `bytes` as a file named `name` on the page, the way a drag from the file manager does. */
function dropFile(name, bytes) {
  return page.evaluate(
    ({ name, base64 }) => {
      const data = Uint8Array.from(atob(base64), (c) => c.charCodeAt(0));
      const dt = new DataTransfer();
      dt.items.add(new File([data], name));
      const init = { dataTransfer: dt, bubbles: true, cancelable: true };
      // In-page timing, free of the test's byte transfer: drop -> status "ready".
      const status = document.getElementById('status');
      const observer = new MutationObserver(() => {
        if (status.textContent === 'ready') {
          window.kerfcam.dropToReadyMs = performance.now() - t0;
          observer.disconnect();
        }
      });
      observer.observe(status, { childList: true, characterData: true, subtree: true });
      const t0 = performance.now();
      window.kerfcam.dropStart = t0; // long tasks before this are the test's own decoding of the bytes
      document.body.dispatchEvent(new DragEvent('dragover', init));
      document.body.dispatchEvent(new DragEvent('drop', init));
    },
    { name, base64: Buffer.from(bytes).toString('base64') },
  );
}

async function setNumber(selector, value) {
  await page.fill(selector, String(value));
  await page.press(selector, 'Tab'); // commits: fires `change`
}

const summary = () =>
  page.evaluate(() =>
    Object.fromEntries([...document.querySelectorAll('#summary dd[data-key]')].map((dd) => [dd.dataset.key, dd.textContent])),
  );

/** Number of canvas pixels within `tol` of each named colour. */
function countColours(colours, tol = 12) {
  return page.evaluate(
    ({ colours, tol }) => {
      const c = document.getElementById('preview');
      const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
      const counts = Object.fromEntries(Object.keys(colours).map((k) => [k, 0]));
      for (let i = 0; i < d.length; i += 4) {
        for (const [k, [r, g, b]] of Object.entries(colours)) {
          if (Math.abs(d[i] - r) <= tol && Math.abs(d[i + 1] - g) <= tol && Math.abs(d[i + 2] - b) <= tol) counts[k]++;
        }
      }
      counts.total = d.length / 4;
      return counts;
    },
    { colours, tol },
  );
}

const clearFiles = () => clearFilesOf(page);

const errorText = () => page.$eval('#error', (e) => (e.hidden ? '' : e.textContent));
const lastReport = () => page.evaluate(() => window.kerfcam.lastReport);

/** Clicks Download, checks the file is the page's program and that `rs274` accepts it; returns the text. */
async function downloadAndCheck(expectedName) {
  assert.equal(await page.isDisabled('#download'), false);
  const [download] = await Promise.all([page.waitForEvent('download'), page.click('#download')]);
  assert.equal(download.suggestedFilename(), expectedName);
  const file = path.join(downloadDir, download.suggestedFilename());
  await download.saveAs(file);
  const gcode = fs.readFileSync(file, 'utf8');
  assert.equal(gcode, await page.evaluate(() => window.kerfcam.lastGcode));
  assert.match(gcode, /^%\r?\n\(/, 'G-code header: a % line, then a comment');
  assert.match(gcode, /\n%\r?\n?$/, 'a program opened with % ends with %');
  const code = gcode.replace(/\([^)]*\)/g, '').replace(/;.*$/gm, '');
  for (const word of [/\bG21\b/, /\bM0?3\b/, /\bM0?5\b/, /\bM0?2\b/]) assert.match(code, word);

  assertRs274Accepts(file);
  return gcode;
}

/** The layer list as shown: name (as text), checked, entity count, greyed. */
const shownLayers = () =>
  page.$$eval('#layers li.layer', (items) =>
    items.map((li) => ({
      name: li.querySelector('.layer-name').textContent,
      checked: li.querySelector('input[type=checkbox]').checked,
      entities: Number(li.querySelector('.layer-count').firstChild.textContent),
      greyed: li.classList.contains('empty'),
    })),
  );
const layerBox = (index) => page.locator(`#layers li[data-index="${index}"] input[type=checkbox]`);

function expectPlateSummary(s) {
  assert.equal(s.file, 'seed000-plate-6-holes.dxf');
  assert.equal(s.parts, '1');
  assert.equal(s.holes, '6');
  assert.equal(s.open, '0');
  assert.equal(s['invalid-vertices'], '4');
}

// --- tests -----------------------------------------------------------------------------------------

test('the page loads the wasm and waits for a file', async () => {
  assert.equal(await errorText(), '');
  assert.equal(await page.textContent('#status'), 'waiting for a file');
  assert.equal(await page.isDisabled('#download'), true);
  assert.match(await page.textContent('#version'), /^v\d/);
});

test('a DXF opened with the file picker gives the expected plan, preview and G-code', async () => {
  await setNumber('#kerf', 2); // no file yet: nothing runs, the value is kept
  await untilReady(() => openWithPicker(PLATE));
  assert.equal(await errorText(), '');
  expectPlateSummary(await summary());
  const report = await page.evaluate(() => window.kerfcam.lastReport);
  assert.equal(report.invalid_vertices.length, 4);

  const px = await countColours(COLOURS);
  assert.ok(px.background > px.total * 0.2, `mostly background expected: ${JSON.stringify(px)}`);
  assert.ok(px.partFill > px.total * 0.05, `part fill expected: ${JSON.stringify(px)}`);
  assert.ok(px.kerf >= 20, `kerf red expected: ${JSON.stringify(px)}`);

  await downloadAndCheck('seed000-plate-6-holes.ngc');
});

test('changing the kerf re-runs the job on the same file', async () => {
  const before = await page.evaluate(() => window.kerfcam.lastGcode);
  await untilReady(() => setNumber('#kerf', 3));
  const after = await page.evaluate(() => window.kerfcam.lastGcode);
  assert.notEqual(after, before);
  expectPlateSummary(await summary());
  await untilReady(() => setNumber('#kerf', 2));
  assert.equal(await page.evaluate(() => window.kerfcam.lastGcode), before);
});

test('a DXF dropped on the page is opened', async () => {
  await untilReady(() => openWithPicker(path.join(shared, 'fixtures', 'seed000-figure1.dxf')));
  assert.equal((await summary()).file, 'seed000-figure1.dxf');
  await untilReady(() => dropFile('seed000-plate-6-holes.dxf', fs.readFileSync(PLATE)));
  assert.equal(await errorText(), '');
  expectPlateSummary(await summary());
  assert.equal(await page.evaluate(() => document.body.classList.contains('dragging')), false);
});

test('a file that is not a DXF shows an error and the page stays usable', async () => {
  let seed = 42; // deterministic noise, including bytes that are not UTF-8
  const noise = Buffer.alloc(4096, 0).map(() => ((seed = (seed * 1103515245 + 12345) >>> 0) >>> 16) & 0xff);
  await dropFile('noise.bin', noise);
  await page.waitForFunction(() => document.getElementById('status').textContent === 'error');
  const message = await errorText();
  assert.ok(message.length > 10, `error message expected, got ${JSON.stringify(message)}`);
  assert.match(message, /noise\.bin/);
  assert.equal(await page.isDisabled('#download'), true);
  assert.equal(await page.evaluate(() => window.kerfcam.lastGcode), null);
  assert.equal(await page.isHidden('#placeholder'), true, 'no "Open or drop a DXF file" with a file open');

  await untilReady(() => openWithPicker(PLATE));
  assert.equal(await errorText(), '');
  expectPlateSummary(await summary());
});

test('a binary DXF is read: the summary says binary and shows its 3 LINE entities', async () => {
  await untilReady(() => dropFile(path.basename(BINARY_R14), fs.readFileSync(BINARY_R14)));
  const s = await summary();
  assert.equal(s.file, 'bin_dxf_r14.dxf');
  assert.match(s.format, /\bbinary\b/);
  assert.match(s.format, /AC1014/);
  assert.match(s.entities, /^3 \(LINE 3\)$/);
  // Issue 13's rule: $MEASUREMENT alone does not state the drawing's unit; mm is assumed, visibly.
  assert.match(s.units, /^mm \(assumed: the file does not say\)$/);
  const r = await lastReport();
  assert.equal(r.units_assumed, true);
  assert.equal(r.binary, true);
  assert.deepEqual(r.entities, { LINE: 3 });
});

test('a DXF of SPLINEs gives a part, a pierce and a program rs274 accepts', async () => {
  await untilReady(() => dropFile(path.basename(SPLINES), fs.readFileSync(SPLINES)));
  const s = await summary();
  assert.match(s.entities, /SPLINE \d+/);
  assert.equal(s.skipped, 'none');
  assert.ok(Number(s.parts) >= 1, `parts: ${s.parts}`);
  assert.ok(Number(s.pierces) >= 1, `pierces: ${s.pierces}`);
  assert.equal(s.units, 'mm (assumed: the file does not say)');
  assert.match(s.format, /version not stated/);
  assert.doesNotMatch(s.format, /binary/);
  await downloadAndCheck('Inkspace_dxf_export_kreis_splines.ngc');
});

test('layers: unchecking one cuts less, the choice survives a units change, a new file resets it', async () => {
  await untilReady(() => openWithPicker(MULTI_LAYER));
  const before = await lastReport();
  assert.ok(before.layers.filter((l) => l.entities > 0).length >= 2, 'geometry on two layers or more');
  assert.deepEqual(
    await shownLayers(),
    before.layers.map((l) => ({ name: l.name, checked: l.selected, entities: l.entities, greyed: l.entities === 0 })),
  );
  assert.equal(await page.textContent('#layer-count'), `(${before.layers.length} of ${before.layers.length} cut)`);
  assert.equal((await summary()).units, 'mm (from $INSUNITS)');

  // The layer with the most closed contours: leaving it out must leave out pierces.
  const closed = (name) => before.contours.filter((c) => c.closed && c.layer === name).length;
  const index = before.layers.reduce((best, l, i) => (closed(l.name) > closed(before.layers[best].name) ? i : best), 0);
  const name = before.layers[index].name;
  assert.ok(closed(name) > 0);

  await untilReady(() => layerBox(index).uncheck());
  const off = await lastReport();
  assert.ok(off.plan.pierces < before.plan.pierces, `pierces ${off.plan.pierces} < ${before.plan.pierces}`);
  assert.equal(off.layers[index].name, name);
  assert.equal(off.layers[index].selected, false);
  assert.ok(off.layers.every((l, i) => i === index || l.selected), 'the other layers stay selected');
  assert.equal(off.layers[index].entities, before.layers[index].entities, 'its entities are still counted');
  assert.equal(await layerBox(index).isChecked(), false);
  assert.equal((await summary()).pierces, String(off.plan.pierces));
  assert.equal(await page.textContent('#layer-count'), `(${before.layers.length - 1} of ${before.layers.length} cut)`);

  // Another unit: the selection stays, the summary says where the unit came from.
  await untilReady(() => page.selectOption('#units', 'cm'));
  assert.equal((await summary()).units, 'cm (set in Settings)');
  const cm = await lastReport();
  assert.equal(cm.units_source, 'override');
  assert.equal(cm.layers[index].selected, false);
  assert.equal(cm.plan.pierces, off.plan.pierces);
  const ratio = cm.plan.cut_length / off.plan.cut_length; // about 10: the drawing scales, the kerf does not
  assert.ok(ratio > 8 && ratio < 12, `cut length ×${ratio} in cm`);
  await untilReady(() => page.selectOption('#units', ''));
  assert.equal((await summary()).units, 'mm (from $INSUNITS)');

  // With the keyboard: Space on the focused checkbox turns the layer back on; the focus stays there.
  await layerBox(index).focus();
  await untilReady(() => page.keyboard.press('Space'));
  const on = await lastReport();
  assert.equal(on.plan.pierces, before.plan.pierces);
  assert.equal(on.layers[index].selected, true);
  assert.equal(await page.evaluate(() => document.activeElement?.closest('li')?.dataset.index), String(index));

  // None, then a new file: it starts with its own visible layers again.
  await untilReady(() => page.click('#layers-none'));
  const none = await lastReport();
  assert.ok(none.layers.every((l) => !l.selected));
  assert.equal(none.plan.pierces, 0);
  await untilReady(() => openWithPicker(MULTI_LAYER));
  const fresh = await lastReport();
  assert.deepEqual(fresh.layers.map((l) => l.selected), before.layers.map((l) => l.selected));
  assert.equal(fresh.plan.pierces, before.plan.pierces);
});

test('layer names are shown as text and never reach the G-code', async () => {
  const XSS = '<img src=x onerror="window.__xss=1">';
  const GCODE = 'evil) M2 (; G0 X999'; // would end a comment and stop the machine if copied into one
  const circle = (layer, x) => `0\nCIRCLE\n8\n${layer}\n10\n${x}\n20\n0\n40\n5\n`;
  const dxf = `0\nSECTION\n2\nENTITIES\n${circle(XSS, 0)}${circle(GCODE, 20)}0\nENDSEC\n0\nEOF\n`;
  await untilReady(() => dropFile('layers-injection.dxf', Buffer.from(dxf)));

  assert.deepEqual((await shownLayers()).map((l) => l.name), [XSS, GCODE]);
  const s = await summary();
  assert.equal(s.parts, '2');
  assert.equal(s.pierces, '2');
  await page.waitForTimeout(100); // time for an image error handler to run, if there were an image
  const dom = () =>
    page.evaluate(() => ({
      img: document.querySelectorAll('img').length,
      onerror: document.querySelectorAll('[onerror]').length,
      xss: window.__xss,
    }));
  assert.deepEqual(await dom(), { img: 0, onerror: 0, xss: undefined });

  const gcode = await downloadAndCheck('layers-injection.ngc');
  for (const piece of ['img', 'onerror', '__xss', 'evil', 'X999', '<', '>', '"']) {
    assert.ok(!gcode.includes(piece), `the G-code contains ${JSON.stringify(piece)} from a layer name`);
  }
  const comments = gcode.match(/\([^)]*\)|;.*$/gm) || [];
  assert.ok(comments.every((c) => !c.includes(XSS) && !c.includes(GCODE)));

  // A layer left out is named in a warning: as text too.
  await untilReady(() => layerBox(0).uncheck());
  assert.match(await page.textContent('#warnings'), /not selected for cutting/);
  assert.ok((await page.textContent('#warnings')).includes(XSS));
  assert.equal((await summary()).pierces, '1');
  await page.waitForTimeout(100);
  assert.deepEqual(await dom(), { img: 0, onerror: 0, xss: undefined });
});

test('repairs (report.healing) are shown when the engine reports them', async () => {
  // A square drawn with one line twice, a collinear overlap on another side and a 0.02 mm gap at a corner.
  const line = (x0, y0, x1, y1) => `0\nLINE\n8\n0\n10\n${x0}\n20\n${y0}\n11\n${x1}\n21\n${y1}\n`;
  const dxf = '0\nSECTION\n2\nENTITIES\n' + line(0, 0, 100, 0) + line(0, 0, 100, 0) + line(100, 0, 100, 100) +
    line(100, 100, 0, 100) + line(60, 100, 20, 100) + line(0, 100, 0, 0.02) + '0\nENDSEC\n0\nEOF\n';
  await untilReady(() => dropFile('repairs.dxf', Buffer.from(dxf)));
  const repaired = await lastReport();
  assert.deepEqual([repaired.healing.duplicates, repaired.healing.overlaps, repaired.healing.gaps_closed], [1, 1, 1]);
  assert.equal((await summary()).healing, '1 duplicate removed, 1 overlap merged, 1 gap closed');
  assert.equal(await page.isVisible('#healing'), true);
  assert.equal(await page.textContent('#healing-count'), '(3)');
  assert.deepEqual(await page.$$eval('#healing-list li', (li) => li.map((e) => e.textContent)), [
    'duplicate at 50.00, 0.00',
    'overlap at 40.00, 100.00',
    'gap at 0.00, 0.00',
  ]);
  // The real engine on a clean drawing: no repairs ("none"), or no Repairs row if it reports no healing.
  await untilReady(() => openWithPicker(PLATE));
  const r = await lastReport();
  if (r.healing) {
    const fixes = r.healing.duplicates + r.healing.overlaps + r.healing.gaps_closed + r.healing.zero_length;
    if (fixes === 0) assert.equal((await summary()).healing, 'none');
    assert.equal(await page.isVisible('#healing'), r.healing.locations.length > 0);
  } else {
    assert.equal((await summary()).healing, undefined);
    assert.equal(await page.isVisible('#healing'), false);
  }
});

test('the cut plan: orders compared side by side, the order select re-plans', async () => {
  await untilReady(() => openWithPicker(path.join(shared, 'fixtures', 'seed003-grid-3x2.dxf')));
  await page.click('#compare');
  await page.waitForSelector('#comparison tbody tr'); // the engine answers asynchronously
  const rows = await page.$$eval('#comparison tbody tr', (trs) => trs.map((tr) => tr.dataset.order));
  assert.deepEqual(rows, ['contour', 'chained', 'eulerian']);
  const cmp = await page.evaluate(() => window.kerfcam.lastComparison);
  const contour = cmp.find((r) => r.order === 'contour');
  assert.equal(contour.pierces, 6);
  assert.ok(contour.est_time_s > 0);
  // Issue 14: the grid's parts touch, so at the default 1.5 mm kerf every order cuts into them: the column says
  // so and no order is marked best.
  for (const r of cmp) assert.ok(r.cuts_into_parts && r.into_parts_depth > 0, JSON.stringify(r));
  const flagged = await page.$$eval('#comparison tbody tr', (trs) => trs.map((tr) => [tr.dataset.cutsParts, tr.dataset.best]));
  assert.deepEqual(flagged, [['true', undefined], ['true', undefined], ['true', undefined]]);
  assert.match(await page.textContent('#comparison thead'), /Cuts into parts/);
  // With no kerf (a knife, paper 003's figure 14): the postman order cuts the 5900 mm of unique edges once,
  // re-travels 1500 mm, one pierce, and cuts into no part (the contour order's lead-ins at inner corners run
  // into the neighbouring piece).
  await untilReady(() => page.fill('#kerf', '0'));
  await page.click('#compare');
  await page.waitForFunction(() => window.kerfcam.lastComparison?.some((r) => !r.cuts_into_parts));
  const knife = await page.evaluate(() => window.kerfcam.lastComparison);
  const euler = knife.find((r) => r.order === 'eulerian');
  assert.deepEqual([euler.cut_length, euler.repeated_length, euler.rapid_length, euler.pierces], [5900, 1500, 0, 1]);
  assert.equal(await page.$eval('#comparison tr[data-best="true"]', (tr) => tr.dataset.order), 'eulerian');
  await untilReady(() => page.fill('#kerf', '1.5'));
  await untilReady(() => page.selectOption('#order', 'chained'));
  assert.equal((await lastReport()).plan.order, 'chained');
  assert.match((await summary()).order, /chained/);
  // The order is remembered per file: another file opens with the default order (the page is left on it).
  await untilReady(() => openWithPicker(PLATE));
  assert.equal(await page.$eval('#order', (s) => s.value), 'contour');
});

test('the animation plays the program: time advances, the tool is drawn, the scrubber seeks', async () => {
  await untilReady(() => openWithPicker(PLATE));
  const total = await page.textContent('#anim-time');
  assert.match(total, /^\d+:\d\d \/ \d+:\d\d$/);
  // Loaded: the whole plan is shown, the time reads total / total, and the scrubber agrees.
  const [shown, whole] = total.split(' / ');
  assert.equal(shown, whole);
  assert.equal(await page.inputValue('#scrub'), '1000');
  await page.selectOption('#speed', '50');
  await page.click('#play');
  await page.waitForTimeout(600);
  const mid = await page.textContent('#anim-time');
  assert.notEqual(mid.split(' / ')[0], '0:00', `time should advance: ${mid}`);
  // The tool marker (#111) is on the overlay.
  const dark = await page.evaluate(() => {
    const c = document.getElementById('overlay');
    const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
    let n = 0;
    for (let i = 0; i < d.length; i += 4) if (d[i + 3] > 200 && d[i] < 30 && d[i + 1] < 30 && d[i + 2] < 30) n++;
    return n;
  });
  assert.ok(dark > 10, `tool marker expected on the overlay (${dark} dark pixels)`);
  await page.click('#play'); // pause
  await page.fill('#scrub', '1000');
  await page.dispatchEvent('#scrub', 'input');
  const [done, all] = (await page.textContent('#anim-time')).split(' / ');
  assert.equal(done, all);
});

test('a start point moved by clicking on a hole moves its pierce', async () => {
  await untilReady(() => openWithPicker(PLATE));
  await setNumber('#kerf', 2);
  // The Ø12 hole at (30, 30) starts nearest the origin: its kerf path (r 5) at (25, 30), pierced 3 mm inside.
  // (The run may wait behind another file's program in the worker: wait for it, not for a fixed time.)
  await page.waitForFunction(() => /G0 X28 Y30\n/.test(window.kerfcam.lastGcode ?? ''), null, { timeout: 30_000 });
  await page.click('#set-start');
  const [x, y] = await page.evaluate(() => window.kerfcam.screenOf(36, 30));
  await untilReady(() => page.click('#preview', { position: { x, y } }));
  const g = await page.evaluate(() => window.kerfcam.lastGcode);
  assert.doesNotMatch(g, /G0 X28 Y30\n/);
  assert.match(g, /G0 X32 Y30(\.00\d)?\n/); // the click lands within a hundredth of a pixel of (36, 30)
  await untilReady(() => page.click('#clear-starts'));
  assert.match(await page.evaluate(() => window.kerfcam.lastGcode), /G0 X28 Y30\n/);
});

test('a job in progress can be cancelled, and the page stays usable', async () => {
  const big = fs.readFileSync(TIMED[0]);
  // Click Cancel the moment it shows (the job takes a fraction of a second), just after typing in
  // the kerf field: the re-run that typing schedules (400 ms later) must not undo the cancel.
  await page.evaluate(() => {
    const cancel = document.getElementById('cancel');
    const kerf = document.getElementById('kerf');
    const observer = new MutationObserver(() => {
      if (!cancel.hidden) {
        observer.disconnect();
        kerf.dispatchEvent(new Event('input', { bubbles: true }));
        cancel.click();
      }
    });
    observer.observe(cancel, { attributes: true });
  });
  // Every change of status and error, so a failure says what happened around the cancel.
  await page.evaluate(() => {
    const [status, error] = [document.getElementById('status'), document.getElementById('error')];
    window.kerfcam.statusLog = [];
    const note = () => window.kerfcam.statusLog.push(`${status.textContent} | ${error.hidden ? '' : error.textContent}`);
    const seen = new MutationObserver(note);
    for (const node of [status, error]) seen.observe(node, { childList: true, characterData: true, subtree: true, attributes: true });
  });
  await dropFile('big.dxf', big);
  await page.waitForFunction(() => document.getElementById('status').textContent === 'cancelled', null, { timeout: 30_000 });
  const said = await errorText();
  const log = await page.evaluate(() => window.kerfcam.statusLog.join('\n'));
  assert.match(said, /Cancelled/, `status and error since the drop:\n${log}`);
  await page.waitForTimeout(1000); // past the typing re-run's 400 ms: nothing may start again
  assert.equal(await page.textContent('#status'), 'cancelled', await page.evaluate(() => window.kerfcam.statusLog.join('\n')));
  assert.equal(await page.isDisabled('#download'), true);
  await untilReady(() => openWithPicker(PLATE));
  expectPlateSummary(await summary());
});

test('posts: a preset changes the program; an edited post is checked, saved in the browser and survives reload', async () => {
  await untilReady(() => openWithPicker(PLATE));
  const options = await page.$$eval('#post option', (os) => os.map((o) => o.value));
  for (const name of ['linuxcnc-plasma', 'grbl-laser', 'annex-h', 'point-list']) assert.ok(options.includes(`preset:${name}`), name);
  await untilReady(() => page.selectOption('#post', 'preset:grbl-laser'));
  assert.match(await page.evaluate(() => window.kerfcam.lastGcode), /^M4\b/m);
  // Edit: 2 decimals, then an invalid decimals value is refused with the field named.
  await page.click('#post-edit');
  await page.fill('#pf-name', 'shop laser');
  await page.fill('#pf-decimals', '9');
  await page.click('#post-form button[type=submit]');
  // The engine checks the post in its worker: wait for its answer.
  await page.waitForFunction(() => document.getElementById('post-error').textContent !== '');
  assert.match(await page.textContent('#post-error'), /decimals/);
  await page.fill('#pf-decimals', '2');
  await untilReady(() => page.click('#post-form button[type=submit]'));
  assert.equal(await page.inputValue('#post'), 'mine:shop laser');
  const g = await page.evaluate(() => window.kerfcam.lastGcode);
  assert.doesNotMatch(g, /\d\.\d{3}\b/, 'no 3-decimal numbers with a 2-decimal post');
  await clearFiles(); // kept files would be opened again after the reload
  await page.reload();
  await page.waitForFunction(() => document.getElementById('status').textContent === 'waiting for a file');
  const again = await page.$$eval('#post option', (os) => os.map((o) => o.value));
  assert.ok(again.includes('mine:shop laser'), 'the saved post survives a reload');
  await page.selectOption('#post', '');
});

test('backplot: our own program re-read from its text is drawn and understood', async () => {
  await untilReady(() => openWithPicker(PLATE));
  const gcode = await page.evaluate(() => window.kerfcam.lastGcode);
  const file = path.join(downloadDir, 'plate-backplot.ngc');
  fs.writeFileSync(file, gcode);
  await page.setInputFiles('#backplot-input', file);
  await page.waitForFunction(() => document.getElementById('status').textContent === 'backplot');
  const b = await page.evaluate(() => window.kerfcam.lastBackplot);
  assert.ok(b.moves > 20, `moves re-read: ${b.moves}`);
  assert.deepEqual(b.warnings, []);
  const drawn = await page.evaluate(() => {
    const c = document.getElementById('overlay');
    const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
    let n = 0;
    for (let i = 3; i < d.length; i += 4) if (d[i] > 100) n++;
    return n;
  });
  assert.ok(drawn > 500, `the program is drawn (${drawn} pixels)`);
  await page.click('#backplot-close');
  assert.equal(await page.isVisible('#backplot-close'), false);
});

for (const file of TIMED) {
  test(`large corpus file ${path.basename(file)}: drop-to-preview time (a measurement)`, async () => {
    const bytes = fs.readFileSync(file);
    await clearFiles(); // no other file's program in the worker's queue: the time is this file's
    // The main thread's longest task while the engine worker does the job (Chromium's Long Tasks API).
    await page.evaluate(() => {
      window.kerfcam.longest = 0;
      window.kerfcam.dropStart = Infinity;
      window.kerfcam.longTasks?.disconnect();
      window.kerfcam.longTasks = new PerformanceObserver((list) => {
        for (const e of list.getEntries()) {
          if (e.startTime >= (window.kerfcam.dropStart ?? Infinity)) {
            window.kerfcam.longest = Math.max(window.kerfcam.longest, e.duration);
          }
        }
      });
      window.kerfcam.longTasks.observe({ type: 'longtask' });
    });
    const wall = await untilReady(() => dropFile(path.basename(file), bytes), 300_000);
    const ms = await page.evaluate(() => window.kerfcam.dropToReadyMs);
    const longest = await page.evaluate(() => window.kerfcam.longest);
    const s = await summary();
    console.log(
      `measurement: ${path.relative(shared, file)} (${bytes.length} bytes): drop to preview ${ms.toFixed(0)} ms ` +
        `in the page (${wall.toFixed(0)} ms including the test's transfer of the bytes); ` +
        `parts ${s.parts}, holes ${s.holes}, open ${s.open}, pierces ${s.pierces}; ` +
        `main thread's longest task ${longest ? `${longest.toFixed(0)} ms` : 'under 50 ms (none reported)'}`,
    );
    const px = await countColours(COLOURS);
    assert.ok(px.background < px.total, 'the preview shows something');
  });
}

test('a warning with a place zooms the preview there; the preview saves as a PNG', async () => {
  await untilReady(() => openWithPicker(PLATE));
  const r = await lastReport();
  const i = r.warnings.findIndex((w) => Array.isArray(w.at));
  assert.ok(i >= 0, 'the plate has a located warning (its invalid vertices)');
  await page.locator('#warnings li').nth(i).locator('button.show-at').click();
  await page.waitForTimeout(200);
  const [x, y] = await page.evaluate((p) => window.kerfcam.screenOf(p[0], p[1]), r.warnings[i].at);
  const box = await page.locator('#preview').boundingBox();
  assert.ok(Math.abs(x - box.width / 2) < 2 && Math.abs(y - box.height / 2) < 2, `centred: ${x}, ${y}`);
  const [download] = await Promise.all([page.waitForEvent('download'), page.click('#save-png')]);
  assert.equal(download.suggestedFilename(), 'seed000-plate-6-holes.png');
  const bytes = fs.readFileSync(await download.path());
  assert.deepEqual([...bytes.subarray(1, 4)], [0x50, 0x4e, 0x47]); // "PNG"
  const [svgDownload] = await Promise.all([page.waitForEvent('download'), page.click('#save-svg')]);
  const svg = fs.readFileSync(await svgDownload.path(), 'utf8');
  assert.match(svg, /^<\?xml[^]*<svg [^>]*viewBox=/);
  // The plate's 7 pierces are numbered; the arcs of its circles are SVG arcs.
  assert.equal((svg.match(/<text /g) || []).length, 7);
  assert.match(svg, /A5 5 0 0 [01] /);
  await page.click('#fit');
});

test('settings survive a reload; "Reset to defaults" puts back the page\'s values', async () => {
  await setNumber('#feed', 3300);
  await page.selectOption('#order', 'chained');
  await page.check('#cut-open');
  await clearFiles();
  await page.reload();
  await page.waitForFunction(() => document.getElementById('status').textContent === 'waiting for a file');
  assert.equal(await page.inputValue('#feed'), '3300');
  assert.equal(await page.inputValue('#order'), 'chained');
  assert.equal(await page.isChecked('#cut-open'), true);
  await page.click('#reset-settings');
  assert.equal(await page.inputValue('#feed'), '2000');
  assert.equal(await page.inputValue('#order'), 'contour');
  assert.equal(await page.isChecked('#cut-open'), false);
  await page.reload();
  await page.waitForFunction(() => document.getElementById('status').textContent === 'waiting for a file');
  assert.equal(await page.inputValue('#feed'), '2000');
});

test('offline: with the server stopped, a reload still gives a working app (service worker)', async () => {
  await page.evaluate(async () => {
    await navigator.serviceWorker.ready;
  });
  // The page loaded before the worker existed is not controlled yet: reload once online.
  await clearFiles();
  await page.reload();
  await page.waitForFunction(() => navigator.serviceWorker.controller !== null);
  await page.waitForFunction(() => document.getElementById('status').textContent === 'waiting for a file');
  await server.close();
  server = null;
  await page.reload();
  await page.waitForFunction(() => document.getElementById('status').textContent !== 'loading', null, { timeout: 30_000 });
  assert.equal(await page.textContent('#status'), 'waiting for a file');
  await untilReady(() => openWithPicker(PLATE));
  expectPlateSummary(await summary());
});

test('no uncaught errors in the page', () => {
  assert.deepEqual(pageErrors.map(String), []);
});
