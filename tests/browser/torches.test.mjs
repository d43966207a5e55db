// Several torches in the Sheet mode (issue 18 item 7, paper 001 §6.5), in Debian's headless chromium:
// 5 plates on a 1500 × 1000 sheet with 2 torches 500 mm apart. The nest is made for torch 1's band,
// the page says 3 under torch 1 and 6 cut, draws torch 2's copies faded, and the downloaded program
// drives torch 1 only: single path, a comment naming the setup, the park and M0 before the first cut,
// and rs274 accepts it. A setup that cannot fit is refused with the reason.
//
//   node --test tests/browser/torches.test.mjs

import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { after, before, test } from 'node:test';
import { assertRs274Accepts, fixture, openApp } from './harness.mjs';
import { dropInPage, nestAndWait as nestAndWaitOn } from './helpers.mjs';

const PLATE = 'seed000-plate-6-holes.dxf';
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

test('two torches 500 mm apart: the band nested, torch 2 faded, one path with the comment and the stop', async () => {
  await page.click('#mode-sheet');
  await page.evaluate(dropInPage, { name: PLATE, base64: fs.readFileSync(fixture(PLATE)).toString('base64') });
  const row = `#parts li.part[data-name="${PLATE}"]`;
  await page.waitForSelector(`${row} [data-units]`);
  await page.fill(`${row} input.qty`, '5');
  await page.fill('#sheet-w', '1500');
  await page.fill('#sheet-h', '1000');
  await page.fill('#nest-time', '0');
  await page.fill('#nest-margin', '5');

  // Three torches 500 mm apart do not fit 1000 mm: said, no nest.
  await page.fill('#nest-torches', '3');
  await page.fill('#torch-spacing', '500');
  await page.click('#nest-run');
  await page.waitForFunction(() => !document.getElementById('nest-message').hidden, null, { timeout: 30_000 });
  assert.match(await page.textContent('#nest-message'), /3 torches 500 mm apart/);
  // In Portuguese, the engine's reason too (it was English on a pt-BR page).
  await page.selectOption('#lang', 'pt-BR');
  await page.click('#nest-run');
  await page.waitForFunction(() => /tochas a 500 mm/.test(document.getElementById('nest-message').textContent), null, { timeout: 30_000 });
  assert.match(await page.textContent('#nest-message'), /3 tochas a 500 mm uma da outra passam da chapa: 1000 mm de altura/);
  await page.selectOption('#lang', 'en');

  await page.fill('#nest-torches', '2');
  await page.fill('#torch-park-x', '0');
  await page.fill('#torch-park-y', '1200');
  await nestAndWait();
  const nest = await page.evaluate(() => window.kerfcam.lastNest);
  assert.equal(nest.torches.count, 2);
  assert.equal(nest.torches.parts[0].per_torch, 3);
  assert.equal(nest.torches.parts[0].made, 6);
  assert.match(await page.textContent('#nest-figures [data-key="torches"]'), /^2 torches 500 mm apart: 3 under torch 1, 6 cut$/);
  // Torch 2's copies are drawn, faded, 500 mm up; torch 1's are the editable ones.
  assert.equal(await page.$$eval('.nest-slave[data-torch="2"] path', (l) => l.length), 3);
  assert.equal(await page.$$eval('.nest-svg .nest-copy', (l) => l.length), 3);

  const [download] = await Promise.all([page.waitForEvent('download'), page.click('#download')]);
  const file = path.join(app.downloadDir, download.suggestedFilename());
  await download.saveAs(file);
  const lines = fs.readFileSync(file, 'utf8').split('\n').map((l) => l.trim());
  const at = (re) => lines.findIndex((l) => re.test(l));
  const comment = at(/\(2 torches 500 mm apart in Y: this program drives torch 1/);
  const park = at(/^G0 X0 Y1200$/);
  const stop = at(/^M0$/);
  const firstOn = at(/^M3/);
  assert.ok(comment >= 0 && comment < park && park < stop && stop < firstOn, `${comment} ${park} ${stop} ${firstOn}`);
  // Single path: three plates (outline + 6 holes each) and the crop line, nothing of torch 2.
  assert.equal(lines.filter((l) => /^M3/.test(l)).length, 3 * 7 + 1);
  assertRs274Accepts(file);
});
