// kerfcam program origin and scale in view (issue 13 §2). The settings choose where the program's
// (0,0) is: automatic (the engine picks the drawing's zero, or the lower-left of the parts when the
// zero is far away, and says so), the drawing's own zero, the lower-left corner of the parts, or a
// point picked on the preview (kept with its file). The preview is in program coordinates, so the
// origin mark is drawn at the scene's (0,0); a scale bar in the corner gives the drawing's size.

import { fmtNumber, register, t } from './i18n.js';
import { drawAimCross } from './plan.js';
import { rebaseChoices } from './choices.js';

register({
  en: {
    'settings.origin': 'Program origin',
    'origin.mode.auto': 'automatic', 'origin.mode.drawing': 'drawing zero', 'origin.mode.lower-left': 'lower-left of the parts',
    'origin.mode.point': 'a point I pick',
    'origin.pick': 'Pick the origin on the preview',
    'origin.pick-hint': 'Click the preview where the program\'s zero should be (it snaps to ends and centres).',
    'origin.need-pick': 'No origin picked for this file yet: the automatic one is used.',
    'origin.picked': 'This file\'s origin: drawing point {x}, {y}.',
    'origin.text.drawing': 'the drawing\'s zero', 'origin.text.lower-left': 'lower-left corner of the parts',
    'origin.text.point': 'a picked point',
    'origin.text.auto': '{mode} (automatic)',
    'origin.text.at': '{mode}: drawing point {x}, {y}',
    'origin.mark': 'X0 Y0',
  },
  'pt-BR': {
    'settings.origin': 'Origem do programa',
    'origin.mode.auto': 'automática', 'origin.mode.drawing': 'zero do desenho', 'origin.mode.lower-left': 'canto inferior esquerdo das peças',
    'origin.mode.point': 'um ponto que eu escolher',
    'origin.pick': 'Escolher a origem na visualização',
    'origin.pick-hint': 'Clique na visualização onde deve ficar o zero do programa (ele se prende a pontas e centros).',
    'origin.need-pick': 'Ainda não há origem escolhida para este arquivo: usa-se a automática.',
    'origin.picked': 'Origem deste arquivo: ponto do desenho {x}; {y}.',
    'origin.text.drawing': 'zero do desenho', 'origin.text.lower-left': 'canto inferior esquerdo das peças',
    'origin.text.point': 'um ponto escolhido',
    'origin.text.auto': '{mode} (automática)',
    'origin.text.at': '{mode}: ponto do desenho {x}; {y}',
    'origin.mark': 'X0 Y0',
  },
});

const MODES = ['auto', 'drawing', 'lower-left', 'point'];
const SNAP_PX = 10;

/** The report's origin in words: "lower-left corner of the parts (automatic): drawing point 120, 45". */
export function originText(o) {
  if (!o || !MODES.includes(o.mode) || o.mode === 'auto') return null;
  let mode = t(`origin.text.${o.mode}`);
  if (o.auto) mode = t('origin.text.auto', { mode });
  const [x, y] = Array.isArray(o.at) ? o.at : [NaN, NaN];
  return Number.isFinite(x) && Number.isFinite(y) ? t('origin.text.at', { mode, x: fmtNumber(x, 2), y: fmtNumber(y, 2) }) : mode;
}

export class Origin {
  /**
   * `ui`: { select, pick (button), hint, row (the pick button's paragraph) }; `current()` is the shown
   * job (its `originPoint`, drawing mm); `report()` the shown report; `snap(x, y, reach)` the engine's
   * snap; `scale()` CSS px per mm; `onPicked(job)` keeps the job's choice and re-runs.
   */
  constructor(ui, { current, report, snap, scale, onPicked, onPicking }) {
    Object.assign(this, { ui, current, report, snap, scale, onPicked, onPicking });
    this.picking = false;
    ui.select.addEventListener('change', () => {
      if (ui.select.value !== 'point') this.setPicking(false);
      else if (!this.current()?.originPoint) this.setPicking(true);
      this.update();
    });
    ui.pick.addEventListener('click', () => this.setPicking(!this.picking));
    this.update();
  }

