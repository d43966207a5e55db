// kerfcam page: what the program takes from the parts, shown before the download (issue 45 §3).
// The engine names the loss: the warnings that say one carry `loss` ("cuts-into": the kerf takes part
// material; "not-cut": drawn loops left uncut) and the loops they are about by identity ({part, copy,
// contour}); the worker sends those loops' outlines (Job.loss_outlines) and where a cut comes within
// half the kerf of another part (Job.closeness_heat, squares as the verification's heat map). Nothing
// is recomputed here: the marks are the engine's numbers, drawn over the preview.
// The Download button says what the program cuts into ("Download G-code (cuts into 3 parts)") until the
// operator has seen it: seen = a "show" button of a loss warning was clicked (the preview then shows
// the marked parts). A new plan whose loss is another (other codes or loops, or another file) asks
// again; a loss seen once this session (the same file re-planned with another feed, or shown again)
// stays seen. Downloading is never blocked.

import { fmtNumber, onLangChange, register, t } from './i18n.js';
import { pointOn } from './plan.js';
import { drawSquares } from './process.js';

register({
  en: {
    'gcode.download-with': 'Download G-code ({what})',
    'losses.cuts': { one: 'cuts into {n} part', other: 'cuts into {n} parts' },
    'losses.uncut': { one: '{n} contour not cut', other: '{n} contours not cut' },
    'losses.some': 'parts lose material',
    'gcode.download-title': 'The program takes material from parts or leaves contours uncut: see the first warning and the parts marked on the preview',
    'losses.show': { one: 'show the part', other: 'show the {n} parts' },
    'losses.show-label': 'Show on the preview the parts this warning is about: {message}',
    'losses.tag': 'material loss',
    'legend.loss': 'Part losing material',
    'legend.loss.title': 'Outline of a part the cuts take material from or do not cut free (marked on every run); squares: where a cut comes within half the kerf',
  },
  'pt-BR': {
    'gcode.download-with': 'Baixar o G-code ({what})',
    'losses.cuts': { one: 'invade {n} peça', other: 'invade {n} peças' },
    'losses.uncut': { one: '{n} contorno não cortado', other: '{n} contornos não cortados' },
    'losses.some': 'peças perdem material',
    'gcode.download-title': 'O programa remove material de peças ou deixa contornos sem corte: veja o primeiro aviso e as peças marcadas na visualização',
    'losses.show': { one: 'mostrar a peça', other: 'mostrar as {n} peças' },
    'losses.show-label': 'Mostrar na visualização as peças deste aviso: {message}',
    'losses.tag': 'perda de material',
    'legend.loss': 'Peça que perde material',
    'legend.loss.title': 'Contorno de uma peça da qual os cortes removem material ou que não é solta (marcado em toda execução); quadrados: onde um corte chega a menos de meia sangria',
  },
});

// The marks' colours: the outline a strong red under a light halo (the torch path is a thinner red
// dash: the halo tells them apart), the squares the heat map's magenta (style.css .swatch.loss).
const HALO = 'rgba(255, 70, 70, 0.3)';
const LINE = '#e00000';
export const LOSS_SQUARES = [255, 0, 110];

const refKey = (r) => `${r.part}/${r.copy}/${r.contour}`;

/** The report's warnings that say a loss, with their loops. */
export const lossWarnings = (report) => (report?.warnings || []).filter((w) => w.loss === 'cuts-into' || w.loss === 'not-cut');

/**
 * What the program does to the parts: `cuts` parts (part and copy) the kerf takes from, `uncut` loops
 * left uncut, `any` a loss said at all, `key` what identifies it (codes and loops).
 */
export function lossOf(report) {
  const ws = lossWarnings(report);
  const cuts = new Set();
  const uncut = new Set();
  for (const w of ws) {
    for (const r of w.loops || []) {
      if (w.loss === 'cuts-into') cuts.add(`${r.part}/${r.copy}`);
      else uncut.add(refKey(r));
    }
  }
  const key = ws.map((w) => `${w.code}:${(w.loops || []).map(refKey).join(',')}`).sort().join(';');
  return { any: ws.length > 0, cuts: cuts.size, uncut: uncut.size, key };
}

/** What `loss` (lossOf) takes, in words ("cuts into 3 parts, 1 contour not cut"); '' when nothing is lost. */
export function lossWords(loss) {
  if (!loss?.any) return '';
  const { cuts, uncut } = loss;
  const what = [
    ...(cuts ? [t('losses.cuts', { n: fmtNumber(cuts), count: cuts })] : []),
    ...(uncut ? [t('losses.uncut', { n: fmtNumber(uncut), count: uncut })] : []),
  ];
  return what.length ? what.join(', ') : t('losses.some');
}

/** The Download button's words for `loss` (lossOf), or the plain words when nothing is lost. */
export function downloadLabel(loss) {
  return loss?.any ? t('gcode.download-with', { what: lossWords(loss) }) : t('gcode.download');
}

