// The page on a shop PC (issue 19 item 1): at 1366 × 768 (a shop laptop) and 1920 × 1080, in English and
// Portuguese, with six files open (one refused) and the orders compared. Screenshots go to tests/out/
// (git-ignored) to be looked at; the test asserts what a person would see wrong in them: a select or
// button whose text is cut, a Compare table wider than its box, the summary out of sight, the Files list
// hiding jobs, a toolbar that wraps, a word broken in two, the post editor's Save out of reach.
//
//   node --test tests/browser/layout.test.mjs      (KERFCAM_SHOTS=prefix names the screenshots)

import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { test } from 'node:test';
import { corpus, fixture, openApp, repoRoot, untilReady } from './harness.mjs';

const OUT = path.join(repoRoot, 'tests', 'out');
const PREFIX = process.env.KERFCAM_SHOTS || 'layout';
const FILES = [
  corpus('dxf2gcode-plasma', '2-test-layers-nested.dxf'),
  fixture('seed000-plate-6-holes.dxf'), fixture('seed003-grid-3x2.dxf'), fixture('seed000-figure1.dxf'),
  fixture('seed002-figure4.dxf'),
];
const BROKEN = { name: 'not-a-drawing.dxf', mimeType: 'application/dxf', buffer: Buffer.from('0\nSECTION\n2\nENTITIES\n0\nLINE\n10\nx\n') };

/** In the page: every visible control whose text does not fit its box. */
function clippedControls() {
  const ctx = document.createElement('canvas').getContext('2d');
  const visible = (e) => e.getClientRects().length && getComputedStyle(e).visibility !== 'hidden' && !e.closest('[hidden], dialog:not([open]), details:not([open]) > :not(summary)');
  const out = [];
  for (const e of document.querySelectorAll('select, button')) {
    if (!visible(e)) continue;
    const name = e.id || e.textContent.trim().slice(0, 30);
    if (e.scrollWidth > e.clientWidth + 1) out.push(`${name}: scrollWidth ${e.scrollWidth} > ${e.clientWidth}`);
    if (e.tagName !== 'SELECT') continue;
    // Any option can be chosen: the longest must fit beside the arrow (≈ 20 px), inside the padding.
    const s = getComputedStyle(e);
    ctx.font = `${s.fontWeight} ${s.fontSize} ${s.fontFamily}`;
    const room = e.clientWidth - parseFloat(s.paddingLeft) - parseFloat(s.paddingRight) - 20;
    for (const o of e.options) {
      const w = ctx.measureText(o.textContent).width;
      if (w > room) out.push(`${name}: option "${o.textContent}" ${Math.ceil(w)} px in ${Math.floor(room)} px`);
    }
  }
  return out;
}

/**
 * In the page: words of `selector`'s text broken across two lines although they would fit on one (as
 * "$MEASUREM ENT" was). A break after a hyphen is a word's own break point; a word wider than its box
 * (a long file name) has to break.
 */
function brokenWords(selector) {
  const out = [];
  for (const root of document.querySelectorAll(selector)) {
    if (!root.getClientRects().length) continue;
    const walker = document.createTreeWalker(root, NodeFilter.SHOW_TEXT);
    for (let n = walker.nextNode(); n; n = walker.nextNode()) {
      const room = n.parentElement.closest('dd, li, p, h2, h3, div, button, span')?.clientWidth ?? Infinity;
      for (const m of n.data.matchAll(/[^\s-]+-?/g)) {
        const r = document.createRange();
        r.setStart(n, m.index);
        r.setEnd(n, m.index + m[0].length);
        const rects = [...r.getClientRects()].filter((q) => q.width > 0);
        const width = rects.reduce((w, q) => w + q.width, 0);
        if (new Set(rects.map((q) => Math.round(q.top))).size > 1 && width < room) out.push(m[0]);
      }
    }
  }
  return out;
}

const box = (page, sel) => page.$eval(sel, (e) => {
  const r = e.getBoundingClientRect();
  return { top: r.top, bottom: r.bottom, left: r.left, right: r.right, width: r.width, height: r.height };
});

