// kerfcam page layout (issue 19): the job at a glance over the preview (parts, holes, size, time,
// warnings), the orders compared under the preview, the cut order's one-line explanation, and the
// side panels that fold (which ones the user folded is kept in this browser).
// Everything from the file or the report is shown with textContent only.

import { fmtNumber, onLangChange, register, t } from './i18n.js';
import { formatTime } from './plan.js';
import { realWarnings } from './summary.js';

register({
  en: {
    'mode.label': 'Mode', 'mode.drawing': 'One drawing', 'view.keys': 'Mouse and keys',
    'legend.backplot-label': 'Legend of the backplot', 'legend.bp-cut': 'Cut (torch on)', 'legend.bp-dry': 'Feed, torch off',
    'legend.bp-tool': 'Tool at the end',
    'post.format': 'Numbers and words', 'post.blocks': 'Blocks written into the program',
    'glance.heading': 'The job at a glance', 'glance.warnings': 'Warnings', 'glance.time': 'Time',
    'glance.size': '{w} × {h} mm',
    'glance.warnings-label': { one: '{n} warning: show the list', other: '{n} warnings: show the list' },
    'compare.where': 'the table opens under the preview', 'compare.close': 'Close',
    'plan.order.help.contour': 'Each contour pierced and cut on its own, the holes of a part before the part. The safe choice.',
    'plan.order.help.chained': 'Nearby contours joined by short links with the torch on (up to the longest link): fewer pierces.',
    'plan.order.help.eulerian': 'An edge two parts share is cut once: the least cutting for parts that touch (zero kerf: knife, common-line cutting).',
    'plan.order.help.drawing': 'The contours in the order the DXF file lists them: a part can drop before its holes are cut.',
    'views.label': 'Show', 'views.nest': 'Nest', 'views.plan': 'Cut plan', 'views.both': 'Both',
  },
  'pt-BR': {
    'mode.label': 'Modo', 'mode.drawing': 'Um desenho', 'view.keys': 'Mouse e teclas',
    'legend.backplot-label': 'Legenda da visualização do programa', 'legend.bp-cut': 'Corte (tocha ligada)',
    'legend.bp-dry': 'Avanço, tocha desligada', 'legend.bp-tool': 'Ferramenta no fim',
    'post.format': 'Números e palavras', 'post.blocks': 'Blocos escritos no programa',
    'glance.heading': 'O trabalho num relance', 'glance.warnings': 'Avisos', 'glance.time': 'Tempo',
    'glance.size': '{w} × {h} mm',
    'glance.warnings-label': { one: '{n} aviso: mostrar a lista', other: '{n} avisos: mostrar a lista' },
    'compare.where': 'a tabela abre embaixo da visualização', 'compare.close': 'Fechar',
    'plan.order.help.contour': 'Cada contorno perfurado e cortado sozinho, os furos de uma peça antes da peça. A escolha segura.',
    'plan.order.help.chained': 'Contornos vizinhos unidos por ligações curtas com a tocha ligada (até a maior ligação): menos perfurações.',
    'plan.order.help.eulerian': 'Uma aresta comum a duas peças é cortada uma vez: o menor corte para peças que se tocam (sangria zero: faca, corte em linha comum).',
    'plan.order.help.drawing': 'Os contornos na ordem em que o arquivo DXF os lista: uma peça pode cair antes de seus furos serem cortados.',
    'views.label': 'Mostrar', 'views.nest': 'Encaixe', 'views.plan': 'Plano de corte', 'views.both': 'Ambos',
  },
});

function el(tag, text, attrs = {}) {
  const node = Object.assign(document.createElement(tag), attrs);
  node.textContent = text;
  return node;
}

/** One glance item: <div><dt>label</dt><dd data-key=key>value</dd></div> (value: text or a node). */
function item(key, label, value) {
  const dd = document.createElement('dd');
  dd.dataset.key = key;
  dd.append(value);
  const div = document.createElement('div');
  div.append(el('dt', label), dd);
  return div;
}

export class Glance {
  /** `dl`: the glance list; `onWarnings()`: shows the full list of warnings. */
  constructor(dl, onWarnings) {
    Object.assign(this, { dl, onWarnings });
  }

  clear(name) {
    this.dl.replaceChildren(item('file', t('summary.file'), name || t('summary.none-yet')));
  }

