// kerfcam page: the router's tool (issue 43) — the end mill that profiles, pockets, engraves and drills
// the layers given a milling operation in the layers panel. Shown when a layer has one; its number
// fields join numbers.js's table (typed the local way, checked against the engine's ranges at the
// field, kept across a reload), its choices are selects kept with the form. The values reach the
// engine under the CLI's Spec names (--tool-diameter, --stepover, --entry…), so the page's program is
// the CLI's for the same values.

import { FIELDS, parseNumber } from './numbers.js';
import { fmtNumber, onLangChange, register, t } from './i18n.js';

/** The layer operations that need the tool. */
export const MILLING = ['profile', 'pocket', 'engrave', 'drill'];

register({
  en: {
    'tool.heading': 'Router tool',
    'tool.help': 'The end mill for the layers set to profile, pocket, engrave or drill. Depth and deepest pass: Process technology; feed: Settings. The profiles are cut with the tool\'s width (the kerf field is not used); with Lead-in: arc they enter and leave each pass on arcs of the lead-in arc radius, in the waste.',
    'tool.diameter': 'Tool diameter',
    'tool.stepover': 'Stepover',
    'tool.plunge-feed': 'Plunge feed',
    'tool.spindle': 'Spindle speed',
    'tool.number': 'Tool number (T, H)',
    'tool.milling': 'Direction',
    'tool.milling.climb': 'climb',
    'tool.milling.conventional': 'conventional',
    'tool.pocket': 'Pocket strategy',
    'tool.pocket.zigzag': 'zig-zag',
    'tool.pocket.offset': 'contour-parallel',
    'tool.pocket-from': 'Contour-parallel order',
    'tool.pocket-from.centre': 'from the centre outwards',
    'tool.pocket-from.walls': 'from the walls inwards',
    'tool.pocket-angle': 'Zig-zag angle',
    'tool.entry': 'Entry',
    'tool.entry.plunge': 'plunge',
    'tool.entry.ramp': 'ramp',
    'tool.entry.helix': 'helix',
    'tool.ramp-angle': 'Ramp angle',
    'tool.helix-diameter': 'Helix diameter (0 = the tool\'s radius)',
    'tool.allowance': 'Stock allowance for the finishing pass',
    'tool.peck': 'Drilling peck (0 = the deepest pass)',
    'tool.drill-max': 'Drill circles up to (0 = the tool\'s diameter)',
    'tool.v-angle': 'V-bit angle (0 = a flat end mill)',
    'tool.engrave-width': 'Engraving width with a V-bit (0 = from the depth)',
    'tool.engrave-depth': 'Engraving depth with a V-bit (0 = from the width, else the job\'s depth)',
    'tool.v-engraving': 'Engraving with the {angle}° V-bit: {depth} mm deep, {width} mm wide at the top (width = 2 × depth × tan(angle/2)).',
    'tool.lead-radius': 'Lead-in arc radius (0 = the tool\'s diameter)',
    'tool.tab-height': 'Tab height at the bottom (0 = the tool lifts over the tab)',
    'tool.list.heading': 'Other tools',
    'tool.list.help': 'Each pocket, engrave or drill layer can take one of these in the layers panel. The program machines them in this order, then the tool above (which also cuts the profiles), with a tool change between. Feeds in mm/min; blank feeds and speed: the tool above\'s.',
    'tool.list.number': 'No.',
    'tool.list.diameter': 'Diameter (mm)',
    'tool.list.v-angle': 'V angle (°)',
    'tool.list.feed': 'Feed (mm/min)',
    'tool.list.plunge': 'Plunge (mm/min)',
    'tool.list.spindle': 'Spindle (rpm)',
    'tool.list.number.short': 'No.',
    'tool.list.diameter.short': 'Ø mm',
    'tool.list.v-angle.short': 'V °',
    'tool.list.feed.short': 'Feed',
    'tool.list.plunge.short': 'Plunge',
    'tool.list.spindle.short': 'rpm',
    'tool.list.add': 'Add a tool',
    'tool.list.remove': 'Remove tool {n}',
    'tool.list.field': 'Tool {n}: {field}',
    'layers.tool': 'Tool of layer {name}',
    'layers.tool.job': 'tool T{n} (Router tool)',
    'layers.tool.listed': 'tool T{n}, {d} mm',
  },
  'pt-BR': {
    'tool.heading': 'Ferramenta da fresadora',
    'tool.help': 'A fresa das camadas marcadas para perfil, bolsão, gravar ou furar. Profundidade e passe mais fundo: Tecnologia do processo; avanço: Configurações. Os perfis são cortados com a largura da ferramenta (o campo de sangria não é usado); com Entrada: arco, entram e saem de cada passe por arcos do raio da entrada em arco, na sobra.',
    'tool.diameter': 'Diâmetro da ferramenta',
    'tool.stepover': 'Passo lateral',
    'tool.plunge-feed': 'Avanço de mergulho',
    'tool.spindle': 'Rotação do fuso',
    'tool.number': 'Número da ferramenta (T, H)',
    'tool.milling': 'Sentido',
    'tool.milling.climb': 'concordante',
    'tool.milling.conventional': 'convencional',
    'tool.pocket': 'Estratégia do bolsão',
    'tool.pocket.zigzag': 'zigue-zague',
    'tool.pocket.offset': 'paralela ao contorno',
    'tool.pocket-from': 'Ordem paralela ao contorno',
    'tool.pocket-from.centre': 'do centro para fora',
    'tool.pocket-from.walls': 'das paredes para dentro',
    'tool.pocket-angle': 'Ângulo do zigue-zague',
    'tool.entry': 'Entrada',
    'tool.entry.plunge': 'mergulho',
    'tool.entry.ramp': 'rampa',
    'tool.entry.helix': 'hélice',
    'tool.ramp-angle': 'Ângulo da rampa',
    'tool.helix-diameter': 'Diâmetro da hélice (0 = o raio da ferramenta)',
    'tool.allowance': 'Sobremetal para o passe de acabamento',
    'tool.peck': 'Avanço por bicada ao furar (0 = o passe mais fundo)',
    'tool.drill-max': 'Furar círculos até (0 = o diâmetro da ferramenta)',
    'tool.v-angle': 'Ângulo da fresa em V (0 = fresa de topo reto)',
    'tool.engrave-width': 'Largura da gravação com fresa em V (0 = pela profundidade)',
    'tool.engrave-depth': 'Profundidade da gravação com fresa em V (0 = pela largura, senão a do trabalho)',
    'tool.v-engraving': 'Gravação com a fresa em V de {angle}°: {depth} mm de profundidade, {width} mm de largura no topo (largura = 2 × profundidade × tan(ângulo/2)).',
    'tool.lead-radius': 'Raio da entrada em arco (0 = o diâmetro da ferramenta)',
    'tool.tab-height': 'Altura da ponte no fundo (0 = a ferramenta sobe sobre ela)',
    'tool.list.heading': 'Outras ferramentas',
    'tool.list.help': 'Cada camada de bolsão, gravação ou furação pode receber uma destas no painel de camadas. O programa as usa nesta ordem, depois a ferramenta acima (que também corta os perfis), com uma troca de ferramenta entre elas. Avanços em mm/min; avanços e rotação em branco: os da ferramenta acima.',
    'tool.list.number': 'Nº',
    'tool.list.diameter': 'Diâmetro (mm)',
    'tool.list.v-angle': 'Ângulo do V (°)',
    'tool.list.feed': 'Avanço (mm/min)',
    'tool.list.plunge': 'Mergulho (mm/min)',
    'tool.list.spindle': 'Rotação (rpm)',
    'tool.list.number.short': 'Nº',
    'tool.list.diameter.short': 'Ø mm',
    'tool.list.v-angle.short': 'V °',
    'tool.list.feed.short': 'Avanço',
    'tool.list.plunge.short': 'Merg.',
    'tool.list.spindle.short': 'rpm',
    'tool.list.add': 'Acrescentar ferramenta',
    'tool.list.remove': 'Remover a ferramenta {n}',
    'tool.list.field': 'Ferramenta {n}: {field}',
    'layers.tool': 'Ferramenta da camada {name}',
    'layers.tool.job': 'ferramenta T{n} (Ferramenta da fresadora)',
    'layers.tool.listed': 'ferramenta T{n}, {d} mm',
  },
});