  /** The engine settings for `job`: { origin, origin_point }. "point" without a picked point: automatic. */
  settingsFor(job) {
    const mode = MODES.includes(this.ui.select.value) ? this.ui.select.value : 'auto';
    if (mode !== 'point') return { origin: mode };
    const p = job?.originPoint;
    return Array.isArray(p) ? { origin: 'point', origin_point: [p[0], p[1]] } : { origin: 'auto' };
  }

  /** Shows the pick button with "point", and says when this file has no point yet. */
  update() {
    const point = this.ui.select.value === 'point';
    this.ui.row.hidden = !point;
    const job = this.current();
    const p = job?.originPoint;
    this.ui.hint.textContent = this.picking ? t('origin.pick-hint')
      : !point || !job ? ''
        : p ? t('origin.picked', { x: fmtNumber(p[0], 2), y: fmtNumber(p[1], 2) }) : t('origin.need-pick');
  }

  setPicking(on) {
    this.picking = on && !!this.current();
    this.ui.pick.setAttribute('aria-pressed', String(this.picking));
    this.onPicking?.(this.picking);
    this.update();
  }

  /**
   * A click on the preview at program point (x, y) while picking: snapped, then turned into the
   * drawing's own coordinates (the program's (0,0) is the drawing point report.origin.at).
   */
  async pick(x, y) {
    const job = this.current();
    if (!job) return;
    const [sx, sy] = await this.snap(x, y, SNAP_PX / this.scale());
    const at = this.report()?.origin?.at;
    const [ox, oy] = Array.isArray(at) ? at : [0, 0];
    job.originPoint = [round(sx + ox), round(sy + oy)];
    this.setPicking(false);
    this.onPicked(job);
  }

  /** Overlay decoration (PlanLayer.decorations): the origin mark at (0,0) and the scale bar. */
  decorate(ctx, px, dpr) {
    drawOrigin(ctx, px, dpr);
    drawScaleBar(ctx, px, dpr);
    if (this.picking && document.activeElement?.id === 'preview') drawAimCross(ctx, dpr, '#0a6b2a', 10); // Enter picks here
  }
}

/** The frame of a report's program coordinates: { at (drawing point at zero, mm), units }. */
export const frameOf = (report) => (report?.origin ? { at: report.origin.at, units: report.units } : null);

/** Start points or tabs in the frame `to` (see choices.js `rebaseChoices`). */
export const rebaseStarts = rebaseChoices;

/** Micrometres: the engine's own rounding of coordinates in the report. */
const round = (v) => Math.round(v * 1000) / 1000;

function drawOrigin(ctx, px, dpr) {
  const [x, y] = px(0, 0);
  const { width, height } = ctx.canvas;
  if (!Number.isFinite(x) || !Number.isFinite(y)) return;
  if (x < 0 || y < 0 || x > width || y > height) return drawOriginArrow(ctx, x, y, dpr);
  const r = 7 * dpr;
  ctx.save();
  ctx.setLineDash([]);
  for (const [colour, w] of [['rgba(255,255,255,0.95)', 4], ['#0a6b2a', 1.8]]) {
    ctx.strokeStyle = colour;
    ctx.lineWidth = w * dpr;
    ctx.beginPath();
    ctx.arc(x, y, r, 0, 2 * Math.PI);
    ctx.moveTo(x - 2 * r, y);
    ctx.lineTo(x + 2 * r, y);
    ctx.moveTo(x, y - 2 * r);
    ctx.lineTo(x, y + 2 * r);
    ctx.stroke();
  }
  // Quadrants filled like a machinist's origin symbol.
  ctx.fillStyle = '#0a6b2a';
  ctx.beginPath();
  ctx.moveTo(x, y);
  ctx.arc(x, y, r, -Math.PI / 2, 0);
  ctx.closePath();
  ctx.moveTo(x, y);
  ctx.arc(x, y, r, Math.PI / 2, Math.PI);
  ctx.closePath();
  ctx.fill();
  label(ctx, t('origin.mark'), x + 2.2 * r, y + 2.2 * r, dpr, 'left', 'top');
  ctx.restore();
}


