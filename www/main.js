// kerfcam page: open a DXF, run the wasm Job in the engine worker, show the preview and summary,
// download the G-code. The page's main thread never runs the pipeline: it stays responsive and can cancel.
// Everything that comes from the file or the report is shown with textContent: layer names and messages are data.

import { Batch, baseName as baseOf } from './batch.js';
import { download } from './download.js';
import { Engine } from './engine.js';
import { loadFiles } from './file-store.js';
import { Inspector } from './inspect.js';
import { CompareBox, Glance, keepFolds, orderHelp, reveal } from './layout.js';
import { NumberFields } from './numbers.js';
import { Origin, frameOf, rebaseStarts } from './origin.js';
import { applyTranslations, bindSwitch, fmtNumber, getLang, onLangChange, t } from './i18n.js';
import './page-strings.js';
import { PlanLayer, formatTime, movesToSvg, showComparison } from './plan.js';
import { Posts } from './posts.js';
import { Progress } from './progress.js';
import { fillSheet } from './sheet.js';
import { Summary } from './summary.js';
import { resetSettings, restoreSettings, saveSettings } from './settings-store.js';

const $ = (id) => document.getElementById(id);
const ui = {
  file: $('file-input'), fileName: $('file-name'), form: $('settings'),
  kerf: $('kerf'), tolerance: $('tolerance'), feed: $('feed'), units: $('units'),
  layers: $('layers'), layersBox: $('layers-box'), layerCount: $('layer-count'),
  layersAll: $('layers-all'), layersNone: $('layers-none'),
  healing: $('healing'), healingList: $('healing-list'), healingCount: $('healing-count'),
  canvas: $('preview'), stage: $('stage'), placeholder: $('placeholder'),
  summary: $('summary'), warnings: $('warnings'), warningCount: $('warning-count'),
  download: $('download'), fit: $('fit'), error: $('error'), status: $('status'), version: $('version'),
  rapid: $('rapid'), pierceDelay: $('pierce-delay'), planForm: $('plan-settings'),
  leadOuter: $('lead-outer'), leadHole: $('lead-hole'), overcut: $('overcut'), maxLink: $('max-link'),
  order: $('order'), eulerMode: $('euler-mode'), lead: $('lead'), outerDir: $('outer-dir'), holeDir: $('hole-dir'),
  cutOpen: $('cut-open'), setStart: $('set-start'), clearStarts: $('clear-starts'), startHint: $('start-hint'),
  compare: $('compare'), comparison: $('comparison'), cancel: $('cancel'),
  backplotInput: $('backplot-input'), backplotClose: $('backplot-close'), backplotInfo: $('backplot-info'),
  overlay: $('overlay'), play: $('play'), speed: $('speed'), scrub: $('scrub'), animTime: $('anim-time'),
  jobs: $('jobs'), jobCount: $('job-count'), downloadAll: $('download-all'), clearFiles: $('clear-files'), jobMessage: $('job-message'),
  progress: $('progress'), progressBar: $('progress-bar'), progressText: $('progress-text'),
  measure: $('measure'), tip: $('inspect-tip'), readout: $('readout'),
  notes: $('notes'), notesList: $('notes-list'), notesCount: $('notes-count'),
  origin: $('origin'), pickOrigin: $('pick-origin'), originHint: $('origin-hint'), originRow: $('origin-row'),
  jobSheet: $('job-sheet'), sheetView: $('sheet-view'), sheet: $('sheet'), sheetPrint: $('sheet-print'), sheetClose: $('sheet-close'),
};
// Choice fields: settings key → select.
const CHOICES = { order: 'order', euler_mode: 'eulerMode', lead: 'lead', outer_dir: 'outerDir', hole_dir: 'holeDir' };
const MAX_DPR = 2; // more device pixels cost render time for no visible gain

let engine = null; // the worker running the wasm pipeline
let engineReady = false;
// view = { cx, cy, scale }: the mm point at the canvas centre and CSS pixels per mm (Y up).
// layers: the names to cut, or null for the file's visible layers (reset for each new file).
// layerNames: the names of the layer list as shown (index = the checkbox's data-index).
// current: the batch job on the preview (its bytes, name, layers and start points are copied here).
const state = {
  job: null /* { bbox, moves } of the shown job */, file: null /* Blob */, name: '', settingsKey: '', gcode: null /* UTF-8 */, view: null, runId: 0,
  layers: null, layerNames: null, starts: [], picking: false, current: null, running: null,
};
let planLayer = null; // the overlay: sequence numbers and the animation
let posts = null; // the post menu and editor
let batch = null; // the list of files (jobs)
let progress = null; // the stage progress bar
let inspector = null; // hover inspect and the measure tool
let numbers = null; // the number fields: parsed the local way, checked against their ranges
let summary = null; // the summary, warnings and repairs
let origin = null; // the program origin setting, its picking and the origin and scale marks
let glance = null; // the job at a glance, over the preview
let compareBox = null; // the orders compared, under the preview
let updateOrderHelp = () => {}; // the order's explanation, after a script sets the order
const utf8 = new TextDecoder();
window.kerfcam = { lastReport: null };
// The shown program as text, decoded when asked (the page itself keeps and saves the bytes).
Object.defineProperty(window.kerfcam, 'lastGcode', { get: () => (state.gcode ? utf8.decode(state.gcode) : null) });

