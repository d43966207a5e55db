// Issue 13 in the browser: numbers typed the local way, sizes and the program origin in view, the
// assumed unit as a control, truncated files marked, grouped warnings. Debian's chromium through
// playwright-core (harness.mjs); every downloaded program is read by LinuxCNC's rs274.
//
//   node --test tests/browser/trust.test.mjs

import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { after, before, test } from 'node:test';
import { dropInPage } from './helpers.mjs';
import { assertRs274Accepts, clearFiles, openApp, untilReady } from './harness.mjs';

let app;
let page;

before(async () => {
  app = await openApp();
  page = app.page;
});

after(async () => {
  await app?.close();
});

// --- helpers ---------------------------------------------------------------------------------------

/**
 * A small ASCII DXF (R12 style: ENTITIES only, or with a HEADER when `header` lists variables) of
 * LINEs: `rects` are [x0, y0, x1, y1] rectangles. No $INSUNITS unless `header` gives one.
 */
function dxf({ rects, header = [], tail = 'EOF' }) {
  const out = [];
  const pair = (code, value) => out.push(String(code), String(value));
  if (header.length) {
    pair(0, 'SECTION');
    pair(2, 'HEADER');
    for (const [name, code, value] of header) {
      pair(9, name);
      pair(code, value);
    }
    pair(0, 'ENDSEC');
  }
  pair(0, 'SECTION');
  pair(2, 'ENTITIES');
  for (const [x0, y0, x1, y1] of rects) {
    const corners = [[x0, y0], [x1, y0], [x1, y1], [x0, y1]];
    corners.forEach(([ax, ay], i) => {
      const [bx, by] = corners[(i + 1) % 4];
      pair(0, 'LINE');
      pair(8, '0');
      pair(10, ax);
      pair(20, ay);
      pair(30, 0);
      pair(11, bx);
      pair(21, by);
      pair(31, 0);
    });
  }
  if (tail === 'EOF') {
    pair(0, 'ENDSEC');
    pair(0, 'EOF');
  }
  return Buffer.from(`${out.join('\n')}\n`, 'latin1');
}

const drop = (name, bytes) => page.evaluate(dropInPage, { name, base64: Buffer.from(bytes).toString('base64') });
const gcode = () => page.evaluate(() => window.kerfcam.lastGcode);
const report = () => page.evaluate(() => window.kerfcam.lastReport);

async function setField(selector, value) {
  await page.fill(selector, String(value));
  await page.press(selector, 'Tab'); // commits: fires `change`
}

async function setLang(lang) {
  await page.selectOption('#lang', lang);
  await page.waitForFunction((l) => document.documentElement.lang === l, lang);
}

/** Clicks Download, saves the program, checks it is the page's and that rs274 reads it; returns its text. */
async function downloadProgram() {
  const [download] = await Promise.all([page.waitForEvent('download'), page.click('#download')]);
  const file = path.join(app.downloadDir, `${Date.now()}-${download.suggestedFilename()}`);
  await download.saveAs(file);
  const text = fs.readFileSync(file, 'utf8');
  assert.equal(text, await gcode(), 'the download is the program the page shows');
  assertRs274Accepts(file);
  return text;
}

/** Every X and Y word of the program's moves (comments removed), as numbers. */
function coordinates(program) {
  const xs = [];
  const ys = [];
  for (const line of program.replace(/\([^)]*\)/g, '').replace(/;.*$/gm, '').split('\n')) {
    for (const [, axis, v] of line.matchAll(/([XY])\s*(-?\d+(?:\.\d*)?|-?\.\d+)/g)) (axis === 'X' ? xs : ys).push(Number(v));
  }
  return { xs, ys };
}

const SQUARE = dxf({ rects: [[10, 10, 60, 40]] });

// --- numbers typed the local way -------------------------------------------------------------------

