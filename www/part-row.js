// kerfcam page, Sheet mode (issue 18 item 1): one row of the parts list — a dropped DXF file's parts with
// their quantity, rotation choice, mirror toggle and grain lock, and the unit the file is read in with a
// switch to read it in another (units.js's switch, the engine's units: an inch file whose header says
// nothing is read as mm and flagged, and one click reads it in inches). File names are data: textContent.
//
// Grain lock: a part cut from brushed, rolled or patterned sheet must keep its grain along the sheet's.
// Turning it by 180° keeps the grain's direction (the lines stay parallel), 90° does not; so a locked
// part may turn by 0° or 180° only, as nesting programs for shops commonly do ("grain constraint"):
// it is passed to the engine as that part's allowed rotations ("180", or "none" if it may not turn).

import { el } from './app.js';
import { fmtNumber, register, t } from './i18n.js';
import { unitsText } from './summary.js';
import { unitSwitch } from './units.js';

register({
  en: {
    'nest.grain': 'Grain lock', 'nest.grain-help': 'keeps the grain: turns by 180° only',
    'nest.part-size': { one: '{w} × {h} mm · {area} cm² · {holes} hole', other: '{w} × {h} mm · {area} cm² · {holes} holes' },
    'nest.part-count': { one: '{n} part', other: '{n} parts, each with its own quantity:' },
    'nest.part-layer': 'layer {layer}',
    'nest.set-all': 'For every part of this file:',
  },
  'pt-BR': {
    'nest.grain': 'Travar o sentido do grão', 'nest.grain-help': 'mantém o sentido do grão: gira só 180°',
    // CLDR counts 0 as "one" in Portuguese ("0 furo"): the count after a colon reads right for any number.
    'nest.part-size': '{w} × {h} mm · {area} cm² · furos: {holes}',
    'nest.part-count': { one: '{n} peça', other: '{n} peças, cada uma com sua quantidade:' },
    'nest.part-layer': 'camada {layer}',
    'nest.set-all': 'Para todas as peças deste arquivo:',
  },
});

/** The rotations a grain-locked part keeps of a choice: none stays none, any other turns by 180° only. */
export const grainRotations = (rotations) => (rotations === 'none' ? 'none' : '180');

const SVGNS = 'http://www.w3.org/2000/svg';

/** The part's picture: its outline and holes as the core drew them (SVG path data, y up), fitted in 56 × 40 px. */
function thumbnail(row) {
  const svg = document.createElementNS(SVGNS, 'svg');
  const pad = 0.04 * Math.max(row.width, row.height, 1e-6);
  svg.setAttribute('viewBox', `${row.x - pad} ${-(row.y + row.height) - pad} ${row.width + 2 * pad} ${row.height + 2 * pad}`);
  svg.setAttribute('class', 'part-thumb');
  svg.setAttribute('aria-hidden', 'true');
  const path = document.createElementNS(SVGNS, 'path');
  path.setAttribute('d', row.d);
  path.setAttribute('transform', 'scale(1 -1)');
  path.setAttribute('fill-rule', 'evenodd');
  path.setAttribute('vector-effect', 'non-scaling-stroke');
  svg.append(path);
  return svg;
}

/** `W × H mm · area · n holes` of a part row. */
const sizeText = (r) => t('nest.part-size', {
  w: fmtNumber(r.width, 1), h: fmtNumber(r.height, 1), area: fmtNumber(r.area / 100, 1), holes: fmtNumber(r.holes), count: r.holes,
});

/**
 * Quantity, rotation, mirror and grain fields bound to `c` ({ quantity, rotations, mirror, grain }), ids from
 * `id`. `opts`: { label (whose quantity, for the message), zero (0 allowed), greyed (why the nester cannot place
 * it: 0 only), set(key, value) after a change }.
 * Returns { grid, bad, help, refresh() (the fields shown again from `c`) }.
 */
