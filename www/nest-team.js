// kerfcam page, Sheet mode: the nest in several workers at once (issue 44 item 2). Each worker runs one
// search of the job with its own seed (worker.js searchStart: search k's seed is drawn from the job's);
// every EXCHANGE_EVERY evaluations they all pause, this main thread hands every worker the list of
// their best nests (postMessage, no SharedArrayBuffer) and each takes the best of them (the first among
// equals), as `kerfcam nest --threads N` does with threads (src/nest/team.rs). The same seed, worker
// count and evaluation budget give the same nest. The budget holds for each worker; Stop ends them
// all, and the nest kept is the best one shown (nestFrom makes it the last nest in the engine's worker).
// Sheets at a cost (runCheapest): the engine's worker holds the trials of the cheapest combination (the
// CLI's, src/nest/stock.rs) and says which combination to nest next; each is a team nest as above, so the
// nest is the CLI's `--threads N` one. Stop keeps the best nest shown, on the combination it was nested on.

import { Engine } from './engine.js';

/** Evaluations between two exchanges: src/nest/team.rs EXCHANGE_EVERY (the CLI's, so both make the same nests). */
export const EXCHANGE_EVERY = 10000;
/** Most workers by default: a shop PC's cores; more are asked by the setting only. */
const MOST = 4;
/** Most workers the setting may ask for (src/nest/team.rs MOST). */
const MOST_ASKED = 8;

/**
 * Workers a nest runs in: the machine's cores, at most 4; `kerfcam.nestWorkers` (the page's object, set by
 * a test or the console) or localStorage 'kerfcam.nestWorkers' overrides it (1 to 8).
 */
export function teamSize() {
  let asked = globalThis.kerfcam?.nestWorkers;
  try {
    asked ??= globalThis.localStorage?.getItem('kerfcam.nestWorkers');
  } catch {
    // storage refused (a private window): the machine's count
  }
  const n = Number(asked);
  if (asked != null && Number.isInteger(n) && n >= 1) return Math.min(n, MOST_ASKED);
  return Math.max(1, Math.min(navigator.hardwareConcurrency || 1, MOST));
}

/** Index of the best of `bests` ({lost, sheets, length} or null): fewest left out, sheets, then shortest; the first among equals. */
export function bestOf(bests) {
  let k = -1;
  for (const [i, b] of bests.entries()) {
    if (!b) continue;
    const a = k < 0 ? null : bests[k];
    if (!a || b.lost < a.lost || (b.lost === a.lost && (b.sheets < a.sheets || (b.sheets === a.sheets && b.length < a.length)))) k = i;
  }
  return k;
}

export class NestTeam {
  /**
   * Helper workers beside `engine` (the page's engine worker, which keeps the nest) for `n` workers in all;
   * null when a second worker cannot be made or does not load (the nest then runs in `engine` alone).
   */
  static async make(engine, n) {
    const helpers = [];
    try {
      for (let k = 1; k < n; k++) helpers.push(new Engine());
      await Promise.all(helpers.map((h) => h.ready));
    } catch {
      for (const h of helpers) h.close();
      return null;
    }
    return helpers.length ? new NestTeam(engine, helpers) : null;
  }

  constructor(engine, helpers) {
    this.engines = [engine, ...helpers];
    this.shown = null; // the best nest shown: what Stop keeps
    this.shownTrial = null; // with sheets at a cost: the trial it was nested in ({combination, passed_over})
    this.evaluations = 0; // the team's, as last heard
  }

  /** Workers in the team. */
  get size() {
    return this.engines.length;
  }

  /**
   * Nests `args` (as the worker's nest op takes them); `onProgress` hears the shapes first, then the team's best
   * nest as it improves (its placements when another nest is shown). Resolves with the nest (the engine's
   * last nest), rejects with "cancelled" when stopped.
   */
  async run(args, onProgress, every = EXCHANGE_EVERY) {
    const start = performance.now();
    await this.search(args, onProgress, every);
    const seconds = (performance.now() - start) / 1000;
    return this.engines[0].call('searchFinish', { evaluations: this.evaluations, seconds, labels: args.labels });
  }

  /**
   * Sheets at a cost: nests `args` on the cheapest combination of its sheet sizes, each combination the engine's
   * trials name a team nest (`trial` added to the settings); `onProgress` as `run`'s, each report with the
   * `combination` under trial ({counts, passed_over}: the nest's sheets are its sheets).
   */
  async runCheapest(args, onProgress, every = EXCHANGE_EVERY) {
    const start = performance.now();
    const engine = this.engines[0];
    await engine.call('trialsStart', args);
    let drawn = false; // the shapes go out once, with the first trial
    for (;;) {
      const trial = await engine.call('trialsNext', {});
      if (!trial) break;
      const combination = { counts: trial.combination, passed_over: trial.passed_over };
      await this.search({ ...args, settings: { ...args.settings, ...trial } }, (p) => {
        if (!p.outlines) onProgress({ ...p, combination });
        else if (!drawn) onProgress(p);
        drawn ||= !!p.outlines;
      }, every, trial);
      await engine.call('trialsRecord', { evaluations: this.evaluations });
    }
    const seconds = (performance.now() - start) / 1000;
    return engine.call('trialsFinish', { seconds, labels: args.labels });
  }

  /** The team's search of `args` up to its budget, every worker's best exchanged every `every` evaluations. */
  async search(args, onProgress, every, trial = null) {
    const n = this.engines.length;
    const bests = new Array(n).fill(null); // each worker's best as last heard: { best, flat }
    const evals = new Array(n).fill(0);
    const start = performance.now();
    let from = -1; // the worker whose nest is shown
    const hear = (k) => (p) => {
      if (p.outlines) {
        if (k === 0) onProgress(p);
        return;
      }
      evals[k] = p.evaluations;
      if (p.best) bests[k] = { best: p.best, flat: p.placements };
      const b = bestOf(bests.map((x) => x?.best ?? null));
      if (b < 0) return;
      const { best, flat } = bests[b];
      const redraw = b !== from || (k === b && p.best);
      from = b;
      this.shown = best;
      this.shownTrial = trial && { combination: trial.combination, passed_over: trial.passed_over };
      this.evaluations = evals.reduce((a, e) => a + e, 0);
      onProgress({
        evaluations: this.evaluations, sheets: best.sheets, length: best.length,
        unplaced: best.unplaced.length + best.stopped.length, elapsed_s: (performance.now() - start) / 1000,
        ...(redraw ? { placements: flat } : {}),
      });
    };
    const call = (k, op, a, progress = null) => this.engines[k].call(op, a, progress);
    await Promise.all(this.engines.map((_, k) => call(k, 'searchStart', { ...args, k }, hear(k))).map(async (p, k) => {
      const shapes = await p;
      if (k === 0) onProgress(shapes);
    }));
    let until = 0;
    let answers;
    for (;;) {
      until += every;
      answers = await Promise.all(this.engines.map((_, k) => call(k, 'searchRun', { until }, hear(k))));
      const list = answers.map((a) => a.best);
      await Promise.all(this.engines.map((_, k) => call(k, 'searchAdopt', { bests: list })));
      if (!answers.some((a) => a.more)) break;
    }
    this.evaluations = answers.reduce((a, x) => a + x.evaluations, 0);
  }

  /** Ends the helper workers (the engine's own worker is the caller's to cancel). */
  close() {
    for (const e of this.engines.slice(1)) e.close();
  }
}
