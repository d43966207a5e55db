// The pipeline through the page's cutting core (www/pkg/kerfcam.js, the `Job` API), under Node: the
// same fixture answers as the native tests, and a pixel check that the preview draws what it should.
//
//   bash scripts/build-wasm.sh && node --test tests/wasm/

import assert from 'node:assert/strict';
import { test } from 'node:test';
import { core, fixture, refused, report, settings, utf8 } from './load.mjs';

const { Job, check_post, materials_cfg, materials_read } = await core();

const PLATE = fixture('seed000-plate-6-holes.dxf');
const GRID = fixture('seed003-grid-3x2.dxf');

test('plate through the Job API has one part, six holes and four invalid vertices', () => {
  const job = new Job(PLATE, settings(2));
  const r = report(job);
  assert.equal(r.plan.parts, 1);
  assert.equal(r.plan.holes, 6);
  assert.equal(r.plan.open, 0);
  assert.equal(r.plan.pierces, 7);
  assert.equal(r.invalid_vertices.length, 4);
  const g = job.gcode();
  assert.ok(g.includes('G21 G90 G17 G40 G91.1') && g.includes('F1500') && g.trimEnd().endsWith('%'));
  assert.equal(g.split('M3 S1').length - 1, 7);
});

test('grid contours and cut length match the native answer', () => {
  const r = report(new Job(GRID, settings(0)));
  assert.equal(r.contours.length, 6);
  assert.equal(r.plan.cut_length, 8400);
});

/** A DXF before AutoCAD 2007 in code page `page`, one line on a layer whose name is the raw bytes `name`. */
function codePageDxf(page, name) {
  const head = utf8(
    `0\nSECTION\n2\nHEADER\n9\n$ACADVER\n1\nAC1015\n9\n$DWGCODEPAGE\n3\n${page}\n0\nENDSEC\n` +
      '0\nSECTION\n2\nENTITIES\n0\nLINE\n8\n',
  );
  const tail = utf8('\n10\n0\n20\n0\n11\n10\n21\n0\n0\nENDSEC\n0\nEOF\n');
  return new Uint8Array([...head, ...name, ...tail]);
}

test('layer names decode with the file’s code page in wasm', () => {
  // The page's wasm decodes code pages with the browser's TextDecoder (src/wasm_text.rs); the
  // characters here are the code pages' published mappings (Python's codecs gave the bytes), not kerfcam's.
  for (const [page, bytes, name] of [
    ['ANSI_932', [0x82, 0xa0, 0x8a, 0xbf], 'あ漢'],
    ['ANSI_936', [0xd6, 0xd0], '中'],
    ['ANSI_949', [0xc7, 0xd1, 0xb1, 0xdb], '한글'],
    ['ANSI_950', [0xa4, 0xa4, 0xa4, 0xe5], '中文'],
    ['ANSI_1250', [0x43, 0x7a, 0xea, 0x9c, 0xe6], 'Część'],
    ['DOS850', [0x81], 'ü'],
  ]) {
    const r = report(new Job(codePageDxf(page, bytes), settings(0)));
    const layers = r.layers.map((l) => l.name).filter((n) => typeof n === 'string');
    assert.deepEqual(layers, [name], page);
  }
  // A code page no decoder knows: read as Windows-1252, with a warning.
  const r = report(new Job(codePageDxf('ANSI_9999', [0xe9]), settings(0)));
  assert.equal(r.layers[0].name, 'é');
});

test('layer selection ignores case beyond ASCII in wasm', () => {
  // Case folding of non-ASCII names goes through JavaScript in wasm (src/case.rs): "äRGER" selects the
  // layer "Ärger", "ÖL" does not.
  const dxf = codePageDxf('ANSI_1252', [0xc4, ...utf8('rger')]);
  const pick = (name) => report(new Job(dxf, { kerf: 0, layers: [name] })).contours?.length ?? 0;
  assert.equal(pick('äRGER'), 1);
  assert.equal(pick('ÖL'), 0);
});

test('missing settings take the defaults and bad ones are refused', () => {
  assert.ok(new Job(PLATE, undefined));
  refused(() => new Job(PLATE, settings(-1)));
  refused(() => new Job(new Uint8Array([0, 1, ...utf8('garbage')]), settings(1)));
});

