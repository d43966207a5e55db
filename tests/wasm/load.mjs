// The page's two wasm modules as it loads them: the glue scripts/build-wasm.sh wrote to www/pkg
// (`wasm-bindgen --target web`), each started with its wasm's bytes read from disk (no fetch under
// Node), so these tests run exactly what the page runs. Build www/pkg first: bash scripts/build-wasm.sh.

import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import * as coreGlue from '../../www/pkg/kerfcam.js';
import * as nestGlue from '../../www/pkg/kerfcam_nest.js';

const ROOT = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');
const PKG = path.join(ROOT, 'www', 'pkg');
/** The shared fixtures, read in place (/work/shared/fixtures beside the repository). */
const FIXTURES = path.join(ROOT, '..', 'shared', 'fixtures');

/** Starts a module as the page's worker does (its default export given the wasm's bytes), once. */
async function started(glue, wasm) {
  await glue.default({ module_or_path: fs.readFileSync(path.join(PKG, wasm)) });
  return glue;
}

/** The cutting core (kerfcam.js): what the page loads at once and runs a drawing through. */
export const core = () => started(coreGlue, 'kerfcam_bg.wasm');

/** The nester module (kerfcam_nest.js): what Sheet mode loads when it first needs the nester. */
export const nest = () => started(nestGlue, 'kerfcam_nest_bg.wasm');

/** A fixture's bytes. */
export const fixture = (name) => new Uint8Array(fs.readFileSync(path.join(FIXTURES, name)));

/** A text's UTF-8 bytes (what the Rust tests' `as_bytes()` gave). */
export const utf8 = (text) => new TextEncoder().encode(text);

/** The page's cutting settings: kerf, tolerance 0.001 mm and feed 1500 mm/min. */
export const settings = (kerf) => ({ kerf, tolerance: 0.001, feed: 1500 });

/** A job's report, parsed. */
export const report = (job) => JSON.parse(job.report_json());

/**
 * Calls `f` and asserts the API refused it as the page hears a refusal: a thrown Error with a message
 * (a JsError), not a wasm trap (a panic, which kills the page's module). Returns the message.
 */
export function refused(f) {
  try {
    f();
  } catch (e) {
    assert.ok(e instanceof Error && !(e instanceof WebAssembly.RuntimeError), `not a refusal: ${e}`);
    assert.ok(e.message.length > 0, 'a refusal without a message');
    return e.message;
  }
  assert.fail('not refused');
}
