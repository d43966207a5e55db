// The service worker's SHELL list (www/sw.js) must name every file the page loads, or the app breaks
// offline in a way no online test sees. No browser needed: the list is read from the source.
//
//   node --test tests/browser/offline-shell.test.mjs

import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { test } from 'node:test';
import { repoRoot } from './harness.mjs';

const www = path.join(repoRoot, 'www');

test('the service worker caches every module, style sheet and the wasm of the page', () => {
  const sw = fs.readFileSync(path.join(www, 'sw.js'), 'utf8');
  const list = sw.match(/const SHELL = \[([\s\S]*?)\];/);
  assert.ok(list, 'sw.js has a SHELL list');
  const shell = new Set([...list[1].matchAll(/'\.\/([^']*)'/g)].map((m) => m[1]));
  const needed = [
    'index.html',
    ...fs.readdirSync(www).filter((f) => /\.(js|css)$/.test(f) && f !== 'sw.js'),
    'vendor/fflate.js', 'pkg/kerfcam.js', 'pkg/kerfcam_bg.wasm', 'pkg/kerfcam_nest.js', 'pkg/kerfcam_nest_bg.wasm',
  ];
  assert.deepEqual(needed.filter((f) => !shell.has(f)), [], 'files the page loads but the service worker does not keep');
  // And every module a page module imports is one of them.
  for (const f of fs.readdirSync(www).filter((f) => f.endsWith('.js'))) {
    const src = fs.readFileSync(path.join(www, f), 'utf8');
    for (const [, spec] of src.matchAll(/^\s*import[^'"]*['"]\.\/([^'"]+)['"]/gm)) {
      assert.ok(shell.has(spec), `${f} imports ./${spec}, which sw.js does not cache`);
    }
  }
});
