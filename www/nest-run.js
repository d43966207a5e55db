// kerfcam page, Sheet mode (issue 18): Nest runs the parts list on the sheet in the engine worker
// (wasm Nester), with a progress line (time, utilisation, sheets) and Stop, which keeps the best nest;
// the result (sheets, utilisation per sheet and for the job, parts placed and not placed with the
// reason) is shown, and the sheet picked is cut by the ordinary cut plan (worker op cutSheet), so the
// preview, Play, the job sheet and the downloaded program are the nest's. Part names are data.

import { $, el } from './app.js';
import { fmtNumber, getLang, onLangChange, register, t } from './i18n.js';
import { LabelsPanel } from './labels.js';
import { SheetTabs } from './nest-tabs.js';
import { copies } from './nest-view.js';
import { EXCHANGE_EVERY, NestTeam, teamSize } from './nest-team.js';
import { formatValue } from './numbers.js';
import { sheetSize } from './sheet-sizes.js';

register({
  en: {
    'nest.run': 'Nest', 'nest.stop': 'Stop (keep the best)', 'nest.nothing': 'Add parts to nest first.',
    'nest.progress': '{time} s · {sheets} · {util} · {tries} nests tried',
    'nest.progress-sheets': { one: '{n} sheet', other: '{n} sheets' },
    'nest.progress-util': 'about {u} % used', 'nest.progress-missing': { one: '{n} copy not placed yet', other: '{n} copies not placed yet' },
    'nest.stopping': 'Stopping: keeping the best nest so far…', 'nest.failed': 'The nest failed: {message}',
    'nest.result': 'Nest', 'nest.sheets-used': 'Sheets used', 'nest.placed': 'Parts placed',
    'nest.placed-of': '{placed} of {asked}', 'nest.job-util': 'Utilisation (job)', 'nest.time-used': 'Search',
    'nest.time-value': '{time} s, {tries} nests tried',
    'nest.sheet-line': { one: 'Sheet {k}: {n} part, {u} %', other: 'Sheet {k}: {n} parts, {u} %' },
    'nest.unplaced': 'Not placed', 'nest.unplaced-line': { one: '{part}: {n} copy: {reason}', other: '{part}: {n} copies: {reason}' },
    'nest.unplaced-note': '{part}: {reason}',
    'nest.done': 'Done: {time} s, {tries} nests tried; the best nest was found at {best} s.',
    'nest.lost': 'The nest was dropped when the engine was stopped (Cancel): Nest again.',
    'nest.all-placed': 'Every part is placed.', 'nest.stale': 'The parts or the sheet changed: Nest again to use them.',
    'nest.stock': 'Sheets chosen', 'nest.stock-line': '{n} × {w} × {h} mm at {cost} each', 'nest.sheet-cost': 'Sheet cost',
    'nest.passed-over': { one: '{n} cheaper combination did not hold every copy', other: '{n} cheaper combinations did not hold every copy' },
    'nest.trying': 'trying {sheets} ({cost})', 'nest.no-currency': 'no currency set in Cost and time',
  },
  'pt-BR': {
    'nest.run': 'Encaixar', 'nest.stop': 'Parar (manter o melhor)', 'nest.nothing': 'Adicione peças para encaixar primeiro.',
    'nest.progress': '{time} s · {sheets} · {util} · {tries} encaixes testados',
    'nest.progress-sheets': { one: '{n} chapa', other: '{n} chapas' },
    'nest.progress-util': 'cerca de {u} % usado', 'nest.progress-missing': { one: '{n} cópia ainda não colocada', other: '{n} cópias ainda não colocadas' },
    'nest.stopping': 'Parando: mantendo o melhor encaixe até agora…', 'nest.failed': 'O encaixe falhou: {message}',
    'nest.result': 'Encaixe', 'nest.sheets-used': 'Chapas usadas', 'nest.placed': 'Peças colocadas',
    'nest.placed-of': '{placed} de {asked}', 'nest.job-util': 'Aproveitamento (trabalho)', 'nest.time-used': 'Busca',
    'nest.time-value': '{time} s, {tries} encaixes testados',
    'nest.sheet-line': { one: 'Chapa {k}: {n} peça, {u} %', other: 'Chapa {k}: {n} peças, {u} %' },
    'nest.unplaced': 'Não colocadas', 'nest.unplaced-line': { one: '{part}: {n} cópia: {reason}', other: '{part}: {n} cópias: {reason}' },
    'nest.unplaced-note': '{part}: {reason}',
    'nest.done': 'Pronto: {time} s, {tries} encaixes testados; o melhor encaixe foi achado em {best} s.',
    'nest.lost': 'O encaixe foi descartado quando o motor foi parado (Cancelar): encaixe de novo.',
    'nest.all-placed': 'Todas as peças foram colocadas.', 'nest.stale': 'As peças ou a chapa mudaram: encaixe de novo para usá-las.',
    'nest.stock': 'Chapas escolhidas', 'nest.stock-line': '{n} × {w} × {h} mm a {cost} cada', 'nest.sheet-cost': 'Custo das chapas',
    'nest.passed-over': { one: '{n} combinação mais barata não comportou todas as cópias', other: '{n} combinações mais baratas não comportaram todas as cópias' },
    'nest.trying': 'testando {sheets} ({cost})', 'nest.no-currency': 'nenhuma moeda definida em Custo e tempo',
  },
});

