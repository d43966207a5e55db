// The job report (issue 42 §4) and Sheet mode on a shop screen (§5), in Debian's headless chromium at
// 1366 × 768 as a shop uses it. Five plates, two to a 450 × 180 sheet, labelled and priced, make three
// sheets; the job sheet is then the job report: a page for the job (parts ordered and placed, sheets, totals,
// quote) and one per sheet whose figures are the page's own when that sheet is shown (its plan's pierces,
// time and lengths, the nest's utilisation and copies, the program name its Download gives, the labels on
// its map); printed to PDF it has one page per sheet plus the job's; it speaks Portuguese with a decimal
// comma. Then the view switch: the nest, the cut plan or both, each canvas inside the window with no page
// scroll, the choice kept over a reload; screenshots at 1366 × 768 and 1920 × 1080 in both languages go to
// tests/out/ to be looked at. Bad input: a quantity or a price that is not a number is said at its field,
// and the last good nest and quote stay.
//
//   node --test tests/browser/job-report.test.mjs

import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { test } from 'node:test';
import { pagePerFile, partRow, repoRoot, sheetVerbs } from './harness.mjs';
import { nestAndWait } from './helpers.mjs';

const OUT = path.join(repoRoot, 'tests', 'out');
const PLATE = 'seed000-plate-6-holes.dxf'; // 200 × 120, six holes (../shared/fixtures/EXPECTED.md)
const PRICES = { currency: 'EUR', machine_per_hour: '90', per_pierce: '0.05', per_metre: '0.2', material_price: '40', setup_per_sheet: '10', markup_percent: '20' };

let app;
let page;

pagePerFile((opened) => {
  app = opened;
  page = opened.page;
}, { viewport: { width: 1366, height: 768 } });

const { dropBytes, loadParts, text, nest, ready } = sheetVerbs(() => page);
const PER = 7; // numbers per copy in lastNest.flat: part, copy, sheet, rotation, mirror, x, y

/** Sheet k picked and its plan on the preview: the page's own figures of it, and the name its Download gives. */
async function shown(k) {
  await page.click(`#nest-tab-${k}`);
  await page.waitForFunction((name) => document.getElementById('status').dataset.state === 'ready'
    && window.kerfcam.lastReport && document.querySelector('#glance [data-key="file"]')?.textContent.includes(name), `nest-sheet-${k + 1}`);
  const plan = (await page.evaluate(() => window.kerfcam.lastReport)).plan;
  const [d] = await Promise.all([page.waitForEvent('download'), page.click('#download')]);
  return { plan, program: d.suggestedFilename() };
}

/** Pages of a PDF: its /Type /Page objects (not the /Pages tree). */
const pdfPages = (bytes) => (bytes.toString('latin1').match(/\/Type\s*\/Page(?![a-zA-Z])/g) || []).length;