export class Losses {
  /** `ui`: { download (button), legend (li) }; `redraw()` draws the overlay again; `showBox(box)` fits the preview to it. */
  constructor(ui, { redraw, showBox }) {
    Object.assign(this, { ui, redraw, showBox });
    this.loss = null; // lossOf the shown report
    this.name = '';
    this.seenKeys = new Set(); // the losses (file and key) the operator has seen, this session
    this.marks = null; // { outlines: Float64Array [x0, y0, x1, y1, bulge, …], squares: [side, x, y, depth, …] }
    onLangChange(() => this.showLabel());
  }

  /** The shown job: its report, its marks (worker: Job.loss_outlines, Job.closeness_heat), its file's name. */
  set(report, marks, name) {
    this.loss = report ? lossOf(report) : null;
    this.name = name || '';
    const outlines = marks?.outlines?.length ? marks.outlines : null;
    const squares = marks?.squares?.length ? marks.squares : null;
    this.marks = outlines || squares ? { outlines: outlines || [], squares: squares || [] } : null;
    if (this.ui.legend) this.ui.legend.hidden = !this.marks;
    this.showLabel();
  }

  /** True while the loss of the shown plan has not been seen. */
  unseen() {
    return !!this.loss?.any && !this.seenKeys.has(this.fullKey());
  }

  fullKey() {
    return `${this.name}\n${this.loss?.key ?? ''}`;
  }

  /** The operator looked at the marked parts: the Download button says only "Download G-code". */
  seen() {
    if (!this.loss?.any) return;
    this.seenKeys.add(this.fullKey());
    this.showLabel();
  }

  showLabel() {
    const b = this.ui.download;
    if (!b) return;
    const warn = this.unseen();
    // Its words follow the language switch here, not through data-i18n (which would put the plain words back).
    if (warn) delete b.dataset.i18n;
    else b.dataset.i18n = 'gcode.download';
    b.textContent = warn ? downloadLabel(this.loss) : t('gcode.download');
    b.dataset.loss = warn ? 'unseen' : (this.loss?.any ? 'seen' : 'none');
    if (warn) b.title = t('gcode.download-title');
    else b.removeAttribute('title');
  }

  /** The box of the marked outlines and squares, [x0, y0, x1, y1] mm, or null. */
  box() {
    if (!this.marks) return null;
    let [x0, y0, x1, y1] = [Infinity, Infinity, -Infinity, -Infinity];
    const add = (x, y) => { x0 = Math.min(x0, x); y0 = Math.min(y0, y); x1 = Math.max(x1, x); y1 = Math.max(y1, y); };
    const o = this.marks.outlines;
    for (let i = 0; i < o.length; i += 5) { add(o[i], o[i + 1]); add(o[i + 2], o[i + 3]); }
    const q = this.marks.squares;
    for (let i = 1; i < q.length; i += 3) add(q[i], q[i + 1]);
    return Number.isFinite(x0) ? [x0, y0, x1, y1] : null;
  }

  /** The "show" button of a loss warning (summary.js): fits the preview to the marked parts; the loss is then seen. */
  showButton(w, message) {
    const n = new Set((w.loops || []).map((r) => `${r.part}/${r.copy}`)).size;
    const b = document.createElement('button');
    b.type = 'button';
    b.className = 'small-button show-loss';
    b.textContent = t('losses.show', { n: fmtNumber(n), count: n });
    b.setAttribute('aria-label', t('losses.show-label', { message }));
    b.addEventListener('click', () => {
      const box = this.box();
      if (box) this.showBox(box);
      this.seen();
      this.redraw();
    });
    return b;
  }

  /** Overlay decoration (PlanLayer.decorations): the marked outlines, then where the cuts come close. */
  decorate(ctx, px, dpr) {
    if (!this.marks) return;
    const o = this.marks.outlines;
    if (o.length) {
      ctx.save();
      ctx.setLineDash([]);
      ctx.lineCap = 'round';
      ctx.lineJoin = 'round';
      const path = new Path2D();
      for (let i = 0; i < o.length; i += 5) {
        const [sx, sy] = px(o[i], o[i + 1]);
        path.moveTo(sx, sy);
        const bulge = o[i + 4];
        const steps = Math.abs(bulge) < 1e-12 ? 1 : 24;
        for (let s = 1; s <= steps; s++) {
          // A move of Job.moves() is [kind, x0, y0, x1, y1, bulge, …]: the outline's segment read as one.
          const [x, y] = pointOn(o, i - 1, s / steps);
          const [qx, qy] = px(x, y);
          path.lineTo(qx, qy);
        }
      }
      ctx.strokeStyle = HALO;
      ctx.lineWidth = 8 * dpr;
      ctx.stroke(path);
      ctx.strokeStyle = LINE;
      ctx.lineWidth = 2 * dpr;
      ctx.stroke(path);
      ctx.restore();
    }
    if (this.marks.squares.length) drawSquares(ctx, px, dpr, this.marks.squares, LOSS_SQUARES);
  }
}
