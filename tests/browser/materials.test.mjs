// The cut chart (issue 20 §1) in Debian's headless chromium, as a user would: import a QtPlasmaC
// material file, choose one of its materials for the job, download the program and read its kerf and
// feed (and M190 with the QtPlasmaC post), export the chart back byte for byte, edit an entry, and
// import a broken file whose message names the material and the field. Programs through rs274.
//
//   node --test tests/browser/materials.test.mjs

import assert from 'node:assert/strict';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { after, before, test } from 'node:test';
import { assertRs274Accepts, clearFiles, fixture, openApp, untilReady } from './harness.mjs';

let app;
let page;
let dir;

before(async () => {
  app = await openApp();
  page = app.page;
  dir = app.downloadDir; // removed by app.close()
});

after(async () => {
  await app?.close();
});

// As QtPlasmaC writes it (aligned keys, a blank line after each), with a hand-edited section, CRLF on
// one line and no line end at the very end: all of it must come back out unchanged.
const CFG = '# plasmac material file\n# my table\n[MATERIAL_NUMBER_4]\nNAME               = Mild 4mm 65A\n' +
  'KERF_WIDTH         = 1.7\nTHC                = 1\nPIERCE_HEIGHT      = 4\nPIERCE_DELAY       = 0.5\n' +
  'CUT_HEIGHT         = 1.5\nCUT_SPEED          = 2700\nCUT_AMPS           = 65\nCUT_VOLTS          = 125\n\n' +
  '[MATERIAL_NUMBER_9]\nNAME = Alu 3\r\nKERF_WIDTH=1.9\nPIERCE_HEIGHT = 3.5\nPIERCE_DELAY = 0.2\nCUT_HEIGHT = 1.5\nCUT_SPEED = 4100';

async function saved(locator) {
  const [d] = await Promise.all([page.waitForEvent('download'), page.click(locator)]);
  const file = path.join(dir, `${Date.now()}-${d.suggestedFilename()}`);
  await d.saveAs(file);
  return file;
}

async function importChart(name, text) {
  const file = path.join(dir, name);
  fs.writeFileSync(file, text);
  await page.setInputFiles('#material-import', file);
}

test('a QtPlasmaC material file imported and chosen sets the program, and exports byte for byte', async () => {
  await clearFiles(page);
  if (!(await page.isVisible('#material-list'))) await page.click('#panel-materials > summary');
  // The starter entries are there, each labelled an example.
  const starter = await page.$$eval('#material option', (os) => os.map((o) => o.textContent));
  assert.ok(starter.length > 1 && starter.slice(1).every((s) => s.endsWith('(example)')), starter.join('|'));
  await untilReady(page, () => page.setInputFiles('#file-input', fixture('seed000-plate-6-holes.dxf')));
  await importChart('table_material.cfg', CFG);
  await page.waitForFunction(() => /Imported 2 entries/.test(document.getElementById('material-message').textContent));
  // Choosing a material: its kerf and feed reach the program, and show (locked) in the settings.
  await untilReady(page, () => page.selectOption('#material', 'Mild 4mm 65A'));
  let file = await saved('#download');
  let g = fs.readFileSync(file, 'utf8');
  assert.ok(g.includes('kerf 1.7 mm, feed 2700 mm/min'), g.slice(0, 600));
  assert.ok(g.includes('F2700') && g.includes('G4 P0.5'));
  assertRs274Accepts(file);
  assert.equal(await page.inputValue('#kerf'), '1.7');
  assert.equal(await page.getAttribute('#kerf', 'readonly'), '');
  assert.match(await page.textContent('#material-note'), /Kerf 1\.7 mm, feed 2700 mm\/min.*Mild 4mm 65A/);
  // With the QtPlasmaC post the controller's material is selected by its number.
  await untilReady(page, () => page.selectOption('#post', 'preset:qtplasmac'));
  g = fs.readFileSync(await saved('#download'), 'utf8');
  assert.ok(/^M190 P4$/m.test(g), g.slice(0, 800));
  await untilReady(page, () => page.selectOption('#post', ''));
  // Export: the very bytes imported, under the name they came with.
  file = await saved('#material-export-cfg');
  assert.equal(path.basename(file).replace(/^\d+-/, ''), 'table_material.cfg');
  assert.equal(fs.readFileSync(file, 'utf8'), CFG);
  // Kept across a reload.
  await page.reload();
  await page.waitForFunction(() => document.getElementById('material').options.length === 3);
  assert.equal(await page.inputValue('#material'), 'Mild 4mm 65A');
  assert.equal(await page.inputValue('#kerf'), '1.7');
});