function choiceFields(c, id, hooks, opts) {
  const grid = el('div', '', { className: 'part-fields' });
  const qty = el('input', '', { id: id('qty'), type: 'text', inputMode: 'numeric', value: c.quantity, autocomplete: 'off', className: 'qty' });
  const bad = el('p', '', { id: id('qty-error'), className: 'error-text small' });
  const check = () => {
    const readable = hooks.quantityOk(qty.value, opts.zero);
    // A greyed row (the nester cannot place it) takes 0 only: more is said here, and no nest starts on it.
    const ok = readable && !(opts.greyed && Number(qty.value.trim()) > 0);
    qty.setAttribute('aria-invalid', String(!ok));
    bad.textContent = ok ? '' : hooks.quantityBad(opts.label, opts.zero, readable ? opts.greyed : null);
    return ok;
  };
  qty.setAttribute('aria-describedby', bad.id);
  qty.addEventListener('input', () => {
    c.quantity = qty.value;
    if (check()) opts.set?.('quantity', qty.value);
    hooks.changed();
  });
  const rot = el('select', '', { id: id('rot') });
  const fillRotations = () => {
    if (c.grain) c.rotations = grainRotations(c.rotations);
    const offered = c.grain ? ['none', '180'] : ['none', '180', '90', 'free'];
    rot.replaceChildren(...offered.map((r) => el('option', t(`nest.rot.${r}`), { value: r })));
    rot.value = c.rotations;
  };
  fillRotations();
  rot.addEventListener('change', () => {
    c.rotations = rot.value;
    opts.set?.('rotations', rot.value);
    hooks.changed();
  });
  const check2 = (key, on, set) => {
    const box = el('input', '', { id: id(key), type: 'checkbox', checked: on });
    box.addEventListener('change', () => set(box.checked));
    const label = el('label', '', { htmlFor: box.id, className: 'check' });
    label.append(box, ' ', t(`nest.${key}`));
    return label;
  };
  const mirror = check2('mirror', c.mirror, (on) => {
    c.mirror = on;
    opts.set?.('mirror', on);
    hooks.changed();
  });
  const help = el('p', c.grain ? t('nest.grain-help') : '', { id: id('grain-help'), className: 'muted small' });
  const grain = check2('grain', !!c.grain, (on) => {
    c.grain = on;
    help.textContent = on ? t('nest.grain-help') : '';
    fillRotations();
    opts.set?.('grain', on);
    hooks.changed();
  });
  grain.title = t('nest.grain-help');
  grain.querySelector('input').setAttribute('aria-describedby', id('grain-help'));
  grid.append(el('label', t('nest.quantity'), { htmlFor: qty.id }), qty,
    el('label', t('nest.rotations'), { htmlFor: rot.id }), rot, mirror, grain);
  check();
  const refresh = () => {
    qty.value = c.quantity;
    check();
    fillRotations();
    mirror.querySelector('input').checked = !!c.mirror;
    grain.querySelector('input').checked = !!c.grain;
    help.textContent = c.grain ? t('nest.grain-help') : '';
  };
  return { grid, bad, help, refresh };
}

/**
 * One part of a file of several (issue 42 §1): its picture, name (and layer), size, area and holes, and its
 * own quantity, rotation, mirror and grain. A row that is not a part (its outline encloses no area) is greyed
 * with the engine's reason and asks 0 copies; a quantity typed on it is said at its field, and no nest starts.
 */
function partItem(p, i, row, hooks) {
  const c = p.each[i];
  const li = el('li', '', { className: row.not_nestable ? 'part-item not-part' : 'part-item' });
  li.dataset.part = row.name;
  const text = el('div', '', { className: 'part-text' });
  const name = el('p', '', { className: 'part-name' });
  name.append(el('strong', row.name));
  if (row.layer && row.layer !== '0') name.append(' ', el('span', t('nest.part-layer', { layer: row.layer }), { className: 'muted small' }));
  text.append(name, el('p', sizeText(row), { className: 'muted small' }));
  if (row.not_nestable) text.append(el('p', row.not_nestable, { className: 'warn-text small' }));
  const f = choiceFields(c, (s) => `part-${p.id}-${i}-${s}`, hooks, { label: row.name, zero: true, greyed: row.not_nestable });
  li.append(thumbnail(row), text, f.grid, f.bad, f.help);
  return { li, refresh: f.refresh };
}

