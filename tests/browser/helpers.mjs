// Shared by the single-file and big-file browser tests: the rs274 check of a downloaded program, a file
// drop done inside the page, and a proxy that records any request a browser makes to a host.
// (Not a test file: node --test picks only *.test.mjs here.)

import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import fs from 'node:fs';
import http from 'node:http';
import os from 'node:os';
import path from 'node:path';

export function which(cmd) {
  const r = spawnSync('sh', ['-c', `command -v ${cmd}`], { encoding: 'utf8' });
  return r.status === 0 ? r.stdout.trim() : null;
}

/**
 * `rs274 -g file` run with a HOME of its own. rs274 keeps its tool table in `$HOME/.tool.mmap`, truncated by
 * every run (libtooldata): runs at once under one HOME truncate each other's map, and one dies of SIGBUS or
 * says a tool of the program is not in the tool table (tests/common/mod.rs, run_rs274, has the figures).
 */
export function rs274(file) {
  const home = fs.mkdtempSync(path.join(os.tmpdir(), 'kerfcam-rs274-'));
  try {
    return spawnSync('rs274', ['-g', file], { cwd: path.dirname(file), encoding: 'utf8', input: '', timeout: 60_000, env: { ...process.env, HOME: home } });
  } finally {
    fs.rmSync(home, { recursive: true, force: true });
  }
}

/** Asserts that LinuxCNC's `rs274 -g` reads `file` without a complaint (it exits 0 even on errors). */
export function checkWithRs274(file) {
  if (process.env.KERFCAM_NO_RS274 === '1') return;
  assert.ok(which('rs274'), 'rs274 is not on PATH: install linuxcnc-uspace (scripts/setup.sh test) or set KERFCAM_NO_RS274=1');
  const rs = rs274(file);
  const out = `${rs.stdout}\n${rs.stderr}`;
  assert.equal(rs.signal, null, `rs274 was killed (${rs.signal}):\n${out.slice(-2000)}`);
  const bad = out.split('\n').filter((line) => /error|differs|unknown|bad|cannot|not found/i.test(line));
  assert.deepEqual(bad, [], `rs274 complained:\n${out.slice(-2000)}`);
  assert.equal(rs.status, 0, `rs274 exit status ${rs.status}:\n${out.slice(-2000)}`);
  assert.match(rs.stdout, /PROGRAM_END/);
}

/**
 * In-page code (pass to evaluate with { name, base64 }): drops the bytes as a file named `name` on the
 * page, the way a drag from the file manager does. Returns nothing.
 */
export function dropInPage({ name, base64 }) {
  const data = Uint8Array.from(atob(base64), (c) => c.charCodeAt(0));
  const dt = new DataTransfer();
  dt.items.add(new File([data], name));
  const init = { dataTransfer: dt, bubbles: true, cancelable: true };
  document.body.dispatchEvent(new DragEvent('dragover', init));
  document.body.dispatchEvent(new DragEvent('drop', init));
}

/**
 * An HTTP proxy that answers nothing and records every request sent to it (plain and CONNECT). Browsers
 * pointed at it with no bypass, even for loopback, cannot reach any host without it being seen here.
 */
export async function startTrapProxy() {
  const seen = [];
  const server = http.createServer((req, res) => {
    seen.push(`${req.method} ${req.url}`);
    res.writeHead(403).end();
  });
  server.on('connect', (req, socket) => {
    seen.push(`CONNECT ${req.url}`);
    socket.end('HTTP/1.1 403 Forbidden\r\n\r\n');
  });
  await new Promise((resolve) => server.listen(0, '127.0.0.1', resolve));
  return {
    port: server.address().port,
    seen,
    close: () => new Promise((done) => {
      server.closeAllConnections?.();
      server.close(() => done());
    }),
  };
}

/**
 * Clicks Nest on `page` and waits for the result and its sheet's cut plan on the preview (conditions, not
 * the first answer: a loaded machine may take its time).
 */
export async function nestAndWait(page, timeout = 60_000) {
  // A job still running (a re-plan of the nest shown, after a field changed) or new labels placed on it
  // set lastNest again: the new nest is known by its id (lastNestId), which only a nest result raises.
  await page.waitForFunction(() => !['working', 'planning', 'loading'].includes(document.getElementById('status').dataset.state)
    && !document.getElementById('nest-run').disabled, null, { timeout });
  const before = await page.evaluate(() => {
    window.kerfcam.lastNest = null;
    return window.kerfcam.lastNestId ?? 0;
  });
  await page.click('#nest-run');
  await page.waitForFunction((id) => (window.kerfcam.lastNestId ?? 0) > id && window.kerfcam.lastNest !== null
    && document.getElementById('status').dataset.state === 'ready' && window.kerfcam.lastReport !== null, before, { timeout });
}
