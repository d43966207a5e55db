// The Cost panel (issue 42 §3) in Debian's headless chromium, as a shop meets it: a 100 × 50 plate
// with a 20 × 10 hole (4800 mm²) is planned; the shop's prices typed in give a quote whose job price is
// the one worked out here by hand from the report's plan (time, pierces, metres) and the part's area;
// the CSV downloaded says the same; a negative price is said at its field and the last good quote
// stays; the prices are kept over a reload; the job sheet prints the quote; the panel speaks
// Portuguese. In Sheet mode three copies nested are quoted with the sheet's share: their times sum to
// the sheet's, their material to the sheet used. A screenshot goes to tests/out/ to be looked at.
//
//   node --test tests/browser/cost.test.mjs

import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { after, before, test } from 'node:test';
import { openApp, repoRoot, untilReady } from './harness.mjs';
import { dropInPage, nestAndWait } from './helpers.mjs';

const OUT = path.join(repoRoot, 'tests', 'out');

function plate() {
  const out = ['0', 'SECTION', '2', 'HEADER', '9', '$INSUNITS', '70', '4', '0', 'ENDSEC', '0', 'SECTION', '2', 'ENTITIES'];
  const square = (x0, y0, w, h) => {
    const p = [[x0, y0], [x0 + w, y0], [x0 + w, y0 + h], [x0, y0 + h], [x0, y0]];
    for (let i = 0; i < 4; i++) out.push('0', 'LINE', '8', '0', '10', p[i][0], '20', p[i][1], '11', p[i + 1][0], '21', p[i + 1][1]);
  };
  square(0, 0, 100, 50);
  square(40, 20, 20, 10);
  out.push('0', 'ENDSEC', '0', 'EOF');
  return { name: 'plate.dxf', mimeType: 'application/dxf', buffer: Buffer.from(out.join('\n') + '\n') };
}

const PRICES = {
  currency: 'EUR', machine_per_hour: '90', per_pierce: '0.05', per_metre: '0.2', material_price: '40',
  setup_per_sheet: '10', markup_percent: '20',
};

let app;
let page;

before(async () => {
  app = await openApp({ viewport: { width: 1366, height: 768 } });
  page = app.page;
});

after(async () => {
  await app?.close();
});

/** Waits until the panel's quote is one whose job price differs from `not` (null: any quote). */
const quoteAfter = (not) => page.waitForFunction((p) => {
  const q = window.kerfcam.quote?.();
  return q && q.job.price !== p ? q : null;
}, not).then((h) => h.jsonValue());

