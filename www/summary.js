// kerfcam summary panel: the report's figures, its warnings and its repairs (moved out of main.js).
// Warnings (issue 13 §4): identical ones come grouped with a count and their first few places, the
// most serious first; information (repairs, the moved origin) is listed apart and not counted as a
// warning. The "units assumed" warning carries the unit switch (units.js). Messages, layer names and
// everything else from the file or the report is shown with textContent only.

import { fmtLength, fmtNumber, getLang, register, t } from './i18n.js';
import { originText } from './origin.js';
import { formatTime } from './plan.js';
import { extentText, sizeText, unitSwitch } from './units.js';

register({
  en: {
    'summary.size': 'Size', 'summary.origin': 'Program origin', 'summary.extent': 'Parts in the program',
    'severity.error': 'error', 'severity.warning': 'warning', 'severity.info': 'note',
    'warnings.count': { one: '{n} time', other: '{n} times' },
    'warnings.place': 'show {i} of {n}',
    'warnings.place-label': 'Show place {i} of {n} on the preview: {message}',
    'notes.heading': 'Information',
  },
  'pt-BR': {
    'summary.size': 'Tamanho', 'summary.origin': 'Origem do programa', 'summary.extent': 'Peças no programa',
    'severity.error': 'erro', 'severity.warning': 'aviso', 'severity.info': 'nota',
    'warnings.count': { one: '{n} vez', other: '{n} vezes' },
    'warnings.place': 'mostrar {i} de {n}',
    'warnings.place-label': 'Mostrar o local {i} de {n} na visualização: {message}',
    'notes.heading': 'Informações',
  },
});

const MAX_SHOWN = 200;
const SEVERITY_RANK = { error: 0, warning: 1, info: 2 };

function el(tag, text, attrs = {}) {
  const node = Object.assign(document.createElement(tag), attrs);
  node.textContent = text;
  return node;
}

/** A summary row: <dt>label</dt><dd data-key=key>value</dd> (value: text or a node). */
export function row(key, label, value) {
  const dd = value instanceof Node ? document.createElement('dd') : el('dd', String(value));
  if (value instanceof Node) dd.append(value);
  dd.dataset.key = key; // stable hook for tests
  return [el('dt', label), dd];
}
const mm = (x) => fmtLength(x);
const count = (n) => (Number.isFinite(Number(n)) && n !== null ? fmtNumber(n) : String(n ?? '?'));
const listCounts = (counts) => Object.entries(counts || {}).map(([type, n]) => `${type} ${fmtNumber(n)}`).join(', ');

const UNITS_SOURCES = {
  $INSUNITS: 'units.from-insunits',
  $MEASUREMENT: 'units.from-measurement', // older engines
  default: 'units.assumed', // older engines
  assumed: 'units.assumed',
  override: 'units.override',
  'width/height': 'units.from-svg-size', // an SVG's width and height in a real unit
  nest: 'units.from-nest', // a nested sheet (src/nest/output.rs)
};

/** True when the units the file is read in were guessed, not stated nor chosen. */
export const unitsAssumed = (r) => r.units_assumed === true || ((r.units_assumed ?? null) === null && (r.units_source === 'default' || r.units_source === 'assumed'));

/** "mm (from $INSUNITS)", "in (chosen for this file)", "mm (assumed: the file does not say)". */
export function unitsText(r, chosenForFile = false) {
  const key = chosenForFile && r.units_source === 'override' ? 'units.chosen' : UNITS_SOURCES[r.units_source];
  const source = key ? t(key) : (r.units_source ? t('units.from', { source: r.units_source }) : '');
  return source ? `${r.units} (${source})` : String(r.units);
}

// $ACADVER codes and the AutoCAD release that introduced them.
const RELEASES = {
  AC1006: 'R10', AC1009: 'R11/R12', AC1012: 'R13', AC1014: 'R14', AC1015: '2000', AC1018: '2004',
  AC1021: '2007', AC1024: '2010', AC1027: '2013', AC1032: '2018',
};
function formatText(r) {
  if (r.format === 'svg') return r.version || t('format.no-producer'); // the program that wrote it
  // A nested sheet, drawn by the nester (src/nest/output.rs: units_source "nest"): no $ACADVER to miss.
  if (r.units_source === 'nest') return t('format.nest');
  const version = r.version ? `${r.version}${RELEASES[r.version] ? ` (AutoCAD ${RELEASES[r.version]})` : ''}` : t('format.no-version');
  return r.binary ? t('format.binary', { version }) : version;
}

export const at = (p) => (Array.isArray(p) ? t('warnings.at', { x: fmtNumber(p[0], 2), y: fmtNumber(p[1], 2) }) : '');

