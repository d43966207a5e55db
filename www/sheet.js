// kerfcam page, Sheet mode (issue 18): the mode strip, the parts list (each dropped DXF file's parts
// with a quantity, a rotation choice and a mirror toggle, its units shown so an inch file is never
// nested at the wrong scale unnoticed) and the sheet's fields (presets or W × H, sheets, a cost per
// sheet, spacing, margin, time budget). The nest itself runs in nest-run.js. File names are data:
// textContent only.

import { $, el } from './app.js';
import { fmtNumber, getLang, onLangChange, register, t } from './i18n.js';
import { formatValue, parseNumber } from './numbers.js';
import { grainRotations, partRow } from './part-row.js';
import { SheetSizes } from './sheet-sizes.js';

register({
  en: {
    'mode.sheet': 'Sheet', 'nest.heading': '1. Parts and sheet', 'nest.open-parts': 'Open DXF or SVG parts…',
    'nest.drop-parts': 'or drop .dxf or .svg files anywhere on this page: their parts are nested on the sheet',
    'nest.parts': 'Parts', 'nest.no-parts': 'No parts yet.',
    'nest.part-names': { one: '{n} part: {names}', other: '{n} parts: {names}' },
    'nest.no-nestable': 'no closed outline to nest',
    'nest.units': 'units: {units}', 'nest.units-assumed': 'units assumed: {units}. Check the size!',
    'nest.quantity': 'Quantity', 'nest.rotations': 'Rotation', 'nest.mirror': 'Mirror', 'nest.remove': 'Remove',
    'nest.rot.none': 'none', 'nest.rot.180': '180°', 'nest.rot.90': '90° steps', 'nest.rot.free': 'free',
    'nest.quantity-bad': 'Quantity of {name}: enter a whole number from 1 to {max}.',
    'nest.quantity-bad-0': 'Quantity of {name}: enter a whole number from 0 to {max}.',
    'nest.quantity-greyed': 'Quantity of {name}: 0 only, the nester cannot place it ({reason}).',
    'nest.added-again': { one: '{names} is already in the list: one more of each of its parts.', other: '{names} are already in the list: one more of each of their parts.' },
    'nest.reading': 'reading {name}…', 'nest.read-failed': '{name}: {message}',
    'nest.torches': 'Torches', 'nest.torch-spacing': 'Torch spacing', 'nest.torch-park': 'Stop to set the torches at X, Y',
    'nest.torch-park-help': 'Several torches cut the same moves across the sheet (Y); the program drives torch 1. Empty X, Y: no stop.',
    'nest.torch-park-bad': 'Stop position: give both X and Y in mm, or neither.',
    'nest.torches-line': '{n} torches {d} mm apart: {per} under torch 1, {made} cut',
    'nest.sheet': 'Sheet', 'nest.preset': 'Size', 'nest.custom': 'custom', 'nest.width': 'Width', 'nest.height': 'Height',
    'nest.count': 'Sheets available', 'nest.spacing': 'Spacing', 'nest.margin': 'Margin', 'nest.time': 'Time budget',
    'nest.time-help': '0: the first nest only, no search.',
    'nest.common-line': 'Common line (spacing = kerf)', 'nest.spacing-default': 'Kerf + 1 mm',
    'nest.spacing-is': { one: 'spacing follows the kerf: kerf + {d} mm', other: 'spacing follows the kerf: kerf + {d} mm' },
    'nest.spacing-common': 'common line: spacing = kerf, shared edges can be cut once (order "shared edges once")',
    'nest.spacing-own': 'spacing as typed',
    'nest.field-bad': '{label}: enter a number from {min} to {max}{unit}.',
    'nest.zero': "The program's zero is the sheet's lower-left corner.",
    'nest.sheet-dxf': 'Sheet from a DXF or SVG (remnant)…', 'nest.sheet-rect': 'Use the size below',
    'nest.sheet-dxf-is': 'sheet: {name} (its outline; holes and layer DEFECT are no-go zones)',
    'nest.cost': 'Cost per sheet',
    'nest.cost-help': 'Optional. In {cur}, the currency of Cost and time. With a cost for every sheet size, the nest takes the cheapest sheets that hold every copy.',
    'nest.cost-help-none': 'Optional, in the currency of Cost and time (none set there yet). With a cost for every sheet size, the nest takes the cheapest sheets that hold every copy.',
    'nest.cost-bad': '{label}: enter a price of 0 or more, or leave it blank.',
    'nest.cost-some': '{label}: give a cost for every sheet size or for none.',
    'nest.cost-torches': '{label}: a multi-torch nest takes the sheets as given (leave the costs out).',
  },
  'pt-BR': {
    'mode.sheet': 'Chapa', 'nest.heading': '1. Peças e chapa', 'nest.open-parts': 'Abrir peças DXF ou SVG…',
    'nest.drop-parts': 'ou solte arquivos .dxf ou .svg em qualquer lugar desta página: suas peças são encaixadas na chapa',
    'nest.parts': 'Peças', 'nest.no-parts': 'Nenhuma peça ainda.',
    'nest.part-names': { one: '{n} peça: {names}', other: '{n} peças: {names}' },
    'nest.no-nestable': 'nenhum contorno fechado para encaixar',
    'nest.units': 'unidades: {units}', 'nest.units-assumed': 'unidades supostas: {units}. Confira o tamanho!',
    'nest.quantity': 'Quantidade', 'nest.rotations': 'Rotação', 'nest.mirror': 'Espelhar', 'nest.remove': 'Remover',
    'nest.rot.none': 'nenhuma', 'nest.rot.180': '180°', 'nest.rot.90': 'passos de 90°', 'nest.rot.free': 'livre',
    'nest.quantity-bad': 'Quantidade de {name}: informe um número inteiro de 1 a {max}.',
    'nest.quantity-bad-0': 'Quantidade de {name}: informe um número inteiro de 0 a {max}.',
    'nest.quantity-greyed': 'Quantidade de {name}: só 0, o encaixe não consegue posicioná-la ({reason}).',
    'nest.added-again': { one: '{names} já está na lista: mais uma de cada peça dele.', other: '{names} já estão na lista: mais uma de cada peça deles.' },
    'nest.reading': 'lendo {name}…', 'nest.read-failed': '{name}: {message}',
    'nest.torches': 'Tochas', 'nest.torch-spacing': 'Distância entre tochas', 'nest.torch-park': 'Parar para ajustar as tochas em X, Y',
    'nest.torch-park-help': 'Várias tochas cortam os mesmos movimentos ao longo da chapa (Y); o programa comanda a tocha 1. X, Y vazios: sem parada.',
    'nest.torch-park-bad': 'Posição de parada: informe X e Y em mm, ou nenhum.',
    'nest.torches-line': '{n} tochas a {d} mm: {per} sob a tocha 1, {made} cortadas',
    'nest.sheet': 'Chapa', 'nest.preset': 'Tamanho', 'nest.custom': 'personalizado', 'nest.width': 'Largura', 'nest.height': 'Altura',
    'nest.count': 'Chapas disponíveis', 'nest.spacing': 'Espaçamento', 'nest.margin': 'Margem', 'nest.time': 'Tempo de busca',
    'nest.time-help': '0: só o primeiro encaixe, sem busca.',
    'nest.common-line': 'Linha comum (espaçamento = sangria)', 'nest.spacing-default': 'Sangria + 1 mm',
    'nest.spacing-is': { one: 'o espaçamento segue a sangria: sangria + {d} mm', other: 'o espaçamento segue a sangria: sangria + {d} mm' },
    'nest.spacing-common': 'linha comum: espaçamento = sangria, arestas comuns podem ser cortadas uma vez (ordem "arestas comuns uma vez")',
    'nest.spacing-own': 'espaçamento como digitado',
    'nest.field-bad': '{label}: informe um número de {min} a {max}{unit}.',
    'nest.zero': 'O zero do programa é o canto inferior esquerdo da chapa.',
    'nest.sheet-dxf': 'Chapa de um DXF ou SVG (retalho)…', 'nest.sheet-rect': 'Usar o tamanho abaixo',
    'nest.sheet-dxf-is': 'chapa: {name} (seu contorno; furos e a camada DEFECT são zonas proibidas)',
    'nest.cost': 'Custo por chapa',
    'nest.cost-help': 'Opcional. Em {cur}, a moeda de Custo e tempo. Com um custo para cada tamanho de chapa, o encaixe usa as chapas mais baratas que comportam todas as cópias.',
    'nest.cost-help-none': 'Opcional, na moeda de Custo e tempo (nenhuma definida lá ainda). Com um custo para cada tamanho de chapa, o encaixe usa as chapas mais baratas que comportam todas as cópias.',
    'nest.cost-bad': '{label}: informe um preço de 0 ou mais, ou deixe em branco.',
    'nest.cost-some': '{label}: informe um custo para cada tamanho de chapa ou para nenhum.',
    'nest.cost-torches': '{label}: um encaixe com várias tochas usa as chapas como dadas (deixe os custos em branco).',
  },
});

