// A router job through the page's cutting core under Node (issue 43): what Play animates (Job.moves())
// traces the path the program (Job.gcode()) cuts in X and Y — read back here from the program's text
// by this file's own reader — both ways within 0.005 mm and the same length cut (each depth pass
// listed), ends at the program's estimated time, and the plan SVG (Save SVG) has the milling layer.
//
//   bash scripts/build-wasm.sh && node --test tests/wasm/

import assert from 'node:assert/strict';
import { test } from 'node:test';
import { core, report, utf8 } from './load.mjs';
import { pocketIslandDxf } from '../common/pocket-drawing.mjs';

const { Job } = await core();

/** The router tests' drawing, as bytes. */
const drawing = () => utf8(pocketIslandDxf());

/** Points every `step` mm along a move { a, b, arc: { c, ccw } | null }, ends included. */
function samples(m, step) {
  const len = lengthOf(m);
  const n = Math.max(1, Math.ceil(len / step));
  const out = [];
  for (let k = 0; k <= n; k++) out.push(at(m, k / n));
  return out;
}

function arcParts(m) {
  const { c, ccw } = m.arc;
  const r = Math.hypot(m.a[0] - c[0], m.a[1] - c[1]);
  const a0 = Math.atan2(m.a[1] - c[1], m.a[0] - c[0]);
  const a1 = Math.atan2(m.b[1] - c[1], m.b[0] - c[0]);
  let sweep = ccw ? a1 - a0 : a0 - a1;
  while (sweep <= 1e-9) sweep += 2 * Math.PI;
  return { c, r, a0, sweep: ccw ? sweep : -sweep };
}

function lengthOf(m) {
  if (!m.arc) return Math.hypot(m.b[0] - m.a[0], m.b[1] - m.a[1]);
  const { r, sweep } = arcParts(m);
  return r * Math.abs(sweep);
}

function at(m, t) {
  if (!m.arc) return [m.a[0] + (m.b[0] - m.a[0]) * t, m.a[1] + (m.b[1] - m.a[1]) * t];
  const { c, r, a0, sweep } = arcParts(m);
  return [c[0] + r * Math.cos(a0 + sweep * t), c[1] + r * Math.sin(a0 + sweep * t)];
}

function dist(m, p) {
  const ends = Math.min(Math.hypot(p[0] - m.a[0], p[1] - m.a[1]), Math.hypot(p[0] - m.b[0], p[1] - m.b[1]));
  if (m.arc) {
    const { c, r, a0, sweep } = arcParts(m);
    let rel = (Math.atan2(p[1] - c[1], p[0] - c[0]) - a0) * Math.sign(sweep);
    rel = ((rel % (2 * Math.PI)) + 2 * Math.PI) % (2 * Math.PI);
    return rel <= Math.abs(sweep) ? Math.min(Math.abs(Math.hypot(p[0] - c[0], p[1] - c[1]) - r), ends) : ends;
  }
  const [dx, dy] = [m.b[0] - m.a[0], m.b[1] - m.a[1]];
  const l2 = dx * dx + dy * dy;
  if (!l2) return ends;
  const t = Math.min(1, Math.max(0, ((p[0] - m.a[0]) * dx + (p[1] - m.a[1]) * dy) / l2));
  return Math.hypot(p[0] - m.a[0] - t * dx, p[1] - m.a[1] - t * dy);
}

