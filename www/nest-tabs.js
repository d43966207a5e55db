// kerfcam page, Sheet mode (issue 18 item 3): the nest's sheets as tabs above the nest view. Each tab
// names its sheet with its utilisation (paper 001's formula, as the engine computes it per sheet) once
// the nest is done, or with the copies it holds so far while the search runs; the job's utilisation
// is beside them. A tab is picked with the pointer or the keyboard (Left / Right / Home / End, the
// WAI-ARIA tabs pattern: one tab in the Tab order, the arrows move among them).

import { el } from './app.js';
import { fmtNumber, register, t } from './i18n.js';

register({
  en: {
    'tabs.label': 'Sheets of the nest', 'tabs.sheet': 'Sheet {k} · {u} %',
    'tabs.sheet-live': { one: 'Sheet {k} · {n} copy', other: 'Sheet {k} · {n} copies' },
    'tabs.job': { one: 'Job: {u} % used on {n} sheet', other: 'Job: {u} % used on {n} sheets' },
  },
  'pt-BR': {
    'tabs.label': 'Chapas do encaixe', 'tabs.sheet': 'Chapa {k} · {u} %',
    'tabs.sheet-live': { one: 'Chapa {k} · {n} cópia', other: 'Chapa {k} · {n} cópias' },
    'tabs.job': { one: 'Trabalho: {u} % aproveitado em {n} chapa', other: 'Trabalho: {u} % aproveitado em {n} chapas' },
  },
});

export class SheetTabs {
  /** `box`: the tab strip; `panel`: the element the tabs show (the nest drawing); `onPick(k)`. */
  constructor(box, panel, onPick) {
    Object.assign(this, { box, panel, onPick });
    this.list = el('div', '', { className: 'nest-tab-list' });
    this.list.setAttribute('role', 'tablist');
    this.list.setAttribute('aria-label', t('tabs.label')); // named again by show() in the language of the day
    this.job = el('span', '', { className: 'small muted nest-tab-job' });
    box.replaceChildren(this.list, this.job);
    panel.setAttribute('role', 'tabpanel');
    this.list.addEventListener('keydown', (e) => this.key(e));
  }

  /**
   * Shows one tab per sheet. `sheets`: [{ utilisation }] (a finished nest) or [{ copies }] (live);
   * `k`: the sheet shown; `job`: the job's utilisation (0..1) or null.
   */
  show(sheets, k, job = null) {
    this.list.setAttribute('aria-label', t('tabs.label'));
    // The tabs already there are updated in place, not drawn again: while the search runs this is called
    // on every better nest, and a tab replaced between a press and its release takes no click.
    const tabs = [...this.list.querySelectorAll('[role="tab"]')].slice(0, sheets.length);
    for (let i = tabs.length; i < sheets.length; i++) {
      const b = el('button', '', { type: 'button', className: 'nest-tab', id: `nest-tab-${i}` });
      b.setAttribute('role', 'tab');
      b.dataset.sheet = String(i);
      b.addEventListener('click', () => this.pick(i));
      tabs.push(b);
    }
    sheets.forEach((s, i) => {
      const b = tabs[i];
      b.textContent = Number.isFinite(s.utilisation)
        ? t('tabs.sheet', { k: fmtNumber(i + 1), u: fmtNumber(100 * s.utilisation, 1) })
        : t('tabs.sheet-live', { k: fmtNumber(i + 1), n: fmtNumber(s.copies ?? 0), count: s.copies ?? 0 });
      b.setAttribute('aria-selected', String(i === k));
      b.tabIndex = i === k ? 0 : -1;
      if (Number.isFinite(s.utilisation)) b.dataset.utilisation = String(s.utilisation);
      else delete b.dataset.utilisation;
    });
    if (tabs.some((b, i) => this.list.children[i] !== b) || this.list.children.length !== tabs.length) this.list.replaceChildren(...tabs);
    this.list.dataset.count = String(sheets.length);
    if (tabs[k]) this.panel.setAttribute('aria-labelledby', tabs[k].id);
    this.job.textContent = Number.isFinite(job)
      ? t('tabs.job', { u: fmtNumber(100 * job, 1), n: fmtNumber(sheets.length), count: sheets.length }) : '';
    this.job.dataset.utilisation = Number.isFinite(job) ? String(job) : '';
  }

  pick(i) {
    const tabs = this.list.querySelectorAll('[role="tab"]');
    if (!tabs[i]) return;
    this.onPick(i);
    this.list.querySelector(`#nest-tab-${i}`)?.focus(); // onPick may have drawn the strip again
  }

  key(e) {
    const tabs = [...this.list.querySelectorAll('[role="tab"]')];
    const at = tabs.indexOf(document.activeElement);
    if (at < 0 || !tabs.length) return;
    const n = tabs.length;
    const to = { ArrowRight: (at + 1) % n, ArrowLeft: (at + n - 1) % n, Home: 0, End: n - 1 }[e.key];
    if (to === undefined) return;
    e.preventDefault();
    this.pick(to);
  }
}
