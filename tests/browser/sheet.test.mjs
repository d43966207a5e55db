// Sheet mode (issue 18), in Debian's headless chromium, the way a shop operator uses it: switch to
// Sheet, drop two fixture parts, refuse an absurd quantity, nest 5 + 3 copies on a 1000 × 500 sheet
// with a short budget, see the progress line then the result (counts, utilisation per sheet and for the
// job), the nest's sheet on the preview as the cut plan, and download its program, which rs274 accepts
// and which is the very plan previewed. Stop keeps the best nest. Both languages.
//
//   node --test tests/browser/sheet.test.mjs

import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { after, before, test } from 'node:test';
import { assertRs274Accepts, openApp, partRow, sheetVerbs } from './harness.mjs';
import { nestAndWait as nestAndWaitOn } from './helpers.mjs';

const PLATE = 'seed000-plate-6-holes.dxf';
const CHAMFER = 'seed001-P51703.dxf';
// The parts' areas from ../shared/fixtures/EXPECTED.md, not from the code under test: the plate's
// outline 23806.86 less four Ø12 holes, the slot and the 20 × 15 hole; P51703 is the 200 × 200 square
// less the 160 × 160 / 2 chamfer triangle.
const AREA = { 'seed000-plate-6-holes': 23806.86 - 4 * 113.097 - 1114.16 - 300, 'seed001-P51703': 200 * 200 - 160 * 160 / 2 };

let app;
let page;
const nestAndWait = (timeout) => nestAndWaitOn(page, timeout);

before(async () => {
  app = await openApp();
  page = app.page;
});

after(async () => {
  await app?.close();
});

const { drop, text } = sheetVerbs(() => page);

/** Starts watching a status line: every text it shows is kept in window.seenLines[id]. */
const watch = (id) => page.evaluate((id) => {
  window.seenLines ??= {};
  const seen = (window.seenLines[id] = []);
  const node = document.getElementById(id);
  new MutationObserver(() => seen.push(node.textContent)).observe(node, { childList: true, characterData: true, subtree: true });
}, id);