const messageOf = (e) => (e && e.message) || String(e);

// Status states (data-state, for scripts and tests) → their text key.
const STATUS = {
  loading: 'status.loading', 'waiting for a file': 'status.waiting', working: 'status.working', ready: 'status.ready',
  error: 'status.error', cancelled: 'status.cancelled', backplot: 'status.backplot',
};
function setStatus(state) {
  ui.status.textContent = STATUS[state] ? t(STATUS[state]) : state;
  ui.status.dataset.state = state;
}

function showError(message) {
  ui.error.textContent = message;
  ui.error.hidden = !message;
}

function el(tag, text, attrs = {}) {
  const node = Object.assign(document.createElement(tag), attrs);
  node.textContent = text;
  return node;
}

// --- running a job ---------------------------------------------------------------------------------

/** Adds the files to the list (kept in this browser) and shows the first of them. */
async function openFiles(files) {
  files = [...(files || [])];
  if (!files.length || !batch) return;
  let jobs;
  try {
    jobs = await batch.add(files);
  } catch (e) {
    return fail(t('error.read', { name: files.map((f) => f.name).join(', '), message: messageOf(e) }));
  }
  await showJob(jobs[0]);
}

/** Puts a job of the list on the preview (null: no file), with its own layers and start points. */
async function showJob(job) {
  state.backplot = null;
  ui.backplotClose.hidden = true;
  ui.backplotInfo.hidden = true;
  showLegend(false);
  state.current = job;
  batch.setShown(job);
  inspector?.reset();
  state.name = job ? job.name : '';
  state.file = job ? job.file : null;
  state.layers = job ? job.layers : null;
  state.starts = job ? job.starts : [];
  // The order is the file's own (issue 14): a new file starts with the default order, not the last file's.
  if (job) ui.order.value = job.order || ui.order.querySelector('option[selected]')?.value || 'contour';
  updateOrderHelp();
  ui.fileName.textContent = state.name;
  origin.setPicking(false); // a point is picked on its own file
  if (!job) {
    state.runId++; // a run in flight is for a file that is gone
    fail('', 'waiting for a file');
    return;
  }
  await run({ fit: true });
}

/** The shown file's layer choices and start points are kept with it. */
function keepChoices() {
  if (!state.current) return;
  state.current.layers = state.layers;
  state.current.starts = state.starts;
  batch.keep(state.current);
}

/** The engine settings for the shown file, or for `job` of the list (its own layers and start points). */
function readSettings(job = null) {
  const { values, problems } = numbers.read();
  const settings = { ...values };
  for (const [key, id] of Object.entries(CHOICES)) settings[key] = ui[id].value;
  settings.cut_open = ui.cutOpen.checked;
  settings.starts = job ? job.starts : state.starts;
  Object.assign(settings, posts ? posts.settings() : {});
  if (problems.length) throw Object.assign(new Error(problems.join(' ')), { invalid: true });
  const j = job || state.current;
  // null: the units the file states; a unit chosen beside the "units assumed" warning is the file's own.
  settings.units = ui.units.value || j?.units || null;
  Object.assign(settings, origin.settingsFor(j));
  settings.layers = job ? job.layers : state.layers; // null: the file's visible layers
  return settings;
}

async function run({ fit = false } = {}) {
  if (!engineReady || !state.file) return;
  let settings;
  try {
    settings = readSettings();
  } catch (e) {
    // A value out of its range is marked on its field (numbers.js); the last good preview and
    // program stay, as they are, for the values they were made with.
    // A new file (or one whose preview is gone) has no good preview to keep: it says what to correct.
    if (e.invalid && state.job && state.shownJob === state.current) return;
    if (e.invalid) return fail(t('error.numbers', { list: messageOf(e) }));
    return fail(messageOf(e)); // no G-code for settings other than the ones shown
  }
  const key = JSON.stringify(settings);
  if (!fit && key === state.settingsKey) return; // nothing changed
  state.settingsKey = key;
  settings.lang = getLang(); // messages only: the report carries every language, so a switch does not re-run
  const runId = ++state.runId;
  const current = state.current;
  setStatus('working');
  ui.cancel.hidden = false;
  showError('');
  progress.start();
  let result;
  try {
    // The file itself (a Blob handle) goes to the worker, which reads it: the page never copies a
    // 25 MB drawing on its main thread.
    const onStage = (p) => runId === state.runId && progress.stage(p);
    state.running = engine.call('run', { file: state.file, settings }, onStage);
    result = await state.running;
  } catch (e) {
    if (runId !== state.runId) return; // a newer run took over
    progress.finish();
    ui.cancel.hidden = true;
    if (e.cancelled) {
      state.settingsKey = '';
      if (current) batch.failed(current, key, 'cancelled', true);
      return fail(t('error.cancelled', { name: state.name }), 'cancelled');
    }
    if (current) batch.failed(current, key, messageOf(e));
    return fail(t('error.run', { name: state.name, message: messageOf(e) }));
  } finally {
    if (runId === state.runId) state.running = null;
  }
  if (runId !== state.runId) return; // a newer file or setting came in meanwhile
  window.kerfcam.lastStages = progress.stages; // what each stage made, for tests and the curious
  progress.finish();
  ui.cancel.hidden = true;
  try {
    state.job = { bbox: result.bbox, moves: result.moves };
    state.backplot = null; // a new plan replaces a program being looked at
    ui.backplotClose.hidden = true;
    ui.backplotInfo.hidden = true;
    showLegend(false);
    const report = JSON.parse(result.report);
    state.gcode = result.gcode;
    window.kerfcam.lastReport = report;
    showSummary(report);
    for (const b of [ui.download, ui.fit, ui.compare, ui.setStart, ui.measure, ui.jobSheet, $('save-png'), $('save-svg')]) b.disabled = false;
    ui.clearStarts.disabled = !state.starts.length;
    ui.comparison.replaceChildren();
    compareBox.hide();
    planLayer.setMoves(result.moves);
    ui.placeholder.hidden = true;
    if (fit || !state.view) fitView();
    state.shownJob = current; // the job the preview and program are of
    if (current) batch.result(current, key, report, state.gcode);
    await draw();
    setStatus('ready');
    // Start points are program coordinates: when the origin or the unit changed, they follow the drawing.
    const moved = current && rebaseStarts(current.starts, current.startsFrame, frameOf(report));
    if (current && report.origin) current.startsFrame = frameOf(report);
    if (moved) {
      state.starts = moved;
      keepChoices();
      return run();
    }
    batch.schedule(); // the other files, with the same settings
  } catch (e) {
    fail(t('error.internal', { name: state.name, message: messageOf(e) }));
  }
}

