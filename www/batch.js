// kerfcam batch: several DXFs at once (issue 6 §4). Each file is a job in a list with its own status,
// warnings and program; the one on the preview is run by the page, the others by this module in the
// background (one at a time, in the same worker). "Download all" zips every program with fflate.
// Every file is kept in this browser (file-store.js) with its layer choices and start points until
// the user removes it. File names are data: they are shown with textContent only.

import { download } from './download.js';
import { forgetAllFiles, forgetFile, keepFile } from './file-store.js';
import { fmtNumber, onLangChange, register, t } from './i18n.js';
import { lossOf, lossWords } from './losses.js';
import { zipSync } from './vendor/fflate.js';

register({
  en: {
    'drawing.open-files': 'Open DXF or SVG files…',
    'drawing.drop-files': 'or drop one or more .dxf or .svg files anywhere on this page',
    'batch.heading': 'Files', 'batch.download-all': 'Download all (.zip)', 'batch.clear': 'Clear files',
    'batch.kept': 'Files stay in this browser until you clear them.',
    'compare.table': 'Comparison table',
    'batch.status.waiting': 'waiting',
    'batch.status.working': 'working…',
    'batch.status.done': 'done',
    'batch.status.error': 'error',
    'batch.status.cancelled': 'cancelled',
    'batch.status.truncated': 'done from a truncated file: check it',
    'batch.units-assumed': 'units assumed ({unit})',
    'batch.pierces': { one: '{n} pierce', other: '{n} pierces' },
    'batch.warnings': { one: '{n} warning', other: '{n} warnings' },
    'batch.show': 'Show {name} on the preview',
    'batch.download': 'G-code',
    'batch.download.label': 'Download the G-code of {name}',
    'batch.remove.label': 'Remove {name} from this browser',
    'batch.zip.failed': 'Not in the zip (no program): {names}',
    'batch.zip.none': 'No program to download yet.',
    'batch.zip.losses': 'In the zip, programs that take material from parts: {list}',
    'batch.count': { one: '({n} file)', other: '({n} files)' },
    'batch.restored': 'Restored from this browser: {files} file(s), {starts} start point(s), {tabs} placed tab(s).',
  },
  'pt-BR': {
    'drawing.open-files': 'Abrir arquivos DXF ou SVG…',
    'drawing.drop-files': 'ou solte um ou mais arquivos .dxf ou .svg em qualquer lugar desta página',
    'batch.heading': 'Arquivos', 'batch.download-all': 'Baixar todos (.zip)', 'batch.clear': 'Limpar arquivos',
    'batch.kept': 'Os arquivos ficam neste navegador até você limpá-los.',
    'compare.table': 'Tabela de comparação',
    'batch.status.waiting': 'na fila',
    'batch.status.working': 'processando…',
    'batch.status.done': 'pronto',
    'batch.status.error': 'erro',
    'batch.status.cancelled': 'cancelado',
    'batch.status.truncated': 'pronto a partir de um arquivo truncado: confira',
    'batch.units-assumed': 'unidades supostas ({unit})',
    'batch.pierces': { one: '{n} perfuração', other: '{n} perfurações' },
    'batch.warnings': { one: '{n} aviso', other: '{n} avisos' },
    'batch.show': 'Mostrar {name} na visualização',
    'batch.download': 'Código G',
    'batch.download.label': 'Baixar o código G de {name}',
    'batch.remove.label': 'Tirar {name} deste navegador',
    'batch.zip.failed': 'Fora do zip (sem programa): {names}',
    'batch.zip.none': 'Ainda não há programa para baixar.',
    'batch.zip.losses': 'No zip, programas que removem material de peças: {list}',
    'batch.count': { one: '({n} arquivo)', other: '({n} arquivos)' },
    'batch.restored': 'Restaurado deste navegador: {files} arquivo(s), {starts} ponto(s) de entrada, {tabs} ponte(s) colocada(s).',
  },
});

/** "part.dxf" → "part"; used for the program's file name. */
export const baseName = (name) => String(name).replace(/\.[^.]*$/, '') || 'kerfcam';
/** The name the page downloads a job's program under (Download, and the job report's program file). */
export const programName = (name) => `${baseName(name)}.ngc`;

