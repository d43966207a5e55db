// kerfcam page, Sheet mode (issue 16 item 6, "a list"): more sheet sizes after the first. A shop has
// full sheets and a few smaller ones (offcuts kept square, a second stock size); the nest fills the
// sheets of the size above first, then each size listed here in its order, as `kerfcam nest --sheet
// WxH:N --sheet WxH:N` does. Each row is W × H, how many and, optionally, the cost of one sheet (with a
// cost for every size, the nest takes the cheapest sheets that hold every copy, as `--sheet WxH:N:COST`
// does; issue 44 item 3); the engine gets the whole list (`sheet_list`), and each sheet of the nest is
// drawn, cropped and cut at its own size.

import { el } from './app.js';
import { register, t } from './i18n.js';
import { formatValue, parseNumber } from './numbers.js';

register({
  en: {
    'nest.more-sizes': 'More sheet sizes',
    'nest.more-sizes-help': 'Filled after the sheets above, in this order, when those are full; with a cost for every size, the cheapest sheets that hold every copy.',
    'nest.add-size': 'Add a sheet size', 'nest.remove-size': 'Remove',
    'nest.size-row': 'Size {n}', 'nest.size-count': 'Sheets', 'nest.width-mm': 'Width, mm', 'nest.height-mm': 'Height, mm',
    'nest.size-cost': 'Cost, {cur}', 'nest.size-cost-plain': 'Cost',
  },
  'pt-BR': {
    'nest.more-sizes': 'Mais tamanhos de chapa',
    'nest.more-sizes-help': 'Usados depois das chapas acima, nesta ordem, quando aquelas estiverem cheias; com um custo para cada tamanho, as chapas mais baratas que comportam todas as cópias.',
    'nest.add-size': 'Adicionar um tamanho de chapa', 'nest.remove-size': 'Remover',
    'nest.size-row': 'Tamanho {n}', 'nest.size-count': 'Chapas', 'nest.width-mm': 'Largura, mm', 'nest.height-mm': 'Altura, mm',
    'nest.size-cost': 'Custo, {cur}', 'nest.size-cost-plain': 'Custo',
  },
});

export class SheetSizes {
  /**
   * `list`: the <ul> the rows go in (inside the sheet's form, whose input listener hears the edits);
   * `add`: the button that adds one; `changed()`: a size was added or removed; `currency()`: the Cost
   * panel's currency ('' when none is set), which the costs are in.
   */
  constructor(list, add, changed, currency = () => '') {
    // rows: [{ id, inputs: { width, height, count, cost } }] in their order; the panel reads and checks them.
    Object.assign(this, { list, add, changed, currency, rows: [], nextId: 1, disabled: false });
    add.addEventListener('click', () => {
      this.push({ width: '', height: '', count: '1', cost: '' });
      this.rows.at(-1).inputs.width.focus();
      changed();
    });
    this.render();
  }

  /** A row of text fields (what was typed, kept as typed). */
  push(values) {
    const id = this.nextId++;
    const inputs = {};
    for (const key of ['width', 'height', 'count', 'cost']) {
      inputs[key] = el('input', '', {
        id: `sheet-size-${id}-${key}`, type: 'text', inputMode: key === 'count' ? 'numeric' : 'decimal',
        value: values[key] ?? '', autocomplete: 'off', spellcheck: false, className: key,
      });
    }
    this.rows.push({ id, inputs });
    this.render();
  }

  /** Rows from numbers (a nest file's `sheet_list`, its first size left out: that is the fields above). */
  set(sizes) {
    this.rows = [];
    for (const s of sizes) {
      const cost = Number.isFinite(s.cost) ? formatValue(s.cost) : '';
      this.push({ width: formatValue(s.width, 3), height: formatValue(s.height, 3), count: String(s.count), cost });
    }
    this.render();
  }

  /** A sheet drawn in a DXF has its own outline: no sizes apply. */
  setDisabled(on) {
    this.disabled = on;
    this.render();
  }

  /** Numbers typed again with the language's decimal sign. */
  relocalise() {
    for (const r of this.rows) {
      for (const key of ['width', 'height', 'cost']) {
        const v = parseNumber(r.inputs[key].value);
        if (Number.isFinite(v)) r.inputs[key].value = formatValue(v, key === 'cost' ? 6 : 3);
      }
    }
    this.render();
  }

  render() {
    this.add.disabled = this.disabled;
    this.list.replaceChildren(...this.rows.map((r, i) => {
      const li = el('li', '', { className: 'sheet-size' });
      li.setAttribute('role', 'group');
      li.setAttribute('aria-label', t('nest.size-row', { n: String(i + 2) }));
      const field = (key, label) => {
        const input = r.inputs[key];
        input.disabled = this.disabled;
        const wrap = el('label', label, { htmlFor: input.id });
        wrap.append(input);
        return wrap;
      };
      const cur = this.currency();
      const remove = el('button', t('nest.remove-size'), { type: 'button', className: 'small-button', disabled: this.disabled });
      remove.setAttribute('aria-label', `${t('nest.remove-size')}: ${t('nest.size-row', { n: String(i + 2) })}`);
      remove.addEventListener('click', () => {
        this.rows = this.rows.filter((x) => x !== r);
        this.render();
        this.changed();
        this.add.focus();
      });
      li.append(field('width', t('nest.width-mm')), field('height', t('nest.height-mm')), field('count', t('nest.size-count')),
        field('cost', cur ? t('nest.size-cost', { cur }) : t('nest.size-cost-plain')), remove);
      return li;
    }));
  }
}

/**
 * Sheet `k`'s size under the nest's settings: the k-th of `sheet_list` (past the last, the last), or
 * the one W × H; NaN for a strip or a sheet drawn in a DXF.
 */
export function sheetSize(settings, k) {
  const list = settings.sheet_list;
  if (Array.isArray(list) && list.length) {
    let left = k;
    for (const s of list) {
      if (left < s.count) return { width: s.width, height: s.height };
      left -= s.count;
    }
    const last = list.at(-1);
    return { width: last.width, height: last.height };
  }
  return { width: settings.sheet_width ?? NaN, height: settings.sheet_height ?? NaN };
}
