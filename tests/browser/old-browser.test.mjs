// The cutting core is built with WebAssembly SIMD (issue 17). A browser without it must be told, in
// words, which browsers run kerfcam — not shown a compile error naming an opcode — and dropping a
// file then must not throw. Debian's chromium has SIMD, so the test takes it away the way such a
// browser answers: WebAssembly.validate refuses the SIMD probe (and only the probe's answer changes).
//
//   node --test tests/browser/old-browser.test.mjs

import assert from 'node:assert/strict';
import fs from 'node:fs';
import { after, before, test } from 'node:test';
import { fixture, openApp } from './harness.mjs';
import { dropInPage } from './helpers.mjs';

let app;
let page;

before(async () => {
  app = await openApp();
  page = app.page;
});

after(async () => {
  await app?.close();
});

test('this chromium runs the engine: no message, the version shown', async () => {
  assert.equal(await page.$eval('#error', (e) => (e.hidden ? '' : e.textContent)), '');
  assert.match(await page.$eval('#version', (e) => e.textContent), /^v\d/);
});

test('a browser without WebAssembly SIMD is told which browsers run kerfcam', async () => {
  await app.context.addInitScript(() => {
    const validate = WebAssembly.validate;
    // The probe is the only SIMD module the page validates; every other answer stays the browser's.
    WebAssembly.validate = (bytes) => (bytes.length === 29 && bytes[14] === 123 ? false : validate(bytes));
  });
  await page.reload();
  await page.waitForFunction(() => document.getElementById('status').dataset.state === 'error');
  const message = await page.$eval('#error', (e) => (e.hidden ? '' : e.textContent));
  assert.match(message, /WebAssembly SIMD/);
  assert.match(message, /Chrome or Edge 91/);
  assert.match(message, /Firefox 89/);
  assert.match(message, /Safari 16\.4/);
  // A file dropped anyway is not run, and nothing throws over the message.
  const name = 'seed000-plate-6-holes.dxf';
  await page.evaluate(dropInPage, { name, base64: fs.readFileSync(fixture(name)).toString('base64') });
  await page.waitForTimeout(500);
  assert.equal(await page.$eval('#error', (e) => e.textContent), message);
  assert.deepEqual(app.pageErrors.map(String), []);
});
