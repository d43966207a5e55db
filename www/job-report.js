// kerfcam job report (issue 42 §4): Sheet mode's job sheet. A page for the job — the part files, each
// part ordered against placed (and why not), the sheets used, the totals over the sheets, the process the
// engine applied, the quote when the Cost panel has prices — then one page per sheet for the floor: its
// map with the copies' labels, its parts with their copies and labels, utilisation, remnant, cut time,
// pierces, lengths, the program file the page downloads for it and its plan's warnings. Each sheet's
// figures are the engine's, from the sheet cut with the page's settings (worker op sheetFigures), as the
// preview cuts the sheet shown. Printed one page each (style.css: .report-page, break-after: page).
// Part names and labels come from files: textContent and attributes only.

import { el } from './app.js';
import { fmtLength, fmtNumber, getLang, register, t } from './i18n.js';
import { formatTime } from './plan.js';
import { sortedWarnings } from './summary.js';
import { quoteTable } from './cost.js';
import { sheetDrawing, svg } from './nest-view.js';

register({
  en: {
    'report.title': 'Job report', 'report.files': 'Part files', 'report.sheets': 'Sheets used',
    'report.placed': 'Copies placed', 'report.placed-of': '{placed} of {asked}', 'report.job-util': 'Utilisation (job)',
    'report.totals': 'Totals over the sheets', 'report.parts': 'Parts ordered and placed', 'report.ordered': 'Ordered',
    'report.placed-col': 'Placed', 'report.missing': 'Not placed', 'report.sheet': 'Sheet {k} of {n}',
    'report.size': 'Size', 'report.size-value': '{w} × {h} mm', 'report.util': 'Utilisation', 'report.remnant': 'Remnant',
    'report.remnant-value': '{w} × {h} mm beyond x = {x} mm ({a} m²)', 'report.no-remnant': 'none kept',
    'report.copies': 'Copies', 'report.used-length': 'Used length', 'report.program': 'Program file',
    'report.map': 'Sheet map: the copies with their labels', 'report.sheet-parts': 'Parts on this sheet',
    'report.labels': 'Labels', 'report.no-labels': 'labels off', 'report.left-out': 'not labelled (does not fit)',
    'report.page': 'page {p} of {n}',
  },
  'pt-BR': {
    'report.title': 'Relatório do trabalho', 'report.files': 'Arquivos de peças', 'report.sheets': 'Chapas usadas',
    'report.placed': 'Cópias colocadas', 'report.placed-of': '{placed} de {asked}', 'report.job-util': 'Aproveitamento (trabalho)',
    'report.totals': 'Totais das chapas', 'report.parts': 'Peças pedidas e colocadas', 'report.ordered': 'Pedidas',
    'report.placed-col': 'Colocadas', 'report.missing': 'Não colocadas', 'report.sheet': 'Chapa {k} de {n}',
    'report.size': 'Tamanho', 'report.size-value': '{w} × {h} mm', 'report.util': 'Aproveitamento', 'report.remnant': 'Retalho',
    'report.remnant-value': '{w} × {h} mm além de x = {x} mm ({a} m²)', 'report.no-remnant': 'nenhum guardado',
    'report.copies': 'Cópias', 'report.used-length': 'Comprimento usado', 'report.program': 'Arquivo do programa',
    'report.map': 'Mapa da chapa: as cópias com suas etiquetas', 'report.sheet-parts': 'Peças nesta chapa',
    'report.labels': 'Etiquetas', 'report.no-labels': 'etiquetas desligadas', 'report.left-out': 'sem etiqueta (não cabe)',
    'report.page': 'página {p} de {n}',
  },
});

const pct = (u) => (Number.isFinite(u) ? `${fmtNumber(100 * u, 1)} %` : '?');
const MAX_WARNINGS = 6; // a sheet's page keeps its map in sight: its warnings beyond these are counted

/**
 * Fills `root` with the report. `job`: { files (names), report (the shown sheet's: the process applied),
 * post, quote (or null), nest (NestRun.report()), programName(k) (the file the page downloads for sheet k) }.
 */
