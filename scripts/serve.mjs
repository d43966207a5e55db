// Dependency-free static server for www/ (the page and the wasm built into www/pkg).
//
//   node scripts/serve.mjs            -> http://localhost:8080/   (PORT and HOST override)
//   import { startServer } from './serve.mjs';
//   const { url, close } = await startServer(0);   // tests: any free port
//
// It listens on the loopback interface only unless HOST says otherwise, serves GET and HEAD,
// never a file outside www/, and sends `Cache-Control: no-cache` so a rebuilt wasm is picked up.

import fs from 'node:fs';
import http from 'node:http';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const ROOT = fs.realpathSync(fileURLToPath(new URL('../www/', import.meta.url)));

const TYPES = {
  '.html': 'text/html; charset=utf-8',
  '.js': 'text/javascript; charset=utf-8',
  '.mjs': 'text/javascript; charset=utf-8',
  '.css': 'text/css; charset=utf-8',
  '.json': 'application/json; charset=utf-8',
  '.wasm': 'application/wasm',
  '.svg': 'image/svg+xml',
  '.png': 'image/png',
  '.ico': 'image/x-icon',
  '.txt': 'text/plain; charset=utf-8',
  '.ts': 'text/plain; charset=utf-8',
  '.map': 'application/json; charset=utf-8',
};

/** Maps a request path to a file inside ROOT, or null when it is not one. */
function resolveFile(urlPath) {
  let decoded;
  try {
    decoded = decodeURIComponent(urlPath.split('?')[0].split('#')[0]);
  } catch {
    return null; // malformed %-escape
  }
  if (decoded.includes('\0')) return null;
  let file = path.resolve(ROOT, '.' + path.posix.normalize('/' + decoded));
  if (!isInside(file)) return null;
  try {
    if (fs.statSync(file).isDirectory()) file = path.join(file, 'index.html');
    const real = fs.realpathSync(file); // also refuses symlinks pointing out of www/
    return isInside(real) && fs.statSync(real).isFile() ? real : null;
  } catch {
    return null;
  }
}

function isInside(file) {
  return file === ROOT || file.startsWith(ROOT + path.sep);
}

/**
 * While scripts/build-wasm.sh --serve (npm start) is still building the nester module, www/pkg/.nester-pending
 * holds that build's process id: the nester's files (kerfcam_nest.js, kerfcam_nest_bg.wasm) are then held back
 * until the build ends, so Sheet mode's first request waits for the new module instead of getting an old one or
 * none. A marker whose process is gone (a build that was stopped) holds nothing back.
 */
const PENDING = path.join(ROOT, 'pkg', '.nester-pending');
const FAILED = path.join(ROOT, 'pkg', '.nester-failed');
const HELD = /^\/pkg\/kerfcam_nest[._]/;

function nesterPending(marker) {
  let pid;
  try {
    pid = Number(fs.readFileSync(marker, 'utf8').trim());
  } catch {
    return false;
  }
  if (!Number.isInteger(pid) || pid <= 0) return false;
  try {
    process.kill(pid, 0);
    return true;
  } catch (e) {
    return e.code === 'EPERM'; // alive, another user's
  }
}

/** Resolves once the nester module is built (or its build is gone); polls, as fs.watch misses some renames. */
function nesterBuilt(res, marker) {
  return new Promise((resolve) => {
    const check = () => {
      if (res.destroyed || !nesterPending(marker)) resolve();
      else setTimeout(check, 250);
    };
    check();
  });
}

/** `pending`, `failed`: the markers' paths (tests give their own). */
async function handle(req, res, { pending = PENDING, failed = FAILED } = {}) {
  const held = HELD.test((req.url || '/').split('?')[0]);
  if (held && nesterPending(pending)) {
    await nesterBuilt(res, pending);
    if (res.destroyed) return;
  }
  if (held && fs.existsSync(failed)) {
    res.writeHead(503, { 'Content-Type': 'text/plain; charset=utf-8', 'Cache-Control': 'no-cache' });
    res.end(fs.readFileSync(failed, 'utf8'));
    return;
  }
  if (req.method !== 'GET' && req.method !== 'HEAD') {
    res.writeHead(405, { Allow: 'GET, HEAD', 'Content-Type': 'text/plain; charset=utf-8' });
    res.end('method not allowed\n');
    return;
  }
  const file = resolveFile(req.url || '/');
  if (!file) {
    res.writeHead(404, { 'Content-Type': 'text/plain; charset=utf-8', 'Cache-Control': 'no-cache' });
    res.end('not found\n');
    return;
  }
  res.writeHead(200, {
    'Content-Type': TYPES[path.extname(file).toLowerCase()] || 'application/octet-stream',
    'Content-Length': fs.statSync(file).size,
    'Cache-Control': 'no-cache',
    'X-Content-Type-Options': 'nosniff',
  });
  if (req.method === 'HEAD') {
    res.end();
    return;
  }
  fs.createReadStream(file)
    .on('error', () => res.destroy())
    .pipe(res);
}

/**
 * Starts serving www/ on `port` (0 = any free port); `markers` ({ pending, failed }) overrides where the nester
 * build's markers are looked for.
 * Resolves to { server, url, close } where close() resolves once the server has stopped.
 */
export function startServer(port = 8080, host = '127.0.0.1', markers = {}) {
  const server = http.createServer((req, res) => handle(req, res, markers).catch(() => res.destroy()));
  return new Promise((resolve, reject) => {
    server.once('error', reject);
    server.listen(port, host, () => {
      server.off('error', reject);
      const { port: actual } = server.address();
      const url = `http://${host.includes(':') ? `[${host}]` : host}:${actual}/`;
      const close = () =>
        new Promise((done) => {
          server.closeAllConnections?.();
          server.close(() => done());
        });
      resolve({ server, url, close });
    });
  });
}

const isMain = process.argv[1] && path.resolve(process.argv[1]) === fileURLToPath(import.meta.url);
if (isMain) {
  const port = Number(process.env.PORT ?? 8080);
  const host = process.env.HOST || '127.0.0.1';
  if (!fs.existsSync(path.join(ROOT, 'pkg', 'kerfcam.js'))) {
    console.warn('warning: www/pkg/kerfcam.js is missing; run `npm run build:wasm` first');
  }
  startServer(port, host).then(
    ({ server }) => {
      const shown = host === '127.0.0.1' ? 'localhost' : host;
      console.log(`kerfcam: serving www/ at http://${shown}:${server.address().port}/  (Ctrl+C to stop)`);
      if (nesterPending(PENDING)) console.log('kerfcam: the nester module (Sheet mode) is still being built; Sheet mode waits for it');
    },
    (err) => {
      console.error(
        err.code === 'EADDRINUSE'
          ? `error: port ${port} is already in use; try PORT=8081 npm start`
          : `error: ${err.message}`,
      );
      process.exit(1);
    },
  );
}
