// scripts/build-single.mjs on small made-up pages (no browser): the module forms it bundles behave as
// ES modules do once run, and what it cannot inline stops the build with a message naming the file.

import assert from 'node:assert/strict';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { after, test } from 'node:test';
import vm from 'node:vm';
import { BuildError, build } from '../../scripts/build-single.mjs';

const dirs = [];
after(() => dirs.forEach((d) => fs.rmSync(d, { recursive: true, force: true })));

const INDEX = `<!doctype html><html><head><link rel="icon" href="data:,">
<link rel="stylesheet" href="style.css"><script type="module" src="main.js"></script></head>
<body><p>page</p></body></html>`;

// Every import/export form the builder reads, and two files with the same top-level name (`local`).
const FILES = {
  'index.html': INDEX,
  'style.css': 'p { color: red; background: url("data:,x"); }',
  'main.js': `import { a, b as bee } from './lib.js';
import seven, * as lib from './lib.js';
import { again } from './re.js';
import { Engine } from './engine.js';
const local = 'main';
globalThis.out = { a: a(), bee, seven, ns: lib.a(), again: again(), local, counter: lib.counter, engine: new Engine().url };
`,
  'lib.js': `const local = 'lib';
export function a() { return local; }
export const b = 2;
export let counter = 0;
counter = 5; // a live binding: importers see 5
export default 7;
`,
  're.js': `export { a as again } from './lib.js';\n`,
  'engine.js': `export class Engine {
  constructor() { this.url = globalThis.kerfcamEmbedded ? 'embedded' : new URL('./worker.js', import.meta.url).href; }
}
`,
  'worker.js': `import init, { version } from './pkg/kerfcam.js';\nself.out = init() + version();\n`,
  'pkg/kerfcam.js': `function version() { return '-1.0'; }
function __wbg_init() { return new URL('kerfcam_bg.wasm', import.meta.url).href; }
export { version };
function initSync() {}
export { initSync, __wbg_init as default };
`,
  'pkg/kerfcam_bg.wasm': Buffer.from([0, 0x61, 0x73, 0x6d, 1, 0, 0, 0]),
  'sw.js': 'self.addEventListener("fetch", () => {});',
};

function page(changes = {}) {
  const www = fs.mkdtempSync(path.join(os.tmpdir(), 'kerfcam-build-'));
  dirs.push(www);
  for (const [name, text] of Object.entries({ ...FILES, ...changes })) {
    if (text === null) continue;
    fs.mkdirSync(path.dirname(path.join(www, name)), { recursive: true });
    fs.writeFileSync(path.join(www, name), text);
  }
  return { www, out: path.join(www, 'dist', 'kerfcam.html') };
}

/** The text of the <script> whose opening tag matches `open`. */
const scriptOf = (html, open) => {
  const start = html.indexOf(open);
  assert.ok(start >= 0, `no ${open}`);
  return html.slice(start + open.length, html.indexOf('</script>', start));
};

test('the bundled page and worker run their modules as ES modules would', () => {
  const p = page();
  const r = build(p);
  const html = fs.readFileSync(r.out, 'utf8');
  assert.match(html, /<style>\np \{ color: red;/);
  assert.doesNotMatch(html, /src="|href="(?!data:)/, 'nothing left to load');
  assert.deepEqual(r.files.sort(), ['engine.js', 'index.html', 'lib.js', 'main.js', 'pkg/kerfcam.js', 'pkg/kerfcam_bg.wasm', 're.js', 'style.css', 'worker.js']);

  // The page's module script, with a document that has the page's blocks.
  const blocks = {
    'kerfcam-wasm': scriptOf(html, '<script type="application/octet-stream" id="kerfcam-wasm">'),
    'kerfcam-worker': scriptOf(html, '<script type="text/plain" id="kerfcam-worker">'),
  };
  const urls = [];
  const context = vm.createContext({
    document: { getElementById: (id) => ({ textContent: blocks[id] }) },
    URL: Object.assign(function (...a) { return new URL(...a); }, { createObjectURL: (blob) => urls.push(blob) && 'blob:null/1' }),
    Blob, atob, Uint8Array,
  });
  // A module script; vm runs classic scripts, so its one import.meta becomes the page's address here.
  vm.runInContext(scriptOf(html, '<script type="module">').replaceAll('import.meta.url', '"file:///page.html"'), context);
  assert.deepEqual({ ...context.out }, { a: 'lib', bee: 2, seven: 7, ns: 'lib', again: 'lib', local: 'main', counter: 5, engine: 'embedded' });
  assert.deepEqual([...context.kerfcamEmbedded.wasm], [...FILES['pkg/kerfcam_bg.wasm']]);
  assert.equal(urls.length, 1);

  // The worker: a classic script, import.meta.url read as its own location.
  const self = { location: { href: 'file:///somewhere/worker.js' } };
  vm.runInNewContext(blocks['kerfcam-worker'], { self, URL });
  assert.equal(self.out, 'file:///somewhere/kerfcam_bg.wasm-1.0');
});

test('what cannot be inlined stops the build, naming the file', () => {
  const cases = [
    [{ 'lib.js': `${FILES['lib.js']}export * from './re.js';\n` }, /lib\.js: export \* is not supported/],
    [{ 'lib.js': `import x from 'some-package';\n${FILES['lib.js']}` }, /bare import "some-package"/],
    // A literal ./ path is bundled like a static import (the worker's nester glue), so it must exist; any
    // other import() is refused.
    [{ 'lib.js': `${FILES['lib.js']}const m = () => import('./gone.js');\n` }, /lib\.js imports gone\.js, which does not exist/],
    [{ 'lib.js': `${FILES['lib.js']}const m = (p) => import(p);\n` }, /lib\.js: import\(\) of other than a literal \.\/ path/],
    [{ 'lib.js': `import { again } from './re.js';\n${FILES['lib.js']}` }, /import cycle/],
    [{ 'main.js': `import { nope } from './lib.js';\n` }, /main\.js imports nope from lib\.js, which does not export it/],
    [{ 'main.js': `import { x } from './missing.js';\n` }, /imports missing\.js, which does not exist/],
    [{ 'lib.js': `${FILES['lib.js']}const t = fetch('./strings.json');\n` }, /lib\.js: fetch\('\.\/strings\.json'\)/],
    [{ 'index.html': INDEX.replace('</head>', '<link rel="manifest" href="app.webmanifest"></head>') }, /refers to "app\.webmanifest"/],
    [{ 'style.css': '@font-face { src: url(font.woff2); }' }, /style\.css: url\(\) or @import/],
    [{ 'pkg/kerfcam_bg.wasm': null }, /kerfcam_bg\.wasm is missing/],
    [{ 'engine.js': 'export class Engine {}\n' }, /expected one worker/],
  ];
  for (const [changes, message] of cases) {
    assert.throws(() => build(page(changes)), (e) => e instanceof BuildError && message.test(e.message), String(message));
  }
});
