// kerfcam engine worker: the wasm pipeline runs here, off the page's main thread, so the page stays
// responsive (scroll, pan, Cancel) while a big DXF is read, chained, offset and planned.
// Protocol: {id, op, args} in; {id, progress} while it runs (stage done: {stage, count, ms}), then
// {id, ok: true, result} or {id, ok: false, error} out.
// Sheet mode (issue 18) adds partInfo, nest and cutSheet: the nest's sheet becomes the current Job, so
// the preview, inspect, compare and the program work on it as on one drawing.

import init, { Job, backplot_json, check_cost, check_post, defaults_json, materials_cfg, materials_check, materials_read, materials_starter, presets_json, version } from './pkg/kerfcam.js';
// The nesting engine is a second wasm module (issue 17: the cutting core stays small): its glue is
// imported here, its wasm is fetched and compiled only when Sheet mode first needs the nester.
// It also has the SVG reader (issue 41; the core's wasm stays within its size without it): an SVG
// runs as a Job of that module, the same pipeline.

let job = null; // the current wasm Job
let nested = null; // the last NestResult (Sheet mode)
let search = null; // this worker's search of a team nest (nest-team.js), between two exchanges
let trials = null; // the trials of a team nest at a cost (nest-team.js), held by the engine's worker

// Above this many contours the report's per-contour list stays here: parsing the 18 MB report of a
// 125 000-contour nest took 288 ms of the page's main thread, and the page shows only counts. The
// engine leaves the list out itself (Job.page_report_json): writing it and parsing it here to drop it
// cost the worker ~0.3 s more.
const PAGE_CONTOURS_MAX = 5000;

/**
 * What the page gets of a finished job: the report, the program as UTF-8 bytes moved (not copied) to
 * the page (receiving a 25 MB string was part of the page's longest task at the end of a big job; the
 * engine hands the bytes over as they are, no string decoded and encoded again), the box, the moves.
 */
const resultOf = (j) => ({
  report: j.page_report_json(PAGE_CONTOURS_MAX),
  gcode: j.program(),
  bbox: j.bbox(),
  moves: j.moves(),
  ...heatOf(j),
  ...lossesOf(j),
});

/** The engine's per-stage callback, reporting each stage's name, count and milliseconds to the page. */
function stageTimer(progress) {
  let t0 = performance.now();
  return (stage, count) => {
    const t = performance.now();
    progress({ stage, count, ms: t - t0 });
    t0 = t;
  };
}

/** The verification's heat map (issue 20 §9): the overcut squares and where parts stay attached. */
const heatOf = (j) => ({ heat: j.overcut_heat(), attached: j.attached_points() });

/** What the cuts take from the parts, marked before the download (issue 45 §3): the outlines the loss warnings name, and where a cut comes within half the kerf. */
const lossesOf = (j) => ({ lossOutlines: j.loss_outlines(), lossSquares: j.closeness_heat() });

/** A Nester with the parts files (and the remnant sheet) read as `kerfcam nest` reads them. */
async function partsNester({ parts, cutting, lang, sheet }) {
  const nester = new Nester(lang);
  try {
    if (cutting) nester.set_cutting(cutting);
    if (sheet) nester.set_sheet_dxf(new Uint8Array(await sheet.arrayBuffer())); // throws for no closed outline
    for (const p of parts) {
      const bytes = new Uint8Array(await p.file.arrayBuffer());
      nester.add_part(bytes, p.name, { quantity: p.quantity, rotations: p.rotations, mirror: p.mirror, units: p.units || '', each: p.each || [] });
    }
    return nester;
  } catch (e) {
    nester.free();
    throw e;
  }
}

/** What the page gets of the last nest (`nested`), with the labels as the page set them. */
function nestAnswer(labels) {
  if (labels) nested.set_labels(JSON.stringify(labels)); // the page checked them (labels.js)
  return { json: nested.json(), sheets: nested.sheet_count(), state: nested.state(), outlines: nested.outlines() };
}

