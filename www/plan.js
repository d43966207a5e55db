// kerfcam page: the cut plan on top of the preview — sequence numbers, the animation (play, pause, speed,
// scrubber, tool position and elapsed estimated time) and the side-by-side comparison of orders.
// The animation plays the wasm Job's own moves (Job.moves()), the very list the G-code is written from.

import { fmtNumber, register, t } from './i18n.js';

register({
  en: {
    'anim.play': 'Play', 'anim.pause': 'Pause',
    'compare.order': 'Order', 'compare.cut': 'Cut', 'compare.repeat': 'Repeated', 'compare.lead': 'Leads + links',
    'compare.rapid': 'Rapids', 'compare.pierces': 'Pierces', 'compare.time': 'Est. time', 'compare.travel': 'Travel vs contour',
    'compare.parts': 'Cuts into parts', 'compare.parts.none': 'no',
    'compare.parts.yes': 'yes: {length} mm, up to {depth} mm deep', 'compare.best': 'best',
    'plan.labels-thinned': '{drawn} of {total} sequence numbers shown: zoom in for the rest',
  },
  'pt-BR': {
    'anim.play': 'Reproduzir', 'anim.pause': 'Pausar',
    'compare.order': 'Ordem', 'compare.cut': 'Corte', 'compare.repeat': 'Repetido', 'compare.lead': 'Entradas + ligações',
    'compare.rapid': 'Deslocamentos rápidos', 'compare.pierces': 'Perfurações', 'compare.time': 'Tempo est.',
    'compare.travel': 'Percurso vs contorno',
    'compare.parts': 'Corta as peças', 'compare.parts.none': 'não',
    'compare.parts.yes': 'sim: {length} mm, até {depth} mm de profundidade', 'compare.best': 'melhor',
    'plan.labels-thinned': '{drawn} de {total} números de sequência mostrados: aproxime para ver os outros',
  },
});

// Kinds of move in Job.moves() (src/animation.rs, mod kind); 8: a feed move with the torch off (only in programs re-read by the
// backplot); 9: a mark (scribe) on the drawn line (issue 20); 10: over a tab, the torch off (issue 20 §6);
// a router's (issue 43): 11 a Z move in place (up, or down into the material), 12 a milling cut at one
// depth, 13 a ramp or helix (Z going down along the path).
export const KIND = {
  rapid: 0, leadIn: 1, contour: 2, leadOut: 3, link: 4, repeat: 5, pierce: 6, spot: 7, dryFeed: 8, mark: 9, tab: 10,
  z: 11, mill: 12, millEntry: 13,
};
export const STRIDE = 7; // [kind, x0, y0, x1, y1, bulge, t_end]
const MAX_LABELS = 1500; // more sequence numbers in sight than this are unreadable anyway
// What the animation and the backplot have drawn, in the legend's colours: cutting red like the torch
// path, leads green, links and repeats as in the plan (never the holes' orange: it read as a hole).
const DONE_COLOUR = {
  0: 'rgba(90,90,90,0.9)', 1: 'rgba(26,158,58,0.9)', 2: 'rgba(214,40,40,0.9)', 3: 'rgba(26,158,58,0.9)',
  4: 'rgba(139,26,26,0.85)', 5: 'rgba(112,72,232,0.85)', 8: 'rgba(0,120,160,0.9)', 9: 'rgba(0,137,123,0.9)',
  10: 'rgba(240,140,0,0.95)', 12: 'rgba(46,26,135,0.9)', 13: 'rgba(26,158,58,0.9)',
};

/** Formats seconds as m:ss (or h:mm:ss). */
export function formatTime(s) {
  if (!Number.isFinite(s) || s < 0) return '–';
  const total = Math.round(s);
  const h = Math.floor(total / 3600);
  const m = Math.floor((total % 3600) / 60);
  const sec = String(total % 60).padStart(2, '0');
  return h ? `${h}:${String(m).padStart(2, '0')}:${sec}` : `${m}:${sec}`;
}

/** Point at fraction `f` of a move (lines and bulge arcs). */
export function pointOn(m, i, f) {
  const [x0, y0, x1, y1, bulge] = [m[i + 1], m[i + 2], m[i + 3], m[i + 4], m[i + 5]];
  if (Math.abs(bulge) < 1e-12) return [x0 + (x1 - x0) * f, y0 + (y1 - y0) * f];
  const arc = arcOf(x0, y0, x1, y1, bulge);
  const a = arc.start + arc.sweep * f;
  return [arc.cx + arc.r * Math.cos(a), arc.cy + arc.r * Math.sin(a)];
}