const pct = (u) => fmtNumber(100 * u, 1);

/** The sheets of a combination under trial (issue 44 item 3): `counts` of each size of `list`, in its order, none left out. */
export function trialList(list, counts) {
  return (list ?? []).map((s, i) => ({ ...s, count: counts[i] ?? 0 })).filter((s) => s.count > 0);
}

/** The least time between two live drawings of the nest while it is searched, ms. */
const LIVE_MS = 250;
/** Whether the nest's settings price the sheets: then the engine takes the cheapest combination. */
const priced = (settings) => !!settings.sheet_list?.some((s) => s.cost !== undefined && s.cost !== null);

/** Job utilisation (paper 001's formula summed over the sheets): part area over the useful sheet area. */
export function jobUtilisation(result, areas) {
  let parts = 0;
  let useful = 0;
  for (const [k, s] of result.sheets.entries()) {
    let a = 0;
    for (const p of result.placements) {
      if (p.sheet !== k) continue;
      const area = areas.get(p.part);
      if (!Number.isFinite(area)) return null;
      a += area;
    }
    if (!(s.utilisation > 0)) return null;
    parts += a;
    useful += a / s.utilisation;
  }
  return useful > 0 ? parts / useful : null;
}

// A whole number above 0 set from the console or a test as window.kerfcam[key], or null.
function consoleCount(key) {
  const n = Number(window.kerfcam?.[key]);
  return Number.isInteger(n) && n > 0 ? n : null;
}

// Evaluations between the workers' exchanges: the engine's (EXCHANGE_EVERY, the CLI's), or the console's or a
// test's (window.kerfcam.nestExchangeEvery), so that a test sees an exchange within a small budget.
function exchangeEvery() {
  return consoleCount('nestExchangeEvery') ?? EXCHANGE_EVERY;
}

export class NestRun {
  /**
   * `panel`: the SheetPanel; `hooks`: { engine(), show(k) (cuts sheet k and previews it), edit (the NestEdit:
   * the nest drawn live and adjusted by hand), recut() (the nest was edited: cut the sheet shown again) }.
   */
  constructor(panel, hooks) {
    Object.assign(this, { panel, hooks });
    this.result = null; // { json, id, asked }
    this.k = 0;
    this.ids = 0;
    this.ui = {
      run: $('nest-run'), stop: $('nest-stop'), progress: $('nest-progress'), message: $('nest-message'),
      box: $('nest-result'), figures: $('nest-figures'), sheets: $('nest-sheets'),
      unplaced: $('nest-unplaced'), stale: $('nest-stale'),
    };
    this.tabs = new SheetTabs($('nest-tabs'), $('nest-canvas'), (k) => this.pick(k));
    this.labels = new LabelsPanel({ changed: () => this.relabel() });
    this.ui.run.addEventListener('click', () => this.nest());
    this.ui.stop.addEventListener('click', () => this.stop());
    onLangChange(() => {
      this.showResult();
      if (this.result) this.labels.show(this.result.json); // "5 labels placed." in the new language
      if (!this.running) this.showDone();
    });
  }