test('"1,5" and "1.5" in the kerf field both give a 1.5 mm kerf, in English and in Portuguese', async () => {
  await untilReady(page, () => drop('square.dxf', SQUARE));
  for (const lang of ['en', 'pt-BR']) {
    await setLang(lang);
    await untilReady(page, () => setField('#kerf', '15'));
    const fifteen = await gcode();
    await untilReady(page, () => setField('#kerf', '1.5'));
    const point = await gcode();
    assert.notEqual(point, fifteen, `${lang}: a 1.5 mm kerf is not a 15 mm one`);
    await untilReady(page, () => setField('#kerf', '2'));
    await untilReady(page, () => setField('#kerf', '1,5'));
    assert.equal(await gcode(), point, `${lang}: "1,5" is 1.5`);
    assert.equal(await page.getAttribute('#kerf', 'aria-invalid'), 'false');
  }
  await setLang('en');
});

test('a negative or zero feed marks the field with its label and range and keeps the preview and program', async () => {
  assert.equal(await page.inputValue('#feed'), '2000');
  const program = await gcode();
  for (const [lang, label] of [['en', 'Feed rate'], ['pt-BR', 'Velocidade de corte']]) {
    await setLang(lang);
    for (const bad of ['-100', '0', 'abc']) {
      await setField('#feed', bad);
      await page.waitForFunction(() => document.getElementById('feed').getAttribute('aria-invalid') === 'true');
      await page.waitForTimeout(600); // a re-run, if one were started, would have begun
      const problem = await page.textContent('#settings-problems');
      assert.match(problem, new RegExp(`${label}: .*\\b1\\b.*1000000 mm/min`), `${lang} ${bad}: ${problem}`);
      assert.doesNotMatch(problem, /'feed'|setting|configuração '/);
      assert.equal(await page.isHidden('#placeholder'), true, 'the preview stays');
      assert.equal(await page.isDisabled('#download'), false, 'the program stays');
      assert.equal(await gcode(), program);
      assert.notEqual(await page.getAttribute('#feed', 'aria-describedby'), null);
      assert.equal(await page.$eval('#status', (s) => s.dataset.state), 'ready');
    }
  }
  await setLang('en');
  await untilReady(page, () => setField('#feed', '2500'));
  assert.equal(await page.getAttribute('#feed', 'aria-invalid'), 'false');
  assert.equal(await page.isHidden('#settings-problems'), true);
  assert.notEqual(await gcode(), program);
  await untilReady(page, () => setField('#feed', '2000'));
  assert.equal(await gcode(), program);
});

test('arrow keys step each field by its own step, onto the step\'s grid', async () => {
  const steps = async (selector, start, keys) => {
    await page.fill(selector, start);
    const seen = [];
    for (const key of keys) {
      await page.press(selector, key);
      seen.push(await page.inputValue(selector));
    }
    return seen;
  };
  assert.deepEqual(await steps('#feed', '2000', ['ArrowUp', 'ArrowDown', 'ArrowDown']), ['2100', '2000', '1900']);
  assert.deepEqual(await steps('#feed', '2001', ['ArrowUp', 'ArrowDown']), ['2100', '2000']);
  assert.deepEqual(await steps('#rapid', '10000', ['ArrowUp', 'PageDown']), ['11000', '1000']);
  assert.deepEqual(await steps('#kerf', '1.5', ['ArrowUp', 'ArrowUp', 'ArrowDown']), ['1.6', '1.7', '1.6']);
  assert.deepEqual(await steps('#kerf', '0.1', ['ArrowDown', 'ArrowDown']), ['0', '0'], 'not below the range');
  await setLang('pt-BR');
  assert.deepEqual(await steps('#kerf', '0,2', ['ArrowUp']), ['0,3']);
  await setLang('en');
  await untilReady(page, async () => {
    await page.fill('#kerf', '1.5');
    await page.fill('#feed', '2000');
    await page.fill('#rapid', '10000');
    await page.press('#rapid', 'Tab');
  });
});

test('no uncaught errors in the page', () => {
  assert.deepEqual(app.pageErrors.map((e) => e.message), []);
});