let nextId = Date.now();

export class Batch {
  /**
   * `ui`: { list, count, downloadAll, clear, message }. `settingsFor(job)` gives the engine settings for
   * a job (its own layers and start points) or throws; `onShow(job)` puts a job on the preview;
   * `runShown()` resolves when the shown job's program is made for the current settings;
   * `previewBusy()` resolves when the page's own run (the preview) is done: it goes first.
   */
  constructor(ui, { engine, settingsFor, onShow, runShown, previewBusy }) {
    Object.assign(this, { ui, engine, settingsFor, onShow, runShown, previewBusy });
    this.jobs = [];
    this.shown = null;
    this.running = null; // the background loop, while it runs
    this.stopped = false; // set by a cancel; the next schedule() starts again
    ui.downloadAll.addEventListener('click', () => this.downloadAll());
    ui.clear.addEventListener('click', () => this.clear());
    onLangChange(() => this.render());
    this.render();
  }

  /**
   * Adds files the user opened or dropped; returns their jobs (read and kept). A file already in the
   * list (same name, size and date) is not added twice. Files are kept as they are (Blobs): the page
   * never reads them; the engine worker does.
   */
  async add(files) {
    const added = [];
    for (const file of files) {
      const same = this.jobs.find((j) => j.name === file.name && sameFile(j.file, file));
      if (same) {
        // Opened again: the same job, started afresh (its own visible layers, no moved start points).
        Object.assign(same, { layers: null, starts: [], tabsAt: [], sidesAt: [] });
        keepFile(this.record(same));
        added.push(same);
        continue;
      }
      const job = { id: String(nextId++), name: file.name, file, layers: null, starts: [], added: Date.now(), status: 'waiting' };
      this.jobs.push(job);
      added.push(job);
      keepFile(this.record(job), file); // the File itself: the browser stores it off the main thread
    }
    this.render();
    return added;
  }

  /** Jobs from the files kept in this browser; returns the one that was on the preview, if any. */
  restore(records) {
    for (const r of records) {
      this.jobs.push({
        id: r.id, name: r.name, file: r.blob, layers: Array.isArray(r.layers) ? r.layers : null,
        units: typeof r.units === 'string' ? r.units : null, originPoint: Array.isArray(r.originPoint) ? r.originPoint : null,
        startsFrame: Array.isArray(r.startsFrame?.at) ? r.startsFrame : null,
        starts: Array.isArray(r.starts) ? r.starts : [], added: r.added, status: 'waiting', shownBefore: !!r.shown,
        tabsAt: Array.isArray(r.tabsAt) ? r.tabsAt : [], // issue 39: placed tabs come back with the file
        sidesAt: Array.isArray(r.sidesAt) ? r.sidesAt : [], // issue 43: the profiles' sides too
        layerOps: r.layerOps && typeof r.layerOps === 'object' ? r.layerOps : {}, // issue 20: each layer's operation
        layerTools: r.layerTools && typeof r.layerTools === 'object' ? r.layerTools : {}, // issue 43: a milling layer's tool
        layerDepths: r.layerDepths && typeof r.layerDepths === 'object' ? r.layerDepths : {}, // and its depth
      });
    }
    this.render();
    if (records.length) {
      // Said, so a choice that did not come back would be noticed (issue 39 §2).
      const count = (key) => this.jobs.reduce((n, j) => n + (j[key]?.length ?? 0), 0);
      this.ui.message.textContent = t('batch.restored', { files: records.length, starts: count('starts'), tabs: count('tabsAt') });
    }
    return this.jobs.find((j) => j.shownBefore) || this.jobs[this.jobs.length - 1] || null;
  }