/** Centre, radius, start angle and signed sweep of a bulge arc (sweep = 4 atan(bulge)). */
function arcOf(x0, y0, x1, y1, bulge) {
  const sweep = 4 * Math.atan(bulge);
  const dx = x1 - x0;
  const dy = y1 - y0;
  const chord = Math.hypot(dx, dy);
  const r = chord / (2 * Math.abs(Math.sin(sweep / 2)));
  // Centre: from the chord midpoint along the left normal by (chord/2)·cot(sweep/2), signed by the sweep.
  const d = (chord / 2) / Math.tan(sweep / 2);
  const cx = (x0 + x1) / 2 - (dy / chord) * d;
  const cy = (y0 + y1) / 2 + (dx / chord) * d;
  return { cx, cy, r, start: Math.atan2(y0 - cy, x0 - cx), sweep };
}

/**
 * The keyboard's aim on the overlay: a cross of arms `arm` CSS px at the canvas's centre, where
 * Enter acts (inspect, measure, pick the origin).
 */
export function drawAimCross(ctx, dpr, colour, arm) {
  const { width, height } = ctx.canvas;
  ctx.save();
  ctx.setLineDash([]);
  ctx.strokeStyle = colour;
  ctx.lineWidth = 1.5 * dpr;
  ctx.beginPath();
  ctx.moveTo(width / 2 - arm * dpr, height / 2);
  ctx.lineTo(width / 2 + arm * dpr, height / 2);
  ctx.moveTo(width / 2, height / 2 - arm * dpr);
  ctx.lineTo(width / 2, height / 2 + arm * dpr);
  ctx.stroke();
  ctx.restore();
}

export class PlanLayer {
  /** `ui`: overlay canvas and animation controls; `viewOf()` returns { cx, cy, scale, width, height, dpr }. */
  constructor(ui, viewOf) {
    Object.assign(this, { ui, viewOf, moves: null, total: 0, t: null, playing: false, speed: 10, last: 0 });
    this.decorations = []; // (ctx, px, dpr) => void: drawn over the plan (e.g. the measure line)
    ui.play.addEventListener('click', () => this.toggle());
    ui.speed.addEventListener('change', () => (this.speed = Number(ui.speed.value) || 1));
    this.speed = Number(ui.speed.value) || 1;
    ui.scrub.addEventListener('input', () => {
      this.pause();
      this.t = (Number(ui.scrub.value) / 1000) * this.total;
      this.draw();
    });
  }

  /** A new job's moves (Job.moves(), a Float64Array, or null); the animation back at the start. */
  /** `later`: the overlay is drawn with the preview coming next, not now (a big plan's numbers cost). */
  setMoves(moves, { showAll = false, later = false } = {}) {
    this.pause();
    this.moves = moves;
    this.showAll = showAll; // a backplot: the whole program is drawn, not only what the animation reached
    const n = this.moves ? this.moves.length : 0;
    this.total = n ? this.moves[n - 1] : 0;
    this.t = null;
    for (const c of [this.ui.play, this.ui.scrub]) c.disabled = !n;
    // The whole plan is shown and the time reads total / total: the scrubber sits at the end
    // (it sat at 0 beside "1:07 / 1:07"). Play starts again from 0.
    this.ui.scrub.value = n ? '1000' : '0';
    this.showTime();
    if (!later) this.draw();
  }

  toggle() {
    if (this.playing) return this.pause();
    if (!this.moves) return;
    if (this.t === null || this.t >= this.total) this.t = 0;
    this.playing = true;
    this.ui.play.textContent = t('anim.pause');
    this.ui.play.dataset.i18n = 'anim.pause'; // a language switch keeps the button's state
    this.ui.play.setAttribute('aria-pressed', 'true');
    this.last = performance.now();
    requestAnimationFrame((now) => this.tick(now));
  }

  pause() {
    this.playing = false;
    this.ui.play.textContent = t('anim.play');
    this.ui.play.dataset.i18n = 'anim.play';
    this.ui.play.setAttribute('aria-pressed', 'false');
  }

  tick(now) {
    if (!this.playing) return;
    this.t = Math.min(this.total, this.t + ((now - this.last) / 1000) * this.speed);
    this.last = now;
    this.ui.scrub.value = String(Math.round((this.t / Math.max(this.total, 1e-9)) * 1000));
    this.draw();
    if (this.t >= this.total) return this.pause();
    requestAnimationFrame((n) => this.tick(n));
  }

