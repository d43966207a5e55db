// kerfcam inspect and measure (issue 6 §6). Hovering the preview names the contour under the pointer
// (layer, entity types, length, area, drawn and cut direction, part, cut number); a click pins it in
// the readout for keyboard and screen-reader users. The measure tool (paper 001's "distance and
// angle") takes two clicks, each snapped by the engine to the nearest segment end, arc centre or
// POINT, and gives the distance, ΔX, ΔY and the angle from +X. Names from the file are textContent.

import { fmtNumber, onLangChange, register, t } from './i18n.js';
import { KIND, STRIDE, drawAimCross, pointOn } from './plan.js';

register({
  en: {
    'inspect.kind.outer': 'outer contour', 'inspect.kind.hole': 'hole', 'inspect.kind.open': 'open contour',
    'inspect.layer': 'layer {layer}',
    'inspect.length': 'length {length} mm', 'inspect.area': 'area {area} mm²',
    'inspect.drawn': 'drawn {dir}', 'inspect.cut': 'cut {dir}',
    'inspect.dir.cw': 'clockwise', 'inspect.dir.ccw': 'counter-clockwise',
    'inspect.part': 'part {part}', 'inspect.sequence': 'cut no. {n}', 'inspect.not-cut': 'not cut',
    'inspect.segments': { one: '{n} segment', other: '{n} segments' },
    'inspect.nothing': 'Nothing here.',
    'measure.button': 'Measure', 'measure.title': 'Measure distance and angle (M)',
    'view.hint': 'Drag to pan, wheel to zoom, click a contour to inspect it. Keys: F fit, + and − zoom, Space play, M measure, Esc stop; on the focused preview, arrow keys pan and Enter inspects or measures at the cross.',
    'measure.first': 'Measure: click the first point (it snaps to ends and centres).',
    'measure.second': 'Measure: from {x}, {y}: click the second point.',
    'measure.result': 'Distance {d} mm · ΔX {dx} · ΔY {dy} · angle {a}° (from {x0}, {y0} to {x1}, {y1})',
  },
  'pt-BR': {
    'inspect.kind.outer': 'contorno externo', 'inspect.kind.hole': 'furo', 'inspect.kind.open': 'contorno aberto',
    'inspect.layer': 'camada {layer}',
    'inspect.length': 'comprimento {length} mm', 'inspect.area': 'área {area} mm²',
    'inspect.drawn': 'desenhado no sentido {dir}', 'inspect.cut': 'cortado no sentido {dir}',
    'inspect.dir.cw': 'horário', 'inspect.dir.ccw': 'anti-horário',
    'inspect.part': 'peça {part}', 'inspect.sequence': 'corte nº {n}', 'inspect.not-cut': 'não cortado',
    'inspect.segments': { one: '{n} segmento', other: '{n} segmentos' },
    'inspect.nothing': 'Nada aqui.',
    'measure.button': 'Medir', 'measure.title': 'Medir distância e ângulo (M)',
    'view.hint': 'Arraste para mover, roda do mouse para zoom, clique num contorno para inspecioná-lo. Teclas: F ajustar, + e − zoom, Espaço reproduzir, M medir, Esc sair; na visualização focada, as setas movem e Enter inspeciona ou mede na cruz.',
    'measure.first': 'Medir: clique no primeiro ponto (ele se prende a pontas e centros).',
    'measure.second': 'Medir: a partir de {x}, {y}: clique no segundo ponto.',
    'measure.result': 'Distância {d} mm · ΔX {dx} · ΔY {dy} · ângulo {a}° (de {x0}, {y0} a {x1}, {y1})',
  },
});

const SNAP_PX = 10; // how near (CSS pixels) a drawn point must be to catch a measuring click

/** The inspector's text for one contour (ContourInfo from the engine). */
export function describe(info) {
  if (!info) return t('inspect.nothing');
  const types = (info.entity_types || []).map(([type, n]) => (n > 1 ? `${type} ×${n}` : type)).join(', ');
  const parts = [
    t(`inspect.kind.${info.kind}`),
    t('inspect.layer', { layer: info.layer === '' ? '""' : info.layer }),
    `${types} (${t('inspect.segments', { n: fmtNumber(info.segments), count: info.segments })})`,
    t('inspect.length', { length: fmtNumber(info.length, 2) }),
  ];
  if (info.kind !== 'open') parts.push(t('inspect.area', { area: fmtNumber(info.area, 1) }));
  if (info.drawn === 'cw' || info.drawn === 'ccw') parts.push(t('inspect.drawn', { dir: t(`inspect.dir.${info.drawn}`) }));
  if (info.cut) parts.push(t('inspect.cut', { dir: t(`inspect.dir.${info.cut}`) }));
  if (info.part) parts.push(t('inspect.part', { part: info.part }));
  parts.push(info.sequence ? t('inspect.sequence', { n: info.sequence }) : t('inspect.not-cut'));
  return parts.join(' · ');
}