let nestWasm = null; // the single-file build's nester module, base64, decoded when first needed
let nestReady = null;

let FullJob = null; // the nester module's Job and Nester, once it is loaded
let Nester = null;

/**
 * Loads the nester module once (the first Sheet-mode operation); resolves when Nester can be used. Its glue is
 * imported then, not with the worker: npm start serves the page before the nester module is built (issue 40),
 * and the cutting core must not wait for it.
 */
function nesterLoaded() {
  if (!nestReady) {
    const bytes = nestWasm && Uint8Array.from(atob(nestWasm.replace(/\s+/g, '')), (c) => c.charCodeAt(0));
    nestReady = import('./pkg/kerfcam_nest.js').then(async (glue) => {
      await glue.default(bytes ? { module_or_path: bytes } : undefined);
      nestWasm = null;
      ({ Job: FullJob, Nester } = glue);
    });
    nestReady.catch(() => (nestReady = null)); // a failed load is tried again by the next operation
  }
  return nestReady;
}

/** True for an SVG's bytes (XML after an optional byte-order mark and white space, or gzip): as the engine's input::Format. */
function isSvg(b) {
  if (b[0] === 0x1f && b[1] === 0x8b) return true;
  let i = b[0] === 0xef && b[1] === 0xbb && b[2] === 0xbf ? 3 : 0;
  while (i < b.length && (b[i] === 0x20 || b[i] === 0x09 || b[i] === 0x0a || b[i] === 0x0d)) i++;
  return b[i] === 0x3c;
}

/** The Job class that reads these bytes: the core's for a DXF, the second module's for an SVG. */
async function jobClass(bytes) {
  if (!isSvg(bytes)) return Job;
  await nesterLoaded();
  return FullJob;
}