// The engine's ranges (src/settings/process.rs): a value the page accepts is one the engine takes. The
// helix's diameter (up to the tool's) and the allowance (up to its radius) follow the tool's diameter as
// it is when the fields are checked (numbers.js `follows`), whichever was typed first.
const toolMax = (v, k) => (v.tool_diameter > 0 && v.tool_diameter <= 200 ? v.tool_diameter * k : undefined);
const TOOL_FIELDS = {
  tool_diameter: { id: 'tool-diameter', label: 'tool.diameter', min: 0, max: 200, step: 0.5, unit: 'mm', above: true },
  stepover: { id: 'stepover', label: 'tool.stepover', min: 1, max: 100, step: 5, unit: '%' },
  plunge_feed: { id: 'plunge-feed', label: 'tool.plunge-feed', min: 0.001, max: 1000000, step: 50, unit: 'mm/min' },
  spindle_rpm: { id: 'spindle-rpm', label: 'tool.spindle', min: 0, max: 1000000, step: 1000, unit: 'rpm' },
  // The post's {tool_number}: LinuxCNC's and Mach3's T… M6 and G43 H… (a whole number).
  tool_number: { id: 'tool-number', label: 'tool.number', min: 1, max: 99999, step: 1, unit: '', whole: true },
  pocket_angle: { id: 'pocket-angle', label: 'tool.pocket-angle', min: -360, max: 360, step: 15, unit: '°' },
  ramp_angle: { id: 'ramp-angle', label: 'tool.ramp-angle', min: 0.1, max: 45, step: 0.5, unit: '°' },
  helix_diameter: { id: 'helix-diameter', label: 'tool.helix-diameter', min: 0, max: 200, step: 0.5, unit: 'mm', follows: (v) => ({ max: toolMax(v, 1) }) },
  allowance: { id: 'allowance', label: 'tool.allowance', min: 0, max: 100, step: 0.1, unit: 'mm', follows: (v) => ({ max: toolMax(v, 0.5) }) },
  peck: { id: 'peck', label: 'tool.peck', min: 0, max: 1000, step: 0.5, unit: 'mm' },
  drill_max: { id: 'drill-max', label: 'tool.drill-max', min: 0, max: 1000, step: 0.5, unit: 'mm' },
  // A V-bit's angle: 0 (none) or 1° to 179°; the engraving's width (its depth follows) needs one, and
  // is at most the tool's diameter.
  v_angle: { id: 'v-angle', label: 'tool.v-angle', min: 0, max: 179, step: 15, unit: '°', follows: (v) => ({ min: v.v_angle > 0 ? 1 : undefined }) },
  // The profiles' lead arcs (Lead-in: arc), entering and leaving each depth pass in the waste.
  lead_radius: { id: 'lead-radius', label: 'tool.lead-radius', min: 0, max: 200, step: 0.5, unit: 'mm' },
  // The tabs' bridge: the passes deeper than depth − height go over it, those above cut through.
  tab_height: { id: 'tab-height', label: 'tool.tab-height', min: 0, max: 1000, step: 0.5, unit: 'mm' },
  engrave_width: { id: 'engrave-width', label: 'tool.engrave-width', min: 0, max: 200, step: 0.1, unit: 'mm', follows: (v) => ({ max: v.v_angle > 0 ? toolMax(v, 1) : 0 }) },
  // Or the engraving's own depth (the width follows): a V-bit's too, and not with a width.
  engrave_depth: { id: 'engrave-depth', label: 'tool.engrave-depth', min: 0, max: 1000, step: 0.1, unit: 'mm', follows: (v) => ({ max: v.v_angle > 0 && !(v.engrave_width > 0) ? undefined : 0 }) },
};
Object.assign(FIELDS, TOOL_FIELDS);

