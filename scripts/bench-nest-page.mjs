// Time to a first nest and to a good nest for a 100-part job (issue 18's closing note): the page in
// Debian's chromium (the Sheet mode as a user drives it, the engine in its Web Worker, wasm) beside the
// native CLI (`kerfcam nest`), same parts, same sheet, spacing, margin, rotations and seed, one run.
// A benchmark, not a test: it asserts nothing, it prints.
//
//   node scripts/bench-nest-page.mjs [BUDGET_S (default 30)] [corpus | plates (default corpus)]
//   env KERFCAM: the CLI (default $CARGO_TARGET_DIR/release/kerfcam or target/release/kerfcam)
//       WORKERS: the page's nest workers (default: the page's own choice, the machine's cores up to 4)
//
// Then the final nests at equal time (issue 44 item 2): the page's after BUDGET_S in WORKERS workers
// beside the CLI's `--time BUDGET_S` on one core (`--threads 1`), run after the page, not beside it.
// Measured 2026-11-30 (main 604b7d8, the nester's crate at opt-level 3, quiet 2-core machine, ci-profile
// CLI), `WORKERS=2 node scripts/bench-nest-page.mjs 60 plates`: the page's nest 1918.2 mm (213 711 nests
// tried by the two workers) against the CLI's 1899.1 mm (259 695): page / CLI 1.010. A 4-core figure
// cannot be measured on this machine kind (2 cores).
// Measured 2026-12-02 (session 45, ci-profile CLI, quiet 2-core machine, one run each): before, the page
// 1931.4 mm (140 208 and 143 063 nests tried, the old and the new wasm) against the CLI's 1896.4 and
// 1894.7 mm: 1.018 and 1.019. With the live drawing and progress line at most every 250 ms (nest-run.js
// LIVE_MS): the page 1911.3 mm, 265 112 nests tried, against the CLI's 1903.2 mm (252 257): page / CLI
// 1.004. One worker (WORKERS=1): 112 048 -> 137 600 nests tried. Under headless chromium the renderer's
// main thread shows 100 % of a core in top -H even with the page idle (a bare page awaiting one worker
// shows it too): the two workers share the other core's worth with it, which a 4-core PC would not.
// The nester's f64 min and max as a compare and a select (geom::fmin, fmax; in wasm f64::min is a call):
// under Node 20 (V8 without wasm inlining) 1.6x the nests a second (6 000 evaluations of this job, 24.5
// and 25.3 s -> 15.1 and 15.4 s CPU, the same nest); in chromium 156, which inlines the call, the page's
// 140 208 against 143 063 nests tried above: no difference told.
//
// The jobs, on 3000 × 1500 sheets, spacing 2.5 mm, margin 10 mm, rotations 90°, seed 1: "corpus", 100
// copies of parts from six corpus files (a file may hold several parts; small parts with many arcs, so
// each nest tried is slow), or "plates", 50 + 50 copies of the two fixture plates (quick nests, so the
// search improves many times within the budget).
// - First nest: the page's first progress report (the engine's own clock from the search's start, and
//   the wall clock from the click on Nest, which adds reading the DXFs in the worker); the CLI's whole
//   run with --time 0 (process start, DXF reading, first nest).
// - Good nest: the first nest the page's search showed whose used length is within 1 % of the best it
//   found in BUDGET_S (as many sheets, every copy placed). The search is replayable by its evaluations
//   count (the page's Stop relies on it), so the CLI is run with --evaluations N of that nest: the same
//   nest, whose wall time is printed beside the page's; the two nests' figures are printed to show it.
//
// Measured 2026-11-24, this 2-core machine shared with three other jobs (load average 7.5), one run each:
//   job      budget | first nest: chromium   CLI      ratio | good nest: chromium   CLI                 ratio
//   plates     60 s |             4.18 s     4.29 s   0.97x |            30.77 s    25.19 s (6 nests)   1.22x
//   corpus     90 s |            35.18 s    23.58 s   1.49x |            35.18 s    23.05 s (1 nest)    1.53x
// The same nests both sides (plates: 2285.5 mm first, 2201.9 mm good; corpus: 137.9 mm). On "corpus"
// a nest tried takes ~30 s under this load, so the first nest is the best of the budget (3 nests tried
// in 98.5 s: the search ends only after the nest in progress, see the instant Stop).