export function fillReport(root, job) {
  const { nest } = job;
  const n = nest.sheets.length;
  const pages = [summaryPage(job)];
  nest.sheets.forEach((s, k) => pages.push(sheetPage(job, s, k)));
  pages.forEach((p, i) => p.append(el('p', t('report.page', { p: fmtNumber(i + 1), n: fmtNumber(n + 1) }), { className: 'report-foot muted small' })));
  root.replaceChildren(...pages);
}

/** A number's text with its raw value kept beside it (data-value), for the reader and for tests. */
const valued = (text, value) => ({ text, value });

/** A job sheet's facts: `rows` [key, text or { text, value }] as a <dl>, each <dd> named by its key (data-key). */
export function factsList(rows, className = 'sheet-facts') {
  const facts = el('dl', '', { className });
  for (const [key, v] of rows) {
    const dd = el('dd', typeof v === 'object' && v !== null ? v.text : v);
    dd.dataset.key = key.slice(key.indexOf('.') + 1);
    if (typeof v === 'object' && v !== null && Number.isFinite(Number(v.value))) dd.dataset.value = String(v.value);
    facts.append(el('dt', t(key)), dd);
  }
  return facts;
}

/** The process the engine applied (the report's `process`, not the form's values) and the post, as facts. */
export function processRows(r, post) {
  const s = r.process || {};
  const chart = s.material ? (s.material.example ? t('sheet.chart-example', { name: s.material.name }) : s.material.name) : '';
  return [
    ['sheet.post', post],
    ['sheet.kerf', fmtLength(s.kerf, 2)],
    ['sheet.feed', `${fmtNumber(s.feed)} mm/min`],
    ['sheet.rapid-speed', `${fmtNumber(s.rapid)} mm/min`],
    ['sheet.pierce-delay', `${fmtNumber(s.pierce_delay, 1)} s`],
    ['sheet.heights', `${fmtLength(s.pierce_height)} / ${fmtLength(s.cut_height)}`],
    ...(chart ? [['sheet.chart', chart]] : []),
  ];
}

/** Warnings as list items, most serious first, grouped with their counts; beyond `max` they are counted. */
export function warningList(warnings, max) {
  const sorted = sortedWarnings(warnings);
  const items = sorted.slice(0, max).map((w) => {
    const times = w.count > 1 ? ` (${t('warnings.count', { n: fmtNumber(w.count), count: w.count })})` : '';
    return el('li', `${t(`severity.${w.severity}`)}: ${w.messages?.[getLang()] ?? w.message}${times}`);
  });
  if (sorted.length > max) items.push(el('li', t('sheet.more', { n: fmtNumber(sorted.length - max) })));
  if (!sorted.length) items.push(el('li', t('sheet.none')));
  return items;
}

function summaryPage(job) {
  const { nest } = job;
  const page = el('section', '', { className: 'report-page report-job' });
  const sum = (key) => nest.sheets.reduce((a, s) => a + (Number(s.plan?.[key]) || 0), 0);
  const rows = [
    ['report.files', job.files.join(', ')],
    ['sheet.date', new Date().toLocaleString(getLang())],
    ['report.sheets', valued(fmtNumber(nest.sheets.length), nest.sheets.length)],
    ['report.placed', valued(t('report.placed-of', { placed: fmtNumber(nest.placed), asked: fmtNumber(nest.asked) }), nest.placed)],
    ['report.job-util', valued(pct(nest.job), nest.job)],
  ];
  const totals = [
    ['sheet.pierces', valued(fmtNumber(sum('pierces')), sum('pierces'))],
    ['sheet.cut', valued(fmtLength(sum('cut_length')), sum('cut_length'))],
    ['sheet.rapid', valued(fmtLength(sum('rapid_length')), sum('rapid_length'))],
    ['sheet.time', valued(formatTime(sum('est_time_s')), sum('est_time_s'))],
  ];
  // Dozens of parts: the job's page prints compact too (its parts and the quote a row each).
  if (nest.parts.length > DENSE_ROWS) page.classList.add('report-dense');
  // A dense page's parts list in two columns side by side: with the quote's row per part below it, a list of
  // dozens of parts in one column pushed the job's page onto a second sheet of paper.
  const dense = page.classList.contains('report-dense');
  const half = dense ? Math.ceil(nest.parts.length / 2) : nest.parts.length;
  const columns = [nest.parts.slice(0, half), nest.parts.slice(half)].filter((c) => c.length);
  const parts = el('div', '', { className: dense ? 'report-columns' : '' });
  parts.append(...columns.map(partsTable));
  const blanks = el('dl', '', { className: 'sheet-blanks' });
  for (const key of ['sheet.operator', 'sheet.material', 'sheet.notes']) blanks.append(el('dt', t(key)), el('dd', ' '));
  const quote = job.quote ? [el('h3', t('sheet.quote')), ...quoteTable(job.quote)] : [];
  page.append(
    el('h2', t('report.title'), { id: 'sheet-title' }), factsList(rows), el('h3', t('report.totals')), factsList(totals),
    factsList(processRows(job.report || {}, job.post)), parts, ...quote, blanks,
  );
  return page;
}

