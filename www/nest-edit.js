// kerfcam page, Sheet mode (issue 18 item 4, paper 001 §6.2): the nest drawn live while it improves,
// then adjusted by hand: pick a copy (pointer, or the Copy menu), drag it or nudge it with the arrow
// keys (Shift: 10 mm), R turns it to its next allowed step (or the angle typed), M mirrors it (when its
// part may be mirrored), Delete removes it, Add puts one more copy of a part, S butts it left and down
// at the spacing (MOVEPECA); Ctrl+Z / Ctrl+Y undo and redo. After every change the engine checks the
// nest (src/nest/edit.rs): copies that break the rules turn red and are listed with the reason, and the
// sheet is not cut (no preview, no download) until they are fixed. The crop line after the last part is
// dragged (or typed) and Save remnant downloads the piece beyond it as a sheet DXF.

import { $, el } from './app.js';
import { download } from './download.js';
import { fmtNumber, onLangChange, register, t } from './i18n.js';
import { formatValue, parseNumber } from './numbers.js';
import { NestView, copies, place, row } from './nest-view.js';
import { sheetSize } from './sheet-sizes.js';

register({
  en: {
    'edit.heading': 'Nest on the sheet', 'edit.undo': 'Undo', 'edit.redo': 'Redo', 'edit.copy': 'Copy', 'edit.none': '(none)',
    'edit.snap': 'Snap (S)', 'edit.rotate': 'Rotate (R)', 'edit.angle': 'Angle (°)', 'edit.mirror': 'Mirror (M)',
    'edit.remove': 'Remove (Del)', 'edit.part': 'Part', 'edit.add': 'Add a copy', 'edit.crop': 'Crop line at x (mm)',
    'edit.save-remnant': 'Save remnant', 'edit.view': 'Sheet {k}: {n} copies. Arrow keys move the copy picked.',
    'edit.keys': 'Pick a copy, then drag it or use the arrow keys (Shift: 10 mm), R, M, S, Delete; Ctrl+Z / Ctrl+Y undo and redo.',
    'edit.figures': 'Used length {l} mm · utilisation {u} %', 'edit.remnant': 'remnant {a} m² beyond x = {x} mm',
    'edit.no-remnant': 'no remnant kept', 'edit.live': 'Best nest so far ({n} copies on sheet {k})',
    'edit.overlap': '{a} overlaps {b}', 'edit.spacing': '{a} is closer than the spacing ({s} mm) to {b}',
    'edit.off-sheet': '{a} is off the sheet', 'edit.margin': "{a} is inside the sheet's margin ({m} mm)",
    'edit.no-go': '{a} is on a no-go zone of the sheet',
    'edit.blocked': { one: '{n} copy breaks the rules: fix it (or Undo) to cut the sheet.', other: '{n} copies break the rules: fix them (or Undo) to cut the sheet.' },
    'edit.ok': 'The nest keeps the spacing and the margin.', 'edit.no-turn': '{a} may not turn (its rotation is "none").',
    'edit.steps-only': '{a} turns only in steps of {s}°.', 'edit.no-mirror': '{a} may not be mirrored (tick Mirror in the parts list).',
    'edit.angle-bad': 'Angle: enter a number of degrees.', 'edit.crop-bad': 'Crop line: enter a number of mm.',
    'edit.pick-first': 'Pick a copy first.', 'edit.nothing-kept': 'No remnant is kept beyond the crop line.',
    'edit.failed': 'The edit failed: {message}',
    'edit.snap-stuck': '{a} did not move: Snap slides a copy only through free places (move it clear of the others first).',
  },
  'pt-BR': {
    'edit.heading': 'Encaixe na chapa', 'edit.undo': 'Desfazer', 'edit.redo': 'Refazer', 'edit.copy': 'Cópia', 'edit.none': '(nenhuma)',
    'edit.snap': 'Encostar (S)', 'edit.rotate': 'Girar (R)', 'edit.angle': 'Ângulo (°)', 'edit.mirror': 'Espelhar (M)',
    'edit.remove': 'Remover (Del)', 'edit.part': 'Peça', 'edit.add': 'Adicionar cópia', 'edit.crop': 'Linha de retalho em x (mm)',
    'edit.save-remnant': 'Salvar retalho', 'edit.view': 'Chapa {k}: {n} cópias. As setas movem a cópia escolhida.',
    'edit.keys': 'Escolha uma cópia e arraste-a ou use as setas (Shift: 10 mm), R, M, S, Delete; Ctrl+Z / Ctrl+Y desfazem e refazem.',
    'edit.figures': 'Comprimento usado {l} mm · aproveitamento {u} %', 'edit.remnant': 'retalho de {a} m² além de x = {x} mm',
    'edit.no-remnant': 'nenhum retalho guardado', 'edit.live': 'Melhor encaixe até agora ({n} cópias na chapa {k})',
    'edit.overlap': '{a} sobrepõe {b}', 'edit.spacing': '{a} está mais perto que o espaçamento ({s} mm) de {b}',
    'edit.off-sheet': '{a} está fora da chapa', 'edit.margin': '{a} está dentro da margem da chapa ({m} mm)',
    'edit.no-go': '{a} está numa zona proibida da chapa',
    'edit.blocked': { one: '{n} cópia quebra as regras: corrija-a (ou Desfazer) para cortar a chapa.', other: '{n} cópias quebram as regras: corrija-as (ou Desfazer) para cortar a chapa.' },
    'edit.ok': 'O encaixe respeita o espaçamento e a margem.', 'edit.no-turn': '{a} não pode girar (rotação "nenhuma").',
    'edit.steps-only': '{a} gira só em passos de {s}°.', 'edit.no-mirror': '{a} não pode ser espelhada (marque Espelhar na lista de peças).',
    'edit.angle-bad': 'Ângulo: informe um número de graus.', 'edit.crop-bad': 'Linha de retalho: informe um número em mm.',
    'edit.pick-first': 'Escolha uma cópia primeiro.', 'edit.nothing-kept': 'Nenhum retalho é guardado além da linha de retalho.',
    'edit.failed': 'A edição falhou: {message}',
    'edit.snap-stuck': '{a} não se moveu: Encostar desliza uma cópia só por lugares livres (afaste-a das outras antes).',
  },
});

