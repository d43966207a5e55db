// Issue 41 in the browser: an Inkscape SVG dropped on the page is read at its true size with its layers,
// in both languages, and cut to a program LinuxCNC's rs274 accepts; an SVG in px offers px at 96 and at 72
// per inch beside its units-assumed warning, and px at 72 reads it 96/72 larger; the open buttons say DXF or
// SVG; Save SVG writes the engine's cut plan (a layer per part, kerf paths) in mm. Debian's chromium
// through playwright-core (harness.mjs).
//
//   node --test tests/browser/svg.test.mjs

import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { after, before, test } from 'node:test';
import { dropInPage } from './helpers.mjs';
import { assertRs274Accepts, clearFiles, downloadProgram, openApp, untilReady } from './harness.mjs';

const corpusSvg = (...parts) => path.join(path.dirname(path.dirname(path.dirname(new URL(import.meta.url).pathname))), '..', 'shared', 'corpus-svg', ...parts);
// Inkscape 1.1.2, 100 × 50 mm, shapes on 5 named layers.
const INKSCAPE = corpusSvg('openscad', 'id-layer-selection-test.svg');
// Illustrator 21: no width/height, a viewBox of 255 × 266 user units (px at 96 per inch: 67.5 × 70.4 mm).
const ILLUSTRATOR = corpusSvg('openscad', 'box-w-holes.svg');

let app;
let page;

before(async () => {
  app = await openApp();
  page = app.page;
});

after(async () => {
  await app?.close();
});

const drop = (file) => page.evaluate(dropInPage, { name: path.basename(file), base64: fs.readFileSync(file).toString('base64') });
const report = () => page.evaluate(() => window.kerfcam.lastReport);

async function setLang(lang) {
  await page.selectOption('#lang', lang);
  await page.waitForFunction((l) => document.documentElement.lang === l, lang);
}

test('an Inkscape SVG dropped on the page reads at its true size with its layers, in both languages', async () => {
  for (const lang of ['en', 'pt-BR']) {
    await setLang(lang);
    await clearFiles(page);
    await untilReady(page, () => drop(INKSCAPE));
    const r = await report();
    assert.equal(r.format, 'svg');
    assert.equal(r.units, 'mm');
    assert.equal(r.units_assumed, false);
    assert.ok(Math.abs(r.size.w - 100) < 0.01 && Math.abs(r.size.h - 50) < 0.01, `${lang}: ${JSON.stringify(r.size)}`);
    assert.ok(r.layers.length >= 5, `${lang}: layers ${r.layers.map((l) => l.name)}`);
    assert.ok(r.plan.pierces >= 1, `${lang}: pierces ${r.plan.pierces}`);
    // Its format named as such (it read "DXF: SVG, Inkscape …"), the program that wrote it beside.
    const format = await page.$eval('#summary dd[data-key="format"]', (dd) => [dd.previousElementSibling.textContent, dd.textContent]);
    assert.equal(format[0], 'SVG');
    assert.match(format[1], /^Inkscape 1\.1\.2/);
    // Where its unit comes from, in words (it read "mm (from width/height)").
    assert.equal(await page.textContent('#summary dd[data-key="units"]'),
      lang === 'en' ? "mm (from the SVG's width and height)" : 'mm (da largura e altura do SVG)');
    for (const key of ['drawing.open-files', 'nest.open-parts']) {
      assert.match(await page.textContent(`[data-i18n="${key}"]`), /DXF (or|ou) SVG/, `${lang}: ${key}`);
    }
    assertRs274Accepts(await downloadProgram(page, app.downloadDir));
  }
  await setLang('en');
});

test('Save SVG writes the cut plan in mm: a layer per part with its kerf path, read back at true size', async () => {
  await clearFiles(page);
  await untilReady(page, () => drop(INKSCAPE));
  const r = await report();
  const [d] = await Promise.all([page.waitForEvent('download'), page.click('#save-svg')]);
  assert.equal(d.suggestedFilename(), 'id-layer-selection-test.svg');
  // saveAs, not path(): under the suite's one shared chromium the download is remote (harness.mjs).
  const file = path.join(app.downloadDir, d.suggestedFilename());
  await d.saveAs(file);
  const svg = fs.readFileSync(file, 'utf8');
  assert.match(svg, /^<\?xml[^]*<svg [^>]*width="[0-9.]+mm" height="[0-9.]+mm" viewBox="0 0 /);
  assert.match(svg, /inkscape:label="id-layer-selection-test\.svg"/);
  assert.match(svg, /inkscape:label="part 1"/);
  const kerfLayers = (svg.match(/inkscape:label="kerf path"/g) || []).length;
  assert.ok(kerfLayers >= 1 && kerfLayers <= r.plan.parts, `kerf path layers ${kerfLayers}, parts ${r.plan.parts}`);
  const numbers = (svg.match(/<text /g) || []).length;
  assert.ok(numbers >= 1 && numbers <= r.plan.pierces, `numbered ${numbers}, pierces ${r.plan.pierces}`);
  // The page holds the drawing (and the leads outside it) with 5 mm to spare each side: true size, not px.
  const [, w] = svg.match(/width="([0-9.]+)mm"/);
  assert.ok(Number(w) >= r.size.w + 10 && Number(w) <= r.size.w + 40, `${w} for ${r.size.w}`);
});

test('an SVG in px offers px at 96 and at 72 per inch, and px at 72 reads it 96/72 larger', async () => {
  await clearFiles(page);
  await untilReady(page, () => drop(ILLUSTRATOR));
  const r96 = await report();
  assert.equal(r96.units_assumed, true);
  assert.equal(r96.units, 'px');
  await page.waitForSelector('#warnings li[data-code="units-assumed"] .unit-switch button[data-unit="px72"]');
  assert.match(await page.textContent('#warnings li[data-code="units-assumed"]'), /72 px per inch/);
  await untilReady(page, () => page.click('#warnings li[data-code="units-assumed"] button[data-unit="px72"]'));
  const r72 = await report();
  assert.equal(r72.units, 'px72');
  // The report rounds sizes to the micrometre.
  assert.ok(Math.abs(r72.size.w - (r96.size.w * 96) / 72) < 0.002, `${r72.size.w} / ${r96.size.w}`);
  assertRs274Accepts(await downloadProgram(page, app.downloadDir));
  assert.deepEqual(app.pageErrors, []);
});
