// kerfcam page: the cut chart (issue 20 §1) — a library of materials kept in this browser
// (localStorage), each entry editable, imported and exported as kerfcam JSON or as a LinuxCNC QtPlasmaC
// material file. The engine reads, checks and writes every chart (src/wasm/materials.rs): the page never
// parses one. The entry chosen for the job goes to the engine whole (`material`), which sets kerf, feed,
// pierce delay, heights and the material number from it (Settings::with_material, the CLI's path); the
// kerf, feed and pierce delay fields show its values and are locked while it is chosen.

import { download } from './download.js';
import { FIELDS as NUMBER_FIELDS, formatValue, parseNumber } from './numbers.js';
import { getLang, onLangChange, register, t } from './i18n.js';

const STORE = 'kerfcam.materials';
const VERSION = 1;

register({
  en: {
    'materials.heading': 'Cut chart',
    'materials.help': 'Kerf, feed and pierce settings by material. The starter entries are examples: check them against your machine\'s manual before cutting.',
    'materials.choose': 'Material',
    'materials.none': 'none: the values typed below',
    'materials.entries': 'Entries',
    'materials.example': '(example)',
    'materials.note': 'Kerf {kerf} mm, feed {feed} mm/min, pierce delay {delay} s from “{name}” (locked below; choose “none” to type your own).',
    'materials.note.example': 'This is an example, not your machine\'s figure: check it against your machine\'s manual.',
    'materials.new': 'New entry', 'materials.save': 'Save entry', 'materials.delete': 'Delete entry',
    'materials.export-json': 'Export (.json)', 'materials.export-cfg': 'Export QtPlasmaC (.cfg)',
    'materials.import': 'Import (replaces the chart)…', 'materials.starter': 'Back to the examples',
    'materials.saved': 'Saved “{name}” in this browser.', 'materials.deleted': 'Deleted “{name}”.',
    'materials.imported': 'Imported {count} entries from {file}.', 'materials.import-failed': 'Could not import {file}: {message}',
    'materials.not-number': 'material \'{name}\', {field}: \'{value}\' is not a number',
    'materials.name-used': 'material \'{name}\', name: another entry has this name',
    'materials.new-name': 'New material',
    'materials.f.name': 'Name', 'materials.f.process': 'Process', 'materials.f.material': 'Material',
    'materials.f.thickness': 'Thickness', 'materials.f.kerf': 'Kerf width', 'materials.f.feed': 'Cut feed',
    'materials.f.pierce_delay': 'Pierce delay', 'materials.f.pierce_height': 'Pierce height',
    'materials.f.cut_height': 'Cut height', 'materials.f.amps': 'Current / power', 'materials.f.volts': 'Arc voltage',
    'materials.f.gas_pressure': 'Gas pressure', 'materials.f.small_hole_speed': 'Small-hole speed',
    'materials.f.number': 'Controller material number',
    'materials.p.plasma': 'plasma', 'materials.p.oxy-fuel': 'oxy-fuel', 'materials.p.laser': 'laser',
    'materials.p.waterjet': 'waterjet', 'materials.p.knife': 'knife', 'materials.p.router': 'router',
  },
  'pt-BR': {
    'materials.heading': 'Tabela de corte',
    'materials.help': 'Sangria, velocidade e perfuração por material. As entradas iniciais são exemplos: confira-as no manual da sua máquina antes de cortar.',
    'materials.choose': 'Material',
    'materials.none': 'nenhum: os valores digitados abaixo',
    'materials.entries': 'Entradas',
    'materials.example': '(exemplo)',
    'materials.note': 'Sangria {kerf} mm, velocidade {feed} mm/min, tempo de perfuração {delay} s de “{name}” (travados abaixo; escolha “nenhum” para digitar os seus).',
    'materials.note.example': 'Isto é um exemplo, não um valor da sua máquina: confira no manual da sua máquina.',
    'materials.new': 'Nova entrada', 'materials.save': 'Salvar entrada', 'materials.delete': 'Excluir entrada',
    'materials.export-json': 'Exportar (.json)', 'materials.export-cfg': 'Exportar QtPlasmaC (.cfg)',
    'materials.import': 'Importar (substitui a tabela)…', 'materials.starter': 'Voltar aos exemplos',
    'materials.saved': '“{name}” salvo neste navegador.', 'materials.deleted': '“{name}” excluído.',
    'materials.imported': '{count} entradas importadas de {file}.', 'materials.import-failed': 'Não foi possível importar {file}: {message}',
    'materials.not-number': 'material \'{name}\', {field}: \'{value}\' não é um número',
    'materials.name-used': 'material \'{name}\', name: outra entrada tem este nome',
    'materials.new-name': 'Novo material',
    'materials.f.name': 'Nome', 'materials.f.process': 'Processo', 'materials.f.material': 'Material',
    'materials.f.thickness': 'Espessura', 'materials.f.kerf': 'Sangria', 'materials.f.feed': 'Velocidade de corte',
    'materials.f.pierce_delay': 'Tempo de perfuração', 'materials.f.pierce_height': 'Altura de perfuração',
    'materials.f.cut_height': 'Altura de corte', 'materials.f.amps': 'Corrente / potência', 'materials.f.volts': 'Tensão do arco',
    'materials.f.gas_pressure': 'Pressão do gás', 'materials.f.small_hole_speed': 'Velocidade em furos pequenos',
    'materials.f.number': 'Número do material no controlador',
    'materials.p.plasma': 'plasma', 'materials.p.oxy-fuel': 'oxicorte', 'materials.p.laser': 'laser',
    'materials.p.waterjet': 'jato d\'água', 'materials.p.knife': 'faca', 'materials.p.router': 'fresa',
  },
});

