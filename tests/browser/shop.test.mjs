// The page as a shop-floor tool (issue 6 §2–§6), in Debian's headless chromium: stage progress, a
// batch of files zipped into programs rs274 accepts, files and layer choices kept across a reload,
// hover inspect, the measure tool, keyboard shortcuts and the printable job sheet.
//
//   node --test tests/browser/shop.test.mjs

import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { after, before, test } from 'node:test';
import { unzipSync } from 'fflate';
import { assertRs274Accepts, clearFiles, corpus, fixture, openApp, untilReady } from './harness.mjs';

const PLATE = fixture('seed000-plate-6-holes.dxf');
const GRID = fixture('seed003-grid-3x2.dxf');
const MULTI_LAYER = corpus('dxf2gcode-plasma', 'pumpenteile.dxf');
const BIG = corpus('dxf2gcode-plasma', 'rumpfseiten b2 01 2004.dxf');

let app;
let page;

before(async () => {
  app = await openApp();
  page = app.page;
});

after(async () => {
  await app?.close();
});

const jobRows = () =>
  page.$$eval('#jobs li.job', (items) => items.map((li) => ({ name: li.dataset.name, status: li.dataset.status })));
const untilJobsDone = (n) =>
  page.waitForFunction(
    (n) => {
      const rows = [...document.querySelectorAll('#jobs li.job')];
      return rows.length === n && rows.every((li) => li.dataset.status === 'done' || li.dataset.status === 'error');
    },
    n,
    { timeout: 60_000 },
  );

test('a big file shows its stages as they finish, each with what it made', async () => {
  const seen = [];
  await page.exposeFunction('kerfcamProgressSeen', (text) => seen.push(text));
  await page.evaluate(() => {
    const text = document.getElementById('progress-text');
    new MutationObserver(() => window.kerfcamProgressSeen(text.textContent)).observe(text, { childList: true, characterData: true, subtree: true });
  });
  await untilReady(page, () => page.setInputFiles('#file-input', BIG));
  const stages = await page.evaluate(() => window.kerfcam.lastStages);
  assert.deepEqual(stages.map((s) => s.stage), ['reading', 'chaining', 'offset', 'planning', 'gcode']);
  const report = await page.evaluate(() => window.kerfcam.lastReport);
  const gcode = await page.evaluate(() => window.kerfcam.lastGcode);
  assert.equal(stages[3].count, report.plan.pierces, 'planning reports the pierces of the plan');
  assert.equal(stages[4].count, Buffer.byteLength(gcode), 'the G-code stage reports the program bytes');
  assert.ok(stages.every((s) => s.ms >= 0));
  // The bar said each stage while it ran: the text grew one stage at a time.
  assert.ok(seen.some((t) => /reading the DXF…/.test(t)), `progress texts: ${seen.join(' | ')}`);
  assert.ok(seen.some((t) => /entities read/.test(t) && /finding contours…/.test(t)));
  assert.equal(await page.$eval('#progress', (e) => getComputedStyle(e).visibility), 'hidden', 'the bar goes away when the job is done');
  assert.equal(await page.evaluate(() => window.kerfcam.renders), 1, 'one preview render for the job: nothing resized the preview');
  console.log(`stages of ${path.basename(BIG)}: ${stages.map((s) => `${s.stage} ${s.count} in ${s.ms.toFixed(0)} ms`).join(', ')}`);
});

test('a batch of three files: each a job with its status, all zipped as programs rs274 accepts', async () => {
  await clearFiles(page);
  await untilReady(page, () => page.setInputFiles('#file-input', [PLATE, GRID, MULTI_LAYER]));
  await untilJobsDone(3);
  const rows = await jobRows();
  assert.deepEqual(rows.map((r) => r.name), [path.basename(PLATE), path.basename(GRID), path.basename(MULTI_LAYER)]);
  assert.ok(rows.every((r) => r.status === 'done'), JSON.stringify(rows));
  assert.equal(await page.textContent('#summary dd[data-key="file"]'), path.basename(PLATE), 'the first file is shown');

  const [download] = await Promise.all([page.waitForEvent('download'), page.click('#download-all')]);
  assert.equal(download.suggestedFilename(), 'kerfcam-programs.zip');
  const zipFile = path.join(app.downloadDir, 'programs.zip');
  await download.saveAs(zipFile);
  const files = unzipSync(new Uint8Array(fs.readFileSync(zipFile)));
  assert.deepEqual(Object.keys(files).sort(), ['pumpenteile.ngc', 'seed000-plate-6-holes.ngc', 'seed003-grid-3x2.ngc']);
  const shownProgram = await page.evaluate(() => window.kerfcam.lastGcode);
  assert.equal(new TextDecoder().decode(files['seed000-plate-6-holes.ngc']), shownProgram, 'the zip holds what is previewed');
  for (const [name, bytes] of Object.entries(files)) {
    const file = path.join(app.downloadDir, name);
    fs.writeFileSync(file, bytes);
    assertRs274Accepts(file);
  }

  // Another file of the list goes on the preview with one click.
  await untilReady(page, () => page.click(`#jobs li.job[data-name="${path.basename(GRID)}"] .job-name`));
  assert.equal(await page.textContent('#summary dd[data-key="file"]'), path.basename(GRID));
  assert.equal(await page.getAttribute(`#jobs li.job[data-name="${path.basename(GRID)}"] .job-name`, 'aria-pressed'), 'true');
});

