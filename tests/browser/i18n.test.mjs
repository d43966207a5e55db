// The page in English and Brazilian Portuguese (issue 6 §7), in Debian's headless Chromium driven by
// playwright-core: the first visit follows the browser's languages, the switch changes every text (static
// and written by the page, engine warnings included) without running the job again, numbers get the
// locale's decimal sign in the UI but never in the G-code, no text key is missing, and a reload keeps
// the choice. Needs www/pkg (scripts/build-wasm.sh) and `chromium` on PATH (CHROMIUM=/path overrides).
//
//   node --test tests/browser/

import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { after, before, test } from 'node:test';
import { fileURLToPath } from 'node:url';
import { chromium } from 'playwright-core';
import { startServer } from '../../scripts/serve.mjs';
import { clearFiles } from './harness.mjs';

const repoRoot = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..', '..');
const ARGS = [
  '--headless', '--no-sandbox', '--disable-gpu', '--disable-background-networking', '--disable-component-update',
  '--no-first-run', '--disable-sync', '--disable-quic',
];

// A 100.25 × 50 mm plate with a 20 mm hole, no $INSUNITS/$MEASUREMENT: the engine warns about the units
// ("units-assumed") and the lengths have decimals.
const line = (x0, y0, x1, y1) => `0\nLINE\n8\nCUT\n10\n${x0}\n20\n${y0}\n11\n${x1}\n21\n${y1}\n`;
const PLATE = '0\nSECTION\n2\nENTITIES\n' +
  line(0, 0, 100.25, 0) + line(100.25, 0, 100.25, 50) + line(100.25, 50, 0, 50) + line(0, 50, 0, 0) +
  '0\nCIRCLE\n8\nCUT\n10\n30\n20\n25\n40\n10\n0\nENDSEC\n0\nEOF\n';

let server;
const contexts = [];
const dirs = [];
const pageErrors = [];

function which(cmd) {
  const r = spawnSync('sh', ['-c', `command -v ${cmd}`], { encoding: 'utf8' });
  return r.status === 0 ? r.stdout.trim() : null;
}

/** A fresh browser profile whose navigator.languages start with `locale`. */
async function openPage(locale) {
  const executablePath = process.env.CHROMIUM || which('chromium');
  assert.ok(executablePath, 'chromium is not on PATH: run scripts/setup.sh test');
  const userDataDir = fs.mkdtempSync(path.join(os.tmpdir(), 'kerfcam-i18n-'));
  const downloadDir = fs.mkdtempSync(path.join(os.tmpdir(), 'kerfcam-i18n-dl-'));
  dirs.push(userDataDir, downloadDir);
  const context = await chromium.launchPersistentContext(userDataDir, {
    executablePath, headless: true, args: ARGS, locale, acceptDownloads: true, downloadsPath: downloadDir,
    viewport: { width: 1280, height: 800 },
  });
  contexts.push(context);
  const page = context.pages()[0] ?? (await context.newPage());
  page.on('pageerror', (e) => pageErrors.push(e));
  page.on('console', (m) => m.type() === 'error' && pageErrors.push(new Error(m.text())));
  await page.goto(server.url);
  await untilEngine(page);
  return { page, downloadDir };
}

const untilEngine = (page) => page.waitForFunction(() => {
  const s = document.getElementById('status').dataset.state;
  return s && s !== 'loading';
}, null, { timeout: 30_000 });

before(async () => {
  assert.ok(fs.existsSync(path.join(repoRoot, 'www', 'pkg', 'kerfcam_bg.wasm')), 'www/pkg missing: run scripts/build-wasm.sh');
  server = await startServer(0);
});

after(async () => {
  for (const c of contexts) await c.close();
  await server?.close();
  for (const d of dirs) fs.rmSync(d, { recursive: true, force: true });
});

/** Drops the plate and waits for the job (status state "ready", not its text: that is translated). */
async function dropPlate(page) {
  await page.evaluate(() => (window.kerfcam.lastReport = null));
  await page.evaluate((dxf) => {
    const dt = new DataTransfer();
    dt.items.add(new File([dxf], 'plate.dxf'));
    const init = { dataTransfer: dt, bubbles: true, cancelable: true };
    document.body.dispatchEvent(new DragEvent('dragover', init));
    document.body.dispatchEvent(new DragEvent('drop', init));
  }, PLATE);
  await page.waitForFunction(() => {
    const s = document.getElementById('status').dataset.state;
    return s === 'error' || (s === 'ready' && window.kerfcam.lastReport !== null);
  }, null, { timeout: 30_000 });
  assert.equal(await page.$eval('#error', (e) => (e.hidden ? '' : e.textContent)), '');
}