test('the job report: a page for the job, one per sheet with the page\'s own figures, printed one page each', async () => {
  await loadParts({ [PLATE]: 5 }, { sheet: [450, 180], time: 0 });
  await page.check('#labels-on');
  await page.selectOption('#cost-material_unit', 'm2');
  for (const [field, value] of Object.entries(PRICES)) await page.fill(`#cost-${field}`, value);
  await nestAndWait(page);
  await ready();
  const n = await nest();
  assert.equal(n.sheets.length, 3, JSON.stringify(n.sheets));
  assert.equal(n.placed, 5);
  const quote = await page.waitForFunction(() => {
    const q = window.kerfcam.quote?.();
    return q && q.copies.length === 5 ? q : null;
  }).then((h) => h.jsonValue());

  // The page's own figures of each sheet, shown one by one.
  const seen = [];
  for (let k = 0; k < n.sheets.length; k++) seen.push(await shown(k));

  await page.click('#job-sheet');
  await page.waitForFunction(() => document.querySelectorAll('#sheet .report-sheet').length > 0 && !document.getElementById('sheet-view').hidden);
  const sections = await page.$$eval('#sheet .report-sheet', (ss) => ss.map((s) => ({
    sheet: Number(s.dataset.sheet),
    values: Object.fromEntries([...s.querySelectorAll('dd[data-key]')].map((d) => [d.dataset.key, d.dataset.value ?? d.textContent])),
    texts: Object.fromEntries([...s.querySelectorAll('dd[data-key]')].map((d) => [d.dataset.key, d.textContent])),
    parts: [...s.querySelectorAll('.report-sheet-parts tbody tr')].map((tr) => ({ part: tr.dataset.part, copies: Number(tr.dataset.copies), labels: tr.cells[2].textContent })),
    mapCopies: s.querySelectorAll('.report-map .nest-copy').length,
    mapLabels: [...s.querySelectorAll('.report-map text[data-label]')].map((e) => e.textContent).sort(),
    heading: s.querySelector('h2').textContent,
  })));
  assert.deepEqual(sections.map((s) => s.sheet), [0, 1, 2], 'one section per sheet, in order');
  for (const [k, s] of sections.entries()) {
    const { plan, program } = seen[k];
    const copies = n.flat.filter((_, i) => i % PER === 2).filter((sheet) => sheet === k).length;
    assert.equal(Number(s.values.pierces), plan.pierces, `sheet ${k + 1}: pierces`);
    assert.equal(Number(s.values.time), plan.est_time_s, `sheet ${k + 1}: time`);
    assert.equal(Number(s.values.cut), plan.cut_length, `sheet ${k + 1}: cut length`);
    assert.equal(Number(s.values.rapid), plan.rapid_length, `sheet ${k + 1}: rapid length`);
    assert.equal(Number(s.values.util), n.sheets[k].utilisation, `sheet ${k + 1}: utilisation`);
    assert.equal(s.texts.util, `${(100 * n.sheets[k].utilisation).toFixed(1)} %`);
    assert.equal(Number(s.values.copies), copies);
    assert.equal(s.mapCopies, copies, `sheet ${k + 1}: every copy on its map`);
    assert.equal(s.texts.program, program, `sheet ${k + 1}: the program's name is its Download's`);
    assert.match(s.heading, new RegExp(`^Sheet ${k + 1} of 3 · ${program.replace('.', '\\.')}$`));
    // Its parts with their copies and labels, and the same labels written on its map.
    const labels = n.labels.labels.filter((l) => l.sheet === k).map((l) => l.text).sort();
    assert.equal(labels.length, copies, 'every copy is labelled');
    assert.deepEqual(s.mapLabels, labels);
    assert.deepEqual(s.parts.map((p) => [p.part, p.copies]), [['seed000-plate-6-holes', copies]]);
    assert.deepEqual(s.parts[0].labels.split(', ').sort(), labels);
    // The remnant: the last sheet's, beyond its crop line; none kept on the others.
    if (k === 2) assert.match(s.texts.remnant, new RegExp(`beyond x = ${n.sheets[k].crop_x.toFixed(1)} mm`));
    else assert.equal(s.texts.remnant, 'none kept');
  }
  // The job's page: ordered against placed, the sheets, the totals over the sheets, the quote.
  const job = await page.$eval('#sheet .report-job', (p) => ({
    values: Object.fromEntries([...p.querySelectorAll('dd[data-key]')].map((d) => [d.dataset.key, d.dataset.value ?? d.textContent])),
    parts: [...p.querySelectorAll('.report-parts tbody tr')].map((tr) => [tr.dataset.part, tr.dataset.ordered, tr.dataset.placed]),
    quote: [...p.querySelectorAll('.cost-table tbody tr')].map((tr) => [...tr.cells].map((c) => c.textContent)),
  }));
  assert.deepEqual(job.parts, [['seed000-plate-6-holes', '5', '5']]);
  assert.equal(Number(job.values.sheets), 3);
  assert.equal(Number(job.values.pierces), seen.reduce((a, s) => a + s.plan.pierces, 0));
  assert.ok(Math.abs(Number(job.values.time) - seen.reduce((a, s) => a + s.plan.est_time_s, 0)) < 1e-6);
  assert.equal(job.quote.at(-1)[0], 'Job');
  assert.equal(job.quote.at(-1)[7], `${quote.job.price.toFixed(2)} EUR`);
  assert.equal(job.quote.filter((r) => /^Sheet \d$/.test(r[0])).length, 3);

  // Printed: one page for the job, one per sheet.
  const pdf = await page.pdf({ format: 'A4' });
  fs.mkdirSync(OUT, { recursive: true });
  fs.writeFileSync(path.join(OUT, 'job-report.pdf'), pdf);
  assert.equal(pdfPages(pdf), 1 + n.sheets.length, 'pages printed');
  assert.equal(pdfPages(await page.pdf({ format: 'Letter' })), 1 + n.sheets.length, 'pages printed on Letter');
  await page.screenshot({ path: path.join(OUT, 'job-report-1366x768-en.png') });

  // In Portuguese, as the page writes numbers (decimal comma).
  await page.selectOption('#lang', 'pt-BR');
  await page.waitForFunction(() => /^Chapa 1 de 3/.test(document.querySelector('#sheet .report-sheet h2')?.textContent));
  assert.equal(await text('#sheet .report-sheet [data-key="util"]'), `${(100 * n.sheets[0].utilisation).toFixed(1).replace('.', ',')} %`);
  assert.equal(await text('#sheet .report-job h2'), 'Relatório do trabalho');
  await page.$eval('#sheet .report-sheet', (s) => s.scrollIntoView());
  await page.screenshot({ path: path.join(OUT, 'job-report-1366x768-pt-BR.png') });
  const pdfPt = await page.pdf({ format: 'A4' });
  fs.writeFileSync(path.join(OUT, 'job-report-pt-BR.pdf'), pdfPt);
  assert.equal(pdfPages(pdfPt), 1 + n.sheets.length, 'pages printed in Portuguese');
  await page.selectOption('#lang', 'en');
  await page.click('#sheet-close');
  assert.deepEqual(app.pageErrors, []);
});

