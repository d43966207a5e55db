// The small bugs a new user hits in the first hour (issue 19 item 3), each as the user meets it:
// "Back to the plan" after a backplot, the readout's inspect text during a backplot and after a
// language switch, the animation's colours, the backplot's own legend, the inspected contour
// highlighted, the "Open contours" checkbox beside its text.
//
//   node --test tests/browser/first-hour.test.mjs

import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { after, before, test } from 'node:test';
import { fixture, openApp, untilReady } from './harness.mjs';

const PLATE = fixture('seed000-plate-6-holes.dxf');

let app;
let page;

before(async () => {
  app = await openApp({ viewport: { width: 1366, height: 768 } });
  page = app.page;
});

after(async () => {
  await app?.close();
});

/** The page pixel of the drawing point (x, y) mm. */
async function pointAtMm(x, y) {
  const [px, py] = await page.evaluate(([x, y]) => window.kerfcam.screenOf(x, y), [x, y]);
  const box = await page.locator('#preview').boundingBox();
  return [box.x + px, box.y + py];
}

/** Overlay pixels (opaque enough) within `tol` of the colour `rgb`. */
const overlayPixels = (rgb, tol = 40) => page.evaluate(([rgb, tol]) => {
  const c = document.getElementById('overlay');
  const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
  let n = 0;
  for (let i = 0; i < d.length; i += 4) {
    if (d[i + 3] > 150 && Math.abs(d[i] - rgb[0]) + Math.abs(d[i + 1] - rgb[1]) + Math.abs(d[i + 2] - rgb[2]) < tol) n++;
  }
  return n;
}, [rgb, tol]);

const HOLE_ORANGE = [0xe0, 0x7b, 0x00];
const OLD_DONE_ORANGE = [255, 140, 0];
const CUT_RED = [0xd6, 0x28, 0x28];
const HIGHLIGHT = [0xf2, 0xa9, 0x00];

test('clicking a hole highlights it on the preview; the readout follows a language switch', async () => {
  await untilReady(page, () => page.setInputFiles('#file-input', PLATE));
  assert.equal(await overlayPixels(HIGHLIGHT, 30), 0, 'nothing highlighted before a click');
  // The Ø12 hole at (30, 30): its line passes through (36, 30).
  const [hx, hy] = await pointAtMm(36, 30);
  await page.mouse.click(hx, hy);
  await page.waitForFunction(() => /^hole/.test(document.getElementById('readout').textContent));
  const info = await page.evaluate(() => window.kerfcam.inspected());
  assert.equal(info.kind, 'hole');
  const lit = await overlayPixels(HIGHLIGHT, 30);
  assert.ok(lit > 100, `the hole is highlighted (${lit} amber pixels)`);
  // The highlight sits on that hole: its amber pixels are within its box (plus the kerf and the dashes).
  const far = await page.evaluate(([hx, hy]) => {
    const c = document.getElementById('overlay');
    const r = c.getBoundingClientRect();
    const k = c.width / r.width;
    const [cx, cy] = window.kerfcam.screenOf(30, 30).map((v) => v * k);
    const reach = (6 + 4) * k * (window.kerfcam.screenOf(1, 0)[0] - window.kerfcam.screenOf(0, 0)[0]) + 12 * k;
    const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
    let n = 0;
    for (let i = 0; i < d.length; i += 4) {
      const amber = d[i + 3] > 150 && Math.abs(d[i] - 0xf2) + Math.abs(d[i + 1] - 0xa9) + Math.abs(d[i + 2]) < 30;
      const [x, y] = [(i / 4) % c.width, Math.floor(i / 4 / c.width)];
      if (amber && Math.max(Math.abs(x - cx), Math.abs(y - cy)) > reach) n++;
    }
    return n;
  }, [hx, hy]);
  assert.equal(far, 0, 'amber pixels away from the inspected hole');

  await page.selectOption('#lang', 'pt-BR');
  await page.waitForFunction(() => document.documentElement.lang === 'pt-BR');
  assert.match(await page.textContent('#readout'), /^furo · camada /, 'the pinned text in Portuguese');
  await page.selectOption('#lang', 'en');
  assert.match(await page.textContent('#readout'), /^hole · layer /);
});

