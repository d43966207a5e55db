// kerfcam page, Sheet mode (issue 18): the nest drawn on its sheet, as an SVG in the sheet's own
// coordinates (mm, y up): the sheet and its margin, every copy of the sheet shown as its part's outline
// (arcs kept) moved by its placement, the crop line. It is drawn live while the search improves the
// nest, then edited by hand (nest-edit.js): a copy is picked and dragged with the pointer, the crop line
// dragged along x. This module only draws and reports pointer gestures; the rules are the engine's.
// Part names are data: they only ever go into textContent / attributes.

const SVG = 'http://www.w3.org/2000/svg';
export const svg = (name, attrs = {}) => {
  const e = document.createElementNS(SVG, name);
  for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, String(v));
  return e;
};
/** Numbers per copy in a flat placements array: part, copy, sheet, rotation, mirror, x, y. */
export const PER_COPY = 7;

/** The copies of a flat placements array as objects. */
export function copies(flat) {
  const out = [];
  for (let i = 0; i + PER_COPY <= flat.length; i += PER_COPY) {
    out.push({ part: flat[i], copy: flat[i + 1], sheet: flat[i + 2], rotation: flat[i + 3], mirror: !!flat[i + 4], x: flat[i + 5], y: flat[i + 6] });
  }
  return out;
}

/** A copy as a flat row. */
export const row = (c) => [c.part, c.copy, c.sheet, c.rotation, c.mirror ? 1 : 0, c.x, c.y];

/** The SVG transform of a placement: mirror x → −x, turn, move (the engine's Placement::affine). */
export const transformOf = (c) => `translate(${c.x} ${c.y}) rotate(${c.rotation})${c.mirror ? ' scale(-1 1)' : ''}`;

/** Where the part point `q` lands under placement `c`. */
export function place(c, q) {
  const a = (c.rotation * Math.PI) / 180;
  const x = c.mirror ? -q.x : q.x;
  return { x: Math.cos(a) * x - Math.sin(a) * q.y + c.x, y: Math.sin(a) * x + Math.cos(a) * q.y + c.y };
}

/**
 * Sheet `k` of `s` as SVG nodes in sheet coordinates (to go under a y-flip): the sheet, its margin, every
 * copy of the sheet as its part's outline (`outlines` by part index) moved by its placement, the other
 * torches' copies, the labels and the crop line. `s`: { sheets: [{width, height, crop_x}], flat, margin,
 * sheet_shape ({kind, path, box}: the sheet's outline, or null: W × H at 0, 0), torches, labels }, `opts`:
 * { conflicts: Map(copy → why), selected }. Drawn by the nest view and printed on the job report's sheet
 * maps (job-report.js). Returns { viewBox, aspect, nodes, drawn, all } or null (no such sheet).
 */