/** The page's scroll, and where each shown canvas lies (the nest's SVG, the cut plan's preview). */
const layout = () => page.evaluate(() => {
  const box = (sel) => {
    const e = document.querySelector(sel);
    if (!e || !e.getClientRects().length) return null;
    const r = e.getBoundingClientRect();
    return r.width > 0 && r.height > 0 ? { top: r.top, bottom: r.bottom, left: r.left, right: r.right, height: r.height, width: r.width } : null;
  };
  return {
    scroll: document.scrollingElement.scrollHeight - window.innerHeight,
    w: window.innerWidth, h: window.innerHeight,
    nest: box('#nest-canvas svg'), plan: box('#preview'), view: document.body.dataset.sheetView,
  };
});
/** Waits until the cut plan's preview is drawn at the size it is shown (a render in flight leaves the old picture stretched). */
const planDrawn = () => page.waitForFunction(() => {
  const c = document.getElementById('preview');
  const r = c.getBoundingClientRect();
  const dpr = Math.min(window.devicePixelRatio || 1, 2);
  return r.width > 0 && Math.abs(c.width - Math.round(r.width * dpr)) <= 1 && Math.abs(c.height - Math.round(r.height * dpr)) <= 1
    && document.getElementById('status').dataset.state === 'ready';
}, null, { timeout: 30_000 });
const inside = (r, l) => r && r.top >= 0 && r.left >= 0 && r.bottom <= l.h + 0.5 && r.right <= l.w + 0.5;

test('on a 1366 × 768 screen the nest, the cut plan or both fit with no page scroll, and the choice is kept', async () => {
  // The nest of the test above is on the page. Both, by default.
  let l = await layout();
  assert.equal(l.view, 'both');
  assert.ok(l.scroll <= 0, `the page scrolls by ${l.scroll} px`);
  assert.ok(inside(l.nest, l) && inside(l.plan, l), JSON.stringify(l));
  // The nest's canvas three fifths of the two (it was 100–130 px at 1366 × 768 when they shared equally).
  assert.ok(l.nest.height > 200 && l.plan.height > 150, `each has room: ${JSON.stringify(l)}`);
  console.log(`both at 1366 x 768: nest ${Math.round(l.nest.height)} px, plan ${Math.round(l.plan.height)} px`);
  fs.mkdirSync(OUT, { recursive: true });
  await planDrawn();
  await page.screenshot({ path: path.join(OUT, 'sheet-views-both-1366x768-en.png') });

  await page.click('#sheet-views [data-view="plan"]');
  l = await layout();
  assert.ok(l.scroll <= 0 && l.nest === null && inside(l.plan, l), JSON.stringify(l));
  assert.ok(l.plan.height > 350, `the cut plan takes the height: ${JSON.stringify(l)}`);
  assert.equal(await page.isVisible('#nest-tab-1'), true, 'the sheet tabs stay');
  // The preview is fitted to its new size: the plan is drawn (not a blank canvas).
  await page.waitForFunction(() => {
    const c = document.getElementById('preview');
    const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
    let ink = 0;
    for (let i = 0; i < d.length; i += 4 * 37) if (d[i] < 200 || d[i + 1] < 200 || d[i + 2] < 200) ink++;
    return ink > 50;
  });
  await page.screenshot({ path: path.join(OUT, 'sheet-views-plan-1366x768-en.png') });

  await page.click('#sheet-views [data-view="nest"]');
  l = await layout();
  assert.ok(l.scroll <= 0 && l.plan === null && inside(l.nest, l), JSON.stringify(l));
  assert.ok(l.nest.height > 300, `the nest takes the height: ${JSON.stringify(l)}`);
  await page.selectOption('#lang', 'pt-BR');
  assert.equal(await text('#sheet-views [data-view="plan"]'), 'Plano de corte');
  await page.screenshot({ path: path.join(OUT, 'sheet-views-nest-1366x768-pt-BR.png') });
  await page.selectOption('#lang', 'en');

  // Kept over a reload (the nest is gone with the page: the switch shows the choice once Sheet mode is back).
  await page.reload();
  await page.waitForFunction(() => document.getElementById('status').textContent !== 'loading');
  assert.equal(await page.evaluate(() => document.body.dataset.sheetView), 'nest');
  assert.equal(await page.getAttribute('#sheet-views [data-view="nest"]', 'aria-pressed'), 'true');
  assert.deepEqual(app.pageErrors, []);
});

