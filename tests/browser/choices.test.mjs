// The operator's choices stay on the part they were set on (issue 39 §1-2), in Debian's headless
// chromium, as a user would: a start point moved onto B1's right edge and a tab clicked on its top edge;
// layer A switched off (every contour renumbered): both still on B1, nothing on B2; layer B off: both
// kept, named in a warning, not applied; B on again: back on B1 exactly; a reload restores both and says
// so. Every program through rs274.
//
//   node --test tests/browser/choices.test.mjs

import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { after, before, test } from 'node:test';
import { assertRs274Accepts, downloadProgram, openApp, untilReady } from './harness.mjs';

let app;
let page;
let dir;

before(async () => {
  app = await openApp();
  page = app.page;
  dir = app.downloadDir; // removed by app.close()
});

after(async () => {
  await app?.close();
});

/** A0 on layer A, B1, B2, B3 on layer B: 40 mm squares 20 mm apart in a row, mm. */
function drawing() {
  const out = ['0', 'SECTION', '2', 'HEADER', '9', '$INSUNITS', '70', '4', '0', 'ENDSEC', '0', 'SECTION', '2', 'ENTITIES'];
  for (const [layer, x] of [['A', 0], ['B', 60], ['B', 120], ['B', 180]]) {
    const p = [[x, 0], [x + 40, 0], [x + 40, 40], [x, 40], [x, 0]];
    for (let i = 0; i < 4; i++) out.push('0', 'LINE', '8', layer, '10', p[i][0], '20', p[i][1], '11', p[i + 1][0], '21', p[i + 1][1]);
  }
  out.push('0', 'ENDSEC', '0', 'EOF');
  const file = path.join(dir, 'four-squares.dxf');
  fs.writeFileSync(file, out.join('\n') + '\n');
  return file;
}

/** Clicks the preview where the drawing point (x, y) mm is shown, and waits for the new program. */
async function clickAt(x, y) {
  const [sx, sy] = await page.evaluate(([a, b]) => window.kerfcam.screenOf(a, b), [x, y]);
  await untilReady(page, () => page.click('#preview', { position: { x: sx, y: sy } }));
}

/** Switches the layer named `name` on or off in the Layers panel, and waits for the new program. */
async function setLayer(name, on) {
  const index = await page.$$eval(
    '#layers li.layer',
    (items, n) => items.findIndex((li) => li.querySelector('.layer-name')?.textContent === n),
    name,
  );
  assert.ok(index >= 0, `layer ${name} listed`);
  const box = page.locator(`#layers li[data-index="${index}"] input[type=checkbox]`);
  if ((await box.isChecked()) !== on) await untilReady(page, () => box.click());
}

const warnings = () => page.$$eval('#warnings li', (items) => items.map((li) => li.textContent));

/** The downloaded program, checked by rs274. */
async function program() {
  const file = await downloadProgram(page, dir);
  assertRs274Accepts(file);
  return fs.readFileSync(file, 'utf8');
}

/**
 * B1's choices in `g`: its loop starts on the right edge at y 25 (kerf 1.5: the path 0.75 mm out), and
 * its one tab is on the top edge (y 40.75) around x 80.
 */
function assertOnB1(g) {
  // Within the click's pixel of y 25.
  const start = /\nG1 X100\.75 Y(2[45]\.\d+|25)\n/.exec(g);
  assert.ok(start && Math.abs(Number(start[1]) - 25) < 0.02, 'B1 starts where the start point was set');
  const tabs = [...g.matchAll(/G1 X([\d.]+) Y([\d.]+)\n\(tab\)\nM5\nG0 X([\d.]+) Y([\d.]+)\n/g)];
  assert.equal(tabs.length, 1, g);
  const [, a, ya, b, yb] = tabs[0].map(Number);
  assert.equal(ya, 40.75);
  assert.equal(yb, 40.75);
  assert.ok(Math.abs((a + b) / 2 - 80) < 0.05, `${a} → ${b}`);
}

test('a start point and a tab stay on B1 through layers switched off and on, and a reload', async () => {
  await page.selectOption('#origin', 'drawing');
  await untilReady(page, () => page.setInputFiles('#file-input', drawing()));
  await page.click('#set-start');
  await clickAt(100, 25);
  await page.click('#place-tabs');
  await clickAt(80, 40);
  await page.keyboard.press('Escape');
  assertOnB1(await program());
  // Layer A off: the contours are numbered anew; the choices follow B1, B2 gets nothing.
  await setLayer('A', false);
  let g = await program();
  assertOnB1(g);
  assert.ok(!(await warnings()).some((w) => w.includes('not applied')), (await warnings()).join('\n'));
  // Layer B off (A on): both kept, named, not applied to A0.
  await setLayer('A', true);
  await setLayer('B', false);
  g = await program();
  assert.ok(!g.includes('(tab)'), g);
  assert.doesNotMatch(g, /\nG1 X40\.75 Y2[45][.\d]*\n/);
  const said = (await warnings()).find((w) => w.includes('not applied'));
  assert.ok(said, (await warnings()).join('\n'));
  assert.match(said, /1 start point\(s\) and 1 tab\(s\)/);
  assert.match(said, /layer B is not cut now/);
  // B on again: back on B1 exactly.
  await setLayer('B', true);
  assertOnB1(await program());
  // Reloaded: the file comes back from this browser with both choices, and the page says so.
  await untilReady(page, () => page.reload());
  assert.match(await page.textContent('#job-message'), /1 start point\(s\), 1 placed tab\(s\)/);
  assertOnB1(await program());
  assert.deepEqual(app.pageErrors, []);
});