test('Sheet mode: parts with quantities, a nest on 1000 × 500, its program through rs274', async () => {
  // The mode strip, by keyboard.
  await page.focus('#mode-sheet');
  await page.keyboard.press('Enter');
  assert.equal(await page.getAttribute('#mode-sheet', 'aria-pressed'), 'true');
  assert.equal(await page.isVisible('#panel-sheet'), true);
  assert.equal(await page.isVisible('#panel-drawing'), false, 'the files list gives way to the parts list');
  assert.equal(await page.isDisabled('#origin'), true, "the program's zero is the sheet's corner");
  assert.equal(await page.isDisabled('#units'), true, 'the nest is in mm');
  // The empty preview says what to do here: parts, then Nest (not "a DXF file to see the cutting plan").
  const placeholder = () => page.$$eval('#placeholder p', (ps) => ps.filter((p) => p.getClientRects().length).map((p) => p.textContent));
  assert.match((await placeholder())[0], /^Open or drop the parts \(DXF or SVG\), then Nest: /);
  await page.click('#mode-drawing');
  assert.match((await placeholder())[0], /^Open or drop a DXF or SVG file to see the cutting plan\.$/);
  await page.click('#mode-sheet');

  // Dropped files become parts, each with its units.
  await drop(PLATE);
  await drop(CHAMFER);
  for (const name of [PLATE, CHAMFER]) await page.waitForSelector(`${partRow(name)} [data-units]`);
  assert.equal(await page.$eval(`${partRow(PLATE)} [data-units]`, (e) => e.dataset.units), 'mm');
  assert.match(await text(partRow(PLATE)), /1 part: seed000-plate-6-holes/);
  assert.equal(await page.$$eval('#panel-drawing #jobs li.job', (l) => l.length), 0, 'parts are not single-drawing jobs');

  // Absurd and non-integer quantities are refused with a message, and no nest starts.
  const qty = (name) => `${partRow(name)} input.qty`;
  for (const bad of ['2.5', '99999', '-3', 'abc']) {
    await page.fill(qty(PLATE), bad);
    assert.equal(await page.getAttribute(qty(PLATE), 'aria-invalid'), 'true', bad);
    assert.match(await text(`${partRow(PLATE)} .error-text`), /whole number from 1 to 10000/);
  }
  await page.click('#nest-run');
  assert.match(await text('#nest-message'), /Quantity of seed000-plate-6-holes\.dxf: enter a whole number/);
  assert.equal(await page.isVisible('#nest-result'), false);

  await page.fill(qty(PLATE), '5');
  assert.equal(await page.getAttribute(qty(PLATE), 'aria-invalid'), 'false');
  await page.fill(qty(CHAMFER), '3');
  await page.selectOption(`${partRow(CHAMFER)} select`, 'free');
  // The sheet: a preset fills W × H, typing makes it custom; spacing follows the kerf (1.5 + 1).
  assert.equal(await text('#sheet-preset option[value="48x96"]'), '48" × 96" (2438.4 × 1219.2 mm)');
  await page.selectOption('#sheet-preset', '48x96');
  assert.deepEqual([await page.inputValue('#sheet-w'), await page.inputValue('#sheet-h')], ['2438.4', '1219.2']);
  await page.selectOption('#sheet-preset', '2000x1000');
  assert.equal(await page.inputValue('#sheet-w'), '2000');
  await page.fill('#sheet-w', '1000');
  await page.fill('#sheet-h', '500');
  assert.equal(await page.inputValue('#sheet-preset'), 'custom');
  assert.equal(await page.inputValue('#nest-spacing'), '2.5');
  await page.click('#common-line');
  assert.equal(await page.inputValue('#nest-spacing'), '1.5', 'common line: spacing = kerf');
  await page.click('#spacing-default');
  assert.equal(await page.inputValue('#nest-spacing'), '2.5');
  // The margin's default is the engine's, the same as `kerfcam nest`'s (5 mm), not one of the page's own.
  assert.equal(await page.inputValue('#nest-margin'), '5');
  await page.fill('#nest-time', '3');

  await watch('nest-progress');
  await nestAndWait();
  const seen = await page.evaluate(() => window.seenLines['nest-progress']);
  assert.ok(seen.some((l) => /\d s · 1 sheet · .* nests tried/.test(l)), `progress lines: ${seen.join(' | ')}`);
  assert.match(await text('#nest-progress'), /^Done: \d+\.\d s, \d+ nests tried; the best nest was found at \d+\.\d s\.$/);

  // The result: 8 copies placed on one sheet, counts and utilisation as the engine found them.
  const nest = await page.evaluate(() => window.kerfcam.lastNest);
  const box = await page.$eval('#nest-result', (e) => ({ ...e.dataset }));
  assert.equal(box.asked, '8');
  assert.equal(nest.placed, 8, JSON.stringify(nest.unplaced));
  assert.equal(box.placed, '8');
  assert.equal(nest.sheets.length, 1);
  assert.match(await text('#nest-figures [data-key="placed"]'), /^8 of 8$/);
  assert.equal(await page.$eval('#nest-unplaced', (e) => e.dataset.count), '0');
  const sheet = nest.sheets[0];
  assert.equal(sheet.parts, 8);
  assert.ok(sheet.utilisation > 0 && sheet.utilisation <= 1, String(sheet.utilisation));
  assert.match(await text('#nest-sheets li'), new RegExp(`Sheet 1: 8 parts, ${(100 * sheet.utilisation).toFixed(1)} %`));
  // The job's utilisation, from the fixtures' own areas: on one sheet it is the sheet's.
  const partsArea = nest.placements.reduce((a, p) => a + AREA[p.part], 0);
  const useful = partsArea / sheet.utilisation;
  const job = partsArea / useful;
  assert.ok(Math.abs(Number(box.utilisation) - job) < 1e-3, `${box.utilisation} vs ${job}`);
  assert.equal(await text('#nest-figures [data-key="utilisation"]'), `${(100 * job).toFixed(1)} %`);
  // Every placement is inside the sheet less its margin (5 mm, the engine's default) as far as its translation says.
  for (const p of nest.placements) assert.equal(p.sheet, 0);

  // The nest's sheet is the cut plan on the preview: 8 parts with their 6 + 0 holes each.
  const report = await page.evaluate(() => window.kerfcam.lastReport);
  assert.equal(report.plan.parts, 8, JSON.stringify(report.plan));
  assert.equal(report.plan.holes, 5 * 6);
  assert.equal(await page.isEnabled('#play'), true);
  assert.equal(await page.isEnabled('#job-sheet'), true);
  assert.match(await text('#glance [data-key="file"]'), /nest-sheet-1/);

  // The downloaded program is the previewed plan, and LinuxCNC's interpreter reads it.
  const [download] = await Promise.all([page.waitForEvent('download'), page.click('#download')]);
  assert.equal(download.suggestedFilename(), 'nest-sheet-1.ngc');
  const file = path.join(app.downloadDir, download.suggestedFilename());
  await download.saveAs(file);
  const gcode = fs.readFileSync(file, 'utf8');
  assert.equal(gcode, await page.evaluate(() => window.kerfcam.lastGcode));
  const pierces = gcode.split('\n').filter((l) => /^\s*(N\d+\s+)?M0?3\b/.test(l)).length;
  assert.equal(pierces, report.plan.pierces, 'one torch-on per pierce of the plan');
  assertRs274Accepts(file);

  // Compare the orders and the job sheet work on the nest's sheet as on one drawing.
  await page.click('#compare');
  await page.waitForSelector('#comparison tr[data-order="chained"]');
  await page.click('#job-sheet');
  await page.waitForFunction(() => !document.getElementById('sheet-view').hidden);
  // In Sheet mode the job sheet is the job report (issue 42 §4, job-report.test.mjs): the job, then the sheet
  // (its size, its utilisation, its program, parts × copies on it).
  await page.waitForSelector('#sheet .report-sheet');
  assert.equal(await text('#sheet .report-sheet [data-key="program"]'), 'nest-sheet-1.ngc');
  assert.equal(await text('#sheet .report-sheet [data-key="size"]'), '1000.0 × 500.0 mm');
  assert.equal(await text('#sheet .report-sheet [data-key="util"]'), `${(100 * sheet.utilisation).toFixed(1)} %`);
  assert.equal(await text('#sheet .report-job [data-key="job-util"]'), `${(100 * job).toFixed(1)} %`);
  assert.deepEqual(await page.$$eval('#sheet .report-sheet-parts tbody tr', (rows) => rows.map((r) => [r.cells[0].textContent, r.cells[1].textContent]).sort()),
    [['seed000-plate-6-holes', '5'], ['seed001-P51703', '3']]);
  await page.keyboard.press('Escape');

  // A cut setting changed re-plans the same nest (no new nest): the program follows the settings.
  await page.selectOption('#order', 'chained');
  await page.waitForFunction(() => window.kerfcam.lastReport?.plan?.order === 'chained' && document.getElementById('status').dataset.state === 'ready');
  assert.deepEqual(await page.evaluate(() => window.kerfcam.lastNest), nest);
  await page.selectOption('#order', 'contour');
  assert.deepEqual(app.pageErrors, []);
});

