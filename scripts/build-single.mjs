// Builds dist/kerfcam.html: the whole app in one file that works opened straight from disk (file://),
// with no request to any host. Run after scripts/build-wasm.sh (`npm run build` does both).
//
//   node scripts/build-single.mjs [out.html]
//
// What goes in, all read from www/ by following the page's own references (no hard-coded file list):
//   - every <link rel="stylesheet"> becomes a <style>;
//   - the <script type="module" src> entry and every module it imports are concatenated in dependency
//     order, each in its own function scope (see bundle()), into one inline module script;
//   - a Web Worker named as `new URL('./x.js', import.meta.url)` is bundled the same way into a
//     non-executed <script type="text/plain"> block; the page turns it into a blob: URL (a file:// page may
//     not start a worker from a file). It runs as a classic worker, with import.meta.url read as
//     self.location.href: Chromium refuses a *module* worker from a file:// page's blob: URL (its origin is
//     opaque, "blob:null/…"), and a bundle has no import left that would need one;
//   - the wasm goes in base64 in another non-executed block; the page decodes it and hands the bytes to
//     the worker, so wasm-bindgen's init never fetches kerfcam_bg.wasm; the nester module
//     (kerfcam_nest_bg.wasm, when the worker imports its glue) goes in a third block, handed over as
//     base64 text that the worker decodes when Sheet mode first nests.
// The hand-overs reach www/engine.js through globalThis.kerfcamEmbedded = { workerUrl, wasm, nest }, set by
// a few lines put before the modules. The service worker is not included: main.js registers it on http(s)
// only, and a file:// page has none.
//
// No bundler dependency: the www modules are plain ES modules whose import/export statements start at the
// beginning of a line, which is all this handles. Anything else (export *, dynamic import(), an import
// cycle, a resource other than a worker or a data: URL) stops the build with a message rather than
// producing a page that fails at run time.

import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import zlib from 'node:zlib';

const ROOT = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
let WWW = path.join(ROOT, 'www'); // build({ www }) points it elsewhere (the builder's own test)
const IDS = { worker: 'kerfcam-worker', wasm: 'kerfcam-wasm', nest: 'kerfcam-nest-wasm' };

export class BuildError extends Error {}
const fail = (message) => {
  throw new BuildError(message);
};
const rel = (file) => path.relative(WWW, file).split(path.sep).join('/');

// --- modules ---------------------------------------------------------------------------------------

