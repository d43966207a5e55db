// Nesting (issues 16, 18, 42) through the page's nester module (www/pkg/kerfcam_nest.js): the Nester /
// NestResult API Sheet mode uses, under Node; a sheet's DXF is read back by the cutting core
// (www/pkg/kerfcam.js), as the page reads a drawing.
//
//   bash scripts/build-wasm.sh && node --test tests/wasm/

import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { test } from 'node:test';
import { fileURLToPath } from 'node:url';
import { core, fixture, nest, refused, report, settings, utf8 } from './load.mjs';

const ROOT = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');

const { Nester } = await nest();
const { Job } = await core();

const PLATE = fixture('seed000-plate-6-holes.dxf');
const GRID = fixture('seed003-grid-3x2.dxf');
const EMPTY = utf8('0\nSECTION\n2\nENTITIES\n0\nENDSEC\n0\nEOF\n');

/** A clock that moves 1 ms each time it is read: the same run every time. */
function tickClock() {
  let t = 0;
  return () => (t += 0.001);
}

/** The page's nest settings: `count` sheets of `w` × `h` mm, spacing 2.5, margin 5, seed 3. */
const sheet = (w, h, count, timeS) => ({
  sheet_width: w,
  sheet_height: h,
  sheet_count: count,
  spacing: 2.5,
  margin: 5,
  time_s: timeS,
  seed: 3,
});

/** A part file's options: `quantity` copies, turned by 90° steps. */
const qty = (quantity) => ({ quantity, rotations: '90' });