import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';
import { openApp, repoRoot, shared } from '../tests/browser/harness.mjs';
import { dropInPage } from '../tests/browser/helpers.mjs';

const BUDGET = Number(process.argv[2] || 30);
const WHICH = process.argv[3] || 'corpus';
const CORPUS = [
  ['cadquery/1001.dxf', 20], // 1 part
  ['cadquery/vslot-2020_1.dxf', 30], // 1 part
  ['openbuilds-cam/Motor NEMA23 - Sliding Mount.dxf', 4], // 5 parts
  ['dxf2gcode-plasma/SchlittenBack.dxf', 10], // 1 part
  ['maslow-mechanics/ExtraBrackets.DXF', 4], // 3 parts
  ['dxf2gcode-plasma/1997.DXF', 2], // 4 parts
];
const PLATES = [['../fixtures/seed000-plate-6-holes.dxf', 50], ['../fixtures/seed001-P51703.dxf', 50]];
const JOB = WHICH === 'plates' ? PLATES : CORPUS;
const SHEET = { w: 3000, h: 1500, n: 10 };
const SPACING = 2.5;
const MARGIN = 10;
const SEED = 1;
const target = process.env.CARGO_TARGET_DIR || path.join(repoRoot, 'target');
const CLI = process.env.KERFCAM || path.join(target, 'release', 'kerfcam');
const file = (f) => path.join(shared, 'corpus', f);

function cli(extra) {
  const args = ['nest', ...JOB.map(([f, q]) => `${file(f)}:${q}`), '--sheet', `${SHEET.w}x${SHEET.h}:${SHEET.n}`,
    '--spacing', String(SPACING), '--margin', String(MARGIN), '--rotations', '90', '--seed', String(SEED), '--json', ...extra];
  const t0 = process.hrtime.bigint();
  const out = execFileSync(CLI, args, { encoding: 'utf8', maxBuffer: 1 << 28, stdio: ['ignore', 'pipe', 'ignore'] });
  const ms = Number(process.hrtime.bigint() - t0) / 1e6;
  return { ms, json: JSON.parse(out) };
}

async function page() {
  const app = await openApp({ viewport: { width: 1400, height: 1000 } });
  try {
    const { page: p } = app;
    await p.click('#mode-sheet');
    for (const [f] of JOB) {
      await p.evaluate(dropInPage, { name: path.basename(f), base64: fs.readFileSync(file(f)).toString('base64') });
    }
    await p.waitForFunction((n) => document.querySelectorAll('#parts [data-units]').length === n, JOB.length, { timeout: 120_000 });
    for (const [f, q] of JOB) await p.fill(`#parts li.part[data-name="${path.basename(f)}"] input.qty`, String(q));
    await p.fill('#sheet-w', String(SHEET.w));
    await p.fill('#sheet-h', String(SHEET.h));
    await p.fill('#sheet-count', String(SHEET.n));
    await p.fill('#nest-spacing', String(SPACING));
    await p.fill('#nest-margin', String(MARGIN));
    await p.fill('#nest-time', String(BUDGET));
    if (process.env.WORKERS) await p.evaluate((n) => { window.kerfcam.nestWorkers = n; }, Number(process.env.WORKERS));
    // Every progress report the page shows, with the wall clock since the click on Nest.
    await p.evaluate(() => {
      const run = window.kerfcam.sheet.nest;
      const line = run.progressLine.bind(run);
      window.reports = [];
      run.progressLine = (r, s, a) => {
        window.reports.push({ wall_ms: performance.now() - window.clicked, elapsed_s: r.elapsed_s, length: r.length, sheets: r.sheets, unplaced: r.unplaced, evaluations: r.evaluations });
        return line(r, s, a);
      };
      window.kerfcam.lastNest = null;
      window.clicked = performance.now();
      document.getElementById('nest-run').click();
    });
    await p.waitForFunction(() => window.kerfcam.lastNest !== null, null, { timeout: (BUDGET + 300) * 1000 });
    const reports = await p.evaluate(() => window.reports);
    const nest = await p.evaluate(() => window.kerfcam.lastNest);
    const asked = Number(await p.$eval('#nest-result', (e) => e.dataset.asked));
    const workers = await p.evaluate(() => window.kerfcam.sheet.nest.workers ?? null);
    return { reports, nest, asked, workers };
  } finally {
    await app.close();
  }
}

