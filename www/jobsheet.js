// kerfcam job sheet (issue 6 §5): one printable page for the operator at the table, after paper
// 001's listings: the file, units, parts and holes, pierces, cut and rapid length, estimated time,
// post, the process the engine applied (kerf, feed, rapid, delay, heights, the cut-chart entry: the report's
// `process`, not the form's values), the plan with its sequence numbers, the pierce points in order, and the warnings.
// Printing uses the print style sheet (style.css, @media print): only the sheet is printed.
// Everything from the file (name, layer names in warnings) is textContent.

import { $, app, messageOf, showError, state, ui } from './app.js';
import { programName } from './batch.js';
import { sheetName } from './sheet.js';
import { fmtLength, fmtNumber, getLang, onLangChange, register, t } from './i18n.js';
import { originText } from './origin.js';
import { KIND, STRIDE, formatTime } from './plan.js';
import { unitsText } from './summary.js';
import { extentText, sizeText } from './units.js';
import { composite, draw, fitView, requestDraw } from './view.js';
import { quoteTable } from './cost.js';
import { factsList, fillReport, processRows, warningList } from './job-report.js';

register({
  en: {
    'sheet.button': 'Job sheet', 'sheet.title': 'Job sheet', 'sheet.print': 'Print', 'sheet.close': 'Close',
    'sheet.file': 'File', 'sheet.date': 'Date', 'sheet.units': 'Units', 'sheet.parts': 'Parts', 'sheet.holes': 'Holes',
    'sheet.open': 'Open contours', 'sheet.pierces': 'Pierces', 'sheet.order': 'Order', 'sheet.cut': 'Cut length',
    'sheet.leads': 'Leads and links', 'sheet.rapid': 'Rapid length', 'sheet.time': 'Estimated time', 'sheet.post': 'Post',
    'sheet.kerf': 'Kerf width', 'sheet.feed': 'Feed rate', 'sheet.rapid-speed': 'Rapid speed', 'sheet.pierce-delay': 'Pierce delay',
    'sheet.heights': 'Pierce / cut height', 'sheet.chart': 'Cut-chart entry', 'sheet.chart-example': '{name} (example: check it against your machine\'s chart)',
    'sheet.plan': 'Cutting plan (numbers: cutting order)', 'sheet.sequence': 'Pierce points in cutting order',
    'sheet.warnings': 'Warnings', 'sheet.none': 'none', 'sheet.more': '… and {n} more',
    'sheet.no': 'No.', 'sheet.x': 'X (mm)', 'sheet.y': 'Y (mm)', 'sheet.spot': 'mark',
    'sheet.operator': 'Operator', 'sheet.material': 'Material and thickness', 'sheet.notes': 'Notes',
    'sheet.size': 'Size', 'sheet.origin': 'Program origin (X0 Y0)', 'sheet.extent': 'Parts in the program',
    'sheet.nest-part': 'Part', 'sheet.quote': 'Cost and time (the whole job)',
  },
  'pt-BR': {
    'sheet.button': 'Folha de trabalho', 'sheet.title': 'Folha de trabalho', 'sheet.print': 'Imprimir', 'sheet.close': 'Fechar',
    'sheet.file': 'Arquivo', 'sheet.date': 'Data', 'sheet.units': 'Unidades', 'sheet.parts': 'Peças', 'sheet.holes': 'Furos',
    'sheet.open': 'Contornos abertos', 'sheet.pierces': 'Perfurações', 'sheet.order': 'Ordem', 'sheet.cut': 'Comprimento de corte',
    'sheet.leads': 'Entradas, saídas e ligações', 'sheet.rapid': 'Deslocamento rápido', 'sheet.time': 'Tempo estimado',
    'sheet.post': 'Pós-processador', 'sheet.kerf': 'Sangria (kerf)', 'sheet.feed': 'Velocidade de corte',
    'sheet.rapid-speed': 'Velocidade rápida', 'sheet.pierce-delay': 'Tempo de perfuração',
    'sheet.heights': 'Altura de perfuração / de corte', 'sheet.chart': 'Entrada da tabela de corte',
    'sheet.chart-example': '{name} (exemplo: confira com a tabela da sua máquina)',
    'sheet.plan': 'Plano de corte (números: ordem de corte)', 'sheet.sequence': 'Pontos de perfuração na ordem de corte',
    'sheet.warnings': 'Avisos', 'sheet.none': 'nenhum', 'sheet.more': '… e mais {n}',
    'sheet.no': 'Nº', 'sheet.x': 'X (mm)', 'sheet.y': 'Y (mm)', 'sheet.spot': 'marcação',
    'sheet.operator': 'Operador', 'sheet.material': 'Material e espessura', 'sheet.notes': 'Observações',
    'sheet.size': 'Tamanho', 'sheet.origin': 'Origem do programa (X0 Y0)', 'sheet.extent': 'Peças no programa',
    'sheet.nest-part': 'Peça', 'sheet.quote': 'Custo e tempo (o trabalho todo)',
  },
});

const MAX_ROWS = 300; // pierce rows and warnings on paper; the rest are counted

function el(tag, text = '', attrs = {}) {
  const node = Object.assign(document.createElement(tag), attrs);
  if (text) node.textContent = text;
  return node;
}

/** Pierce (and marking) points in program order from the flat move list. */
export function piercePoints(moves) {
  const out = [];
  for (let i = 0; moves && i < moves.length; i += STRIDE) {
    const kind = moves[i];
    if (kind === KIND.pierce || kind === KIND.spot) out.push({ x: moves[i + 3], y: moves[i + 4], spot: kind === KIND.spot });
  }
  return out;
}