test('an entry edited in the chart changes the job; a bad value and a broken file name the entry and field', async () => {
  await untilReady(page, () => page.setInputFiles('#file-input', fixture('seed000-plate-6-holes.dxf')));
  if (!(await page.isVisible('#material-list'))) await page.click('#panel-materials > summary');
  await page.selectOption('#material-list', '0');
  assert.equal(await page.inputValue('#material-f-feed'), '2700');
  await page.fill('#material-f-feed', 'fast');
  await page.click('#material-save');
  await page.waitForFunction(() => document.getElementById('material-message').dataset.error === 'true');
  assert.equal(await page.textContent('#material-message'), "material 'Mild 4mm 65A', feed: 'fast' is not a number");
  await page.fill('#material-f-feed', '-3');
  await page.click('#material-save');
  await page.waitForFunction(() => /feed: -3 is not between/.test(document.getElementById('material-message').textContent));
  assert.match(await page.textContent('#material-message'), /^material 'Mild 4mm 65A', feed: /);
  await untilReady(page, async () => {
    await page.fill('#material-f-feed', '2500');
    await page.click('#material-save');
  });
  let g = fs.readFileSync(await saved('#download'), 'utf8');
  assert.ok(g.includes('feed 2500 mm/min') && g.includes('F2500'), g.slice(0, 600));
  // The edited section is rewritten, the other one kept as read.
  const cfg = fs.readFileSync(await saved('#material-export-cfg'), 'utf8');
  assert.ok(cfg.includes('CUT_SPEED          = 2500\n') && cfg.includes('[MATERIAL_NUMBER_9]\nNAME = Alu 3\r\n'), cfg);
  // A broken file: the message names the material and the field, in Portuguese too; the chart stays.
  await importChart('broken_material.cfg', '[MATERIAL_NUMBER_2]\nNAME = Inox 2\nPIERCE_HEIGHT = 3\nPIERCE_DELAY = 0.3\nCUT_HEIGHT = 1\nCUT_SPEED = rápido\n');
  await page.waitForFunction(() => document.getElementById('material-message').dataset.error === 'true');
  assert.match(await page.textContent('#material-message'), /broken_material\.cfg: material 'Inox 2', CUT_SPEED: 'rápido' is not a number/);
  await page.selectOption('#lang', 'pt-BR');
  await importChart('broken_material.cfg', '[MATERIAL_NUMBER_2]\nNAME = Inox 2\nPIERCE_HEIGHT = 3\nPIERCE_DELAY = 0.3\nCUT_HEIGHT = 1\n');
  await page.waitForFunction(() => /CUT_SPEED: ausente/.test(document.getElementById('material-message').textContent));
  assert.match(await page.textContent('#material-message'), /material 'Inox 2', CUT_SPEED: ausente/);
  await page.selectOption('#lang', 'en');
  assert.equal(await page.$$eval('#material option', (os) => os.length), 3);
  // None: the kerf field is the user's again.
  await untilReady(page, () => page.selectOption('#material', ''));
  assert.equal(await page.getAttribute('#kerf', 'readonly'), null);
  assert.deepEqual(app.pageErrors, []);
});
