// Sheet mode, sheets at a cost (issue 44 item 3), in Debian's headless chromium as a shop uses it: the
// currency set in Cost and time (BRL), then two sheet sizes typed with a cost each: three 450 × 180
// sheets at 7 (two 200 × 120 plates each) and five 250 × 150 at 2 (one plate each). Filled in order, five
// plates take three big sheets (21); the cheapest sheets that hold them are the five small ones (10), and
// the page takes those, as `kerfcam nest --sheet 450x180:3:7 --sheet 250x150:5:2` does. A cost typed
// wrong, or given for one size and not the other, is said at its field, in English and Portuguese; the
// nest saved and opened again keeps the costs and the choice; Stop during the trials keeps the nest on the
// combination it was trying, with its cost. Screenshots of the panel go to tests/out/.
//
//   node --test tests/browser/nest-cost.test.mjs

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

/** The message said at field `id` (its .field-error), or null. */
const saidAt = (id) => page.$eval('#nest-form', (f, i) => f.querySelector(`.field-error[data-for="${i}"]`)?.textContent ?? null, id);
const invalid = (id) => page.$eval(`#${id}`, (e) => e.getAttribute('aria-invalid'));

test('two sheet sizes with a cost each: the cheapest that hold the parts are taken, said with their cost', async () => {
  await page.fill('#cost-currency', 'BRL');
  // A nest the same from run to run: 400 evaluations, 25 for each combination tried (1/16).
  // One worker: the engine's own route through the trials (nest-cost-team.test.mjs has two).
  await page.evaluate(() => Object.assign(window.kerfcam, { nestWorkers: 1, nestEvaluations: 400 }));
  await loadParts({ [PLATE]: 5 }, { sheet: [450, 180], time: 60 });
  assert.equal(await text('#sheet-cost-unit'), 'BRL');
  assert.match(await text('#sheet-cost-help'), /^Optional\. In BRL, the currency of Cost and time\./);
  await typeSizes([{ count: 3, cost: 7 }, { width: 250, height: 150, count: 5 }]);
  assert.equal(await page.$eval('label[for="sheet-size-1-cost"]', (e) => e.firstChild.textContent), 'Cost, BRL');

  // A cost for one size and not the other: the CLI's rule, said at the blank field; nothing runs.
  await page.click('#nest-run');
  await page.waitForSelector('#nest-message:not([hidden])');
  assert.equal(await saidAt('sheet-size-1-cost'), 'Size 2: Cost: give a cost for every sheet size or for none.');
  assert.equal(await invalid('sheet-size-1-cost'), 'true');
  assert.equal(await saidAt('sheet-cost'), null, 'the field with a cost is not blamed');
  // A cost that is not a price: said at its field.
  await page.fill('#sheet-size-1-cost', '-2');
  await page.click('#nest-run');
  await page.waitForFunction(() => document.querySelector('.field-error[data-for="sheet-size-1-cost"]')?.textContent.includes('price'));
  assert.equal(await saidAt('sheet-size-1-cost'), 'Size 2: Cost: enter a price of 0 or more, or leave it blank.');
  assert.match(await text('#nest-message'), /Size 2: Cost: enter a price/);
  assert.equal(await page.$eval('#nest-result', (e) => e.hidden), true, 'no nest');

  await page.fill('#sheet-size-1-cost', '2');
  await nestAndWait(page);
  await ready();
  assert.equal(await saidAt('sheet-size-1-cost'), null, 'the message goes once the cost is right');
  assert.equal(await invalid('sheet-size-1-cost'), 'false');
  const n = await page.evaluate(() => window.kerfcam.lastNest);
  assert.equal(n.placed, 5);
  assert.deepEqual(n.stock.map((s) => [s.width, s.height, s.in_stock, s.cost, s.used]), [[450, 180, 3, 7, 0], [250, 150, 5, 2, 5]]);
  assert.equal(n.sheet_cost, 10);
  assert.ok(n.combinations_passed_over >= 1, 'cheaper combinations (four small sheets: 8) were tried first');
  assert.deepEqual(n.sheets.map((s) => [s.width, s.height, s.parts]), Array(5).fill([250, 150, 1]));
  assert.equal(await text('#nest-figures [data-key="stock"]'), '5 × 250 × 150 mm at 2.00 BRL each');
  const passed = n.combinations_passed_over;
  const plural = passed === 1 ? '1 cheaper combination did not' : `${passed} cheaper combinations did not`;
  assert.equal(await text('#nest-figures [data-key="sheet-cost"]'), `10.00 BRL (${plural} hold every copy)`);
  assert.equal(await page.$eval('#nest-result', (e) => e.dataset.sheetCost), '10');
  await shoot('en');

  // In Portuguese: the result, the fields' words, and a cost typed wrong said at its field.
  await page.selectOption('#lang', 'pt-BR');
  assert.equal(await text('#nest-figures [data-key="stock"]'), '5 × 250 × 150 mm a 2,00 BRL cada');
  assert.match(await text('#nest-figures [data-key="sheet-cost"]'), /^10,00 BRL \(\d+ combinaç(ão|ões) mais barata/);
  assert.match(await text('#sheet-cost-help'), /^Opcional\. Em BRL, a moeda de Custo e tempo\./);
  assert.equal(await page.$eval('label[for="sheet-size-1-cost"]', (e) => e.firstChild.textContent), 'Custo, BRL');
  await shoot('pt-BR');
  // The currency cleared in Cost and time: the figures say so once, on the total, not on every size too.
  await page.fill('#cost-currency', '');
  assert.equal(await text('#nest-figures [data-key="stock"]'), '5 × 250 × 150 mm a 2,00 cada');
  assert.match(await text('#nest-figures [data-key="sheet-cost"]'), /^10,00 \(nenhuma moeda definida em Custo e tempo; \d+ combinaç(ão|ões) mais barata/);
  assert.equal((await text('#nest-figures')).split('nenhuma moeda').length, 2, 'the missing currency said once');
  await page.fill('#cost-currency', 'BRL');
  assert.equal(await text('#nest-figures [data-key="stock"]'), '5 × 250 × 150 mm a 2,00 BRL cada');
  await page.fill('#sheet-cost', 'sete');
  await page.click('#nest-run');
  await page.waitForFunction(() => document.querySelector('.field-error[data-for="sheet-cost"]'));
  assert.equal(await saidAt('sheet-cost'), 'Custo por chapa: informe um preço de 0 ou mais, ou deixe em branco.');
  await shoot('pt-BR', 'error', [[1366, 768]]);
  await page.fill('#sheet-cost', '');
  await page.click('#nest-run');
  await page.waitForFunction(() => document.querySelector('.field-error[data-for="sheet-cost"]')?.textContent.includes('nenhum'));
  assert.equal(await saidAt('sheet-cost'), 'Custo por chapa: informe um custo para cada tamanho de chapa ou para nenhum.');
  await page.fill('#sheet-cost', '7');
  await page.selectOption('#lang', 'en');

  // Saved and opened again: the costs back in their fields, the same choice and cost.
  const [saved] = await Promise.all([page.waitForEvent('download'), page.click('#nest-save')]);
  const file = path.join(app.downloadDir, 'cost.kerfcam-nest.json');
  await saved.saveAs(file);
  const doc = JSON.parse(fs.readFileSync(file, 'utf8'));
  assert.deepEqual(doc.settings.sheet_list, [{ width: 450, height: 180, count: 3, cost: 7 }, { width: 250, height: 150, count: 5, cost: 2 }]);
  assert.deepEqual(doc.combination, [0, 5]);
  await page.fill('#sheet-cost', '99');
  await page.fill('#sheet-size-1-cost', '98');
  await page.evaluate(() => (window.kerfcam.lastNest = null));
  await page.setInputFiles('#nest-open-input', file);
  await page.waitForFunction(() => window.kerfcam.lastNest !== null, null, { timeout: 30_000 });
  await ready();
  assert.equal(await page.inputValue('#sheet-cost'), '7');
  assert.deepEqual(await page.$$eval('#sheet-sizes li input', (l) => l.map((e) => e.value)), ['250', '150', '5', '2']);
  const back = await page.evaluate(() => window.kerfcam.lastNest);
  assert.deepEqual([back.stock, back.sheet_cost, back.flat], [n.stock, n.sheet_cost, n.flat]);
  assert.equal(await text('#nest-figures [data-key="sheet-cost"]'), `10.00 BRL (${plural} hold every copy)`);
  assert.deepEqual(app.pageErrors, []);
});

test('Stop during the trials keeps the nest on the combination being tried, with its cost', async () => {
  // No evaluation budget: a long search, stopped once a combination is being tried.
  await page.evaluate(() => (window.kerfcam.nestEvaluations = null));
  await page.fill('#nest-time', '600');
  await page.evaluate(() => (window.kerfcam.lastNest = null));
  await page.click('#nest-run');
  await page.waitForFunction(() => /trying \d/.test(document.getElementById('nest-progress').textContent), null, { timeout: 30_000 });
  await page.click('#nest-stop');
  await page.waitForFunction(() => window.kerfcam.lastNest !== null, null, { timeout: 60_000 });
  await ready();
  const n = await page.evaluate(() => window.kerfcam.lastNest);
  // Its sheets are the combination's (so many of each size, in the list's order), and its cost theirs.
  const sizes = n.sheets.map((s) => `${s.width}x${s.height}`);
  const used = n.stock.flatMap((s) => Array(s.used).fill(`${s.width}x${s.height}`));
  assert.deepEqual(sizes, used);
  assert.equal(n.sheet_cost, n.stock.reduce((c, s) => c + s.used * s.cost, 0));
  assert.match(await text('#nest-figures [data-key="sheet-cost"]'), /^\d+\.00 BRL/);
  assert.deepEqual(app.pageErrors, []);
});

/**
 * The Sheet panel with the costs (`what`: 'fields' and the result, or 'error': the fields alone) at the two
 * window sizes asked (issue 44 item 3), to tests/out/nest-cost-LANG-WxH-*.png.
 */
async function shoot(lang, what = 'fields', sizes = [[1366, 768], [1920, 1080]]) {
  fs.mkdirSync(OUT, { recursive: true });
  const viewport = page.viewportSize();
  for (const [w, h] of sizes) {
    await page.setViewportSize({ width: w, height: h });
    await page.$eval('#sheet-preset', (e) => e.scrollIntoView({ block: 'start' }));
    await page.screenshot({ path: path.join(OUT, `nest-cost-${lang}-${w}x${h}-${what}.png`) });
    if (what !== 'fields') continue;
    await page.$eval('#nest-result', (e) => e.scrollIntoView({ block: 'start' }));
    await page.screenshot({ path: path.join(OUT, `nest-cost-${lang}-${w}x${h}-result.png`) });
  }
  await page.setViewportSize(viewport);
}
