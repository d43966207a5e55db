// Where the page's worker spends its time on a big file (issue 17 item 4), in wasm under Node (the
// page's engine without the browser): each pipeline stage as the worker's stage timer hears it, the
// contours' preview rendered inside the run, then each piece of the worker's glue (report, program,
// box, moves, heat map) and the plan's preview, as worker.js calls them. A benchmark, not a test.
//   node scripts/bench-page-worker.mjs FILE.dxf [WIDTH HEIGHT]   (default 1000 × 700 CSS px, ratio 1)
// KERFCAM_PKG=dir picks another build of www/pkg. The native stages of the same file:
//   cargo run --release --example stages -- FILE.dxf
//
// Session 19 (2026-11-25, the 25 MB nest, 137k contours, Node 20; the machine shared and noisy, so ranges):
// the Job 1.9-2.1 s (reading ~225, chaining 330-400, offset ~95, planning 860-1030, G-code 315-350 ms),
// moves 160-185 ms, in all 2.3-2.5 s. The same crate at opt-level 3: the Job 1.54-1.67 s (planning 745-875,
// G-code 178-199, chaining 250-310) but 475,138 B gzip, over the 450 KiB of issue 17 (opt-level 2: 469,466 B).
// Where "s" loses (a named build's profile, --cpu-prof): in the G-code stage a third is the byte-copy
// machinery (Vec::extend_from_slice not inlined, a memory.copy per word: ~120 of ~340 ms); over the
// run, f64::min/max as calls to fmin/fmax (~65 ms: wasm's f64.min/max differ on NaN) and libm's hypot
// (~45 ms). Kept: moves() makes its room at once (its first call 180-200 -> 145-170 ms, the same numbers);
// the program's bytes appended without the copy machinery in this build (src/gcode/bytes.rs): the G-code
// stage 322 -> 277 and 383 -> 317 ms (medians of 5 alternating runs, two sittings), +3.5 KB gzip (435,201 B),
// the same programs (84 of them, corpus, fixtures and nests, LinuxCNC and QtPlasmaC posts, compared with cmp).
import { readFileSync } from 'node:fs';
import { join, resolve } from 'node:path';

const root = resolve(new URL('..', import.meta.url).pathname);
const pkg = resolve(process.env.KERFCAM_PKG || join(root, 'www/pkg'));
const { default: init, Job } = await import(join(pkg, 'kerfcam.js'));
await init({ module_or_path: readFileSync(join(pkg, 'kerfcam_bg.wasm')) });

const [file, w = '1000', h = '700'] = process.argv.slice(2);
if (!file) throw new Error('usage: node scripts/bench-page-worker.mjs FILE.dxf [WIDTH HEIGHT]');
const size = [Number(w), Number(h), 1];
const rows = [];
const time = (name, f) => {
  const t = performance.now();
  const v = f();
  rows.push([name, performance.now() - t]);
  return v;
};

const t0 = performance.now();
const bytes = readFileSync(file);
let last = performance.now();
const stage = (name, count) => {
  const t = performance.now();
  rows.push([`stage ${name} (${count})`, t - last]);
  last = t;
};
let fit = null;
const onContours = (rgba, view) => {
  const t = performance.now();
  rows.push(['stage chaining: contours preview rendered and handed over', t - last]);
  last = t;
  fit = [...view];
};
const watched = Job.watched ? (...a) => Job.watched(...a) : (b, s, f) => new Job(b, s, f);
const job = time('Job (the whole run)', () => watched(new Uint8Array(bytes), { kerf: 1.5, tolerance: 0.001, feed: 2000 }, stage, size, onContours));
const report = time('page_report_json', () => (job.page_report_json ? job.page_report_json(5000) : job.report_json()));
const program = time('program bytes', () => (job.program ? job.program() : new TextEncoder().encode(job.gcode())));
const bbox = time('bbox', () => job.bbox());
const moves = time('moves', () => job.moves());
time('heat, attached', () => [job.overcut_heat(), job.attached_points()]);
const [cx, cy, scale] = fit ?? [(bbox[0] + bbox[2]) / 2, (bbox[1] + bbox[3]) / 2, Math.min(size[0] / (bbox[2] - bbox[0]) / 1.1, size[1] / (bbox[3] - bbox[1]) / 1.1)];
time('render the plan preview', () => job.render(size[0], size[1], cx, cy, scale, 1));
const total = performance.now() - t0;
console.log(`${file}: ${bytes.length} bytes; report ${report.length} chars, program ${program.length} bytes, moves ${moves.length / 7} (${(moves.byteLength / 1e6).toFixed(1)} MB)`);
for (const [name, ms] of rows) console.log(`${ms.toFixed(0).padStart(7)} ms  ${name}`);
console.log(`${total.toFixed(0).padStart(7)} ms  in all`);
job.free();