test('Stop keeps the best nest found so far', async () => {
  await page.fill('#nest-time', '120');
  await page.evaluate(() => (window.kerfcam.lastNest = null));
  await page.click('#nest-run');
  await page.waitForFunction(() => /nests tried/.test(document.getElementById('nest-progress').textContent));
  await page.waitForTimeout(1500);
  const t0 = Date.now();
  await page.click('#nest-stop');
  await page.waitForFunction(() => window.kerfcam.lastNest !== null && document.getElementById('status').dataset.state === 'ready', null, { timeout: 60_000 });
  const nest = await page.evaluate(() => window.kerfcam.lastNest);
  const best = await page.evaluate(() => window.kerfcam.sheet.nest.last); // the best nest the progress line showed
  assert.ok(Date.now() - t0 < 60_000);
  // The nest kept is the one the progress line last showed: its evaluations, sheets, copies left out and
  // length used on its last sheet.
  assert.equal(nest.evaluations, best.evaluations);
  assert.equal(nest.sheets.length, best.sheets);
  assert.equal(nest.unplaced.reduce((n, u) => n + u.copies, 0), best.unplaced);
  // (The search measures its parts grown by half the spacing; the figures, the parts themselves.)
  const gap = Math.abs(nest.sheets.at(-1).used_length - best.length);
  assert.ok(gap <= nest.spacing / 2 + 1e-6, `${nest.sheets.at(-1).used_length} vs ${best.length}`);
  assert.ok(nest.time_s < 60, `stopped, not run to the 120 s budget: ${nest.time_s}`);
  assert.equal(nest.placed, 8);
  assert.equal(await page.isVisible('#nest-stop'), false);
  assert.deepEqual(app.pageErrors, []);
});