/** Drops the current job (so nothing stale can be downloaded) and shows `message`. */
function fail(message, status = 'error') {
  progress?.finish();
  Object.assign(state, { job: null, gcode: null, settingsKey: '' });
  window.kerfcam.lastReport = null;
  for (const b of [ui.download, ui.fit, ui.compare, ui.setStart, ui.clearStarts, ui.measure, ui.jobSheet, $('save-png'), $('save-svg')]) b.disabled = true;
  inspector?.reset();
  ui.comparison.replaceChildren();
  compareBox?.hide();
  planLayer.setMoves(null);
  state.shownJob = null;
  ui.placeholder.hidden = !!state.file; // "Open or drop a DXF file" only with no file open: the error says the rest
  summary.clear(state.name);
  glance?.clear(state.name);
  showLayers(null);
  ui.canvas.getContext('2d').clearRect(0, 0, ui.canvas.width, ui.canvas.height);
  showError(message);
  setStatus(status);
}

// --- summary (summary.js) ---------------------------------------------------------------------------

function showSummary(r) {
  summary.show(r, state.name);
  glance.show(r, state.name);
  showLayers(r.layers);
}

// --- layers ----------------------------------------------------------------------------------------

// AutoCAD colour index 1..7; everything else (0 = BYBLOCK, 256 = BYLAYER, 8..255) is shown grey.
const ACI = ['', '#e02020', '#e8c800', '#22a83a', '#20b8c8', '#2050e0', '#c020c0', '#1d2329'];
const aciColour = (c) => ACI[Math.abs(Number(c))] || '#9aa5b1'; // negative = layer off, same colour

/**
 * Shows the report's layers as checkboxes. The list is rebuilt only when the names change, so
 * toggling a layer keeps the keyboard focus on its checkbox. Names are file data: textContent only.
 */
function showLayers(layers) {
  layers = Array.isArray(layers) ? layers : null;
  ui.layersBox.disabled = !layers?.length;
  if (!layers?.length) {
    state.layerNames = null;
    ui.layerCount.textContent = '';
    ui.layers.replaceChildren(el('li', layers ? t('layers.none-in-file') : t('layers.no-file'), { className: 'muted small' }));
    return;
  }
  const names = layers.map((l) => String(l.name));
  const same = state.layerNames && names.length === state.layerNames.length && names.every((n, i) => n === state.layerNames[i]);
  if (!same) {
    state.layerNames = names;
    ui.layers.replaceChildren(...layers.map((l, i) => layerRow(l, i)));
  }
  layers.forEach((l, i) => {
    const li = ui.layers.children[i];
    li.querySelector('input').checked = !!l.selected;
    li.classList.toggle('empty', !l.entities);
    li.querySelector('.layer-count').firstChild.textContent = String(l.entities ?? 0);
    li.querySelector('.layer-note').textContent = l.visible === false ? t('layers.off') : '';
    li.querySelector('.layer-count .sr-only').textContent = t('layers.entities');
    const unnamed = li.querySelector('.layer-name.muted');
    if (unnamed) unnamed.textContent = t('layers.no-name');
  });
  const selected = layers.filter((l) => l.selected).length;
  ui.layerCount.textContent = t('layers.count', { selected, total: layers.length });
}