/** The most copies of one file's parts (the engine's MAX_QUANTITY). */
export const MAX_QUANTITY = 10000;
const INCH = 25.4;
/** Sheet presets, W × H in mm (W along X). */
export const PRESETS = [
  { id: '3000x1500', w: 3000, h: 1500 },
  { id: '2500x1250', w: 2500, h: 1250 },
  { id: '2000x1000', w: 2000, h: 1000 },
  { id: '48x96', w: 96 * INCH, h: 48 * INCH, inches: '48" × 96"' },
  { id: '60x120', w: 120 * INCH, h: 60 * INCH, inches: '60" × 120"' },
];
/** A preset's name in the menu, its mm with the language's decimal sign. */
const presetLabel = (p) => {
  const mm = `${formatValue(p.w, 1)} × ${formatValue(p.h, 1)} mm`;
  return p.inches ? `${p.inches} (${mm})` : mm;
};
// The sheet's number fields: key → element id, label, range, unit.
const FIELDS = {
  sheet_width: { id: 'sheet-w', label: 'nest.width', min: 1, max: 100000, unit: ' mm' },
  sheet_height: { id: 'sheet-h', label: 'nest.height', min: 1, max: 100000, unit: ' mm' },
  sheet_count: { id: 'sheet-count', label: 'nest.count', min: 1, max: 1000, unit: '', whole: true },
  spacing: { id: 'nest-spacing', label: 'nest.spacing', min: 0, max: 1000, unit: ' mm' },
  margin: { id: 'nest-margin', label: 'nest.margin', min: 0, max: 10000, unit: ' mm' },
  // 0: the first nest whole and no search, as the CLI's --time 0.
  time_s: { id: 'nest-time', label: 'nest.time', min: 0, max: 3600, unit: ' s' },
  // Paper 001 §6.5: torches at a fixed distance across the sheet (1: one torch).
  torches: { id: 'nest-torches', label: 'nest.torches', min: 1, max: 16, unit: '', whole: true },
  torch_spacing: { id: 'torch-spacing', label: 'nest.torch-spacing', min: 0, max: 100000, unit: ' mm' },
};

