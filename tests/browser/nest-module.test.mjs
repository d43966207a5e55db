// The nesting engine is a wasm module of its own (issue 17: the cutting core stays small). In Debian's
// headless chromium: a page that only cuts a drawing never fetches it; the first parts file dropped in
// Sheet mode loads it, once, and the nester answers through it (the part's row with its units).
//
//   node --test tests/browser/nest-module.test.mjs

import assert from 'node:assert/strict';
import fs from 'node:fs';
import { after, before, test } from 'node:test';
import { fixture, openApp, untilReady } from './harness.mjs';
import { dropInPage } from './helpers.mjs';

const PLATE = 'seed000-plate-6-holes.dxf';

let app;
let page;
const fetched = []; // every wasm the page or its worker asked for, by file name

before(async () => {
  app = await openApp();
  page = app.page;
});

after(async () => {
  await app?.close();
});

const drop = (name) => page.evaluate(dropInPage, { name, base64: fs.readFileSync(fixture(name)).toString('base64') });

test('the nester module loads only when Sheet mode first needs it', async () => {
  // Requests from here on (the worker's too); the page has already loaded the cutting core.
  page.on('request', (r) => {
    const m = /\/pkg\/([^/?]+\.wasm)/.exec(r.url());
    if (m) fetched.push(m[1]);
  });
  // A drawing cut in the ordinary mode: the cutting core alone.
  await untilReady(page, () => drop(PLATE));
  assert.equal(await page.evaluate(() => window.kerfcam.lastReport !== null), true);
  assert.deepEqual(fetched.filter((f) => f.includes('nest')), [], 'cutting a drawing fetched the nester module');

  // Sheet mode: the first parts file asks the nester for its parts, which loads its module.
  await page.click('#mode-sheet');
  await drop(PLATE);
  await page.waitForSelector(`#parts li.part[data-name="${PLATE}"] [data-units]`);
  assert.match(await page.textContent(`#parts li.part[data-name="${PLATE}"]`), /1 part: seed000-plate-6-holes/);
  assert.deepEqual(fetched.filter((f) => f.includes('nest')), ['kerfcam_nest_bg.wasm']);
  assert.deepEqual(app.pageErrors, []);
});