test('a backplot clears the inspect text, shows its own legend; "Back to the plan" puts the status back', async () => {
  await untilReady(page, () => page.setInputFiles('#file-input', PLATE));
  const [hx, hy] = await pointAtMm(36, 30);
  await page.mouse.click(hx, hy);
  await page.waitForFunction(() => /^hole/.test(document.getElementById('readout').textContent));
  const gcode = await page.evaluate(() => window.kerfcam.lastGcode);
  const file = path.join(app.downloadDir, 'plate.ngc');
  fs.writeFileSync(file, gcode);
  await page.setInputFiles('#backplot-input', file);
  await page.waitForFunction(() => document.getElementById('status').dataset.state === 'backplot');
  assert.equal(await page.textContent('#readout'), '', 'no inspect text of the plan over the backplot');
  assert.equal(await page.evaluate(() => window.kerfcam.inspected()), null);
  assert.equal(await page.isVisible('#legend'), false, "the plan's legend is hidden");
  assert.equal(await page.isVisible('#legend-backplot'), true, "the backplot's legend is shown");
  // The program drawn: cuts in the torch path's red, nothing in the holes' orange.
  assert.ok(await overlayPixels(CUT_RED) > 200, 'the cuts are drawn red');
  assert.equal(await overlayPixels(OLD_DONE_ORANGE, 30), 0, 'cuts drawn in orange');
  assert.equal(await overlayPixels(HOLE_ORANGE, 30), 0, 'cuts drawn in the holes\' orange');
  // Switching the language keeps the readout empty (no stale English text comes back).
  await page.selectOption('#lang', 'pt-BR');
  assert.equal(await page.textContent('#readout'), '');
  await page.selectOption('#lang', 'en');

  await page.click('#backplot-close');
  assert.equal(await page.getAttribute('#status', 'data-state'), 'ready');
  assert.equal(await page.textContent('#status'), 'ready');
  assert.equal(await page.isVisible('#legend'), true);
  assert.equal(await page.isVisible('#legend-backplot'), false);
});

test('the animation draws what is cut in the torch path\'s red, not in the holes\' orange', async () => {
  await untilReady(page, () => page.setInputFiles('#file-input', PLATE));
  await page.fill('#scrub', '700');
  await page.dispatchEvent('#scrub', 'input');
  assert.ok(await overlayPixels(CUT_RED) > 200, 'what is cut so far is red');
  assert.equal(await overlayPixels(OLD_DONE_ORANGE, 30), 0);
  assert.equal(await overlayPixels(HOLE_ORANGE, 30), 0);
});

test('the "Open contours" checkbox sits on the line of its text', async () => {
  const [box, text] = await page.evaluate(() => {
    const r = (e) => { const b = e.getBoundingClientRect(); return { top: b.top, bottom: b.bottom, left: b.left, right: b.right }; };
    const cb = document.getElementById('cut-open');
    return [r(cb), r(cb.parentElement.querySelector('[data-i18n="plan.cut-open.hint"]'))];
  });
  const mid = (b) => (b.top + b.bottom) / 2;
  assert.ok(Math.abs(mid(box) - mid(text)) < 6, `checkbox ${JSON.stringify(box)} beside its text ${JSON.stringify(text)}`);
  assert.ok(box.right <= text.left, 'the checkbox comes before its text');
  assert.deepEqual(app.pageErrors.map(String), []);
});

test('posts are named as a shop knows them, each with one line about it; the orders are explained', async () => {
  const menu = () => page.$$eval('#post option', (os) => os.map((o) => ({ value: o.value, text: o.textContent, group: o.parentElement.label })));
  const en = await menu();
  const texts = en.map((o) => o.text);
  for (const name of ['LinuxCNC — plasma (QtPlasmaC)', 'GRBL — laser', 'ISO 6983 generic', 'Paper 001 annex H dialect',
    'Point list (x;y) for step-motor tables', 'Tangential knife, relative moves']) assert.ok(texts.includes(name), `${name} in ${texts.join(' | ')}`);
  // Plain LinuxCNC once (it was "LinuxCNC (default)" beside "linuxcnc"), and no engine key shown as a name; the
  // router posts (issue 43) are named as routers, in their own group.
  assert.deepEqual(texts.filter((t) => /^LinuxCNC/.test(t) && !/plasma|router/.test(t)), ['LinuxCNC — plain G-code (default)']);
  assert.ok(texts.includes('LinuxCNC — router') && texts.includes('GRBL — router'), texts.join(' | '));
  assert.deepEqual(texts.filter((t) => /^[a-z0-9-]+$/.test(t)), []);
  assert.equal(new Set(texts).size, texts.length, 'a name listed twice');
  assert.ok(en.every((o) => o.group), 'every post in a group');
  for (const { value } of en) {
    await page.selectOption('#post', value);
    const about = await page.textContent('#post-about');
    assert.ok(about.length > 30, `a line about ${value}: "${about}"`);
  }
  await page.selectOption('#post', '');
  const orders = [];
  for (const value of ['contour', 'chained', 'eulerian', 'drawing']) {
    await page.selectOption('#order', value);
    orders.push(await page.textContent('#order-help'));
  }
  assert.equal(new Set(orders).size, 4, `one explanation per order: ${orders.join(' | ')}`);
  assert.match(orders[3], /drop before its holes/);

  await page.selectOption('#lang', 'pt-BR');
  await page.waitForFunction(() => document.documentElement.lang === 'pt-BR');
  const pt = await menu();
  assert.equal(pt.length, en.length);
  assert.ok(pt.some((o) => o.text === 'LinuxCNC — simples (padrão)'));
  assert.ok(pt.some((o) => o.text === 'Faca tangencial, mov. relativos'));
  assert.match(await page.textContent('#post-about'), /qualquer máquina LinuxCNC/);
  assert.match(await page.textContent('#order-help'), /cair antes de seus furos/);
  await page.selectOption('#lang', 'en');
  await page.selectOption('#order', 'contour');
  assert.deepEqual(app.pageErrors.map(String), []);
});