/** Field `f`'s number typed in `input`: the input marked, and a value out of range named in `problems` as `label`. */
function readField(f, input, label, problems) {
  const v = parseNumber(input.value);
  const ok = Number.isFinite(v) && v >= f.min && v <= f.max && (!f.whole || Number.isInteger(v));
  input.setAttribute('aria-invalid', String(!ok));
  if (!ok) problems.push(t('nest.field-bad', { label, min: fmtNumber(f.min, f.min % 1 ? 1 : 0), max: fmtNumber(f.max), unit: f.unit }));
  return v;
}

/** A quantity as typed: a whole number 1..MAX_QUANTITY, or NaN ("2.5", "1e9", "-3", "abc"). */
export function parseQuantity(text, zero = false) {
  const s = String(text ?? '').trim();
  if (!/^\d{1,6}$/.test(s)) return NaN;
  const n = Number(s);
  return n >= (zero ? 0 : 1) && n <= MAX_QUANTITY ? n : NaN;
}

/** Each part's choices of file `p` once its rows are read: kept where the rows are the same as before, else
 * the file's (a row that is not a part asks 0 copies). */
function eachOf(p, before) {
  const rows = p.info?.rows ?? [];
  if (before?.length === rows.length) return before;
  return rows.map((r) => ({ quantity: r.not_nestable ? '0' : p.quantity, rotations: p.rotations, mirror: p.mirror, grain: p.grain }));
}

