// Tabs placed by a click (issue 20 §6) in Debian's headless chromium, as a user would: turn the tool
// on, click on a plate's top edge in the preview, download the program and find the gap there (the
// torch off Tab width + kerf long, centred on the click); a click on the tab removes it; Undo too.
// Every program through rs274.
//
//   node --test tests/browser/tabs-click.test.mjs

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

/** A 100 × 50 plate, in mm, drawn from (0, 0). */
function plate() {
  const out = ['0', 'SECTION', '2', 'HEADER', '9', '$INSUNITS', '70', '4', '0', 'ENDSEC', '0', 'SECTION', '2', 'ENTITIES'];
  const p = [[0, 0], [100, 0], [100, 50], [0, 50], [0, 0]];
  for (let i = 0; i < 4; i++) out.push('0', 'LINE', '8', '0', '10', p[i][0], '20', p[i][1], '11', p[i + 1][0], '21', p[i + 1][1]);
  out.push('0', 'ENDSEC', '0', 'EOF');
  const file = path.join(dir, 'tab-plate.dxf');
  fs.writeFileSync(file, out.join('\n') + '\n');
  return file;
}

/** The program the Download button gives. */
const downloaded = () => downloadProgram(page, dir);

/** Clicks the preview where the drawing point (x, y) mm is shown, and waits for the new program. */
async function clickAt(x, y) {
  const [sx, sy] = await page.evaluate(([a, b]) => window.kerfcam.screenOf(a, b), [x, y]);
  await untilReady(page, () => page.click('#preview', { position: { x: sx, y: sy } }));
}

test('a tab clicked on the top edge leaves its gap there; clicked again or undone, it is gone', async () => {
  await page.selectOption('#origin', 'drawing');
  await untilReady(page, () => page.setInputFiles('#file-input', plate()));
  let g = fs.readFileSync(await downloaded(), 'utf8');
  assert.ok(!g.includes('(tab)'));
  await page.click('#place-tabs');
  assert.equal(await page.getAttribute('#place-tabs', 'aria-pressed'), 'true');
  await clickAt(30, 50);
  const file = await downloaded();
  g = fs.readFileSync(file, 'utf8');
  assert.equal(g.match(/\(tab\)/g)?.length, 1, g);
  // The kerf path runs 0.75 mm above the top edge; the torch is off over 3 + 1.5 mm centred on the
  // click at x = 30 (within the click's pixel).
  const gap = /G1 X([\d.]+) Y50\.75\n\(tab\)\nM5\nG0 X([\d.]+) Y50\.75\n/.exec(g);
  assert.ok(gap, g);
  const [a, b] = [Number(gap[1]), Number(gap[2])];
  assert.ok(Math.abs(Math.abs(b - a) - 4.5) < 0.002, `${a} → ${b}`);
  assert.ok(Math.abs((a + b) / 2 - 30) < 0.02, `${a} → ${b}`);
  assertRs274Accepts(file);
  assert.equal(await page.textContent('#tabs-status'), '1 tab(s) placed by hand.');
  const report = await page.evaluate(() => window.kerfcam.lastReport);
  assert.deepEqual(report.plan.tabs_per_part, [{ part: 1, tabs: 1 }]);
  // A click on the tab takes it away.
  await clickAt(30.5, 50);
  g = fs.readFileSync(await downloaded(), 'utf8');
  assert.ok(!g.includes('(tab)'), g);
  // Two placed, one undone: one left, the first.
  await clickAt(30, 50);
  await clickAt(70, 0);
  assert.equal((fs.readFileSync(await downloaded(), 'utf8').match(/\(tab\)/g) || []).length, 2);
  await untilReady(page, () => page.click('#undo-tab'));
  g = fs.readFileSync(await downloaded(), 'utf8');
  assert.equal(g.match(/\(tab\)/g)?.length, 1);
  assert.match(g, /X(27\.7|32\.2)\d* Y50\.75\n\(tab\)/);
  await untilReady(page, () => page.click('#clear-tabs'));
  assert.equal(await page.isDisabled('#clear-tabs'), true);
  await page.keyboard.press('Escape');
  assert.equal(await page.getAttribute('#place-tabs', 'aria-pressed'), 'false');
  assert.deepEqual(app.pageErrors, []);
});