const STEP = { '90': 90, '180': 180, free: 15 }; // free turns: the engine's FREE_STEPS (24 steps of 15°)

export class NestEdit {
  /** `hooks`: { engine(), panel (the SheetPanel), k() (sheet shown), changed() (the nest changed: cut it again) } */
  constructor(hooks) {
    this.hooks = hooks;
    this.state = null;
    this.undo = [];
    this.redo = [];
    this.selected = null;
    this.version = 0;
    this.queue = Promise.resolve();
    const ids = ['nest-view', 'nest-undo', 'nest-redo', 'nest-copy', 'nest-snap', 'nest-rotate', 'nest-angle', 'nest-mirror', 'nest-remove',
      'nest-add-part', 'nest-add', 'nest-crop', 'nest-save-remnant', 'nest-export-dxf', 'nest-export-svg', 'nest-view-figures', 'nest-edit-message', 'nest-conflicts'];
    this.ui = Object.fromEntries(ids.map((id) => [id.replace(/^nest-/, '').replace(/-(\w)/g, (_, c) => c.toUpperCase()), $(id)]));
    this.view = new NestView($('nest-canvas'), {
      select: (i) => this.select(i),
      moved: (i, dx, dy) => this.change(i, (c) => ({ ...c, x: c.x + dx, y: c.y + dy })),
      cropMoved: (x) => this.apply(() => ({ crop: x })),
      label: (k) => t('edit.view', { k: fmtNumber(k + 1), n: fmtNumber(this.view.root.dataset.copies || 0) }),
    });
    const on = (name, f) => this.ui[name].addEventListener('click', f);
    on('undo', () => this.back(this.undo, this.redo));
    on('redo', () => this.back(this.redo, this.undo));
    on('snap', () => this.snap());
    on('rotate', () => this.rotate());
    on('mirror', () => this.mirror());
    on('remove', () => this.remove());
    on('add', () => this.add());
    on('saveRemnant', () => this.saveRemnant());
    this.ui.copy.addEventListener('change', () => this.select(this.ui.copy.value === '' ? null : Number(this.ui.copy.value)));
    this.ui.angle.addEventListener('change', () => this.turnTo(parseNumber(this.ui.angle.value)));
    this.ui.crop.addEventListener('change', () => {
      const x = parseNumber(this.ui.crop.value);
      if (Number.isFinite(x)) this.apply(() => ({ crop: x }));
      else this.say(t('edit.crop-bad'));
    });
    this.ui.view.addEventListener('keydown', (e) => this.key(e));
    onLangChange(() => this.render());
  }

  /** Copies in conflict: the sheet may not be cut. */
  get blocked() {
    return !!this.state?.conflicts.length;
  }