test('at 1920 × 1080 both fit too; in Portuguese at 1366 × 768', async () => {
  await loadParts({ [PLATE]: 5 }, { sheet: [450, 180], time: 0 });
  await nestAndWait(page);
  await page.click('#sheet-views [data-view="both"]');
  for (const [w, h, lang] of [[1920, 1080, 'en'], [1920, 1080, 'pt-BR'], [1366, 768, 'pt-BR'], [1366, 768, 'en']]) {
    await page.setViewportSize({ width: w, height: h });
    await page.selectOption('#lang', lang);
    await planDrawn();
    const l = await layout();
    assert.ok(l.scroll <= 0, `${w}x${h} ${lang}: the page scrolls by ${l.scroll} px`);
    assert.ok(inside(l.nest, l) && inside(l.plan, l), `${w}x${h} ${lang}: ${JSON.stringify(l)}`);
    await page.screenshot({ path: path.join(OUT, `sheet-views-both-${w}x${h}-${lang}.png`) });
  }
  assert.deepEqual(app.pageErrors, []);
});

test('a quantity or a price that is not a number is said at its field; the last good nest and quote stay', async () => {
  await page.selectOption('#cost-material_unit', 'm2');
  for (const [field, value] of Object.entries(PRICES)) await page.fill(`#cost-${field}`, value);
  const before = await page.waitForFunction(() => window.kerfcam.quote?.()).then((h) => h.jsonValue());
  const nested = await nest();
  const qty = `${partRow(PLATE)} input.qty`;
  await page.fill(qty, 'abc');
  assert.equal(await page.getAttribute(qty, 'aria-invalid'), 'true');
  assert.match(await text(partRow(PLATE)), /Quantity of seed000-plate-6-holes\.dxf: enter a whole number from 1 to 10000/);
  await page.click('#nest-run');
  await page.waitForFunction(() => !document.getElementById('nest-message').hidden);
  assert.match(await text('#nest-message'), /Quantity of/);
  assert.deepEqual(await nest(), nested, 'the last good nest stays');
  assert.equal(await page.isEnabled('#download'), true, 'its program can still be downloaded');

  await page.fill('#cost-machine_per_hour', 'abc');
  await page.waitForSelector('#cost-form .field-error[data-field="machine_per_hour"]');
  assert.equal(await page.getAttribute('#cost-machine_per_hour', 'aria-invalid'), 'true');
  assert.equal(await text('#cost-form .field-error'), 'Machine rate per hour: enter a number (or leave it blank).');
  assert.equal((await page.evaluate(() => window.kerfcam.quote())).job.price, before.job.price, 'the last good quote stays');
  assert.match(await text('#cost-message'), /last good quote is kept/);
  await page.fill(qty, '5');
  await page.fill('#cost-machine_per_hour', '90');
  await page.waitForFunction(() => !document.querySelector('#cost-form .field-error'));
  assert.deepEqual(app.pageErrors, []);
});