const PROCESSES = ['plasma', 'oxy-fuel', 'laser', 'waterjet', 'knife', 'router'];
// The editor's fields: [key, unit, required]. Optional numbers left blank are absent from the entry.
const EDITED = [
  ['thickness', 'mm', true], ['kerf', 'mm', true], ['feed', 'mm/min', true], ['pierce_delay', 's', true],
  ['pierce_height', 'mm'], ['cut_height', 'mm'], ['amps', 'A / W'], ['volts', 'V'], ['gas_pressure', ''],
  ['small_hole_speed', '%'], ['number', ''],
];
// The job's fields a chosen material sets (shown, and locked while it is chosen).
const JOB_FIELDS = ['kerf', 'feed', 'pierce_delay'];

const el = (tag, props = {}, ...kids) => {
  const e = Object.assign(document.createElement(tag), props);
  e.append(...kids);
  return e;
};

/** The same entry, blank (null) and absent fields alike. */
const same = (a, b) => {
  const norm = (o) => JSON.stringify(Object.keys(o).sort().filter((k) => o[k] != null).map((k) => [k, o[k]]));
  return norm(a) === norm(b);
};

export class Materials {
  /**
   * `ui`: { choose, note, list, form, message, newButton, save, remove, exportJson, exportCfg, importInput,
   * starter }; `engine`: the worker; `onChange()`: re-run the job.
   */
  constructor(ui, engine, onChange) {
    Object.assign(this, { ui, engine, onChange, library: null, chosen: '', file: null });
    this.buildForm();
    onLangChange(() => this.fill());
  }

  async load() {
    let saved = null;
    try {
      saved = JSON.parse(localStorage.getItem(STORE) || 'null');
    } catch {
      saved = null;
    }
    if (saved?.version === VERSION && saved.library && !(await this.check(saved.library))) {
      Object.assign(this, { library: saved.library, chosen: saved.chosen || '', file: saved.file || null });
    } else {
      this.library = JSON.parse(await this.engine.call('materialsStarter'));
    }
    this.wire();
    this.fill();
    this.lockJobFields();
  }

  /** The engine's word on a library: '' when valid, else the message naming the entry and field. */
  check(library) {
    return this.engine.call('materialsCheck', { json: JSON.stringify(library), lang: getLang() });
  }

  keep() {
    try {
      localStorage.setItem(STORE, JSON.stringify({ version: VERSION, library: this.library, chosen: this.chosen, file: this.file }));
    } catch {
      // storage full or disabled: the chart lives until the page closes
    }
  }