async function downloadGcode(page, downloadDir) {
  const [download] = await Promise.all([page.waitForEvent('download'), page.click('#download')]);
  const file = path.join(downloadDir, `${Date.now()}-${download.suggestedFilename()}`);
  await download.saveAs(file);
  return fs.readFileSync(file);
}

const summary = (page) => page.evaluate(() => Object.fromEntries(
  [...document.querySelectorAll('#summary dd[data-key]')].map((dd) => [dd.dataset.key, dd.textContent])));

/**
 * Every text the user can meet, in document order: text nodes (trimmed, non-empty) and the title,
 * aria-label and placeholder attributes, with the element they belong to. The language menu's own
 * labels are left out (they name each language in itself on purpose).
 */
const texts = (page) => page.evaluate(() => {
  const out = [];
  const where = (el) => el.id ? `#${el.id}` : `${el.parentElement?.id ? `#${el.parentElement.id} > ` : ''}${el.tagName.toLowerCase()}`;
  const walk = (node) => {
    if (node.nodeType === Node.TEXT_NODE) {
      const text = node.textContent.trim();
      if (text) out.push([where(node.parentElement), text]);
      return;
    }
    if (node.nodeType !== Node.ELEMENT_NODE || ['SCRIPT', 'STYLE', 'NOSCRIPT'].includes(node.tagName)) return;
    if (node.id === 'lang' || node.htmlFor === 'lang') return;
    if (node.tagName === 'OPTION' && /^(preset|mine):/.test(node.value)) return; // post names are data
    for (const a of ['title', 'aria-label', 'placeholder', 'label']) {
      if (node.hasAttribute(a) && (a !== 'label' || node.tagName === 'OPTGROUP')) out.push([`${where(node)}@${a}`, node.getAttribute(a)]);
    }
    for (const c of node.childNodes) walk(c);
  };
  walk(document.head.querySelector('title'));
  walk(document.body);
  return out;
});

/** True for texts made only of numbers, units, symbols and names (G-code, DXF, LINE, kerfcam). */
const NEUTRAL_WORDS = new Set(['mm', 'cm', 'm', 'in', 'ft', 's', 'min', 'kerfcam', 'plate', 'dxf', 'x', 'perpendicular',
  'material', 'plasma', 'laser', 'h', 'g', 'kg', 'cm³', 'rpm']); // the same words in Portuguese (units: the cost panel's /h, g/cm³, /kg; the spindle's rpm)
const neutral = (text) => text.replace(/G-code/g, 'G').split(/[^\p{L}\p{N}$]+/u).filter(Boolean)
  .every((w) => /^[\d.,]+$/.test(w) || w === w.toUpperCase() || NEUTRAL_WORDS.has(w.toLowerCase()) || /^v\d/.test(w));

test('first visit follows the browser: pt-BR gives Portuguese, en-US English', async () => {
  const pt = await openPage('pt-BR');
  assert.equal(await pt.page.getAttribute('html', 'lang'), 'pt-BR');
  assert.equal(await pt.page.inputValue('#lang'), 'pt-BR');
  assert.equal(await pt.page.textContent('#download'), 'Baixar o G-code');
  assert.equal(await pt.page.textContent('#status'), 'aguardando um arquivo');
  assert.equal(await pt.page.getAttribute('#status', 'data-state'), 'waiting for a file');
  await contexts.pop().close();
});

