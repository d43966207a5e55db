// kerfcam number fields (issue 13 §5): numbers typed the local way. `1,5` and `1.5` both mean 1.5 in
// both languages (the page never groups thousands, so a single comma or point is always the decimal
// sign). Each field has its own range and step; a value outside the range marks its field with the
// field's label and range in the page's language, and the page keeps its last good preview and
// program. The fields are text inputs (inputmode="decimal": a number keypad that has a comma on phones)
// with role="spinbutton": ArrowUp/ArrowDown step by the field's step, PageUp/PageDown by ten steps,
// always onto the step's grid (2000 → 2100 → 2000, never 2001 → 1801).

import { fmtNumber, getLang, onLangChange, register, t } from './i18n.js';

register({
  en: {
    'numbers.range': '{label}: enter a number from {min} to {max}{unit}.',
    'numbers.range-whole': '{label}: enter a whole number from {min} to {max}{unit}.',
    'numbers.range-above': '{label}: enter a number greater than {min} and up to {max}{unit}.',
    'numbers.problems': 'Not used until corrected (the preview and program shown are from the last valid values):',
  },
  'pt-BR': {
    'numbers.range': '{label}: informe um número de {min} a {max}{unit}.',
    'numbers.range-whole': '{label}: informe um número inteiro de {min} a {max}{unit}.',
    'numbers.range-above': '{label}: informe um número maior que {min} e até {max}{unit}.',
    'numbers.problems': 'Não usado até ser corrigido (a visualização e o programa mostrados são dos últimos valores válidos):',
  },
});

/**
 * The number fields: settings key → { id (element id), label (text key), min, max, step, unit,
 * above (true: min itself is not allowed), whole (true: whole numbers only), follows (optional: the other fields' values by key → the
 * range's parts that depend on them, as { min, max, above }) }. The ranges are the engine's
 * (src/settings.rs), so a value the page accepts is never refused by the engine with an internal field
 * name; a range that follows another field is checked with that field's value as it is now, whichever
 * of the two was typed first.
 */
export const FIELDS = {
  kerf: { id: 'kerf', label: 'settings.kerf', min: 0, max: 100, step: 0.1, unit: 'mm' },
  tolerance: { id: 'tolerance', label: 'settings.tolerance', min: 0.000001, max: 1, step: 0.001, unit: 'mm' },
  feed: { id: 'feed', label: 'settings.feed', min: 1, max: 1000000, step: 100, unit: 'mm/min' },
  rapid: { id: 'rapid', label: 'settings.rapid', min: 1, max: 1000000, step: 1000, unit: 'mm/min' },
  pierce_delay: { id: 'pierce-delay', label: 'settings.pierce-delay', min: 0, max: 60, step: 0.1, unit: 's' },
  lead_outer: { id: 'lead-outer', label: 'plan.lead-outer', min: 0, max: 1000, step: 0.5, unit: 'mm' },
  lead_hole: { id: 'lead-hole', label: 'plan.lead-hole', min: 0, max: 1000, step: 0.5, unit: 'mm' },
  overcut: { id: 'overcut', label: 'plan.overcut', min: 0, max: 1000, step: 0.5, unit: 'mm' },
  max_link: { id: 'max-link', label: 'plan.max-link', min: 0, max: 100000, step: 5, unit: 'mm' },
};

const NUMBER = /^[+-]?(\d+([.,]\d*)?|[.,]\d+)([eE][+-]?\d+)?$/;

/** A number as typed by a person: `1,5`, `1.5`, ` 2000 `, `-3`, `.5`; NaN for anything else. */
export function parseNumber(text) {
  const s = String(text ?? '').replace(/[\s\u00a0\u202f]/g, '');
  if (!NUMBER.test(s)) return NaN;
  return Number(s.replace(',', '.'));
}

/** Decimals of a step (0.1 → 1, 0.001 → 3, 100 → 0). */
const decimalsOf = (step) => Math.max(0, Math.ceil(-Math.log10(step) - 1e-9));

