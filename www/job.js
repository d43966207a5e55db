// kerfcam page: running a job — open files into the list, show one, read the settings, run the wasm
// Job in the engine worker, show its preview, summary and program, or say why not.
// Split out of main.js (issue 15 item 7).

import { CHOICES, MAX_DPR, app, messageOf, setStatus, showError, state, ui, $, keepChoices } from './app.js';
import { showLegend } from './backplot.js';
import { getLang, t } from './i18n.js';
import { layerDepths, layerOps, layerTools, showLayers } from './layers.js';
import { frameOf, rebaseStarts } from './origin.js';
import { draw, fitView, stageSize } from './view.js';

/** Adds the files to the list (kept in this browser) and shows the first of them. */
export async function openFiles(files) {
  files = [...(files || [])];
  if (app.sheet?.active) return app.sheet.addFiles(files); // Sheet mode: the files are parts to nest
  if (!files.length || !app.batch) return;
  let jobs;
  try {
    jobs = await app.batch.add(files);
  } catch (e) {
    return fail(t('error.read', { name: files.map((f) => f.name).join(', '), message: messageOf(e) }));
  }
  await showJob(jobs[0]);
}

/** Puts a job of the list on the preview (null: no file), with its own layers and start points. */
export async function showJob(job) {
  state.backplot = null;
  ui.backplotClose.hidden = true;
  ui.backplotInfo.hidden = true;
  showLegend(false);
  state.current = job;
  app.batch.setShown(job);
  app.inspector?.reset();
  state.name = job ? job.name : '';
  state.file = job ? job.file : null;
  state.layers = job ? job.layers : null;
  state.starts = job ? job.starts : [];
  app.tabsTool?.show(); // the placed tabs are the file's own
  app.sideTool?.show(); // and so are the profiles' sides
  // The order is the file's own (issue 14): a new file starts with the default order, not the last file's.
  if (job) ui.order.value = job.order || ui.order.querySelector('option[selected]')?.value || 'contour';
  app.updateOrderHelp();
  ui.fileName.textContent = state.name;
  app.origin.setPicking(false); // a point is picked on its own file
  if (!job) {
    state.runId++; // a run in flight is for a file that is gone
    fail('', 'waiting for a file');
    return;
  }
  await run({ fit: true });
}

/** The engine settings for the shown file, or for `job` of the list (its own layers and start points). */
export function readSettings(job = null) {
  const { values, problems } = app.numbers.read();
  const settings = { ...values };
  for (const [key, id] of Object.entries(CHOICES)) settings[key] = ui[id].value;
  settings.cut_open = ui.cutOpen.checked;
  settings.starts = job ? job.starts : state.starts;
  Object.assign(settings, app.posts ? app.posts.settings() : {});
  app.process?.settings(settings);
  app.materials?.settings(settings); // the cut-chart entry chosen: the engine sets kerf, feed, delay from it
  app.tabsTool?.settings(settings, job); // tabs placed by a click on the preview
  app.sideTool?.settings(settings, job); // router profiles' sides set by a click (issue 43)
  if (problems.length) throw Object.assign(new Error(problems.join(' ')), { invalid: true });
  const j = job || state.current;
  // null: the units the file states; a unit chosen beside the "units assumed" warning is the file's own.
  settings.units = ui.units.value || j?.units || null;
  Object.assign(settings, app.origin.settingsFor(j));
  settings.layers = job ? job.layers : state.layers; // null: the file's visible layers
  settings.layer_ops = layerOps(j); // each layer's operation chosen in the layers panel (issue 20)
  settings.layer_tools = layerTools(j); // a milling layer's listed tool (issue 43 §1), kept by tool.js when listed
  settings.layer_depths = layerDepths(j); // a milling layer's own depth (issue 43 §1), kept by tool.js when it mills
  app.tool?.settings(settings, !job); // a milling layer's tool (issue 43), shown when one mills
  return settings;
}