export function sheetDrawing(s, k, outlines, opts = {}) {
  const sheet = s.sheets[k];
  if (!sheet) return null;
  const shape = s.sheet_shape;
  const [x0, y0, x1, y1] = shape?.box ?? [0, 0, sheet.width, sheet.height];
  const [W, H] = [x1 - x0, y1 - y0];
  const pad = Math.max(W, H) * 0.02;
  const nodes = [shape ? svg('path', { d: shape.path, class: 'nest-sheet', 'fill-rule': 'evenodd' })
    : svg('rect', { x: 0, y: 0, width: W, height: H, class: 'nest-sheet' })];
  const m = s.margin || 0;
  const rect = !shape || shape.kind === 'rect';
  if (rect && m > 0 && W > 2 * m && H > 2 * m) nodes.push(svg('rect', { x: x0 + m, y: y0 + m, width: W - 2 * m, height: H - 2 * m, class: 'nest-margin' }));
  let drawn = 0;
  const all = copies(s.flat || []);
  all.forEach((c, i) => {
    if (c.sheet !== k) return;
    const o = outlines[c.part];
    if (!o) return;
    const p = svg('path', { d: o.d, transform: transformOf(c), class: 'nest-copy', 'fill-rule': 'evenodd', 'data-copy': i, 'data-part': o.name });
    const why = opts.conflicts?.get(i);
    if (why) {
      p.classList.add('conflict');
      p.dataset.why = why;
    }
    if (opts.selected === i) p.classList.add('selected');
    nodes.push(p);
    drawn++;
  });
  // The other torches' copies (paper 001 §6.5), faded: drawn for the eye,
  // not edited, not cut by this program (torch 1's).
  const torches = s.torches;
  if (torches && torches.count > 1) {
    for (let n = 1; n < torches.count; n++) {
      const g = svg('g', { transform: `translate(0 ${n * torches.spacing})`, class: 'nest-slave', 'data-torch': n + 1 });
      all.forEach((c) => {
        const o = outlines[c.part];
        if (c.sheet === k && o) g.append(svg('path', { d: o.d, transform: transformOf(c), 'fill-rule': 'evenodd' }));
      });
      nodes.push(g);
    }
  }
  // The copies' labels (issue 42 §2): the engine's strokes, sheet coordinates; the text is data (an attribute).
  for (const l of s.labels?.labels || []) {
    if (l.sheet !== k) continue;
    const d = l.strokes.map((p) => p.reduce((a, v, j) => a + (j % 2 ? ` ${v}` : `${j ? ' L' : 'M'}${v}`), '')).join(' ');
    nodes.push(svg('path', { d, class: 'nest-label', 'data-label': l.text, 'data-part': l.part, 'data-label-copy': l.copy }));
  }
  if (Number.isFinite(sheet.crop_x) && k === s.sheets.length - 1) {
    const x = sheet.crop_x;
    nodes.push(svg('rect', { x, y: y0, width: Math.max(0, x1 - x), height: H, class: 'nest-remnant' }));
    const line = svg('line', { x1: x, y1: y0 - pad / 2, x2: x, y2: y1 + pad / 2, class: 'nest-crop', 'data-crop': x });
    nodes.push(line, svg('line', { x1: x, y1: y0, x2: x, y2: y1, class: 'nest-crop-grip', 'data-crop': x }));
  }
  return { viewBox: `${x0 - pad} ${-y1 - pad} ${W + 2 * pad} ${H + 2 * pad}`, aspect: `${W + 2 * pad} / ${H + 2 * pad}`, nodes, drawn, all };
}

export class NestView {
  /**
   * `box`: the element the SVG goes in. `hooks`: { select(i), moved(i, dx, dy) (a drag ended, mm),
   * cropMoved(x) (the crop line dropped at x), label(k) (the SVG's accessible name) }.
   */
  constructor(box, hooks) {
    Object.assign(this, { box, hooks });
    this.outlines = [];
    this.root = svg('svg', { class: 'nest-svg', tabindex: '0', role: 'img', 'data-copies': '0', 'data-updates': '0' });
    this.title = svg('title');
    this.root.append(this.title);
    this.flip = svg('g', { transform: 'scale(1 -1)' }); // sheet coordinates, y up
    this.root.append(this.flip);
    box.replaceChildren(this.root);
    this.updates = 0;
    this.drag = null;
    this.root.addEventListener('pointerdown', (e) => this.down(e));
    this.root.addEventListener('pointermove', (e) => this.move(e));
    this.root.addEventListener('pointerup', (e) => this.up(e));
    this.root.addEventListener('pointercancel', () => this.cancel());
  }

  setOutlines(outlines) {
    this.outlines = outlines || [];
  }

  /** Sheet coordinates (mm) of a pointer event. */
  at(e) {
    const m = this.flip.getScreenCTM();
    if (!m) return { x: 0, y: 0 };
    const p = new DOMPoint(e.clientX, e.clientY).matrixTransform(m.inverse());
    return { x: p.x, y: p.y };
  }