  /** What is kept of a job besides its file: its choices. */
  record(job) {
    return {
      id: job.id, name: job.name, layers: job.layers, starts: job.starts, shown: job === this.shown, added: job.added,
      units: job.units ?? null, originPoint: job.originPoint ?? null, // issue 13: the unit and origin chosen for this file
      startsFrame: job.startsFrame ?? null, // the origin and unit the start points and tabs were set in
      tabsAt: job.tabsAt ?? [],
      sidesAt: job.sidesAt ?? [],
      layerOps: job.layerOps ?? {},
      layerTools: job.layerTools ?? {},
      layerDepths: job.layerDepths ?? {},
    };
  }

  /** The page shows `job` now. */
  setShown(job) {
    const before = this.shown;
    this.shown = job;
    for (const j of [before, job]) if (j && this.jobs.includes(j)) keepFile(this.record(j));
    this.render();
  }

  /** The shown job's layer choices or start points changed: keep them. */
  keep(job) {
    if (this.jobs.includes(job)) keepFile(this.record(job));
  }

  /** The page ran the shown job: its result is this job's result for these settings. */
  result(job, key, report, gcode) {
    Object.assign(job, { key, status: 'done', error: null, gcode, summary: summaryOf(report) });
    this.render();
  }

  failed(job, key, message, cancelled = false) {
    Object.assign(job, { key, status: cancelled ? 'cancelled' : 'error', error: cancelled ? null : message, gcode: null, summary: null });
    if (cancelled) this.stopped = true;
    this.render();
  }

  /** Runs, in the background, every job whose program is missing or made with other settings. */
  schedule() {
    this.stopped = false;
    if (!this.running) {
      this.running = this.work().finally(() => {
        this.running = null;
      });
    }
    return this.running;
  }

  async work() {
    for (;;) {
      await this.previewBusy(); // the preview's job first: the operator is looking at it
      if (this.stopped) return;
      const next = this.jobs.find((j) => j !== this.shown && j.status !== 'working' && this.stale(j));
      if (!next) return;
      let settings;
      try {
        settings = this.settingsFor(next);
      } catch (e) {
        // A number out of its range is marked on its field: the jobs keep their last programs.
        if (!e.invalid) this.failed(next, null, e.message);
        return; // the settings are wrong for every job: the page says so
      }
      const key = JSON.stringify(settings);
      next.status = 'working';
      this.render();
      try {
        const r = await this.engine.call('program', { file: next.file, settings });
        if (this.jobs.includes(next)) this.result(next, key, JSON.parse(r.report), r.gcode);
      } catch (e) {
        if (this.jobs.includes(next)) this.failed(next, key, e.message, !!e.cancelled);
      }
    }
  }

  /** True when `job` has no program for the settings it would now run with. */
  stale(job) {
    if (job.status === 'cancelled' && this.stopped) return false;
    try {
      return job.key !== JSON.stringify(this.settingsFor(job)) || (job.status !== 'done' && job.status !== 'error');
    } catch {
      return job.status !== 'error';
    }
  }

  /** Every program (made first where missing) in one zip; names of jobs without a program are listed. */
  async downloadAll() {
    this.ui.message.textContent = '';
    // The shown job is run by the page; the rest here. Wait for both.
    await Promise.all([this.runShown(), this.schedule()]);
    const files = {};
    const failed = [];
    const lossy = [];
    const used = new Set();
    for (const job of this.jobs) {
      if (job.status !== 'done' || !job.gcode) {
        failed.push(job.name);
        continue;
      }
      if (job.summary?.loss.any) lossy.push(`${job.name} (${lossWords(job.summary.loss)})`);
      let name = `${baseName(job.name)}.ngc`;
      for (let i = 2; used.has(name); i++) name = `${baseName(job.name)}-${i}.ngc`;
      used.add(name);
      files[name] = job.gcode; // UTF-8 bytes, as the engine wrote them
    }
    // What the zip holds that takes material is said as the Download button says it; never blocked.
    const said = [
      ...(failed.length ? [t('batch.zip.failed', { names: failed.join(', ') })] : []),
      ...(lossy.length ? [t('batch.zip.losses', { list: lossy.join('; ') })] : []),
    ];
    if (said.length) this.ui.message.textContent = said.join(' ');
    if (!used.size) {
      this.ui.message.textContent = t('batch.zip.none');
      return;
    }
    const zip = zipSync(files, { level: 6 });
    download(new Blob([zip], { type: 'application/zip' }), 'kerfcam-programs.zip');
  }

