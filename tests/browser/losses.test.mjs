// What the program takes from the parts, shown before the download (issue 45 §3), in Debian's headless
// chromium, as an operator meets it: two 40 × 30 parts drawn 1 mm apart, cut with a 1.5 mm kerf, no
// verification asked. The two parts the kerf eats into are outlined in red on the preview (and only
// they: a third part far away is not), with squares where the cut comes within half the kerf; the
// warning that says so is first in the list; the Download button says "cuts into 2 parts" until the
// warning's "show the parts" is clicked, then the plain words; a new plan with another loss asks again,
// the same loss re-planned does not. Downloading is never blocked. Screenshots at 1366 × 768 and
// 1920 × 1080, in English and Portuguese, go to tests/out/ to be looked at.
//
//   node --test tests/browser/losses.test.mjs

import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { after, before, test } from 'node:test';
import { corpus, downloadProgram, openApp, repoRoot, untilReady } from './harness.mjs';

const OUT = path.join(repoRoot, 'tests', 'out');

/** Two 40 × 30 squares `gap` mm apart and a 10 mm square at x 200 (in mm), as LINEs. */
function drawing(gap, name = `two-parts-${gap}.dxf`) {
  const out = ['0', 'SECTION', '2', 'HEADER', '9', '$INSUNITS', '70', '4', '0', 'ENDSEC', '0', 'SECTION', '2', 'ENTITIES'];
  const square = (x0, y0, w, h) => {
    const p = [[x0, y0], [x0 + w, y0], [x0 + w, y0 + h], [x0, y0 + h], [x0, y0]];
    for (let i = 0; i < 4; i++) out.push('0', 'LINE', '8', '0', '10', p[i][0], '20', p[i][1], '11', p[i + 1][0], '21', p[i + 1][1]);
  };
  square(0, 0, 40, 30);
  square(40 + gap, 0, 40, 30);
  square(200, 0, 10, 10);
  out.push('0', 'ENDSEC', '0', 'EOF');
  return { name, mimeType: 'application/dxf', buffer: Buffer.from(out.join('\n') + '\n') };
}

/**
 * Overlay pixels of the marks' strong red (#e00000) in three boxes of the drawing (mm): around the two
 * close parts, and around the far square; and of the squares' magenta.
 */
function marks(page) {
  return page.evaluate(() => {
    const c = document.getElementById('overlay');
    const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
    const dpr = c.width / c.getBoundingClientRect().width;
    const count = ([x0, y0, x1, y1], test) => {
      const [ax, ay] = window.kerfcam.screenOf(x0, y1).map((v) => Math.round(v * dpr));
      const [bx, by] = window.kerfcam.screenOf(x1, y0).map((v) => Math.round(v * dpr));
      let n = 0;
      for (let y = Math.max(0, ay); y < Math.min(c.height, by); y++) {
        for (let x = Math.max(0, ax); x < Math.min(c.width, bx); x++) {
          const i = 4 * (y * c.width + x);
          if (d[i + 3] > 200 && test(d[i], d[i + 1], d[i + 2])) n++;
        }
      }
      return n;
    };
    const red = (r, g, b) => r > 200 && g < 30 && b < 30;
    const magenta = (r, g, b) => r > 200 && g < 60 && b > 60 && b < 150;
    return {
      left: count([-3, -3, 20, 33], red), right: count([61, -3, 84, 33], red),
      far: count([195, -5, 215, 15], red), between: count([39, 5, 42, 25], magenta),
    };
  });
}

const label = (page) => page.$eval('#download', (b) => ({ text: b.textContent, loss: b.dataset.loss }));
const warnings = (page) => page.$$eval('#warnings li', (ls) => ls.map((l) => ({ code: l.dataset.code, loss: l.dataset.loss || null })));

let app;
let page;

before(async () => {
  app = await openApp({ viewport: { width: 1366, height: 768 } });
  page = app.page;
});

after(async () => {
  await app?.close();
});