  show(r, name) {
    const plan = r.plan || {};
    const kinds = { outer: 0, hole: 0 };
    for (const c of r.contours || []) kinds[c.kind] = (kinds[c.kind] || 0) + 1;
    const n = realWarnings(r.warnings).length;
    const warnings = el('button', fmtNumber(n), { type: 'button', className: 'link-button' });
    warnings.setAttribute('aria-label', t('glance.warnings-label', { n: fmtNumber(n), count: n }));
    warnings.addEventListener('click', () => this.onWarnings());
    const items = [
      item('file', t('summary.file'), name),
      item('parts', t('summary.parts'), fmtNumber(plan.parts ?? kinds.outer)),
      item('holes', t('summary.holes'), fmtNumber(plan.holes ?? kinds.hole)),
      item('size', t('summary.size'), Number.isFinite(r.size?.w) && Number.isFinite(r.size?.h)
        ? t('glance.size', { w: fmtNumber(r.size.w, 1), h: fmtNumber(r.size.h, 1) }) : '–'),
      item('pierces', t('summary.pierces'), fmtNumber(plan.pierces ?? 0)),
      item('est-time', t('glance.time'), formatTime(plan.est_time_s)),
      item('warnings', t('glance.warnings'), warnings),
    ];
    const said = items.at(-1);
    said.lastChild.dataset.warnings = String(n > 0);
    // Parts losing material (issue 45 §3): the count beside the file's name, where the strip never cuts it
    // off (the Download button then says the loss in more words and leaves the strip less room).
    if ((r.warnings || []).some((w) => w.loss)) {
      said.lastChild.dataset.loss = 'true';
      items.splice(1, 0, items.pop());
    }
    items[0].lastChild.title = name; // the whole name, where the strip cuts it
    this.dl.replaceChildren(...items);
  }
}

/** The cut order's one-line explanation under its select, in the page's language. */
export function orderHelp(select, help) {
  const update = () => (help.textContent = t(`plan.order.help.${select.value}`));
  select.addEventListener('change', update);
  onLangChange(update);
  update();
  return update; // for a value set by a script (a file's own order)
}

/** The orders compared, under the preview: shown with a table, hidden with Close or when the plan changes. */
export class CompareBox {
  constructor({ box, table, close, button }) {
    Object.assign(this, { box, table, button });
    close.addEventListener('click', () => this.hide(true));
  }

  shown() {
    this.box.hidden = false;
  }

  /** Hides the box (`focusBack`: the keyboard goes back to the Compare button). */
  hide(focusBack = false) {
    if (this.box.hidden) return;
    this.box.hidden = true;
    if (focusBack) this.button.focus();
  }
}

const FOLDED = 'kerfcam.folded.v1';

/** The side panels (details.panel with an id): the ones the user folds stay folded on the next visit. */
export function keepFolds(root) {
  let folded = [];
  try {
    folded = JSON.parse(localStorage.getItem(FOLDED) || '[]');
  } catch {
    folded = [];
  }
  const panels = [...root.querySelectorAll('details.panel[id]')];
  for (const p of panels) {
    if (Array.isArray(folded) && folded.includes(p.id)) p.open = false;
    p.addEventListener('toggle', () => {
      try {
        localStorage.setItem(FOLDED, JSON.stringify(panels.filter((q) => !q.open).map((q) => q.id)));
      } catch {
        // storage blocked: the folds last for this visit
      }
    });
  }
}

/** Opens a folded panel and brings `target` into view. */
export function reveal(panel, target) {
  panel.open = true;
  target.scrollIntoView({ block: 'nearest' });
}

const SHEET_VIEW = 'kerfcam.sheet-view.v1';
const SHEET_VIEWS = ['nest', 'plan', 'both'];

/**
 * Sheet mode on a shop screen (issue 42 §5): the nest, the sheet's cut plan, or both stacked, each fitted in
 * the window (no page scroll: style.css, body[data-sheet-view]). The operator's choice is kept in this
 * browser. `group`: the buttons (data-view); `hooks.shown(view)`: the choice made (the preview, shown
 * again, is fitted to its new size).
 */
export class SheetViews {
  constructor(group, hooks) {
    this.buttons = [...group.querySelectorAll('button[data-view]')];
    this.hooks = hooks;
    let kept = null;
    try {
      kept = localStorage.getItem(SHEET_VIEW);
    } catch {
      kept = null;
    }
    this.set(SHEET_VIEWS.includes(kept) ? kept : 'both', false);
    for (const b of this.buttons) b.addEventListener('click', () => this.set(b.dataset.view));
  }

  set(view, keep = true) {
    const before = this.view;
    this.view = view;
    document.body.dataset.sheetView = view;
    for (const b of this.buttons) b.setAttribute('aria-pressed', String(b.dataset.view === view));
    if (keep) {
      try {
        localStorage.setItem(SHEET_VIEW, view);
      } catch {
        // storage blocked: the choice lasts for this visit
      }
    }
    if (before !== undefined && before !== view) this.hooks.shown?.(view);
  }
}