  showTime() {
    const t = this.t === null ? this.total : this.t;
    this.ui.time.textContent = `${formatTime(t)} / ${formatTime(this.total)}`;
  }

  /** Redraws the overlay: sequence numbers always; while animating, what is done and the tool. */
  draw() {
    const canvas = this.ui.overlay;
    const v = this.viewOf();
    if (!v) return;
    const w = Math.max(1, Math.round(v.width * v.dpr));
    const h = Math.max(1, Math.round(v.height * v.dpr));
    if (canvas.width !== w) canvas.width = w;
    if (canvas.height !== h) canvas.height = h;
    const ctx = canvas.getContext('2d');
    ctx.setTransform(1, 0, 0, 1, 0, 0);
    ctx.clearRect(0, 0, w, h);
    this.showTime();
    const m = this.moves;
    if (!m) return;
    const k = v.scale * v.dpr;
    const px = (x, y) => [(x - v.cx) * k + w / 2, h / 2 - (y - v.cy) * k];
    if (this.t !== null || this.showAll) this.drawDone(ctx, m, px, k, v.dpr);
    this.drawLabels(ctx, m, px, v.dpr);
    // Other tools' marks (the measure line), in device pixels, on top.
    for (const decorate of this.decorations) decorate(ctx, px, v.dpr);
  }

  drawDone(ctx, m, px, k, dpr) {
    const until = this.t === null ? Infinity : this.t;
    ctx.lineCap = 'round';
    let tool = null;
    let tPrev = 0;
    for (let i = 0; i < m.length; i += STRIDE) {
      const kind = m[i];
      const tEnd = m[i + 6];
      if (tPrev >= until) break;
      const f = tEnd > tPrev ? Math.min(1, (until - tPrev) / (tEnd - tPrev)) : 1;
      tPrev = tEnd;
      if (kind === KIND.pierce || kind === KIND.spot || kind === KIND.z) {
        tool = [m[i + 1], m[i + 2]];
        continue;
      }
      const dry = kind === KIND.rapid || kind === KIND.dryFeed;
      ctx.strokeStyle = DONE_COLOUR[kind] || DONE_COLOUR[KIND.contour];
      ctx.lineWidth = (dry ? 1.5 : 4) * dpr;
      ctx.setLineDash(dry ? [4 * dpr, 4 * dpr] : []);
      ctx.beginPath();
      const [sx, sy] = px(m[i + 1], m[i + 2]);
      ctx.moveTo(sx, sy);
      const steps = Math.abs(m[i + 5]) < 1e-12 ? 1 : 24;
      for (let s = 1; s <= steps; s++) {
        const [x, y] = pointOn(m, i, (s / steps) * f);
        const [qx, qy] = px(x, y);
        ctx.lineTo(qx, qy);
      }
      ctx.stroke();
      tool = pointOn(m, i, f);
    }
    ctx.setLineDash([]);
    if (!tool) return;
    const [tx, ty] = px(tool[0], tool[1]);
    ctx.fillStyle = '#111';
    ctx.strokeStyle = '#fff';
    ctx.lineWidth = 2 * dpr;
    ctx.beginPath();
    ctx.arc(tx, ty, 6 * dpr, 0, 2 * Math.PI);
    ctx.fill();
    ctx.stroke();
  }