  entry(name = this.chosen) {
    return this.library?.entries.find((e) => e.name === name) ?? null;
  }

  /** Adds the chosen entry to the job's settings: the engine applies it (kerf, feed, delay, heights, number). */
  settings(settings) {
    const e = this.entry();
    if (e) settings.material = JSON.stringify(e);
    return settings;
  }

  label(e) {
    return e.example ? e.name.replace(/\s*\(example\)$/, ` ${t('materials.example')}`) : e.name;
  }

  buildForm() {
    const { form } = this.ui;
    const row = (key, input, unit = '') => {
      input.id = `material-f-${key}`;
      input.name = key;
      form.append(el('label', { htmlFor: input.id, textContent: t(`materials.f.${key}`) }), input, el('span', { className: 'unit', textContent: unit }));
      input.previousSibling.dataset.i18n = `materials.f.${key}`;
    };
    const text = () => el('input', { type: 'text', autocomplete: 'off', spellcheck: false });
    row('name', text());
    const option = (p) => {
      const o = el('option', { value: p, textContent: t(`materials.p.${p}`) });
      o.dataset.i18n = `materials.p.${p}`;
      return o;
    };
    row('process', el('select', {}, ...PROCESSES.map(option)));
    row('material', text());
    for (const [key, unit] of EDITED) row(key, Object.assign(text(), { inputMode: 'decimal' }), unit);
    form.addEventListener('submit', (e) => {
      e.preventDefault();
      this.save();
    });
  }

  wire() {
    const { ui } = this;
    ui.choose.addEventListener('change', () => this.choose(ui.choose.value));
    ui.list.addEventListener('change', () => this.edit(this.library.entries[Number(ui.list.value)]));
    ui.newButton.addEventListener('click', () => {
      // A new entry starts from the engine's defaults (main.js sets `defaults`).
      const d = this.defaults ?? {};
      this.edit({ name: t('materials.new-name'), process: 'plasma', material: '', thickness: 0, kerf: d.kerf, feed: d.feed, pierce_delay: d.pierce_delay }, true);
      ui.form.elements.name.focus();
    });
    ui.remove.addEventListener('click', () => this.remove());
    ui.exportJson.addEventListener('click', () => {
      download(new Blob([JSON.stringify(this.library, null, 2)], { type: 'application/json' }), 'kerfcam-materials.json');
    });
    ui.exportCfg.addEventListener('click', async () => {
      try {
        const text = await this.engine.call('materialsCfg', { json: JSON.stringify(this.library), lang: getLang() });
        // The name it came in with (QtPlasmaC reads <machine>_material.cfg): a file goes back as it came.
        download(new Blob([text], { type: 'text/plain' }), this.file?.endsWith('.cfg') ? this.file : 'kerfcam_material.cfg');
      } catch (e) {
        this.say(e.message || String(e), true);
      }
    });
    ui.importInput.addEventListener('change', async () => {
      const file = ui.importInput.files[0];
      ui.importInput.value = '';
      if (file) await this.importChart(file.name, await file.text());
    });
    ui.starter.addEventListener('click', async () => {
      this.library = JSON.parse(await this.engine.call('materialsStarter'));
      this.file = null;
      this.chosen = '';
      this.changed();
    });
  }

  async importChart(name, text) {
    try {
      const library = JSON.parse(await this.engine.call('materialsRead', { text, lang: getLang() }));
      Object.assign(this, { library, file: name });
      if (!this.entry()) this.chosen = '';
      this.changed();
      this.say(t('materials.imported', { count: library.entries.length, file: name }));
    } catch (e) {
      this.say(t('materials.import-failed', { file: name, message: e.message || String(e) }), true);
    }
  }

  say(text, error = false) {
    this.ui.message.textContent = text;
    this.ui.message.classList.toggle('error-text', error);
    this.ui.message.dataset.error = String(error);
  }

  choose(name) {
    this.chosen = this.entry(name) ? name : '';
    this.keep();
    this.lockJobFields();
    this.showNote();
    this.onChange();
  }

