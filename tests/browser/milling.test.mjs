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
import { assertRs274Accepts, clearFiles, downloadProgram, openApp, repoRoot, sheetVerbs, untilReady } from './harness.mjs';
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

/** The command line's binary: the native layer's build. Under scripts/test-all.sh the native chain builds
 * it beside this one and then writes KERFCAM_BIN_READY ("ok", or "failed"): waited for here, not a build
 * half linked. */
async function cli() {
  const bin = process.env.KERFCAM_BIN || path.join(process.env.CARGO_TARGET_DIR ? path.resolve(repoRoot, process.env.CARGO_TARGET_DIR) : path.join(repoRoot, 'target'), 'ci', 'kerfcam');
  const ready = process.env.KERFCAM_BIN_READY;
  if (ready) {
    const until = Date.now() + 30 * 60_000;
    while (!fs.existsSync(ready) && Date.now() < until) await new Promise((r) => setTimeout(r, 1000));
    const said = fs.existsSync(ready) ? fs.readFileSync(ready, 'utf8').trim() : 'not written in 30 minutes';
    assert.equal(said, 'ok', `the native build (${bin}): ${said}`);
  }
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
  const fromCli = execFileSync(await cli(), args, { encoding: 'utf8', stdio: ['ignore', 'pipe', 'pipe'] });
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

/** The field `id` is marked (or not), its problem saying `text`. */
async function marked(id, text) {
  await page.waitForSelector(`#${id}[aria-invalid="true"]`);
  if (text) assert.match(await page.textContent(`#${id}-problem`), text);
}
const clean = (id) => page.waitForSelector(`#${id}[aria-invalid="false"]`);

test('a check between two values is said at the field whichever was typed first, a kept diameter too', async () => {
  // The diameter kept from the last test (6 mm), never typed on this page: the helix's limit follows it.
  await page.reload();
  await page.waitForFunction(() => document.getElementById('status').dataset.state === 'ready');
  assert.equal(await page.inputValue('#tool-diameter'), '6');
  await type('helix-diameter', 8);
  await marked('helix-diameter', /Helix diameter.*from 0 to 6 mm/);
  await untilReady(page, () => type('helix-diameter', 3));
  await clean('helix-diameter');
  // The allowance first, then a tool too small for it: the allowance is marked, not the diameter.
  await untilReady(page, () => type('allowance', 2.5));
  await type('tool-diameter', 4);
  await marked('allowance', /from 0 to 2 mm/);
  assert.equal(await page.getAttribute('#tool-diameter', 'aria-invalid'), 'false');
  await type('tool-diameter', 6);
  await clean('allowance');
  // Depth passes need both: the deepest pass emptied under a depth is said at its field.
  await type('pass-depth', 0);
  await marked('pass-depth', /Deepest pass: enter a number greater than 0/);
  await type('pass-depth', 2);
  await clean('pass-depth');
  // A V-bit's engraving width needs its angle, typed before or after.
  await type('engrave-width', 2);
  await marked('engrave-width', /from 0 to 0 mm/);
  await type('v-angle', 90);
  await clean('engrave-width');
  await type('v-angle', 0.5);
  await marked('v-angle', /from 1 to 179/);
  await type('engrave-width', 0);
  await untilReady(page, () => type('v-angle', 0));
  await clean('v-angle');
  await untilReady(page, () => type('allowance', 0));
});

test('Sheet mode cuts its sheets with the kerf field, not the router tool\'s width', async () => {
  // The router tool panel filled (a 10 mm tool) on a drawing with a milling layer, the kerf 1.7 mm.
  await untilReady(page, () => type('tool-diameter', 10));
  assert.equal(await page.isVisible('#panel-tool'), true);
  await type('kerf', 1.7);
  const { loadParts, ready } = sheetVerbs(() => page);
  await loadParts({ 'seed000-plate-6-holes.dxf': 1 }, { sheet: [1000, 500], time: 0 });
  await page.evaluate(() => (window.kerfcam.lastNest = null));
  await page.click('#nest-run');
  await page.waitForFunction(() => window.kerfcam.lastNest !== null, null, { timeout: 60_000 });
  await ready();
  const report = await page.evaluate(() => window.kerfcam.lastReport);
  assert.equal(report.process.kerf, 1.7, 'the sheet is cut with the kerf field');
  const program = fs.readFileSync(await downloadProgram(page, dir), 'utf8');
  assert.match(program, /kerf 1\.7 mm/, 'the program\'s header says the kerf field\'s width');
  await page.click('#mode-drawing').catch(() => {});
});

test('a router profile\'s lead arcs: Lead-in arc and the tool panel\'s radius, every pass, the CLI\'s program', async () => {
  await clearFiles(page);
  const file = drawing();
  await untilReady(page, () => page.setInputFiles('#file-input', file));
  // Kept from the tests before or not: set without waiting, the lead's change (from perpendicular) last.
  await page.fill('#depth', '6');
  await type('pass-depth', 2);
  await page.selectOption('#post', 'preset:grbl-router');
  await page.selectOption(opOf('PROFILE'), 'profile');
  await page.selectOption(opOf('POCKET'), 'ignore');
  await type('tool-diameter', 6);
  await untilReady(page, () => page.selectOption('#lead', 'arc'));
  // The engine's range, said at the field.
  await type('lead-radius', 300);
  await marked('lead-radius', /Lead-in arc radius.*from 0 to 200 mm/);
  await untilReady(page, () => type('lead-radius', 4));
  await clean('lead-radius');
  const saved = await downloadProgram(page, dir);
  const program = fs.readFileSync(saved, 'utf8');
  assertRs274Accepts(saved);
  // Three passes, each entered on an arc of R 4 (I/J 4 from its start) right after going down.
  const entries = program.split('\n').filter((l, i, all) => /^G1 Z-\d/.test(all[i - 1] || '') && /^G[23] .*[IJ]-?4(\s|$)/.test(l));
  assert.equal(entries.length, 3, `lead-in arcs after the plunges:\n${program}`);
  const args = [
    file, '--post', 'grbl-router', '--layer-op', 'POCKET=ignore', '--layer-op', 'PROFILE=profile',
    '--tool-diameter', '6', '--depth', '6', '--pass-depth', '2', '--lead', 'arc', '--lead-radius', '4',
  ];
  const fromCli = execFileSync(await cli(), args, { encoding: 'utf8', stdio: ['ignore', 'pipe', 'pipe'] });
  assert.equal(program, fromCli, 'the page\'s program is the CLI\'s');
  // Play ends at the report's time (the passes' lifts and arcs counted alike).
  const end = await page.evaluate(() => { const m = window.kerfcam.playMoves(); return m[m.length - 1]; });
  const report = await page.evaluate(() => window.kerfcam.lastReport);
  assert.ok(Math.abs(end - report.plan.est_time_s) < 0.051, `Play ends at ${end} s, report ${report.plan.est_time_s} s`);
  await page.selectOption('#lang', 'pt-BR');
  assert.match(await page.textContent('label[for="lead-radius"]'), /^Raio da entrada em arco/);
  await page.selectOption('#lang', 'en');
  await untilReady(page, () => page.selectOption('#lead', 'perpendicular'));
  await untilReady(page, () => type('lead-radius', 0));
});

/** The program's rapids across between a profile's depth passes (src/gcode/passes.rs): each `G0 X Y` right before
 * "; pass k of n" (k > 1), from where the tool was (the lead-out's end) to where it goes down again. */
function reliftRapids(program) {
  const lines = program.split('\n');
  const at = { X: 0, Y: 0 };
  const out = [];
  for (let i = 0; i < lines.length; i++) {
    const l = lines[i];
    const word = (c) => { const m = l.match(new RegExp(`(?:^|\\s)${c}(-?[\\d.]+)`)); return m ? Number(m[1]) : null; };
    const [x, y] = [word('X'), word('Y')];
    if (/^G0\s/.test(l) && x !== null && y !== null && /^; pass ([2-9]|\d\d) of/.test(lines[i + 1] || '')) {
      out.push({ from: [at.X, at.Y], to: [x, y] });
    }
    if (x !== null) at.X = x;
    if (y !== null) at.Y = y;
  }
  return out;
}

/** How many of the points 30 %…70 % along `from`→`to` (drawing mm) have a pixel of canvas `id` within ±1 px that
 * `looks(r, g, b, a)` accepts: the line as the user sees it. */
const pixelsAlong = (id, from, to, looks) => page.evaluate(({ id, from, to, looks }) => {
  const c = document.getElementById(id);
  const ctx = c.getContext('2d');
  const dpr = c.width / c.clientWidth;
  const accept = new Function('r', 'g', 'b', 'a', `return ${looks};`);
  let n = 0;
  for (let k = 6; k <= 14; k++) {
    const f = k / 20;
    const [sx, sy] = window.kerfcam.screenOf(from[0] + (to[0] - from[0]) * f, from[1] + (to[1] - from[1]) * f);
    const d = ctx.getImageData(Math.round(sx * dpr) - 1, Math.round(sy * dpr) - 1, 3, 3).data;
    let hit = false;
    for (let i = 0; i < d.length; i += 4) hit ||= accept(d[i], d[i + 1], d[i + 2], d[i + 3]);
    if (hit) n++;
  }
  return n;
}, { id, from, to, looks });

test('a router profile\'s lift and rapid between depth passes: drawn by the preview and by Play, as the program makes them', async () => {
  await clearFiles(page);
  const file = drawing();
  await untilReady(page, () => page.setInputFiles('#file-input', file));
  await page.fill('#depth', '6');
  await type('pass-depth', 2);
  await page.selectOption('#post', 'preset:grbl-router');
  await page.selectOption(opOf('PROFILE'), 'profile');
  await page.selectOption(opOf('POCKET'), 'ignore');
  await type('tool-diameter', 6);
  await type('lead-radius', 0);
  await untilReady(page, () => page.selectOption('#lead', 'arc'));
  const program = await page.evaluate(() => window.kerfcam.lastGcode);
  // The square's 3 passes, each entered on its lead-in arc: 2 rapids across, 12 mm (two lead radii) long.
  const rapids = reliftRapids(program);
  assert.equal(rapids.length, 2, `rapids between passes:\n${program}`);
  for (const { from, to } of rapids) {
    const len = Math.hypot(to[0] - from[0], to[1] - from[1]);
    assert.ok(len > 5, `a rapid across, ${len} mm: ${JSON.stringify({ from, to })}`);
  }
  const { from, to } = rapids[0];
  // The preview (the engine's raster, src/preview.rs): the rapid's grey dashes along it.
  const grey = '(r - g) ** 2 < 144 && (g - b) ** 2 < 144 && r < 235 && a > 0';
  const drawn = await pixelsAlong('preview', from, to, grey);
  assert.ok(drawn >= 3, `the preview draws the rapid between passes at ${drawn} of 9 points`);
  // Play: its moves hold that rapid, where the program has it…
  const inPlay = await page.evaluate(({ from, to }) => {
    const m = window.kerfcam.playMoves();
    const near = (x, y, p) => Math.hypot(x - p[0], y - p[1]) < 1e-3;
    let n = 0;
    for (let i = 0; i < m.length; i += 7) if (m[i] === 0 && near(m[i + 1], m[i + 2], from) && near(m[i + 3], m[i + 4], to)) n++;
    return n;
  }, { from, to });
  const same = rapids.filter((r) => Math.hypot(r.from[0] - from[0], r.from[1] - from[1]) + Math.hypot(r.to[0] - to[0], r.to[1] - to[1]) < 1e-3);
  assert.equal(inPlay, same.length, 'Play moves across at rapid where the program does, as often');
  // …and draws it once the scrubber has passed it (Play's done moves: rapids dashed in grey, plan.js).
  assert.equal(await pixelsAlong('overlay', from, to, grey), 0, 'nothing drawn by Play before it plays');
  await page.fill('#scrub', '1000');
  await page.dispatchEvent('#scrub', 'input');
  const played = await pixelsAlong('overlay', from, to, grey);
  assert.ok(played >= 3, `Play draws the rapid between passes at ${played} of 9 points`);
  await untilReady(page, () => page.selectOption('#lead', 'perpendicular'));
});

test('a router\'s tabs with a height leave a bridge: the passes below its top go over it, the CLI\'s program', async () => {
  await clearFiles(page);
  const file = drawing();
  await untilReady(page, () => page.setInputFiles('#file-input', file));
  await page.fill('#depth', '6');
  await type('pass-depth', 2);
  await page.selectOption('#post', 'preset:grbl-router');
  await page.selectOption(opOf('PROFILE'), 'profile');
  await page.selectOption(opOf('POCKET'), 'ignore');
  await type('tool-diameter', 6);
  await page.selectOption('#lead', 'perpendicular');
  await type('tab-width', 6);
  await untilReady(page, () => type('tabs', 2));
  await type('tab-height', -1);
  await marked('tab-height', /Tab height.*from 0 to 1000 mm/);
  await untilReady(page, () => type('tab-height', 3));
  await clean('tab-height');
  const saved = await downloadProgram(page, dir);
  const program = fs.readFileSync(saved, 'utf8');
  assertRs274Accepts(saved);
  // Passes 2 and 3 (Z -4, -6) go up to Z -3 over each of the 2 tabs; pass 1 (Z -2) cuts through.
  assert.equal((program.match(/^; tab\n(G90\n)?G0 Z-3$/gm) || []).length, 4, program);
  const args = [
    file, '--post', 'grbl-router', '--layer-op', 'POCKET=ignore', '--layer-op', 'PROFILE=profile',
    '--tool-diameter', '6', '--depth', '6', '--pass-depth', '2', '--tabs', '2', '--tab-width', '6', '--tab-height', '3',
  ];
  const fromCli = execFileSync(await cli(), args, { encoding: 'utf8', stdio: ['ignore', 'pipe', 'pipe'] });
  assert.equal(program, fromCli, 'the page\'s program is the CLI\'s');
  const end = await page.evaluate(() => { const m = window.kerfcam.playMoves(); return m[m.length - 1]; });
  const report = await page.evaluate(() => window.kerfcam.lastReport);
  assert.ok(Math.abs(end - report.plan.est_time_s) < 0.051, `Play ends at ${end} s, report ${report.plan.est_time_s} s`);
  await page.selectOption('#lang', 'pt-BR');
  assert.match(await page.textContent('label[for="tab-height"]'), /^Altura da ponte/);
  await page.selectOption('#lang', 'en');
  await type('tab-height', 0);
  await untilReady(page, () => type('tabs', 0));
});

test('a profile\'s side set by clicking on its contour: kept on its loop, the CLI\'s --side-at program', async () => {
  await clearFiles(page);
  await page.setViewportSize({ width: 1366, height: 768 });
  const file = drawing();
  await untilReady(page, () => page.setInputFiles('#file-input', file));
  await page.fill('#depth', '6');
  await type('pass-depth', 2);
  await page.selectOption('#post', 'preset:grbl-router');
  await page.selectOption(opOf('PROFILE'), 'profile');
  await type('tool-diameter', 6);
  await page.selectOption('#lead', 'perpendicular');
  await untilReady(page, () => page.selectOption(opOf('POCKET'), 'ignore'));
  const outside = fs.readFileSync(await downloadProgram(page, dir), 'utf8');
  // The square (80..110 × 0..30) cut inside: clicked on its bottom edge.
  await page.selectOption('#side-choice', 'inside');
  await page.click('#place-sides');
  assert.equal(await page.getAttribute('#place-sides', 'aria-pressed'), 'true');
  const [sx, sy] = await page.evaluate(([a, b]) => window.kerfcam.screenOf(a, b), [95, 0]);
  await untilReady(page, () => page.click('#preview', { position: { x: sx, y: sy } }));
  await page.keyboard.press('Escape');
  assert.match(await page.textContent('#sides-status'), /1 contour\(s\) with their own side/);
  const saved = await downloadProgram(page, dir);
  const inside = fs.readFileSync(saved, 'utf8');
  assertRs274Accepts(saved);
  assert.notEqual(inside, outside, 'the side changed the program');
  // The tool's centre 3 mm inside the square: X 83..107, never beyond.
  const xs = [...inside.matchAll(/^G1 X(-?[\d.]+)/gm)].map((m) => Number(m[1]));
  assert.ok(xs.length && Math.min(...xs) >= 83 - 1e-6 && Math.max(...xs) <= 107 + 1e-6, `X ${Math.min(...xs)}..${Math.max(...xs)}`);
  const base = [
    file, '--post', 'grbl-router', '--layer-op', 'PROFILE=profile', '--tool-diameter', '6', '--depth', '6', '--pass-depth', '2',
  ];
  const bin = await cli();
  const cliProgram = (extra) => execFileSync(bin, [...base, ...extra], { encoding: 'utf8', stdio: ['ignore', 'pipe', 'pipe'] });
  assert.equal(inside, cliProgram(['--layer-op', 'POCKET=ignore', '--side-at', '95,0=inside']), 'the page\'s program is the CLI\'s');
  // The pocket's loops become profiles too, cut before the square (every contour renumbered): the side
  // stays on the square.
  await untilReady(page, () => page.selectOption(opOf('POCKET'), 'profile'));
  const more = fs.readFileSync(await downloadProgram(page, dir), 'utf8');
  assert.equal(more, cliProgram(['--layer-op', 'POCKET=profile', '--side-at', '95,0=inside']), 'renumbered: still the CLI\'s');
  const report = await page.evaluate(() => window.kerfcam.lastReport);
  assert.ok(!report.warnings.some((w) => w.code === 'sides-not-applied'), JSON.stringify(report.warnings));
  fs.mkdirSync(path.join(repoRoot, 'tests', 'out'), { recursive: true });
  await page.locator('#sides-status').scrollIntoViewIfNeeded();
  await page.screenshot({ path: path.join(repoRoot, 'tests', 'out', 'router-sides-1366x768-en.png') });
  await page.selectOption('#lang', 'pt-BR');
  assert.equal(await page.textContent('label[for="side-choice"]'), 'Lado do perfil de um contorno');
  assert.equal(await page.textContent('#side-choice option[value="inside"]'), 'por dentro');
  assert.equal(await page.textContent('#place-sides'), 'Definir clicando');
  assert.equal(await page.textContent('#sides-status'), '1 contorno(s) com lado próprio.');
  await page.locator('#sides-status').scrollIntoViewIfNeeded();
  await page.screenshot({ path: path.join(repoRoot, 'tests', 'out', 'router-sides-1366x768-pt-BR.png') });
  await page.selectOption('#lang', 'en');
  // Removed: the square is cut outside again.
  await untilReady(page, () => page.click('#clear-sides'));
  await untilReady(page, () => page.selectOption(opOf('POCKET'), 'ignore'));
  assert.equal(fs.readFileSync(await downloadProgram(page, dir), 'utf8'), outside);
  assert.deepEqual(app.pageErrors, []);
});

test('a V-bit engraving\'s own depth or its width in the Router tool panel, both shown as made; the CLI\'s program', async () => {
  await clearFiles(page);
  await page.setViewportSize({ width: 1366, height: 768 });
  const file = drawing();
  await untilReady(page, () => page.setInputFiles('#file-input', file));
  await page.fill('#depth', '6');
  await type('pass-depth', 2);
  await page.selectOption('#post', 'preset:grbl-router');
  await page.selectOption(opOf('PROFILE'), 'ignore');
  await page.selectOption('#lead', 'perpendicular');
  await untilReady(page, () => page.selectOption(opOf('POCKET'), 'engrave'));
  await type('tool-diameter', 6);
  assert.equal(await page.isHidden('#v-engraving'), true, 'a flat end mill: no V engraving');
  await untilReady(page, () => type('v-angle', 90));
  // Its own depth, 1.5 mm (not the job's 6): 3 mm wide at the top.
  await untilReady(page, () => type('engrave-depth', 1.5));
  assert.equal(await page.textContent('#v-engraving'), 'Engraving with the 90° V-bit: 1.500 mm deep, 3.000 mm wide at the top (width = 2 × depth × tan(angle/2)).');
  const saved = await downloadProgram(page, dir);
  const program = fs.readFileSync(saved, 'utf8');
  assertRs274Accepts(saved);
  const lowest = Math.min(...[...program.matchAll(/Z(-?[\d.]+)/g)].map((m) => Number(m[1])));
  assert.equal(lowest, -1.5, 'down to the engraving\'s own depth');
  const bin = await cli();
  const base = [
    file, '--post', 'grbl-router', '--layer-op', 'POCKET=engrave', '--layer-op', 'PROFILE=ignore',
    '--tool-diameter', '6', '--depth', '6', '--pass-depth', '2', '--v-angle', '90',
  ];
  const fromCli = (extra) => execFileSync(bin, [...base, ...extra], { encoding: 'utf8', stdio: ['ignore', 'pipe', 'pipe'] });
  assert.equal(program, fromCli(['--engrave-depth', '1.5']), 'the page\'s program is the CLI\'s');
  fs.mkdirSync(path.join(repoRoot, 'tests', 'out'), { recursive: true });
  await page.locator('#v-engraving').scrollIntoViewIfNeeded();
  await page.screenshot({ path: path.join(repoRoot, 'tests', 'out', 'router-vbit-1366x768-en.png') });
  await page.selectOption('#lang', 'pt-BR');
  assert.equal(await page.textContent('#v-engraving'), 'Gravação com a fresa em V de 90°: 1,500 mm de profundidade, 3,000 mm de largura no topo (largura = 2 × profundidade × tan(ângulo/2)).');
  assert.match(await page.textContent('label[for="engrave-depth"]'), /^Profundidade da gravação com fresa em V/);
  await page.locator('#v-engraving').scrollIntoViewIfNeeded();
  await page.screenshot({ path: path.join(repoRoot, 'tests', 'out', 'router-vbit-1366x768-pt-BR.png') });
  await page.selectOption('#lang', 'en');
  // Or its width, 2 mm: 1 mm deep.
  await untilReady(page, () => type('engrave-depth', 0));
  await untilReady(page, () => type('engrave-width', 2));
  assert.match(await page.textContent('#v-engraving'), /1\.000 mm deep, 2\.000 mm wide/);
  assert.equal(fs.readFileSync(await downloadProgram(page, dir), 'utf8'), fromCli(['--engrave-width', '2']));
  // Both: the depth is said at its field, the last program kept.
  await type('engrave-depth', 1);
  await marked('engrave-depth');
  await type('engrave-depth', 0);
  await clean('engrave-depth');
  await untilReady(page, () => type('engrave-width', 0));
  await untilReady(page, () => type('v-angle', 0));
  assert.equal(await page.isHidden('#v-engraving'), true);
  assert.deepEqual(app.pageErrors, []);
});

test('the Router tool panel\'s tool number: T M6 and G43 H in the LinuxCNC router\'s program, as the CLI\'s --tool-number writes them', async () => {
  await clearFiles(page);
  const file = drawing();
  await untilReady(page, () => page.setInputFiles('#file-input', file));
  await page.fill('#depth', '6');
  await type('pass-depth', 2);
  await page.selectOption(opOf('PROFILE'), 'profile');
  await page.selectOption(opOf('POCKET'), 'pocket');
  await type('tool-diameter', 6);
  await untilReady(page, () => page.selectOption('#post', 'preset:linuxcnc-router'));
  // A tool number is a whole number: said at its field.
  await type('tool-number', 2.5);
  await marked('tool-number', /Tool number \(T, H\): enter a whole number from 1 to 99999/);
  await untilReady(page, () => type('tool-number', 3));
  await clean('tool-number');
  const saved = await downloadProgram(page, dir);
  const program = fs.readFileSync(saved, 'utf8');
  const lines = program.split('\n');
  const change = lines.indexOf('T3 M6');
  assert.ok(change > 0, `T3 M6 in the header:\n${program.slice(0, 400)}`);
  assert.equal(lines[change + 1], 'G43 H3');
  assertRs274Accepts(saved);
  // The CLI's header for the same post and number: the same lines up to the spindle's start.
  const fromCli = execFileSync(await cli(), [
    file, '--post', 'linuxcnc-router', '--layer-op', 'POCKET=pocket', '--layer-op', 'PROFILE=profile',
    '--tool-diameter', '6', '--depth', '6', '--pass-depth', '2', '--tool-number', '3',
  ], { encoding: 'utf8', stdio: ['ignore', 'pipe', 'pipe'] });
  const header = (text) => { const l = text.split('\n'); return l.slice(0, l.findIndex((x) => x.startsWith('M3 S')) + 1).filter((x) => !x.startsWith(';') && !x.startsWith('(')); };
  assert.deepEqual(header(program), header(fromCli), 'the CLI\'s header');
  await page.selectOption('#lang', 'pt-BR');
  assert.equal(await page.textContent('label[for="tool-number"]'), 'Número da ferramenta (T, H)');
  await page.selectOption('#lang', 'en');
  await untilReady(page, () => type('tool-number', 1));
  await untilReady(page, () => page.selectOption('#post', 'preset:grbl-router'));
});


test('two milling layers with two tools: the other tool picked per layer, previewed, the CLI\'s program, in pt-BR too', async () => {
  // The page's defaults (the tests before kept theirs), then the job of tests/it/milling_tools.rs.
  await clearFiles(page);
  await page.evaluate(() => localStorage.clear());
  await page.reload();
  await page.waitForFunction(() => !['', 'loading', undefined].includes(document.getElementById('status').dataset.state));
  const file = path.join(dir, 'two-tools.dxf');
  const small = ['0', 'LWPOLYLINE', '8', 'SMALL', '90', '4', '70', '1', '10', '89', '20', '9', '10', '101', '20', '9', '10', '101', '20', '21', '10', '89', '20', '21'].join('\n');
  fs.writeFileSync(file, pocketIslandDxf().replace('0\nENDSEC\n0\nEOF', `${small}\n0\nENDSEC\n0\nEOF`));
  await untilReady(page, () => page.setInputFiles('#file-input', file));
  await page.fill('#depth', '3');
  await untilReady(page, () => type('pass-depth', 3));
  await untilReady(page, () => page.selectOption('#post', 'preset:linuxcnc-router'));
  await untilReady(page, () => page.selectOption(opOf('PROFILE'), 'profile'));
  await type('tool-diameter', 6);
  await untilReady(page, () => page.selectOption(opOf('POCKET'), 'pocket'));
  await untilReady(page, () => page.selectOption(opOf('SMALL'), 'pocket'));
  const toolOf = (name) => `#layers li:has(.layer-name:text-is("${name}")) select.layer-tool`;
  assert.equal(await page.isHidden(toolOf('SMALL')), true, 'no other tool listed: no tool to pick');
  // Another tool: T2, 3 mm, its own feeds and speed.
  await page.click('#add-tool');
  const cell = (key) => `#tool-list input[data-row="0"][data-key="${key}"]`;
  assert.equal(await page.inputValue(cell('number')), '2');
  // No layer takes it yet: the program does not change (nothing re-runs to wait for).
  for (const [key, v] of [['diameter', '3'], ['feed', '800'], ['plunge_feed', '150'], ['spindle_rpm', '24000']]) {
    await page.fill(cell(key), v);
    await page.dispatchEvent(cell(key), 'change');
  }
  await page.waitForSelector(`${toolOf('SMALL')}:not([hidden])`);
  assert.equal(await page.isHidden(toolOf('PROFILE')), true, 'a profile is the job\'s tool\'s');
  assert.equal(await page.textContent(`${toolOf('SMALL')} option[value="2"]`), 'tool T2, 3 mm');
  await untilReady(page, () => page.selectOption(toolOf('SMALL'), '2'));
  assert.ok((await clearedPixels()) > 1000, 'the preview draws what both tools clear');
  const report = await page.evaluate(() => window.kerfcam.lastReport);
  assert.deepEqual(report.plan.tools.map((t) => [t.number, t.pockets]), [[2, 1], [1, 1]]);
  const end = await page.evaluate(() => { const m = window.kerfcam.playMoves(); return m[m.length - 1]; });
  assert.ok(Math.abs(end - report.plan.est_time_s) < 0.051, `Play ends at ${end} s, report ${report.plan.est_time_s} s`);
  const fromCli = async (diameter) => execFileSync(await cli(), [
    file, '--post', 'linuxcnc-router', '--layer-op', 'POCKET=pocket', '--layer-op', 'SMALL=pocket', '--layer-op', 'PROFILE=profile',
    '--tool-diameter', '6', '--depth', '3', '--pass-depth', '3',
    '--tool', `2=${diameter},feed=800,plunge-feed=150,spindle-rpm=24000`, '--layer-tool', 'SMALL=2',
  ], { encoding: 'utf8', stdio: ['ignore', 'pipe', 'pipe'] });
  let saved = await downloadProgram(page, dir);
  let program = fs.readFileSync(saved, 'utf8');
  assert.ok(program.includes('T2 M6') && program.includes('\nT1 M6\nG43 H1\n'), program.slice(0, 600));
  assertRs274Accepts(saved);
  assert.equal(program, await fromCli('3'), 'the page\'s program is the CLI\'s');
  // pt-BR: the list and the pick in Portuguese; a diameter typed with a decimal comma.
  await page.selectOption('#lang', 'pt-BR');
  assert.equal(await page.textContent('#panel-tool h3'), 'Outras ferramentas');
  assert.equal(await page.textContent(`${toolOf('SMALL')} option[value="2"]`), 'ferramenta T2, 3 mm');
  await untilReady(page, async () => {
    await page.fill(cell('diameter'), '3,175');
    await page.dispatchEvent(cell('diameter'), 'change');
  });
  assert.equal(await page.textContent(`${toolOf('SMALL')} option[value="2"]`), 'ferramenta T2, 3,175 mm');
  saved = await downloadProgram(page, dir);
  program = fs.readFileSync(saved, 'utf8');
  assertRs274Accepts(saved);
  assert.equal(program, await fromCli('3.175'), 'the page\'s program in pt-BR is the CLI\'s');
  // Contour-parallel from the walls inwards (issue 43 §2): the panel's order, the CLI's --pocket-from.
  assert.equal(await page.textContent('label[for="pocket-from"]'), 'Ordem paralela ao contorno');
  assert.equal(await page.textContent('#pocket-from option[value="walls"]'), 'das paredes para dentro');
  await page.selectOption('#lang', 'en');
  await untilReady(page, () => page.selectOption('#pocket', 'offset'));
  await untilReady(page, () => page.selectOption('#pocket-from', 'walls'));
  saved = await downloadProgram(page, dir);
  program = fs.readFileSync(saved, 'utf8');
  assertRs274Accepts(saved);
  const walls = execFileSync(await cli(), [
    file, '--post', 'linuxcnc-router', '--layer-op', 'POCKET=pocket', '--layer-op', 'SMALL=pocket', '--layer-op', 'PROFILE=profile',
    '--tool-diameter', '6', '--depth', '3', '--pass-depth', '3', '--pocket', 'offset', '--pocket-from', 'walls',
    '--tool', '2=3.175,feed=800,plunge-feed=150,spindle-rpm=24000', '--layer-tool', 'SMALL=2',
  ], { encoding: 'utf8', stdio: ['ignore', 'pipe', 'pipe'] });
  assert.equal(program, walls, 'from the walls: the CLI\'s program');
  assert.notEqual(program, await fromCli('3.175'), 'the order changes the program');
  await page.evaluate(() => localStorage.clear());
});

test('two milling layers at two depths: a depth and pass under the layer, previewed, the CLI\'s --layer-depth program, in pt-BR too', async () => {
  // The sign of tests/it/milling_depths.rs: lettering pocketed 3 mm deep in passes of 1.5, the outline
  // profiled through the 18 mm board in passes of 6.
  await clearFiles(page);
  await page.evaluate(() => localStorage.clear());
  await page.reload();
  await page.waitForFunction(() => !['', 'loading', undefined].includes(document.getElementById('status').dataset.state));
  const file = path.join(dir, 'sign.dxf');
  const e = ['0', 'LWPOLYLINE', '8', 'LETTERS', '90', '4', '70', '1', '10', '20', '20', '15', '10', '32', '20', '15', '10', '32', '20', '45', '10', '20', '20', '45',
    '0', 'CIRCLE', '8', 'LETTERS', '10', '80', '20', '30', '40', '12', '0', 'CIRCLE', '8', 'LETTERS', '10', '80', '20', '30', '40', '4',
    '0', 'LWPOLYLINE', '8', 'OUTLINE', '90', '4', '70', '1', '10', '0', '20', '0', '10', '120', '20', '0', '10', '120', '20', '60', '10', '0', '20', '60'];
  fs.writeFileSync(file, ['0', 'SECTION', '2', 'HEADER', '9', '$INSUNITS', '70', '4', '0', 'ENDSEC', '0', 'SECTION', '2', 'ENTITIES', ...e, '0', 'ENDSEC', '0', 'EOF'].join('\n') + '\n');
  await untilReady(page, () => page.setInputFiles('#file-input', file));
  await page.fill('#depth', '18');
  await untilReady(page, () => type('pass-depth', 6));
  await untilReady(page, () => page.selectOption('#post', 'preset:grbl-router'));
  await untilReady(page, () => page.selectOption(opOf('OUTLINE'), 'profile'));
  await type('tool-diameter', 6);
  await untilReady(page, () => page.selectOption(opOf('LETTERS'), 'pocket'));
  const row = (name) => `#layers li:has(.layer-name:text-is("${name}"))`;
  assert.equal(await page.isHidden(`${row('OUTLINE')} .layer-depths`), true, 'a profile is cut at the job\'s depth');
  assert.equal(await page.isVisible(`${row('LETTERS')} .layer-depths`), true, 'a pocket layer shows its depth');
  assert.equal(await page.getAttribute(`${row('LETTERS')} input.layer-depth`, 'placeholder'), '18', 'blank: the job\'s depth');
  const at = async (sel, v) => { await page.fill(sel, v); await page.dispatchEvent(sel, 'change'); };
  const depthOf = `${row('LETTERS')} input.layer-depth`;
  const passOf = `${row('LETTERS')} input.layer-pass`;
  // Deeper than the board: said at the field, nothing runs.
  await at(depthOf, '20');
  await page.waitForSelector(`${depthOf}[aria-invalid="true"]`);
  assert.match(await page.getAttribute(depthOf, 'title'), /at most the job's depth/);
  await untilReady(page, () => at(depthOf, '3'));
  await untilReady(page, () => at(passOf, '1.5'));
  assert.ok((await clearedPixels()) > 1000, 'the preview draws the cleared lettering');
  const report = await page.evaluate(() => window.kerfcam.lastReport);
  const end = await page.evaluate(() => { const m = window.kerfcam.playMoves(); return m[m.length - 1]; });
  assert.ok(Math.abs(end - report.plan.est_time_s) < 0.051, `Play ends at ${end} s, report ${report.plan.est_time_s} s`);
  const fromCli = async (depth) => execFileSync(await cli(), [
    file, '--post', 'grbl-router', '--layer-op', 'LETTERS=pocket', '--layer-op', 'OUTLINE=profile',
    '--tool-diameter', '6', '--depth', '18', '--pass-depth', '6', '--layer-depth', `LETTERS=${depth},pass-depth=1.5`,
  ], { encoding: 'utf8', stdio: ['ignore', 'pipe', 'pipe'] });
  let saved = await downloadProgram(page, dir);
  let program = fs.readFileSync(saved, 'utf8');
  assert.ok(/^G1 .*Z-1\.5\b/m.test(program) && /^G1 .*Z-3\b/m.test(program) && /^G1 .*Z-18\b/m.test(program), program.slice(0, 800));
  assertRs274Accepts(saved);
  assert.equal(program, await fromCli('3'), 'the page\'s program is the CLI\'s');
  // pt-BR: the labels in Portuguese, a depth typed with a decimal comma.
  await page.selectOption('#lang', 'pt-BR');
  assert.equal(await page.textContent(`${row('LETTERS')} .layer-depths-label`), 'Profundidade');
  assert.match(await page.getAttribute(depthOf, 'aria-label'), /^Profundidade da camada LETTERS, mm/);
  await untilReady(page, () => at(depthOf, '2,5'));
  saved = await downloadProgram(page, dir);
  program = fs.readFileSync(saved, 'utf8');
  assertRs274Accepts(saved);
  assert.equal(program, await fromCli('2.5'), 'the page\'s program in pt-BR is the CLI\'s');
  // The layer's direction (issue 43 §1): the Router tool panel's, named, unless one is chosen for it.
  const dirOf = `${row('LETTERS')} select.layer-milling`;
  assert.equal(await page.textContent(`${dirOf} option[value=""]`), 'do trabalho (concordante)');
  assert.equal(await page.getAttribute(dirOf, 'aria-label'), 'Sentido da camada LETTERS');
  const shoot = async (lang, w, h) => {
    const viewport = page.viewportSize();
    await page.setViewportSize({ width: w, height: h });
    await page.$eval(row('LETTERS'), (e) => e.scrollIntoView({ block: 'center' }));
    await page.screenshot({ path: path.join(repoRoot, 'tests', 'out', `router-layer-depths-${w}x${h}-${lang}.png`) });
    await page.setViewportSize(viewport);
  };
  await shoot('pt-BR', 1366, 768);
  await page.selectOption('#lang', 'en');
  await shoot('en', 1920, 1080);
  assert.equal(await page.textContent(`${dirOf} option[value=""]`), 'job\'s (climb)');
  await untilReady(page, () => page.selectOption(dirOf, 'conventional'));
  const cliAt = async (given) => execFileSync(await cli(), [
    file, '--post', 'grbl-router', '--layer-op', 'LETTERS=pocket', '--layer-op', 'OUTLINE=profile',
    '--tool-diameter', '6', '--depth', '18', '--pass-depth', '6', '--layer-depth', given,
  ], { encoding: 'utf8', stdio: ['ignore', 'pipe', 'pipe'] });
  saved = await downloadProgram(page, dir);
  program = fs.readFileSync(saved, 'utf8');
  assertRs274Accepts(saved);
  assert.equal(program, await cliAt('LETTERS=2.5,pass-depth=1.5,milling=conventional'), 'conventional: the CLI\'s milling=conventional');
  assert.notEqual(program, await fromCli('2.5'), 'the direction changes the program');
  // The depth left blank, the pass and direction kept: the job's 18 mm in passes of 1.5, conventional.
  await untilReady(page, () => at(depthOf, ''));
  saved = await downloadProgram(page, dir);
  program = fs.readFileSync(saved, 'utf8');
  assert.equal(program, await cliAt('LETTERS=18,pass-depth=1.5,milling=conventional'), 'blank depth: the job\'s, the layer\'s pass and direction');
  await page.evaluate(() => localStorage.clear());
});

test('a layer set to pocket before the job has a depth: the run fails and says why, and the layer\'s row stays to put it right', async () => {
  await clearFiles(page);
  await page.evaluate(() => localStorage.clear());
  await page.reload();
  await page.waitForFunction(() => !['', 'loading', undefined].includes(document.getElementById('status').dataset.state));
  await untilReady(page, () => page.setInputFiles('#file-input', drawing()));
  assert.equal(await page.inputValue('#depth'), '0', 'no depth yet');
  await page.selectOption(opOf('POCKET'), 'pocket');
  await page.waitForFunction(() => document.getElementById('status').dataset.state === 'error');
  assert.match(await page.textContent('#error'), /layers to pocket, engrave or drill need the depth and the deepest pass/);
  // The rows stay (they went with the failed run: "Open a file to see its layers", nothing to set back).
  assert.deepEqual(await page.$$eval('#layers li.layer .layer-name', (l) => l.map((e) => e.textContent)), ['POCKET', 'PROFILE']);
  assert.equal(await page.inputValue(opOf('POCKET')), 'pocket');
  assert.equal(await page.isVisible('#layers li:has(.layer-name:text-is("POCKET")) .layer-depths'), true, 'its own depth in reach');
  // In Portuguese too, from what was kept.
  await page.selectOption('#lang', 'pt-BR');
  assert.equal(await page.$eval(`${opOf('POCKET')} option[value="pocket"]`, (o) => o.textContent), 'bolsão (fresadora)');
  await page.selectOption('#lang', 'en');
  // Set back on its row: the file is cut again.
  await untilReady(page, () => page.selectOption(opOf('POCKET'), ''));
  assert.equal(await page.isVisible('#error'), false);
  // Pocketed once the job has its depth (and a router's post).
  await page.fill('#depth', '6');
  await untilReady(page, () => type('pass-depth', 2));
  await untilReady(page, () => page.selectOption('#post', 'preset:grbl-router'));
  await untilReady(page, () => page.selectOption(opOf('POCKET'), 'pocket'));
  assert.ok((await clearedPixels()) > 1000, 'the pocket is drawn');
  assert.deepEqual(app.pageErrors, []);
  await page.evaluate(() => localStorage.clear());
});
