// Sheet mode, sheets at a cost nested by two workers (issue 44 items 2 and 3), in Debian's headless
// chromium: the engine's worker holds the trials of the cheapest combination (the CLI's), and each
// combination is nested by both workers exchanging their best (nest-team.js runCheapest). Five 200 × 120
// plates on three 450 × 180 sheets at 7 and five 250 × 150 at 2: the five small sheets (10) hold them, as
// nest-cost.test.mjs finds with one worker. With an evaluation budget the same seed and worker count give
// the same nest twice; the Cost panel's quote and the job sheet's take the sheets' costs as the material,
// said so in English and Portuguese (the CLI's quote of the same kind of job: tests/wasm/nest.test.mjs);
// Stop during the trials ends both workers and keeps the best nest shown, on the combination it was
// nested on, with its cost. Screenshots of the quote go to tests/out/.
//
//   node scripts/browser-tests.mjs tests/browser/nest-cost-team.test.mjs

import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { test } from 'node:test';
import { pagePerFile, repoRoot, sheetVerbs } from './harness.mjs';
import { nestAndWait } from './helpers.mjs';

const PLATE = 'seed000-plate-6-holes.dxf'; // 200 × 120, six holes (../shared/fixtures/EXPECTED.md)
const OUT = path.join(repoRoot, 'tests', 'out');

let app;
let page;

pagePerFile((opened) => {
  app = opened;
  page = opened.page;
});

const { loadParts, typeSizes, text, ready } = sheetVerbs(() => page);

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
  await typeSizes([{ count: 3, cost: 7 }, { width: 250, height: 150, count: 5, cost: 2 }]);
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

test('the Cost panel and the job sheet quote the sheets the nest chose at their cost, said so', async () => {
  // The shop's prices, material at 40 BRL/m²: not applied, the sheets were bought at their cost.
  await page.selectOption('#cost-material_unit', 'm2');
  const prices = { machine_per_hour: '90', per_pierce: '0.05', per_metre: '0.2', material_price: '40', setup_per_sheet: '10', markup_percent: '20' };
  for (const [field, value] of Object.entries(prices)) await page.fill(`#cost-${field}`, value);
  const q = await page.waitForFunction(() => {
    const q = window.kerfcam.quote?.();
    return q && q.copies.length === 5 && q.model.markup_percent === 20 ? q : null;
  }).then((h) => h.jsonValue());
  const n = await page.evaluate(() => window.kerfcam.lastNest);
  assert.equal(q.material_share, 'sheet_cost');
  assert.equal(q.job.material, n.sheet_cost);
  assert.deepEqual(q.sheets.map((s) => s.material), [2, 2, 2, 2, 2]);
  const job = await page.$eval('#cost-result .cost-money tr.cost-job', (tr) => [...tr.cells].map((c) => c.textContent));
  assert.equal(job[2], '10.00', `the job's material: ${job}`);
  const said = 'material: the 5 sheet(s) the nest chose, at the costs given with the sheets (10.00 BRL in all)';
  const notes = () => page.$$eval('#cost-result .cost-note', (ps) => ps.map((p) => p.textContent));
  assert.ok((await notes()).some((t) => t.startsWith(said)), (await notes()).join(' | '));
  assert.ok(!(await notes()).some((t) => /own area|share, by area, of the sheet used/.test(t)), 'no other material basis is said');
  // Said at the material fields too, which the quote does not apply.
  assert.match(await page.$eval('#cost-sheet-cost', (e) => (e.hidden ? '' : e.textContent)), /^The nest's sheets have a cost each/);
  await shootCost('en');
  // On the job sheet, the same quote and words.
  await page.click('#job-sheet');
  await page.waitForSelector('#sheet .cost-table tbody tr');
  const printed = await page.$$eval('#sheet .cost-note', (ps) => ps.map((p) => p.textContent));
  assert.ok(printed.some((t) => t.startsWith(said)), printed.join(' | '));
  assert.equal(await page.$eval('#sheet .cost-table tr.cost-job', (tr) => tr.cells[5].textContent), '10.00 BRL');
  await page.click('#sheet-close');
  // In Portuguese.
  await page.selectOption('#lang', 'pt-BR');
  await page.waitForFunction(() => [...document.querySelectorAll('#cost-result .cost-note')].some((p) => p.textContent.startsWith('material: a(s) 5 chapa(s)')));
  assert.ok((await notes()).some((t) => t.startsWith('material: a(s) 5 chapa(s) escolhida(s) pelo encaixe, aos custos dados com as chapas (10,00 BRL ao todo)')));
  assert.equal(await page.$eval('#cost-result .cost-money tr.cost-job', (tr) => tr.cells[2].textContent), '10,00');
  assert.match(await page.$eval('#cost-sheet-cost', (e) => (e.hidden ? '' : e.textContent)), /^As chapas do encaixe têm um custo cada/);
  // Every column shows in the panel in Portuguese too (its heads are the longer): no sideways scroll.
  await shootCost('pt-BR');
  const fit = await page.$eval('#cost-result', (r) => [...r.querySelectorAll('table')].map((tb) => tb.getBoundingClientRect().right <= r.closest('.panel').getBoundingClientRect().right));
  await page.selectOption('#lang', 'en');
  assert.deepEqual(fit, [true, true]);
  assert.deepEqual(app.pageErrors, []);
});

/** The Cost panel's quote at 1366 × 768, to tests/out/nest-cost-quote-LANG-1366x768.png. */
async function shootCost(lang) {
  fs.mkdirSync(OUT, { recursive: true });
  const viewport = page.viewportSize();
  await page.setViewportSize({ width: 1366, height: 768 });
  await page.$eval('#cost-material_share', (e) => e.scrollIntoView({ block: 'start' }));
  await page.screenshot({ path: path.join(OUT, `nest-cost-quote-${lang}-1366x768.png`) });
  await page.setViewportSize(viewport);
}

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
