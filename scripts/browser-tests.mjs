// The browser layer (scripts/test-all.sh, the web chain's last): `node --test tests/browser/` with one chromium shared by
// every test file (issue 40). Launching a browser with a fresh profile per file was a second or more of
// each file; the files now open fresh contexts of this one (tests/browser/harness.mjs, openApp), as
// isolated from one another as fresh profiles. Arguments are passed to `node --test` (default: tests/browser/).
// Two files run at a time (KERFCAM_BROWSER_FILES overrides): one file at a time kept one of this 2-core
// machine's cores mostly idle (a run of 119 tests: 240 s of CPU in 453 s), node's default being the cores
// less one.
//
//   node scripts/browser-tests.mjs [FILES...]

import { spawn } from 'node:child_process';
import { chromium } from 'playwright-core';
import { CHROMIUM_ARGS, which } from '../tests/browser/harness.mjs';

const executablePath = process.env.CHROMIUM || which('chromium');
if (!executablePath) {
  console.error('chromium is not on PATH: run scripts/setup.sh test');
  process.exit(1);
}
const server = await chromium.launchServer({ executablePath, headless: true, args: CHROMIUM_ARGS });
const files = process.argv.slice(2);
const concurrency = Number(process.env.KERFCAM_BROWSER_FILES || 2);
const child = spawn(process.execPath, ['--test', `--test-concurrency=${concurrency}`, ...(files.length ? files : ['tests/browser/'])], {
  stdio: 'inherit',
  env: { ...process.env, KERFCAM_CHROMIUM_WS: server.wsEndpoint() },
});
const code = await new Promise((resolve) => child.on('exit', (c, signal) => resolve(c ?? (signal ? 1 : 0))));
await server.close();
process.exit(code);