  /** Sheet k picked (a tab): drawn in the nest view, and cut for the preview once the nest is done. */
  pick(k) {
    this.k = k;
    if (this.running || !this.result) {
      this.liveTabs(this.hooks.edit.live(null));
      return;
    }
    this.hooks.edit.render();
    this.showResult();
    this.hooks.show(this.k);
  }

  /** The tabs while the search runs: one per sheet of the best nest so far, with its copies. */
  liveTabs(counts) {
    if (!counts) return;
    this.k = Math.min(this.k, counts.length - 1);
    this.tabs.show(counts.map((copies) => ({ copies })), this.k);
  }

  /** {k, key} of the sheet to cut (key: changes with each nest), or null before a nest. */
  cutting() {
    // Cancel starts a fresh worker, which has no nest: the result shown is gone with the old one.
    if (this.result && this.hooks.engine().generation !== this.result.generation) {
      this.result = null;
      window.kerfcam.lastNest = null;
      this.hooks.edit.load(null);
      this.showResult();
      this.say(t('nest.lost'));
    }
    // A nest edited into conflict is not cut: nothing to preview or download until it is fixed.
    if (!this.result || this.hooks.edit.blocked) return null;
    return { k: this.k, key: `#nest${this.result.id}.${this.hooks.edit.version}:${this.k}` };
  }

  /**
   * The job report's figures (issue 42 §4): the nest as it stands (its state and outlines, for the sheet
   * maps), each part ordered, placed and not placed, each sheet's copies with their labels, and each sheet
   * cut with `settings` (the page's, as the preview cuts the sheet shown): its plan's figures and warnings.
   */
  async report(settings) {
    const r = this.result?.json;
    if (!r) return null;
    const cut = await this.hooks.engine().call('sheetFigures', { settings });
    const names = r.outlines.map((o) => o.name);
    const placed = new Map(names.map((n) => [n, 0]));
    const sheets = r.sheets.map((s, k) => ({ ...s, k, plan: cut[k]?.plan ?? {}, warnings: cut[k]?.warnings ?? [], parts: new Map() }));
    for (const c of copies(r.flat)) {
      const name = names[c.part] ?? '?';
      placed.set(name, (placed.get(name) || 0) + 1);
      const on = sheets[c.sheet]?.parts;
      if (on && !on.has(name)) on.set(name, { name, n: 0, labels: [] });
      if (on) on.get(name).n++;
    }
    for (const l of r.labels?.labels || []) sheets[l.sheet]?.parts.get(names[l.part])?.labels.push(l.text);
    const missing = new Map();
    for (const u of r.unplaced) missing.set(u.part, [...(missing.get(u.part) || []), u]);
    const ordered = this.result.ordered ?? new Map();
    const parts = [...new Set([...ordered.keys(), ...placed.keys()])].map((name) => ({
      name, ordered: ordered.get(name) ?? null, placed: placed.get(name) || 0, unplaced: missing.get(name) || [],
    }));
    return {
      state: r, sheets: sheets.map((s) => ({ ...s, parts: [...s.parts.values()] })), parts,
      job: jobUtilisation(r, this.panel.areas()), asked: this.result.asked, placed: r.placed,
    };
  }

  /** The preview's extent for sheet k's plan (`b`, mm): the sheet itself is in sight. */
  bbox(b) {
    const s = this.result?.json.sheets[this.k];
    if (!s || !b.every(Number.isFinite)) return b;
    const [x0, y0, x1, y1] = this.sheetBox(s);
    return [Math.min(b[0], x0), Math.min(b[1], y0), Math.max(b[2], x1), Math.max(b[3], y1)];
  }

  /** The sheet's box in the nest's coordinates (a remnant lies where it was on the table). */
  sheetBox(s) {
    return this.result?.json.sheet_shape?.box ?? [0, 0, s.width, s.height];
  }