// In one worker (a single-core PC) Stop replays the search to the count shown, with a longer clock and the
// run's budget (nest-run.js): the sequence search's share of the work is sized from the budget, so a replay
// sized from its longer clock switches to the separation later and keeps another nest than the one shown.
// A 20 s budget on a 60 s clock (window.kerfcam.nestBudget): 2500 evaluations took 10 s of a 20 s run on
// an idle machine, and 5100 about 17 s beside the native tests of a CI run, so the search could end before
// the Stop. Stopped past 2500 evaluations, past the sequence search of a 20 s budget, short of its full
// share (30 s): a replay given the full share failed this test when stopped past 2000, 3000 and 5100.
test('Stop in one worker on a short budget keeps the nest shown', async () => {
  await page.fill('#nest-time', '60');
  await page.evaluate(() => {
    window.kerfcam.nestBudget = 20;
    window.kerfcam.nestWorkers = 1;
    window.kerfcam.lastNest = null;
  });
  try {
    await page.click('#nest-run');
    await page.waitForFunction(() => (window.kerfcam.sheet.nest.last?.evaluations ?? 0) > 2500, null, { timeout: 60_000 });
    await page.click('#nest-stop');
    await page.waitForFunction(() => window.kerfcam.lastNest !== null && document.getElementById('status').dataset.state === 'ready', null, { timeout: 60_000 });
    assert.equal(await page.evaluate(() => window.kerfcam.sheet.nest.workers), 1);
    const nest = await page.evaluate(() => window.kerfcam.lastNest);
    const best = await page.evaluate(() => window.kerfcam.sheet.nest.last);
    assert.equal(nest.evaluations, best.evaluations);
    const gap = Math.abs(nest.sheets.at(-1).used_length - best.length);
    assert.ok(gap <= nest.spacing / 2 + 1e-6, `${nest.sheets.at(-1).used_length} vs ${best.length}`);
    assert.equal(nest.placed, 8);
  } finally {
    await page.evaluate(() => {
      delete window.kerfcam.nestWorkers;
      delete window.kerfcam.nestBudget;
    });
  }
  assert.deepEqual(app.pageErrors, []);
});

test('a part larger than the sheet is listed with the reason, the rest nests on several sheets, each one cut', async () => {
  // 400 × 180 less the 5 mm margin: one plate (200 × 120) per sheet, P51703 (200 × 200) on none.
  await page.selectOption(`${partRow(CHAMFER)} select`, '90');
  await page.fill('#sheet-w', '400');
  await page.fill('#sheet-h', '180');
  await page.fill('#nest-time', '2');
  await nestAndWait();
  const nest = await page.evaluate(() => window.kerfcam.lastNest);
  assert.equal(nest.placed, 5);
  assert.equal(nest.sheets.length, 5);
  assert.match(await text('#nest-figures [data-key="placed"]'), /^5 of 8$/);
  assert.equal(await page.$eval('#nest-unplaced', (e) => e.dataset.count), '3');
  assert.match(await text('#nest-unplaced'), /seed001-P51703: 3 copies: larger than the sheet 400 × 180 mm at every allowed rotation/);
  // The reason follows the page's language, also when it changes after the nest.
  await page.selectOption('#lang', 'pt-BR');
  assert.match(await text('#nest-unplaced'), /seed001-P51703: 3 cópias: maior que a chapa 400 × 180 mm em todas as rotações permitidas, com margem de 5 mm/);
  await page.selectOption('#lang', 'en');
  assert.match(await text('#nest-unplaced'), /seed001-P51703: 3 copies: larger than the sheet 400 × 180 mm/);
  assert.equal(await page.$$eval('#nest-sheets li', (l) => l.length), 5);
  // The sheets as tabs over the nest view, each with its utilisation; the job's beside them.
  assert.equal(await page.$$eval('#nest-tabs [role="tab"]', (l) => l.length), 5);
  for (const [k, s] of nest.sheets.entries()) {
    assert.equal(await text(`#nest-tab-${k}`), `Sheet ${k + 1} · ${(100 * s.utilisation).toFixed(1)} %`);
  }
  assert.equal(await page.$eval('#nest-tab-0', (e) => e.getAttribute('aria-selected')), 'true');
  assert.match(await text('#nest-tabs .nest-tab-job'), /^Job: \d+\.\d % used on 5 sheets$/);
  // Sheet 2 on the preview (its tab, by keyboard): its own plan and program.
  await page.evaluate(() => (window.kerfcam.lastReport = null));
  await page.focus('#nest-tab-0');
  await page.keyboard.press('ArrowRight');
  assert.equal(await page.$eval('#nest-tab-1', (e) => e.getAttribute('aria-selected')), 'true');
  assert.equal(await page.evaluate(() => document.activeElement.id), 'nest-tab-1', 'focus follows the tab picked');
  assert.equal(await page.$eval('#nest-canvas svg', (e) => e.dataset.sheet), '1');
  await page.waitForFunction(() => window.kerfcam.lastReport !== null && document.getElementById('status').dataset.state === 'ready');
  assert.match(await text('#glance [data-key="file"]'), /nest-sheet-2/);
  const report = await page.evaluate(() => window.kerfcam.lastReport);
  assert.equal(report.plan.parts, 1);
  assert.equal(report.plan.holes, 6);
  const [download] = await Promise.all([page.waitForEvent('download'), page.click('#download')]);
  assert.equal(download.suggestedFilename(), 'nest-sheet-2.ngc');
  const file = path.join(app.downloadDir, download.suggestedFilename());
  await download.saveAs(file);
  assert.equal(fs.readFileSync(file, 'utf8'), await page.evaluate(() => window.kerfcam.lastGcode));
  assertRs274Accepts(file);
  // Back to the 1000 × 500 sheet for what follows.
  await page.fill('#sheet-w', '1000');
  await page.fill('#sheet-h', '500');
  await page.fill('#nest-time', '0');
  await nestAndWait();
  assert.deepEqual(app.pageErrors, []);
});

