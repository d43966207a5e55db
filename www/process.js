// kerfcam page: the process technology panel (issue 20) — small holes, tabs, the torch-height lock,
// depth passes, the repair of self-crossing outlines (issue 45 §2), the controller's compensation and
// the verification of the cut, the settings the CLI had alone. Its number fields join numbers.js's
// table (typed the local way, checked against the engine's ranges, kept across a reload); its
// checkboxes and the verification's figures are here.

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
    'process.repair': 'Self-crossing outlines',
    'process.repair.hint': 'repaired: the region they enclose is cut',
    'process.controller-comp': 'Kerf at the controller',
    'process.controller-comp.hint': 'G41/G42 on the lead-in, the drawn contours',
    'process.fit-arcs': 'Arc fitting',
    'process.fit-arcs.hint': 'G2/G3 for short lines on an arc',
    'process.incremental': 'Incremental (G91)',
    'process.incremental.hint': 'moves relative to the last point',
    'process.verify': 'Check the cut',
    'process.verify.hint': 'sweep the kerf over the parts',
    'process.verify.clean': 'Checked: the kerf takes nothing from the parts and frees every part.',
    'process.verify.result':
      'Checked: {area} mm² of part material taken, up to {depth} mm past an edge; {free} part(s) not cut free; {tabs} held by tabs.',
    'process.verify-heat': 'Show on the preview',
    'process.verify-heat.hint': 'where parts are overcut or not freed',
    'legend.overcut': 'Overcut (darker: deeper)',
    'legend.overcut.title': 'Where the kerf takes part material, as the check counts it',
    'legend.attached': 'Not freed',
    'legend.attached.title': 'Outline of a part not cut free that no cut reaches: it stays attached here',
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
    'process.repair': 'Contornos que se cruzam',
    'process.repair.hint': 'reparados: corta-se a região que encerram',
    'process.controller-comp': 'Sangria no controlador',
    'process.controller-comp.hint': 'G41/G42 na entrada, os contornos desenhados',
    'process.fit-arcs': 'Ajuste de arcos',
    'process.fit-arcs.hint': 'G2/G3 no lugar de linhas curtas em arco',
    'process.incremental': 'Coordenadas incrementais (G91)',
    'process.incremental.hint': 'movimentos relativos ao último ponto',
    'process.verify': 'Verificar o corte',
    'process.verify.hint': 'varrer a sangria sobre as peças',
    'process.verify.clean': 'Verificado: a sangria não remove nada das peças e solta todas.',
    'process.verify.result':
      'Verificado: {area} mm² de material das peças removidos, até {depth} mm além de uma aresta; {free} peça(s) não soltas; {tabs} presas por pontes.',
    'process.verify-heat': 'Mostrar na prévia',
    'process.verify-heat.hint': 'onde as peças são invadidas ou não se soltam',
    'legend.overcut': 'Invasão (mais escuro: mais fundo)',
    'legend.overcut.title': 'Onde a sangria remove material das peças, como a verificação conta',
    'legend.attached': 'Não solta',
    'legend.attached.title': 'Contorno de uma peça não solta que nenhum corte alcança: ela fica presa aqui',
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
  // Depth passes need both values (src/settings/process.rs): one given, the other is said at its field.
  depth: { id: 'depth', label: 'process.depth', min: 0, max: 1000, step: 0.5, unit: 'mm', follows: (v) => ({ above: v.pass_depth > 0 }) },
  pass_depth: { id: 'pass-depth', label: 'process.pass-depth', min: 0, max: 1000, step: 0.5, unit: 'mm', follows: (v) => ({ above: v.depth > 0 }) },
});

// The heat map's colours (style.css's .swatch.overcut and .swatch.attached).
const OVERCUT = [255, 0, 110];
const ATTACHED = '#6a00f4';

/**
 * Squares `q` = [side, x, y, depth, …] (mm) in colour `rgb`, darker where deeper, at least two device
 * pixels wide so a thin overcut shows on a whole sheet: the verification's heat map, and the closeness
 * check's (losses.js).
 */