function layerRow(l, i) {
  const box = el('input', '', { type: 'checkbox' });
  box.dataset.index = String(i);
  const swatch = el('span', '', { className: 'layer-swatch' });
  swatch.style.background = aciColour(l.color);
  swatch.setAttribute('aria-hidden', 'true');
  const name = String(l.name);
  const nameEl = name ? el('span', name, { className: 'layer-name' }) : el('span', t('layers.no-name'), { className: 'layer-name muted' });
  const count = el('span', '', { className: 'layer-count' });
  count.append(document.createTextNode(''), el('span', t('layers.entities'), { className: 'sr-only' }));
  const label = el('label', '');
  label.append(box, swatch, nameEl, el('span', '', { className: 'layer-note muted small' }), count);
  const li = el('li', '', { className: 'layer' });
  li.dataset.index = String(i);
  li.append(label);
  return li;
}

/** Cuts the checked layers (or `names`) of the current file. */
function selectLayers(names) {
  if (!state.layerNames) return;
  state.layers = names ?? [...ui.layers.querySelectorAll('input[type=checkbox]')]
    .filter((b) => b.checked)
    .map((b) => state.layerNames[Number(b.dataset.index)]);
  keepChoices();
  run();
}

// --- preview ---------------------------------------------------------------------------------------

const stageSize = () => ui.stage.getBoundingClientRect();

function fitView() {
  const [x0, y0, x1, y1] = (state.backplot || state.job).bbox;
  const { width, height } = stageSize();
  const w = Math.max(x1 - x0, 1e-3);
  const h = Math.max(y1 - y0, 1e-3);
  state.view = [x0, y0, x1, y1].every(Number.isFinite)
    ? { cx: (x0 + x1) / 2, cy: (y0 + y1) / 2, scale: Math.min(width / (w * 1.1), height / (h * 1.1)) }
    : { cx: 0, cy: 0, scale: 1 };
}

// One render in flight at a time; views asked for meanwhile collapse into one more render.
let rendering = null;
let renderAgain = false;

async function draw() {
  if (state.backplot && state.view) {
    // A program re-read from its text: nothing but the overlay's moves.
    const { width, height } = stageSize();
    const dpr = Math.min(window.devicePixelRatio || 1, MAX_DPR);
    ui.canvas.width = Math.max(1, Math.round(width * dpr));
    ui.canvas.height = Math.max(1, Math.round(height * dpr));
    const ctx = ui.canvas.getContext('2d');
    ctx.fillStyle = '#fff';
    ctx.fillRect(0, 0, ui.canvas.width, ui.canvas.height);
    planLayer.draw();
    return;
  }
  if (!state.job || !state.view) return;
  if (rendering) {
    renderAgain = true;
    return rendering;
  }
  rendering = (async () => {
    do {
      renderAgain = false;
      const dpr = Math.min(window.devicePixelRatio || 1, MAX_DPR);
      const { width, height } = stageSize();
      const w = Math.max(1, Math.round(width * dpr));
      const h = Math.max(1, Math.round(height * dpr));
      const { cx, cy, scale } = state.view;
      let rgba;
      window.kerfcam.renders = (window.kerfcam.renders || 0) + 1; // engine renders asked for (tests count them)
      try {
        rgba = await engine.call('render', { width: w, height: h, cx, cy, scale: scale * dpr, dpr });
      } catch (e) {
        if (!e.cancelled && state.job) showError(t('error.draw', { message: messageOf(e) }));
        return;
      }
      if (!state.job) return;
      if (ui.canvas.width !== w) ui.canvas.width = w;
      if (ui.canvas.height !== h) ui.canvas.height = h;
      const pixels = new Uint8ClampedArray(rgba.buffer, rgba.byteOffset, rgba.byteLength);
      ui.canvas.getContext('2d').putImageData(new ImageData(pixels, w, h), 0, 0);
      planLayer.draw();
    } while (renderAgain);
  })();
  try {
    await rendering;
  } finally {
    rendering = null;
  }
}

/** Centres the preview on (x, y) mm, zoomed in to about 40 mm across (never out). */
function zoomTo(x, y) {
  if (!state.view || !Number.isFinite(x) || !Number.isFinite(y)) return;
  const { width, height } = stageSize();
  const scale = Math.max(state.view.scale, Math.min(width, height) / 40);
  state.view = { cx: x, cy: y, scale: Math.min(scale, 1e4) };
  requestDraw();
  ui.canvas.focus();
}

/** The preview as the user sees it: the plan raster with the overlay (numbers, animation) on top. */
function composite() {
  const out = document.createElement('canvas');
  out.width = ui.canvas.width;
  out.height = ui.canvas.height;
  const ctx = out.getContext('2d');
  ctx.drawImage(ui.canvas, 0, 0);
  ctx.drawImage(ui.overlay, 0, 0, out.width, out.height);
  return out;
}

/** The preview as the user sees it (plan raster and overlay) as a PNG download. */
function savePicture() {
  if (!state.job && !state.backplot) return;
  composite().toBlob((blob) => {
    if (!blob) return showError(t('error.picture'));
    download(blob, `${baseName()}.png`);
  }, 'image/png');
}