test('the parts the kerf eats into are marked, warned first, and said on the Download button until seen', async () => {
  await untilReady(page, () => page.setInputFiles('#file-input', drawing(1)));
  const report = await page.evaluate(() => window.kerfcam.lastReport);
  assert.equal(report.verification, undefined, 'no verification asked');
  const close = report.warnings.find((w) => w.code === 'parts-closer-than-kerf');
  assert.ok(close, JSON.stringify(report.warnings.map((w) => w.code)));
  assert.equal(close.loss, 'cuts-into');
  assert.equal(close.loops.length, 2, JSON.stringify(close.loops));

  // The warning first in the list, set apart, with its button.
  const list = await warnings(page);
  assert.equal(list[0].code, 'parts-closer-than-kerf', JSON.stringify(list));
  assert.equal(list[0].loss, 'cuts-into');
  assert.equal(await page.isVisible('#warnings li[data-code="parts-closer-than-kerf"] .show-loss'), true);
  // At a glance, the warnings' count beside the file's name (the long Download label leaves the strip less room).
  assert.deepEqual(await page.$$eval('#glance dd', (dds) => dds.slice(0, 2).map((d) => [d.dataset.key, d.dataset.loss ?? null])),
    [['file', null], ['warnings', 'true']]);

  // Marked on the preview, without --verify: the two close parts in red, the far one not; squares between.
  const m = await marks(page);
  assert.ok(m.left > 50 && m.right > 50, `red outline pixels: ${JSON.stringify(m)}`);
  assert.equal(m.far, 0, `the far part is not marked: ${JSON.stringify(m)}`);
  assert.ok(m.between > 5, `squares where the kerf reaches across: ${JSON.stringify(m)}`);
  assert.equal(await page.isVisible('#legend-loss'), true);

  // The Download button says it, and downloads all the same.
  assert.deepEqual(await label(page), { text: 'Download G-code (cuts into 2 parts)', loss: 'unseen' });
  const saved = await downloadProgram(page, app.downloadDir);
  assert.equal(fs.readFileSync(saved, 'utf8'), await page.evaluate(() => window.kerfcam.lastGcode), 'what is previewed is downloaded');
  assert.equal((await label(page)).loss, 'unseen', 'a download is not looking');

  // In Portuguese, the same words translated.
  await page.selectOption('#lang', 'pt-BR');
  assert.deepEqual(await label(page), { text: 'Baixar o G-code (invade 2 peças)', loss: 'unseen' });
  fs.mkdirSync(OUT, { recursive: true });
  await page.screenshot({ path: path.join(OUT, 'losses-1366x768-pt-BR-unseen.png') });
  await page.selectOption('#lang', 'en');
  await page.screenshot({ path: path.join(OUT, 'losses-1366x768-en-unseen.png') });

  // Seen: the warning's button shows the parts; the label goes back to the plain words.
  await page.click('#warnings li[data-code="parts-closer-than-kerf"] .show-loss');
  assert.deepEqual(await label(page), { text: 'Download G-code', loss: 'seen' });
  await page.waitForTimeout(800); // the preview's raster follows the new view (the overlay is drawn at once)
  await page.screenshot({ path: path.join(OUT, 'losses-1366x768-en-seen.png') });
  await page.selectOption('#lang', 'pt-BR');
  assert.equal((await label(page)).text, 'Baixar o G-code');
  await page.selectOption('#lang', 'en');

  // The same loss re-planned (another feed) stays seen; another loss (the parts 0.5 mm apart in a new
  // file) asks again; parts apart have nothing to say.
  await untilReady(page, async () => {
    await page.fill('#feed', '2500');
    await page.press('#feed', 'Enter');
  });
  assert.equal((await label(page)).loss, 'seen');
  await untilReady(page, () => page.setInputFiles('#file-input', drawing(0.5)));
  assert.deepEqual(await label(page), { text: 'Download G-code (cuts into 2 parts)', loss: 'unseen' });
  await untilReady(page, () => page.setInputFiles('#file-input', drawing(20)));
  assert.deepEqual(await label(page), { text: 'Download G-code', loss: 'none' });
  assert.equal(await page.$$eval('#glance dd', (dds) => dds.at(-1).dataset.key), 'warnings', 'in its place when nothing is lost');
  const apart = await marks(page);
  assert.equal(apart.left + apart.right + apart.far + apart.between, 0, JSON.stringify(apart));
  assert.equal(await page.isVisible('#legend-loss'), false);
  assert.deepEqual(app.pageErrors, []);
});

