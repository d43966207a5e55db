// kerfcam page: what the page's modules share — the elements (ui), the shown job's state, the parts
// made at start (app: the engine worker, the plan overlay, the inspector…) and late-bound functions
// (app.run, app.showJob) that a panel calls without importing the module that defines them (the
// single-file build refuses import cycles). Split out of main.js (issue 15 item 7).

import { t } from './i18n.js';

// What scripts and tests read of the page (filled by the modules).
window.kerfcam = { lastReport: null };

export const $ = (id) => document.getElementById(id);
export const ui = {
  file: $('file-input'), fileName: $('file-name'), form: $('settings'),
  kerf: $('kerf'), tolerance: $('tolerance'), feed: $('feed'), units: $('units'),
  layers: $('layers'), layersBox: $('layers-box'), layerCount: $('layer-count'),
  layersAll: $('layers-all'), layersNone: $('layers-none'),
  healing: $('healing'), healingList: $('healing-list'), healingCount: $('healing-count'),
  canvas: $('preview'), stage: $('stage'), placeholder: $('placeholder'), planningNote: $('planning-note'),
  summary: $('summary'), warnings: $('warnings'), warningCount: $('warning-count'),
  download: $('download'), fit: $('fit'), error: $('error'), status: $('status'), version: $('version'),
  rapid: $('rapid'), pierceDelay: $('pierce-delay'), planForm: $('plan-settings'),
  leadOuter: $('lead-outer'), leadHole: $('lead-hole'), overcut: $('overcut'), maxLink: $('max-link'),
  join: $('join'), order: $('order'), eulerMode: $('euler-mode'), lead: $('lead'), outerDir: $('outer-dir'), holeDir: $('hole-dir'),
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
export const CHOICES = { join: 'join', order: 'order', euler_mode: 'eulerMode', lead: 'lead', outer_dir: 'outerDir', hole_dir: 'holeDir' };
export const MAX_DPR = 2; // more device pixels cost render time for no visible gain

// view = { cx, cy, scale }: the mm point at the canvas centre and CSS pixels per mm (Y up).
// layers: the names to cut, or null for the file's visible layers (reset for each new file).
// layerNames: the names of the layer list as shown (index = the checkbox's data-index).
// layersOf: { job, layers }: the batch job whose layers the list shows, and them (a failed run of the same
// job keeps them).
// current: the batch job on the preview (its bytes, name, layers and start points are copied here).
export const state = {
  job: null /* { bbox, moves } of the shown job */, file: null /* Blob */, name: '', settingsKey: '', gcode: null /* UTF-8 */, view: null, runId: 0,
  layers: null, layerNames: null, layersOf: null, starts: [], picking: false, current: null, running: null,
};

/** The parts made at start (main.js) and the functions a panel calls late. */
export const app = {
  engine: null, // the worker running the wasm pipeline
  engineReady: false,
  planLayer: null, // the overlay: sequence numbers and the animation
  posts: null, // the post menu and editor
  batch: null, // the list of files (jobs)
  progress: null, // the stage progress bar
  inspector: null, // hover inspect and the measure tool
  numbers: null, // the number fields: parsed the local way, checked against their ranges
  summary: null, // the summary, warnings and repairs
  origin: null, // the program origin setting, its picking and the origin and scale marks
  glance: null, // the job at a glance, over the preview
  compareBox: null, // the orders compared, under the preview
  updateOrderHelp: () => {}, // the order's explanation, after a script sets the order
  run: async () => {}, // job.js: runs the shown file with the settings (re-plans)
  closeSheet: () => {}, // jobsheet.js: closes the job sheet (Escape on the page)
  sheet: null, // main.js, Sheet mode (issue 18): { active, addFiles(files), cutting(), settings(s), bbox(b), report(), files() } for job.js and jobsheet.js
};

export const messageOf = (e) => (e && e.message) || String(e);

// Status states (data-state, for scripts and tests) → their text key.
const STATUS = {
  loading: 'status.loading', 'waiting for a file': 'status.waiting', working: 'status.working', ready: 'status.ready',
  error: 'status.error', cancelled: 'status.cancelled', backplot: 'status.backplot', planning: 'status.planning',
};
export function setStatus(s) {
  ui.status.textContent = STATUS[s] ? t(STATUS[s]) : s;
  ui.status.dataset.state = s;
}

export function showError(message) {
  ui.error.textContent = message;
  ui.error.hidden = !message;
}

export function el(tag, text, attrs = {}) {
  const node = Object.assign(document.createElement(tag), attrs);
  node.textContent = text;
  return node;
}

/** The shown file's layer choices and start points are kept with it. */
export function keepChoices() {
  if (!state.current) return;
  state.current.layers = state.layers;
  state.current.starts = state.starts;
  app.batch.keep(state.current);
}