/** `v` written for the field in the page's language, with no more decimals than needed (up to 6). */
export function formatValue(v, digits = 6) {
  const s = fmtNumber(v, digits);
  const sep = getLang() === 'pt-BR' ? ',' : '.';
  return s.includes(sep) ? s.replace(/0+$/, '').replace(new RegExp(`\\${sep}$`), '') : s;
}

/**
 * One step up (dir 1) or down (-1), `times` steps, from `v`: onto the step's grid first (2001 up → 2100,
 * down → 2000), clamped to the range. Exact in decimal (no 0.30000000000000004).
 */
export function stepValue(v, field, dir, times = 1) {
  const { step, min, max } = field;
  const d = decimalsOf(step);
  const k = v / step;
  const near = Math.round(k);
  const onGrid = Math.abs(k - near) < 1e-9;
  let n = onGrid ? near + dir * times : (dir > 0 ? Math.ceil(k) : Math.floor(k)) + dir * (times - 1);
  let next = Number((n * step).toFixed(d));
  if (!Number.isFinite(v)) next = dir > 0 ? min : max;
  if (next < min) next = min;
  if (next > max) next = max;
  return next;
}

/** The field's problem with `v`, as a sentence in the page's language, or '' when `v` is valid. */
function problemOf(field, v) {
  const ok = Number.isFinite(v) && v <= field.max && (field.above ? v > field.min : v >= field.min);
  if (ok && (!field.whole || Number.isInteger(v))) return '';
  return t(field.above ? 'numbers.range-above' : field.whole ? 'numbers.range-whole' : 'numbers.range', {
    label: t(field.label), min: formatValue(field.min), max: formatValue(field.max), unit: field.unit ? ` ${field.unit}` : '',
  });
}

export class NumberFields {
  /**
   * `onStep()` is called after an arrow key stepped a field (the page re-runs); `forms`: where each
   * form's problem list goes (after the form).
   */
  constructor(forms) {
    this.inputs = Object.fromEntries(Object.entries(FIELDS).map(([key, f]) => [key, document.getElementById(f.id)]));
    this.boxes = new Map(); // form → its problem list (a <div role=alert> after it)
    for (const form of forms) {
      const box = document.createElement('div');
      box.className = 'field-problems small';
      box.id = `${form.id}-problems`;
      box.setAttribute('role', 'alert');
      box.hidden = true;
      form.after(box);
      this.boxes.set(form, box);
    }
    for (const [key, input] of Object.entries(this.inputs)) {
      const f = FIELDS[key];
      input.setAttribute('role', 'spinbutton');
      input.setAttribute('aria-valuemin', String(f.min));
      input.setAttribute('aria-valuemax', String(f.max));
      input.addEventListener('keydown', (e) => this.key(e, key));
      // Keys that cannot be part of a number type nothing (as in a number field); pasted text is checked.
      input.addEventListener('beforeinput', (e) => {
        if (e.inputType === 'insertText' && e.data && /[^0-9.,+\-eE]/.test(e.data)) e.preventDefault();
      });
      this.addStepper(input, key);
    }
    this.problems = [];
    onLangChange(() => this.relocalise());
  }

  key(e, key) {
    const steps = { ArrowUp: [1, 1], ArrowDown: [-1, 1], PageUp: [1, 10], PageDown: [-1, 10] }[e.key];
    if (!steps || e.altKey || e.ctrlKey || e.metaKey) return;
    e.preventDefault();
    this.step(key, ...steps);
  }

  /** Steps the field; the page re-runs (and keeps the value) once the steps stop for a moment. */
  step(key, dir, times = 1) {
    const input = this.inputs[key];
    input.value = formatValue(stepValue(parseNumber(input.value), this.rangeOf(key, this.values()), dir, times));
    input.dispatchEvent(new Event('input', { bubbles: true }));
    clearTimeout(this.committing);
    this.committing = setTimeout(() => input.dispatchEvent(new Event('change', { bubbles: true })), 400);
  }

