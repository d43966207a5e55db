// The single-file build (issue 6 §1b): dist/kerfcam.html, opened straight from disk (file://) in Debian's
// Chromium (playwright-core) and Firefox ESR (puppeteer-core over WebDriver BiDi), does the whole job —
// drop a DXF, get the G-code, rs274 accepts it — and asks no host for anything.
//
// "No request": in Chromium, context-level routing sees every request of the page and its worker (every
// URL must be file:, data: or blob:; others are recorded and aborted). In Firefox, every http(s) request
// of the whole browser, loopback included, goes through a proxy that records them all (helpers.mjs), and
// its background traffic is switched off by prefs, so the proxy must see nothing. (Chromium's own
// services call Google through a proxy whatever the flags, so there a proxy cannot tell page from browser.)
// Each check is shown to work first: a canary request made by the page (and by the worker, in Chromium)
// must be seen. Neither browser may download anything: both are Debian's.
//
// Needs www/pkg (scripts/build-wasm.sh), `chromium`, `firefox-esr` and `rs274` (scripts/setup.sh test).
// CHROMIUM= and FIREFOX= override the browsers.

import assert from 'node:assert/strict';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { after, before, test } from 'node:test';
import { fileURLToPath, pathToFileURL } from 'node:url';
import { chromium } from 'playwright-core';
import puppeteer from 'puppeteer-core';
import { build } from '../../scripts/build-single.mjs';
import { checkWithRs274, dropInPage, startTrapProxy, which } from './helpers.mjs';

process.env.PUPPETEER_SKIP_DOWNLOAD = '1'; // puppeteer-core never downloads; say so anyway

const repoRoot = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..', '..');
const PLATE = path.resolve(repoRoot, '..', 'shared', 'fixtures', 'seed000-plate-6-holes.dxf');
const LOCAL = /^(file|data|blob):/;
const CANARY = 'http://canary.invalid/';

let single; // { out, bytes, gzip }
let pageUrl;
let proxy;
const dirs = [];
const tempDir = (prefix) => {
  const d = fs.mkdtempSync(path.join(os.tmpdir(), prefix));
  dirs.push(d);
  return d;
};

before(async () => {
  assert.ok(fs.existsSync(path.join(repoRoot, 'www', 'pkg', 'kerfcam_bg.wasm')), 'www/pkg missing: run scripts/build-wasm.sh');
  single = build(); // the page under test is built from the current www/, into dist/kerfcam.html
  // Opened from a folder of its own: a file it still needed (www/pkg/…) could not be found next to it.
  const alone = path.join(tempDir('kerfcam-single-page-'), 'kerfcam.html');
  fs.copyFileSync(single.out, alone);
  pageUrl = pathToFileURL(alone).href;
  console.log(`measurement: ${path.relative(repoRoot, single.out)} ${single.bytes} bytes, gzip -9 ${single.gzip} bytes`);
  proxy = await startTrapProxy();
});

after(async () => {
  await proxy?.close();
  for (const d of dirs) fs.rmSync(d, { recursive: true, force: true });
});

/** The page's state, read the same way in both browsers. */
const pageState = () => ({
  status: document.getElementById('status').textContent,
  error: document.getElementById('error').hidden ? '' : document.getElementById('error').textContent,
  version: document.getElementById('version').textContent,
  protocol: location.protocol,
  controlled: Boolean(navigator.serviceWorker?.controller),
  gcode: window.kerfcam?.lastGcode ?? null,
  pierces: window.kerfcam?.lastReport?.plan?.pierces ?? null,
});
const isReady = () => {
  const s = document.getElementById('status').textContent;
  return s === 'error' || (s === 'ready' && window.kerfcam.lastReport !== null);
};
const dropArgs = () => ({ name: path.basename(PLATE), base64: fs.readFileSync(PLATE).toString('base64') });

