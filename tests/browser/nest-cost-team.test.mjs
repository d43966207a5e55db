// Sheet mode, sheets at a cost nested by two workers (issue 44 items 2 and 3), in Debian's headless
// chromium: the engine's worker holds the trials of the cheapest combination (the CLI's), and each
// combination is nested by both workers exchanging their best (nest-team.js runCheapest). Five 200 × 120
// plates on three 450 × 180 sheets at 7 and five 250 × 150 at 2: the five small sheets (10) hold them, as
// nest-cost.test.mjs finds with one worker. With an evaluation budget the same seed and worker count give
// the same nest twice; Stop during the trials ends both workers and keeps the best nest shown, on the
// combination it was nested on, with its cost.
//
//   node scripts/browser-tests.mjs tests/browser/nest-cost-team.test.mjs

import assert from 'node:assert/strict';
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

/** The nest kept, checked again placement by placement by the engine's edit checker: its conflicts. */
const recheck = () => page.evaluate(async () => {
  const n = window.kerfcam.lastNest;
  const placements = [];
  for (let i = 0; i + 6 < n.flat.length; i += 7) placements.push(n.flat.slice(i, i + 7));
  const state = JSON.parse(await window.kerfcam.sheet.nest.hooks.engine().call('editNest', { json: JSON.stringify({ placements }) }));
  return state.conflicts.length;
});

test('two workers at a cost: the cheapest sheets, the same nest twice for the same seed', async () => {
  await page.fill('#cost-currency', 'BRL');
  // 400 evaluations a worker, 25 for each combination tried (1/16), the workers exchanging every 10: several
  // exchanges within each trial.
  await page.evaluate(() => Object.assign(window.kerfcam, { nestWorkers: 2, nestEvaluations: 400, nestExchangeEvery: 10 }));
  await loadParts({ [PLATE]: 5 }, { sheet: [450, 180], time: 600 });
  await page.fill('#sheet-count', '3');
  await page.fill('#sheet-cost', '7');
  await page.click('#sheet-size-add');
  await page.fill('#sheet-size-1-width', '250');
  await page.fill('#sheet-size-1-height', '150');
  await page.fill('#sheet-size-1-count', '5');
  await page.fill('#sheet-size-1-cost', '2');
  const nests = [];
  const combinations = [];
  for (let run = 0; run < 2; run++) {
    // Every combination the progress line said it was trying, in order.
    await page.evaluate(() => {
      const seen = (window.kerfcam.trialsSeen = []);
      const line = document.getElementById('nest-progress');
      window.kerfcam.trialsWatch?.disconnect();
      window.kerfcam.trialsWatch = new MutationObserver(() => {
        const m = /trying (.*?) \(/.exec(line.textContent);
        if (m && seen.at(-1) !== m[1]) seen.push(m[1]);
      });
      window.kerfcam.trialsWatch.observe(line, { childList: true, characterData: true, subtree: true });
    });
    await nestAndWait(page, 300_000);
    await ready();
    assert.equal(await page.evaluate(() => window.kerfcam.sheet.nest.workers), 2, 'the nest ran in two workers');
    nests.push(await page.evaluate(() => window.kerfcam.lastNest));
    combinations.push(await page.evaluate(() => window.kerfcam.trialsSeen));
  }
  const [a, b] = nests;
  assert.equal(a.placed, 5);
  assert.deepEqual(a.stock.map((s) => [s.width, s.height, s.in_stock, s.cost, s.used]), [[450, 180, 3, 7, 0], [250, 150, 5, 2, 5]]);
  assert.equal(a.sheet_cost, 10);
  assert.ok(a.combinations_passed_over >= 1, 'cheaper combinations (four small sheets: 8) were tried first');
  assert.ok(combinations[0].length >= 2, `the trials were shown as they ran: ${combinations[0].join(' / ')}`);
  assert.deepEqual([b.flat, b.stock, b.sheet_cost, b.combinations_passed_over, b.evaluations],
    [a.flat, a.stock, a.sheet_cost, a.combinations_passed_over, a.evaluations], 'the same nest for the same seed and workers');
  assert.deepEqual(combinations[1], combinations[0], 'the same trials in the same order');
  assert.equal(await recheck(), 0, 'no copy overlaps another or leaves its sheet');
  assert.equal(await text('#nest-figures [data-key="stock"]'), '5 × 250 × 150 mm at 2.00 BRL each');
  assert.deepEqual(app.pageErrors, []);
});

test('Stop during the trials of two workers keeps the nest on the combination being tried', async () => {
  // No evaluation budget: a long search, stopped once a combination is being tried.
  await page.evaluate(() => Object.assign(window.kerfcam, { nestEvaluations: null, nestExchangeEvery: null, lastNest: null }));
  await page.fill('#nest-time', '600');
  const t0 = Date.now();
  await page.click('#nest-run');
  await page.waitForFunction(() => /trying \d/.test(document.getElementById('nest-progress').textContent), null, { timeout: 60_000 });
  assert.equal(await page.evaluate(() => window.kerfcam.sheet.nest.workers), 2);
  await page.click('#nest-stop');
  await page.waitForFunction(() => window.kerfcam.lastNest !== null, null, { timeout: 60_000 });
  await ready();
  assert.ok(Date.now() - t0 < 300_000, 'stopped long before the 600 s budget');
  const n = await page.evaluate(() => window.kerfcam.lastNest);
  // Its sheets are the combination's (so many of each size, in the list's order), and its cost theirs.
  const sizes = n.sheets.map((s) => `${s.width}x${s.height}`);
  const used = n.stock.flatMap((s) => Array(s.used).fill(`${s.width}x${s.height}`));
  assert.deepEqual(sizes, used);
  assert.equal(n.sheet_cost, n.stock.reduce((c, s) => c + s.used * s.cost, 0));
  assert.match(await text('#nest-figures [data-key="sheet-cost"]'), /^\d+\.00 BRL/);
  assert.equal(await recheck(), 0, 'the stopped nest is valid');
  assert.equal(await page.$eval('#nest-run', (e) => e.disabled), false);
  assert.deepEqual(app.pageErrors, []);
});