/** The origin out of sight: an arrow at the edge of the preview pointing to where it is. */
function drawOriginArrow(ctx, x, y, dpr) {
  const { width, height } = ctx.canvas;
  const m = 18 * dpr;
  const cx = width / 2;
  const cy = height / 2;
  // Where the line from the centre to the origin leaves the preview (inset by m).
  const f = Math.min(Math.abs((width / 2 - m) / (x - cx || 1e-9)), Math.abs((height / 2 - m) / (y - cy || 1e-9)), 1);
  const ax = cx + (x - cx) * f;
  const ay = cy + (y - cy) * f;
  const a = Math.atan2(y - cy, x - cx);
  ctx.save();
  ctx.translate(ax, ay);
  ctx.rotate(a);
  ctx.beginPath();
  ctx.moveTo(10 * dpr, 0);
  ctx.lineTo(-6 * dpr, -7 * dpr);
  ctx.lineTo(-6 * dpr, 7 * dpr);
  ctx.closePath();
  ctx.lineWidth = 3 * dpr;
  ctx.strokeStyle = 'rgba(255,255,255,0.95)';
  ctx.stroke();
  ctx.fillStyle = '#0a6b2a';
  ctx.fill();
  ctx.restore();
  const right = ax > cx;
  const below = ay > cy;
  label(ctx, t('origin.mark'), ax + (right ? -14 : 14) * dpr, ay + (below ? -12 : 12) * dpr, dpr, right ? 'right' : 'left', below ? 'bottom' : 'top');
}

/** The largest 1, 2 or 5 × 10^k mm that is at most `mm`. */
export function niceLength(mm) {
  const p = 10 ** Math.floor(Math.log10(mm));
  return [5, 2, 1].map((m) => m * p).find((v) => v <= mm) ?? p;
}

function drawScaleBar(ctx, px, dpr) {
  const k = px(1, 0)[0] - px(0, 0)[0]; // device pixels per mm
  if (!(k > 0) || !Number.isFinite(k)) return;
  const L = niceLength((120 * dpr) / k);
  const len = L * k;
  const x0 = 12 * dpr;
  const y0 = ctx.canvas.height - 14 * dpr;
  ctx.save();
  ctx.setLineDash([]);
  for (const [colour, w] of [['rgba(255,255,255,0.95)', 5], ['#1d2329', 2]]) {
    ctx.strokeStyle = colour;
    ctx.lineWidth = w * dpr;
    ctx.beginPath();
    ctx.moveTo(x0, y0 - 6 * dpr);
    ctx.lineTo(x0, y0);
    ctx.lineTo(x0 + len, y0);
    ctx.lineTo(x0 + len, y0 - 6 * dpr);
    ctx.moveTo(x0 + len / 2, y0);
    ctx.lineTo(x0 + len / 2, y0 - 3 * dpr);
    ctx.stroke();
  }
  if (globalThis.kerfcam) globalThis.kerfcam.scaleBar = { mm: L, px: len / dpr }; // for tests and the curious
  const digits = L >= 1 ? 0 : Math.ceil(-Math.log10(L) - 1e-9);
  label(ctx, `${fmtNumber(L, digits)} mm`, x0 + len / 2, y0 - 7 * dpr, dpr, 'center', 'bottom');
  ctx.restore();
}

function label(ctx, text, x, y, dpr, align, baseline) {
  ctx.font = `${12 * dpr}px system-ui, sans-serif`;
  ctx.textAlign = align;
  ctx.textBaseline = baseline;
  ctx.lineWidth = 3 * dpr;
  ctx.strokeStyle = 'rgba(255,255,255,0.95)';
  ctx.strokeText(text, x, y);
  ctx.fillStyle = '#1d2329';
  ctx.fillText(text, x, y);
}
