// kerfcam Cost panel (issue 42 §3): the shop's prices (a cost model, kept in this browser), checked by
// the engine field by field (a bad value is said at its field, and the last good quote stays), and the
// quote of the shown job after each plan or nest: per part and per sheet, its CSV for download, and
// on the job sheet. The engine computes it (src/quote/): the page only shows it. Part names come
// from files: textContent only.

import { download } from './download.js';
import { fmtNumber, getLang, onLangChange, register, t } from './i18n.js';

register({
  en: {
    'cost.heading': 'Cost and time', 'cost.help': 'The shop\'s prices: each part is priced from the plan\'s time, pierces and length cut, and its material. Kept in this browser.',
    'cost.currency': 'Currency', 'cost.machine_per_hour': 'Machine rate per hour', 'cost.per_pierce': 'Per pierce',
    'cost.per_metre': 'Per metre cut', 'cost.material_unit': 'Material priced', 'cost.material_price': 'Material price', 'cost.per_kg': 'per kg', 'cost.per_m2': 'per m²',
    'cost.density_g_cm3': 'Density (g/cm³)', 'cost.thickness_mm': 'Thickness (mm)', 'cost.scrap_per_kg': 'Scrap credit per kg (blank: none)',
    'cost.setup_per_sheet': 'Setup per sheet', 'cost.markup_percent': 'Markup (%)', 'cost.material_share': 'Material of a part',
    'cost.share.area': 'its own area', 'cost.share.sheet': 'its share of the sheet used',
    'cost.empty': 'Fill in the prices (and the currency) to see a quote.', 'cost.no-job': 'The quote shows once a plan is made.',
    'cost.part': 'Part', 'cost.qty': 'Qty', 'cost.time': 'Time', 'cost.pierces': 'Pierces', 'cost.cut': 'Cut (m)',
    'cost.material': 'Material', 'cost.cost': 'Cost', 'cost.price': 'Price', 'cost.sheet-row': 'Sheet {k}', 'cost.job-row': 'Job',
    'cost.export': 'Export quote (.csv)', 'cost.basis.area': 'Material: each part\'s own area (outline less holes).',
    'cost.basis.sheet': 'Material: each part\'s share, by area, of the sheet used.', 'cost.kept': 'The last good quote is kept.',
    'cost.failed': 'No quote: {message}', 'cost.not-number': '{field}: enter a number (or leave it blank).',
    'cost.sheet-cost': 'The nest\'s sheets have a cost each (Sheet mode): the quote\'s material is what they cost; the material price and the material of a part above are not applied.',
  },
  'pt-BR': {
    'cost.heading': 'Custo e tempo', 'cost.help': 'Os preços da oficina: cada peça é orçada pelo tempo do plano, perfurações, comprimento de corte e material. Guardados neste navegador.',
    'cost.currency': 'Moeda', 'cost.machine_per_hour': 'Hora-máquina', 'cost.per_pierce': 'Por perfuração',
    'cost.per_metre': 'Por metro cortado', 'cost.material_unit': 'Material cobrado', 'cost.material_price': 'Preço do material', 'cost.per_kg': 'por kg', 'cost.per_m2': 'por m²',
    'cost.density_g_cm3': 'Densidade (g/cm³)', 'cost.thickness_mm': 'Espessura (mm)', 'cost.scrap_per_kg': 'Crédito de sucata por kg (vazio: nenhum)',
    'cost.setup_per_sheet': 'Preparação por chapa', 'cost.markup_percent': 'Margem de lucro (%)', 'cost.material_share': 'Material de uma peça',
    'cost.share.area': 'sua própria área', 'cost.share.sheet': 'sua parte da chapa usada',
    'cost.empty': 'Preencha os preços (e a moeda) para ver um orçamento.', 'cost.no-job': 'O orçamento aparece quando um plano é feito.',
    'cost.part': 'Peça', 'cost.qty': 'Qtd.', 'cost.time': 'Tempo', 'cost.pierces': 'Perfurações', 'cost.cut': 'Corte (m)',
    'cost.material': 'Material', 'cost.cost': 'Custo', 'cost.price': 'Preço', 'cost.sheet-row': 'Chapa {k}', 'cost.job-row': 'Trabalho',
    'cost.export': 'Exportar orçamento (.csv)', 'cost.basis.area': 'Material: a área de cada peça (contorno menos furos).',
    'cost.basis.sheet': 'Material: a parte de cada peça, por área, da chapa usada.', 'cost.kept': 'O último orçamento válido foi mantido.',
    'cost.failed': 'Sem orçamento: {message}', 'cost.not-number': '{field}: informe um número (ou deixe em branco).',
    'cost.sheet-cost': 'As chapas do encaixe têm um custo cada (modo Chapa): o material do orçamento é o custo delas; o preço do material e o material de uma peça acima não são aplicados.',
  },
});