/**
 * Warnings as the report gives them, with severity and count filled in: first those that say parts lose
 * material or are not cut (`loss`, issue 45 §3: what the operator must see before the cut), then the
 * most serious first (stable).
 */
export function sortedWarnings(warnings) {
  const lossRank = (w) => (w.loss ? 0 : 1);
  return (warnings || [])
    .map((w, i) => ({ ...w, severity: SEVERITY_RANK[w.severity] === undefined ? 'warning' : w.severity, count: Number(w.count) > 0 ? Number(w.count) : 1, i }))
    .sort((a, b) => lossRank(a) - lossRank(b) || SEVERITY_RANK[a.severity] - SEVERITY_RANK[b.severity] || a.i - b.i);
}

/** The warnings that count as warnings (not information). */
export const realWarnings = (warnings) => sortedWarnings(warnings).filter((w) => w.severity !== 'info');

const HEALING_KEYS = ['duplicates', 'overlaps', 'gaps_closed', 'zero_length'];
/** "2 duplicates removed, 1 gap closed"; "none" when healing changed nothing. */
function healingText(h) {
  const parts = HEALING_KEYS.filter((k) => Number(h[k]) > 0).map((k) => t(`healing.${k}`, { count: Number(h[k]) }));
  return parts.length ? parts.join(', ') : t('summary.none');
}

/** A repair's kind as a word: "duplicate", "zero length"; unknown kinds as the engine names them. */
function healingKind(kind) {
  const k = `healing.kind.${kind ?? 'repair'}`;
  const text = t(k);
  return text === k ? String(kind).replace(/_/g, ' ') : text;
}

export class Summary {
  /**
   * `ui`: { summary, warnings, warningCount, notes, notesList, notesCount, healing, healingList, healingCount };
   * `zoomTo(x, y)` shows a place; `units()` gives { chosen (this file's unit or null), global (the
   * Settings unit or '') }; `onUnits(unit)` reads the file in that unit; `losses` (losses.js): a loss
   * warning's button that shows its parts, and what is told when the operator has looked at them.
   */
  constructor(ui, { zoomTo, units, onUnits, losses = null }) {
    Object.assign(this, { ui, zoomTo, units, onUnits, losses });
  }

  /** Only the file's name (no job). */
  clear(name) {
    const { ui } = this;
    ui.summary.replaceChildren(...row('file', t('summary.file'), name || t('summary.none-yet')));
    ui.warnings.replaceChildren();
    ui.warningCount.textContent = '';
    ui.notes.hidden = true;
    ui.notesList.replaceChildren();
    this.showHealing(null);
  }

  show(r, name) {
    const kinds = { outer: 0, hole: 0, open: 0 };
    for (const c of r.contours || []) kinds[c.kind] = (kinds[c.kind] || 0) + 1;
    const plan = r.plan || {};
    const read = Object.values(r.entities || {}).reduce((a, b) => a + b, 0);
    const spots = (r.spots || []).length;
    const { chosen, global } = this.units();
    const units = el('span', unitsText(r, !!chosen && !global));
    if (unitsAssumed(r)) units.className = 'assumed';
    const size = sizeText(r.size);
    const origin = originText(r.origin);
    this.ui.summary.replaceChildren(
      ...row('file', t('summary.file'), name),
      ...row('format', r.format === 'svg' ? 'SVG' : 'DXF', formatText(r)),
      ...row('units', t('summary.units'), units),
      ...(size ? row('size', t('summary.size'), size) : []),
      ...(origin ? row('origin', t('summary.origin'), origin) : []),
      ...(extentText(r.extent) ? row('extent', t('summary.extent'), extentText(r.extent)) : []),
      ...row('parts', t('summary.parts'), count(plan.parts ?? kinds.outer)),
      ...row('holes', t('summary.holes'), count(plan.holes ?? kinds.hole)),
      ...row('open', t('summary.open'), count(plan.open ?? kinds.open)),
      ...row('entities', t('summary.entities'), read ? `${fmtNumber(read)} (${listCounts(r.entities)})` : '0'),
      ...row('skipped', t('summary.skipped'), listCounts(r.skipped) || t('summary.none')),
      ...row('order', t('summary.order'), plan.order ? t(`order.${plan.order}`) : '?'),
      ...row('cut-length', t('summary.cut-length'), mm(plan.cut_length)),
      ...(plan.repeated_length ? row('repeated-length', t('summary.repeated'), mm(plan.repeated_length)) : []),
      ...row('lead-length', t('summary.leads'), mm(plan.lead_length)),
      ...row('rapid-length', t('summary.rapid-length'), mm(plan.rapid_length)),
      ...row('pierces', t('summary.pierces'), plan.chains
        ? t('summary.pierces-chains', { pierces: count(plan.pierces), chains: count(plan.chains), count: plan.chains })
        : count(plan.pierces)),
      ...row('est-time', t('summary.est-time'), formatTime(plan.est_time_s)),
      ...row('invalid-vertices', t('summary.invalid-vertices'), count((r.invalid_vertices || []).length)),
      ...(spots ? row('spots', t('summary.points'), count(spots)) : []),
      ...(r.healing ? row('healing', t('summary.repairs'), healingText(r.healing)) : []),
    );
    // A unit chosen for this file (the warning is gone then): the switch stays beside the units.
    if (chosen && !global) units.after(' ', this.unitSwitch(r, chosen));
    this.showHealing(r.healing);
    this.showWarnings(r);
  }

