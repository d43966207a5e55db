// kerfcam page: the process technology panel (issue 20) — small holes, tabs, the torch-height lock,
// depth passes, the controller's compensation and the verification of the cut, the settings the CLI
// had alone. Its number fields join numbers.js's table (typed the local way, checked against the
// engine's ranges, kept across a reload); its checkboxes and the verification's figures are here.

import { FIELDS } from './numbers.js';
import { fmtNumber, onLangChange, register, t } from './i18n.js';

const TEXT = {
  en: {
    'process.heading': 'Process technology',
    'process.small-holes': 'Small holes: slower, the height locked, entered from the centre (0 = off)',
    'process.small-hole': 'Small holes below',
    'process.small-hole-speed': 'Small-hole speed',
    'process.small-hole-min': 'Spot holes below',
    'process.tabs-help': "Tabs: material left uncut on each part's outline; the torch goes off over each (0 = none)",
    'process.tabs': 'Tabs per part',
    'process.tab-width': 'Tab width',
    'process.tab-holes': 'Tabs on holes',
    'process.tab-holes.hint': 'holes too',
    'process.thc-help': "Height lock before sharp corners and the contour's end (the post's lock codes; 0 = off)",
    'process.thc-corner': 'Lock at corners',
    'process.thc-corner-angle': 'Corners sharper than',
    'process.thc-end': 'Lock before the end',
    'process.depth-help': 'Depth passes (knife, router; 0 = one pass)',
    'process.depth': 'Depth',
    'process.pass-depth': 'Deepest pass',
    'process.controller-comp': 'Kerf at the controller',
    'process.controller-comp.hint': 'G41/G42 on the lead-in, the drawn contours',
    'process.verify': 'Check the cut',
    'process.verify.hint': 'sweep the kerf over the parts',
    'process.verify.clean': 'Checked: the kerf takes nothing from the parts and frees every part.',
    'process.verify.result':
      'Checked: {area} mm² of part material taken, up to {depth} mm past an edge; {free} part(s) not cut free; {tabs} held by tabs.',
  },
  'pt-BR': {
    'process.heading': 'Tecnologia do processo',
    'process.small-holes': 'Furos pequenos: mais lentos, altura travada, entrada pelo centro (0 = desligado)',
    'process.small-hole': 'Furos pequenos abaixo de',
    'process.small-hole-speed': 'Velocidade em furos pequenos',
    'process.small-hole-min': 'Marcar furos abaixo de',
    'process.tabs-help': 'Pontes: material deixado sem cortar no contorno de cada peça; a tocha desliga sobre cada uma (0 = nenhuma)',
    'process.tabs': 'Pontes por peça',
    'process.tab-width': 'Largura da ponte',
    'process.tab-holes': 'Pontes em furos',
    'process.tab-holes.hint': 'furos também',
    'process.thc-help': 'Trava de altura antes de cantos vivos e do fim do contorno (códigos de trava do pós; 0 = desligado)',
    'process.thc-corner': 'Travar nos cantos',
    'process.thc-corner-angle': 'Cantos mais vivos que',
    'process.thc-end': 'Travar antes do fim',
    'process.depth-help': 'Passes em profundidade (faca, fresa; 0 = um passe)',
    'process.depth': 'Profundidade',
    'process.pass-depth': 'Passe mais fundo',
    'process.controller-comp': 'Sangria no controlador',
    'process.controller-comp.hint': 'G41/G42 na entrada, os contornos desenhados',
    'process.verify': 'Verificar o corte',
    'process.verify.hint': 'varrer a sangria sobre as peças',
    'process.verify.clean': 'Verificado: a sangria não remove nada das peças e solta todas.',
    'process.verify.result':
      'Verificado: {area} mm² de material das peças removidos, até {depth} mm além de uma aresta; {free} peça(s) não soltas; {tabs} presas por pontes.',
  },
};
register(TEXT);

// The engine's ranges (src/settings.rs): a value the page accepts is one the engine takes.
Object.assign(FIELDS, {
  small_hole_diameter: { id: 'small-hole', label: 'process.small-hole', min: 0, max: 1000, step: 0.5, unit: 'mm' },
  small_hole_speed: { id: 'small-hole-speed', label: 'process.small-hole-speed', min: 10, max: 100, step: 5, unit: '%' },
  small_hole_min: { id: 'small-hole-min', label: 'process.small-hole-min', min: 0, max: 1000, step: 0.5, unit: 'mm' },
  tabs: { id: 'tabs', label: 'process.tabs', min: 0, max: 100, step: 1, unit: '' },
  tab_width: { id: 'tab-width', label: 'process.tab-width', min: 0, max: 1000, step: 0.5, unit: 'mm', above: true },
  thc_corner_distance: { id: 'thc-corner', label: 'process.thc-corner', min: 0, max: 1000, step: 0.5, unit: 'mm' },
  thc_corner_angle: { id: 'thc-corner-angle', label: 'process.thc-corner-angle', min: 1, max: 179, step: 5, unit: '°' },
  thc_end_distance: { id: 'thc-end', label: 'process.thc-end', min: 0, max: 1000, step: 0.5, unit: 'mm' },
  depth: { id: 'depth', label: 'process.depth', min: 0, max: 1000, step: 0.5, unit: 'mm' },
  pass_depth: { id: 'pass-depth', label: 'process.pass-depth', min: 0, max: 1000, step: 0.5, unit: 'mm' },
});

/** The panel: its checkboxes into the settings, the verification's figures under it. */
export class ProcessPanel {
  /** `ui`: { form, tabHoles, controllerComp, verify, result }; `onChange()`: re-run the job. */
  constructor(ui, onChange) {
    this.ui = ui;
    this.report = null;
    for (const box of [ui.tabHoles, ui.controllerComp, ui.verify]) box.addEventListener('change', () => onChange());
    onLangChange(() => this.show(this.report));
  }

  /** Adds the panel's choices to `settings` (its numbers are already there, from numbers.js). */
  settings(settings) {
    settings.tab_holes = this.ui.tabHoles.checked;
    settings.controller_comp = this.ui.controllerComp.checked;
    settings.verify = this.ui.verify.checked;
    // A count: 2.4 tabs are 2 (the field steps by one; a typed fraction is rounded, not refused).
    if (Number.isFinite(settings.tabs)) settings.tabs = Math.round(settings.tabs);
    return settings;
  }

  /** The report's verification, when the cut was checked (numbers only: nothing from the file). */
  show(report) {
    this.report = report;
    const v = report?.verification;
    const box = this.ui.result;
    box.hidden = !v;
    if (!v) return;
    const clean = v.overcut_mm2 === 0 && v.max_overcut_mm === 0 && v.parts_not_freed === 0 && !v.parts_held_by_tabs;
    box.textContent = clean
      ? t('process.verify.clean')
      : t('process.verify.result', {
        area: fmtNumber(v.overcut_mm2, 3), depth: fmtNumber(v.max_overcut_mm, 3),
        free: String(v.parts_not_freed), tabs: String(v.parts_held_by_tabs || 0),
      });
    box.dataset.clean = String(clean);
  }
}
