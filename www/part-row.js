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
  },
  'pt-BR': {
    'nest.grain': 'Travar o sentido do grão', 'nest.grain-help': 'mantém o sentido do grão: gira só 180°',
  },
});

/** The rotations a grain-locked part keeps of a choice: none stays none, any other turns by 180° only. */
export const grainRotations = (rotations) => (rotations === 'none' ? 'none' : '180');

/**
 * The row of part file `p` ({ id, name, quantity, rotations, mirror, grain, units, info, error }).
 * `hooks`: { quantityOk(text), quantityBad(p), changed(), remove(p), reread(p) (read again in p.units) }.
 */
export function partRow(p, hooks) {
  const li = el('li', '', { className: 'part' });
  li.dataset.name = p.name;
  const id = (s) => `part-${p.id}-${s}`;
  const head = el('p', '', { className: 'part-name' });
  head.append(el('strong', p.name));
  li.append(head);
  if (p.error) li.append(el('p', p.error, { className: 'error-text small', role: 'alert' }));
  else if (!p.info) li.append(el('p', t('nest.reading', { name: p.name }), { className: 'muted small' }));
  else {
    const names = p.info.parts;
    li.append(el('p', names.length ? t('nest.part-names', { n: fmtNumber(names.length), count: names.length, names: names.join(', ') })
      : t('nest.no-nestable'), { className: names.length ? 'muted small' : 'error-text small' }));
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
  const grid = el('div', '', { className: 'part-fields' });
  const qty = el('input', '', { id: id('qty'), type: 'text', inputMode: 'numeric', value: p.quantity, autocomplete: 'off', className: 'qty' });
  const bad = el('p', '', { id: id('qty-error'), className: 'error-text small' });
  const check = () => {
    const ok = hooks.quantityOk(qty.value);
    qty.setAttribute('aria-invalid', String(!ok));
    bad.textContent = ok ? '' : hooks.quantityBad(p);
  };
  qty.setAttribute('aria-describedby', bad.id);
  qty.addEventListener('input', () => {
    p.quantity = qty.value;
    check();
    hooks.changed();
  });
  const rot = el('select', '', { id: id('rot') });
  const fillRotations = () => {
    if (p.grain) p.rotations = grainRotations(p.rotations);
    const offered = p.grain ? ['none', '180'] : ['none', '180', '90', 'free'];
    rot.replaceChildren(...offered.map((r) => el('option', t(`nest.rot.${r}`), { value: r })));
    rot.value = p.rotations;
  };
  fillRotations();
  rot.addEventListener('change', () => {
    p.rotations = rot.value;
    hooks.changed();
  });
  const check2 = (key, on, set) => {
    const box = el('input', '', { id: id(key), type: 'checkbox', checked: on });
    box.addEventListener('change', () => set(box.checked));
    const label = el('label', '', { htmlFor: box.id, className: 'check' });
    label.append(box, ' ', t(`nest.${key}`));
    return label;
  };
  const mirror = check2('mirror', p.mirror, (on) => {
    p.mirror = on;
    hooks.changed();
  });
  const help = el('p', p.grain ? t('nest.grain-help') : '', { id: id('grain-help'), className: 'muted small' });
  const grain = check2('grain', !!p.grain, (on) => {
    p.grain = on;
    help.textContent = on ? t('nest.grain-help') : '';
    fillRotations();
    hooks.changed();
  });
  grain.title = t('nest.grain-help');
  grain.querySelector('input').setAttribute('aria-describedby', id('grain-help'));
  const remove = el('button', t('nest.remove'), { type: 'button', className: 'small-button' });
  remove.setAttribute('aria-label', `${t('nest.remove')} ${p.name}`);
  remove.addEventListener('click', () => hooks.remove(p));
  grid.append(el('label', t('nest.quantity'), { htmlFor: qty.id }), qty,
    el('label', t('nest.rotations'), { htmlFor: rot.id }), rot, mirror, grain, remove);
  li.append(grid, bad, help);
  check();
  return li;
}
