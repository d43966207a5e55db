// The page's flat move list (Job.moves(): 7 numbers a move, a kind first) read with www/plan.js's KIND
// table, checked against the engine's own report of the same plan: the kind numbers are written in
// src/animation.rs (mod kind) and read in www/plan.js, and this is where a drift between the two shows
// (issue 15 item 6). Runs the page's wasm build (www/pkg) under Node, no browser.
//
//   node --test tests/browser/moves-wire.test.mjs

import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { test } from 'node:test';
import { KIND, STRIDE } from '../../www/plan.js';
import { repoRoot } from './harness.mjs';

const pkg = path.join(repoRoot, 'www', 'pkg');

/** A 100 × 50 plate with a Ø10 hole on layer 0, a line on layer MARK and a POINT on layer SPOT. */
function drawing() {
  const out = ['0', 'SECTION', '2', 'HEADER', '9', '$INSUNITS', '70', '4', '0', 'ENDSEC', '0', 'SECTION', '2', 'ENTITIES'];
  const line = (layer, x0, y0, x1, y1) => out.push('0', 'LINE', '8', layer, '10', x0, '20', y0, '11', x1, '21', y1);
  line('0', 0, 0, 100, 0);
  line('0', 100, 0, 100, 50);
  line('0', 100, 50, 0, 50);
  line('0', 0, 50, 0, 0);
  out.push('0', 'CIRCLE', '8', '0', '10', 30, '20', 25, '40', 5);
  line('MARK', 60, 10, 90, 10);
  out.push('0', 'POINT', '8', 'SPOT', '10', 70, '20', 35);
  out.push('0', 'ENDSEC', '0', 'EOF');
  return new TextEncoder().encode(out.map(String).join('\n') + '\n');
}

const len = (m, i) => {
  const [x0, y0, x1, y1, bulge] = [m[i + 1], m[i + 2], m[i + 3], m[i + 4], m[i + 5]];
  const chord = Math.hypot(x1 - x0, y1 - y0);
  if (Math.abs(bulge) < 1e-12) return chord;
  const sweep = 4 * Math.atan(Math.abs(bulge));
  return (chord / (2 * Math.sin(sweep / 2))) * sweep;
};

test('every move kind the engine writes is one plan.js knows, and means what the report counts', async () => {
  assert.ok(fs.existsSync(path.join(pkg, 'kerfcam_bg.wasm')), 'www/pkg missing: run scripts/build-wasm.sh');
  const { default: init, Job } = await import(path.join(pkg, 'kerfcam.js'));
  await init({ module_or_path: fs.readFileSync(path.join(pkg, 'kerfcam_bg.wasm')) });
  const job = new Job(drawing(), { kerf: 1.5, feed: 2000 }, null);
  const plan = JSON.parse(job.report_json()).plan;
  const m = job.moves();
  assert.equal(STRIDE, 7);
  assert.equal(m.length % STRIDE, 0);
  const known = new Set(Object.values(KIND));
  const count = {};
  const length = {};
  let t = 0;
  for (let i = 0; i < m.length; i += STRIDE) {
    const k = m[i];
    assert.ok(known.has(k), `kind ${k} at move ${i / STRIDE} is not in plan.js's KIND`);
    assert.ok(m[i + 6] >= t - 1e-9, 'the times only grow');
    t = m[i + 6];
    count[k] = (count[k] || 0) + 1;
    length[k] = (length[k] || 0) + len(m, i);
  }
  const near = (a, b, what, tol = 0.01) => assert.ok(Math.abs(a - b) < tol, `${what}: moves ${a}, report ${b}`);
  assert.equal(m[0], KIND.rapid, 'the program starts with a rapid from the origin');
  assert.equal(count[KIND.pierce], plan.pierces, 'pierces');
  assert.equal(count[KIND.spot] || 0, plan.spots, 'spots');
  assert.equal(plan.spots, 1);
  near(length[KIND.mark], plan.mark_length, 'mark length');
  near(length[KIND.mark], 30, 'the MARK line, on the drawn line');
  near(length[KIND.contour], plan.cut_length, 'cut length');
  near((length[KIND.leadIn] || 0) + (length[KIND.leadOut] || 0) + (length[KIND.link] || 0), plan.lead_length, 'leads');
  near(length[KIND.rapid], plan.rapid_length, 'rapid length');
  near(t, plan.est_time_s, 'the last move ends at the estimated time (the report gives 0.1 s)', 0.051);
  job.free();
});

test('tabs (kind 10) are carried with the report\'s count, length and time', async () => {
  const { default: init, Job } = await import(path.join(pkg, 'kerfcam.js'));
  await init({ module_or_path: fs.readFileSync(path.join(pkg, 'kerfcam_bg.wasm')) });
  const job = new Job(drawing(), { kerf: 1.5, feed: 2000, pierce_delay: 0.5, tabs: 2, tab_width: 3 }, null);
  const plan = JSON.parse(job.report_json()).plan;
  const m = job.moves();
  let tabs = 0, tabLength = 0, pierces = 0;
  for (let i = 0; i < m.length; i += STRIDE) {
    if (m[i] === KIND.tab) { tabs += 1; tabLength += len(m, i); }
    if (m[i] === KIND.pierce) pierces += 1;
  }
  assert.equal(tabs, 2, 'two tabs on the one part');
  assert.equal(plan.tabs, tabs);
  assert.deepEqual(plan.tabs_per_part, [{ part: 1, tabs: 2 }]);
  // Each tab a restart: the report's pierces count them.
  assert.equal(plan.pierces, pierces + tabs);
  // The torch is off for the tab and the kerf: 3 + 1.5 mm each.
  assert.ok(Math.abs(tabLength - 2 * 4.5) < 1e-6, `tab length ${tabLength}`);
  assert.ok(Math.abs(m[m.length - 1] - plan.est_time_s) < 0.051, 'times');
  job.free();
});

test('the moves\' times are the report\'s with a small hole at its own speed and depth passes', async () => {
  const { default: init, Job } = await import(path.join(pkg, 'kerfcam.js'));
  await init({ module_or_path: fs.readFileSync(path.join(pkg, 'kerfcam_bg.wasm')) });
  // The Ø10 hole is small below 12 mm, cut at 40 %; 3 mm in passes of 1.5 mm (2 passes).
  const settings = { kerf: 1.5, feed: 2000, small_hole_diameter: 12, small_hole_speed: 40, depth: 3, pass_depth: 1.5 };
  const job = new Job(drawing(), settings, null);
  const plan = JSON.parse(job.report_json()).plan;
  assert.equal(plan.small_holes, 1);
  const m = job.moves();
  assert.ok(Math.abs(m[m.length - 1] - plan.est_time_s) < 0.051, `moves end at ${m[m.length - 1]}, report ${plan.est_time_s}`);
  // Against the same job at full speed in the hole: slower by the hole's feed length × (1/800 − 1/2000) min × 2 passes (contour).
  const fast = new Job(drawing(), { ...settings, small_hole_speed: 100 }, null);
  const f = fast.moves();
  assert.ok(m[m.length - 1] > f[f.length - 1] + 0.1, `${m[m.length - 1]} vs ${f[f.length - 1]}`);
  job.free();
  fast.free();
});