test('preview raster draws part fill, kerf path and invalid vertices', () => {
  const job = new Job(PLATE, settings(2));
  const b = job.bbox();
  const [w, h] = [480, 300];
  const scale = Math.min(w / (b[2] - b[0]), h / (b[3] - b[1])) * 0.95;
  const px = job.render(w, h, (b[0] + b[2]) / 2, (b[1] + b[3]) / 2, scale, 1);
  assert.equal(px.length, w * h * 4);
  const count = ([r, g, bl]) => {
    let n = 0;
    for (let i = 0; i < px.length; i += 4) {
      if (px[i] === r && px[i + 1] === g && px[i + 2] === bl && px[i + 3] === 255) n++;
    }
    return n;
  };
  assert.ok(count([0xcf, 0xe3, 0xf7]) > 20_000, 'part fill');
  assert.ok(count([0xd6, 0x28, 0x28]) > 100, 'kerf path');
  assert.ok(count([0xb0, 0x00, 0xb0]) > 100, 'invalid vertices');
  assert.ok(count([0x1a, 0x9e, 0x3a]) > 100, 'pierce points');
  refused(() => job.render(0, 10, 0, 0, 1, 1));
});

test('progress callback hears each stage in order', () => {
  const seen = [];
  const job = new Job(PLATE, settings(2), (name, count) => seen.push(`${name}:${count}`));
  assert.deepEqual(
    seen.map((s) => s.split(':')[0]),
    ['reading', 'chaining', 'offset', 'planning', 'gcode'],
  );
  assert.equal(seen[3], 'planning:7'); // 7 pierces, as the report says
  assert.equal(seen[4], `gcode:${utf8(job.gcode()).length}`); // the program's bytes
});

test('Portuguese messages, the same program', () => {
  const en = new Job(PLATE, settings(2));
  const pt = new Job(PLATE, { kerf: 2, lang: 'pt-BR' });
  const enDefaultFeed = new Job(PLATE, { kerf: 2, tolerance: 0.001, feed: 2000 });
  assert.equal(pt.gcode(), enDefaultFeed.gcode(), 'the program changed with the language');
  const [rEn, rPt] = [report(en), report(pt)];
  const wPt = rPt.warnings.find((w) => w.code === 'invalid-vertices');
  assert.ok(wPt, 'invalid-vertices warning');
  assert.ok(wPt.message.includes('canto(s) vivo(s)'), wPt.message);
  const wEn = rEn.warnings.find((w) => w.code === 'invalid-vertices');
  assert.ok(wEn);
  assert.ok(wEn.message.includes('sharp corner(s)'), wEn.message);
  assert.deepEqual(wEn.messages, wPt.messages);
  const bad = '{"decimals": 9}';
  assert.ok(check_post(bad).includes('is not between 1 and 6'));
  assert.ok(check_post(bad, 'pt-BR').includes('não está entre 1 e 6'));
});

// Issue 20 through the page's settings: layer operations (a MARK layer scribed first, kind 9 in the
// moves; a DIM layer reported, or cut when the settings say so), the small-hole rule and the verification.
test('layer operations, small holes and verification reach the job', () => {
  const dxf = utf8(
    '0\nSECTION\n2\nENTITIES\n' +
      '0\nCIRCLE\n8\nCUT\n10\n50\n20\n50\n40\n40\n' +
      '0\nCIRCLE\n8\nCUT\n10\n50\n20\n50\n40\n4\n' +
      '0\nLINE\n8\nMARK\n10\n30\n20\n70\n11\n70\n21\n70\n' +
      '0\nLINE\n8\nDIM\n10\n0\n20\n0\n11\n100\n21\n0\n' +
      '0\nENDSEC\n0\nEOF\n',
  );
  const web = (ops) => ({ kerf: 1.5, layer_ops: ops, small_hole_diameter: 10, verify: true });
  const job = new Job(dxf, web([]));
  const r = report(job);
  const codes = r.warnings.map((w) => w.code);
  assert.ok(codes.includes('layer-ignored'), `${codes}`);
  assert.equal(r.plan.small_holes, 1);
  assert.ok(r.plan.mark_length > 39.9, `${r.plan.mark_length}`);
  assert.equal(r.verification.parts_not_freed, 0);
  const moves = job.moves();
  assert.equal(moves.length % 7, 0);
  let firstFeed;
  for (let i = 0; i < moves.length; i += 7) {
    if (moves[i] !== 0 && moves[i] !== 6 && moves[i] !== 7) {
      firstFeed = moves[i];
      break;
    }
  }
  assert.equal(firstFeed, 9, 'the mark is the first feed move');
  const cut = new Job(dxf, web([['DIM', 'cut']]));
  assert.ok(!cut.report_json().includes('layer-ignored'));
  refused(() => new Job(dxf, web([['DIM', 'drill']])));
});

