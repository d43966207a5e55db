// Times the whole pipeline in wasm under Node (the page's engine, without the browser) against
// the native CLI on the same files, and prints MB/s and the ratio. A benchmark, not a test.
//   node scripts/bench-wasm.mjs [--parse-only] [FILE.dxf ...]   (default: every corpus file, plus a generated 25 MB nest)
// --parse-only times the reader alone: the job selects a layer no file has, so the whole file is
// read into a Drawing (every entity built, then set aside as not selected) and nothing is left to cut;
// the native side is then `cargo bench --bench reader` on the same bytes (in-process timing, best
// of 3 rounds, so no process start is counted). KERFCAM_PKG=dir picks another build of www/pkg.
import { readFileSync, readdirSync, statSync, writeFileSync, mkdtempSync } from 'node:fs';
import { join, resolve } from 'node:path';
import { spawnSync } from 'node:child_process';
import { tmpdir } from 'node:os';
const root = resolve(new URL('..', import.meta.url).pathname);
const pkg = resolve(process.env.KERFCAM_PKG || join(root, 'www/pkg'));
const { default: init, Job } = await import(join(pkg, 'kerfcam.js'));
await init({ module_or_path: readFileSync(join(pkg, 'kerfcam_bg.wasm')) });

function walk(dir) {
  return readdirSync(dir).flatMap((n) => {
    const p = join(dir, n);
    return statSync(p).isDirectory() ? walk(p) : n.toLowerCase().endsWith('.dxf') ? [p] : [];
  });
}

function nest(bytesWanted) {
  const out = ['0\nSECTION\n2\nHEADER\n9\n$INSUNITS\n70\n4\n0\nENDSEC\n0\nSECTION\n2\nENTITIES\n'];
  let size = 0;
  for (let i = 0; size < bytesWanted; i++) {
    const x = (i % 200) * 110, y = Math.floor(i / 200) * 70;
    let s = '';
    for (const [a, b] of [[[0, 0], [100, 0]], [[100, 0], [100, 60]], [[100, 60], [0, 60]], [[0, 60], [0, 0]]]) {
      s += `0\nLINE\n8\nparts\n10\n${(x + a[0]).toFixed(6)}\n20\n${(y + a[1]).toFixed(6)}\n11\n${(x + b[0]).toFixed(6)}\n21\n${(y + b[1]).toFixed(6)}\n`;
    }
    s += `0\nCIRCLE\n8\nholes\n10\n${(x + 25).toFixed(6)}\n20\n${(y + 30).toFixed(6)}\n40\n10.0\n`;
    out.push(s);
    size += s.length;
  }
  out.push('0\nENDSEC\n0\nEOF\n');
  return Buffer.from(out.join(''));
}

const parseOnly = process.argv.includes('--parse-only');
const files = process.argv.slice(2).filter((a) => a !== '--parse-only');
const settings = parseOnly ? { kerf: 1.5, layers: ['\u0001no such layer'] } : { kerf: 1.5 };
const inputs = files.length
  ? files.map((f) => [f, readFileSync(f)])
  : [['corpus (all files)', walk(join(root, '..', 'shared', 'corpus')).map((f) => readFileSync(f))], ['generated 25 MB nest', nest(25e6)]];

const cli = join(root, 'target', 'release', 'kerfcam');
const dir = mkdtempSync(join(tmpdir(), 'kerfcam-bench-'));
for (const [name, data] of inputs) {
  const list = Array.isArray(data) ? data : [data];
  const mb = list.reduce((n, b) => n + b.length, 0) / 1e6;
  // The reader alone is quick: best of 3 rounds, as on the native side (the first round also
  // pays for the engine's tier-up compile). The whole pipeline: one round.
  let wasmMs = Infinity;
  let firstMs;
  let t;
  for (let round = 0; round < (parseOnly ? 3 : 1); round++) {
    t = performance.now();
    for (const b of list) {
      try {
        new Job(b, settings).free();
      } catch {
        // unreadable files count their time too
      }
    }
    const ms = performance.now() - t;
    firstMs ??= ms;
    wasmMs = Math.min(wasmMs, ms);
  }
  const paths = list.map((b, i) => {
    const p = join(dir, `${i}.dxf`);
    writeFileSync(p, b);
    return p;
  });
  let nativeMs;
  if (parseOnly) {
    const sub = mkdtempSync(join(dir, 'set-'));
    list.forEach((b, i) => writeFileSync(join(sub, `${i}.dxf`), b));
    const r = spawnSync('cargo', ['bench', '-q', '--bench', 'reader', '--', sub, '3'], { cwd: root, encoding: 'utf8' });
    const m = /best ([\d.]+) ms/.exec(r.stdout);
    if (!m) throw new Error(`cargo bench --bench reader printed no time:\n${r.stdout}${r.stderr}`);
    nativeMs = Number(m[1]);
  } else {
    t = performance.now();
    for (const p of paths) spawnSync(cli, [p, '-q', '-o', '/dev/null']);
    nativeMs = performance.now() - t;
  }
  const wasmRounds = parseOnly ? ` (best of 3; first round ${(mb / (firstMs / 1e3)).toFixed(1)} MB/s)` : '';
  const native = parseOnly ? 'native reader (in-process, best of 3)' : 'native CLI (incl. process start)';
  console.log(
    `${name}: ${mb.toFixed(1)} MB; wasm${wasmRounds} ${wasmMs.toFixed(0)} ms = ${(mb / (wasmMs / 1e3)).toFixed(1)} MB/s; ` +
      `${native} ${nativeMs.toFixed(0)} ms = ${(mb / (nativeMs / 1e3)).toFixed(1)} MB/s; wasm/native time ${(wasmMs / nativeMs).toFixed(2)}`,
  );
}