/** The job sheet: the whole plan fitted, with its numbers, and the job's figures, ready to print. */
async function openSheet() {
  if (!state.job) return;
  const view = state.view;
  fitView();
  await draw();
  const picture = composite().toDataURL('image/png');
  state.view = view; // back to what the user was looking at
  requestDraw();
  let settings = {};
  try {
    settings = readSettings();
  } catch {
    // the figures shown are those of the shown job anyway
  }
  state.sheet = {
    name: state.name, report: window.kerfcam.lastReport, moves: state.job.moves, settings, picture, formatTime,
    unitsChosen: !!state.current?.units && !ui.units.value,
    post: $('post').selectedOptions[0]?.textContent || '',
  };
  fillSheet(ui.sheet, state.sheet);
  ui.sheetView.hidden = false;
  document.body.classList.add('sheet-open');
  ui.sheetPrint.focus();
}

function closeSheet() {
  ui.sheetView.hidden = true;
  document.body.classList.remove('sheet-open');
  ui.jobSheet.focus();
}

/** The program as an SVG drawing in mm (the same moves as the G-code). */
function saveSvg() {
  const moves = (state.backplot || state.job)?.moves;
  if (!moves) return;
  download(new Blob([movesToSvg(moves)], { type: 'image/svg+xml' }), `${baseName()}.svg`);
}

/** The open file's name without its extension, for the files the page saves. */
const baseName = () => baseOf(state.name);

/** Leaves the backplot and shows the current job's plan again. */
function closeBackplot() {
  if (!state.backplot) return;
  state.backplot = null;
  ui.backplotClose.hidden = true;
  ui.backplotInfo.hidden = true;
  showLegend(false);
  // The status the plan had (it stayed at "backplot"): ready, or the error or wait it was in.
  setStatus(state.job ? 'ready' : state.statusBefore || 'waiting for a file');
  planLayer.setMoves(state.job ? state.job.moves : null);
  if (state.job) fitView();
  else ui.placeholder.hidden = !!state.file;
  draw();
}

/** The plan's legend, or the backplot's (a program re-read: cuts, feeds with the torch off, rapids). */
function showLegend(backplot) {
  $('legend').hidden = backplot;
  $('legend-backplot').hidden = !backplot;
}

/** The view for the overlay: the same mapping as the preview's pixels. */
function overlayView() {
  if (!state.view) return null;
  const { width, height } = stageSize();
  return { ...state.view, width, height, dpr: Math.min(window.devicePixelRatio || 1, MAX_DPR) };
}

/** The CSS pixel of the canvas where the drawing point (x, y) mm is shown (for tests and tools). */
window.kerfcam.screenOf = (x, y) => {
  const { width, height } = stageSize();
  const v = state.view;
  return v ? [width / 2 + (x - v.cx) * v.scale, height / 2 - (y - v.cy) * v.scale] : null;
};

/** Puts the drawing point (x, y) mm at the centre of the preview, at the same zoom (for tests and tools). */
window.kerfcam.centreOn = (x, y) => {
  if (!state.view) return;
  state.view = { ...state.view, cx: x, cy: y };
  requestDraw();
};

/** The drawing point (mm) under a CSS pixel of the canvas. */
function pointAt(px, py) {
  const { width, height } = stageSize();
  const v = state.view;
  return [v.cx + (px - width / 2) / v.scale, v.cy - (py - height / 2) / v.scale];
}

function setPicking(on) {
  if (on && inspector?.measuring) inspector.setMeasuring(false);
  if (on && origin?.picking) origin.setPicking(false);
  state.picking = on;
  ui.setStart.setAttribute('aria-pressed', String(on));
  ui.startHint.hidden = !on;
  ui.stage.classList.toggle('picking', on);
}

let drawQueued = false;
function requestDraw() {
  if (drawQueued) return;
  drawQueued = true;
  requestAnimationFrame(() => {
    drawQueued = false;
    draw();
  });
}

/** Zooms by `factor` keeping the mm point under the CSS pixel (px, py) where it is. */
function zoomAt(factor, px, py) {
  const v = state.view;
  if (!v) return;
  const { width, height } = stageSize();
  const scale = Math.min(Math.max(v.scale * factor, 1e-4), 1e4);
  const dx = px - width / 2;
  const dy = py - height / 2;
  state.view = { cx: v.cx + dx / v.scale - dx / scale, cy: v.cy - dy / v.scale + dy / scale, scale };
  requestDraw();
}

function pan(dx, dy) {
  if (!state.view) return;
  state.view.cx -= dx / state.view.scale;
  state.view.cy += dy / state.view.scale;
  requestDraw();
}

// --- wiring ----------------------------------------------------------------------------------------