export async function run({ fit = false } = {}) {
  const sheet = app.sheet?.active ? app.sheet.cutting() : null; // Sheet mode: {k, key} of the nest's sheet shown
  if (app.sheet?.active && !sheet) {
    if (state.job) fail('', 'waiting for a file'); // no nest (any more): nothing to preview or download
    return;
  }
  if (!app.engineReady || (!state.file && !sheet)) return;
  let settings;
  try {
    settings = sheet ? app.sheet.settings(readSettings()) : readSettings();
  } catch (e) {
    // A value out of its range is marked on its field (numbers.js); the last good preview and
    // program stay, as they are, for the values they were made with.
    // A new file (or one whose preview is gone) has no good preview to keep: it says what to correct.
    if (e.invalid && state.job && state.shownJob === state.current) return;
    if (e.invalid) return fail(t('error.numbers', { list: messageOf(e) }));
    return fail(messageOf(e)); // no G-code for settings other than the ones shown
  }
  const key = JSON.stringify(settings) + (sheet ? sheet.key : '');
  if (!fit && key === state.settingsKey) return; // nothing changed
  state.settingsKey = key;
  settings.lang = getLang(); // messages only: the report carries every language, so a switch does not re-run
  const runId = ++state.runId;
  const current = state.current;
  setStatus('working');
  ui.cancel.hidden = false;
  showError('');
  app.progress.start();
  let result;
  try {
    // The file itself (a Blob handle) goes to the worker, which reads it: the page never copies a
    // 25 MB drawing on its main thread.
    const onStage = (p) => {
      if (runId !== state.runId) return;
      if (p.contours) showContours(p.contours);
      else app.progress.stage(p);
    };
    // A new drawing (fit): its contours are shown as soon as they are made, while the plan is made.
    const preview = fit && !sheet ? previewSize() : undefined;
    state.running = sheet
      ? app.engine.call('cutSheet', { k: sheet.k, settings }, onStage)
      : app.engine.call('run', { file: state.file, settings, preview }, onStage);
    result = await state.running;
  } catch (e) {
    if (runId !== state.runId) return; // a newer run took over
    app.progress.finish();
    ui.cancel.hidden = true;
    if (e.cancelled) {
      state.settingsKey = '';
      if (current) app.batch.failed(current, key, 'cancelled', true);
      return fail(t('error.cancelled', { name: state.name }), 'cancelled');
    }
    if (current) app.batch.failed(current, key, messageOf(e));
    return fail(t('error.run', { name: state.name, message: messageOf(e) }));
  } finally {
    if (runId === state.runId) state.running = null;
  }
  if (runId !== state.runId) return; // a newer file or setting came in meanwhile
  window.kerfcam.lastStages = app.progress.stages; // what each stage made, for tests and the curious
  app.progress.finish();
  ui.cancel.hidden = true;
  try {
    state.job = { bbox: sheet ? app.sheet.bbox(result.bbox) : result.bbox, moves: result.moves };
    state.backplot = null; // a new plan replaces a program being looked at
    ui.backplotClose.hidden = true;
    ui.backplotInfo.hidden = true;
    showLegend(false);
    const report = JSON.parse(result.report);
    state.gcode = result.gcode;
    window.kerfcam.lastReport = report;
    showSummary(report);
    app.process?.show(report);
    app.process?.setHeat(result.heat, result.attached); // the verification's raster, drawn over the preview
    // What the cuts take from the parts: marked on the preview and said on the Download button (issue 45 §3).
    app.losses?.set(report, { outlines: result.lossOutlines, squares: result.lossSquares }, state.name);
    state.quoting = app.cost?.update(); // the quote of this plan (cost.js), made after it is shown
    ui.comparison.replaceChildren();
    app.compareBox.hide();
    app.planLayer.setMoves(result.moves, { later: true }); // drawn over the plan's preview, by draw()
    ui.placeholder.hidden = true;
    // Fitted again to the plan (its leads and kerf reach a little beyond the contours' preview's fit).
    if (fit || !state.view) fitView();
    state.shownJob = current; // the job the preview and program are of
    app.tool?.showReport(report); // a V-bit engraving's depth and width, as the engine made them
    if (current) app.batch.result(current, key, report, state.gcode);
    await draw();
    // The program can be saved once its plan is on the preview: what is previewed is what is downloaded.
    ui.planningNote.hidden = true;
    for (const b of [ui.download, ui.fit, ui.compare, ui.setStart, ui.measure, ui.jobSheet, $('save-png'), $('save-svg')]) b.disabled = false;
    ui.clearStarts.disabled = !state.starts.length;
    setStatus('ready');
    // Start points and tabs are program coordinates: when the origin or the unit changed, they follow the drawing.
    const frame = frameOf(report);
    const moved = current && rebaseStarts(current.starts, current.startsFrame, frame);
    const movedTabs = current && rebaseStarts(current.tabsAt, current.startsFrame, frame);
    const movedSides = current && rebaseStarts(current.sidesAt, current.startsFrame, frame);
    if (current && report.origin) current.startsFrame = frame;
    if (moved || movedTabs || movedSides) {
      if (moved) state.starts = moved;
      if (movedTabs) current.tabsAt = movedTabs;
      if (movedSides) current.sidesAt = movedSides;
      keepChoices();
      return run();
    }
    if (!sheet) app.batch.schedule(); // the other files, with the same settings
  } catch (e) {
    fail(t('error.internal', { name: state.name, message: messageOf(e) }));
  }
}