/**
 * The message of a quantity out of range, for part or file `name` (`zero`: 0 is allowed); `greyed`, the reason a
 * part cannot be nested, when copies were asked of it (issue 42: a quantity on a greyed row is said at its field).
 */
const quantityBad = (name, zero, greyed) => (greyed ? t('nest.quantity-greyed', { name, reason: greyed })
  : t(zero ? 'nest.quantity-bad-0' : 'nest.quantity-bad', { name, max: fmtNumber(MAX_QUANTITY) }));

export class SheetPanel {
  /**
   * `hooks`: { engine(), kerf() (mm or NaN), cutting() (the page's cutting settings parts are read with: layers,
   * tolerance, gap, kerf; null when a field is out of range), onMode(active), onChange(), currency() (the Cost
   * panel's currency, '' when none: the sheet costs are in it) }
   */
  constructor(hooks) {
    this.hooks = hooks;
    this.active = false;
    this.parts = []; // { id, file, name, quantity, rotations, mirror, grain, units (chosen, or null), info | null, error }
    this.nextId = 1;
    this.follow = 'default'; // spacing = kerf + follow ('default': the engine's, null: as typed)
    this.overKerf = null; // the engine's default spacing beyond the kerf, once it is loaded (setDefaults)
    this.sheetFile = null; // a sheet drawn in a DXF (a remnant saved from a nest), or null: W × H
    this.ui = {
      modeDrawing: $('mode-drawing'), modeSheet: $('mode-sheet'), panel: $('panel-sheet'), input: $('parts-input'),
      list: $('parts'), count: $('parts-count'), message: $('parts-message'), preset: $('sheet-preset'),
      commonLine: $('common-line'), spacingDefault: $('spacing-default'), spacingHint: $('spacing-hint'),
    };
    for (const p of PRESETS) this.ui.preset.append(el('option', presetLabel(p), { value: p.id }));
    this.sizes = new SheetSizes($('sheet-sizes'), $('sheet-size-add'), () => hooks.onChange(), () => this.currency());
    this.ui.modeDrawing.addEventListener('click', () => this.setActive(false));
    this.ui.modeSheet.addEventListener('click', () => this.setActive(true));
    this.ui.input.addEventListener('change', () => {
      this.addFiles(this.ui.input.files);
      this.ui.input.value = '';
    });
    this.ui.preset.addEventListener('change', () => this.applyPreset());
    $('sheet-dxf-input').addEventListener('change', (e) => {
      this.setSheetFile(e.target.files?.[0] ?? null);
      e.target.value = '';
    });
    $('sheet-dxf-clear').addEventListener('click', () => this.setSheetFile(null));
    for (const key of ['sheet_width', 'sheet_height']) {
      $(FIELDS[key].id).addEventListener('input', () => (this.ui.preset.value = 'custom'));
    }
    $(FIELDS.spacing.id).addEventListener('input', () => this.setFollow(null));
    $('nest-form').addEventListener('input', () => hooks.onChange()); // a nest shown is for the old values
    this.ui.commonLine.addEventListener('click', () => this.setFollow(0));
    this.ui.spacingDefault.addEventListener('click', () => this.setFollow('default'));
    this.applyPreset();
    this.setFollow('default');
    this.render();
    this.currencyChanged();
    onLangChange(() => this.relocalise());
  }