  /** A new nest starts: the view draws it live. */
  start(outlines, sheet, shape) {
    Object.assign(this, { state: null, undo: [], redo: [], selected: null, sheet, shape, crop: undefined, liveNest: null, liveCounts: null });
    this.view.setOutlines(outlines);
    this.view.reset();
    this.ui.view.hidden = false;
    this.ui.view.classList.add('live');
    this.say('');
    this.ui.conflicts.replaceChildren();
  }

  /**
   * A progress report (`p`, or null: draw the last one again, another sheet picked): the best nest so far
   * drawn on the sheet picked. Answers the copies on each sheet of that nest (for the tabs), or null.
   */
  live(p) {
    // Sheets at a cost: the combination under trial is the nest's sheets (nest-run.js gives its list).
    if (p?.sheet_list) this.sheet = { ...this.sheet, sheet_list: p.sheet_list };
    if (p?.placements) this.liveNest = { flat: p.placements, sheets: Math.max(1, p.sheets) };
    const n = this.liveNest;
    if (!n || !this.sheet || (p && !p.placements)) return n ? this.liveCounts : null;
    const { margin } = this.sheet;
    const sheets = Array.from({ length: n.sheets }, (_, k) => sheetSize(this.sheet, k));
    const k = Math.min(this.hooks.k(), n.sheets - 1);
    this.view.draw({ sheets, flat: n.flat, margin, sheet_shape: this.shape }, k, { live: true });
    const counts = sheets.map(() => 0);
    for (const c of copies(n.flat)) if (c.sheet < counts.length) counts[c.sheet]++;
    this.ui.viewFigures.textContent = t('edit.live', { n: fmtNumber(counts[k]), k: fmtNumber(k + 1) });
    this.liveCounts = counts;
    return counts;
  }

  /** The finished nest (`state`: NestResult.state()), or null when there is none; `crop`: its crop line as left. */
  load(state, crop) {
    this.ui.view.classList.remove('live');
    this.state = state;
    this.crop = crop;
    this.ui.view.hidden = !state;
    this.version++;
    if (state) this.fillMenus();
    this.render();
  }

  /** Sheet mode on or off: the nest view is shown in Sheet mode only, when there is a nest. */
  shown(on) {
    this.ui.view.hidden = !(on && this.state);
  }

  name(i) {
    const c = copies(this.state.flat)[i];
    return c ? `${this.state.outlines[c.part]?.name ?? '?'} #${c.copy + 1}` : '?';
  }

  fillMenus() {
    const names = this.state.outlines.map((o) => o.name);
    this.ui.addPart.replaceChildren(...names.map((n, i) => el('option', n, { value: String(i) })));
  }

  render() {
    const s = this.state;
    if (!s) return;
    const k = this.hooks.k();
    const conflicts = new Map();
    for (const c of s.conflicts) if (!conflicts.has(c.copy)) conflicts.set(c.copy, c.why);
    this.view.draw(s, k, { conflicts, selected: this.selected });
    const all = copies(s.flat);
    this.ui.copy.replaceChildren(el('option', t('edit.none'), { value: '' }),
      ...all.map((c, i) => (c.sheet === k ? el('option', this.name(i), { value: String(i) }) : null)).filter(Boolean));
    this.ui.copy.value = this.selected === null ? '' : String(this.selected);
    const sheet = s.sheets[k];
    const figures = [t('edit.figures', { l: fmtNumber(sheet?.used_length ?? 0, 1), u: fmtNumber(100 * (sheet?.utilisation ?? 0), 1) })];
    const last = k === s.sheets.length - 1;
    if (last) figures.push(Number.isFinite(sheet?.crop_x) ? t('edit.remnant', { a: fmtNumber((s.remnant_area ?? 0) / 1e6, 3), x: fmtNumber(sheet.crop_x, 1) }) : t('edit.no-remnant'));
    this.ui.viewFigures.textContent = figures.join(' · ');
    this.ui.crop.disabled = !last || !s.crop_range;
    if (last && Number.isFinite(sheet?.crop_x) && document.activeElement !== this.ui.crop) this.ui.crop.value = formatValue(sheet.crop_x, 2);
    this.ui.saveRemnant.disabled = !last || !Number.isFinite(sheet?.crop_x) || this.blocked;
    this.ui.exportDxf.disabled = this.blocked; // the DXF is the nest cut: not while copies are in conflict
    this.ui.exportSvg.disabled = this.blocked;
    this.ui.undo.disabled = !this.undo.length;
    this.ui.redo.disabled = !this.redo.length;
    for (const b of ['snap', 'rotate', 'mirror', 'remove', 'angle']) this.ui[b].disabled = this.selected === null;
    const items = s.conflicts.map((c) => {
      const a = this.name(c.copy);
      const b = c.with === null || c.with === undefined ? '' : this.name(c.with);
      const li = el('li', t(`edit.${c.why}`, { a, b, s: fmtNumber(s.spacing), m: fmtNumber(this.state?.margin ?? 0) }));
      li.dataset.copy = String(c.copy);
      li.dataset.why = c.why;
      return li;
    });
    this.ui.conflicts.replaceChildren(...items);
    this.ui.view.dataset.conflicts = String(new Set(s.conflicts.map((c) => c.copy)).size);
    this.ui.view.dataset.placed = String(all.length);
    if (!this.message) this.ui.editMessage.textContent = s.conflicts.length
      ? t('edit.blocked', { n: fmtNumber(conflicts.size), count: conflicts.size }) : t('edit.ok');
    if (this.selected !== null && this.selected < all.length) this.ui.angle.value = formatValue(all[this.selected].rotation, 3);
  }