/** Distance, ΔX, ΔY and the angle from +X (degrees, counter-clockwise, -180..180] between two points. */
export function measure([x0, y0], [x1, y1]) {
  const dx = x1 - x0;
  const dy = y1 - y0;
  return { d: Math.hypot(dx, dy), dx, dy, angle: (Math.atan2(dy, dx) * 180) / Math.PI };
}

export const HIGHLIGHT = '#f2a900'; // the focus ring's amber: no line of the plan has it
const KERF_ROOM = 3; // mm: a contour's torch path runs up to half a kerf outside its box

/**
 * The inspected contour on the overlay: its box, and the torch path of its cut (the moves of cut no.
 * `info.sequence` that run within the box: a chain's links to other contours are left out), drawn
 * wide in amber over the plan.
 */
function highlight(ctx, px, dpr, info, moves) {
  const [x0, y0, x1, y1] = info.bbox;
  ctx.save();
  ctx.setLineDash([]);
  ctx.lineCap = 'round';
  ctx.lineJoin = 'round';
  ctx.strokeStyle = HIGHLIGHT;
  ctx.globalAlpha = 0.85;
  ctx.lineWidth = 5 * dpr;
  const inside = (x, y) => x >= x0 - KERF_ROOM && x <= x1 + KERF_ROOM && y >= y0 - KERF_ROOM && y <= y1 + KERF_ROOM;
  let cut = 0;
  ctx.beginPath();
  for (let i = 0; moves && info.sequence && i < moves.length; i += STRIDE) {
    const kind = moves[i];
    if (kind === KIND.pierce || kind === KIND.spot) cut++;
    if (cut > info.sequence) break;
    if (cut !== info.sequence || (kind !== KIND.contour && kind !== KIND.repeat)) continue;
    if (!inside(moves[i + 1], moves[i + 2]) || !inside(moves[i + 3], moves[i + 4])) continue;
    const [sx, sy] = px(moves[i + 1], moves[i + 2]);
    ctx.moveTo(sx, sy);
    const steps = Math.abs(moves[i + 5]) < 1e-12 ? 1 : 24;
    for (let s = 1; s <= steps; s++) ctx.lineTo(...px(...pointOn(moves, i, s / steps)));
  }
  ctx.stroke();
  // The box, dashed, so a contour that is not cut (or too small to see) is found too.
  const [ax, ay] = px(x0, y1);
  const [bx, by] = px(x1, y0);
  ctx.lineWidth = 1.5 * dpr;
  ctx.setLineDash([5 * dpr, 3 * dpr]);
  ctx.strokeRect(ax - 4 * dpr, ay - 4 * dpr, bx - ax + 8 * dpr, by - ay + 8 * dpr);
  ctx.restore();
}

export class Inspector {
  /**
   * `ui`: { canvas, tip (hover box), readout (aria-live text), measureButton }; `engine` answers
   * 'inspect' and 'snap'; `pointAt(px, py)` and `scale()` map CSS pixels to mm; `planLayer` draws marks;
   * `active()` says whether a job is shown and no other tool (start point) has the pointer.
   */
  constructor(ui, { engine, pointAt, scale, planLayer, active }) {
    Object.assign(this, { ui, engine, pointAt, scale, planLayer, active });
    this.measuring = false;
    this.points = []; // the measure's clicked points, mm
    this.last = null; // the pinned or measured text, re-rendered on a language change
    this.hoverSeq = 0;
    planLayer.decorations.push((ctx, px, dpr) => this.decorate(ctx, px, dpr));
    ui.measureButton.addEventListener('click', () => this.setMeasuring(!this.measuring));
    ui.canvas.addEventListener('pointermove', (e) => this.hover(e));
    ui.canvas.addEventListener('pointerleave', () => (ui.tip.hidden = true));
    // A language switch writes the pinned or measured text again in the new language (it stayed in
    // the old one), and hides a hover box written in the old one.
    onLangChange(() => {
      this.setReadout(this.last);
      ui.tip.hidden = true;
    });
  }

