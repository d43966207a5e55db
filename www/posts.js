// kerfcam page: post-processors — pick a preset or one of your own, edit it in a form, keep it in this
// browser (localStorage), export and import it as a JSON file. The engine checks every post and names
// the field that is wrong. Template lines are the post's own words with typed variables ({feed}, {kerf}…);
// nothing from a DXF ever reaches them.

import { parseNumber } from './numbers.js';
import { download } from './download.js';
import { getLang, onLangChange, register, t } from './i18n.js';

const STORE = 'kerfcam.posts.v1';

register({
  en: {
    'post.presets': 'Presets', 'post.default': 'LinuxCNC (default)', 'post.mine': 'My posts',
    'post.import-failed': 'Could not import {name}: {message}', 'post.copy-name': '{name} (mine)',
    'post.unnamed': 'my post', 'post.saved': 'Saved "{name}" in this browser.',
  },
  'pt-BR': {
    'post.presets': 'Modelos', 'post.default': 'LinuxCNC (padrão)', 'post.mine': 'Meus pós-processadores',
    'post.import-failed': 'Não foi possível importar {name}: {message}', 'post.copy-name': '{name} (meu)',
    'post.unnamed': 'meu pós-processador', 'post.saved': '"{name}" salvo neste navegador.',
  },
});

/** Your saved posts: { name: post }. */
function loadMine() {
  try {
    const mine = JSON.parse(localStorage.getItem(STORE) || '{}');
    return mine && typeof mine === 'object' ? mine : {};
  } catch {
    return {};
  }
}

function saveMine(mine) {
  localStorage.setItem(STORE, JSON.stringify(mine));
}

// Form fields: [post key, kind]; kinds: text, number, select, check, lines.
const FIELDS = [
  ['name', 'text'], ['units', 'select'], ['decimals', 'number'], ['trailing_zeros', 'check'],
  ['arcs', 'select'], ['chord', 'number'], ['max_arc_sweep_deg', 'number'], ['comments', 'select'],
  ['modal', 'check'], ['rapid_speed', 'number'], ['rapid', 'text'], ['line', 'text'],
  ['header', 'lines'], ['torch_on', 'lines'], ['dwell', 'lines'], ['torch_off', 'lines'], ['footer', 'lines'],
];

export class Posts {
  /** `ui`: select, edit/export/import controls and the dialog form; `engine`: the worker. */
  constructor(ui, engine, onChange) {
    Object.assign(this, { ui, engine, onChange, presets: {}, mine: loadMine() });
  }

  async load() {
    this.presets = JSON.parse(await this.engine.call('presets'));
    this.fillMenu('');
    this.wire();
  }

  fillMenu(selected) {
    const { select } = this.ui;
    const option = (value, text) => Object.assign(document.createElement('option'), { value, textContent: text });
    const presets = document.createElement('optgroup');
    presets.label = t('post.presets');
    presets.append(option('', t('post.default')));
    for (const name of Object.keys(this.presets)) presets.append(option(`preset:${name}`, name));
    const groups = [presets];
    const names = Object.keys(this.mine);
    if (names.length) {
      const mine = document.createElement('optgroup');
      mine.label = t('post.mine');
      for (const name of names) mine.append(option(`mine:${name}`, name));
      groups.push(mine);
    }
    select.replaceChildren(...groups);
    select.value = selected;
    if (select.value !== selected) select.value = '';
  }

  /** The selected post as an object (null: the default). */
  current() {
    const v = this.ui.select.value;
    if (v.startsWith('preset:')) return this.presets[v.slice(7)] ?? null;
    if (v.startsWith('mine:')) return this.mine[v.slice(5)] ?? null;
    return null;
  }

  /** What the Job's settings carry: a preset's name or your post's JSON. */
  settings() {
    const v = this.ui.select.value;
    if (v.startsWith('preset:')) return { post: v.slice(7), post_json: null };
    if (v.startsWith('mine:') && this.mine[v.slice(5)]) return { post: null, post_json: JSON.stringify(this.mine[v.slice(5)]) };
    return { post: null, post_json: null };
  }

  wire() {
    const { ui } = this;
    onLangChange(() => this.fillMenu(ui.select.value)); // the group names and the default's label
    ui.select.addEventListener('change', () => this.onChange());
    ui.edit.addEventListener('click', () => this.openEditor());
    ui.form.addEventListener('submit', (e) => {
      e.preventDefault();
      this.saveEditor();
    });
    ui.cancel.addEventListener('click', () => ui.dialog.close());
    ui.exportButton.addEventListener('click', () => {
      const post = this.current() ?? this.presets.linuxcnc;
      download(
        new Blob([JSON.stringify(post, null, 2)], { type: 'application/json' }),
        `${(post.name || 'post').replace(/[^\w.-]+/g, '_')}.post.json`,
      );
    });
    ui.importInput.addEventListener('change', async () => {
      const file = ui.importInput.files[0];
      ui.importInput.value = '';
      if (!file) return;
      try {
        await this.store(JSON.parse(await file.text()));
      } catch (e) {
        this.ui.message.textContent = t('post.import-failed', { name: file.name, message: e.message || e });
      }
    });
  }

  openEditor() {
    const post = structuredClone(this.current() ?? this.presets.linuxcnc);
    const { form } = this.ui;
    form.dataset.base = JSON.stringify(post);
    for (const [key, kind] of FIELDS) {
      const input = form.elements[key];
      if (!input) continue;
      if (kind === 'check') input.checked = Boolean(post[key]);
      else if (kind === 'lines') input.value = (post[key] || []).join('\n');
      else input.value = post[key] ?? '';
    }
    form.elements.line_numbers.checked = Boolean(post.line_numbers);
    form.elements.ln_start.value = post.line_numbers?.start ?? 10;
    form.elements.ln_step.value = post.line_numbers?.step ?? 10;
    if (!this.mine[post.name]) form.elements.name.value = t('post.copy-name', { name: post.name });
    this.ui.error.textContent = '';
    this.ui.dialog.showModal();
  }

  async saveEditor() {
    const { form } = this.ui;
    const post = JSON.parse(form.dataset.base);
    for (const [key, kind] of FIELDS) {
      const input = form.elements[key];
      if (!input) continue;
      if (kind === 'check') post[key] = input.checked;
      // Typed the local way where the field is text (the chord: '0,01' or '0.01'); whole numbers use type=number.
      else if (kind === 'number') post[key] = input.type === 'number' ? input.valueAsNumber : parseNumber(input.value);
      else if (kind === 'lines') post[key] = input.value.split('\n').map((l) => l.trim()).filter(Boolean);
      else post[key] = input.value;
    }
    post.line_numbers = form.elements.line_numbers.checked
      ? { start: form.elements.ln_start.valueAsNumber, step: form.elements.ln_step.valueAsNumber, width: 0 }
      : null;
    try {
      await this.store(post);
      this.ui.dialog.close();
    } catch (e) {
      this.ui.error.textContent = e.message || String(e);
    }
  }

  /** Checks `post` with the engine, keeps it under its name and selects it. */
  async store(post) {
    const problem = await this.engine.call('checkPost', { json: JSON.stringify(post), lang: getLang() });
    if (problem) throw new Error(problem);
    const name = String(post.name || t('post.unnamed')).trim() || t('post.unnamed');
    this.mine = { ...this.mine, [name]: post };
    saveMine(this.mine);
    this.fillMenu(`mine:${name}`);
    this.ui.message.textContent = t('post.saved', { name });
    this.onChange();
  }
}