const KEY = 'kerfcam.cost';
// The model's numeric fields, in the form's order (their inputs are #cost-<field>).
const NUMBERS = ['machine_per_hour', 'per_pierce', 'per_metre', 'material_price', 'density_g_cm3', 'thickness_mm', 'scrap_per_kg',
  'setup_per_sheet', 'markup_percent'];
const OPTIONAL = new Set(['density_g_cm3', 'thickness_mm', 'scrap_per_kg']);

function el(tag, text = '', attrs = {}) {
  const node = Object.assign(document.createElement(tag), attrs);
  if (text) node.textContent = text;
  return node;
}

/** A number as typed: '' → null; the page's decimal comma read too; anything else is passed on for the engine to refuse. */
function numberOf(text) {
  const s = text.trim();
  if (!s) return null;
  const v = Number(s.replace(',', '.'));
  return Number.isNaN(v) ? s : v;
}

export class CostPanel {
  /**
   * `root`: the panel's <details>; `engine`: the worker; `context()`: { sheet: bool, settings, name } of
   * the shown job (null when none): what to quote.
   */
  constructor(root, engine, context) {
    this.root = root;
    this.engine = engine;
    this.context = context;
    this.form = root.querySelector('#cost-form');
    this.result = root.querySelector('#cost-result');
    this.message = root.querySelector('#cost-message');
    this.exportButton = root.querySelector('#cost-export');
    this.quote = null; // the last good quote (parsed JSON)
    this.csv = null;
    this.seq = 0;
    this.pending = Promise.resolve(); // the last update asked for (settled)
    this.restore();
    this.form.addEventListener('input', () => this.changed());
    this.form.addEventListener('change', () => this.changed());
    this.form.addEventListener('submit', (e) => e.preventDefault());
    this.exportButton.addEventListener('click', () => this.exportCsv());
    // The CSV again, in the new language's spreadsheet convention (Export waits for it).
    onLangChange(() => {
      const again = !!this.csv;
      this.csv = null;
      this.show();
      if (again) this.update();
    });
    this.show();
  }

  field(name) {
    return this.form.querySelector(`#cost-${name}`);
  }

  /** The form as a cost model (the engine's JSON), or null while the currency and prices are all blank. */
  model() {
    const m = { currency: this.field('currency').value.trim() };
    const v = {};
    for (const f of NUMBERS) v[f] = numberOf(this.field(f).value);
    if (!m.currency && NUMBERS.every((f) => v[f] === null)) return null;
    for (const f of ['machine_per_hour', 'per_pierce', 'per_metre', 'setup_per_sheet', 'markup_percent']) m[f] = v[f];
    m[this.field('material_unit').value === 'kg' ? 'material_per_kg' : 'material_per_m2'] = v.material_price;
    for (const f of OPTIONAL) if (v[f] !== null) m[f] = v[f];
    m.material_share = this.field('material_share').value;
    return m;
  }