  /** The currency the sheet costs are in: the Cost panel's ('' when none is set there). */
  currency() {
    return this.hooks.currency?.() ?? '';
  }

  /** The Cost panel's currency set or changed: said beside every cost field. */
  currencyChanged() {
    const cur = this.currency();
    $('sheet-cost-unit').textContent = cur;
    $('sheet-cost-help').textContent = cur ? t('nest.cost-help', { cur }) : t('nest.cost-help-none');
    this.sizes.render();
  }

  setActive(on) {
    if (on === this.active) return;
    this.active = on;
    this.ui.modeDrawing.setAttribute('aria-pressed', String(!on));
    this.ui.modeSheet.setAttribute('aria-pressed', String(on));
    document.body.dataset.mode = on ? 'sheet' : 'drawing';
    this.ui.panel.hidden = !on;
    for (const id of ['panel-drawing', 'panel-layers']) $(id).hidden = on;
    // The nest is in mm and its program in the sheet's own coordinates: these two settings do not apply.
    for (const id of ['units', 'origin']) $(id).disabled = on;
    this.render();
    this.hooks.onMode(on);
  }

  /** The sheet is drawn in a DXF file (its size fields then do not apply), or (null) W × H. */
  setSheetFile(file) {
    this.sheetFile = file;
    $('sheet-dxf-name').textContent = file ? t('nest.sheet-dxf-is', { name: file.name }) : '';
    $('sheet-dxf-clear').hidden = !file;
    for (const key of ['sheet_width', 'sheet_height', 'sheet_count']) $(FIELDS[key].id).disabled = !!file;
    $('sheet-cost').disabled = !!file;
    this.ui.preset.disabled = !!file;
    this.sizes.setDisabled(!!file);
    this.hooks.onChange();
  }

  /** The sheet's fields as a nest file saved them (numbers by key), the spacing as typed. */
  setSheetValues(values) {
    for (const [key, f] of Object.entries(FIELDS)) if (Number.isFinite(values[key])) $(f.id).value = formatValue(values[key], 3);
    // A list's first size is the fields above (its cost too); the rest are its rows.
    const list = Array.isArray(values.sheet_list) ? values.sheet_list : [];
    $('sheet-cost').value = Number.isFinite(list[0]?.cost) ? formatValue(list[0].cost) : '';
    this.sizes.set(list.slice(1));
    this.ui.preset.value = 'custom';
    this.setFollow(null);
  }

  /** Sheet presets fill W × H; "custom" keeps what is typed. */
  applyPreset() {
    const p = PRESETS.find((x) => x.id === this.ui.preset.value);
    if (!p) return;
    $(FIELDS.sheet_width.id).value = formatValue(p.w, 1);
    $(FIELDS.sheet_height.id).value = formatValue(p.h, 1);
  }

  /** The engine's defaults (`nest` of its defaults_json): the spacing beyond the kerf `kerfcam nest` takes. */
  setDefaults(nest) {
    if (Number.isFinite(nest?.spacing_over_kerf)) this.overKerf = nest.spacing_over_kerf;
    // The margin's default is the engine's (`kerfcam nest` uses the same): shown unless kept or typed.
    const margin = $(FIELDS.margin.id);
    if (Number.isFinite(nest?.margin)) {
      const kept = margin.value !== margin.defaultValue;
      margin.defaultValue = formatValue(nest.margin);
      if (!kept) margin.value = margin.defaultValue;
    }
    this.kerfChanged();
  }

  /** Spacing follows the kerf (+ the engine's default, or +0: common line), or is as typed (null). */
  setFollow(d) {
    this.follow = d;
    this.kerfChanged();
  }