  say(text) {
    this.message = text;
    this.ui.editMessage.textContent = text;
  }

  select(i) {
    this.selected = i === null || !this.state || i >= this.state.flat.length / 7 ? null : i;
    this.say('');
    this.render();
  }

  /** The nest as it stands, as an edit that puts it back (an undo step). */
  snapshot() {
    return { placements: copies(this.state.flat).map(row), crop: this.crop ?? 'auto' };
  }

  /**
   * Queues a change: `make()` gives the edit (placements and/or crop line) from the nest as it stands when
   * its turn comes (keys pressed fast each build on the one before), the engine checks it, the answer is
   * the nest as it now stands. `op`: 'editNest' (default) or another engine call with `make()` as args.
   */
  apply(make, op = 'editNest') {
    return this.enqueue(async () => {
      if (!this.state) return;
      const edit = make();
      if (!edit) return;
      const before = this.snapshot();
      try {
        if (edit.crop !== undefined) this.crop = edit.crop;
        const args = op === 'editNest' ? { json: JSON.stringify(edit) } : edit;
        const changed = this.take(JSON.parse(await this.hooks.engine().call(op, args)), before);
        if (!changed && op === 'snapCopy') this.say(t('edit.snap-stuck', { a: this.name(edit.i) }));
      } catch (e) {
        this.crop = before.crop;
        throw e;
      }
    });
  }

  /**
   * Runs `task` after the edits queued before it. A task that fails says why and the queue goes on: a
   * rejected link would skip every later edit, undo and redo without a word.
   */
  enqueue(task) {
    this.queue = this.queue.then(task).catch((e) => this.say(t('edit.failed', { message: e.message || String(e) })));
    return this.queue;
  }

  take(s, before) {
    const same = before && before.placements.flat().every((v, j) => v === s.flat[j]) && before.placements.length * 7 === s.flat.length
      && (before.crop ?? 'auto') === (this.crop ?? 'auto');
    if (same) {
      this.render(); // nothing changed (a crop line held at the parts, a snap with no room): no undo step, no new cut
      return false;
    }
    if (before) {
      this.undo.push(before);
      this.redo = [];
    }
    s.outlines = this.state.outlines;
    this.state = s;
    if (this.selected !== null && this.selected >= s.flat.length / 7) this.selected = null;
    this.version++;
    this.say('');
    this.render();
    window.kerfcam.lastNest = s;
    this.hooks.changed();
    return true;
  }

  back(from, to) {
    return this.enqueue(async () => {
      if (!this.state || !from.length) return;
      const entry = from.pop();
      const here = this.snapshot();
      to.push(here);
      this.crop = entry.crop;
      try {
        this.take(JSON.parse(await this.hooks.engine().call('editNest', { json: JSON.stringify(entry) })), null);
      } catch (e) {
        // Not applied: the step stays where it was, to be tried again.
        to.pop();
        from.push(entry);
        this.crop = here.crop;
        this.render();
        throw e;
      }
    });
  }

  /** Copy i changed by `f` (a copy → the copy), kept when the engine has checked it. */
  change(i, f) {
    return this.apply(() => {
      const all = copies(this.state.flat);
      if (!all[i]) return null;
      all[i] = f(all[i]);
      return { placements: all.map(row) };
    });
  }

  picked() {
    if (this.selected === null) this.say(t('edit.pick-first'));
    return this.selected;
  }