test('the Portuguese switch changes every text, not the G-code; reload keeps it', async () => {
  const { page, downloadDir } = await openPage('en-US');
  assert.equal(await page.getAttribute('html', 'lang'), 'en');
  assert.equal(await page.inputValue('#lang'), 'en');
  assert.equal(await page.textContent('#download'), 'Download G-code');
  await dropPlate(page);
  const en = await summary(page);
  assert.match(en['cut-length'], /^\d+\.\d mm$/);
  const enUnits = await page.textContent('#warnings li[data-code="units-assumed"]');
  assert.match(enUnits, /does not state its units/);
  const enGcode = await downloadGcode(page, downloadDir);
  await page.click('#compare');
  await page.waitForSelector('#comparison tr[data-order="chained"]');
  const enTexts = await texts(page);

  // Switch: no re-run (the report carries both languages), every text follows.
  await page.evaluate(() => (window.kerfcam.runsBefore = window.kerfcam.lastReport));
  await page.selectOption('#lang', 'pt-BR');
  assert.equal(await page.getAttribute('html', 'lang'), 'pt-BR');
  assert.equal(await page.evaluate(() => window.kerfcam.lastReport === window.kerfcam.runsBefore), true, 'the switch re-ran the job');
  assert.equal(await page.textContent('#download'), 'Baixar o G-code');
  assert.equal(await page.textContent('h2[data-i18n="drawing.heading"]'), '1. Desenho');
  assert.equal(await page.textContent('#status'), 'pronto');
  assert.equal(await page.getAttribute('#status', 'data-state'), 'ready');
  const pt = await summary(page);
  assert.match(pt['cut-length'], /^\d+,\d mm$/, 'decimal comma in the summary');
  assert.equal(pt['cut-length'].replace(',', '.'), en['cut-length']);
  assert.equal(pt.units, 'mm (suposto: o arquivo não informa)');
  const ptUnits = await page.textContent('#warnings li[data-code="units-assumed"]');
  assert.match(ptUnits, /não informa suas unidades/);
  assert.match(await page.textContent('#comparison thead'), /Perfurações/);

  // Every text the page shows changed, unless it is numbers and names.
  const ptTexts = await texts(page);
  assert.equal(ptTexts.length, enTexts.length, 'the switch changed the page structure');
  const same = enTexts.filter(([, text], i) => text === ptTexts[i][1] && !neutral(text));
  assert.deepEqual(same, [], 'texts left in English');

  // The engine run in Portuguese writes the same program, byte for byte; its report's message is Portuguese.
  await dropPlate(page);
  const report = await page.evaluate(() => window.kerfcam.lastReport);
  assert.match(report.warnings.find((w) => w.code === 'units-assumed').message, /não informa suas unidades/);
  const ptGcode = await downloadGcode(page, downloadDir);
  assert.ok(ptGcode.equals(enGcode), 'the G-code changed with the language');
  assert.doesNotMatch(ptGcode.toString(), /\d,\d/, 'a decimal comma in the G-code');

  // Dynamic texts: animation button, post editor and its engine-checked error. At 1× the animation lasts the
  // program's own time: at the default 10× a loaded machine let it end between the two clicks (CI of ab7177e).
  await page.selectOption('#speed', '1');
  await page.click('#play');
  assert.equal(await page.textContent('#play'), 'Pausar');
  await page.click('#play');
  assert.equal(await page.textContent('#play'), 'Reproduzir');
  await page.click('#post-edit');
  assert.equal(await page.textContent('#post-dialog-title'), 'Editar pós-processador');
  await page.fill('#pf-decimals', '9');
  await page.click('#post-form button[type=submit]');
  await page.waitForFunction(() => document.getElementById('post-error').textContent !== '');
  assert.match(await page.textContent('#post-error'), /decimals.*não está entre 1 e 6/);
  await page.click('#post-cancel');

  const keys = await page.evaluate(async () => {
    const i18n = await import('./i18n.js');
    return { missing: i18n.missingKeys(), gaps: i18n.catalogGaps() };
  });
  assert.deepEqual(keys.missing, [], 'text keys missing');
  assert.deepEqual(keys.gaps, [], 'keys in one language only');

  // Reload: the choice is kept (the kept files are cleared first: they would be opened again).
  await clearFiles(page);
  await page.reload();
  await untilEngine(page);
  assert.equal(await page.getAttribute('html', 'lang'), 'pt-BR');
  assert.equal(await page.inputValue('#lang'), 'pt-BR');
  assert.equal(await page.textContent('#status'), 'aguardando um arquivo');
  assert.equal(await page.textContent('#download'), 'Baixar o G-code');
  assert.deepEqual(pageErrors, []);
});
