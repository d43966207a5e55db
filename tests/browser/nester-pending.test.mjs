// npm start serves the page as soon as the cutting core is built and builds the nester module meanwhile
// (scripts/build-wasm.sh --serve, issue 40). In Debian's headless chromium: while the nester's build is
// pending, the server holds its files and Sheet mode's first parts file waits for them; once the build
// ends, the same request is answered and the part's row appears. A failed build answers 503 and the page
// says the nester could not be loaded. The markers here are the test's own files, not www/pkg's.
//
//   node --test tests/browser/nester-pending.test.mjs

import assert from 'node:assert/strict';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { after, before, test } from 'node:test';
import { fixture, openApp } from './harness.mjs';
import { dropInPage } from './helpers.mjs';

const PLATE = 'seed000-plate-6-holes.dxf';
const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'kerfcam-nester-pending-'));
const markers = { pending: path.join(dir, '.nester-pending'), failed: path.join(dir, '.nester-failed') };

let app;
let page;

before(async () => {
  // A live process (this one) building the nester: its files are held.
  fs.writeFileSync(markers.pending, `${process.pid}\n`);
  app = await openApp({ markers });
  page = app.page;
});

after(async () => {
  await app?.close();
  fs.rmSync(dir, { recursive: true, force: true });
});

const drop = (name) => page.evaluate(dropInPage, { name, base64: fs.readFileSync(fixture(name)).toString('base64') });
const row = `#parts li.part[data-name="${PLATE}"] [data-units]`;

test('Sheet mode waits for a nester module still being built, then nests with it', async () => {
  const asked = [];
  page.on('request', (r) => /kerfcam_nest/.test(r.url()) && asked.push(r.url()));
  await page.click('#mode-sheet');
  await drop(PLATE);
  // The worker asked for the nester; the server holds it: no row yet, and the page is not in error.
  const deadline = Date.now() + 3000;
  while (Date.now() < deadline && asked.length === 0) await new Promise((r) => setTimeout(r, 100));
  assert.ok(asked.length > 0, 'Sheet mode did not ask for the nester module');
  await new Promise((r) => setTimeout(r, 1500));
  assert.equal(await page.$(row), null, 'a part row appeared while the nester was held back');
  assert.equal(await page.$eval('#error', (e) => e.hidden), true, 'the page shows an error while waiting');
  // The build ends: the held request is answered and the row appears.
  fs.rmSync(markers.pending);
  await page.waitForSelector(row, { timeout: 30_000 });
  assert.match(await page.textContent(`#parts li.part[data-name="${PLATE}"]`), /1 part: seed000-plate-6-holes/);
  assert.deepEqual(app.pageErrors, []);
});

test('a marker whose build is gone holds nothing back, and a failed build answers 503', async () => {
  const url = `${app.server.url}pkg/kerfcam_nest.js`;
  // A process id nothing runs as (the largest pid_max allows is 4194304).
  fs.writeFileSync(markers.pending, '4194303\n');
  const t0 = Date.now();
  let r = await fetch(url);
  assert.equal(r.status, 200);
  assert.ok(Date.now() - t0 < 5000);
  fs.rmSync(markers.pending);
  fs.writeFileSync(markers.failed, 'the nester module\'s build failed: see npm start\'s output\n');
  r = await fetch(url);
  assert.equal(r.status, 503);
  assert.match(await r.text(), /build failed/);
  // The cutting core is never held.
  r = await fetch(`${app.server.url}pkg/kerfcam.js`);
  assert.equal(r.status, 200);
});