// Issue 20 §8 through the page's settings: `depth` and `pass_depth` cut a circle in three passes on a
// post with a Z word; a post without one refuses the job.
test('depth passes reach the program and a post without Z refuses', () => {
  const dxf = utf8('0\nSECTION\n2\nENTITIES\n0\nCIRCLE\n8\n0\n10\n0\n20\n0\n40\n10\n0\nENDSEC\n0\nEOF\n');
  const web = (post) => ({ kerf: 1, depth: 10, pass_depth: 4, post });
  const g = new Job(dxf, web('linuxcnc')).gcode();
  const zs = g.split('\n').filter((l) => l.startsWith('G1 Z-'));
  assert.deepEqual(zs, ['G1 Z-3.333', 'G1 Z-6.667', 'G1 Z-10'], g);
  refused(() => new Job(dxf, web('qtplasmac')));
});

test('a material chosen in the page sets the program and bad ones name the field', () => {
  const file =
    '[MATERIAL_NUMBER_4]\nNAME = Mild 4mm\nKERF_WIDTH = 1.7\nPIERCE_HEIGHT = 4\n' +
    'PIERCE_DELAY = 0.5\nCUT_HEIGHT = 1.5\nCUT_SPEED = 2700\n';
  const lib = JSON.parse(materials_read(file));
  assert.equal(materials_cfg(JSON.stringify(lib)), file);
  const web = (material) => ({ kerf: 1, feed: 1000, post: 'qtplasmac', material });
  const g = new Job(PLATE, web(JSON.stringify(lib.entries[0]))).gcode();
  assert.ok(g.includes('M190 P4') && g.includes('kerf 1.7 mm'), g);
  const bad = { ...lib.entries[0], feed: -1 };
  refused(() => new Job(PLATE, web(JSON.stringify(bad))));
});

test('the contours preview comes once, before the plan, fitted in the canvas', () => {
  // What the page's callbacks hear, in order.
  const heard = [];
  const onStage = (name) => heard.push(name);
  const onContours = (rgba, view) =>
    heard.push(['contours', rgba.length, view[0], view[1], view[2], rgba.some((v, i) => i % 4 < 3 && v < 255)]);
  const job = Job.watched(PLATE, settings(2), onStage, [300, 200, 2], onContours);
  const previews = heard.filter((h) => Array.isArray(h));
  assert.equal(previews.length, 1, 'one contours preview');
  const at = heard.indexOf(previews[0]);
  // After chaining, before the kerf and the plan.
  assert.deepEqual(heard.slice(0, at), ['reading', 'chaining']);
  assert.deepEqual(heard.slice(at + 1), ['offset', 'planning', 'gcode']);
  const v = heard[at];
  // 300 × 200 CSS pixels at ratio 2: 600 × 400 RGBA pixels, something drawn.
  assert.equal(v[1], 600 * 400 * 4);
  assert.equal(v[5], true);
  // The view: the contours' extent fitted with a 10 % margin, as the page fits a job.
  const [cx, cy, scale] = v.slice(2, 5);
  assert.ok(Number.isFinite(cx) && Number.isFinite(cy) && scale > 0);
  const { w, h } = report(job).size;
  assert.ok(Math.abs(scale - Math.min(300 / (w * 1.1), 200 / (h * 1.1))) < 1e-6 * scale, `${scale} for ${w} × ${h}`);
  // Without a canvas size, no preview and no error.
  assert.ok(
    Job.watched(PLATE, settings(2), null, null, () => {
      throw 1;
    }),
  );
});

test('the page report leaves out a long contour list and says how long it was', () => {
  const job = new Job(PLATE, settings(2));
  const full = report(job);
  assert.deepEqual(JSON.parse(job.page_report_json(100)), full);
  const short = JSON.parse(job.page_report_json(3));
  assert.equal(short.contours_omitted, 7);
  assert.deepEqual(short.contours, []);
  assert.deepEqual(short.plan, full.plan);
  // The job keeps its list.
  assert.deepEqual(report(job), full);
  assert.deepEqual(job.program(), utf8(job.gcode()));
});