/** The job's parts ordered against placed (and why not) as a table (style.css shows a second column's caption blank). */
function partsTable(list) {
  const parts = el('table', '', { className: 'sheet-table report-parts' });
  parts.append(el('caption', t('report.parts')), el('thead'), el('tbody'));
  const head = el('tr');
  for (const key of ['sheet.nest-part', 'report.ordered', 'report.placed-col', 'report.missing']) head.append(el('th', t(key), { scope: 'col' }));
  parts.tHead.append(head);
  for (const p of list) {
    const tr = el('tr');
    tr.dataset.part = p.name;
    const why = p.unplaced.map((u) => (u.copies ? `${fmtNumber(u.copies)}: ` : '') + (u.reason_text?.[getLang()] ?? u.reason)).join('; ');
    tr.append(el('td', p.name), el('td', p.ordered === null ? '?' : fmtNumber(p.ordered)), el('td', fmtNumber(p.placed)), el('td', why));
    Object.assign(tr.dataset, { ordered: String(p.ordered), placed: String(p.placed) });
    parts.tBodies[0].append(tr);
  }
  return parts;
}

/**
 * A copy's labels as printed: a run of three or more numbered alike (`A1, A2, A3` or `PLATE#4, PLATE#5,
 * PLATE#6`) as its first and last (`A1–A3`), so a sheet of dozens of copies keeps its parts list short.
 */
export function labelRuns(labels) {
  const split = (l) => {
    const m = /^(.*?)(\d+)$/.exec(l);
    return m ? [m[1], Number(m[2])] : [l, NaN];
  };
  const out = [];
  for (let i = 0; i < labels.length;) {
    const [head, n] = split(labels[i]);
    let j = i + 1;
    while (j < labels.length && Number.isFinite(n)) {
      const [h, m] = split(labels[j]);
      if (h !== head || m !== n + (j - i)) break;
      j += 1;
    }
    out.push(j - i >= 3 ? `${labels[i]}–${labels[j - 1]}` : labels.slice(i, j).join(', '));
    i = j;
  }
  return out.join(', ');
}

/** A sheet of this many part rows or copies prints compact (report-dense): one printed page per sheet. */
const DENSE_ROWS = 6;
const DENSE_COPIES = 24;