test('Sheet mode speaks Portuguese, and One drawing comes back', async () => {
  await page.selectOption('#lang', 'pt-BR');
  assert.equal((await text('#mode-sheet')).trim(), 'Chapa');
  assert.equal((await text('#nest-run')).trim(), 'Encaixar');
  assert.equal(await text('#sheet-preset option[value="60x120"]'), '60" × 120" (3048 × 1524 mm)');
  assert.equal(await text('#sheet-preset option[value="48x96"]'), '48" × 96" (2438,4 × 1219,2 mm)');
  assert.match(await text('#nest-progress'), /^Pronto: \d+,\d s, \d+ encaixes testados; o melhor encaixe foi achado em \d+,\d s\.$/);
  assert.match(await text('#nest-figures [data-key="placed"]'), /^8 de 8$/);
  assert.match(await text('#nest-sheets li'), /^Chapa 1: 8 peças, \d+,\d %$/);
  assert.equal(await text('#summary dd[data-key="units"]'), 'mm (um encaixe é em mm)', 'not "mm (de nest)"');
  assert.equal(await text('#summary dd[data-key="format"]'), 'uma chapa do encaixe do kerfcam', 'not "versão não informada"');
  await page.fill(`${partRow(PLATE)} input.qty`, '0');
  assert.match(await text(`${partRow(PLATE)} .error-text`), /número inteiro de 1 a 10000/);
  assert.equal(await page.isVisible('#nest-stale'), true);
  const missing = await page.evaluate(async () => (await import('./i18n.js')).missingKeys());
  assert.deepEqual(missing.filter((k) => /nest|mode/.test(k)), []);
  await page.selectOption('#lang', 'en');
  await page.click('#mode-drawing');
  assert.equal(await page.isVisible('#panel-drawing'), true);
  assert.equal(await page.isVisible('#panel-sheet'), false);
  assert.equal(await page.isEnabled('#origin'), true);
  assert.equal(await page.isEnabled('#units'), true);
  assert.equal(await page.isEnabled('#download'), false, 'no file in One drawing: nothing to download');
  assert.deepEqual(app.pageErrors, []);
});

test('back in Sheet mode the nest is on the preview again; after Cancel it is gone and said so', async () => {
  await page.evaluate(() => (window.kerfcam.lastReport = null));
  await page.click('#mode-sheet');
  await page.waitForFunction(() => window.kerfcam.lastReport !== null && document.getElementById('status').dataset.state === 'ready');
  assert.match(await text('#glance [data-key="file"]'), /nest-sheet-1/);
  assert.equal(await page.isEnabled('#download'), true);
  // The engine stopped (what Cancel does): the worker that held the nest is gone.
  await page.evaluate(() => window.kerfcam.sheet.nest.hooks.engine().cancel());
  await page.selectOption('#order', 'chained');
  await page.waitForFunction(() => !document.getElementById('nest-message').hidden);
  assert.match(await text('#nest-message'), /The nest was dropped .* Nest again/);
  assert.equal(await page.isVisible('#nest-result'), false);
  assert.equal(await page.isEnabled('#download'), false, 'no nest: no program to download');
  await page.selectOption('#order', 'contour');
  assert.deepEqual(app.pageErrors, []);
});
