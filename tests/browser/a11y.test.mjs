// Accessibility (issue 6 §8) in Debian's headless chromium: an axe-core audit (npm axe-core, run in
// the page) of each state of the page with no serious or critical violation, and a keyboard walk:
// Tab reaches every visible control, each with a visible focus ring.
//
//   node --test tests/browser/a11y.test.mjs

import assert from 'node:assert/strict';
import { createRequire } from 'node:module';
import { after, before, test } from 'node:test';
import { fixture, openApp, untilReady } from './harness.mjs';

const AXE = createRequire(import.meta.url).resolve('axe-core/axe.min.js');
const TAGS = ['wcag2a', 'wcag2aa', 'wcag21a', 'wcag21aa', 'best-practice'];

let app;
let page;

before(async () => {
  app = await openApp();
  page = app.page;
});

after(async () => {
  await app?.close();
});

/** axe's violations of the page as it is now; prints every one, returns the serious and critical ones. */
async function audit(label) {
  if (!(await page.evaluate(() => typeof window.axe === 'object'))) await page.addScriptTag({ path: AXE });
  const result = await page.evaluate((tags) => window.axe.run(document, { runOnly: tags }), TAGS);
  for (const v of result.violations) {
    console.log(`${label}: ${v.impact} ${v.id} (${v.nodes.length}): ${v.help}: ${v.nodes.slice(0, 3).map((n) => n.target.join(' ')).join(' | ')}`);
  }
  console.log(`${label}: ${result.violations.length} violations, ${result.passes.length} rules passed`);
  return result.violations.filter((v) => v.impact === 'serious' || v.impact === 'critical').map((v) => `${v.id}: ${v.help}`);
}

test('axe-core finds no serious violation in any state of the page', async () => {
  assert.deepEqual(await audit('empty page'), []);

  await untilReady(page, () => page.setInputFiles('#file-input', [fixture('seed000-plate-6-holes.dxf'), fixture('seed003-grid-3x2.dxf')]));
  await page.click('#compare');
  await page.waitForSelector('#comparison tr');
  await page.keyboard.press('m'); // the measure tool's readout
  assert.deepEqual(await audit('a job, two files, comparison, measuring'), []);
  await page.keyboard.press('Escape');

  await page.click('#post-edit');
  await page.waitForSelector('#post-dialog[open]');
  assert.deepEqual(await audit('post editor'), []);
  await page.click('#post-cancel');

  await page.click('#job-sheet');
  await page.waitForFunction(() => !document.getElementById('sheet-view').hidden);
  assert.deepEqual(await audit('job sheet'), []);
  await page.keyboard.press('Escape');

  await page.selectOption('#lang', 'pt-BR');
  await page.waitForFunction(() => document.documentElement.lang === 'pt-BR');
  assert.deepEqual(await audit('in Portuguese'), []);
  await page.selectOption('#lang', 'en');

  // Issue 13: a file whose units are assumed (its warning carries the unit switch), a field out of its
  // range, and the origin picked on the preview.
  const square = ['0', 'SECTION', '2', 'ENTITIES',
    ...[[0, 0, 40, 0], [40, 0, 40, 30], [40, 30, 0, 30], [0, 30, 0, 0]].flatMap(([a, b, c, d]) => ['0', 'LINE', '8', '0', '10', a, '20', b, '11', c, '21', d]),
    '0', 'ENDSEC', '0', 'EOF'].join('\n');
  await untilReady(page, () => page.setInputFiles('#file-input', { name: 'no-units.dxf', mimeType: 'application/dxf', buffer: Buffer.from(square) }));
  await page.fill('#feed', '-100');
  await page.press('#feed', 'Tab');
  await page.selectOption('#origin', 'point');
  await page.waitForFunction(() => document.getElementById('feed').getAttribute('aria-invalid') === 'true');
  assert.deepEqual(await audit('units assumed, a field out of range, picking the origin'), []);
  await page.keyboard.press('Escape');
  await page.fill('#feed', '2000');
  await page.press('#feed', 'Tab');
  await page.selectOption('#origin', 'auto');
});

test('Tab reaches every visible control, and each shows where the focus is', () => tabWalk());