test('files and their layer choices survive a reload; "Clear files" forgets them', async () => {
  await untilReady(page, () => page.click(`#jobs li.job[data-name="${path.basename(MULTI_LAYER)}"] .job-name`));
  const before = await page.evaluate(() => window.kerfcam.lastReport.plan.pierces);
  await untilReady(page, () => page.locator('#layers li[data-index="1"] input[type=checkbox]').uncheck());
  const fewer = await page.evaluate(() => window.kerfcam.lastReport.plan.pierces);
  assert.ok(fewer < before, `unchecking a layer cuts less (${before} → ${fewer})`);
  const unchecked = await page.textContent('#layers li[data-index="1"] .layer-name');

  await untilReady(page, () => page.reload());
  assert.equal((await jobRows()).length, 3, 'the three files are still listed');
  assert.equal(await page.textContent('#summary dd[data-key="file"]'), path.basename(MULTI_LAYER), 'the shown file is shown again');
  assert.equal(await page.evaluate(() => window.kerfcam.lastReport.plan.pierces), fewer, 'with its layer choice');
  assert.equal(await page.textContent('#layers li[data-index="1"] .layer-name'), unchecked);
  assert.equal(await page.isChecked('#layers li[data-index="1"] input[type=checkbox]'), false);

  await page.click('#clear-files');
  await page.waitForFunction(() => document.getElementById('status').textContent === 'waiting for a file');
  assert.equal((await jobRows()).length, 0);
  await page.reload();
  await page.waitForFunction(() => document.getElementById('status').textContent !== 'loading');
  assert.equal(await page.textContent('#status'), 'waiting for a file', 'nothing comes back after Clear files');
});

/** Moves the mouse to the drawing point (x, y) mm on the preview. */
async function pointAtMm(x, y) {
  const [px, py] = await page.evaluate(([x, y]) => window.kerfcam.screenOf(x, y), [x, y]);
  const box = await page.locator('#preview').boundingBox();
  return [box.x + px, box.y + py];
}

test('hovering a hole names it; a click pins it; the measure tool snaps to centres', async () => {
  await untilReady(page, () => page.setInputFiles('#file-input', PLATE));
  // The Ø12 hole at (30, 30): its line passes through (36, 30).
  const [hx, hy] = await pointAtMm(36, 30);
  await page.mouse.move(hx, hy);
  await page.waitForFunction(() => !document.getElementById('inspect-tip').hidden);
  const tip = await page.textContent('#inspect-tip');
  assert.match(tip, /^hole · layer /);
  assert.match(tip, /CIRCLE/);
  assert.match(tip, /length 37\.70 mm/); // π·12
  assert.match(tip, /area 113\.1 mm²/);
  assert.match(tip, /cut counter-clockwise/);
  assert.match(tip, /part 1/);
  await page.mouse.click(hx, hy);
  await page.waitForFunction(() => /^hole/.test(document.getElementById('readout').textContent));

  // Measure (key M): from the centre of the hole at (30, 30) to the one at (170, 30), clicking 1 mm off.
  await page.keyboard.press('m');
  assert.equal(await page.getAttribute('#measure', 'aria-pressed'), 'true');
  for (const [x, y] of [[30.6, 29.5], [169.4, 30.5]]) {
    const [px, py] = await pointAtMm(x, y);
    await page.mouse.click(px, py);
  }
  await page.waitForFunction(() => window.kerfcam.lastMeasure()?.d > 0);
  const m = await page.evaluate(() => window.kerfcam.lastMeasure());
  assert.ok(Math.abs(m.d - 140) < 1e-9 && Math.abs(m.angle) < 1e-9, JSON.stringify(m));
  assert.match(await page.textContent('#readout'), /Distance 140\.000 mm .* angle 0\.00°/);
  await page.keyboard.press('Escape');
  assert.equal(await page.getAttribute('#measure', 'aria-pressed'), 'false');

  // The same with the keyboard alone: the hole's centre under the cross, Enter; arrow keys; Enter.
  await page.evaluate(() => window.kerfcam.centreOn(30, 30));
  await page.locator('#preview').focus();
  await page.keyboard.press('m');
  await page.keyboard.press('Enter');
  await page.evaluate(() => window.kerfcam.centreOn(30.3, 90.2)); // the hole at (30, 90), a little off
  await page.keyboard.press('Enter');
  await page.waitForFunction(() => Math.abs(window.kerfcam.lastMeasure()?.d - 60) < 1e-9);
  assert.ok(Math.abs((await page.evaluate(() => window.kerfcam.lastMeasure())).angle - 90) < 1e-9);
  await page.keyboard.press('Escape');
});