  restore() {
    let kept = null;
    try {
      kept = JSON.parse(localStorage.getItem(KEY) || 'null');
    } catch {
      kept = null;
    }
    if (!kept || typeof kept !== 'object') return;
    for (const [k, value] of Object.entries(kept)) {
      const input = this.field(k);
      if (input && typeof value === 'string') input.value = value;
    }
  }

  save() {
    const kept = {};
    for (const input of this.form.querySelectorAll('input, select')) kept[input.id.slice('cost-'.length)] = input.value;
    try {
      localStorage.setItem(KEY, JSON.stringify(kept));
    } catch {
      // Storage full or refused: the panel still works for this visit.
    }
  }

  /** Clears the marks at the fields. */
  clearMarks() {
    for (const input of this.form.querySelectorAll('input, select')) {
      input.removeAttribute('aria-invalid');
      input.setCustomValidity?.('');
    }
    for (const p of this.form.querySelectorAll('.field-error')) p.remove();
  }

  /** Says `message` at the field the engine named (the price field for either material price). */
  markField(field, message) {
    const name = field === 'material_per_kg' || field === 'material_per_m2' ? 'material_price' : field;
    const input = this.field(name) ?? this.field('currency');
    input.setAttribute('aria-invalid', 'true');
    const p = el('p', message, { className: 'field-error small', role: 'alert' });
    p.dataset.field = name;
    const unit = input.nextElementSibling?.classList.contains('unit') ? input.nextElementSibling : input;
    unit.insertAdjacentElement('afterend', p);
  }

  async changed() {
    this.save();
    await this.update();
  }

  /** Checks the model and quotes the shown job again (after a plan or a nest, or a field changed). */
  async update() {
    const n = ++this.seq; // a later update wins over one still waiting for the engine
    this.pending = (async () => {
      try {
        await this.quoteAgain(() => n === this.seq);
      } catch (e) {
        if (n === this.seq && !e?.cancelled) this.message.textContent = t('cost.failed', { message: (e && e.message) || String(e) });
      }
    })();
    await this.pending;
  }

  /**
   * The quote once every update asked for so far has finished: the job sheet prints the quote of the job
   * shown, not the one before it (a report opened while the nest's quote was still being made printed the
   * previous job's).
   */
  async settled() {
    let p;
    do {
      p = this.pending;
      await p;
    } while (p !== this.pending);
    return this.quote;
  }

  async quoteAgain(current) {
    const model = this.model();
    this.clearMarks();
    if (!model) {
      this.quote = null;
      this.csv = null;
      return this.show();
    }
    // A price that is not a number is said at its own field here: the engine's JSON reader would name no field.
    const nan = NUMBERS.find((f) => typeof numberOf(this.field(f).value) === 'string');
    if (nan) {
      this.markField(nan, t('cost.not-number', { field: t(`cost.${nan}`) }));
      this.message.textContent = this.quote ? t('cost.kept') : '';
      return;
    }
    const json = JSON.stringify(model);
    const bad = await this.engine.call('checkCost', { json, lang: getLang() });
    if (!current()) return;
    if (bad) {
      const { field, message } = JSON.parse(bad);
      this.markField(field, message);
      this.message.textContent = this.quote ? t('cost.kept') : '';
      return;
    }
    const ctx = this.context();
    if (!ctx) {
      this.quote = null;
      this.csv = null;
      return this.show();
    }
    try {
      // The CSV in the page's language's spreadsheet convention (`;` and `,` decimals in pt-BR).
      const r = await this.engine.call('quote', { cost: json, ...ctx, lang: getLang() });
      if (!current()) return;
      this.quote = JSON.parse(r.json);
      this.csv = r.csv;
      this.message.textContent = '';
    } catch (e) {
      if (!current() || e?.cancelled) return;
      // A model the job cannot use (the sheet's share of a drawing on no sheet): said, the last quote kept.
      const message = (e && e.message) || String(e);
      const field = /'([a-z_0-9]+)'/.exec(message)?.[1];
      if (field && this.field(field === 'material_per_kg' || field === 'material_per_m2' ? 'material_price' : field)) this.markField(field, message);
      this.message.textContent = t('cost.failed', { message }) + (this.quote ? ` ${t('cost.kept')}` : '');
      return;
    }
    this.show();
  }