  kerfChanged() {
    const kerf = this.hooks.kerf();
    const spacing = $(FIELDS.spacing.id);
    const over = this.follow === 'default' ? this.overKerf : this.follow;
    if (over !== null && Number.isFinite(kerf)) {
      const next = formatValue(kerf + over, 3);
      if (next !== spacing.value && parseNumber(next) !== parseNumber(spacing.value)) this.hooks.onChange();
      spacing.value = next;
    }
    this.ui.spacingHint.textContent = this.follow === null ? t('nest.spacing-own')
      : over === 0 ? t('nest.spacing-common') : over === null ? '' : t('nest.spacing-is', { d: fmtNumber(over), count: over });
    this.ui.commonLine.setAttribute('aria-pressed', String(this.follow === 0));
  }

  relocalise() {
    for (const p of PRESETS) {
      const option = this.ui.preset.querySelector(`option[value="${p.id}"]`);
      if (option) option.textContent = presetLabel(p);
    }
    for (const f of Object.values(FIELDS)) {
      const v = parseNumber($(f.id).value);
      if (Number.isFinite(v)) $(f.id).value = formatValue(v, 3);
    }
    const cost = parseNumber($('sheet-cost').value);
    if (Number.isFinite(cost)) $('sheet-cost').value = formatValue(cost);
    this.currencyChanged();
    this.sizes.relocalise();
    this.kerfChanged();
    if (this.sheetFile) $('sheet-dxf-name').textContent = t('nest.sheet-dxf-is', { name: this.sheetFile.name });
    this.render();
  }

  /**
   * Adds each file as parts (`choices`: each one's saved choices, a nest file's), then reads them. A file
   * already in the list (the same bytes) adds one copy of each of its parts instead of a new row, and says so.
   */
  async addFiles(files, choices = []) {
    files = [...(files || [])];
    if (!choices.length) files = await this.countAgain(files);
    const added = files.map((file, i) => ({
      id: this.nextId++, file, name: file.name, quantity: '1', rotations: '90', mirror: false, grain: false, units: null,
      ...choices[i], info: null, error: '',
    }));
    this.parts.push(...added);
    this.render();
    await this.readInfo(added);
    this.hooks.onChange();
  }

  /** `files` less those already listed (same bytes): those add one to each of their parts' quantities. */
  async countAgain(files) {
    const bytes = async (f) => new Uint8Array(await f.arrayBuffer());
    const same = (a, b) => a.length === b.length && a.every((x, i) => x === b[i]);
    const fresh = [];
    const again = [];
    for (const file of files) {
      const mine = await bytes(file);
      let twin = null;
      for (const p of this.parts) {
        if (p.file.size === file.size && same(await bytes(p.file), mine)) {
          twin = p;
          break;
        }
      }
      if (!twin) {
        fresh.push(file);
        continue;
      }
      const up = (q) => (Number.isFinite(parseQuantity(q, true)) ? String(Math.min(MAX_QUANTITY, parseQuantity(q, true) + 1)) : q);
      twin.quantity = up(twin.quantity);
      (twin.info?.rows ?? []).forEach((r, i) => {
        if (twin.each?.[i] && !r.not_nestable) twin.each[i].quantity = up(twin.each[i].quantity);
      });
      again.push(twin.name);
    }
    if (again.length) {
      this.ui.message.textContent = t('nest.added-again', { names: again.join(', '), count: again.length });
      this.render();
      this.hooks.onChange();
    }
    return fresh;
  }

  /** The page's cutting settings the engine reads parts with, as `kerfcam nest` reads them (or null: its defaults). */
  cutting() {
    return this.hooks.cutting?.() ?? null;
  }

  /** Reads parts files' names, units and areas in the worker (in the unit chosen for each, if any). */
  async readInfo(parts) {
    await Promise.all(parts.map(async (p) => {
      Object.assign(p, { info: null, error: '' });
      this.render();
      try {
        p.info = await this.hooks.engine().call('partInfo', { file: p.file, name: p.name, lang: getLang(), units: p.units, cutting: this.cutting() });
        p.each = eachOf(p, p.each);
      } catch (e) {
        p.error = t('nest.read-failed', { name: p.name, message: e.message || String(e) });
      }
      this.render();
    }));
  }