/** The checks common to both browsers once the downloaded program is on disk. */
function expectPlateProgram(state, file) {
  assert.equal(state.error, '');
  assert.equal(state.status, 'ready');
  assert.equal(state.pierces, 7, 'the plate: one outer and six holes');
  const gcode = fs.readFileSync(file, 'utf8');
  assert.equal(gcode, state.gcode, 'the download is the program the page made');
  assert.match(gcode, /^%\r?\n\(/);
  checkWithRs274(file);
}

test('Chromium: the single file from file:// does the whole job with no request to any host', async () => {
  const executablePath = process.env.CHROMIUM || which('chromium');
  assert.ok(executablePath, 'chromium is not on PATH: run scripts/setup.sh test');
  const downloads = tempDir('kerfcam-single-dl-');
  const context = await chromium.launchPersistentContext(tempDir('kerfcam-single-chromium-'), {
    executablePath,
    headless: true,
    args: [
      '--no-sandbox', '--disable-gpu', '--disable-background-networking', '--disable-component-update',
      '--no-first-run', '--disable-sync', '--disable-quic',
    ],
    acceptDownloads: true,
    downloadsPath: downloads,
  });
  const requests = [];
  const errors = [];
  try {
    context.on('request', (r) => requests.push(r.url()));
    await context.route('**/*', (route) => {
      const url = route.request().url();
      if (LOCAL.test(url)) return route.continue();
      requests.push(url);
      return route.abort('blockedbyclient');
    });
    const page = context.pages()[0] ?? (await context.newPage());
    page.on('pageerror', (e) => errors.push(String(e)));
    page.on('console', (m) => m.type() === 'error' && errors.push(m.text()));
    await page.goto(pageUrl);
    await page.waitForFunction(() => document.getElementById('status').textContent !== 'loading');
    let state = await page.evaluate(pageState);
    assert.equal(state.error, '');
    assert.equal(state.status, 'waiting for a file');
    assert.equal(state.protocol, 'file:');
    assert.match(state.version, /^v\d/);

    await page.evaluate(dropInPage, dropArgs());
    await page.waitForFunction(isReady, null, { timeout: 60_000 });
    const [download] = await Promise.all([page.waitForEvent('download'), page.click('#download')]);
    assert.equal(download.suggestedFilename(), 'seed000-plate-6-holes.ngc');
    const file = path.join(downloads, download.suggestedFilename());
    await download.saveAs(file);
    state = await page.evaluate(pageState);
    expectPlateProgram(state, file);
    assert.equal(state.controlled, false, 'no service worker on file://');

    assert.deepEqual(errors, []);
    // Canaries: a request from the page and one from the engine worker are both seen (and blocked).
    assert.equal(page.workers().length, 1, 'the engine worker');
    await page.evaluate((url) => fetch(url).catch(() => null), `${CANARY}page`);
    await page.workers()[0].evaluate((url) => fetch(url).catch(() => null), `${CANARY}worker`);
  } finally {
    await context.close();
  }
  assert.deepEqual(requests.filter((u) => u.startsWith('file:')), [pageUrl], 'no file but the page itself');
  const remote = requests.filter((u) => !LOCAL.test(u));
  for (const who of ['page', 'worker']) assert.ok(remote.includes(`${CANARY}${who}`), `the ${who}'s canary request was seen`);
  assert.deepEqual(remote.filter((u) => !u.startsWith(CANARY)), [], 'requests to a host');
});

// Firefox's own background traffic (updates, telemetry, safe browsing, captive portal, remote settings…)
// is switched off, so the proxy sees only what the page asks for, which must be nothing.
function firefoxPrefs(downloads) {
  return {
    'app.update.enabled': false,
    'app.update.auto': false,
    'app.normandy.enabled': false,
    'browser.safebrowsing.malware.enabled': false,
    'browser.safebrowsing.phishing.enabled': false,
    'browser.safebrowsing.downloads.enabled': false,
    'browser.safebrowsing.downloads.remote.enabled': false,
    'browser.safebrowsing.blockedURIs.enabled': false,
    'browser.safebrowsing.provider.mozilla.updateURL': '',
    'browser.safebrowsing.provider.google4.updateURL': '',
    'browser.search.update': false,
    'browser.newtabpage.enabled': false,
    'browser.startup.page': 0,
    'browser.topsites.contile.enabled': false,
    'browser.newtabpage.activity-stream.feeds.system.topstories': false,
    'browser.newtabpage.activity-stream.feeds.snippets': false,
    'browser.ping-centre.telemetry': false,
    'datareporting.healthreport.uploadEnabled': false,
    'datareporting.policy.dataSubmissionEnabled': false,
    'toolkit.telemetry.enabled': false,
    'toolkit.telemetry.unified': false,
    'toolkit.telemetry.archive.enabled': false,
    'toolkit.telemetry.server': '',
    'network.captive-portal-service.enabled': false,
    'network.connectivity-service.enabled': false,
    'network.dns.disablePrefetch': true,
    'network.prefetch-next': false,
    'network.predictor.enabled': false,
    'extensions.update.enabled': false,
    'extensions.getAddons.cache.enabled': false,
    'extensions.blocklist.enabled': false,
    // Remote settings (blocklists, certificates…) answered by nobody: a data: URL is never a request.
    'services.settings.server': 'data:,#remote-settings-dummy/v1',
    'dom.push.enabled': false,
    'dom.push.serverURL': '',
    'geo.provider.network.url': '',
    'media.gmp-manager.url': '',
    'media.gmp-gmpopenh264.enabled': false,
    'identity.fxaccounts.enabled': false,
    'security.OCSP.enabled': 0,
    // puppeteer's profile relaxes file:// origins for its own tests; a user's Firefox does not.
    'security.fileuri.strict_origin_policy': true,
    // Everything to a host goes through the recording proxy, loopback too.
    'network.proxy.type': 1,
    'network.proxy.http': '127.0.0.1',
    'network.proxy.http_port': proxy.port,
    'network.proxy.ssl': '127.0.0.1',
    'network.proxy.ssl_port': proxy.port,
    'network.proxy.no_proxies_on': '',
    'network.proxy.allow_hijacking_localhost': true,
    // Downloads land in `downloads` without a dialog.
    'browser.download.dir': downloads,
    'browser.download.folderList': 2,
    'browser.download.useDownloadDir': true,
    'browser.download.always_ask_before_handling_new_types': false,
    'browser.helperApps.neverAsk.saveToDisk': 'text/plain,application/octet-stream',
    'browser.download.panel.shown': true,
  };
}

/** Waits until `dir` holds a finished file named `name` (Firefox writes a .part first). */
async function waitForFile(dir, name, timeout = 30_000) {
  const file = path.join(dir, name);
  const t0 = Date.now();
  while (Date.now() - t0 < timeout) {
    const names = fs.readdirSync(dir);
    if (names.includes(name) && !names.some((n) => n.endsWith('.part')) && fs.statSync(file).size > 0) return file;
    await new Promise((r) => setTimeout(r, 100));
  }
  throw new Error(`no download ${name} in ${dir} after ${timeout} ms (found: ${fs.readdirSync(dir).join(', ') || 'nothing'})`);
}

test('Firefox: the single file from file:// does the whole job with no request to any host', async () => {
  const executablePath = process.env.FIREFOX || which('firefox-esr');
  assert.ok(executablePath, 'firefox-esr is not on PATH: run scripts/setup.sh test');
  const downloads = tempDir('kerfcam-single-ffdl-');
  const browser = await puppeteer.launch({
    browser: 'firefox',
    executablePath,
    headless: true,
    userDataDir: tempDir('kerfcam-single-firefox-'),
    extraPrefsFirefox: firefoxPrefs(downloads),
    // A release Firefox takes services.settings.server from the prefs only with this set.
    env: { ...process.env, MOZ_REMOTE_SETTINGS_DEVTOOLS: '1' },
  });
  const requests = [];
  const errors = [];
  try {
    const page = await browser.newPage();
    page.on('request', (r) => requests.push(r.url()));
    page.on('pageerror', (e) => errors.push(String(e)));
    page.on('console', (m) => m.type() === 'error' && errors.push(m.text()));
    await page.goto(pageUrl);
    await page.waitForFunction(() => document.getElementById('status').textContent !== 'loading');
    let state = await page.evaluate(pageState);
    assert.equal(state.error, '');
    assert.equal(state.status, 'waiting for a file');
    assert.equal(state.protocol, 'file:');
    assert.match(state.version, /^v\d/);

    await page.evaluate(dropInPage, dropArgs());
    await page.waitForFunction(isReady, { timeout: 60_000 });
    await page.click('#download');
    const file = await waitForFile(downloads, 'seed000-plate-6-holes.ngc');
    state = await page.evaluate(pageState);
    expectPlateProgram(state, file);
    assert.equal(state.controlled, false, 'no service worker on file://');

    assert.deepEqual(errors, []);
    // Canary: a request from the page reaches the proxy.
    await page.evaluate((url) => fetch(url).catch(() => null), `${CANARY}page`);
  } finally {
    await browser.close();
  }
  assert.ok(proxy.seen.includes(`GET ${CANARY}page`), `the canary request went through the proxy: ${proxy.seen}`);
  assert.deepEqual(proxy.seen.filter((r) => !r.includes(CANARY)), [], 'requests through the proxy');
  assert.deepEqual(requests.filter((u) => !LOCAL.test(u) && !u.startsWith(CANARY)), [], 'requests to a host (request events)');
});