/** The program's feed moves in X and Y (G1/G2/G3 with an X/Y change; G90, I and J from the start). */
function programFeedMoves(text) {
  let [x, y, g] = [0, 0, 0];
  const out = [];
  for (const line of text.split('\n')) {
    const block = line.replace(/\(.*?\)/g, ' ').split(';')[0].trim();
    if (!block || block === '%') continue;
    const words = Object.fromEntries(block.split(/\s+/).map((w) => [w[0].toUpperCase(), Number(w.slice(1))]));
    const gs = block.split(/\s+/).filter((w) => /^G\d/.test(w)).map((w) => Number(w.slice(1)));
    for (const v of gs) if (v >= 0 && v <= 3 && Number.isInteger(v)) g = v;
    if (gs.includes(4)) continue;
    const [nx, ny] = [words.X ?? x, words.Y ?? y];
    if (g !== 0 && (nx !== x || ny !== y)) {
      const arc = g === 2 || g === 3 ? { c: [x + (words.I ?? 0), y + (words.J ?? 0)], ccw: g === 3 } : null;
      out.push({ a: [x, y], b: [nx, ny], arc });
    }
    [x, y] = [nx, ny];
  }
  return out;
}

/** Job.moves()'s moves along which the tool cuts (rapids, pierces and Z moves left out). */
function playFeedMoves(m, KIND) {
  const out = [];
  for (let i = 0; i < m.length; i += 7) {
    if ([KIND.rapid, KIND.pierce, KIND.spot, KIND.z].includes(m[i])) continue;
    const [a, b, bulge] = [[m[i + 1], m[i + 2]], [m[i + 3], m[i + 4]], m[i + 5]];
    if (a[0] === b[0] && a[1] === b[1]) continue;
    let arc = null;
    if (bulge) {
      // The bulge's centre: from the chord's midpoint along its left normal by (chord/2)·cot(sweep/2).
      const sweep = 4 * Math.atan(bulge);
      const [dx, dy] = [b[0] - a[0], b[1] - a[1]];
      const chord = Math.hypot(dx, dy);
      const d = chord / 2 / Math.tan(sweep / 2);
      arc = { c: [(a[0] + b[0]) / 2 - (dy / chord) * d, (a[1] + b[1]) / 2 + (dx / chord) * d], ccw: bulge > 0 };
    }
    out.push({ a, b, arc });
  }
  return out;
}

function farthest(from, to) {
  let worst = [0, null];
  for (const m of from) {
    for (const p of samples(m, 0.5)) {
      let d = Infinity;
      for (const n of to) d = Math.min(d, dist(n, p));
      if (d > worst[0]) worst = [d, p];
    }
  }
  return worst;
}

test('Play\'s moves for a pocket with an island and a profile are the program\'s path, passes and time', async () => {
  const { KIND } = await import('../../www/plan.js');
  const job = new Job(drawing(), {
    post: 'grbl-router', tool_diameter: 6, depth: 6, pass_depth: 2, entry: 'ramp',
    layer_ops: [['POCKET', 'pocket'], ['PROFILE', 'profile']],
  });
  const m = job.moves();
  const play = playFeedMoves(m, KIND);
  const program = programFeedMoves(job.gcode());
  const sum = (ms) => ms.reduce((s, x) => s + lengthOf(x), 0);
  assert.ok(sum(program) > 1000, `program feed ${sum(program)} mm`);
  const [d1, p1] = farthest(play, program);
  assert.ok(d1 <= 0.005, `Play ${d1} mm off the program at ${p1}`);
  const [d2, p2] = farthest(program, play);
  assert.ok(d2 <= 0.005, `the program ${d2} mm off Play at ${p2}`);
  assert.ok(Math.abs(sum(play) - sum(program)) <= 1e-4 * sum(program), `Play ${sum(play)} mm, program ${sum(program)} mm`);
  const kinds = new Set();
  for (let i = 0; i < m.length; i += 7) kinds.add(m[i]);
  assert.ok(kinds.has(KIND.mill) && kinds.has(KIND.millEntry) && kinds.has(KIND.z));
  const r = report(job);
  assert.ok(Math.abs(m[m.length - 1] - r.plan.est_time_s) < 0.051, `${m[m.length - 1]} vs ${r.plan.est_time_s}`);
  const svg = job.plan_svg('pocket');
  assert.match(svg, /inkscape:label="milling"/);
  assert.equal((svg.match(/data-z="/g) || []).length, 3, 'a sublayer per depth');
  job.free();
});