test('a one-part job is quoted as worked by hand, exported, kept and printed', async () => {
  await untilReady(page, () => page.setInputFiles('#file-input', plate()));
  assert.match(await page.textContent('#cost-result'), /Fill in the prices/);

  await page.selectOption('#cost-material_unit', 'm2');
  for (const [field, value] of Object.entries(PRICES)) await page.fill(`#cost-${field}`, value);
  const q = await quoteAfter(null);

  // By hand, from the report's plan (its time is rounded to 0.1 s, its lengths to a micrometre).
  const plan = (await page.evaluate(() => window.kerfcam.lastReport)).plan;
  assert.equal(plan.pierces, 2);
  const metres = (plan.cut_length + plan.lead_length) / 1000;
  const cost = 90 * plan.est_time_s / 3600 + 2 * 0.05 + metres * 0.2 + 4800 / 1e6 * 40 + 10;
  assert.ok(Math.abs(q.job.price - cost * 1.2) < 0.01, `${q.job.price} vs ${cost * 1.2}`);
  assert.equal(q.currency, 'EUR');
  assert.equal(q.parts.length, 1);
  assert.equal(q.parts[0].name, 'plate#1');
  // The side panel's two tables, the work and the money, row for row; the currency said in the heads.
  const cells = (table) => page.$$eval(`#cost-result .${table} tr`, (trs) => trs.map((tr) => [...tr.cells].map((c) => c.textContent)));
  const [work, money] = [await cells('cost-work'), await cells('cost-money')];
  assert.deepEqual(work.map((r) => r[0]), ['Part', 'plate#1', 'Sheet 1', 'Job']);
  assert.deepEqual(money.map((r) => r[0]), ['Part', 'plate#1', 'Sheet 1', 'Job']);
  assert.deepEqual(work[0], ['Part', 'Time, min', 'Pierces', 'Cut (m)']);
  assert.deepEqual(money[0], ['Part', 'Qty', 'Material, EUR', 'Cost, EUR', 'Price, EUR']);
  assert.equal(money[3][4], q.job.price.toFixed(2));
  // Every column shows in the panel: neither table is wider than the panel (no sideways scroll).
  const fit = await page.$eval('#cost-result', (r) => [...r.querySelectorAll('table')].map((tb) => tb.getBoundingClientRect().right <= r.closest('.panel').getBoundingClientRect().right));
  assert.deepEqual(fit, [true, true]);

  // The CSV downloaded: its job row's price is the panel's.
  const [d] = await Promise.all([page.waitForEvent('download'), page.click('#cost-export')]);
  const file = path.join(app.downloadDir, d.suggestedFilename());
  await d.saveAs(file);
  assert.equal(d.suggestedFilename(), 'plate-quote.csv');
  const csv = fs.readFileSync(file, 'utf8').split('\r\n').map((r) => r.split(','));
  const price = csv[0].indexOf('price');
  const job = csv.find((r) => r[0] === 'job');
  assert.ok(Math.abs(Number(job[price]) - q.job.price) < 0.005, job.join(','));

  // A negative price: said at its field, the last good quote kept.
  await page.fill('#cost-per_pierce', '-1');
  await page.waitForSelector('#cost-form .field-error[data-field="per_pierce"]');
  assert.equal(await page.getAttribute('#cost-per_pierce', 'aria-invalid'), 'true');
  assert.match(await page.textContent('#cost-form .field-error'), /per_pierce.*negative/);
  assert.equal((await page.evaluate(() => window.kerfcam.quote())).job.price, q.job.price);
  await page.fill('#cost-per_pierce', '0.05');
  await page.waitForFunction(() => !document.querySelector('#cost-form .field-error'));

  // On the job sheet.
  await page.click('#job-sheet');
  // The sheet is filled once its picture is drawn (jobsheet.js awaits the preview): wait for its quote table.
  await page.waitForSelector('#sheet .cost-table tbody tr');
  const sheet = await page.$$eval('#sheet .cost-table tbody tr', (trs) => trs.map((tr) => tr.cells[0].textContent));
  assert.deepEqual(sheet, ['plate#1', 'Sheet 1', 'Job']);
  await page.click('#sheet-close');

  // In Portuguese.
  await page.selectOption('#lang', 'pt-BR');
  assert.equal(await page.textContent('#cost-heading'), 'Custo e tempo');
  assert.match(await page.textContent('#cost-result'), /Trabalho/);
  // Its CSV in the Brazilian convention: `;` between cells, `,` decimals, Portuguese headers, a byte order mark.
  await page.waitForFunction(() => !document.getElementById('cost-export').disabled);
  const [dPt] = await Promise.all([page.waitForEvent('download'), page.click('#cost-export')]);
  const filePt = path.join(app.downloadDir, `pt-${dPt.suggestedFilename()}`);
  await dPt.saveAs(filePt);
  const textPt = fs.readFileSync(filePt, 'utf8');
  assert.ok(textPt.startsWith('\ufeff'), 'a byte order mark');
  const csvPt = textPt.slice(1).split('\r\n').map((r) => r.split(';'));
  assert.deepEqual(csvPt[0].slice(0, 3), ['tipo', 'nome', 'quantidade']);
  const jobPt = csvPt.find((r) => r[0] === 'trabalho');
  assert.equal(jobPt[csvPt[0].indexOf('preço')], job[price].replace('.', ','), jobPt.join(';'));
  fs.mkdirSync(OUT, { recursive: true });
  await page.$eval('#panel-cost', (p) => p.scrollIntoView());
  await page.screenshot({ path: path.join(OUT, 'cost-1366x768-pt-BR.png') });
  await page.selectOption('#lang', 'en');

  // Kept over a reload.
  await page.reload();
  await page.waitForFunction(() => document.getElementById('status').textContent !== 'loading');
  assert.equal(await page.inputValue('#cost-machine_per_hour'), '90');
  assert.equal(await page.inputValue('#cost-material_unit'), 'm2');
  assert.deepEqual(app.pageErrors, []);
});

test('a nest is quoted per part and per sheet, each copy its share of the sheet', async () => {
  // The drawing on no sheet cannot take the sheet's share: said at the field, the quote kept.
  await untilReady(page, () => page.setInputFiles('#file-input', plate()));
  const drawn = await quoteAfter(null);
  await page.selectOption('#cost-material_share', 'sheet');
  await page.waitForSelector('#cost-form .field-error[data-field="material_share"]');
  assert.equal((await page.evaluate(() => window.kerfcam.quote())).job.price, drawn.job.price);

  await page.click('#mode-sheet');
  const { buffer, name } = plate();
  await page.evaluate(dropInPage, { name, base64: buffer.toString('base64') });
  await page.waitForFunction(() => document.querySelectorAll('#parts [data-units]').length === 1);
  await page.fill('#parts li.part:nth-child(1) input.qty', '3');
  await page.fill('#sheet-w', '400');
  await page.fill('#sheet-h', '300');
  await page.fill('#nest-time', '0');
  await nestAndWait(page);
  const q = await page.waitForFunction(() => {
    const q = window.kerfcam.quote?.();
    return q && q.copies.length === 3 ? q : null;
  }).then((h) => h.jsonValue());
  assert.equal(q.material_share, 'sheet');
  assert.equal(q.parts.length, 1);
  assert.equal(q.parts[0].quantity, 3);
  const sum = (k) => q.copies.reduce((a, c) => a + c[k], 0);
  assert.ok(Math.abs(sum('time_s') - q.sheets[0].time_s) < 1e-9, `${sum('time_s')} vs ${q.sheets[0].time_s}`);
  assert.ok(Math.abs(sum('material_m2') - q.sheets[0].used_m2) < 1e-9);
  const rows = await page.$$eval('#cost-result .cost-work tbody tr', (trs) => trs.map((tr) => tr.cells[0].textContent));
  assert.equal(rows.length, 3, JSON.stringify(rows)); // the part, the sheet, the job
  assert.equal(rows[1], 'Sheet 1');
  assert.match(await page.textContent('#cost-result'), /share, by area, of the sheet used/);
  await page.selectOption('#cost-material_share', 'area');
  assert.deepEqual(app.pageErrors, []);
});