/**
 * The row of part file `p` ({ id, name, quantity, rotations, mirror, grain, units, info, error, each }); a file of
 * several parts lists each part with its own choices, the file's fields then set all of them at once.
 * `hooks`: { quantityOk(text, zero), quantityBad(name, zero, greyed), changed(), remove(p), reread(p) (read again in p.units) }.
 */
export function partRow(p, hooks) {
  const li = el('li', '', { className: 'part' });
  li.dataset.name = p.name;
  const id = (s) => `part-${p.id}-${s}`;
  const head = el('p', '', { className: 'part-name' });
  head.append(el('strong', p.name));
  li.append(head);
  const rows = p.info?.rows ?? [];
  if (p.error) li.append(el('p', p.error, { className: 'error-text small', role: 'alert' }));
  else if (!p.info) li.append(el('p', t('nest.reading', { name: p.name }), { className: 'muted small' }));
  else {
    const names = p.info.parts;
    if (rows.length === 1) {
      const one = el('div', '', { className: 'part-one' });
      one.append(thumbnail(rows[0]), el('p', `${t('nest.part-names', { n: fmtNumber(1), count: 1, names: names[0] })} · ${sizeText(rows[0])}`, { className: 'muted small' }));
      li.append(one);
      if (rows[0].not_nestable) li.append(el('p', rows[0].not_nestable, { className: 'warn-text small' }));
    } else {
      li.append(el('p', names.length ? t('nest.part-count', { n: fmtNumber(names.length), count: names.length })
        : t('nest.no-nestable'), { className: names.length ? 'muted small' : 'error-text small' }));
    }
    for (const s of p.info.suspect ?? []) li.append(el('p', s, { className: 'warn-text small', role: 'note' }));
    const text = unitsText({ units: p.info.units, units_source: p.info.unitsSource }, !!p.units);
    const units = el('p', p.info.unitsAssumed ? t('nest.units-assumed', { units: p.info.units }) : t('nest.units', { units: text }),
      { className: 'small' });
    units.dataset.units = p.info.units;
    if (p.info.unitsAssumed) units.classList.add('warn-text');
    units.append(' ', unitSwitch({
      current: p.info.units, chosen: p.units || null, svg: /^px/.test(p.info.units),
      onPick: (unit) => {
        p.units = unit;
        hooks.reread(p);
      },
    }));
    li.append(units);
  }
  const several = rows.length > 1 && p.each?.length === rows.length;
  const items = several ? rows.map((row, i) => partItem(p, i, row, hooks)) : [];
  // A file of several parts: these fields set every part's (the greyed ones keep their 0 copies).
  const set = several ? (key, value) => {
    rows.forEach((row, i) => {
      if (!(key === 'quantity' && row.not_nestable)) p.each[i][key] = value;
      items[i].refresh();
    });
  } : undefined;
  const f = choiceFields(p, id, hooks, { label: p.name, zero: false, set });
  if (several) li.append(el('p', t('nest.set-all'), { className: 'small set-all' }));
  const remove = el('button', t('nest.remove'), { type: 'button', className: 'small-button' });
  remove.setAttribute('aria-label', `${t('nest.remove')} ${p.name}`);
  remove.addEventListener('click', () => hooks.remove(p));
  f.grid.append(remove);
  li.append(f.grid, f.bad, f.help);
  if (several) li.append(el('ul', '', { className: 'part-items' }));
  if (several) li.lastChild.append(...items.map((x) => x.li));
  return li;
}