  async remove(job) {
    this.jobs = this.jobs.filter((j) => j !== job);
    await forgetFile(job.id);
    if (job === this.shown) {
      this.shown = null;
      this.onShow(this.jobs[0] || null);
    }
    this.render();
  }

  async clear() {
    this.jobs = [];
    this.shown = null;
    await forgetAllFiles();
    this.onShow(null);
    this.render();
  }

  render() {
    const { list, count, downloadAll, clear } = this.ui;
    count.textContent = this.jobs.length ? t('batch.count', { n: fmtNumber(this.jobs.length), count: this.jobs.length }) : '';
    downloadAll.disabled = !this.jobs.length;
    clear.disabled = !this.jobs.length;
    list.replaceChildren(...this.jobs.map((job) => this.row(job)));
  }

  row(job) {
    const li = document.createElement('li');
    li.className = 'job';
    // A program made from a file that ends too soon is marked, never a green "done".
    const truncated = job.status === 'done' && job.summary?.truncated;
    li.dataset.status = truncated ? 'truncated' : job.status;
    li.dataset.name = job.name; // a hook for tests (an attribute: never markup)
    // A program that takes material from parts is said on its row too, as on the Download button.
    const loss = job.status === 'done' && job.summary?.loss.any ? job.summary.loss : null;
    if (loss) li.dataset.loss = 'true';
    const show = document.createElement('button');
    show.type = 'button';
    show.className = 'job-name link-button';
    show.textContent = job.name;
    show.setAttribute('aria-pressed', String(job === this.shown));
    show.setAttribute('aria-label', t('batch.show', { name: job.name }));
    show.addEventListener('click', () => this.onShow(job));
    const status = document.createElement('span');
    status.className = 'job-status small';
    status.textContent = t(`batch.status.${truncated ? 'truncated' : job.status}`) +
      (job.summary ? ` · ${counted('batch.pierces', job.summary.pierces)}, ${counted('batch.warnings', job.summary.warnings)}` : '') +
      (job.summary?.assumed ? ` · ${t('batch.units-assumed', { unit: job.summary.assumed })}` : '') +
      (loss ? ` · ${lossWords(loss)}` : '') +
      (job.error ? ` · ${job.error}` : '');
    const get = document.createElement('button');
    get.type = 'button';
    get.className = 'small-button';
    get.textContent = t('batch.download');
    get.disabled = !(job.status === 'done' && job.gcode);
    get.setAttribute('aria-label', t('batch.download.label', { name: job.name }));
    get.addEventListener('click', () => download(new Blob([job.gcode], { type: 'text/plain' }), `${baseName(job.name)}.ngc`));
    const remove = document.createElement('button');
    remove.type = 'button';
    remove.className = 'small-button';
    remove.textContent = '×';
    remove.setAttribute('aria-label', t('batch.remove.label', { name: job.name }));
    remove.addEventListener('click', () => this.remove(job));
    li.append(show, status, get, remove);
    return li;
  }
}

/** "1 pierce", "3 warnings": the plural form of the language. */
const counted = (key, n) => t(key, { n: fmtNumber(n), count: n });

/** The same file opened again: same size and modification date (its name is compared by the caller). */
const sameFile = (a, b) => a.size === b.size && (a.lastModified ?? 0) === (b.lastModified ?? 0);

/**
 * What the list says of a job's result: pierces, warnings (information such as repairs does not count),
 * what the program takes from the parts, and whether the file was cut off (issue 13 §3: such a job is
 * not a plain "done").
 */
function summaryOf(report) {
  const warnings = report?.warnings || [];
  return {
    pierces: report?.plan?.pierces ?? 0,
    warnings: warnings.filter((w) => w.severity !== 'info').length,
    truncated: warnings.some((w) => w.code === 'file-truncated'),
    loss: lossOf(report), // what the program takes from the parts (losses.js)
    assumed: report?.units_assumed === true ? String(report.units) : null, // read in a unit the file does not state
  };
}