/** Tab from the top of the page: every visible control is reached and shows a focus ring. */
async function tabWalk() {
  // A job the last settings started must end first: its Cancel button, listed while it runs, hides
  // when the job ends, and Tab could not be asked to reach it (a race that failed this once).
  await page.waitForFunction(() => document.getElementById('cancel').hidden, null, { timeout: 60_000 });
  await page.evaluate(() => document.activeElement?.blur());
  const controls = await page.$$eval('button, input, select, textarea, canvas[tabindex], [tabindex="0"]', (els) =>
    els
      // tabindex -1: out of the Tab order on purpose (the nest's sheet tabs: one in it, the arrows move among them)
      .filter((e) => !e.matches(':disabled') && e.tabIndex >= 0 && e.getClientRects().length && getComputedStyle(e).visibility !== 'hidden' && !e.closest('[hidden], dialog:not([open])'))
      .map((e) => e.id || e.getAttribute('aria-label') || e.textContent.trim()),
  );
  // Each focus is recorded in the page as it happens (one round trip for the walk, not one per Tab).
  await page.evaluate(() => {
    window.kerfcamFocusWalk = [];
    window.kerfcamFocusWalkStop?.();
    const seen = (ev) => {
      const e = ev.target;
      if (!(e instanceof Element) || e === document.body) return;
      const name = e.id || e.getAttribute('aria-label') || e.textContent.trim();
      // A file input is focused inside its label, which draws the ring (:focus-within).
      const ringed = e.matches('.file-button input') ? e.closest('label') : e;
      const style = getComputedStyle(ringed);
      window.kerfcamFocusWalk.push({ name, ring: style.outlineStyle !== 'none' && parseFloat(style.outlineWidth) >= 2 });
    };
    document.addEventListener('focusin', seen);
    window.kerfcamFocusWalkStop = () => document.removeEventListener('focusin', seen);
  });
  for (let i = 0; i < controls.length + 40; i++) await page.keyboard.press('Tab');
  const walk = await page.evaluate(() => {
    window.kerfcamFocusWalkStop();
    return window.kerfcamFocusWalk;
  });
  const reached = new Set(walk.map((f) => f.name));
  const unringed = walk.filter((f) => !f.ring).map((f) => f.name);
  console.log(`keyboard walk: ${reached.size} controls reached of ${controls.length} visible`);
  assert.ok(controls.length > 20, `the page's controls were found (${controls.length})`);
  const missed = controls.filter((c) => !reached.has(c));
  assert.deepEqual(missed, [], 'controls Tab never reached');
  assert.deepEqual([...new Set(unringed)], [], 'controls with no visible focus ring');
}

test('Sheet mode (issue 18): parts, a bad quantity and a nest result pass axe, and Tab reaches every control', async () => {
  await page.click('#mode-sheet');
  await page.setInputFiles('#parts-input', [fixture('seed000-plate-6-holes.dxf'), fixture('seed001-P51703.dxf')]);
  await page.waitForFunction(() => document.querySelectorAll('#parts [data-units]').length === 2);
  await page.fill('#parts li.part input.qty', '2.5');
  assert.deepEqual(await audit('Sheet mode, two parts, a bad quantity'), []);
  await page.fill('#parts li.part input.qty', '2');
  await page.fill('#sheet-w', '1000');
  await page.fill('#sheet-h', '500');
  await page.fill('#nest-time', '0');
  await page.evaluate(() => (window.kerfcam.lastNest = null));
  await page.click('#nest-run');
  await page.waitForFunction(() => window.kerfcam.lastNest && document.getElementById('status').dataset.state === 'ready', null, { timeout: 60_000 });
  // A nest kept in the browser's list (Open, Forget), a grain lock ticked (its help shown).
  await Promise.all([page.waitForEvent('download'), page.click('#nest-save')]);
  await page.waitForFunction(() => document.getElementById('nest-kept').dataset.count === '1');
  await page.check('#parts li.part input[id$="-grain"]');
  assert.deepEqual(await audit('Sheet mode, a nest on the preview'), []);
  // The job report (issue 42 §4): the job's page and a page per sheet, with their maps and tables.
  await page.click('#job-sheet');
  await page.waitForSelector('#sheet .report-sheet');
  assert.deepEqual(await audit('Sheet mode, the job report'), []);
  await page.keyboard.press('Escape');
  await page.waitForFunction(() => document.getElementById('sheet-view').hidden);
  await page.selectOption('#lang', 'pt-BR');
  assert.deepEqual(await audit('Sheet mode in Portuguese'), []);
  await page.selectOption('#lang', 'en');
  await tabWalk();
  await page.click('#mode-drawing');
});