/**
 * Fills `root` with the sheet. `job`: { name, report (its `process`: the values the engine cut with), moves,
 * post (its name), picture (a data: URL of the plan with numbers), formatTime (s → text) }.
 */
export function fillSheet(root, job) {
  if (job.nest) return fillReport(root, job); // Sheet mode: the job report (issue 42 §4)
  const r = job.report || {};
  const plan = r.plan || {};
  const rows = [
    ['sheet.file', job.name],
    ['sheet.date', new Date().toLocaleString(getLang())],
    ['sheet.units', r.units ? unitsText(r, job.unitsChosen) : '?'],
    ...(sizeText(r.size) ? [['sheet.size', sizeText(r.size)]] : []),
    ...(originText(r.origin) ? [['sheet.origin', originText(r.origin)]] : []),
    ...(extentText(r.extent) ? [['sheet.extent', extentText(r.extent)]] : []),
    ['sheet.parts', fmtNumber(plan.parts)],
    ['sheet.holes', fmtNumber(plan.holes)],
    ['sheet.open', fmtNumber(plan.open)],
    ['sheet.pierces', fmtNumber(plan.pierces)],
    // The order's name in the page's language ('Ordem contorno a contorno', not 'Ordem contour').
    ['sheet.order', plan.order ? t(`order.${plan.order}`) : '?'],
    ['sheet.cut', fmtLength(plan.cut_length)],
    ['sheet.leads', fmtLength(plan.lead_length)],
    ['sheet.rapid', fmtLength(plan.rapid_length)],
    ['sheet.time', job.formatTime(plan.est_time_s)],
    ...processRows(r, job.post),
  ];
  const facts = factsList(rows);
  // Blanks the operator fills in by hand.
  const blanks = el('dl', '', { className: 'sheet-blanks' });
  for (const key of ['sheet.operator', 'sheet.material', 'sheet.notes']) blanks.append(el('dt', t(key)), el('dd', ' '));

  const picture = el('figure', '', { className: 'sheet-plan' });
  picture.append(el('img', '', { src: job.picture, alt: t('sheet.plan') }), el('figcaption', t('sheet.plan')));

  const points = piercePoints(job.moves);
  const table = el('table', '', { className: 'sheet-table' });
  const head = el('tr');
  for (const key of ['sheet.no', 'sheet.x', 'sheet.y']) head.append(el('th', t(key), { scope: 'col' }));
  table.append(el('caption', t('sheet.sequence')), el('thead'), el('tbody'));
  table.tHead.append(head);
  points.slice(0, MAX_ROWS).forEach((p, i) => {
    const tr = el('tr');
    tr.append(el('td', `${i + 1}${p.spot ? ` (${t('sheet.spot')})` : ''}`), el('td', fmtNumber(p.x, 2)), el('td', fmtNumber(p.y, 2)));
    table.tBodies[0].append(tr);
  });
  if (points.length > MAX_ROWS) {
    const tr = el('tr');
    tr.append(el('td', t('sheet.more', { n: fmtNumber(points.length - MAX_ROWS) }), { colSpan: 3 }));
    table.tBodies[0].append(tr);
  }

  // Most serious first, grouped with their counts; information (repairs) last.
  const list = el('ul', '', { className: 'sheet-warnings' });
  list.append(...warningList(r.warnings, MAX_ROWS));

  const title = el('h2', `${t('sheet.title')}: ${job.name}`, { id: 'sheet-title' });
  // The quote of the Cost panel, when it has one (issue 42 §3).
  const quote = job.quote ? [el('h3', t('sheet.quote')), ...quoteTable(job.quote)] : [];
  root.replaceChildren(
    title, facts, ...quote, blanks, picture, el('h3', t('sheet.warnings')), list, table,
  );
}

// --- on the page (moved from main.js) ---------------------------------------------------------------

/**
 * The job sheet: the whole plan fitted, with its numbers, and the job's figures, ready to print. In Sheet
 * mode the job report (job-report.js): the job, then each sheet of the nest, cut as the preview cuts it.
 */
async function openSheet() {
  if (!state.job) return;
  const quote = (await app.cost?.settled()) ?? null; // the shown job's, made after its plan
  const common = { report: window.kerfcam.lastReport, post: $('post').selectedOptions[0]?.textContent || '', quote };
  if (app.sheet?.active) {
    let nest;
    ui.jobSheet.disabled = true; // every sheet is being cut: once is enough
    try {
      nest = await app.sheet.report();
    } catch (e) {
      return showError(messageOf(e));
    } finally {
      ui.jobSheet.disabled = !state.job;
    }
    if (!nest) return;
    state.sheet = { ...common, files: app.sheet.files(), nest, programName: (k) => programName(sheetName(k)) };
  } else {
    const view = state.view;
    fitView();
    await draw();
    const picture = composite().toDataURL('image/png');
    state.view = view; // back to what the user was looking at
    requestDraw();
    state.sheet = {
      ...common, name: state.name, moves: state.job.moves, picture, formatTime, unitsChosen: !!state.current?.units && !ui.units.value,
    };
  }
  fillSheet(ui.sheet, state.sheet);
  ui.sheetView.hidden = false;
  document.body.classList.add('sheet-open');
  ui.sheetPrint.focus();
}

export function closeSheet() {
  ui.sheetView.hidden = true;
  document.body.classList.remove('sheet-open');
  ui.jobSheet.focus();
}

/** The sheet's buttons, and the open sheet in a new language. */
export function wireSheet() {
  onLangChange(() => {
    if (!ui.sheetView.hidden && state.sheet) fillSheet(ui.sheet, state.sheet);
  });
  ui.jobSheet.addEventListener('click', () => openSheet());
  ui.sheetPrint.addEventListener('click', () => window.print());
  ui.sheetClose.addEventListener('click', closeSheet);
}