// The two sizes of the issue in both languages, and the narrowest and widest screens it names in Portuguese
// (the longer texts).
const SIZES = [[1366, 768, ['en', 'pt-BR']], [1920, 1080, ['en', 'pt-BR']], [1280, 800, ['pt-BR']], [2560, 1440, ['pt-BR']]];
for (const [width, height, langs] of SIZES) {
  for (const lang of langs) {
    test(`${width} × ${height}, ${lang}: nothing clipped, the summary in sight, the preview the biggest thing`, async () => {
      const app = await openApp({ viewport: { width, height } });
      const { page } = app;
      const shot = (name) => page.screenshot({ path: path.join(OUT, `${PREFIX}-${width}x${height}-${lang}-${name}.png`) });
      fs.mkdirSync(OUT, { recursive: true });
      try {
        await page.selectOption('#lang', lang);
        await page.waitForFunction((l) => document.documentElement.lang === l, lang);
        await shot('empty');
        // The tagline of the empty page is whole (it was cut with an ellipsis).
        const tagline = await page.$$eval('[data-i18n="page.tagline"]', (els) => els.filter((e) => e.getClientRects().length)
          .map((e) => ({ text: e.textContent, cut: e.scrollWidth > e.clientWidth + 1 || e.scrollHeight > e.clientHeight + 1 })));
        assert.ok(tagline.length, 'the tagline is shown on the empty page');
        assert.deepEqual(tagline.filter((t) => t.cut), [], 'the tagline is cut');
        assert.deepEqual(await page.evaluate(clippedControls), [], 'controls with their text cut (empty page)');

        const files = FILES.map((f) => ({ name: path.basename(f), mimeType: 'application/dxf', buffer: fs.readFileSync(f) }));
        await untilReady(page, () => page.setInputFiles('#file-input', [...files, BROKEN]));
        await page.waitForFunction(() => {
          const rows = [...document.querySelectorAll('#jobs li.job')];
          return rows.length === 6 && rows.every((li) => ['done', 'error', 'truncated'].includes(li.dataset.status));
        }, null, { timeout: 60_000 });
        await shot('job');
        assert.deepEqual(await page.evaluate(clippedControls), [], 'controls with their text cut');

        // The summary (parts, holes, size, time, warnings) in sight without scrolling, near the top.
        const strip = await box(page, '#glance');
        for (const key of ['parts', 'holes', 'size', 'est-time', 'warnings']) {
          const b = await box(page, `#glance [data-key="${key}"]`);
          assert.ok(b.height > 0 && b.top >= 0 && b.bottom <= height / 3, `summary ${key} near the top: ${JSON.stringify(b)}`);
          assert.ok(b.right <= strip.right + 0.5, `summary ${key} cut off the strip's end: ${JSON.stringify(b)}`);
        }
        assert.equal(await page.evaluate(() => document.scrollingElement.scrollTop), 0);

        // The preview is the biggest thing on screen.
        const stage = await box(page, '#stage');
        const side = await box(page, '.side');
        assert.ok(stage.width * stage.height > 0.45 * width * height, `preview ${Math.round(stage.width)} × ${Math.round(stage.height)}`);
        assert.ok(stage.width > 2 * side.width, `preview ${Math.round(stage.width)} px wide beside a ${Math.round(side.width)} px sidebar`);
        // The sidebar grows with the screen.
        assert.ok(side.width >= 0.22 * width || side.width >= 500, `sidebar ${Math.round(side.width)} px at ${width} px`);

        // Every file in the list, the refused one too, without scrolling the list itself.
        const jobs = await page.$eval('#jobs', (ul) => ({ scroll: ul.scrollHeight, client: ul.clientHeight, error: !!ul.querySelector('li[data-status="truncated"], li[data-status="error"]') }));
        assert.ok(jobs.error, 'the refused file is listed');
        assert.ok(jobs.scroll <= jobs.client + 1, `the Files list hides jobs: ${jobs.scroll} > ${jobs.client}`);

        // The toolbar on one line; no word of the summary broken across two lines.
        const rows = await page.$$eval('.toolbar > *', (els) => new Set(els.filter((e) => e.getClientRects().length)
          .map((e) => Math.round(e.getBoundingClientRect().top + e.getBoundingClientRect().height / 2))).size);
        assert.equal(rows, 1, 'the toolbar wraps');
        const spill = await page.$eval('.toolbar', (bar) => [...bar.children].filter((e) => e.getClientRects().length
          && e.getBoundingClientRect().right > bar.getBoundingClientRect().right + 0.5).map((e) => e.id || e.textContent));
        assert.deepEqual(spill, [], 'toolbar items past its end');
        assert.deepEqual(await page.evaluate(brokenWords, '#summary, #glance, .toolbar, .bar, #warnings'), [], 'words broken across lines');

        // The orders compared: under the preview, every column in sight (no horizontal scroll), the preview still big.
        await page.click('#compare');
        await page.waitForSelector('#comparison tbody tr');
        await page.evaluate(() => document.activeElement?.blur());
        await shot('compare');
        const fit = await page.$eval('#comparison', (t) => ({ table: t.scrollWidth, box: t.parentElement.clientWidth }));
        assert.ok(fit.table <= fit.box, `the Compare table is ${fit.table} px in a ${fit.box} px box`);
        const cmp = await box(page, '#comparison');
        assert.ok(cmp.right <= width && cmp.left >= 0 && cmp.bottom <= height, `the Compare table is on screen: ${JSON.stringify(cmp)}`);
        const shrunk = await box(page, '#stage');
        assert.ok(shrunk.width * shrunk.height > 0.3 * width * height, `preview beside the table ${Math.round(shrunk.width)} × ${Math.round(shrunk.height)}`);
        assert.deepEqual(await page.evaluate(clippedControls), [], 'controls with their text cut (compare)');

        // The post editor: big fields, Save in reach without scrolling.
        await page.click('#post-edit');
        await page.waitForSelector('#post-dialog[open]');
        await shot('post-editor');
        const save = await box(page, '#post-form button[type=submit]');
        assert.ok(save.bottom <= height && save.top >= 0, `Save is on screen: ${JSON.stringify(save)}`);
        const header = await box(page, '#pf-header');
        assert.ok(header.height >= 70 && header.width >= 300, `the header field is ${Math.round(header.width)} × ${Math.round(header.height)}`);
        assert.deepEqual(await page.evaluate(clippedControls), [], 'controls with their text cut (post editor)');
        await page.click('#post-cancel');
        assert.deepEqual(app.pageErrors.map(String), []);
      } finally {
        await app.close();
      }
    });
  }
}