const fmt = (v, d = 1) => (Number.isFinite(v) ? v.toFixed(d) : '?');
const { reports, nest, asked, workers } = await page();
// The page reports the first nest as it grows (copies still to place counted as left out): its first
// complete one is the first nest.
const first = reports.find((r) => r.unplaced === 0) ?? reports[0];
const placedAll = reports.filter((r) => r.unplaced === 0);
const best = placedAll.reduce((b, r) => (!b || r.sheets < b.sheets || (r.sheets === b.sheets && r.length < b.length) ? r : b), null);
const good = best && placedAll.find((r) => r.sheets === best.sheets && r.length <= best.length * 1.01);
const cliFirst = cli(['--time', '0']);
const cliGood = good ? cli(['--time', String(BUDGET * 20), '--evaluations', String(Math.max(1, good.evaluations))]) : null;

console.log(`100-part job "${WHICH}": ${asked} copies of ${JOB.length} files on ${SHEET.w} × ${SHEET.h} sheets, spacing ${SPACING}, margin ${MARGIN}, rotations 90, seed ${SEED}; page budget ${BUDGET} s`);
console.log(`page: ${reports.length} progress reports; its nest: ${nest.placed} placed on ${nest.sheets.length} sheet(s), used length ${fmt(nest.sheets.at(-1)?.used_length)} mm, ${nest.evaluations} nests tried in ${fmt(nest.time_s)} s`);
console.log('(a progress report\'s length is the search\'s, which counts up to half the spacing more than the used length)');
console.log('');
console.log('                     chromium (wasm, worker)                       CLI (native)');
console.log(`first nest           ${fmt(first?.elapsed_s, 2)} s engine clock, ${fmt(first?.wall_ms / 1000, 2)} s from the click    ${fmt(cliFirst.ms / 1000, 2)} s whole run (--time 0)`);
console.log(`  its figures        ${first?.sheets} sheet(s), length ${fmt(first?.length)} mm, ${first?.unplaced} left out     ${cliFirst.json.sheets.length} sheet(s), length ${fmt(cliFirst.json.sheets.at(-1)?.used_length)} mm, ${cliFirst.json.unplaced.reduce((n, u) => n + u.copies, 0)} left out`);
if (good) {
  console.log(`good nest (≤ 1 % of the best length, ${good.evaluations} nests tried)`);
  console.log(`                     ${fmt(good.elapsed_s, 2)} s engine clock, ${fmt(good.wall_ms / 1000, 2)} s from the click    ${fmt(cliGood.ms / 1000, 2)} s whole run (--evaluations ${good.evaluations})`);
  console.log(`  its figures        ${good.sheets} sheet(s), length ${fmt(good.length)} mm                ${cliGood.json.sheets.length} sheet(s), length ${fmt(cliGood.json.sheets.at(-1)?.used_length)} mm`);
  console.log(`  ratio chromium / CLI: first ${fmt(first.wall_ms / cliFirst.ms, 2)}x, good ${fmt(good.wall_ms / cliGood.ms, 2)}x (wall clocks)`);
  console.log(`best in the page's ${BUDGET} s: ${best.sheets} sheet(s), length ${fmt(best.length)} mm at ${fmt(best.elapsed_s, 2)} s (${best.evaluations} nests tried)`);
} else {
  console.log('good nest: none with every copy placed in the budget');
}

// The final nests at equal time: the page's (its workers) and the CLI's on one core.
const cliEqual = cli(['--time', String(BUDGET), '--threads', '1']);
const last = (n) => n.sheets.at(-1);
const usedOf = (n) => (n.sheets.length - 1) * SHEET.w + (last(n)?.used_length ?? 0);
console.log('');
console.log(`final nests at ${BUDGET} s: page (${process.env.WORKERS || workers || 'its default'} worker(s)) against the CLI on one core`);
console.log(`  page  ${nest.placed} placed, ${nest.sheets.length} sheet(s), last used ${fmt(last(nest)?.used_length)} mm, ${nest.evaluations} nests tried`);
console.log(`  CLI   ${cliEqual.json.placed} placed, ${cliEqual.json.sheets.length} sheet(s), last used ${fmt(last(cliEqual.json)?.used_length)} mm, ${cliEqual.json.evaluations} nests tried`);
console.log(`  total used length page / CLI: ${fmt(usedOf(nest) / usedOf(cliEqual.json), 3)} (below 1: the page's nest is denser)`);