  reset() {
    this.points = [];
    this.pinned = null;
    this.ui.tip.hidden = true;
    this.setReadout(null);
    if (this.measuring) this.setMeasuring(false);
  }

  setReadout(render) {
    this.last = render;
    this.ui.readout.textContent = render ? render() : '';
  }

  setMeasuring(on) {
    this.measuring = on;
    this.points = [];
    this.ui.measureButton.setAttribute('aria-pressed', String(on));
    this.ui.canvas.parentElement.classList.toggle('picking', on);
    this.setReadout(on ? () => t('measure.first') : null);
    this.planLayer.draw();
  }

  local(e) {
    const rect = this.ui.canvas.getBoundingClientRect();
    return [e.clientX - rect.left, e.clientY - rect.top];
  }

  /** Hover: what is under the pointer, at most one question to the engine in flight. */
  async hover(e) {
    if (!this.active() || e.buttons || this.busy) return;
    const [px, py] = this.local(e);
    const [x, y] = this.pointAt(px, py);
    this.busy = true;
    try {
      const info = JSON.parse(await this.engine.call('inspect', { x, y, reach: 6 / this.scale() }));
      const tip = this.ui.tip;
      tip.hidden = !info;
      if (info) {
        tip.textContent = describe(info);
        tip.style.left = `${Math.round(px + 14)}px`;
        tip.style.top = `${Math.round(py + 14)}px`;
      }
    } catch {
      this.ui.tip.hidden = true; // a cancelled or replaced job: nothing to say
    } finally {
      this.busy = false;
    }
  }

  /** A click on the preview (not a drag): a measuring point, or pin what is there. Returns true when used. */
  async click(e) {
    return this.at(...this.local(e));
  }

  /**
   * Enter on the focused preview: the same as a click at its centre, where a cross is drawn while
   * the preview has the keyboard focus (arrow keys move the drawing under it).
   */
  async atCentre() {
    const { width, height } = this.ui.canvas.getBoundingClientRect();
    return this.at(width / 2, height / 2);
  }

  async at(px, py) {
    if (!this.active()) return false;
    const [x, y] = this.pointAt(px, py);
    if (this.measuring) {
      const p = await this.engine.call('snap', { x, y, reach: SNAP_PX / this.scale() });
      this.addPoint([p[0], p[1]]);
      return true;
    }
    const info = JSON.parse(await this.engine.call('inspect', { x, y, reach: 6 / this.scale() }));
    this.setReadout(info ? () => describe(info) : null);
    this.pinned = info; // highlighted on the preview (decorate)
    this.planLayer.draw();
    return !!info;
  }

  /** A measuring point (mm): the first starts a measure, the second ends it. */
  addPoint(p) {
    if (this.points.length >= 2) this.points = [];
    this.points.push(p);
    const f = (v) => fmtNumber(v, 3);
    if (this.points.length === 1) {
      this.setReadout(() => t('measure.second', { x: f(p[0]), y: f(p[1]) }));
    } else {
      const [a, b] = this.points;
      const m = measure(a, b);
      this.result = m;
      this.setReadout(() => t('measure.result', {
        d: f(m.d), dx: f(m.dx), dy: f(m.dy), a: fmtNumber(m.angle, 2), x0: f(a[0]), y0: f(a[1]), x1: f(b[0]), y1: f(b[1]),
      }));
    }
    this.planLayer.draw();
  }

  decorate(ctx, px, dpr) {
    if (this.pinned && this.active()) highlight(ctx, px, dpr, this.pinned, this.planLayer.moves);
    if (document.activeElement === this.ui.canvas && this.active()) {
      // The keyboard's aim: Enter inspects or measures here.
      drawAimCross(ctx, dpr, '#6a1b9a', 8);
    }
    if (!this.measuring || !this.points.length) return;
    const pts = this.points.map(([x, y]) => px(x, y));
    ctx.save();
    ctx.strokeStyle = '#6a1b9a';
    ctx.fillStyle = '#6a1b9a';
    ctx.lineWidth = 2 * dpr;
    ctx.setLineDash([]);
    ctx.beginPath();
    pts.forEach(([x, y], i) => (i ? ctx.lineTo(x, y) : ctx.moveTo(x, y)));
    ctx.stroke();
    for (const [x, y] of pts) {
      ctx.beginPath();
      ctx.arc(x, y, 4 * dpr, 0, 2 * Math.PI);
      ctx.fill();
    }
    ctx.restore();
  }
}
