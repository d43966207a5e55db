// kerfcam page, Sheet mode (issue 42 §2): labels on the nested parts. The operator turns them on, picks what
// they say (the part's name and copy, BRACKET#3, or a short code, A3), their largest and smallest height and
// their margin to the part's edges and holes, and whether the cut scribes them (marks before the cuts, the
// post's mark codes). The engine places them (label::label_nest) and answers their strokes with the nest's
// state; the nest view draws them. A value out of range is said at its field and the last good labels kept.

import { $ } from './app.js';
import { fmtNumber, register, t } from './i18n.js';
import { parseNumber } from './numbers.js';

register({
  en: {
    'labels.on': 'Labels on the parts', 'labels.naming': 'Label text', 'labels.name': 'Part name and copy (BRACKET#3)',
    'labels.code': 'Short code (A3)', 'labels.height-max': 'Largest label height', 'labels.height-min': 'Smallest label height',
    'labels.margin': 'Label margin', 'labels.mark': 'Scribe the labels (marks before the cuts)',
    'labels.bad': '{label}: type a number from {min} to {max} mm.',
    'labels.min-over-max': 'The smallest label height is more than the largest.',
    'labels.left-out': { one: '{n} copy has no room for a label.', other: '{n} copies have no room for a label.' },
    'labels.count': { one: '{n} label placed.', other: '{n} labels placed.' },
  },
  'pt-BR': {
    'labels.on': 'Etiquetas nas peças', 'labels.naming': 'Texto da etiqueta', 'labels.name': 'Nome da peça e cópia (SUPORTE#3)',
    'labels.code': 'Código curto (A3)', 'labels.height-max': 'Altura máxima da etiqueta', 'labels.height-min': 'Altura mínima da etiqueta',
    'labels.margin': 'Margem da etiqueta', 'labels.mark': 'Riscar as etiquetas (marcação antes dos cortes)',
    'labels.bad': '{label}: informe um número de {min} a {max} mm.',
    'labels.min-over-max': 'A altura mínima da etiqueta é maior que a máxima.',
    'labels.left-out': { one: '{n} cópia sem espaço para etiqueta.', other: '{n} cópias sem espaço para etiqueta.' },
    'labels.count': { one: '{n} etiqueta colocada.', other: '{n} etiquetas colocadas.' },
  },
});

// The number fields: key → element id, label, range (mm).
const FIELDS = {
  height_max: { id: 'label-height-max', label: 'labels.height-max', min: 0.5, max: 1000 },
  height_min: { id: 'label-height-min', label: 'labels.height-min', min: 0.5, max: 1000 },
  margin: { id: 'label-margin', label: 'labels.margin', min: 0, max: 1000 },
};

export class LabelsPanel {
  /** `hooks`: { changed() (a good setting to send to the engine) }. */
  constructor(hooks) {
    this.hooks = hooks;
    this.ui = { on: $('labels-on'), naming: $('labels-naming'), mark: $('labels-mark'), message: $('labels-message'), figures: $('labels-figures') };
    this.good = null; // the last good setting
    for (const input of [this.ui.on, this.ui.naming, this.ui.mark, ...Object.values(FIELDS).map((f) => $(f.id))]) {
      input.addEventListener('change', () => {
        if (this.spec()) this.hooks.changed();
      });
    }
  }

  /** The labels as set ({on, naming, height_max, height_min, margin, mark}), or the last good ones when a field is bad (said). */
  spec() {
    const problems = [];
    const out = { on: this.ui.on.checked, naming: this.ui.naming.value === 'code' ? 'code' : 'name', mark: this.ui.mark.checked };
    for (const [key, f] of Object.entries(FIELDS)) {
      const input = $(f.id);
      const v = parseNumber(input.value);
      const ok = Number.isFinite(v) && v >= f.min && v <= f.max;
      input.setAttribute('aria-invalid', String(!ok));
      if (!ok) problems.push(t('labels.bad', { label: t(f.label), min: fmtNumber(f.min, f.min % 1 ? 1 : 0), max: fmtNumber(f.max) }));
      out[key] = v;
    }
    if (!problems.length && out.height_min > out.height_max) {
      $(FIELDS.height_min.id).setAttribute('aria-invalid', 'true');
      problems.push(t('labels.min-over-max'));
    }
    this.say(problems.join(' '));
    if (problems.length) return this.good;
    this.good = out;
    return out;
  }

  say(text) {
    this.ui.message.textContent = text;
    this.ui.message.hidden = !text;
  }

  /** The labels of a nest's state shown as figures: how many placed, how many copies have no room. */
  show(state) {
    const l = state?.labels;
    if (!l) {
      this.ui.figures.textContent = '';
      return;
    }
    const n = l.labels.length;
    const left = l.left_out.length;
    this.ui.figures.textContent = [t('labels.count', { n: fmtNumber(n), count: n }),
      left ? t('labels.left-out', { n: fmtNumber(left), count: left }) : '', ...(l.warnings || [])].filter(Boolean).join(' ');
  }
}