  /** The parts to nest, or throws an Error listing what to correct (every bad quantity). */
  read() {
    const problems = [];
    const parts = [];
    const turns = (c) => (c.grain ? grainRotations(c.rotations) : c.rotations); // a grain lock turns by 180° at most
    for (const p of this.parts) {
      const rows = p.info?.rows ?? [];
      if (rows.length > 1 && p.each?.length === rows.length) {
        // A file of several parts: each part's own choices (issue 42 §1).
        const each = [];
        rows.forEach((r, i) => {
          const c = p.each[i];
          const q = parseQuantity(c.quantity, true);
          if (!Number.isFinite(q)) problems.push(quantityBad(r.name, true));
          else if (r.not_nestable && q > 0) problems.push(quantityBad(r.name, true, r.not_nestable));
          each.push({ quantity: q, rotations: turns(c), mirror: !!c.mirror, grain: !!c.grain });
        });
        const copies = each.reduce((n, c) => n + c.quantity, 0);
        if (each.every((c) => Number.isFinite(c.quantity)) && copies > 0) {
          parts.push({ file: p.file, name: p.name, quantity: 1, rotations: turns(p), mirror: p.mirror, grain: !!p.grain, units: p.units || null, each, copies });
        }
        continue;
      }
      const q = parseQuantity(p.quantity);
      if (!Number.isFinite(q)) {
        problems.push(quantityBad(p.name, false));
        continue;
      }
      if (!p.info || !p.info.parts.length) continue; // unreadable, or nothing to nest: said on its row
      parts.push({ file: p.file, name: p.name, quantity: q, rotations: turns(p), mirror: p.mirror, grain: !!p.grain, units: p.units || null, copies: q * p.info.parts.length });
    }
    if (problems.length) throw new Error(problems.join(' '));
    return parts;
  }

  /**
   * The copies ordered of each part by its nest name (stem, or stem#number), as read() takes them: the
   * job report's "ordered" (issue 42 §4). A quantity not readable counts as NaN.
   */
  ordered() {
    const out = new Map();
    for (const p of this.parts) {
      const rows = p.info?.rows ?? [];
      rows.forEach((r, i) => {
        const each = rows.length > 1 && p.each?.length === rows.length;
        out.set(r.name, (out.get(r.name) || 0) + parseQuantity(each ? p.each[i].quantity : p.quantity, each));
      });
    }
    return out;
  }

  /** Each part's area by its nest name (stem, or stem#number for a file of several parts), mm². */
  areas() {
    const out = new Map();
    for (const p of this.parts) for (const r of p.info?.rows ?? []) if (Number.isFinite(r.area)) out.set(r.name, r.area);
    return out;
  }

  /** The total area asked for (every copy), mm², for the progress line's estimate. */
  askedArea() {
    let sum = 0;
    for (const p of this.parts) {
      const rows = p.info?.rows ?? [];
      rows.forEach((r, i) => {
        const q = parseQuantity(rows.length > 1 && p.each?.[i] ? p.each[i].quantity : p.quantity, true);
        if (Number.isFinite(q) && Number.isFinite(r.area)) sum += q * r.area;
      });
    }
    return sum;
  }

  /** The sheet's settings for the nester, or throws an Error naming each field out of range. */
  sheetSettings() {
    const out = {};
    const problems = [];
    for (const [key, f] of Object.entries(FIELDS)) {
      const input = $(f.id);
      if (input.disabled) continue; // a sheet from a DXF: its own size
      out[key] = readField(f, input, t(f.label), problems);
    }
    // The stop for the torch setup: both X and Y, or neither (no stop).
    const park = ['torch-park-x', 'torch-park-y'].map((id) => $(id).value.trim());
    const xy = park.map(parseNumber);
    const parkOk = park.every((v) => v === '') || xy.every((v) => Number.isFinite(v) && Math.abs(v) <= 1e6);
    for (const id of ['torch-park-x', 'torch-park-y']) $(id).setAttribute('aria-invalid', String(!parkOk));
    if (!parkOk) problems.push(t('nest.torch-park-bad'));
    else if (park[0] !== '') out.torch_park = xy;
    if (!this.sheetFile) {
      const costs = this.costs(out, problems);
      if (this.sizes.rows.length || costs) out.sheet_list = this.sheetList(out, problems, costs);
    }
    if (problems.length) throw new Error(problems.join(' '));
    return out;
  }

