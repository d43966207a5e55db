// A router job on the page (issue 43), as a user does it: drop a drawing, choose the GRBL router post
// and a depth, set the POCKET layer to pocket in the layers panel, give the Router tool panel (which
// appears then) a 6 mm end mill, see the preview draw the milling, and download the program. The
// program has the pocket's moves, passes rs274, and is byte for byte what the command line writes for
// the same settings (target/ci/kerfcam, built by the native layer; KERFCAM_BIN overrides). Both
// languages: the panel and the layer operations are named in pt-BR too.
//
//   node --test tests/browser/milling.test.mjs

import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';
import { after, before, test } from 'node:test';
import { assertRs274Accepts, clearFiles, downloadProgram, openApp, repoRoot, untilReady } from './harness.mjs';
import { pocketIslandDxf } from '../common/pocket-drawing.mjs';

let app;
let page;
let dir;

before(async () => {
  app = await openApp();
  page = app.page;
  dir = app.downloadDir;
});

after(async () => {
  await app?.close();
});

/** The router tests' drawing, written to a file to drop. */
function drawing() {
  const file = path.join(dir, 'pocket.dxf');
  fs.writeFileSync(file, pocketIslandDxf());
  return file;
}

/** The command line's binary: the native layer's build. */
function cli() {
  const bin = process.env.KERFCAM_BIN || path.join(process.env.CARGO_TARGET_DIR ? path.resolve(repoRoot, process.env.CARGO_TARGET_DIR) : path.join(repoRoot, 'target'), 'ci', 'kerfcam');
  assert.ok(fs.existsSync(bin), `${bin} missing: cargo build --profile ci (or set KERFCAM_BIN)`);
  return bin;
}

/** Types `value` into the number field `id` and commits it. */
async function type(id, value) {
  await page.fill(`#${id}`, String(value));
  await page.dispatchEvent(`#${id}`, 'change');
}

/** The layer operation select of layer `name`. */
const opOf = (name) => `#layers li:has(.layer-name:text-is("${name}")) select.layer-op`;

/** Pixels of the preview in the milling's cleared-area colour (src/preview/milling.rs CLEARED, #eadcc6). */
const clearedPixels = () => page.$eval('#preview', (c) => {
  const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
  let n = 0;
  for (let i = 0; i < d.length; i += 4) if (d[i] === 0xea && d[i + 1] === 0xdc && d[i + 2] === 0xc6) n++;
  return n;
});

test('a layer set to pocket with a 6 mm tool is previewed, downloaded and is the CLI\'s program', async () => {
  await clearFiles(page);
  const file = drawing();
  await untilReady(page, () => page.setInputFiles('#file-input', file));
  assert.equal(await page.isHidden('#panel-tool'), true, 'no milling layer: no tool panel');
  assert.equal(await clearedPixels(), 0, 'nothing milled yet');
  // Depth passes need both values: typed one after the other, then committed.
  await page.fill('#depth', '6');
  await untilReady(page, () => type('pass-depth', 2));
  await untilReady(page, () => page.selectOption('#post', 'preset:grbl-router'));
  await untilReady(page, () => page.selectOption(opOf('PROFILE'), 'profile'));
  assert.equal(await page.isVisible('#panel-tool'), true, 'a milling layer: the tool panel');
  // 6 mm (the panel's starting tool: typed again, the settings do not change, nothing re-runs).
  await type('tool-diameter', 6);
  await untilReady(page, () => page.selectOption('#entry', 'ramp'));
  await untilReady(page, () => page.selectOption(opOf('POCKET'), 'pocket'));
  // A bad value is said at its field, and the last good program stays.
  await type('stepover', 0);
  await page.waitForSelector('#stepover[aria-invalid="true"]');
  assert.match(await page.textContent('#stepover-problem'), /Stepover: enter a number from 1 to 100/);
  await untilReady(page, () => type('stepover', 50));
  assert.equal(await page.getAttribute('#stepover', 'aria-invalid'), 'false');

  // The preview draws the cleared area.
  const cleared = await clearedPixels();
  assert.ok(cleared > 1000, `cleared-area pixels: ${cleared}`);
  // Play's moves hold the milling (kinds 12, 13 of plan.js) and end at the program's time.
  const play = await page.evaluate(async () => {
    const { KIND, STRIDE } = await import('./plan.js');
    const m = window.kerfcam.playMoves();
    const kinds = new Set();
    for (let i = 0; i < m.length; i += STRIDE) kinds.add(m[i]);
    return { mill: kinds.has(KIND.mill), entry: kinds.has(KIND.millEntry), end: m[m.length - 1] };
  });
  const report = await page.evaluate(() => window.kerfcam.lastReport);
  assert.ok(play.mill && play.entry, JSON.stringify(play));
  assert.ok(Math.abs(play.end - report.plan.est_time_s) < 0.051, `Play ends at ${play.end} s, report ${report.plan.est_time_s} s`);

  const saved = await downloadProgram(page, dir);
  const program = fs.readFileSync(saved, 'utf8');
  assert.match(program, /pocket at X0 Y0/, 'the pocket is in the program');
  assert.match(program, /M3 S\d+/);
  assert.ok((program.match(/^G1 .*Z-6/gm) || []).length > 0, 'down to the full depth');
  assertRs274Accepts(saved);
  const args = [
    file, '--post', 'grbl-router', '--layer-op', 'POCKET=pocket', '--layer-op', 'PROFILE=profile',
    '--tool-diameter', '6', '--depth', '6', '--pass-depth', '2', '--entry', 'ramp', '--stepover', '50',
  ];
  const fromCli = execFileSync(cli(), args, { encoding: 'utf8', stdio: ['ignore', 'pipe', 'pipe'] });
  assert.equal(program, fromCli, 'the page\'s program is the CLI\'s');

  // Kept across a reload, like every setting.
  await page.reload();
  await page.waitForFunction(() => document.getElementById('status').dataset.state === 'ready');
  assert.equal(await page.inputValue('#tool-diameter'), '6');
  assert.equal(await page.inputValue('#entry'), 'ramp');

  // pt-BR: the panel and the operations in Portuguese.
  await page.selectOption('#lang', 'pt-BR');
  assert.equal(await page.textContent('#tool-heading'), 'Ferramenta da fresadora');
  assert.equal(await page.textContent(`${opOf('POCKET')} option[value="pocket"]`), 'bolsão (fresadora)');
  assert.equal(await page.textContent('#entry option[value="helix"]'), 'hélice');
  await page.selectOption('#lang', 'en');
});