function wire() {
  ui.file.addEventListener('change', () => {
    openFiles(ui.file.files);
    ui.file.value = ''; // picking the same file again adds it again
  });

  let typing; // re-run shortly after typing stops, at once when a value is committed
  const rerun = (delay) => {
    clearTimeout(typing);
    typing = setTimeout(run, delay);
  };
  // Cancel also drops a re-run still waiting for typing to stop: it would start the job again
  // right after the operator stopped it.
  ui.cancel.addEventListener('click', () => {
    clearTimeout(typing);
    engine?.cancel();
  });
  for (const input of Object.values(numbers.inputs)) {
    input.addEventListener('input', () => rerun(400));
    input.addEventListener('change', () => rerun(0));
  }
  ui.form.addEventListener('submit', (e) => e.preventDefault());
  ui.planForm.addEventListener('submit', (e) => e.preventDefault());
  for (const select of [...Object.values(CHOICES).map((id) => ui[id]), ui.cutOpen]) {
    select.addEventListener('change', () => rerun(0));
  }
  ui.order.addEventListener('change', () => { if (state.current) state.current.order = ui.order.value; });
  ui.compare.addEventListener('click', async () => {
    if (!state.job) return;
    try {
      setStatus('working');
      const rows = JSON.parse(await engine.call('compare'));
      setStatus('ready');
      window.kerfcam.lastComparison = rows;
      showComparison(ui.comparison, rows);
      compareBox.shown();
    } catch (e) {
      showError(t('error.compare', { message: messageOf(e) }));
    }
  });
  ui.setStart.addEventListener('click', () => setPicking(!state.picking));
  $('save-png').addEventListener('click', savePicture);
  ui.jobSheet.addEventListener('click', () => openSheet());
  ui.sheetPrint.addEventListener('click', () => window.print());
  ui.sheetClose.addEventListener('click', closeSheet);

  $('save-svg').addEventListener('click', saveSvg);
  ui.backplotInput.addEventListener('change', async () => {
    const file = ui.backplotInput.files[0];
    ui.backplotInput.value = '';
    if (!file || !engineReady) return;
    try {
      setStatus('working');
      const text = await file.text();
      const b = JSON.parse(await engine.call('backplot', {
        text, feed: numbers.value('feed') || 2000, rapid: numbers.value('rapid') || 10000,
      }));
      inspector.reset(); // no inspect text nor measure of the plan over a program being looked at
      if (!state.backplot) state.statusBefore = ui.status.dataset.state; // what "Back to the plan" puts back
      state.backplot = { bbox: b.bbox, moves: new Float64Array(b.moves), name: file.name };
      window.kerfcam.lastBackplot = { name: file.name, moves: b.moves.length / 7, warnings: b.warnings };
      planLayer.setMoves(state.backplot.moves, { showAll: true });
      state.backplot.info = { name: file.name, moves: b.moves.length / 7, warnings: b.warnings };
      showBackplotInfo();
      showLegend(true);
      ui.backplotInfo.hidden = false;
      ui.backplotClose.hidden = false;
      ui.placeholder.hidden = true;
      fitView();
      await draw();
      setStatus('backplot');
    } catch (e) {
      showError(t('error.backplot', { name: file.name, message: messageOf(e) }));
      setStatus('error');
    }
  });
  ui.backplotClose.addEventListener('click', () => closeBackplot());
  ui.clearStarts.addEventListener('click', () => {
    state.starts = [];
    keepChoices();
    run();
  });
  ui.origin.addEventListener('change', () => {
    clearTimeout(typing);
    run({ fit: true }); // everything moves: fit it again
  });
  ui.units.addEventListener('change', () => {
    clearTimeout(typing);
    run({ fit: true }); // a new unit rescales the drawing: fit it again
  });
  ui.layers.addEventListener('change', (e) => {
    if (e.target.matches('input[type=checkbox]')) selectLayers();
  });
  ui.layersAll.addEventListener('click', () => selectLayers(state.layerNames ? [...state.layerNames] : null));
  ui.layersNone.addEventListener('click', () => selectLayers([]));

  const dragging = (on) => document.body.classList.toggle('dragging', on);
  document.addEventListener('dragover', (e) => {
    e.preventDefault();
    dragging(true);
  });
  document.addEventListener('dragleave', (e) => {
    if (!e.relatedTarget) dragging(false); // left the window
  });
  document.addEventListener('drop', (e) => {
    e.preventDefault();
    dragging(false);
    openFiles(e.dataTransfer?.files);
  });

  ui.download.addEventListener('click', () => {
    if (!state.job) return;
    download(new Blob([state.gcode], { type: 'text/plain' }), `${baseName()}.ngc`);
  });

  ui.fit.addEventListener('click', () => {
    fitView();
    requestDraw();
  });

  let drag = null;
  ui.canvas.addEventListener('pointerdown', async (e) => {
    if (e.button !== 0) return;
    if (origin.picking && state.job) {
      const rect = ui.canvas.getBoundingClientRect();
      await origin.pick(...pointAt(e.clientX - rect.left, e.clientY - rect.top));
      return;
    }
    if (state.picking && state.job) {
      const rect = ui.canvas.getBoundingClientRect();
      const [x, y] = pointAt(e.clientX - rect.left, e.clientY - rect.top);
      const contour = await engine.call('contourAt', { x, y, reach: 12 / state.view.scale });
      if (contour >= 0) {
        state.starts = [...state.starts.filter((s) => s[0] !== contour), [contour, x, y]];
        if (state.current) state.current.startsFrame = frameOf(window.kerfcam.lastReport); // their frame
        keepChoices();
        setPicking(false);
        run();
      }
      return;
    }
    drag = { x: e.clientX, y: e.clientY, x0: e.clientX, y0: e.clientY };
    ui.canvas.setPointerCapture(e.pointerId);
  });
  ui.canvas.addEventListener('pointermove', (e) => {
    if (!drag) return;
    pan(e.clientX - drag.x, e.clientY - drag.y);
    Object.assign(drag, { x: e.clientX, y: e.clientY });
  });
  ui.canvas.addEventListener('pointerup', (e) => {
    // A press that did not move is a click: a measuring point, or inspect what is there.
    if (drag && Math.hypot(e.clientX - drag.x0, e.clientY - drag.y0) < 4) inspector.click(e).catch(() => {});
    drag = null;
  });
  ui.canvas.addEventListener('pointercancel', () => (drag = null));
  ui.canvas.addEventListener('wheel', (e) => {
    e.preventDefault();
    const unit = [1, 16, 400][e.deltaMode] ?? 1; // pixels, lines, pages
    const rect = ui.canvas.getBoundingClientRect();
    zoomAt(Math.exp(-e.deltaY * unit * 0.0015), e.clientX - rect.left, e.clientY - rect.top);
  }, { passive: false });
  for (const type of ['focus', 'blur']) ui.canvas.addEventListener(type, () => planLayer.draw()); // the keyboard's aim
  ui.canvas.addEventListener('keydown', (e) => {
    const keys = {
      ArrowLeft: () => pan(50, 0), ArrowRight: () => pan(-50, 0), ArrowUp: () => pan(0, 50), ArrowDown: () => pan(0, -50),
      // Inspect, measure or pick the origin at the cross in the middle.
      Enter: () => (origin.picking
        ? origin.pick(...pointAt(stageSize().width / 2, stageSize().height / 2)).catch(() => {})
        : inspector.atCentre().catch(() => {})),
    };
    if (!keys[e.key] || !state.job) return;
    e.preventDefault();
    keys[e.key]();
  });
  // Shortcuts anywhere on the page except while typing in a field: F fit, + and - zoom, Space play,
  // M measure, Escape leaves the measure and start-point tools.
  document.addEventListener('keydown', (e) => {
    if (!ui.sheetView.hidden) {
      if (e.key === 'Escape') closeSheet(); // the sheet covers the app: no other shortcut
      return;
    }
    if (e.ctrlKey || e.metaKey || e.altKey || e.target.closest?.('input, select, textarea, dialog, [contenteditable]')) return;
    if (e.key === ' ' && e.target.closest?.('button, a, summary')) return; // Space presses the focused button
    const { width, height } = stageSize();
    const zoom = (f) => zoomAt(f, width / 2, height / 2);
    const keys = {
      '+': () => zoom(1.25), '=': () => zoom(1.25), '-': () => zoom(0.8), f: () => ui.fit.click(), F: () => ui.fit.click(),
      ' ': () => planLayer.toggle(), m: () => ui.measure.click(), M: () => ui.measure.click(),
      Escape: () => {
        if (inspector.measuring) inspector.setMeasuring(false);
        if (state.picking) setPicking(false);
        if (origin.picking) origin.setPicking(false);
      },
    };
    if (!keys[e.key] || !state.job) return;
    e.preventDefault();
    keys[e.key]();
  });
  new ResizeObserver(requestDraw).observe(ui.stage);
}