/** The selects: settings key → element id. */
const CHOICES = { milling: 'milling', pocket: 'pocket', pocket_from: 'pocket-from', entry: 'entry' };

// The job's other tools (issue 43 §1): a short list as a shop's tool table has it — number, diameter,
// V angle, feeds, spindle speed (blank: the tool above's) — kept in this browser. The engine's Spec
// `tools` (the CLI's --tool N=MM,key=value…); each layer's pick is its `layer_tools` (--layer-tool).
const LIST_KEY = 'kerfcam.tool-list';
const COLUMNS = [
  ['number', 'tool.list.number', 'numeric'],
  ['diameter', 'tool.list.diameter', 'decimal'],
  ['v_angle', 'tool.list.v-angle', 'decimal'],
  ['feed', 'tool.list.feed', 'decimal'],
  ['plunge_feed', 'tool.list.plunge', 'decimal'],
  ['spindle_rpm', 'tool.list.spindle', 'decimal'],
];
// The panel is narrow: each column's head is short (`….short`), the field's own label the whole one.

function loadList() {
  try {
    const rows = JSON.parse(localStorage.getItem(LIST_KEY) || '[]');
    return Array.isArray(rows) ? rows.filter((r) => r && typeof r === 'object').map((r) => Object.fromEntries(COLUMNS.map(([k]) => [k, String(r[k] ?? '')]))) : [];
  } catch {
    return [];
  }
}