  /**
   * Mouse users' spinner: ▲ and ▼ inside the field's right edge (the text field has none of its own).
   * Hidden from assistive technology and out of the Tab order: the arrow keys do the same in the field.
   */
  addStepper(input, key) {
    const wrap = document.createElement('span');
    wrap.className = 'number-field';
    input.before(wrap);
    const stepper = document.createElement('span');
    stepper.className = 'stepper';
    stepper.setAttribute('aria-hidden', 'true');
    for (const [text, dir] of [['▲', 1], ['▼', -1]]) {
      const b = document.createElement('span');
      b.textContent = text;
      b.dataset.dir = String(dir);
      b.addEventListener('pointerdown', (e) => {
        e.preventDefault(); // the field keeps (or takes) the focus, not the arrow
        input.focus();
        this.step(key, dir);
      });
      stepper.append(b);
    }
    wrap.append(input, stepper);
  }

  /**
   * The engine's defaults (`defaults_json`, by settings key): each field's default value, which it shows
   * unless a kept or typed value is there already, and which "Reset to defaults" puts back.
   */
  setDefaults(defaults) {
    for (const [key, input] of Object.entries(this.inputs)) {
      const v = defaults?.[key];
      if (!Number.isFinite(v)) continue;
      const kept = input.value !== input.defaultValue; // restored or typed: stays
      input.defaultValue = formatValue(v);
      if (!kept) input.value = input.defaultValue;
    }
  }

  /** The field `key` with its range as the other fields' values `values` (by key) make it. */
  rangeOf(key, values) {
    const f = FIELDS[key];
    if (!f.follows) return f;
    const own = f.follows(values);
    return { ...f, ...Object.fromEntries(Object.entries(own).filter(([, v]) => v !== undefined && !Number.isNaN(v))) };
  }

  /** Every field's value, by key (NaN when it is not a number). */
  values() {
    return Object.fromEntries(Object.entries(this.inputs).map(([key, input]) => [key, parseNumber(input.value)]));
  }

  /** The value of the field `key` (NaN when it is not a number). */
  value(key) {
    return parseNumber(this.inputs[key].value);
  }

  /**
   * Every field's value; marks the invalid ones (aria-invalid, the form's problem list). Returns
   * { values, problems: [text] }.
   */
  read() {
    const values = this.values();
    const problems = [];
    const byForm = new Map([...this.boxes.keys()].map((f) => [f, []]));
    for (const [key, input] of Object.entries(this.inputs)) {
      const v = values[key];
      const range = this.rangeOf(key, values);
      const problem = problemOf(range, v);
      input.setAttribute('aria-valuemin', String(range.min));
      input.setAttribute('aria-valuemax', String(range.max));
      input.setAttribute('aria-invalid', String(!!problem));
      input.classList.toggle('invalid', !!problem);
      if (problem) {
        problems.push(problem);
        input.removeAttribute('aria-valuenow');
        byForm.get(input.form)?.push([input, problem]);
      } else {
        input.setAttribute('aria-valuenow', String(v));
      }
    }
    for (const [form, list] of byForm) {
      const box = this.boxes.get(form);
      box.hidden = !list.length;
      box.replaceChildren(...(list.length ? [Object.assign(document.createElement('p'), { textContent: t('numbers.problems') })] : []),
        ...list.map(([input, text]) => {
          const p = document.createElement('p');
          p.id = `${input.id}-problem`;
          p.textContent = text;
          return p;
        }));
      for (const input of form.querySelectorAll('input')) {
        if (input.getAttribute('aria-invalid') === 'true') input.setAttribute('aria-describedby', `${input.id}-problem`);
        else if (input.getAttribute('aria-describedby')?.endsWith('-problem')) input.removeAttribute('aria-describedby');
      }
    }
    this.problems = problems;
    return { values, problems };
  }

  /** After a language switch: valid values written with the language's decimal sign, problems re-said. */
  relocalise() {
    for (const input of Object.values(this.inputs)) {
      const v = parseNumber(input.value);
      if (Number.isFinite(v) && /[.,]/.test(input.value)) input.value = formatValue(v);
    }
    if (this.problems.length) this.read();
  }
}