test('a sheet of 60 labelled copies of 30 parts prints on one page, its labels as runs', async () => {
  await page.setViewportSize({ width: 1366, height: 768 });
  // 30 different tags, 40 to 127 × 30 (a few vertices each: the first nest is quick on a loaded machine), two
  // of each, the plate removed.
  await page.click(`${partRow(PLATE)} button[aria-label$="${PLATE}"]`);
  const tag = ['0', 'SECTION', '2', 'HEADER', '9', '$INSUNITS', '70', '4', '0', 'ENDSEC', '0', 'SECTION', '2', 'ENTITIES'];
  for (let k = 0; k < 30; k++) {
    const [x, w] = [200 * k, 40 + 3 * k];
    tag.push('0', 'LWPOLYLINE', '8', '0', '90', '4', '70', '1', '10', x, '20', '0', '10', x + w, '20', '0', '10', x + w, '20', '30', '10', x, '20', '30');
  }
  tag.push('0', 'ENDSEC', '0', 'EOF');
  await dropBytes('tags.dxf', `${tag.join('\n')}\n`);
  await page.waitForSelector(`${partRow('tags.dxf')} .part-item`);
  await page.fill(`${partRow('tags.dxf')} > .part-fields input.qty`, '2');
  await page.fill('#sheet-w', '1000');
  await page.fill('#sheet-h', '500');
  await page.fill('#nest-time', '0'); // the first nest whole, and no search
  await page.check('#labels-on');
  await nestAndWait(page);
  await ready();
  const n = await nest();
  assert.equal(n.sheets.length, 1, JSON.stringify(n.sheets));
  assert.equal(n.placed, 60, JSON.stringify(n.unplaced));
  await page.click('#job-sheet');
  await page.waitForFunction(() => document.querySelectorAll('#sheet .report-sheet').length === 1 && !document.getElementById('sheet-view').hidden);
  const sheet = await page.$eval('#sheet .report-sheet', (s) => ({
    dense: s.classList.contains('report-dense'),
    labels: [...s.querySelectorAll('.report-sheet-parts tbody tr td:last-child')].map((td) => td.textContent.split('; ')[0]).join(', '),
    rows: s.querySelectorAll('.report-sheet-parts tbody tr').length,
    mapLabels: s.querySelectorAll('.report-map text[data-label]').length,
  }));
  assert.ok(sheet.dense, 'printed compact');
  assert.equal(sheet.rows, 30);
  // The job's page quotes this nest (the quote made after its plan), not the job shown before it.
  const quoted = await page.$$eval('#sheet .report-job .cost-table tbody tr.cost-part', (trs) => trs.map((tr) => tr.cells[1].textContent));
  assert.deepEqual(quoted, Array(30).fill('2'), 'a quote row per part, two copies each');
  assert.equal(sheet.mapLabels, n.labels.labels.length, 'every label on the map');
  // Every label is in the list, alone or in a run (its first and last).
  const listed = new Set();
  for (const item of sheet.labels.split(', ')) {
    const [a, b] = item.split('–');
    if (!b) listed.add(a);
    else {
      const [, head, from] = /^(.*?)(\d+)$/.exec(a);
      const to = Number(/(\d+)$/.exec(b)[1]);
      for (let k = Number(from); k <= to; k++) listed.add(`${head}${k}`);
    }
  }
  for (const l of n.labels.labels) assert.ok(listed.has(l.text), `${l.text} listed: ${sheet.labels}`);
  for (const [lang, format] of [['en', 'A4'], ['pt-BR', 'A4'], ['en', 'Letter']]) {
    await page.selectOption('#lang', lang);
    // The report is written again in the language (the sheet's figures awaited): print it once it is.
    await page.waitForFunction((re) => new RegExp(re).test(document.querySelector('#sheet .report-sheet h2')?.textContent)
      && document.querySelector('#sheet .report-sheet .report-sheet-parts tbody tr'), lang === 'en' ? '^Sheet 1 of 1' : '^Chapa 1 de 1');
    const pdf = await page.pdf({ format });
    fs.writeFileSync(path.join(OUT, `job-report-60-${lang}-${format}.pdf`), pdf);
    assert.equal(pdfPages(pdf), 2, `${lang} ${format}: the job's page and the sheet's`);
  }
  await page.selectOption('#lang', 'en');
  await page.click('#sheet-close');
  assert.deepEqual(app.pageErrors, []);
});