/** A row's values as the engine takes them, or null while its number or diameter is not a good one. */
function toolOf(row) {
  const n = parseNumber(row.number);
  const d = parseNumber(row.diameter);
  if (!Number.isInteger(n) || n < 1 || !(d > 0)) return null;
  const opt = (k) => (row[k].trim() === '' ? null : parseNumber(row[k]));
  return { number: n, diameter: d, v_angle: opt('v_angle') ?? 0, feed: opt('feed'), plunge_feed: opt('plunge_feed'), spindle_rpm: opt('spindle_rpm') };
}

export class ToolPanel {
  /** `ui`: { panel (the <details>), form }; `onChange()`: re-run the job. */
  constructor(ui, onChange) {
    this.ui = ui;
    for (const id of Object.values(CHOICES)) document.getElementById(id).addEventListener('change', () => onChange());
    onLangChange(() => {
      this.showReport(this.report);
      this.renderList();
      ui.onList?.();
    });
    this.rows = loadList();
    this.renderList();
    const saved = () => localStorage.setItem(LIST_KEY, JSON.stringify(this.rows));
    ui.list.addEventListener('change', (e) => {
      const input = e.target.closest('input[data-key]');
      if (!input) return;
      this.rows[Number(input.dataset.row)][input.dataset.key] = input.value;
      saved();
      this.markRows();
      ui.onList?.();
      onChange();
    });
    ui.list.addEventListener('click', (e) => {
      const b = e.target.closest('button[data-row]');
      if (!b) return;
      this.rows.splice(Number(b.dataset.row), 1);
      saved();
      this.renderList();
      ui.onList?.();
      onChange();
    });
    ui.addTool.addEventListener('click', () => {
      const used = new Set([this.jobNumber(), ...this.rows.map((r) => parseNumber(r.number))]);
      let n = 2;
      while (used.has(n)) n++;
      this.rows.push({ number: String(n), diameter: '', v_angle: '', feed: '', plunge_feed: '', spindle_rpm: '' });
      saved();
      this.renderList();
      ui.onList?.();
      ui.list.querySelector(`input[data-row="${this.rows.length - 1}"][data-key="diameter"]`)?.focus();
    });
  }

  /** The job's own tool's number (the panel's field). */
  jobNumber() {
    const n = parseNumber(document.getElementById('tool-number').value);
    return Number.isInteger(n) ? n : 1;
  }

  /** The listed tools with a good number and diameter: [{number, diameter, …}]. */
  listed() {
    return this.rows.map(toolOf).filter(Boolean);
  }