  /** The chosen entry's kerf, feed and pierce delay in the job's fields, locked; unlocked for none. */
  lockJobFields() {
    const e = this.entry();
    for (const key of JOB_FIELDS) {
      const input = document.getElementById(NUMBER_FIELDS[key].id);
      if (!input) continue;
      input.readOnly = !!e;
      if (e) input.value = formatValue(e[key]);
    }
  }

  showNote() {
    const e = this.entry();
    const { note } = this.ui;
    note.textContent = e
      ? t('materials.note', { kerf: formatValue(e.kerf), feed: formatValue(e.feed), delay: formatValue(e.pierce_delay), name: this.label(e) })
      : '';
    if (e?.example) note.append(' ', el('strong', { textContent: t('materials.note.example') }));
  }

  /** The menus from the library (names from files: text only). */
  fill() {
    if (!this.library) return;
    const { choose, list } = this.ui;
    const at = list.value;
    choose.replaceChildren(el('option', { value: '', textContent: t('materials.none') }),
      ...this.library.entries.map((e) => el('option', { value: e.name, textContent: this.label(e) })));
    choose.value = this.chosen;
    list.replaceChildren(...this.library.entries.map((e, i) => el('option', { value: String(i), textContent: this.label(e) })));
    if (at && list.options[Number(at)]) list.value = at;
    this.showNote();
  }

  /** Puts `e` in the editor (`isNew`: saved as a new entry). */
  edit(e, isNew = false) {
    if (!e) return;
    const f = this.ui.form.elements;
    this.editing = { base: e, isNew };
    f.name.value = e.name;
    f.process.value = e.process;
    f.material.value = e.material || '';
    for (const [key] of EDITED) f[key].value = e[key] == null ? '' : formatValue(e[key]);
    this.say('');
  }

  /** The editor's entry, or throws the message naming the entry and the field. */
  read() {
    const f = this.ui.form.elements;
    const name = f.name.value.trim();
    const e = { ...(this.editing?.base ?? {}), name, process: f.process.value, material: f.material.value.trim() };
    for (const [key, , required] of EDITED) {
      const typed = f[key].value.trim();
      if (!typed && !required) {
        e[key] = null;
        continue;
      }
      const v = parseNumber(typed);
      if (!Number.isFinite(v)) throw new Error(t('materials.not-number', { name, field: key, value: typed }));
      e[key] = v;
    }
    // An edited example is the user's own figure now.
    if (!this.editing?.isNew && this.editing?.base.example && !same(e, this.editing.base)) {
      e.example = false;
      e.name = e.name.replace(/\s*\(example\)$/, '');
    }
    if (this.editing?.isNew) e.example = false;
    return e;
  }

  async save() {
    let e;
    try {
      e = this.read();
    } catch (err) {
      return this.say(err.message, true);
    }
    const entries = [...this.library.entries];
    const i = this.editing?.isNew ? -1 : entries.indexOf(this.editing?.base);
    if (entries.some((x, j) => j !== i && x.name === e.name)) return this.say(t('materials.name-used', { name: e.name }), true);
    if (i < 0) entries.push(e);
    else entries[i] = e;
    const library = { ...this.library, entries };
    const problem = await this.check(library);
    if (problem) return this.say(problem, true);
    const wasChosen = i >= 0 && this.editing.base.name === this.chosen;
    this.library = library;
    this.editing = { base: e, isNew: false };
    if (wasChosen) this.chosen = e.name;
    this.changed(i < 0 ? entries.length - 1 : i);
    this.say(t('materials.saved', { name: e.name }));
  }

  remove() {
    const i = Number(this.ui.list.value);
    const e = this.library.entries[i];
    if (!e || this.ui.list.value === '') return;
    this.library = { ...this.library, entries: this.library.entries.filter((_, j) => j !== i) };
    if (e.name === this.chosen) this.chosen = '';
    this.changed();
    this.say(t('materials.deleted', { name: e.name }));
  }

  /** After any change of the chart: kept, menus refilled, the job re-run with the (maybe edited) entry. */
  changed(select = null) {
    this.keep();
    this.fill();
    if (select !== null) this.ui.list.value = String(select);
    this.lockJobFields();
    this.onChange();
  }
}