test('keyboard: + zooms, F fits, Space plays', async () => {
  const scaleOf = () => page.evaluate(() => {
    const a = window.kerfcam.screenOf(0, 0);
    const b = window.kerfcam.screenOf(100, 0);
    return (b[0] - a[0]) / 100;
  });
  await page.locator('#fit').focus();
  await page.keyboard.press('Tab'); // off the Fit button: shortcuts work anywhere but in fields
  const fitted = await scaleOf();
  await page.keyboard.press('+');
  assert.ok((await scaleOf()) > fitted * 1.2);
  await page.keyboard.press('f');
  assert.ok(Math.abs((await scaleOf()) - fitted) < 1e-9);
  await page.selectOption('#speed', '1'); // the animation outlasts the two key presses, as in i18n.test.mjs
  await page.locator('#preview').focus();
  await page.keyboard.press(' ');
  assert.equal(await page.getAttribute('#play', 'aria-pressed'), 'true');
  await page.keyboard.press(' ');
  assert.equal(await page.getAttribute('#play', 'aria-pressed'), 'false');
  // Typing in a field is never a shortcut.
  await page.locator('#kerf').focus();
  await page.keyboard.press('f');
  assert.equal(await page.getAttribute('#measure', 'aria-pressed'), 'false');
});

test('the job sheet shows the job and prints alone', async () => {
  await untilReady(page, () => page.setInputFiles('#file-input', PLATE));
  await page.click('#job-sheet');
  await page.waitForFunction(() => !document.getElementById('sheet-view').hidden);
  const facts = await page.$$eval('#sheet dd[data-key]', (dds) => Object.fromEntries(dds.map((d) => [d.dataset.key, d.textContent])));
  const report = await page.evaluate(() => window.kerfcam.lastReport);
  assert.equal(facts.file, path.basename(PLATE));
  assert.equal(facts.parts, '1');
  assert.equal(facts.holes, '6');
  assert.equal(facts.pierces, String(report.plan.pierces));
  assert.equal(facts.order, 'contour');
  assert.match(facts.kerf, /^1\.50 mm$/);
  assert.match(facts.post, /LinuxCNC/);
  assert.equal(await page.$$eval('#sheet tbody tr', (r) => r.length), report.plan.pierces, 'one row per pierce');
  await page.waitForFunction(() => document.querySelector('#sheet img')?.naturalWidth > 0);

  await page.emulateMedia({ media: 'print' });
  const shown = await page.evaluate(() => ({
    layout: getComputedStyle(document.querySelector('main.layout')).display,
    header: getComputedStyle(document.querySelector('header')).display,
    sheet: getComputedStyle(document.getElementById('sheet')).display,
    buttons: getComputedStyle(document.querySelector('.sheet-actions')).display,
  }));
  assert.deepEqual(shown, { layout: 'none', header: 'none', sheet: 'block', buttons: 'none' });
  const pdf = await page.pdf({ format: 'A4' });
  assert.ok(pdf.length > 10_000, `the sheet prints (${pdf.length} bytes of PDF)`);
  await page.emulateMedia({ media: 'screen' });
  await page.keyboard.press('Escape');
  assert.ok(await page.$eval('#sheet-view', (e) => e.hidden));

  // In Portuguese the order is named in Portuguese too (it read 'Ordem contour').
  await page.selectOption('#lang', 'pt-BR');
  await page.click('#job-sheet');
  await page.waitForFunction(() => !document.getElementById('sheet-view').hidden);
  assert.equal(await page.textContent('#sheet dd[data-key="order"]'), 'contorno a contorno');
  await page.keyboard.press('Escape');
  await page.selectOption('#lang', 'en');
});

test('no uncaught errors in the page', () => {
  assert.deepEqual(app.pageErrors.map((e) => e.message), []);
});
