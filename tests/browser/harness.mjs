// Shared pieces of the browser tests: Debian's chromium through playwright-core (never a downloaded
// browser), the app served from www/, and LinuxCNC's rs274 as the judge of every program.

import assert from 'node:assert/strict';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { after, before } from 'node:test';
import { fileURLToPath } from 'node:url';
import { chromium } from 'playwright-core';
import { startServer } from '../../scripts/serve.mjs';
import { checkWithRs274, dropInPage, which } from './helpers.mjs';

// One rs274 check and one `which` for every browser test (helpers.mjs).
export { checkWithRs274 as assertRs274Accepts, which };

export const repoRoot = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..', '..');
export const shared = path.resolve(repoRoot, '..', 'shared');
export const fixture = (name) => path.join(shared, 'fixtures', name);

/** A part file's row in Sheet mode's parts list. */
export const partRow = (name) => `#parts li.part[data-name="${name}"]`;

/**
 * The Sheet-mode tests' verbs on the page `pageOf()` gives (it is opened in their `before`): drop a
 * fixture or bytes as a user drops a file, an element's text, the last nest, the page ready with a report.
 */
export function sheetVerbs(pageOf) {
  const dropBytes = (name, bytes) => pageOf().evaluate(dropInPage, { name, base64: Buffer.from(bytes).toString('base64') });
  const drop = (name) => dropBytes(name, fs.readFileSync(fixture(name)));
  return {
    dropBytes,
    drop,
    /**
     * Sheet mode with fixtures dropped as a user drops them, each ready on its row with its quantity
     * (`parts`: { file name: quantity }), the sheet `w` × `h` mm and the nest time `time` s typed in.
     */
    async loadParts(parts, { sheet: [w, h], time }) {
      const page = pageOf();
      await page.click('#mode-sheet');
      for (const name of Object.keys(parts)) await drop(name);
      for (const [name, qty] of Object.entries(parts)) {
        await page.waitForSelector(`${partRow(name)} [data-units]`);
        await page.fill(`${partRow(name)} input.qty`, String(qty));
      }
      await page.fill('#sheet-w', String(w));
      await page.fill('#sheet-h', String(h));
      await page.fill('#nest-time', String(time));
    },
    /**
     * Sheet sizes typed as a user types them: the first row's count and cost in the sheet's own fields, each
     * further row added by "Add size" with its width, height, count and cost. A field not given is left as it is.
     */
    async typeSizes([first, ...more]) {
      const page = pageOf();
      const fill = async (sel, value) => {
        if (value !== undefined) await page.fill(sel, String(value));
      };
      await fill('#sheet-count', first.count);
      await fill('#sheet-cost', first.cost);
      for (const [k, row] of more.entries()) {
        await page.click('#sheet-size-add');
        for (const field of ['width', 'height', 'count', 'cost']) await fill(`#sheet-size-${k + 1}-${field}`, row[field]);
      }
    },
    text: (sel) => pageOf().$eval(sel, (e) => e.textContent),
    nest: () => pageOf().evaluate(() => window.kerfcam.lastNest),
    ready: () => pageOf().waitForFunction(() => document.getElementById('status').dataset.state === 'ready' && window.kerfcam.lastReport !== null),
  };
}
export const corpus = (...parts) => path.join(shared, 'corpus', ...parts);

export const CHROMIUM_ARGS = [
  '--headless', '--no-sandbox', '--disable-gpu', '--disable-background-networking', '--disable-component-update',
  '--no-first-run', '--disable-sync', '--disable-quic',
];

// One chromium for every test file (issue 40): scripts/browser-tests.mjs launches it and names its endpoint
// in KERFCAM_CHROMIUM_WS; each openApp is then a fresh context of it (its own storage, cache and service
// workers, as a fresh profile has) instead of a browser of its own. Without the variable (a test file run
// alone) each openApp launches chromium with a fresh profile.
let sharedBrowser = null; // { browser: Promise<Browser>, open: number }

