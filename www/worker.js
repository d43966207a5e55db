// kerfcam engine worker: the wasm pipeline runs here, off the page's main thread, so the page stays
// responsive (scroll, pan, Cancel) while a big DXF is read, chained, offset and planned.
// Protocol: {id, op, args} in; {id, ok: true, result} or {id, ok: false, error} out.

import init, { Job, backplot_json, check_post, presets_json, version } from './pkg/kerfcam.js';

let job = null; // the current wasm Job

const ops = {
  async init() {
    await init();
    return version();
  },
  run({ bytes, settings }) {
    job?.free();
    job = null;
    job = new Job(bytes, settings);
    return { report: job.report_json(), gcode: job.gcode(), bbox: job.bbox(), moves: job.moves() };
  },
  render({ width, height, cx, cy, scale, dpr }) {
    if (!job) throw new Error('no job');
    return job.render(width, height, cx, cy, scale, dpr);
  },
  compare() {
    if (!job) throw new Error('no job');
    return job.compare_json();
  },
  presets() {
    return presets_json();
  },
  checkPost({ json, lang }) {
    return check_post(json, lang); // the message in the page's language
  },
  backplot({ text, feed, rapid }) {
    return backplot_json(text, feed, rapid);
  },
  contourAt({ x, y, reach }) {
    return job ? job.contour_at(x, y, reach) : -1;
  },
};

self.onmessage = async (e) => {
  const { id, op, args } = e.data;
  try {
    if (!ops[op]) throw new Error(`unknown operation ${op}`);
    const result = await ops[op](args || {});
    // Big arrays move to the page instead of being copied.
    const transfer = [];
    if (result instanceof Uint8Array) transfer.push(result.buffer);
    if (result?.moves instanceof Float64Array) transfer.push(result.moves.buffer);
    self.postMessage({ id, ok: true, result }, transfer);
  } catch (err) {
    self.postMessage({ id, ok: false, error: (err && err.message) || String(err) });
  }
};