/** What the backplot re-read, in the current language. */
function showBackplotInfo() {
  const info = state.backplot?.info;
  if (!info) return;
  const w = info.warnings[0];
  ui.backplotInfo.textContent = t('backplot.info', { name: info.name, moves: fmtNumber(info.moves) }) +
    (w ? t('backplot.not-understood', {
      count: info.warnings.length, line: w.line, message: w.messages?.[getLang()] ?? w.message,
    }) : '');
}

/** After a language switch: everything the page wrote itself, again, from what it kept (no re-run). */
function retranslate() {
  setStatus(ui.status.dataset.state);
  const report = window.kerfcam.lastReport;
  if (report) showSummary(report);
  else if (!state.job) {
    summary?.clear(state.name);
    glance?.clear(state.name);
  }
  origin?.update();
  planLayer?.draw(); // the overlay's own words (the note on numbers left out)
  if (window.kerfcam.lastComparison && state.job && ui.comparison.rows.length) showComparison(ui.comparison, window.kerfcam.lastComparison);
  showBackplotInfo();
}

/** Offline: the service worker keeps a copy of the app (served over http only; file:// has none). */
function registerOffline() {
  if (!('serviceWorker' in navigator) || !location.protocol.startsWith('http')) return;
  navigator.serviceWorker.register('./sw.js').catch((e) => console.warn(`offline copy unavailable: ${messageOf(e)}`));
}

// The forms whose values survive a reload, and the controls outside them.
const kept = () => [[ui.form, ui.planForm], [$('post'), ui.speed]];