const ops = {
  async init({ wasm, nest }) {
    nestWasm = nest ?? null;
    await init(wasm ? { module_or_path: wasm } : undefined); // wasm: bytes from the single-file build
    return version();
  },
  /** The engine's defaults of the form's numbers (and the nest's under `nest`), JSON. */
  defaults() {
    return defaults_json();
  },
  /**
   * `preview` ({width, height, dpr}: the canvas in CSS pixels): the contours are rendered fitted in it
   * as soon as they are made and sent as progress {contours: {rgba, view}} (issue 17 item 4), so the
   * page shows the drawing while the plan is made.
   */
  async run({ file, settings, preview }, progress) {
    const bytes = new Uint8Array(await file.arrayBuffer()); // read here, off the page's main thread
    job?.free();
    job = null;
    const size = preview ? [preview.width, preview.height, preview.dpr] : undefined;
    const onContours = (rgba, view) => progress({ contours: { rgba, view: [...view] } }, [rgba.buffer]);
    const J = await jobClass(bytes);
    job = J.watched(bytes, settings, stageTimer(progress), size, preview ? onContours : undefined);
    return resultOf(job);
  },
  /** A program for a file of a batch: report and G-code, without replacing the job on the preview. */
  async program({ file, settings }, progress) {
    const bytes = new Uint8Array(await file.arrayBuffer());
    const J = await jobClass(bytes);
    const other = new J(bytes, settings, stageTimer(progress));
    try {
      return { report: other.page_report_json(PAGE_CONTOURS_MAX), gcode: other.program() };
    } finally {
      other.free();
    }
  },
  /** A parts file of Sheet mode: its parts' names, its units and the area of one set of its parts. */
  async partInfo({ file, name, lang, units, cutting }) {
    await nesterLoaded();
    const bytes = new Uint8Array(await file.arrayBuffer());
    const nester = new Nester(lang);
    let rows;
    try {
      if (cutting) nester.set_cutting(cutting);
      rows = JSON.parse(nester.part_rows(bytes, name, { units: units || '' }));
    } finally {
      nester.free();
    }
    // The file's units as the single-drawing report states them (or as chosen for it: `units`).
    const J = await jobClass(bytes);
    const one = new J(bytes, { lang, units: units || null }, null);
    try {
      const r = JSON.parse(one.report_json());
      // One row per part (issue 42 §1), in the order the nester takes per-part choices; `parts` their names.
      const parts = rows.rows.map((row) => row.name);
      return { parts, rows: rows.rows, open: rows.open, suspect: rows.suspect, units: r.units, unitsSource: r.units_source, unitsAssumed: !!r.units_assumed };
    } finally {
      one.free();
    }
  },
  /**
   * Nests the parts files on the sheet; progress goes out after each better nest. `stop`: an Int32Array
   * on a SharedArrayBuffer (a cross-origin isolated page) whose first cell the page sets to stop the
   * search; without one the page stops by replaying to the last evaluations count (nest-run.js).
   */
  async nest({ parts, settings, cutting, lang, stop, sheet, labels }, progress) {
    await nesterLoaded();
    // Parts and the sheet read as `kerfcam nest` reads them: the cutting settings' layers, tolerance, gap;
    // the spacing not given is their kerf + 1 mm.
    const nester = await partsNester({ parts, cutting, lang, sheet });
    try {
      progress({ outlines: nester.outlines(), sheet: nester.sheet_shape() }); // shapes first: the nest is drawn live
      nested?.free();
      nested = null;
      nested = nester.nest(settings, () => performance.now() / 1000, (p) => {
        progress(p);
        return !(stop && Atomics.load(stop, 0) === 1);
      });
      return nestAnswer(labels);
    } finally {
      nester.free();
    }
  },
  /**
   * A team nest (nest-team.js, issue 44 item 2): this worker's search `k` of the parts on the sheet, as
   * `nest` reads them; answers the shapes to draw the nest live with.
   */
  async searchStart({ parts, settings, cutting, lang, sheet, k }) {
    await nesterLoaded();
    const nester = await partsNester({ parts, cutting, lang, sheet });
    try {
      search?.free();
      search = null;
      search = nester.search(settings, k);
      return { outlines: nester.outlines(), sheet: nester.sheet_shape() };
    } finally {
      nester.free();
    }
  },
  /** The search run to the exchange at `until` evaluations (or its end); answers its best nest. */
  searchRun({ until }, progress) {
    if (!search) throw new Error('no search');
    const more = search.run(until, () => performance.now() / 1000, (p) => {
      progress(p);
      return true;
    });
    return { more, best: search.best(), evaluations: search.evaluations() };
  },
  /** The exchange: every worker's best, in worker order; this search takes the best when it beats its own. */
  searchAdopt({ bests }) {
    if (!search) throw new Error('no search');
    return search.adopt(bests);
  },
  /** The team's nest: this search's best (the team's after the last exchange) becomes the last nest. */
  searchFinish({ evaluations, seconds, labels }) {
    if (!search) throw new Error('no search');
    nested?.free();
    nested = null;
    try {
      nested = search.finish(evaluations, seconds);
    } finally {
      search.free();
      search = null;
    }
    return nestAnswer(labels);
  },
  /**
   * A team nest at a cost (issue 44 items 2 and 3): the trials of the cheapest combination start here (the
   * engine's worker); each trial is a team nest of the settings and `trialsNext`'s answer.
   */
  async trialsStart({ parts, settings, cutting, lang, sheet }) {
    await nesterLoaded();
    const nester = await partsNester({ parts, cutting, lang, sheet });
    try {
      trials?.free();
      trials = null;
      trials = nester.trials(settings, () => performance.now() / 1000);
    } finally {
      nester.free();
    }
  },
  /** The next trial's settings ({combination, passed_over, max_evaluations, time_s, budget_s}), or null when done. */
  trialsNext() {
    if (!trials) throw new Error('no trials');
    return trials.next(() => performance.now() / 1000);
  },
  /** The trial's nest: this worker's search (search 0, the team's best after the last exchange), spent. */
  trialsRecord({ evaluations }) {
    if (!trials || !search) throw new Error('no trial');
    try {
      trials.record(search, evaluations);
    } finally {
      search.free();
      search = null;
    }
  },
  /** The cheapest nest found by the trials becomes the last nest. */
  trialsFinish({ seconds, labels }) {
    if (!trials) throw new Error('no trials');
    nested?.free();
    nested = null;
    try {
      nested = trials.finish(seconds);
    } finally {
      trials.free();
      trials = null;
    }
    return nestAnswer(labels);
  },
  /** A team nest stopped (its workers ended): the best nest it showed, `best`, made the last nest, no search. */
  async nestFrom({ parts, settings, cutting, lang, sheet, best, evaluations, seconds, labels }) {
    await nesterLoaded();
    const nester = await partsNester({ parts, cutting, lang, sheet });
    try {
      search?.free();
      search = null;
      search = nester.search(settings, 0);
      if (!search.adopt([best])) throw new Error('the nest kept does not fit these parts');
    } finally {
      nester.free();
    }
    return ops.searchFinish({ evaluations, seconds, labels });
  },
  /** A nest file opened: its parts, settings and placements made again into the last nest, no search. */
  async restoreNest({ parts, settings, cutting, lang, sheet, sheets, json, labels }) {
    await nesterLoaded();
    const nester = new Nester(lang);
    try {
      if (cutting) nester.set_cutting(cutting);
      if (sheet) nester.set_sheet_dxf(new Uint8Array(await sheet.arrayBuffer()));
      for (const p of parts) {
        const bytes = new Uint8Array(await p.file.arrayBuffer());
        nester.add_part(bytes, p.name, { quantity: p.quantity, rotations: p.rotations, mirror: p.mirror, units: p.units || '', each: p.each || [] });
      }
      nested?.free();
      nested = null;
      nested = nester.restore(settings, sheets, json);
      if (labels) nested.set_labels(JSON.stringify(labels)); // as the page has them set (labels.js)
      return { json: nested.json(), sheets: nested.sheet_count(), state: nested.state(), outlines: nested.outlines() };
    } finally {
      nester.free();
    }
  },
  /** The last nest adjusted by hand (nest-edit.js): its placements and/or crop line; answers its state. */
  editNest({ json }) {
    if (!nested) throw new Error('no nest');
    return nested.edit(json);
  },
  /** Copy `i` of the last nest butted left then down at the spacing; answers the nest's state. */
  snapCopy({ i }) {
    if (!nested) throw new Error('no nest');
    return nested.snap(i);
  },
  /** The last nest's labels set (issue 42 §2: {on, naming, height_max, height_min, margin, mark}); answers its state. */
  setLabels({ spec }) {
    if (!nested) throw new Error('no nest');
    return nested.set_labels(JSON.stringify(spec));
  },
  /** The last nest as a DXF: its parts placed, each sheet on layer SHEET (`kerfcam nest -o NEST.dxf`). */
  nestDxf() {
    if (!nested) throw new Error('no nest');
    return nested.dxf();
  },
  /** The last nest as an SVG in mm (`kerfcam nest -o NEST.svg`); '' for a multi-torch nest. */
  nestSvg() {
    if (!nested) throw new Error('no nest');
    return nested.svg();
  },
  /** The remnant beyond the last nest's crop line as a sheet DXF ('' when none is kept). */
  remnantDxf() {
    if (!nested) throw new Error('no nest');
    return nested.remnant_dxf();
  },
  /** Sheet `k` of the last nest cut with the page's settings: it becomes the current Job. */
  cutSheet({ k, settings }) {
    if (!nested) throw new Error('no nest');
    const next = nested.cut(k, settings);
    job?.free();
    job = next;
    return resultOf(job);
  },
  inspect({ x, y, reach }) {
    return job ? job.inspect_json(x, y, reach) : 'null';
  },
  snap({ x, y, reach }) {
    return job ? [...job.snap(x, y, reach)] : [x, y];
  },
  render({ width, height, cx, cy, scale, dpr }) {
    if (!job) throw new Error('no job');
    return job.render(width, height, cx, cy, scale, dpr);
  },
  compare() {
    if (!job) throw new Error('no job');
    return job.compare_json();
  },
  /**
   * Every sheet of the last nest cut as `cutSheet` cuts one (the same settings), for the job report (issue 42
   * §4): each sheet's plan figures and warnings. The current job (the sheet on the preview) stays.
   */
  sheetFigures({ settings }) {
    if (!nested) throw new Error('no nest');
    const out = [];
    for (let k = 0; k < nested.sheet_count(); k++) {
      const j = nested.cut(k, settings);
      try {
        const r = JSON.parse(j.page_report_json(0));
        out.push({ plan: r.plan, warnings: r.warnings });
      } finally {
        j.free();
      }
    }
    return out;
  },
  /** The current job's cut plan as an SVG drawing in mm (`kerfcam FILE -o OUT.svg`), its sheet layer named `label`. */
  planSvg({ label }) {
    if (!job) throw new Error('no job');
    return job.plan_svg(label);
  },
  presets() {
    return presets_json();
  },
  checkPost({ json, lang }) {
    return check_post(json, lang); // the message in the page's language
  },
  // The Cost panel (cost.js, issue 42 §3): the model checked ('' or {field, message}), and the quote of
  // the shown job: every sheet of the last nest in Sheet mode, else the drawing on the preview.
  checkCost: ({ json, lang }) => check_cost(json, lang),
  quote({ cost, sheet, settings, name, lang }) {
    if (sheet) {
      if (!nested) throw new Error('no nest');
      return { json: nested.quote(cost, settings, false), csv: nested.quote(cost, settings, true) };
    }
    if (!job) throw new Error('no job');
    return { json: job.quote_json(cost, name), csv: job.quote_csv(cost, name, lang) };
  },
  // The cut chart (materials.js): read, checked and written by the engine.
  materialsStarter: () => materials_starter(),
  materialsRead: ({ text, lang }) => materials_read(text, lang),
  materialsCheck: ({ json, lang }) => materials_check(json, lang),
  materialsCfg: ({ json, lang }) => materials_cfg(json, lang),
  backplot({ text, feed, rapid }) {
    return backplot_json(text, feed, rapid);
  },
  // A start point or tab's place: the loop under the click and its key (choices.js), or null.
  pickAt({ x, y, reach }) {
    return job ? JSON.parse(job.pick_at(x, y, reach)) : null;
  },
};

self.onmessage = async (e) => {
  const { id, op, args } = e.data;
  try {
    if (!ops[op]) throw new Error(`unknown operation ${op}`);
    // Progress messages go out while the (synchronous) wasm job runs; the page gets them at once.
    const progress = (p, transfer = []) => self.postMessage({ id, progress: p }, transfer);
    const result = await ops[op](args || {}, progress);
    // Big arrays move to the page instead of being copied.
    const transfer = [];
    if (result instanceof Uint8Array) transfer.push(result.buffer);
    if (result?.moves instanceof Float64Array) transfer.push(result.moves.buffer);
    if (result?.gcode instanceof Uint8Array) transfer.push(result.gcode.buffer);
    for (const k of ['heat', 'attached', 'lossOutlines', 'lossSquares']) if (result?.[k] instanceof Float64Array) transfer.push(result[k].buffer);
    self.postMessage({ id, ok: true, result }, transfer);
  } catch (err) {
    self.postMessage({ id, ok: false, error: (err && err.message) || String(err) });
  }
};