export function drawSquares(ctx, px, dpr, q, rgb) {
  const { width, height } = ctx.canvas;
  const side = q[0];
  let deepest = 0;
  for (let i = 3; i < q.length; i += 3) deepest = Math.max(deepest, q[i]);
  const [x0] = px(0, 0);
  const [x1] = px(side, 0);
  const size = Math.max(2 * dpr, Math.abs(x1 - x0));
  for (let i = 1; i < q.length; i += 3) {
    const [x, y] = px(q[i], q[i + 1]);
    if (x < -size || y < -size || x > width + size || y > height + size) continue;
    const alpha = 0.35 + 0.6 * (deepest > 0 ? q[i + 2] / deepest : 1);
    ctx.fillStyle = `rgba(${rgb.join(', ')}, ${alpha.toFixed(2)})`;
    ctx.fillRect(x - size / 2, y - size / 2, size, size);
  }
}

/** The panel: its checkboxes into the settings, the verification's figures under it, its heat map. */
export class ProcessPanel {
  /**
   * `ui`: { tabHoles, repair, controllerComp, verify, fitArcs, incremental, result, heat, legend: [li…] }; `onChange()`: re-run the job;
   * `redraw()`: draw the preview's overlay again.
   */
  constructor(ui, onChange, redraw = () => {}) {
    this.ui = ui;
    this.report = null;
    this.heat = null; // { squares: Float64Array [side, x, y, depth, …], attached: [x, y, …] } of the job shown
    for (const box of [ui.tabHoles, ui.repair, ui.controllerComp, ui.verify, ui.fitArcs, ui.incremental]) {
      box?.addEventListener('change', () => onChange());
    }
    ui.heat?.addEventListener('change', () => {
      this.showLegend();
      redraw();
    });
    onLangChange(() => this.show(this.report));
  }

  /** The verification's raster of the job shown (worker: Job.overcut_heat, Job.attached_points), or null. */
  setHeat(squares, attached) {
    this.heat = squares?.length || attached?.length ? { squares: squares || [], attached: attached || [] } : null;
    this.showLegend();
  }

  drawing() {
    return !!(this.heat && this.ui.heat?.checked);
  }

  showLegend() {
    const [overcut, attached] = this.ui.legend || [];
    if (overcut) overcut.hidden = !(this.drawing() && this.heat.squares.length);
    if (attached) attached.hidden = !(this.drawing() && this.heat.attached.length);
  }

  /**
   * Overlay decoration (PlanLayer.decorations): the overcut squares, darker where deeper, at least two
   * device pixels wide so a thin overcut shows on a whole sheet; the points where parts stay attached.
   */
  decorate(ctx, px, dpr) {
    if (!this.drawing()) return;
    const { squares: q, attached: a } = this.heat;
    const { width, height } = ctx.canvas;
    if (q.length) drawSquares(ctx, px, dpr, q, OVERCUT);
    ctx.fillStyle = ATTACHED;
    const r = 2 * dpr;
    for (let i = 0; i < a.length; i += 2) {
      const [x, y] = px(a[i], a[i + 1]);
      if (x < -r || y < -r || x > width + r || y > height + r) continue;
      ctx.fillRect(x - r, y - r, 2 * r, 2 * r);
    }
  }

  /** Adds the panel's choices to `settings` (its numbers are already there, from numbers.js). */
  settings(settings) {
    settings.tab_holes = this.ui.tabHoles.checked;
    // Off: outlines that cross themselves are left uncut, as drawn (the CLI's --no-repair).
    settings.repair_self_crossing = this.ui.repair ? this.ui.repair.checked : true;
    settings.controller_comp = this.ui.controllerComp.checked;
    settings.verify = this.ui.verify.checked;
    // Arc fitting and G91 (issue 43 §5): the CLI's --fit-arcs and --incremental.
    if (this.ui.fitArcs) settings.fit_arcs = this.ui.fitArcs.checked;
    if (this.ui.incremental) settings.incremental = this.ui.incremental.checked;
    // A count: 2.4 tabs are 2 (the field steps by one; a typed fraction is rounded, not refused).
    if (Number.isFinite(settings.tabs)) settings.tabs = Math.round(settings.tabs);
    return settings;
  }

  /** The report's verification, when the cut was checked (numbers only: nothing from the file). */
  show(report) {
    this.report = report;
    if (!report) this.setHeat(null, null);
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