const IMPORT = /^import\s+(?:([\w$]+)\s*,?\s*)?(?:\*\s+as\s+([\w$]+)\s*)?(?:\{([^}]*)\}\s*)?(?:from\s*)?(['"])([^'"]+)\4\s*;?[ \t]*$/gm;
const DYNAMIC_IMPORT = /\bimport\s*\(\s*(['"])(\.\.?\/[^'"]+)\1\s*\)/g;
const EXPORT_DECL = /^export\s+(default\s+)?((?:async\s+)?function\s*\*?\s*|class\s+|const\s+|let\s+|var\s+)([\w$]+)/gm;
const EXPORT_LIST = /^export\s*\{([^}]*)\}\s*(?:from\s*(['"])([^'"]+)\2)?\s*;?[ \t]*$/gm;
const EXPORT_DEFAULT_EXPR = /^export\s+default\s+/gm;
const WORKER_URL = /new\s+URL\(\s*(['"])(\.{1,2}\/[^'"]+\.js)\1\s*,\s*import\.meta\.url\s*\)/g;

/** `a, b as c` → [[a, a], [b, c]]: [local, exported] pairs (or [imported, local] for imports). */
function names(list) {
  return list
    .split(',')
    .map((s) => s.trim())
    .filter(Boolean)
    .map((s) => {
      const m = /^([\w$]+)(?:\s+as\s+([\w$]+))?$/.exec(s);
      if (!m) fail(`cannot read the name list item "${s}"`);
      return [m[1], m[2] ?? m[1]];
    });
}

/** Reads one module: its source with the import/export syntax taken out, its imports and its exports. */
function parseModule(file) {
  let src = fs.readFileSync(file, 'utf8');
  const where = rel(file);
  // import('./x.js') with a literal path (the worker's nester glue, loaded when Sheet mode first needs it) is
  // bundled like a static import, the expression becoming a promise of its namespace; any other is refused.
  const dynamic = [];
  src = src.replace(DYNAMIC_IMPORT, (_, _q, spec) => {
    const namespace = `__dynamic_import_${dynamic.length}`;
    dynamic.push({ spec, namespace });
    return `Promise.resolve(${namespace})`;
  });
  if (/\bimport\s*\(/.test(src.replace(/\/\/.*$/gm, ''))) fail(`${where}: import() of other than a literal ./ path is not supported`);
  if (/^export\s*\*/m.test(src)) fail(`${where}: export * is not supported`);
  // A file fetched at run time would be a request from file://, and fails there: import it instead.
  const fetched = /\bfetch\(\s*(['"`])(?![a-z]+:)([^'"`]*)\1/.exec(src);
  if (fetched) fail(`${where}: fetch('${fetched[2]}') of a file cannot work in the single file; import it as a module`);
  const imports = []; // { from, default?, namespace?, named: [[imported, local]] }
  const exports = []; // [local, exported]
  const resolve = (spec) => {
    if (!spec.startsWith('./') && !spec.startsWith('../')) fail(`${where}: bare import "${spec}" (only ./ and ../ paths)`);
    return path.resolve(path.dirname(file), spec);
  };

  src = src.replace(IMPORT, (_, def, ns, list, _q, spec) => {
    imports.push({ from: resolve(spec), default: def, namespace: ns, named: list ? names(list) : [] });
    return '';
  });
  for (const { spec, namespace } of dynamic) imports.push({ from: resolve(spec), namespace, named: [] });
  src = src.replace(EXPORT_LIST, (_, list, _q, spec) => {
    const pairs = names(list);
    if (spec) {
      // export { a as b } from './x.js': import under private names, export those
      const named = pairs.map(([imported, exported]) => [imported, `__reexport_${exported}`]);
      imports.push({ from: resolve(spec), named });
      for (const [, exported] of pairs) exports.push([`__reexport_${exported}`, exported]);
    } else exports.push(...pairs);
    return '';
  });
  src = src.replace(EXPORT_DECL, (_, isDefault, kind, name) => {
    exports.push([name, isDefault ? 'default' : name]);
    return `${kind}${name}`;
  });
  src = src.replace(EXPORT_DEFAULT_EXPR, () => {
    exports.push(['__default', 'default']);
    return 'const __default = ';
  });
  const left = /^(import|export)\b.*$/m.exec(src);
  if (left) fail(`${where}: cannot bundle the statement "${left[0].slice(0, 80)}"`);
  return { file, src, imports, exports };
}

/**
 * Concatenates `entry` and every module it imports (dependency order) into one script. Each module runs
 * in its own function scope, so top-level names of different files cannot clash, and returns its exports
 * as getters (live bindings, as in a real module).
 */
function bundle(entry) {
  const order = [];
  const state = new Map(); // file → 'visiting' | 'done'
  const modules = new Map();
  const visit = (file, from) => {
    if (state.get(file) === 'done') return;
    if (state.get(file) === 'visiting') fail(`import cycle through ${rel(file)}: not supported`);
    if (!fs.existsSync(file)) fail(`${from ? rel(from) : 'index.html'} imports ${rel(file)}, which does not exist`);
    state.set(file, 'visiting');
    const m = parseModule(file);
    modules.set(file, m);
    for (const i of m.imports) visit(i.from, file);
    state.set(file, 'done');
    order.push(m);
  };
  visit(entry, null);

  const id = new Map(order.map((m, i) => [m.file, `__kerfcam_m${i}`]));
  const parts = order.map((m) => {
    const bindings = m.imports.map((i) => {
      const dep = modules.get(i.from);
      const v = id.get(i.from);
      const out = [];
      const has = (name) => dep.exports.some(([, exported]) => exported === name);
      if (i.namespace) out.push(`const ${i.namespace} = ${v};`);
      if (i.default) {
        if (!has('default')) fail(`${rel(m.file)} imports a default from ${rel(i.from)}, which has none`);
        out.push(`const ${i.default} = ${v}.default;`);
      }
      for (const [imported, local] of i.named) {
        if (!has(imported)) fail(`${rel(m.file)} imports ${imported} from ${rel(i.from)}, which does not export it`);
      }
      if (i.named.length) out.push(`const { ${i.named.map(([a, b]) => (a === b ? a : `${a}: ${b}`)).join(', ')} } = ${v};`);
      return out.join('\n');
    });
    const getters = m.exports.map(([local, exported]) => `get ${exported}() { return ${local}; }`);
    return (
      `// ---- ${rel(m.file)} ----\nconst ${id.get(m.file)} = (() => {\n${bindings.join('\n')}\n` +
      `${m.src}\nreturn Object.freeze({ ${getters.join(', ')} });\n})();\n`
    );
  });
  return { code: parts.join('\n'), modules: order };
}

// --- the page --------------------------------------------------------------------------------------

/** Text safe inside a <script> or <style> element: no closing tag and no comment opener can occur. */
function scriptText(text, tag) {
  const safe = text.replace(new RegExp(`</(${tag})`, 'gi'), '<\\/$1');
  if (/<!--/.test(safe)) fail(`"<!--" in text inlined into <${tag}>: rewrite it (e.g. '<' + '!--')`);
  return safe;
}

// Runs before the modules: hands the worker and the wasm bytes to engine.js (globalThis.kerfcamEmbedded).
const BOOT = `// ---- single-file build: the worker and the wasm come from the blocks at the end of the page ----
{
  const text = (id) => document.getElementById(id).textContent;
  const base64 = text(${JSON.stringify(IDS.wasm)}).replace(/\\s+/g, '');
  let wasm;
  if (typeof Uint8Array.fromBase64 === 'function') wasm = Uint8Array.fromBase64(base64);
  else {
    const bin = atob(base64);
    wasm = new Uint8Array(bin.length);
    for (let i = 0; i < bin.length; i++) wasm[i] = bin.charCodeAt(i);
  }
  const workerUrl = URL.createObjectURL(new Blob([text(${JSON.stringify(IDS.worker)})], { type: 'text/javascript' }));
  // The nester module (when the worker imports it) stays base64 text: the worker decodes it when Sheet
  // mode first nests, so a page that only cuts never spends time on it.
  const nest = document.getElementById(${JSON.stringify(IDS.nest)})?.textContent ?? null;
  globalThis.kerfcamEmbedded = Object.freeze({ workerUrl, wasm, nest });
}
`;

/** Writes the single file to `out` from the page in `www`; returns { out, bytes, gzip, files }. */
export function build({ out = path.join(ROOT, 'dist', 'kerfcam.html'), www = path.join(ROOT, 'www') } = {}) {
  WWW = path.resolve(www);
  const WASM = path.join(WWW, 'pkg', 'kerfcam_bg.wasm');
  if (!fs.existsSync(WASM)) fail('www/pkg/kerfcam_bg.wasm is missing: run scripts/build-wasm.sh (or npm run build)');
  let html = fs.readFileSync(path.join(WWW, 'index.html'), 'utf8');
  const used = new Set([path.join(WWW, 'index.html')]);

  html = html.replace(/<link\s+rel="stylesheet"\s+href="([^"]+)"\s*\/?>/g, (_, href) => {
    const file = path.resolve(WWW, href);
    const css = fs.readFileSync(file, 'utf8');
    if (/url\(\s*(?!['"]?data:)|@import/.test(css)) fail(`${href}: url() or @import of a file cannot be inlined`);
    used.add(file);
    return `<style>\n${scriptText(css, 'style')}\n</style>`;
  });

  const workers = [];
  html = html.replace(/<script\s+type="module"\s+src="([^"]+)"\s*><\/script>/g, (_, src) => {
    const main = bundle(path.resolve(WWW, src));
    for (const m of main.modules) {
      used.add(m.file);
      // The expression stays (engine.js uses kerfcamEmbedded.workerUrl instead when it is set).
      for (const [, , spec] of m.src.matchAll(WORKER_URL)) workers.push(path.resolve(path.dirname(m.file), spec));
    }
    return `<script type="module">\n${scriptText(BOOT + main.code, 'script')}</script>`;
  });
  if (new Set(workers).size !== 1) {
    fail(`expected one worker (new URL('./….js', import.meta.url)) in the page's modules, found ${workers.length}`);
  }
  const worker = bundle(workers[0]);
  worker.code = `'use strict';\n${worker.code.replace(/\bimport\.meta\.url\b/g, 'self.location.href')}`;
  if (/\bimport\.meta\b/.test(worker.code)) fail(`${rel(workers[0])}: import.meta other than import.meta.url in the worker`);
  worker.modules.forEach((m) => used.add(m.file));

  // Nothing else may point at a file or a host: the page must load with the network gone.
  const external = /<(?:script|link|img|iframe|source|video|audio|embed|object)\b[^>]*\b(?:src|href|data)="(?!data:|#)([^"]*)"/i.exec(html);
  if (external) fail(`index.html refers to "${external[1]}", which is not inlined`);

  const wasm = fs.readFileSync(WASM);
  used.add(WASM);
  const base64 = (bytes) => bytes.toString('base64').replace(/.{1,100}/g, '$&\n');
  let blocks =
    `<script type="text/plain" id="${IDS.worker}">\n${scriptText(worker.code, 'script')}</script>\n` +
    `<script type="application/octet-stream" id="${IDS.wasm}">\n${base64(wasm)}</script>\n`;
  // The nesting engine's module (issue 17), when the worker imports its glue: embedded beside the core.
  const NEST = path.join(WWW, 'pkg', 'kerfcam_nest_bg.wasm');
  if (worker.modules.some((m) => m.file === path.join(WWW, 'pkg', 'kerfcam_nest.js'))) {
    if (!fs.existsSync(NEST)) fail('www/pkg/kerfcam_nest_bg.wasm is missing: run scripts/build-wasm.sh (or npm run build)');
    used.add(NEST);
    blocks += `<script type="application/octet-stream" id="${IDS.nest}">\n${base64(fs.readFileSync(NEST))}</script>\n`;
  }
  if (!html.includes('</body>')) fail('index.html has no </body>');
  html = html.replace('</body>', `${blocks}</body>`);

  // Every www script and style sheet is either in the page or known not to belong there.
  const skipped = fs
    .readdirSync(WWW)
    .filter((f) => /\.(js|css)$/.test(f) && f !== 'sw.js')
    .map((f) => path.join(WWW, f))
    .filter((f) => !used.has(f));
  for (const f of skipped) console.warn(`note: www/${rel(f)} is not referenced by the page; not included`);

  fs.mkdirSync(path.dirname(out), { recursive: true });
  fs.writeFileSync(out, html);
  const gzip = zlib.gzipSync(html, { level: 9 }).length;
  return { out, bytes: Buffer.byteLength(html), gzip, files: [...used].map(rel) };
}

const isMain = process.argv[1] && path.resolve(process.argv[1]) === fileURLToPath(import.meta.url);
if (isMain) {
  try {
    const r = build(process.argv[2] ? { out: path.resolve(process.argv[2]) } : {});
    const kib = (n) => `${(n / 1024).toFixed(0)} KiB`;
    console.log(`${path.relative(process.cwd(), r.out)}: ${r.bytes} bytes (${kib(r.bytes)}), gzip -9 ${r.gzip} bytes (${kib(r.gzip)})`);
    console.log(`inlined: ${r.files.join(', ')}`);
  } catch (e) {
    if (!(e instanceof BuildError)) throw e;
    console.error(`build-single: ${e.message}`);
    process.exit(1);
  }
}