function sheetPage(job, s, k) {
  const { nest } = job;
  const n = nest.sheets.length;
  const page = el('section', '', { className: 'report-page report-sheet' });
  page.dataset.sheet = String(k);
  const plan = s.plan || {};
  const last = k === n - 1;
  const remnant = last && Number.isFinite(s.crop_x)
    ? t('report.remnant-value', {
      w: fmtNumber(s.width - s.crop_x, 1), h: fmtNumber(s.height, 1), x: fmtNumber(s.crop_x, 1), a: fmtNumber((nest.state.remnant_area ?? 0) / 1e6, 3),
    })
    : t('report.no-remnant');
  const copies = s.parts.reduce((a, p) => a + p.n, 0);
  if (s.parts.length > DENSE_ROWS || copies > DENSE_COPIES) page.classList.add('report-dense');
  const rows = [
    ['report.size', t('report.size-value', { w: fmtNumber(s.width, 1), h: fmtNumber(s.height, 1) })],
    ['report.util', valued(pct(s.utilisation), s.utilisation)],
    ['report.copies', valued(fmtNumber(copies), copies)],
    ['report.used-length', valued(fmtLength(s.used_length), s.used_length)],
    ['report.remnant', remnant],
    ['sheet.pierces', valued(fmtNumber(plan.pierces), plan.pierces)],
    ['sheet.cut', valued(fmtLength(plan.cut_length), plan.cut_length)],
    ['sheet.rapid', valued(fmtLength(plan.rapid_length), plan.rapid_length)],
    ['sheet.time', valued(formatTime(plan.est_time_s), plan.est_time_s)],
    ['report.program', job.programName(k)],
  ];
  const labelsOn = !!nest.state.labels;
  const table = el('table', '', { className: 'sheet-table report-sheet-parts' });
  table.append(el('caption', t('report.sheet-parts')), el('thead'), el('tbody'));
  const head = el('tr');
  for (const key of ['sheet.nest-part', 'report.copies', 'report.labels']) head.append(el('th', t(key), { scope: 'col' }));
  table.tHead.append(head);
  for (const p of s.parts) {
    const tr = el('tr');
    Object.assign(tr.dataset, { part: p.name, copies: String(p.n) });
    const sorted = [...p.labels].sort((a, b) => a.localeCompare(b, undefined, { numeric: true }));
    const labels = !labelsOn ? t('report.no-labels')
      : [labelRuns(sorted), p.labels.length < p.n ? t('report.left-out') : ''].filter(Boolean).join('; ');
    tr.append(el('td', p.name), el('td', fmtNumber(p.n)), el('td', labels, { className: 'report-labels' }));
    table.tBodies[0].append(tr);
  }
  const warnings = el('ul', '', { className: 'sheet-warnings' });
  warnings.append(...warningList(s.warnings, MAX_WARNINGS));
  page.append(
    el('h2', `${t('report.sheet', { k: fmtNumber(k + 1), n: fmtNumber(n) })} · ${job.programName(k)}`),
    factsList(rows), sheetMap(nest.state, k), table, el('h3', t('sheet.warnings')), warnings,
  );
  return page;
}

/**
 * Sheet k's map: the nest view's drawing of the sheet (nest-view.js), the copies' labels written in type
 * a reader can read on paper (the engine's strokes are the labels' real size: 3 to 10 mm on a sheet of
 * metres is a speck on A4), at each label's place.
 */
export function sheetMap(state, k) {
  const figure = el('figure', '', { className: 'report-map' });
  const d = sheetDrawing(state, k, state.outlines || []);
  if (!d) return figure;
  const root = svg('svg', { viewBox: d.viewBox, role: 'img', class: 'report-map-svg' });
  root.style.aspectRatio = d.aspect;
  const title = svg('title');
  title.textContent = t('report.map');
  const flip = svg('g', { transform: 'scale(1 -1)' });
  flip.append(...d.nodes.filter((node) => !node.classList.contains('nest-label') && !node.classList.contains('nest-crop-grip')));
  const texts = svg('g', { class: 'report-label-text' });
  const [, , vw, vh] = d.viewBox.split(' ').map(Number);
  for (const l of state.labels?.labels || []) {
    if (l.sheet !== k) continue;
    const xs = l.strokes.flatMap((p) => p.filter((_, j) => j % 2 === 0));
    const ys = l.strokes.flatMap((p) => p.filter((_, j) => j % 2 === 1));
    if (!xs.length) continue;
    const x = (Math.min(...xs) + Math.max(...xs)) / 2;
    const y = (Math.min(...ys) + Math.max(...ys)) / 2;
    // The label's own height and reading direction (the engine fitted it inside the part, clear of holes),
    // no smaller than a hundredth of the sheet: what stays readable on A4.
    const size = Math.max(l.height, Math.max(vw, vh) / 100);
    const text = svg('text', {
      x, y: -y, 'font-size': size, 'text-anchor': 'middle', 'dominant-baseline': 'central', 'data-label': l.text,
      transform: `rotate(${-(l.angle || 0)} ${x} ${-y})`,
    });
    text.textContent = l.text;
    texts.append(text);
  }
  root.append(title, flip, texts);
  figure.append(root, el('figcaption', t('report.map')));
  figure.dataset.copies = String(d.drawn);
  return figure;
}