  /**
   * The sizes in their order, the fields above first: [{ width, height, count }], with `cost` when `costs`
   * (one a size) are given. Each row's field out of range is marked and named in `problems` with its row
   * ("Size 2: Width …").
   */
  sheetList(first, problems, costs) {
    const list = [{ width: first.sheet_width, height: first.sheet_height, count: first.sheet_count }];
    const keys = { width: 'sheet_width', height: 'sheet_height', count: 'sheet_count' };
    this.sizes.rows.forEach((row, i) => {
      const size = {};
      for (const [key, field] of Object.entries(keys)) {
        const f = FIELDS[field];
        size[key] = readField(f, row.inputs[key], `${t('nest.size-row', { n: String(i + 2) })}: ${t(f.label)}`, problems);
      }
      list.push(size);
    });
    if (costs) list.forEach((size, i) => (size.cost = costs[i]));
    return list;
  }

  /**
   * Each size's cost per sheet, the field above first (issue 44 item 3), or null when every one is blank. The
   * rule is `kerfcam nest --sheet WxH:N:COST`'s (src/nest/stock.rs stock_of): a cost for every size or for
   * none, a price ≥ 0, one torch. A cost refused is marked and said at its field, and named in `problems`.
   */
  costs(settings, problems) {
    const fields = [
      { input: $('sheet-cost'), at: $('sheet-cost-unit'), label: t('nest.cost') },
      ...this.sizes.rows.map((r, i) => ({
        input: r.inputs.cost, at: r.inputs.cost.closest('li'), label: `${t('nest.size-row', { n: String(i + 2) })}: ${t('nest.size-cost-plain')}`,
      })),
    ];
    for (const f of fields) f.input.setAttribute('aria-invalid', 'false');
    for (const p of $('nest-form').querySelectorAll('.field-error[data-for]')) p.remove();
    const typed = fields.map((f) => f.input.value.trim());
    if (typed.every((v) => v === '')) return null;
    const say = (f, message) => {
      f.input.setAttribute('aria-invalid', 'true');
      const p = el('p', message, { className: 'field-error small', role: 'alert' });
      p.dataset.for = f.input.id;
      if (f.at.tagName === 'LI') f.at.append(p);
      else f.at.insertAdjacentElement('afterend', p);
      problems.push(message);
    };
    const costs = typed.map((v) => (v === '' ? null : parseNumber(v)));
    fields.forEach((f, i) => {
      const c = costs[i];
      if (c === null) say(f, t('nest.cost-some', { label: f.label }));
      else if (!(Number.isFinite(c) && c >= 0)) say(f, t('nest.cost-bad', { label: f.label }));
      else if (settings.torches > 1) say(f, t('nest.cost-torches', { label: f.label }));
    });
    return costs;
  }

  render() {
    const { list, count } = this.ui;
    count.textContent = this.parts.length ? `(${fmtNumber(this.parts.length)})` : '';
    if (!this.parts.length) {
      list.replaceChildren(el('li', t('nest.no-parts'), { className: 'muted small' }));
      return;
    }
    list.replaceChildren(...this.parts.map((p) => this.row(p)));
  }

  row(p) {
    return partRow(p, {
      quantityOk: (text, zero) => Number.isFinite(parseQuantity(text, zero)),
      quantityBad,
      changed: () => this.hooks.onChange(),
      remove: (x) => {
        this.parts = this.parts.filter((y) => y !== x);
        this.render();
        this.hooks.onChange();
        this.ui.input.focus();
      },
      reread: (x) => this.readInfo([x]).then(() => this.hooks.onChange()),
    });
  }
}

/** What state.name is in Sheet mode: the program's file name. */
export const sheetName = (k) => `nest-sheet-${k + 1}`;