async function newContext(options) {
  const ws = process.env.KERFCAM_CHROMIUM_WS;
  if (ws) {
    sharedBrowser ??= { browser: chromium.connect(ws), open: 0 };
    const mine = sharedBrowser;
    mine.open++;
    const context = await (await mine.browser).newContext(options);
    // The connection is dropped when its last context closes, so a test file's process can end.
    const release = async () => {
      if (--mine.open === 0) {
        if (sharedBrowser === mine) sharedBrowser = null;
        await (await mine.browser).close();
      }
    };
    return { context, userDataDir: null, close: async () => { await context.close(); await release(); } };
  }
  const executablePath = process.env.CHROMIUM || which('chromium');
  assert.ok(executablePath, 'chromium is not on PATH: run scripts/setup.sh test');
  const userDataDir = fs.mkdtempSync(path.join(os.tmpdir(), 'kerfcam-chromium-'));
  const context = await chromium.launchPersistentContext(userDataDir, {
    executablePath, headless: true, args: CHROMIUM_ARGS, ...options,
  });
  return { context, userDataDir, close: () => context.close() };
}

/**
 * Serves www/ (`markers`: scripts/serve.mjs's nester-build markers, for a test of their own) and opens it in a
 * fresh headless chromium context. Returns { server, context, page,
 * downloadDir, pageErrors, close }.
 */
export async function openApp({ viewport = { width: 1280, height: 800 }, markers = {} } = {}) {
  assert.ok(fs.existsSync(path.join(repoRoot, 'www', 'pkg', 'kerfcam_bg.wasm')), 'www/pkg missing: run scripts/build-wasm.sh');
  const server = await startServer(0, '127.0.0.1', markers);
  const downloadDir = fs.mkdtempSync(path.join(os.tmpdir(), 'kerfcam-downloads-'));
  const opened = await newContext({ acceptDownloads: true, viewport, ...(process.env.KERFCAM_CHROMIUM_WS ? {} : { downloadsPath: downloadDir }) });
  const { context, userDataDir } = opened;
  const page = context.pages()[0] ?? (await context.newPage());
  const pageErrors = [];
  page.on('pageerror', (e) => pageErrors.push(e));
  page.on('console', (m) => m.type() === 'error' && pageErrors.push(new Error(m.text())));
  await page.goto(server.url);
  await page.waitForFunction(() => document.getElementById('status').textContent !== 'loading');
  const close = async () => {
    await opened.close();
    await server.close();
    for (const dir of [userDataDir, downloadDir]) if (dir) fs.rmSync(dir, { recursive: true, force: true });
  };
  return { server, context, page, downloadDir, pageErrors, close };
}

/**
 * A test file's page: opened in its `before` hook at `viewport` (Sheet mode's tests' 1400 × 1000 unless
 * given), closed in its `after` hook. `opened(app)` receives the openApp handle once the page is open
 * (`page = app.page`), so a file's tests and its sheetVerbs read the page as before.
 */
export function pagePerFile(opened, { viewport = { width: 1400, height: 1000 } } = {}) {
  let app;
  before(async () => {
    app = await openApp({ viewport });
    opened(app);
  });
  after(async () => {
    await app?.close();
  });
}

/** Waits until the page shows a finished job (status "ready" with a report); returns the milliseconds it took. */
export async function untilReady(page, trigger, timeout = 60_000) {
  await page.evaluate(() => (window.kerfcam.lastReport = null));
  const t0 = performance.now();
  await trigger();
  await page.waitForFunction(
    () => {
      const status = document.getElementById('status').dataset.state; // the state's name in any language
      return status === 'error' || (status === 'ready' && window.kerfcam.lastReport !== null);
    },
    null,
    { timeout },
  );
  const ms = performance.now() - t0;
  const error = await page.$eval('#error', (e) => (e.hidden ? '' : e.textContent));
  assert.equal(error, '', 'the page reported an error');
  return ms;
}

/** Forgets the files the page keeps (a reload would open them again), when it has any. */
export async function clearFiles(page) {
  if (await page.isEnabled('#clear-files')) await page.click('#clear-files');
  await page.waitForFunction(() => document.querySelectorAll('#jobs li').length === 0);
}

/** Clicks Download and saves the program into `dir`; resolves to the saved file's path. */
export async function downloadProgram(page, dir) {
  const [d] = await Promise.all([page.waitForEvent('download'), page.click('#download')]);
  const file = path.join(dir, `${Date.now()}-${d.suggestedFilename()}`);
  await d.saveAs(file);
  return file;
}
