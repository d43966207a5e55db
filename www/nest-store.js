// kerfcam page, Sheet mode (issue 18 item 8): the nests kept in this browser. Save nest keeps the nest
// file in IndexedDB (file-store.js, beside the dropped drawings) as well as downloading it; this list
// shows the kept ones, newest first, each with Open (the same path as opening the downloaded file:
// nest-file.js) and Forget. Works where IndexedDB does, file:// included; where it does not (some
// private modes) the list says so and Save nest still downloads. Names are data: textContent only.

import { $, el } from './app.js';
import { forgetNest, keepNest, loadNests } from './file-store.js';
import { fmtNumber, getLang, onLangChange, register, t } from './i18n.js';

register({
  en: {
    'kept.heading': 'Nests kept in this browser', 'kept.none': 'None yet: Save nest keeps one here.',
    'kept.line': { one: '{name}: {n} copy on {sheets} sheet(s), saved {when}', other: '{name}: {n} copies on {sheets} sheet(s), saved {when}' },
    'kept.open': 'Open', 'kept.forget': 'Forget', 'kept.not-kept': 'This browser keeps no files here (private mode?): the nest was only downloaded.',
  },
  'pt-BR': {
    'kept.heading': 'Encaixes guardados neste navegador', 'kept.none': 'Nenhum ainda: Salvar encaixe guarda um aqui.',
    'kept.line': { one: '{name}: {n} cópia em {sheets} chapa(s), salvo {when}', other: '{name}: {n} cópias em {sheets} chapa(s), salvo {when}' },
    'kept.open': 'Abrir', 'kept.forget': 'Esquecer', 'kept.not-kept': 'Este navegador não guarda arquivos aqui (modo privado?): o encaixe só foi baixado.',
  },
});

export class KeptNests {
  /** `open(file)`: opens a nest file (NestFile.open); `say(text)`: the nest's message line. */
  constructor({ open, say }) {
    Object.assign(this, { open, say });
    this.list = $('nest-kept');
    this.kept = [];
    onLangChange(() => this.render());
    this.refresh();
  }

  async refresh() {
    this.kept = await loadNests();
    this.render();
  }

  /** Keeps a nest file (`blob`, its JSON) under `name`; `copies`, `sheets`: for its line in the list. */
  async keep(blob, { name, copies, sheets }) {
    const saved = Date.now();
    const ok = await keepNest({ id: `${saved}-${Math.random().toString(36).slice(2, 8)}`, name, saved, copies, sheets, blob });
    if (!ok) this.say(t('kept.not-kept'));
    await this.refresh();
    return ok;
  }

  render() {
    if (!this.kept.length) {
      this.list.replaceChildren(el('li', t('kept.none'), { className: 'muted small' }));
      this.list.dataset.count = '0';
      return;
    }
    const when = new Intl.DateTimeFormat(getLang(), { dateStyle: 'short', timeStyle: 'short' });
    this.list.replaceChildren(...this.kept.map((r) => {
      const li = el('li', '', { className: 'small kept-nest' });
      li.dataset.id = r.id;
      const line = el('span', t('kept.line', {
        name: r.name, n: fmtNumber(r.copies), count: r.copies, sheets: fmtNumber(r.sheets), when: when.format(r.saved),
      }));
      const open = el('button', t('kept.open'), { type: 'button', className: 'small-button' });
      open.setAttribute('aria-label', `${t('kept.open')} ${line.textContent}`);
      open.addEventListener('click', () => this.open(new File([r.blob], r.name, { type: 'application/json' })));
      const forget = el('button', t('kept.forget'), { type: 'button', className: 'small-button' });
      forget.setAttribute('aria-label', `${t('kept.forget')} ${line.textContent}`);
      forget.addEventListener('click', async () => {
        await forgetNest(r.id);
        await this.refresh();
        $('nest-open-input').focus();
      });
      li.append(line, ' ', open, ' ', forget);
      return li;
    }));
    this.list.dataset.count = String(this.kept.length);
  }
}