  /**
   * Sequence numbers beside the pierces, with level of detail (issue 19 item 2): a number is drawn
   * only where it overlaps none drawn before it, so at Fit zoom a big file shows a readable subset
   * (the first of each crowd, in cutting order) instead of a solid mass; zoomed in, all of them.
   * When some are left out, a note in the corner says how many are shown.
   */
  drawLabels(ctx, m, px, dpr) {
    let n = 0;
    ctx.font = `${11 * dpr}px system-ui, sans-serif`;
    ctx.textBaseline = 'bottom';
    ctx.lineWidth = 3 * dpr;
    ctx.strokeStyle = 'rgba(255,255,255,0.9)';
    ctx.fillStyle = '#0b3d1a';
    const { width, height } = ctx.canvas;
    const h = 12 * dpr; // a label's height, and the side of the cells that record where labels are
    // Cells as numbers (a label starts at most 40 device pixels left of or 20 above the canvas), and
    // a number's width as the sum of its digits' (measured once): a 125,000-pierce nest at Fit zoom
    // asks about every pierce in sight, and a string key and a measureText each cost the main thread
    // more than a second there (issue 17 item 4: never blocked > 50 ms).
    const key = (cx, cy) => (cx + 64) * 1_048_576 + (cy + 64);
    const digit = [...'0123456789'].map((d) => ctx.measureText(d).width);
    const widthOf = (text) => {
      let w = 0;
      for (let k = 0; k < text.length; k++) w += digit[text.charCodeAt(k) - 48];
      return w;
    };
    const taken = new Set();
    const boxes = [];
    let inSight = 0;
    for (let i = 0; i < m.length; i += STRIDE) {
      if (m[i] !== KIND.pierce && m[i] !== KIND.spot) continue;
      n++; // every pierce counts; only those in sight are labelled
      const [x, y] = px(m[i + 1], m[i + 2]);
      if (x < -40 * dpr || y < -20 * dpr || x > width + 10 * dpr || y > height + 20 * dpr) continue;
      inSight++;
      if (boxes.length >= MAX_LABELS) continue;
      const x0 = Math.floor((x + 4 * dpr) / h);
      const y0 = Math.floor((y - 3 * dpr - h) / h);
      if (taken.has(key(x0, y0))) continue; // its first cell already holds a number: no need to measure it
      const text = String(n);
      const box = [x + 4 * dpr, y - 3 * dpr - h, x + 6 * dpr + widthOf(text), y - 3 * dpr];
      const cells = [];
      for (let cx = x0; cx <= Math.floor(box[2] / h); cx++) {
        for (let cy = y0; cy <= Math.floor(box[3] / h); cy++) cells.push(key(cx, cy));
      }
      if (cells.some((c) => taken.has(c))) continue; // it would cover a number already drawn
      for (const c of cells) taken.add(c);
      boxes.push(box);
      ctx.strokeText(text, x + 5 * dpr, y - 3 * dpr);
      ctx.fillText(text, x + 5 * dpr, y - 3 * dpr);
    }
    this.labelStats = { inSight, drawn: boxes.length, boxes };
    if (boxes.length < inSight) {
      const note = t('plan.labels-thinned', { drawn: fmtNumber(boxes.length), total: fmtNumber(inSight) });
      ctx.font = `${12 * dpr}px system-ui, sans-serif`;
      ctx.textAlign = 'right';
      ctx.strokeText(note, width - 8 * dpr, height - 6 * dpr);
      ctx.fillStyle = '#1d2329';
      ctx.fillText(note, width - 8 * dpr, height - 6 * dpr);
      ctx.textAlign = 'start';
    }
  }
}

// Column key, header text key, cell text (numbers in the user's locale).
const COLUMNS = [
  ['order', 'compare.order', (r) => t(`order.${r.order}`)],
  ['cut', 'compare.cut', (r) => `${fmtNumber(r.cut_length, 0)} mm`],
  ['repeat', 'compare.repeat', (r) => `${fmtNumber(r.repeated_length, 0)} mm`],
  ['lead', 'compare.lead', (r) => `${fmtNumber(r.lead_length, 0)} mm`],
  ['rapid', 'compare.rapid', (r) => `${fmtNumber(r.rapid_length, 0)} mm`],
  ['pierces', 'compare.pierces', (r) => fmtNumber(r.pierces)],
  ['time', 'compare.time', (r) => formatTime(r.est_time_s)],
  // Issue 14: whether the order's torch-on moves cut into a part, and how much (the engine checks every move).
  ['parts', 'compare.parts', (r) => (r.cuts_into_parts
    ? t('compare.parts.yes', { length: fmtNumber(r.into_parts_length, 0), depth: fmtNumber(r.into_parts_depth, 2) })
    : t('compare.parts.none'))],
  ['travel', 'compare.travel', null],
];

/** Fills `table` with one row per order; the last column is total travel against the contour order's.
 * The fastest order that cuts into no part is marked best; one that cuts into parts never is. */
