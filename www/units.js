// kerfcam units in view (issue 13 §2): the drawing's overall size in mm and inches, and the unit a file
// is read in as a control beside the "units assumed" warning (mm / inch / cm). The choice re-runs the
// job and is kept with the file (batch.js, file-store.js), so the file opens in it next time too.

import { fmtNumber, register, t } from './i18n.js';

register({
  en: {
    'units.switch': 'Read this file in', 'units.switch.in': 'inch',
    'units.switch.px': 'px at 96/in', 'units.switch.px72': 'px at 72/in',
    'units.switch.pressed': '{unit} (chosen for this file)',
    'units.chosen': 'chosen for this file',
    'size.value': '{w} × {h} mm ({wi} × {hi} in)',
    'extent.value': 'X {x0} … {x1}, Y {y0} … {y1} mm',
  },
  'pt-BR': {
    'units.switch': 'Ler este arquivo em', 'units.switch.in': 'polegada',
    'units.switch.px': 'px a 96/pol', 'units.switch.px72': 'px a 72/pol',
    'units.switch.pressed': '{unit} (escolhido para este arquivo)',
    'units.chosen': 'escolhido para este arquivo',
    'size.value': '{w} × {h} mm ({wi} × {hi} pol)',
    'extent.value': 'X {x0} … {x1}; Y {y0} … {y1} mm',
  },
});

/** "X 0.0 … 50.0, Y 0.0 … 30.0 mm": where the program moves (report.extent); null without one. */
export function extentText(e) {
  const [x0, y0] = Array.isArray(e?.min) ? e.min : [];
  const [x1, y1] = Array.isArray(e?.max) ? e.max : [];
  if (![x0, y0, x1, y1].every(Number.isFinite)) return null;
  const f = (v) => fmtNumber(v, 1);
  return t('extent.value', { x0: f(x0), x1: f(x1), y0: f(y0), y1: f(y1) });
}

/** The units offered beside the warning: the engine's unit names. */
export const UNIT_CHOICES = ['mm', 'in', 'cm'];
/** For an SVG (issue 41 §2): its px at 96 per inch (CSS, Inkscape) or at 72 (Illustrator's legacy). */
export const SVG_UNIT_CHOICES = ['mm', 'in', 'px', 'px72'];

/** "123.4 × 56.7 mm (4.86 × 2.23 in)"; null when the report has no size. */
export function sizeText(size) {
  const w = Number(size?.w);
  const h = Number(size?.h);
  if (!size || !Number.isFinite(w) || !Number.isFinite(h)) return null;
  return t('size.value', { w: fmtNumber(w, 1), h: fmtNumber(h, 1), wi: fmtNumber(w / 25.4, 2), hi: fmtNumber(h / 25.4, 2) });
}

/**
 * The unit switch: one button per unit, the one in use pressed. `current`: the unit the file is read in
 * now; `chosen`: the unit chosen for this file (or null); `onPick(unit)` re-runs with it; `svg`: the
 * file is an SVG (px at 96 and at 72 per inch offered).
 */
export function unitSwitch({ current, chosen, onPick, svg = false }) {
  const group = document.createElement('span');
  group.className = 'unit-switch';
  group.setAttribute('role', 'group');
  group.setAttribute('aria-label', t('units.switch'));
  group.append(Object.assign(document.createElement('span'), { className: 'small muted', textContent: `${t('units.switch')}:` }));
  for (const unit of svg ? SVG_UNIT_CHOICES : UNIT_CHOICES) {
    const b = document.createElement('button');
    b.type = 'button';
    b.className = 'small-button';
    b.dataset.unit = unit; // a hook for tests
    b.textContent = unit === 'in' ? t('units.switch.in') : unit === 'px' ? t('units.switch.px') : unit === 'px72' ? t('units.switch.px72') : unit;
    const pressed = (chosen ?? current) === unit;
    b.setAttribute('aria-pressed', String(pressed));
    b.addEventListener('click', () => {
      if (chosen !== unit) onPick(unit);
    });
    group.append(' ', b);
  }
  return group;
}