  /** The parts list's choices for copy i's part: { rotations, mirror }. */
  rules(i) {
    const name = this.state.outlines[copies(this.state.flat)[i].part]?.name;
    const p = this.hooks.panel.parts.find((x) => x.info?.parts.includes(name));
    return { rotations: p?.rotations ?? 'none', mirror: !!p?.mirror };
  }

  /** Copy i turned to `deg` (and mirrored as `mirror`) about the middle of its outline box. */
  turned(c, deg, mirror) {
    const m = this.view.middle(c.part);
    const at = place(c, m);
    const next = { ...c, rotation: deg, mirror };
    const moved = place({ ...next, x: 0, y: 0 }, m);
    return { ...next, x: at.x - moved.x, y: at.y - moved.y };
  }

  rotate() {
    const i = this.picked();
    if (i === null) return;
    const r = this.rules(i);
    if (!STEP[r.rotations]) return this.say(t('edit.no-turn', { a: this.name(i) }));
    this.change(i, (c) => this.turned(c, (c.rotation + STEP[r.rotations]) % 360, c.mirror));
  }

  turnTo(deg) {
    const i = this.picked();
    if (i === null) return;
    if (!Number.isFinite(deg)) return this.say(t('edit.angle-bad'));
    const r = this.rules(i);
    if (!STEP[r.rotations]) return this.say(t('edit.no-turn', { a: this.name(i) }));
    const step = STEP[r.rotations];
    if (r.rotations !== 'free' && Math.abs(deg / step - Math.round(deg / step)) > 1e-9) return this.say(t('edit.steps-only', { a: this.name(i), s: step }));
    this.change(i, (c) => this.turned(c, ((deg % 360) + 360) % 360, c.mirror));
  }

  mirror() {
    const i = this.picked();
    if (i === null) return;
    if (!this.rules(i).mirror) return this.say(t('edit.no-mirror', { a: this.name(i) }));
    this.change(i, (c) => this.turned(c, c.rotation, !c.mirror));
  }

  remove() {
    const i = this.picked();
    if (i === null) return;
    this.selected = null;
    this.apply(() => {
      const all = copies(this.state.flat);
      all.splice(i, 1);
      return { placements: all.map(row) };
    });
  }

  /** One more copy of the part chosen, beyond the last part of the sheet shown, then butted against the nest. */
  add() {
    const part = Number(this.ui.addPart.value);
    return this.apply(() => {
      const all = copies(this.state.flat);
      const k = this.hooks.k();
      const copy = 1 + Math.max(-1, ...all.filter((c) => c.part === part).map((c) => c.copy));
      const { box } = this.view.middle(part);
      const sheet = this.state.sheets[k];
      const m = this.state?.margin ?? 0;
      const [x0, , x1] = this.state.sheet_shape?.box ?? [0, 0, sheet.width];
      const x = Math.min(x0 + sheet.used_length + this.state.spacing, x1 - m - box.w);
      const y0 = this.state.sheet_shape?.box[1] ?? 0;
      all.push({ part, copy, sheet: k, rotation: 0, mirror: false, x: x - box.x, y: y0 + m - box.y });
      this.selected = all.length - 1;
      return { placements: all.map(row) };
    });
  }

  snap() {
    const i = this.picked();
    if (i === null) return null;
    return this.apply(() => ({ i }), 'snapCopy');
  }

  async saveRemnant() {
    const dxf = await this.hooks.engine().call('remnantDxf');
    if (!dxf) return this.say(t('edit.nothing-kept'));
    download(new Blob([dxf], { type: 'application/dxf' }), 'nest-remnant.dxf');
  }

  key(e) {
    if (!this.state || e.target.matches('input, select')) return;
    const ctrl = e.ctrlKey || e.metaKey;
    const k = e.key.toLowerCase();
    if (ctrl && (k === 'z' || k === 'y')) {
      e.preventDefault();
      if (k === 'z' && !e.shiftKey) this.back(this.undo, this.redo);
      else this.back(this.redo, this.undo);
      return;
    }
    if (ctrl || e.altKey) return;
    const step = e.shiftKey ? 10 : 1;
    const arrows = { arrowleft: [-step, 0], arrowright: [step, 0], arrowup: [0, step], arrowdown: [0, -step] };
    const act = {
      r: () => this.rotate(), m: () => this.mirror(), s: () => this.snap(), delete: () => this.remove(), backspace: () => this.remove(),
    };
    if (arrows[k] && this.selected !== null) {
      const [dx, dy] = arrows[k];
      this.change(this.selected, (c) => ({ ...c, x: c.x + dx, y: c.y + dy }));
    } else if (act[k]) act[k]();
    else return;
    e.preventDefault();
  }
}