  /** The list as rows of text fields (values as typed; the labels in the page's language). */
  renderList() {
    const head = this.ui.listHead;
    head.replaceChildren(...COLUMNS.map(([, label]) => {
      const th = document.createElement('th');
      th.textContent = t(`${label}.short`);
      th.title = t(label);
      th.scope = 'col';
      return th;
    }), document.createElement('th'));
    this.ui.list.replaceChildren(...this.rows.map((row, i) => {
      const tr = document.createElement('tr');
      for (const [key, label, mode] of COLUMNS) {
        const td = document.createElement('td');
        const input = document.createElement('input');
        Object.assign(input, { type: 'text', inputMode: mode, autocomplete: 'off', spellcheck: false, value: row[key] });
        input.dataset.row = String(i);
        input.dataset.key = key;
        input.setAttribute('aria-label', t('tool.list.field', { n: row.number || i + 1, field: t(label) }));
        td.append(input);
        tr.append(td);
      }
      const td = document.createElement('td');
      const b = document.createElement('button');
      Object.assign(b, { type: 'button', className: 'small-button', textContent: '×' });
      b.dataset.row = String(i);
      b.setAttribute('aria-label', t('tool.list.remove', { n: row.number || i + 1 }));
      td.append(b);
      tr.append(td);
      return tr;
    }));
    this.ui.listTable.hidden = !this.rows.length;
    this.markRows();
  }

  /** A row whose number or diameter is not a good one is marked at those fields. */
  markRows() {
    this.rows.forEach((row, i) => {
      const bad = !toolOf(row);
      for (const key of ['number', 'diameter']) {
        const input = this.ui.list.querySelector(`input[data-row="${i}"][data-key="${key}"]`);
        const n = parseNumber(row[key]);
        const ok = key === 'number' ? Number.isInteger(n) && n >= 1 : n > 0;
        input?.setAttribute('aria-invalid', String(bad && !ok));
      }
    });
  }

  /** The V-bit engraving's depth and width as the engine made them (`report.plan.engraving`), or none. */
  showReport(report) {
    this.report = report;
    const e = report?.plan?.engraving;
    const out = this.ui.engraving;
    if (!out) return;
    out.hidden = !e;
    out.textContent = e ? t('tool.v-engraving', { angle: fmtNumber(e.v_angle), depth: fmtNumber(e.depth, 3), width: fmtNumber(e.width, 3) }) : '';
  }

  /**
   * The tool's values into `settings` when one of `settings.layer_ops` mills (the panel shown), else
   * none of them (the panel hidden): the engine's defaults, no tool. With a tool the kerf is left
   * out: the profiles are cut with the tool's width, as the CLI's --tool-diameter without --kerf.
   * `shown`: the settings are the shown file's (the panel follows its layers), not another listed file's.
   */
  settings(settings, shown = true) {
    const active = (settings.layer_ops || []).some(([, op]) => MILLING.includes(op));
    if (shown) this.ui.panel.hidden = !active;
    if (!active) {
      for (const key of Object.keys(TOOL_FIELDS)) delete settings[key];
      delete settings.tools;
      delete settings.layer_tools;
      delete settings.layer_depths;
      return settings;
    }
    for (const [key, id] of Object.entries(CHOICES)) settings[key] = document.getElementById(id).value;
    delete settings.kerf;
    // The listed tools a milling layer takes; a pick of a tool no longer listed is the job's tool's.
    const listed = this.listed();
    const numbers = new Set(listed.map((l) => l.number));
    const milling = new Set((settings.layer_ops || []).filter(([, op]) => ['pocket', 'engrave', 'drill'].includes(op)).map(([l]) => l));
    settings.layer_tools = (settings.layer_tools || []).filter(([l, n]) => numbers.has(n) && milling.has(l));
    // A layer's own depth where it mills; a depth with no pass takes the job's (the engine's default).
    settings.layer_depths = (settings.layer_depths || []).filter((d) => milling.has(d.layer));
    const used = new Set(settings.layer_tools.map(([, n]) => n));
    settings.tools = listed.filter((l) => used.has(l.number));
    return settings;
  }
}
