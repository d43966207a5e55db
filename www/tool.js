// kerfcam page: the router's tool (issue 43) — the end mill that profiles, pockets, engraves and drills
// the layers given a milling operation in the layers panel. Shown when a layer has one; its number
// fields join numbers.js's table (typed the local way, checked against the engine's ranges at the
// field, kept across a reload), its choices are selects kept with the form. The values reach the
// engine under the CLI's Spec names (--tool-diameter, --stepover, --entry…), so the page's program is
// the CLI's for the same values.

import { FIELDS } from './numbers.js';
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

export class ToolPanel {
  /** `ui`: { panel (the <details>), form }; `onChange()`: re-run the job. */
  constructor(ui, onChange) {
    this.ui = ui;
    for (const id of Object.values(CHOICES)) document.getElementById(id).addEventListener('change', () => onChange());
    onLangChange(() => this.showReport(this.report));
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
      return settings;
    }
    for (const [key, id] of Object.entries(CHOICES)) settings[key] = document.getElementById(id).value;
    delete settings.kerf;
    return settings;
  }
}