  /**
   * Draws sheet `k` of `s`: { sheets: [{width, height, crop_x}], flat, margin, sheet_shape ({kind, path,
   * box}: the sheet's outline, or null: W × H at 0, 0) }, `opts`: { conflicts: Map(copy → why), selected, live }.
   */
  draw(s, k, opts = {}) {
    const drawing = sheetDrawing(s, k, this.outlines, opts);
    if (!drawing) return;
    this.root.setAttribute('viewBox', drawing.viewBox);
    this.root.style.aspectRatio = drawing.aspect;
    this.flip.replaceChildren(...drawing.nodes);
    this.root.dataset.copies = String(drawing.drawn);
    this.title.textContent = this.hooks.label(k); // its accessible name says how many copies it shows
    this.root.dataset.sheet = String(k);
    this.root.dataset.live = opts.live ? 'true' : 'false';
    if (opts.live) this.root.dataset.updates = String(++this.updates);
    this.shown = { s, k, all: drawing.all };
    this.lastOpts = opts;
  }

  /** Forgets the live drawings' count (a new nest starts). */
  reset() {
    this.updates = 0;
    this.root.dataset.updates = '0';
  }

  down(e) {
    if (this.root.dataset.live === 'true' || !this.shown) return;
    const t = e.target;
    const start = this.at(e);
    if (t.dataset?.crop !== undefined) {
      this.drag = { crop: true, start, x0: Number(t.dataset.crop), nodes: [...this.flip.querySelectorAll('[data-crop]')] };
    } else if (t.dataset?.copy !== undefined) {
      const i = Number(t.dataset.copy);
      this.hooks.select(i);
      const node = this.flip.querySelector(`[data-copy="${i}"]`);
      this.drag = { i, start, node, c: this.shown.all[i] };
    } else {
      this.hooks.select(null);
      return;
    }
    this.root.setPointerCapture?.(e.pointerId);
    e.preventDefault();
    this.root.focus(); // the arrow keys move the copy picked
  }

  move(e) {
    const d = this.drag;
    if (!d) return;
    const p = this.at(e);
    const dx = p.x - d.start.x;
    const dy = p.y - d.start.y;
    d.moved = Math.abs(dx) + Math.abs(dy) > 0;
    if (d.crop) {
      for (const n of d.nodes) {
        n.setAttribute('x1', d.x0 + dx);
        n.setAttribute('x2', d.x0 + dx);
      }
      d.dx = dx;
    } else if (d.node) {
      d.node.setAttribute('transform', transformOf({ ...d.c, x: d.c.x + dx, y: d.c.y + dy }));
      Object.assign(d, { dx, dy });
    }
  }

  up(e) {
    const d = this.drag;
    this.drag = null;
    if (!d) return;
    this.root.releasePointerCapture?.(e.pointerId);
    if (!d.moved) return;
    if (d.crop) this.hooks.cropMoved(d.x0 + (d.dx || 0));
    else this.hooks.moved(d.i, d.dx || 0, d.dy || 0);
  }

  cancel() {
    this.drag = null;
    if (this.shown) this.draw(this.shown.s, this.shown.k, this.lastOpts);
  }

  /** The part point at the middle of part `part`'s outline box (a copy turns and mirrors about it). */
  middle(part) {
    const o = this.outlines[part];
    if (!o) return { x: 0, y: 0 };
    if (!o.box) {
      const p = svg('path', { d: o.d });
      const probe = svg('svg', { width: 0, height: 0, 'aria-hidden': 'true' });
      probe.style.position = 'absolute';
      probe.append(p);
      document.body.append(probe);
      const b = p.getBBox();
      probe.remove();
      o.box = { x: b.x, y: b.y, w: b.width, h: b.height };
    }
    return { x: o.box.x + o.box.w / 2, y: o.box.y + o.box.h / 2, box: o.box };
  }
}
