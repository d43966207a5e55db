// kerfcam page side of the engine worker (worker.js): promises for its operations, and Cancel, which
// stops the worker mid-job and starts a fresh one.

import { register, t } from './i18n.js';

register({
  en: { 'engine.load-failed': 'the engine worker failed to load' },
  'pt-BR': { 'engine.load-failed': 'o processo do motor de cálculo não carregou' },
});

// The single-file build (scripts/build-single.mjs) has no worker.js or .wasm file to load: it sets
// globalThis.kerfcamEmbedded = { workerUrl: a blob: URL of the bundled worker (a classic script),
// wasm: the cutting core's bytes, nest: the nester module in base64, decoded by the worker when used }.
const EMBEDDED = globalThis.kerfcamEmbedded ?? null;

export class Engine {
  constructor() {
    this.pending = new Map();
    this.nextId = 1;
    this.generation = 0; // bumped by cancel(): calls made before it never reach the new worker
    this.start();
  }

  start() {
    // The embedded worker is a classic script: Chromium refuses a module worker from a file:// page's blob: URL.
    this.worker = EMBEDDED
      ? new Worker(EMBEDDED.workerUrl)
      : new Worker(new URL('./worker.js', import.meta.url), { type: 'module' });
    this.worker.onmessage = (e) => {
      const { id, ok, result, error, progress } = e.data;
      const p = this.pending.get(id);
      if (!p) return;
      if (progress) {
        p.onProgress?.(progress);
        return;
      }
      this.pending.delete(id);
      if (ok) p.resolve(result);
      else p.reject(new Error(error));
    };
    this.worker.onerror = (e) => {
      e.preventDefault();
      this.failAll(new Error(e.message || t('engine.load-failed')));
    };
    this.ready = this.call('init', EMBEDDED ? { wasm: EMBEDDED.wasm, nest: EMBEDDED.nest } : {});
  }

  failAll(error) {
    for (const p of this.pending.values()) p.reject(error);
    this.pending.clear();
  }

  /**
   * Runs `op` in the worker (once its wasm is loaded); resolves with its result, rejects with its error.
   * `onProgress({stage, count, ms})` hears each pipeline stage as it finishes.
   */
  async call(op, args = {}, onProgress = null, transfer = []) {
    const generation = this.generation;
    if (op !== 'init') await this.ready;
    if (generation !== this.generation) throw cancelledError();
    return new Promise((resolve, reject) => {
      const id = this.nextId++;
      this.pending.set(id, { resolve, reject, onProgress });
      this.worker.postMessage({ id, op, args }, transfer);
    });
  }

  /** Ends the worker for good (a team nest's helper, nest-team.js); every pending call rejects with "cancelled". */
  close() {
    this.generation++;
    this.worker.terminate();
    this.failAll(cancelledError());
  }

  /** Stops whatever the worker is doing; every pending call rejects with "cancelled". */
  cancel() {
    this.generation++;
    this.worker.terminate();
    this.failAll(cancelledError());
    this.start();
  }
}

function cancelledError() {
  const error = new Error('cancelled');
  error.cancelled = true;
  return error;
}