  /** The sheet's outline on the preview's overlay (the nest's coordinates are the program's). */
  decorate(ctx, px, dpr) {
    const s = this.panel.active && this.result?.json.sheets[this.k];
    if (!s) return;
    const box = this.sheetBox(s);
    const [x0, y0] = px(box[0], box[1]);
    const [x1, y1] = px(box[2], box[3]);
    ctx.save();
    ctx.setLineDash([]);
    ctx.strokeStyle = '#5a6470';
    ctx.lineWidth = 1.5 * dpr;
    ctx.strokeRect(Math.min(x0, x1), Math.min(y0, y1), Math.abs(x1 - x0), Math.abs(y1 - y0));
    // The copies' labels (issue 42 §2), the engine's strokes as the nest view draws them: on the cut preview
    // and so on the job sheet's map (its picture is the preview), scribed or not.
    ctx.strokeStyle = '#9b1c1c';
    ctx.lineWidth = 1.5 * dpr;
    for (const l of this.result.json.labels?.labels || []) {
      if (l.sheet !== this.k) continue;
      for (const p of l.strokes) {
        ctx.beginPath();
        for (let j = 0; j + 1 < p.length; j += 2) {
          const [x, y] = px(p[j], p[j + 1]);
          if (j) ctx.lineTo(x, y);
          else ctx.moveTo(x, y);
        }
        ctx.stroke();
      }
    }
    ctx.restore();
  }

  /** The page's cutting settings for a nest's sheet: the nest is in mm and has no layers to choose. */
  settings(s) {
    return { ...s, units: 'mm', layers: null };
  }

  /** The parts or the sheet changed after a nest. */
  changed() {
    this.ui.stale.hidden = !this.result;
  }

  say(text) {
    this.ui.message.textContent = text;
    this.ui.message.hidden = !text;
  }