async function start() {
  registerOffline();
  applyTranslations(document);
  setStatus('loading');
  bindSwitch($('lang'));
  onLangChange(retranslate);
  restoreSettings(...kept());
  numbers = new NumberFields([ui.form, ui.planForm]);
  numbers.relocalise(); // the kept or default values with this language's decimal sign
  for (const f of [ui.form, ui.planForm]) f.addEventListener('change', () => saveSettings(...kept()));
  for (const c of [$('post'), ui.speed]) c.addEventListener('change', () => saveSettings(...kept()));
  $('reset-settings').addEventListener('click', () => {
    resetSettings(...kept());
    numbers.relocalise();
    updateOrderHelp();
    ui.origin.dispatchEvent(new Event('change')); // stops picking a point when the origin goes back to automatic
    ui.speed.dispatchEvent(new Event('change'));
    run();
  });
  keepFolds(document.querySelector('.side'));
  updateOrderHelp = orderHelp(ui.order, $('order-help'));
  glance = new Glance($('glance'), () => reveal($('panel-summary'), ui.warnings));
  compareBox = new CompareBox({ box: $('compare-box'), table: ui.comparison, close: $('compare-close'), button: ui.compare });
  planLayer = new PlanLayer(
    { overlay: ui.overlay, play: ui.play, speed: ui.speed, scrub: ui.scrub, time: ui.animTime },
    overlayView,
  );
  progress = new Progress({ box: ui.progress, bar: ui.progressBar, text: ui.progressText });
  inspector = new Inspector(
    { canvas: ui.canvas, tip: ui.tip, readout: ui.readout, measureButton: ui.measure },
    {
      engine: { call: (...a) => engine.call(...a) },
      pointAt,
      scale: () => state.view?.scale || 1,
      planLayer,
      active: () => !!state.job && !state.backplot && !state.picking && !origin?.picking && engineReady,
    },
  );
  window.kerfcam.lastMeasure = () => inspector.result ?? null;
  window.kerfcam.inspected = () => inspector.pinned ?? null;
  window.kerfcam.labelStats = () => planLayer.labelStats ?? null; // the sequence numbers drawn (level of detail)
  summary = new Summary(
    {
      summary: ui.summary, warnings: ui.warnings, warningCount: ui.warningCount, notes: ui.notes, notesList: ui.notesList,
      notesCount: ui.notesCount, healing: ui.healing, healingList: ui.healingList, healingCount: ui.healingCount,
    },
    {
      zoomTo,
      units: () => ({ chosen: state.current?.units ?? null, global: ui.units.value }),
      onUnits: (unit) => {
        if (!state.current) return;
        state.current.units = unit; // kept with the file: it opens in this unit next time
        keepChoices();
        run({ fit: true });
      },
    },
  );
  origin = new Origin(
    { select: ui.origin, pick: ui.pickOrigin, hint: ui.originHint, row: ui.originRow },
    {
      current: () => state.current,
      report: () => window.kerfcam.lastReport,
      snap: (x, y, reach) => engine.call('snap', { x, y, reach }),
      scale: () => state.view?.scale || 1,
      onPicked: () => {
        keepChoices();
        run({ fit: true });
      },
      onPicking: (on) => {
        if (on && state.picking) setPicking(false);
        if (on && inspector.measuring) inspector.setMeasuring(false);
        ui.stage.classList.toggle('picking', on || state.picking); // the crosshair cursor
        planLayer.draw(); // the keyboard's aim
      },
    },
  );
  planLayer.decorations.push((ctx, px, dpr) => origin.decorate(ctx, px, dpr));
  onLangChange(() => {
    if (!ui.sheetView.hidden && state.sheet) fillSheet(ui.sheet, state.sheet); // the open sheet in the new language
  });
  wire();
  try {
    engine = new Engine();
    batch = new Batch(
      { list: ui.jobs, count: ui.jobCount, downloadAll: ui.downloadAll, clear: ui.clearFiles, message: ui.jobMessage },
      {
        engine,
        settingsFor: (job) => readSettings(job),
        onShow: (job) => showJob(job),
        previewBusy: () => state.running?.catch(() => {}),
        runShown: async () => {
          await run();
          await state.running?.catch(() => {});
        },
      },
    );
    ui.version.textContent = `v${await engine.ready}`;
    posts = new Posts(
      {
        select: $('post'), about: $('post-about'), edit: $('post-edit'), exportButton: $('post-export'), importInput: $('post-import'),
        message: $('post-message'), dialog: $('post-dialog'), form: $('post-form'), error: $('post-error'),
        cancel: $('post-cancel'),
      },
      engine,
      () => {
        const p = posts.current();
        if (p && Number.isFinite(p.rapid_speed)) ui.rapid.value = String(p.rapid_speed);
        run();
      },
    );
    await posts.load();
    restoreSettings([], [$('post')]); // the post menu is filled only now
    posts.fillMenu($('post').value); // its description, and a kept "linuxcnc" shown as the default it equals
    engineReady = true;
    setStatus('waiting for a file');
    if (state.file) {
      await run({ fit: true }); // a file dropped while the wasm was loading
    } else {
      const kept = batch.restore(await loadFiles()); // the files of the last visit
      if (kept) await showJob(kept);
    }
  } catch (e) {
    showError(t('error.engine', { message: messageOf(e) }));
    setStatus('error');
  }
}

window.addEventListener('error', (e) => showError(t('error.unexpected', { message: e.message })));
window.addEventListener('unhandledrejection', (e) => showError(t('error.unexpected', { message: messageOf(e.reason) })));
start();