  unitSwitch(r, chosen) {
    return unitSwitch({ current: r.units, chosen, onPick: (unit) => this.onUnits(unit), svg: r.format === 'svg' });
  }

  showWarnings(r) {
    const all = sortedWarnings(r.warnings);
    const warnings = all.filter((w) => w.severity !== 'info');
    const notes = all.filter((w) => w.severity === 'info');
    const { chosen, global } = this.units();
    const list = (ws) => {
      const items = ws.slice(0, MAX_SHOWN).map((w) => {
        const li = this.warningItem(w);
        if (w.code === 'units-assumed' && !global) li.append(' ', this.unitSwitch(r, chosen));
        return li;
      });
      if (ws.length > items.length) items.push(el('li', t('list.more', { count: ws.length - items.length }), { className: 'muted' }));
      return items;
    };
    const items = list(warnings);
    if (!warnings.length) items.push(el('li', t('summary.none'), { className: 'muted' }));
    this.ui.warnings.replaceChildren(...items);
    this.ui.warningCount.textContent = warnings.length ? `(${warnings.length})` : '';
    this.ui.notes.hidden = !notes.length;
    this.ui.notesCount.textContent = notes.length ? `(${notes.length})` : '';
    this.ui.notesList.replaceChildren(...list(notes));
  }

  /** One (grouped) warning: its severity, message, count, first place and a button through its places. */
  warningItem(w) {
    // The engine sends every language: the list follows the switch without running the job again.
    const message = w.messages?.[getLang()] ?? w.message;
    const li = el('li', '', { className: `severity-${w.severity}` });
    li.dataset.severity = w.severity;
    li.dataset.count = String(w.count);
    if (w.code) li.dataset.code = w.code;
    const places = Array.isArray(w.places) && w.places.length ? w.places.filter(Array.isArray) : (Array.isArray(w.at) ? [w.at] : []);
    li.append(el('span', t(`severity.${w.severity}`), { className: 'severity' }), ' ');
    if (w.loss) {
      // What the program takes from the parts (issue 45 §3): set apart, and a button that shows the parts.
      li.classList.add('loss');
      li.dataset.loss = w.loss;
      li.append(el('span', t('losses.tag'), { className: 'loss-tag' }), ' ');
    }
    li.append(`${message}${at(places[0])}`);
    if (w.count > 1) li.append(' ', el('span', t('warnings.count', { n: fmtNumber(w.count), count: w.count }), { className: 'warning-count muted' }));
    if (places.length) {
      // Zoom to where the warning is (the message stays text: it may quote the file); again: the next place.
      let i = 0;
      const label = () => (places.length > 1 ? t('warnings.place', { i: i + 1, n: places.length }) : t('warnings.show'));
      const aria = () => (places.length > 1
        ? t('warnings.place-label', { i: i + 1, n: places.length, message })
        : t('warnings.show-label', { message }));
      const show = el('button', label(), { type: 'button', className: 'small-button show-at' });
      show.setAttribute('aria-label', aria());
      show.addEventListener('click', () => {
        if (w.loss) this.losses?.seen(); // the place is shown with the marks on it
        this.zoomTo(places[i][0], places[i][1]);
        i = (i + 1) % places.length;
        show.textContent = label();
        show.setAttribute('aria-label', aria());
      });
      li.append(' ', show);
    }
    if (w.loss && w.loops?.length && this.losses) li.append(' ', this.losses.showButton(w, message));
    return li;
  }

  /** The places healing changed, when the report has them (`healing` is absent from older engines). */
  showHealing(h) {
    const { ui } = this;
    const locations = (h && Array.isArray(h.locations)) ? h.locations : [];
    ui.healing.hidden = !locations.length;
    ui.healingCount.textContent = locations.length ? `(${locations.length})` : '';
    const items = locations.slice(0, MAX_SHOWN).map((l) => el('li', `${healingKind(l.kind)}${at(l.at)}`));
    if (locations.length > items.length) items.push(el('li', t('list.more', { count: locations.length - items.length }), { className: 'muted' }));
    ui.healingList.replaceChildren(...items);
  }
}