  async nest() {
    let parts;
    let sheet;
    try {
      parts = this.panel.read();
      sheet = this.panel.sheetSettings();
    } catch (e) {
      return this.say(e.message);
    }
    if (!parts.length) return this.say(t('nest.nothing'));
    this.say('');
    // The budget the search shares out (the sequence search's part of it, search.rs sequence_work) is the
    // operator's time, kept apart from the clock for Stop's replay; a test may set it apart from the time
    // (window.kerfcam.nestBudget, seconds) to run a short budget's search on a loaded machine.
    const settings = { ...sheet, seed: 1, budget_s: consoleCount('nestBudget') ?? sheet.time_s };
    // An evaluation budget (each worker's) for nests the same from run to run: the console's or a test's.
    const budget = consoleCount('nestEvaluations');
    if (budget) settings.max_evaluations = budget;
    const sheetFile = this.panel.sheetFile; // a remnant drawn in a DXF: its own outline, no W × H
    if (sheetFile) for (const k of ['sheet_width', 'sheet_height', 'sheet_count', 'sheet_list']) delete settings[k];
    const asked = this.asked(parts);
    const area = this.panel.askedArea();
    // A cross-origin isolated page shares a flag the search reads at each progress; elsewhere Stop ends
    // the worker and the same search (same seed) is replayed up to the best nest's evaluation count.
    const flag = globalThis.crossOriginIsolated ? new Int32Array(new SharedArrayBuffer(4)) : null;
    Object.assign(this, { flag, last: null, kept: null, stopping: false, running: true, k: 0 });
    this.ui.run.disabled = true;
    this.ui.stop.hidden = false;
    this.ui.stop.disabled = false;
    this.ui.progress.textContent = '';
    // The search reports every 64 nests tried; drawn and written at each, two workers tried 143 063 nests in
    // 60 s on a 2-core machine, 265 112 at most every LIVE_MS (100 plates, scripts/bench-nest-page.mjs). What
    // the search stands at (this.last, the nest Stop keeps) is taken at once; the drawing and the progress
    // line follow, the latest nest drawn.
    const live = { at: -Infinity, timer: 0, nest: null, line: null };
    const show = () => { // only ever after a report: live.line is set
      live.timer = 0;
      live.at = performance.now();
      this.liveTabs(this.hooks.edit.live(live.nest ?? live.line));
      if (!this.stopping) this.ui.progress.textContent = this.progressLine(live.line, sheet, area);
      live.nest = live.line = null;
    };
    // Stop shows the nest it keeps (this.last) at once.
    this.liveFlush = () => {
      if (!live.timer) return;
      clearTimeout(live.timer);
      show();
    };
    this.liveEnd = () => {
      clearTimeout(live.timer);
      live.timer = 0;
      live.nest = live.line = null;
    };
    const onProgress = (p) => {
      if (p.outlines) return this.hooks.edit.start(JSON.parse(p.outlines), sheet, JSON.parse(p.sheet));
      if (this.stopping && !flag) return;
      // Sheets at a cost: the nest is on the combination under trial, its sheets numbered in it.
      if (p.combination) {
        p.sheet_list = trialList(sheet.sheet_list, p.combination.counts);
        if (p.best) this.kept = { best: p.best, combination: p.combination };
      }
      this.last = p;
      if (p.placements) live.nest = p;
      live.line = p;
      if (live.timer) return;
      const wait = live.at + LIVE_MS - performance.now();
      if (wait <= 0) show();
      else live.timer = setTimeout(show, wait);
    };
    const engine = this.hooks.engine();
    const args = { parts, cutting: this.panel.cutting(), lang: getLang(), sheet: sheetFile, labels: this.labels.spec() };
    const call = (s, f) => engine.call('nest', { ...args, settings: s, stop: f }, onProgress);
    // Several workers (issue 44 item 2), each a search exchanging its best with the others (nest-team.js);
    // several torches nest in one. Where a second worker cannot be made, the engine's worker nests alone.
    // Sheets at a cost: the combinations are tried in turn, as the CLI tries them, each by the whole team.
    const size = (Number(settings.torches) || 1) > 1 ? 1 : teamSize();
    const team = size > 1 ? await NestTeam.make(engine, size) : null;
    this.team = team;
    this.workers = team?.size ?? 1;
    const t0 = performance.now();
    let res;
    try {
      try {
        res = !team ? await call(settings, flag)
          : priced(settings) ? await team.runCheapest({ ...args, settings }, onProgress, exchangeEvery())
            : await team.run({ ...args, settings }, onProgress, exchangeEvery());
      } catch (e) {
        if (!(e.cancelled && this.stopping && this.last)) throw e;
        this.ui.progress.textContent = t('nest.stopping');
        // A team keeps the best nest it showed, as does a nest at a cost (on the combination it was trying: a
        // replay would share the budget out again); one worker replays its search to the count it showed.
        const seconds = (performance.now() - t0) / 1000;
        const kept = this.kept;
        // A team at a cost keeps its nest on the combination it was nested on.
        const on = team?.shownTrial;
        res = team && team.shown
          ? await engine.call('nestFrom', {
            ...args, settings: on ? { ...settings, combination: on.combination, passed_over: on.passed_over } : settings,
            best: team.shown, evaluations: team.evaluations, seconds,
          })
          : kept ? await engine.call('nestFrom', {
            ...args, settings: { ...settings, combination: kept.combination.counts, passed_over: kept.combination.passed_over },
            best: kept.best, evaluations: this.last.evaluations, seconds,
          })
            // The count ends the replay; its clock only bounds it, twice the run's and 5 s more: a replay
            // slower than the run (a PC busy with something else) would stop on the clock short of the count
            // and keep another nest than the one shown.
            : await call({
              ...settings, time_s: 2 * settings.time_s + 5,
              max_evaluations: Math.max(1, this.last.evaluations),
            }, null);
      }
    } catch (e) {
      this.say(t('nest.failed', { message: e.message || String(e) }));
      this.hooks.edit.load(null);
      return this.done();
    } finally {
      this.liveEnd();
      team?.close();
      this.team = null;
    }
    this.done();
    this.take(res, { asked, inputs: { parts, settings, sheetFile } });
  }

  /** Copies asked for by `parts` (as panel.read() gives them): each part's quantity, summed. */
  asked(parts) {
    return parts.reduce((n, p) => n + (p.copies || 0), 0);
  }