  /** The last good quote, or null (the job sheet waits for it: settled). */
  last() {
    return this.quote;
  }

  exportCsv() {
    if (!this.csv) return;
    const name = (this.context()?.name || 'job').replace(/\.[^.]*$/, '');
    download(new Blob([this.csv], { type: 'text/csv' }), `${name}-quote.csv`);
  }

  show() {
    this.exportButton.disabled = !this.csv;
    // Sheets at a cost (issue 44): said at the material fields, which the quote then does not apply.
    this.root.querySelector('#cost-sheet-cost').hidden = this.quote?.material_share !== 'sheet_cost';
    if (!this.quote) {
      this.result.replaceChildren(el('p', t(this.model() ? 'cost.no-job' : 'cost.empty'), { className: 'muted small' }));
      return;
    }
    this.result.replaceChildren(...quoteTable(this.quote, { narrow: true }));
  }
}

/**
 * The quote as a table (parts, then sheets, then the job) and its basis: for the job sheet, which is wide.
 * `narrow` (the side panel, about 310 px): the same rows as two tables one under the other, the work
 * (time, pierces, length cut) and the money (quantity, material, cost, price), the units (minutes, the
 * currency) said once in the heads, so every column shows without a sideways scroll.
 */
export function quoteTable(q, { narrow = false } = {}) {
  const cur = q.currency;
  // A column: its head and its cell; a unit is said in each cell, or once in the head when narrow.
  const unit = (key, u, value, digits) => (narrow
    ? [`${t(key)}, ${u}`, (_, f) => fmtNumber(value(f), digits)]
    : [t(key), (_, f) => `${fmtNumber(value(f), digits)} ${u}`]);
  const plain = (key, value, digits) => [t(key), (_, f) => fmtNumber(value(f), digits)];
  const qty = [t('cost.qty'), (n) => fmtNumber(n)];
  const work = [unit('cost.time', 'min', (f) => f.time_s / 60, 1), plain('cost.pierces', (f) => f.pierces),
    plain('cost.cut', (f) => f.cut_m, 2)];
  const prices = ['material', 'cost', 'price'].map((k) => unit(`cost.${k}`, cur, (f) => f[k], 2));
  const groups = narrow ? [[work, 'cost-work'], [[qty, ...prices], 'cost-money']] : [[[qty, ...work, ...prices], '']];
  const rows = [...q.parts.map((p) => [p.name, p.quantity, p, 'cost-part']),
    ...q.sheets.map((s) => [t('cost.sheet-row', { k: fmtNumber(s.sheet) }), s.copies, s, 'cost-sheet']),
    [t('cost.job-row'), q.copies.length, q.job, 'cost-job']];
  const tables = groups.map(([cols, cls]) => {
    const table = el('table', '', { className: `sheet-table cost-table ${cls}`.trim() });
    table.append(el('thead'), el('tbody'));
    const head = el('tr');
    for (const [text] of [[t('cost.part')], ...cols]) head.append(el('th', text, { scope: 'col' }));
    table.tHead.append(head);
    for (const [name, qty, f, rowCls] of rows) {
      const tr = el('tr', '', { className: rowCls });
      tr.append(el('td', name), ...cols.map(([, cell]) => el('td', cell(qty, f))));
      table.tBodies[0].append(tr);
    }
    return table;
  });
  // Sheets at a cost (issue 44): the material is the nest's sheets at their cost, said by the engine's note.
  const basis = q.material_share === 'sheet_cost' ? [] : [t(`cost.basis.${q.material_share}`)];
  const notes = [...basis, ...q.notes.map((n) => n[getLang()] ?? n.en)];
  return [...tables, ...notes.map((n) => el('p', n, { className: 'muted small cost-note' }))];
}
