// The README's picture of the page (docs/img/page.png): www/ served as `npm start` serves it, a drawing
// opened with the file picker as a user opens one, the page once its job is done, in Debian's headless
// chromium (tests/browser/harness.mjs: playwright-core, no browser download). Needs www/pkg
// (scripts/build-wasm.sh) and ../shared (the drawing is read in place).
//
//   node scripts/screenshot.mjs [DRAWING.dxf] [OUT.png]
//
// Default: ../shared/corpus/dxf2gcode-plasma/pumpenteile.dxf (parts on four layers, holes) to
// docs/img/page.png, 1200 x 760 CSS pixels at scale 1. When Debian's pngquant is on PATH the picture is
// brought to 128 colours (about a third of the bytes; the page's flat colours lose nothing visible).

import { spawnSync } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';
import { corpus, openApp, repoRoot, untilReady } from '../tests/browser/harness.mjs';

const drawing = path.resolve(process.argv[2] ?? corpus('dxf2gcode-plasma', 'pumpenteile.dxf'));
const out = path.resolve(process.argv[3] ?? path.join(repoRoot, 'docs', 'img', 'page.png'));

const app = await openApp({ viewport: { width: 1200, height: 760 } });
try {
  await untilReady(app.page, () => app.page.setInputFiles('#file-input', drawing));
  if (app.pageErrors.length) throw new Error(`the page reported: ${app.pageErrors.map(String).join('; ')}`);
  fs.mkdirSync(path.dirname(out), { recursive: true });
  await app.page.screenshot({ path: out });
  const q = spawnSync('pngquant', ['--force', '--strip', '--skip-if-larger', '--output', out, '128', out]);
  if (q.error) console.log('note: no pngquant on PATH (apt-get install pngquant): the picture is left as chromium wrote it');
  console.log(`${path.relative(repoRoot, out)}: ${fs.statSync(out).size} bytes, ${path.basename(drawing)}`);
} finally {
  await app.close();
}