  /**
   * A nest from the engine shown and its first sheet cut: `res` is the worker's answer (nest or restoreNest),
   * `inputs` what it was made from (a nest file saves them), `crop` the crop line as the operator left it.
   */
  take(res, { asked, inputs, crop }) {
    // The nest's state (its figures and placements, with the checks of a hand edit) is what is shown.
    const state = { ...JSON.parse(res.state), outlines: JSON.parse(res.outlines) };
    this.result = { json: state, id: ++this.ids, asked, generation: this.hooks.engine().generation, inputs, ordered: this.panel.ordered() };
    this.result.bestAt = this.last?.elapsed_s ?? this.result.json.time_s;
    this.showDone();
    window.kerfcam.lastNest = this.result.json;
    window.kerfcam.lastNestId = this.result.id; // which nest it is: a hand edit or new labels keep the id
    this.k = Math.max(0, Math.min(this.k, state.sheets.length - 1)); // the sheet picked while it ran stays shown
    this.ui.stale.hidden = true;
    this.hooks.edit.load(state, crop);
    this.labels.show(state);
    this.showResult();
    this.hooks.show(this.k);
  }

  /** The labels changed (labels.js): placed again by the engine, drawn, and the sheet cut again (scribed or not). */
  async relabel() {
    const spec = this.labels.spec();
    if (!this.result || this.running || !spec) return;
    const result = this.result;
    try {
      const state = JSON.parse(await this.hooks.engine().call('setLabels', { spec }));
      // A nest started (or done) while these labels were placed: it places its own, and this nest's labelled
      // state must not come back over it (Labels on, then Nest at once, showed the previous nest).
      if (this.result !== result || this.running) return;
      state.outlines = this.result.json.outlines;
      this.hooks.edit.load(state, this.hooks.edit.crop);
      this.edited(state);
    } catch (e) {
      this.labels.say(e.message || String(e));
    }
  }

  /** The nest adjusted by hand (`state`: NestResult.state()): its figures shown, its sheet cut again. */
  edited(state) {
    if (!this.result) return;
    this.result.json = state;
    this.labels.show(state);
    window.kerfcam.lastNest = state;
    this.showResult();
    this.hooks.recut();
  }

  /** The progress line once the nest is done: its time, nests tried and when the best was found. */
  showDone() {
    const r = this.result?.json;
    if (!r) return;
    this.ui.progress.textContent = t('nest.done', {
      time: fmtNumber(r.time_s, 1), tries: fmtNumber(r.evaluations), best: fmtNumber(this.result.bestAt, 1),
    });
  }

  done() {
    this.running = false;
    this.ui.run.disabled = false;
    this.ui.stop.hidden = true;
  }

  stop() {
    if (!this.running || this.stopping) return;
    this.liveFlush?.();
    this.stopping = true;
    this.ui.stop.disabled = true;
    this.ui.progress.textContent = t('nest.stopping');
    if (this.team) {
      this.hooks.engine().cancel();
      this.team.close();
    } else if (this.flag) Atomics.store(this.flag, 0, 1);
    else this.hooks.engine().cancel();
  }

  progressLine(p, sheet, area) {
    // Every sheet before the last whole, the last up to the used length; a remnant: no estimate.
    const on = p.sheet_list ? { ...sheet, sheet_list: p.sheet_list } : sheet;
    let used = 0;
    for (let k = 0; k < p.sheets; k++) {
      const { width: W, height: H } = sheetSize(on, k);
      used += k < p.sheets - 1 ? W * H : H * p.length;
    }
    const util = p.unplaced ? t('nest.progress-missing', { n: fmtNumber(p.unplaced), count: p.unplaced })
      : used > 0 ? t('nest.progress-util', { u: pct(Math.min(1, area / used)) }) : '';
    const line = t('nest.progress', {
      time: fmtNumber(p.elapsed_s, 1), sheets: t('nest.progress-sheets', { n: fmtNumber(p.sheets), count: p.sheets }),
      util, tries: fmtNumber(p.evaluations),
    });
    if (!p.sheet_list) return line;
    const sheets = p.sheet_list.map((s) => `${fmtNumber(s.count)} × ${formatValue(s.width, 1)} × ${formatValue(s.height, 1)}`).join(' + ');
    const cost = p.sheet_list.reduce((c, s) => c + s.count * s.cost, 0);
    // The amount bare when no currency is set: the result's cost row says so (one parenthesis here).
    return `${line} · ${t('nest.trying', { sheets, cost: this.amount(cost) })}`;
  }