/** The canvas as the engine renders it: CSS pixels and the device pixel ratio used. */
function previewSize() {
  const { width, height } = stageSize();
  return { width, height, dpr: Math.min(window.devicePixelRatio || 1, MAX_DPR) };
}

/**
 * The drawing's contours, rendered by the engine once they are made (rgba fitted in the canvas, view
 * [cx, cy, scale]): shown while the plan is made, with the status "planning…". The job shown before
 * (its program, its overlay) goes: nothing but the new file's contours is on the page until its plan is.
 */
function showContours({ rgba, view }) {
  const { width, height, dpr } = previewSize();
  const w = Math.max(1, Math.round(width * dpr));
  const h = Math.max(1, Math.round(height * dpr));
  if (rgba.length !== w * h * 4) return; // the canvas changed size meanwhile: the plan's preview follows
  dropJob();
  state.view = { cx: view[0], cy: view[1], scale: view[2] };
  ui.canvas.width = w;
  ui.canvas.height = h;
  ui.canvas.getContext('2d').putImageData(new ImageData(new Uint8ClampedArray(rgba.buffer, rgba.byteOffset, rgba.length), w, h), 0, 0);
  ui.placeholder.hidden = true;
  app.summary.clear(state.name);
  app.glance?.clear(state.name);
  state.layersOf = null;
  showLayers(null);
  ui.planningNote.hidden = false;
  setStatus('planning');
}

/** No job on the page any more: nothing to download, inspect or animate. */
function dropJob() {
  Object.assign(state, { job: null, gcode: null });
  window.kerfcam.lastReport = null;
  app.process?.show(null);
  app.losses?.set(null);
  app.cost?.update();
  for (const b of [ui.download, ui.fit, ui.compare, ui.setStart, ui.clearStarts, ui.measure, ui.jobSheet, $('save-png'), $('save-svg')]) b.disabled = true;
  app.inspector?.reset();
  ui.comparison.replaceChildren();
  app.compareBox?.hide();
  app.planLayer.setMoves(null);
  state.shownJob = null;
}

/** Drops the current job (so nothing stale can be downloaded) and shows `message`. */
export function fail(message, status = 'error') {
  app.progress?.finish();
  dropJob();
  state.settingsKey = '';
  ui.planningNote.hidden = true;
  ui.placeholder.hidden = !!state.file; // "Open or drop a DXF file" only with no file open: the error says the rest
  app.summary.clear(state.name);
  app.glance?.clear(state.name);
  // The layers of the same file stay, their choices in hand: a layer set to pocket with no depth fails
  // the run, and its row (its op, its own depth) is where the operator puts it right.
  if (!state.current || state.layersOf?.job !== state.current) {
    state.layersOf = null;
    showLayers(null);
  } else showLayers(state.layersOf.layers); // as now chosen: a pocket layer's own depth fields
  ui.canvas.getContext('2d').clearRect(0, 0, ui.canvas.width, ui.canvas.height);
  showError(message);
  setStatus(status);
}

export function showSummary(r) {
  app.summary.show(r, state.name);
  app.glance.show(r, state.name);
  showLayers(r.layers);
  state.layersOf = r.layers?.length ? { job: state.current, layers: r.layers } : null;
}