/** `s` as Rust's `str::parse::<f64>` reads it (what the native tests took), else undefined. */
function f64(s) {
  if (/^[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?$/.test(s)) return Number(s);
  if (/^[+-]?(inf|infinity)$/i.test(s)) return s.startsWith('-') ? -Infinity : Infinity;
  if (/^[+-]?nan$/i.test(s)) return NaN;
  return undefined;
}

/** The copies' placements, 7 numbers each, as rows of a nest edit. */
function rows(flat) {
  const out = [];
  for (let i = 0; i < flat.length; i += 7) out.push(flat.slice(i, i + 7));
  return out;
}

const countOf = (text, word) => text.split(word).length - 1;

test('nest API places parts, reports progress and cuts a sheet with the crop line last', () => {
  const n = new Nester();
  assert.equal(n.add_part(PLATE, 'plate.dxf', qty(3)), '["plate"]');
  const log = [];
  const hear = (p) => {
    log.push(p.length);
    return true;
  };
  const r = n.nest(sheet(1000, 500, 2, 0.2), tickClock(), hear);
  const j = JSON.parse(r.json());
  assert.equal(j.placed, 3, r.json());
  assert.ok(Array.isArray(j.unplaced) && j.unplaced.length === 0, r.json());
  const u = j.sheets[0].utilisation;
  assert.ok(u > 0 && u <= 1, `${u}`);
  // Heard at least the first nest, best-so-far lengths never growing.
  const lengths = log.filter((v) => typeof v === 'number');
  assert.ok(lengths.length > 0);
  assert.ok(
    lengths.every((l, i) => i === 0 || l <= lengths[i - 1] + 1e-9),
    `${lengths}`,
  );
  // Sheet 0 cut by the pipeline: 3 plates × 7 contours, then the crop.
  const crop = j.sheets[0].crop_x;
  assert.equal(typeof crop, 'number', 'a remnant kept');
  const job = r.cut(0, settings(1.5));
  const rep = report(job);
  assert.equal(rep.plan.pierces, 3 * 7 + 1, job.report_json());
  const g = job.gcode();
  assert.equal(countOf(g, 'M3 S1'), 22);
  // Pierced on the sheet's top edge at the crop line, straight down.
  const lines = g.split(/\r?\n/);
  const on = lines.findLastIndex((l) => l.startsWith('M3'));
  assert.ok(on >= 0);
  const xy = (l) => {
    const v = (c) => {
      const x = l
        .split(/\s+/)
        .filter((w) => w.startsWith(c))
        .map((w) => f64(w.slice(1)))
        .find((x) => x !== undefined);
      assert.notEqual(x, undefined, `no ${c} in ${l}`);
      return x;
    };
    return [v('X'), v('Y')];
  };
  const rapid = lines
    .slice(0, on)
    .reverse()
    .find((l) => l.startsWith('G0'));
  assert.ok(rapid !== undefined);
  assert.deepEqual(xy(rapid), [crop, 500], rapid);
  assert.deepEqual(xy(lines[on + 1]), [crop, 0], lines[on + 1]);
  assert.ok(lines[on + 2].startsWith('M5'), lines[on + 2]);
  refused(() => r.cut(5, settings(1.5)));
  // The nest DXF, the sheet's DXF (the cutting core reads it, as the page reads a drawing) and the remnant.
  assert.ok(r.dxf().includes('REMNANT'));
  assert.ok(new Job(utf8(r.sheet_dxf(0)), settings(1.5)));
  const rem = r.remnant_dxf();
  assert.ok(rem.includes('SHEET'));
  // …given back as the sheet of another nest.
  const again = new Nester();
  again.add_part(PLATE, 'plate.dxf', qty(1));
  assert.equal(again.set_sheet_dxf(utf8(rem)), '[]');
  const j2 = JSON.parse(again.nest(undefined, tickClock(), null).json());
  assert.equal(j2.placed, 1, JSON.stringify(j2));
  assert.ok(j2.placements[0].translation[0] > crop, `${j2.placements[0].translation[0]} at crop ${crop}`);
});

// Sheets of two sizes (the page's `sheet_list`): the first size filled first, each sheet reported and
// cut at its own size, and a list with a size of 0 sheets refused.
test('nest API takes a list of sheet sizes', () => {
  const n = new Nester();
  n.add_part(PLATE, 'plate.dxf', qty(4));
  const list = (sizes) => ({ sheet_list: sizes, spacing: 2.5, margin: 10, time_s: 0.05, seed: 1 });
  // 450 × 180 holds two 200 × 120 plates, 250 × 150 one.
  const r = n.nest(
    list([
      { width: 450, height: 180, count: 1 },
      { width: 250, height: 150, count: 3 },
    ]),
    tickClock(),
    null,
  );
  const j = JSON.parse(r.json());
  assert.equal(j.placed, 4, r.json());
  const sizes = j.sheets.map((s) => [s.width, s.height, s.parts]);
  assert.deepEqual(
    sizes,
    [
      [450, 180, 2],
      [250, 150, 1],
      [250, 150, 1],
    ],
    r.json(),
  );
  // Sheet 2's program stays on its 250 × 150.
  const g = r.cut(1, settings(1.5)).gcode();
  for (const w of g.split(/\s+/)) {
    const x = w.startsWith('X') ? f64(w.slice(1)) : undefined;
    if (x !== undefined) assert.ok(x >= -5 && x <= 255, w);
  }
  refused(() =>
    n.nest(
      list([
        { width: 450, height: 180, count: 1 },
        { width: 250, height: 150, count: 0 },
      ]),
      tickClock(),
      null,
    ),
  );
});

/** The largest number in part 0's outline path: its size, whatever the unit. */
function outlineSpan(n) {
  const o = JSON.parse(n.outlines());
  return o[0].d
    .split(/[^0-9.-]/)
    .map(f64)
    .filter((v) => v !== undefined)
    .reduce((m, v) => Math.max(m, Math.abs(v)), 0);
}

test('nest API reads a part file in the unit chosen for it', () => {
  // The page's per-file unit switch (issue 18): the same file read in inches is 25.4 times the size
  // read as its own (mm); an unknown unit is refused, not read at some scale.
  const read = (units) => {
    const n = new Nester();
    n.add_part(PLATE, 'plate.dxf', { quantity: 1, units });
    return outlineSpan(n);
  };
  const own = read('');
  const mm = read('mm');
  const inch = read('in');
  assert.ok(Math.abs(own - mm) < 1e-9, `${own} ${mm}`);
  assert.ok(Math.abs(inch / mm - 25.4) < 1e-9, `${inch} ${mm}`);
  refused(() => read('furlong'));
});

test('nest API: cancel and bad input are answers, not crashes', () => {
  const n = new Nester();
  const names = JSON.parse(n.add_part(GRID, 'grid.dxf', qty(4)));
  assert.ok(Array.isArray(names) && names.every((s) => typeof s === 'string'));
  const stop = () => false;
  const r = n.nest(sheet(1000, 500, 3, 1e6), tickClock(), stop);
  const j = JSON.parse(r.json());
  // Stopped at the first report: the first nest reports every 8 copies (one evaluation each) while it
  // is placed, else once whole.
  const copies = 4 * names.length;
  const first = copies > 8 ? 8 : copies;
  assert.equal(j.evaluations, first, `stopped at the first report: ${r.json()}`);
  const unplaced = j.unplaced.reduce((s, u) => {
    assert.ok(Number.isInteger(u.copies) && u.copies >= 0);
    return s + u.copies;
  }, 0);
  assert.equal(j.placed + unplaced, 4 * names.length, r.json());
  // A clock that throws ends the search, not the page.
  const badClock = () => {
    throw new Error('no clock');
  };
  assert.ok(n.nest(sheet(1000, 500, 3, 5), badClock, null));
  refused(() => new Nester().nest(sheet(1000, 500, 1, 0), tickClock(), null));
  refused(() => n.nest(undefined, tickClock(), null)); // no sheet given
  refused(() => n.nest(sheet(-5, 500, 1, 0), tickClock(), null));
  refused(() => new Nester().add_part(new Uint8Array([0, ...utf8('garbage')]), 'x.dxf', qty(1)));
  refused(() => new Nester().add_part(PLATE, 'p.dxf', { rotations: 'sideways' }));
  refused(() => new Nester().set_sheet_dxf(EMPTY));
});

// Stop without a shared flag (www/nest-run.js) replays the search to the count it showed, with 5 s more on
// the clock (which must not end the replay first) and the run's budget as `budget_s`: the sequence search's
// share is sized from the budget, so the replay is the run stopped. Without `budget_s` the longer clock
// gives it a larger share: another nest. A budget of 10 ms on a clock that stands still.
test('a Stop replay with more time and the run’s budget is the nest shown', () => {
  const n = new Nester();
  n.add_part(PLATE, 'plate.dxf', qty(4));
  const run = sheet(1000, 500, 3, 0.01);
  const still = () => 0;
  const stopped = JSON.parse(n.nest(run, still, (p) => p.evaluations < 1000).json());
  assert.ok(stopped.evaluations >= 1000, `${stopped.evaluations}`);
  const again = (more) => JSON.parse(n.nest({ ...run, ...more, max_evaluations: stopped.evaluations }, still, null).json());
  const replay = again({ time_s: run.time_s + 5, budget_s: run.time_s });
  assert.deepEqual(replay.placements, stopped.placements);
  assert.equal(replay.evaluations, stopped.evaluations);
  assert.notDeepEqual(again({ time_s: run.time_s + 5 }).placements, stopped.placements);
});

test('remnant sheets and nest files are refused in the page’s language', () => {
  // Issue 18: the core's messages about a remnant sheet and a nest file come in Portuguese to a
  // Portuguese page, in English otherwise.
  const pt = refused(() => new Nester('pt-BR').set_sheet_dxf(EMPTY));
  assert.ok(pt.includes('não tem contorno fechado'), pt);
  const en = refused(() => new Nester().set_sheet_dxf(EMPTY));
  assert.ok(en.includes('no closed outline'), en);
  // A nest file naming a sheet the nest does not have.
  const n = new Nester('pt-BR');
  n.add_part(PLATE, 'plate.dxf', qty(1));
  const bad = '{"placements": [[0, 0, 7, 0, 0, 100, 100]]}';
  let e = refused(() => n.restore(sheet(1000, 500, 1, 1), 1, bad));
  assert.ok(e.startsWith('ajuste do encaixe: cópia 0: esperado'), e);
  e = refused(() => n.restore(sheet(1000, 500, 1, 1), 3, bad));
  assert.ok(e.includes('3 chapas: entre 1 e 1'), e);
});

// A nest adjusted by hand (issue 18 item 4): the NestResult edit API.
test('nest API: live placements, hand edits, conflicts, snap and the moved crop line', () => {
  const n = new Nester();
  n.add_part(PLATE, 'plate.dxf', qty(3));
  const outlines = JSON.parse(n.outlines());
  assert.equal(outlines[0].name, 'plate');
  const d = outlines[0].d;
  assert.equal(countOf(d, 'M'), 7, `outline and six holes: ${d}`);
  assert.ok(d.includes('A'), 'the round holes stay arcs');
  // Progress carries the best nest's copies, 7 numbers each, when it changed.
  const heard = [];
  const hear = (p) => {
    if (p.placements) heard.push(p.placements.length);
    return true;
  };
  const r = n.nest(sheet(1000, 500, 1, 0.05), tickClock(), hear);
  const sizes = heard.filter((v) => typeof v === 'number');
  assert.ok(sizes.length > 0 && sizes.every((s) => s === 21), `${sizes}`);
  const state = (s) => JSON.parse(s);
  const s0 = state(r.state());
  assert.equal(s0.conflicts.length, 0, 'the nest as found passes the check');
  const flat = s0.flat;
  assert.ok(flat.every((v) => typeof v === 'number'));
  assert.equal(flat.length, 21);
  const edit = (f) => JSON.stringify({ placements: rows(f) });
  // Copy 1 dropped onto copy 0: both in conflict, and the nest is not cut.
  const moved = [...flat];
  moved[7 + 5] = flat[5] + 10;
  moved[7 + 6] = flat[6];
  moved[7 + 3] = flat[3];
  moved[7 + 4] = flat[4];
  const s1 = state(r.edit(edit(moved)));
  const whys = s1.conflicts.map((c) => `${c.copy}:${c.why}`);
  assert.ok(whys.includes('0:overlap') && whys.includes('1:overlap'), `${whys}`);
  refused(() => r.cut(0, settings(1.5))); // a nest in conflict is not cut
  // Back where it was: cut again.
  const s2 = state(r.edit(edit(flat)));
  assert.equal(s2.conflicts.length, 0);
  assert.ok(r.cut(0, settings(1.5)));
  // Copy 2 taken far right, then snapped: back against its neighbours.
  const far = [...flat];
  far[14 + 5] = 800;
  far[14 + 6] = 300;
  const s3 = state(r.edit(edit(far)));
  const u3 = s3.sheets[0].used_length;
  const s4 = state(r.snap(2));
  assert.equal(s4.conflicts.length, 0);
  const u4 = s4.sheets[0].used_length;
  assert.ok(typeof u3 === 'number' && typeof u4 === 'number' && u4 < u3 - 100, `snapped from ${u3} to ${u4}`);
  // The crop line moved right: the remnant and the program's crop cut follow.
  const [lo, hi] = s4.crop_range;
  assert.ok(typeof lo === 'number' && typeof hi === 'number');
  const x = (lo + hi) / 2;
  const s5 = state(r.edit(`{"crop": ${x}}`));
  assert.equal(s5.sheets[0].crop_x, x);
  assert.ok(s5.sheets[0].utilisation < s4.sheets[0].utilisation);
  assert.ok(r.remnant_dxf().includes(`10\n${x}\n`), r.remnant_dxf());
  const g = r.cut(0, settings(1.5)).gcode();
  assert.ok(g.includes(`X${x.toFixed(3)}`) || g.includes(`X${x}`), `crop at ${x}`);
  // Bad edits change nothing.
  refused(() => r.edit('{"placements": [[9, 0, 0, 0, 0, 1, 1]]}'));
  refused(() => r.edit('{"placements": [[0, 0, 0, 0, 0, 1e400, 1]]}'));
  refused(() => r.edit('{"crop": "left"}'));
  refused(() => r.edit('not json'));
  refused(() => r.snap(99));
  assert.deepEqual(state(r.state()).flat, s5.flat);
  // A nest file: the same parts and settings, the placements and crop line saved, made again without a
  // search: the same nest, figures and all.
  const file = JSON.stringify({ placements: rows(s5.flat), crop: x });
  const again = n.restore(sheet(1000, 500, 1, 0), 1, file);
  const s6 = state(again.state());
  for (const key of ['flat', 'sheets', 'conflicts', 'remnant_area', 'placements']) {
    assert.deepEqual(s6[key], s5[key], key);
  }
  refused(() => n.restore(sheet(1000, 500, 1, 0), 2, file)); // 2 sheets of 1
  refused(() => n.restore(sheet(-1, 500, 1, 0), 1, file));
  refused(() => n.restore(sheet(1000, 500, 1, 0), 1, '{"placements": [[0, 0, 3, 0, 0, 1, 1]]}'));
});

// Issue 42 §1: a file's parts as rows, and each part's own quantity.
test('part rows list each part and each part takes its own quantity', () => {
  const rowsOf = JSON.parse(new Nester().part_rows(GRID, 'grid.dxf', undefined));
  const list = rowsOf.rows;
  assert.equal(list.length, 6, JSON.stringify(rowsOf));
  for (const r of list) {
    assert.ok(r.width > 0 && r.area > 0, JSON.stringify(r));
    assert.ok(r.d.startsWith('M'));
    assert.equal(r.not_nestable ?? null, null);
  }
  const n = new Nester();
  n.add_part(GRID, 'grid.dxf', { quantity: 7, each: [1, 0, 2, 0, 0, 0].map((quantity) => ({ quantity })) });
  const r = n.nest(sheet(1000, 500, 1, 0.2), tickClock(), null);
  const j = JSON.parse(r.json());
  assert.equal(j.placed, 3, r.json());
  const names = list.map((row) => row.name);
  assert.ok(names.every((s) => typeof s === 'string'));
  const [first, third] = [names[0], names[2]];
  const placed = j.placements.map((p) => p.part);
  assert.ok(placed.every((s) => typeof s === 'string'));
  assert.equal(placed.filter((p) => p === first).length, 1, `${placed}`);
  assert.equal(placed.filter((p) => p === third).length, 2, `${placed}`);
});

// Sheets at a cost (issue 44 item 3): the page's nester takes the cheapest combination the CLI takes for the
// same job. The job and the CLI's answer are one file (tests/golden/nest-cost-squares.json, checked against
// `kerfcam nest --sheet WxH:N:COST --json` by tests/it/nest_cost.rs): the same sheets, cost, combinations
// passed over and placements. Costs given for some sizes only, or refused, are said naming the size.
test('nest API takes the cheapest sheets at a cost, as the CLI does for the same job', () => {
  const file = JSON.parse(fs.readFileSync(path.join(ROOT, 'tests', 'golden', 'nest-cost-squares.json'), 'utf8'));
  const { job } = file;
  const n = new Nester();
  n.add_part(utf8(job.dxf), `${job.name}.dxf`, qty(job.quantity));
  const settings = {
    sheet_list: job.sheet_list, margin: job.margin, spacing: job.spacing, max_evaluations: job.max_evaluations,
    time_s: job.time_s, seed: job.seed,
  };
  const heard = [];
  const r = n.nest(settings, tickClock(), (p) => {
    if (p.combination) heard.push(p.combination);
    return true;
  });
  const j = JSON.parse(r.json());
  // The nest's fields (its quote is asked for below, as the Cost panel asks).
  const fields = Object.keys(file.nest).filter((k) => k !== 'quote');
  for (const k of fields) assert.deepEqual(j[k], file.nest[k], `${k}: ${JSON.stringify(j[k])}`);
  // The state the page shows carries them too, and the progress named each combination tried in turn.
  const state = JSON.parse(r.state());
  assert.deepEqual([state.stock, state.sheet_cost], [j.stock, j.sheet_cost]);
  const tried = [...new Set(heard.map((c) => JSON.stringify(c)))].map((c) => JSON.parse(c));
  assert.deepEqual(tried.map((c) => c.counts), [[1, 0], [0, 3], [1, 1], [0, 4]]);
  assert.deepEqual(tried.map((c) => c.passed_over), [0, 1, 2, 3]);
  // Made again from its combination (a nest file, a stopped nest kept): the same cost and choice.
  const again = n.restore({ ...settings, combination: j.stock.map((s) => s.used), passed_over: 3 }, j.sheets.length,
    JSON.stringify({ placements: rows(state.flat) }));
  const back = JSON.parse(again.json());
  assert.deepEqual([back.stock, back.sheet_cost, back.combinations_passed_over], [j.stock, j.sheet_cost, 3]);
  // Its quote at the job's cost model, as the Cost panel asks for it: the CLI's (`--cost`), its material the
  // sheets the nest chose at their cost.
  const quote = JSON.parse(r.quote(JSON.stringify(job.cost_model), undefined, false));
  assert.equal(quote.material_share, 'sheet_cost');
  assert.equal(quote.job.material, j.sheet_cost);
  assert.deepEqual(quote, file.nest.quote);
  assert.match(quote.notes[0].en, /^material: the 4 sheet\(s\) the nest chose, at the costs given with the sheets \(8\.00 EUR in all\)/);

  // A team's route (nest-team.js runCheapest): the trials one at a time, each nested by the team's searches
  // (here one), make the same choice and nest.
  const trials = n.trials(settings, tickClock());
  const told = [];
  for (let t; (t = trials.next(tickClock()));) {
    told.push([t.combination, t.passed_over]);
    const s = n.search({ ...settings, ...t }, 0);
    for (let until = 10000; s.run(until, tickClock(), null); until += 10000) s.adopt([s.best()]);
    trials.record(s, s.evaluations());
    s.free();
  }
  assert.deepEqual(told, [[[1, 0], 0], [[0, 3], 1], [[1, 1], 2], [[0, 4], 3], [[0, 4], 3]]);
  const team = JSON.parse(trials.finish(1).json());
  for (const k of fields) assert.deepEqual(team[k], file.nest[k], `team ${k}`);
  assert.throws(() => trials.finish(1), /finished|not done/);
  refused(() => n.trials({ ...settings, combination: [0, 4] }, tickClock()));

  // The CLI's rule and words: a cost for every size or for none; a price ≥ 0; one torch.
  const costs = (a, b) => ({ ...settings, sheet_list: [{ ...job.sheet_list[0], cost: a }, { ...job.sheet_list[1], cost: b }] });
  let e = refused(() => n.nest(costs(5, null), tickClock(), null));
  assert.equal(e, 'sheet costs: give a cost for every sheet size or for none');
  e = refused(() => n.nest(costs(5, -2), tickClock(), null));
  assert.equal(e, 'sheet size 2: the cost -2 of a 70 × 70 sheet is not a price ≥ 0');
  e = refused(() => n.nest(costs(NaN, 2), tickClock(), null));
  assert.match(e, /^sheet size 1: the cost NaN /);
  e = refused(() => n.nest(costs('abc', 2), tickClock(), null));
  assert.equal(e, "sheet size 1: the cost 'abc' is not a number");
  e = refused(() => n.nest({ ...costs(5, 2), torches: 2, torch_spacing: 300 }, tickClock(), null));
  assert.equal(e, 'sheet costs: a multi-torch nest takes the sheets as given (leave the costs out)');
  const pt = new Nester('pt-BR');
  pt.add_part(utf8(job.dxf), `${job.name}.dxf`, qty(job.quantity));
  e = refused(() => pt.nest(costs(null, 2), tickClock(), null));
  assert.equal(e, 'custos das chapas: informe um custo para cada tamanho de chapa ou para nenhum');
  // A team's search does not choose among combinations: refused, unless given the combination.
  refused(() => n.search(settings, 0));
  assert.ok(n.search({ ...settings, combination: [0, 4] }, 0));
});