  /** The nest's sheet cost, with what to know of it in one parenthesis: no currency set, cheaper combinations passed over. */
  sheetCost(r) {
    const notes = [
      ...(this.panel.currency() ? [] : [t('nest.no-currency')]),
      ...(r.combinations_passed_over ? [t('nest.passed-over', { n: fmtNumber(r.combinations_passed_over), count: r.combinations_passed_over })] : []),
    ];
    const v = this.amount(r.sheet_cost);
    return notes.length ? `${v} (${notes.join('; ')})` : v;
  }

  /** An amount in the sheet costs' currency (the Cost panel's), two decimals; bare when none is set (the cost row says so). */
  amount(v) {
    const cur = this.panel.currency();
    return cur ? `${fmtNumber(v, 2)} ${cur}` : fmtNumber(v, 2);
  }

  showResult() {
    const r = this.result?.json;
    this.ui.box.hidden = !r;
    if (!r) return this.tabs.show([], 0);
    const u = jobUtilisation(r, this.panel.areas());
    this.tabs.show(r.sheets, this.k, u);
    const row = (key, label, value) => {
      const dd = el('dd', value);
      dd.dataset.key = key;
      return [el('dt', label), dd];
    };
    this.ui.figures.replaceChildren(
      ...row('sheets', t('nest.sheets-used'), fmtNumber(r.sheets.length)),
      ...row('placed', t('nest.placed'), t('nest.placed-of', { placed: fmtNumber(r.placed), asked: fmtNumber(this.result.asked) })),
      ...row('utilisation', t('nest.job-util'), u === null ? '?' : `${pct(u)} %`),
      ...(r.torches ? row('torches', t('nest.torches'), t('nest.torches-line', {
        n: fmtNumber(r.torches.count), d: fmtNumber(r.torches.spacing),
        per: fmtNumber(r.placed), made: fmtNumber(r.placed * r.torches.count),
      })) : []),
      ...(r.stock ? [
        ...row('stock', t('nest.stock'), r.stock.filter((s) => s.used > 0).map((s) => t('nest.stock-line', {
          n: fmtNumber(s.used), w: formatValue(s.width, 1), h: formatValue(s.height, 1), cost: this.amount(s.cost),
        })).join(' + ')),
        ...row('sheet-cost', t('nest.sheet-cost'), this.sheetCost(r)),
      ] : []),
      ...row('time', t('nest.time-used'), t('nest.time-value', { time: fmtNumber(r.time_s, 1), tries: fmtNumber(r.evaluations) })),
    );
    if (r.stock) this.ui.box.dataset.sheetCost = String(r.sheet_cost);
    else delete this.ui.box.dataset.sheetCost;
    Object.assign(this.ui.box.dataset, { placed: String(r.placed), asked: String(this.result.asked), sheets: String(r.sheets.length), utilisation: u === null ? '' : String(u) });
    this.ui.sheets.replaceChildren(...r.sheets.map((s, k) => {
      const li = el('li', t('nest.sheet-line', { k: fmtNumber(k + 1), n: fmtNumber(s.parts), count: s.parts, u: pct(s.utilisation) }));
      li.dataset.utilisation = String(s.utilisation);
      li.dataset.parts = String(s.parts);
      return li;
    }));
    // A note with no copy (open contours of a file whose parts are nested) is said without a count.
    const missing = r.unplaced.map((m) => el('li', t(m.copies ? 'nest.unplaced-line' : 'nest.unplaced-note',
      { part: m.part, n: fmtNumber(m.copies), count: m.copies, reason: m.reason_text?.[getLang()] ?? m.reason })));
    this.ui.unplaced.replaceChildren(...(missing.length ? missing : [el('li', t('nest.all-placed'), { className: 'muted' })]));
    this.ui.unplaced.dataset.count = String(r.unplaced.reduce((n, m) => n + m.copies, 0));
  }
}