export function showComparison(table, rows) {
  const travel = (r) => r.cut_length + r.repeated_length + r.lead_length + r.rapid_length;
  const base = rows.find((r) => r.order === 'contour');
  const best = rows.filter((r) => !r.cuts_into_parts)
    .reduce((b, r) => (b && b.est_time_s <= r.est_time_s ? b : r), null);
  const head = document.createElement('tr');
  for (const [, label] of COLUMNS) head.append(Object.assign(document.createElement('th'), { textContent: t(label), scope: 'col' }));
  const body = rows.map((r) => {
    const tr = document.createElement('tr');
    tr.dataset.order = r.order;
    if (r === best) tr.dataset.best = 'true';
    if (r.cuts_into_parts) tr.dataset.cutsParts = 'true';
    for (const [key, , fmt] of COLUMNS) {
      let text = fmt ? fmt(r) : '';
      if (key === 'order' && r === best) text += ` (${t('compare.best')})`;
      if (!fmt && base) {
        const pct = (100 * (travel(r) - travel(base))) / Math.max(travel(base), 1e-9);
        text = r === base ? '—' : `${pct > 0 ? '+' : ''}${fmtNumber(pct, 1)} %`;
      }
      tr.append(Object.assign(document.createElement(key === 'order' ? 'th' : 'td'), { textContent: text }));
    }
    return tr;
  });
  table.replaceChildren(
    Object.assign(document.createElement('thead'), {}),
    Object.assign(document.createElement('tbody'), {}),
  );
  table.tHead.append(head);
  table.tBodies[0].append(...body);
}

const SVG_LOOK = {
  0: ['#7a7a7a', 0.5, '3 3'], 1: ['#1a9e3a', 0.8, ''], 2: ['#d62828', 1, ''], 3: ['#1a9e3a', 0.8, ''],
  4: ['#8b1a1a', 1, ''], 5: ['#7048e8', 1.2, '2 3'], 8: ['#0078a0', 0.5, '3 3'], 9: ['#00897b', 0.8, '1.5 2.5'],
  10: ['#f08c00', 2, ''], 12: ['#2e1a87', 1, ''], 13: ['#1a9e3a', 0.8, ''],
};

/** The program (Job.moves() or a backplot) as an SVG document in mm, Y up, one path per kind of move,
 * pierces numbered in cutting order. Numbers only: nothing from the DXF is written into it. */
export function movesToSvg(m) {
  const paths = {};
  const labels = [];
  let [x0, y0, x1, y1] = [Infinity, Infinity, -Infinity, -Infinity];
  const f = (v) => (Math.round(v * 1000) / 1000).toString();
  for (let i = 0; i < m.length; i += STRIDE) {
    const kind = m[i];
    const [ax, ay, bx, by, bulge] = [m[i + 1], m[i + 2], m[i + 3], m[i + 4], m[i + 5]];
    for (const [x, y] of [[ax, ay], [bx, by]]) {
      x0 = Math.min(x0, x); y0 = Math.min(y0, y); x1 = Math.max(x1, x); y1 = Math.max(y1, y);
    }
    if (kind === KIND.z) continue; // in place: nothing to draw in X and Y
    if (kind === KIND.pierce || kind === KIND.spot) {
      labels.push(`<circle cx="${f(ax)}" cy="${f(-ay)}" r="1" fill="#1a9e3a"/><text x="${f(ax + 1.5)}" y="${f(-ay - 1.5)}" font-size="4">${labels.length + 1}</text>`);
      continue;
    }
    let d = `M${f(ax)} ${f(-ay)}`;
    if (Math.abs(bulge) < 1e-12) d += `L${f(bx)} ${f(-by)}`;
    else {
      const { r, sweep } = arcOf(ax, ay, bx, by, bulge);
      // Y is flipped: a counter-clockwise arc in the drawing is clockwise on screen (sweep-flag 0).
      d += `A${f(r)} ${f(r)} 0 ${Math.abs(sweep) > Math.PI ? 1 : 0} ${sweep > 0 ? 0 : 1} ${f(bx)} ${f(-by)}`;
    }
    (paths[kind] ||= []).push(d);
  }
  if (!Number.isFinite(x0)) [x0, y0, x1, y1] = [0, 0, 1, 1];
  const pad = 5;
  const body = Object.entries(paths).map(([kind, ds]) => {
    const [colour, width, dash] = SVG_LOOK[kind] || SVG_LOOK[2];
    return `<path d="${ds.join('')}" fill="none" stroke="${colour}" stroke-width="${width}"${dash ? ` stroke-dasharray="${dash}"` : ''}/>`;
  });
  const w = x1 - x0 + 2 * pad;
  const h = y1 - y0 + 2 * pad;
  return `<?xml version="1.0" encoding="UTF-8"?>
<svg xmlns="http://www.w3.org/2000/svg" width="${f(w)}mm" height="${f(h)}mm" viewBox="${f(x0 - pad)} ${f(-y1 - pad)} ${f(w)} ${f(h)}">
${body.join('\n')}
${labels.join('\n')}
</svg>
`;
}
