// The page's settings reach the engine through the same builder as the command line's options (issue
// 15 §5: one Spec, one Spec::build). The kerf's corner join was a command-line option only (--join);
// here a user picks "sharp" corners in the Settings panel and the downloaded program's outer contour
// loses its corner arcs, as `kerfcam --join miter` does. The program goes through rs274.
//
//   node --test tests/browser/settings-spec.test.mjs

import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { after, before, test } from 'node:test';
import { assertRs274Accepts, clearFiles, downloadProgram, openApp, untilReady } from './harness.mjs';

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

/** A 100 × 50 mm plate of four lines: its kerf path has arcs only where corners are rounded. */
function plate() {
  const out = ['0', 'SECTION', '2', 'HEADER', '9', '$INSUNITS', '70', '4', '0', 'ENDSEC', '0', 'SECTION', '2', 'ENTITIES'];
  const line = (x0, y0, x1, y1) => out.push('0', 'LINE', '8', '0', '10', x0, '20', y0, '11', x1, '21', y1);
  line(0, 0, 100, 0);
  line(100, 0, 100, 50);
  line(100, 50, 0, 50);
  line(0, 50, 0, 0);
  out.push('0', 'ENDSEC', '0', 'EOF');
  const file = path.join(dir, 'spec-plate.dxf');
  fs.writeFileSync(file, out.join('\n') + '\n');
  return file;
}

/** The program the Download button gives. */
const downloaded = () => downloadProgram(page, dir);

const arcs = (g) => (g.match(/^G[23] /gm) || []).length;

test('sharp kerf corners chosen in the page reach the program as the CLI\'s --join miter', async () => {
  await clearFiles(page);
  await untilReady(page, () => page.setInputFiles('#file-input', plate()));
  const round = fs.readFileSync(await downloaded(), 'utf8');
  assert.equal(arcs(round), 4, 'a rounded corner at each of the 4 corners');
  await untilReady(page, () => page.selectOption('#join', 'miter'));
  const file = await downloaded();
  const sharp = fs.readFileSync(file, 'utf8');
  assert.equal(arcs(sharp), 0, sharp);
  assertRs274Accepts(file);
  // Kept like every other setting, and undone by choosing round again.
  await untilReady(page, () => page.selectOption('#join', 'round'));
  assert.equal(arcs(fs.readFileSync(await downloaded(), 'utf8')), 4);
});