test('at 1366 × 768 a long loss label leaves the figures at a glance whole or out of sight, never cut', async () => {
  // pumpenteile: 7 parts cut into and 6 contours not cut, the longest label of the corpus's plasma drawings.
  const real = { name: 'pumpenteile.dxf', mimeType: 'application/dxf', buffer: fs.readFileSync(corpus('dxf2gcode-plasma', 'pumpenteile.dxf')) };
  await untilReady(page, () => page.setInputFiles('#file-input', real));
  for (const lang of ['en', 'pt-BR']) {
    await page.selectOption('#lang', lang);
    assert.match((await label(page)).text, /\(.*7.*6.*\)$/);
    const seen = await page.$eval('#glance', (g) => {
      const strip = g.getBoundingClientRect();
      return [...g.children].map((d) => {
        const b = d.getBoundingClientRect();
        const dd = d.querySelector('dd');
        return { key: dd.dataset.key, shown: b.height > 0 && b.top < strip.bottom - 1, whole: b.right <= strip.right + 0.5 && dd.scrollWidth <= dd.clientWidth + 1 };
      });
    });
    const shown = seen.filter((f) => f.shown);
    assert.deepEqual(shown.filter((f) => !f.whole), [], `${lang}: figures cut at the strip's end: ${JSON.stringify(seen)}`);
    assert.deepEqual(shown.slice(0, 3).map((f) => f.key), ['file', 'warnings', 'parts'], `${lang}: ${JSON.stringify(seen)}`);
  }
  await page.selectOption('#lang', 'en');
  assert.deepEqual(app.pageErrors, []);
});

test('the Files list says which programs take material, and Download all says it of the zip', async () => {
  // The files of the tests above, kept in the list: two-parts-1 and -0.5 (the kerf eats into both
  // squares), two-parts-20 (apart) and pumpenteile (7 parts cut into, 6 contours not cut).
  await page.waitForFunction(() => {
    const rows = [...document.querySelectorAll('#jobs li.job')];
    return rows.length === 4 && rows.every((li) => li.dataset.status === 'done');
  }, null, { timeout: 120_000 });
  const rows = () => page.$$eval('#jobs li.job', (ls) => Object.fromEntries(ls.map((l) => [l.dataset.name, { loss: l.dataset.loss ?? null, status: l.querySelector('.job-status').textContent }])));
  let r = await rows();
  assert.equal(r['two-parts-20.dxf'].loss, null, JSON.stringify(r));
  assert.doesNotMatch(r['two-parts-20.dxf'].status, /cuts into|not cut/);
  assert.equal(r['two-parts-1.dxf'].loss, 'true');
  assert.match(r['two-parts-1.dxf'].status, /^done · \d+ pierces, \d+ warnings? · cuts into 2 parts$/);
  assert.match(r['pumpenteile.dxf'].status, / · cuts into 7 parts, 6 contours not cut$/);
  const colour = await page.$eval('#jobs li[data-name="two-parts-1.dxf"] .job-status', (e) => getComputedStyle(e).color);
  assert.notEqual(colour, await page.$eval('#jobs li[data-name="two-parts-20.dxf"] .job-status', (e) => getComputedStyle(e).color), 'not the green of a plain done');
  // The zip downloads all the same, and says which of its programs take material.
  const [zip] = await Promise.all([page.waitForEvent('download'), page.click('#download-all')]);
  assert.equal(zip.suggestedFilename(), 'kerfcam-programs.zip');
  const said = await page.textContent('#job-message');
  assert.match(said, /^In the zip, programs that take material from parts: /);
  for (const name of ['two-parts-1.dxf (cuts into 2 parts)', 'two-parts-0.5.dxf (cuts into 2 parts)', 'pumpenteile.dxf (cuts into 7 parts, 6 contours not cut)']) {
    assert.ok(said.includes(name), `${name} in: ${said}`);
  }
  assert.ok(!said.includes('two-parts-20'), said);
  await page.selectOption('#lang', 'pt-BR');
  r = await rows();
  assert.match(r['pumpenteile.dxf'].status, /^pronto · .* · invade 7 peças, 6 contornos não cortados$/);
  await page.selectOption('#lang', 'en');
  assert.deepEqual(app.pageErrors, []);
});

test('1920 × 1080, both languages: the marked parts and the button in sight', async () => {
  const big = await openApp({ viewport: { width: 1920, height: 1080 } });
  try {
    for (const lang of ['en', 'pt-BR']) {
      await big.page.selectOption('#lang', lang);
      await untilReady(big.page, () => big.page.setInputFiles('#file-input', drawing(1, `two-parts-${lang}.dxf`)));
      const b = await big.page.$eval('#download', (e) => {
        const r = e.getBoundingClientRect();
        return { top: r.top, bottom: r.bottom, cut: e.scrollWidth > e.clientWidth + 1 };
      });
      assert.ok(b.top >= 0 && b.bottom <= 1080 && !b.cut, JSON.stringify(b));
      await big.page.screenshot({ path: path.join(OUT, `losses-1920x1080-${lang}-unseen.png`) });
    }
    assert.deepEqual(big.pageErrors, []);
  } finally {
    await big.close();
  }
});
