// kerfcam page: post-processors — pick a preset or one of your own, edit it in a form, keep it in this
// browser (localStorage), export and import it as a JSON file. The engine checks every post and names
// the field that is wrong. Template lines are the post's own words with typed variables ({feed}, {kerf}…);
// nothing from a DXF ever reaches them.

import { parseNumber } from './numbers.js';
import { download } from './download.js';
import { getLang, onLangChange, register, t } from './i18n.js';

const STORE = 'kerfcam.posts.v1';

// The built-in posts by controller and process, as a shop names them, each with one line that says
// what it writes and for which machine (issue 19 item 4). Keys: the engine's preset names; '' is
// the engine's own default (plain LinuxCNC), so the "linuxcnc" preset, the same program, is not
// listed twice. Groups: the process the post is for.
export const PRESETS = [
  ['plasma', 'qtplasmac'], ['plasma', 'linuxcnc-plasma'], ['plasma', 'linuxcnc-z'], ['plasma', 'mach3-plasma'],
  ['plasma', 'grbl-plasma'],
  ['laser', 'grbl-laser'],
  ['knife', 'knife-relative'], ['knife', 'knife-gcode'],
  ['router', 'linuxcnc-router'], ['router', 'mach3-router'], ['router', 'grbl-router'],
  ['other', ''], ['other', 'iso6983'], ['other', 'annex-h'], ['other', 'point-list'],
];
const SAME_AS_DEFAULT = 'linuxcnc';

register({
  en: {
    'post.group.plasma': 'Plasma cutting', 'post.group.laser': 'Laser cutting', 'post.group.knife': 'Knife cutting',
    'post.group.other': 'Any process', 'post.group.router': 'Routing (spindle, depth in Z)',
    'post.name.linuxcnc-router': 'LinuxCNC — router',
    'post.about.linuxcnc-router': 'A router on LinuxCNC: the tool changed by T M6 with its length offset (G43 H, the Router tool panel\'s tool number), M3 S for the spindle, each depth pass plunged at the plunge feed, retract and safe heights on Z, arcs as G2/G3 (helices with Z). Needs a depth.',
    'post.name.mach3-router': 'Mach3 / Mach4 — router',
    'post.about.mach3-router': 'A router on Mach3 or Mach4: T M6 and G43 H for the tool (the Router tool panel\'s tool number), M3 S for the spindle, each depth pass plunged at the plunge feed, retract and safe heights on Z, M30 at the end. Needs a depth.',
    'post.name.grbl-router': 'GRBL — router',
    'post.about.grbl-router': 'A GRBL 1.1 router: M3 S for the spindle, plunges at the plunge feed, retract and safe heights on Z, semicolon comments. Needs a depth.',
    'post.name.': 'LinuxCNC — plain G-code (default)',
    'post.about.': 'G21 G90, arcs as G2/G3 with I J, M3/M5 around each cut, G4 for the pierce: any LinuxCNC machine (the program rs274 checks).',
    'post.name.qtplasmac': 'LinuxCNC — plasma (QtPlasmaC)',
    'post.about.qtplasmac': "QtPlasmaC in full: the material (M190, M66), its cut feed, M3 $0/$1/$2 to cut, scribe and spot, THC locked in small holes; no Z moves.",
    'post.name.linuxcnc-plasma': 'LinuxCNC — plasma, torch only',
    'post.about.linuxcnc-plasma': "QtPlasmaC's torch words only: M3 $0 S1 / M5 $0, its modal header; heights and feeds come from the machine's cut chart.",
    'post.name.linuxcnc-z': 'LinuxCNC — plasma, Z probed',
    'post.about.linuxcnc-z': 'For tables without height control: G38.2 probes the plate, then pierce height, pierce delay, cut height and retract on Z.',
    'post.name.mach3-plasma': 'Mach3 / Mach4 — plasma',
    'post.about.mach3-plasma': 'Mach3 and Mach4 plasma: M3/M5 for the torch, G4 for the pierce delay, arcs with I J from the start.',
    'post.name.grbl-plasma': 'GRBL — plasma',
    'post.about.grbl-plasma': 'GRBL 1.1 with a torch relay: M3 S1000 / M5, semicolon comments, G4 for the pierce delay.',
    'post.name.grbl-laser': 'GRBL — laser',
    'post.about.grbl-laser': 'GRBL 1.1 laser mode: M4 (power follows speed) / M5 S0, semicolon comments.',
    'post.name.knife-relative': 'Tangential knife, relative moves',
    'post.about.knife-relative': 'Relative moves for a tangential knife cutter, the blade turned to each cut; arcs as straight lines.',
    'post.name.knife-gcode': 'Tangential knife, rotary axis A',
    'post.about.knife-gcode': 'G-code with the blade angle on a rotary A axis, Z down to cut and up (lifted) at sharp turns; arcs as lines.',
    'post.name.iso6983': 'ISO 6983 generic',
    'post.about.iso6983': 'ISO 6983 / EIA-274-D with line numbers, G00/G01/G02/G03 and M03/M05: for a control not listed here.',
    'post.name.annex-h': 'Paper 001 annex H dialect',
    'post.about.annex-h': 'The GE-550 controller dialect of paper 001, annex H (Ebisui 1993): % program number, $ comments, N numbers, M25/M26 preheat.',
    'post.name.point-list': 'Point list (x;y) for step-motor tables',
    'post.about.point-list': 'Not G-code: one x;y point per line (Richetti), arcs as short lines, for tables driven point by point by step motors.',
    'post.presets': 'Presets', 'post.default': 'LinuxCNC — plain G-code (default)', 'post.mine': 'My posts',
    'post.about.mine': 'Your post, kept in this browser: "Edit post…" shows its words.',
    'post.import-failed': 'Could not import {name}: {message}', 'post.copy-name': '{name} (mine)',
    'post.unnamed': 'my post', 'post.saved': 'Saved "{name}" in this browser.',
  },
  'pt-BR': {
    'post.group.plasma': 'Corte a plasma', 'post.group.laser': 'Corte a laser', 'post.group.knife': 'Corte com faca',
    'post.group.other': 'Qualquer processo', 'post.group.router': 'Fresadora (fuso, profundidade em Z)',
    'post.name.linuxcnc-router': 'LinuxCNC — fresadora (router)',
    'post.about.linuxcnc-router': 'Uma fresadora no LinuxCNC: a ferramenta trocada por T M6 com o seu corretor de comprimento (G43 H, o número da ferramenta no painel Ferramenta da fresadora), M3 S para o fuso, cada passe de profundidade descido no avanço de mergulho, alturas de recuo e segura em Z, arcos em G2/G3 (hélices com Z). Precisa de uma profundidade.',
    'post.name.mach3-router': 'Mach3 / Mach4 — fresadora (router)',
    'post.about.mach3-router': 'Uma fresadora no Mach3 ou Mach4: T M6 e G43 H para a ferramenta (o número da ferramenta no painel Ferramenta da fresadora), M3 S para o fuso, cada passe de profundidade descido no avanço de mergulho, alturas de recuo e segura em Z, M30 no fim. Precisa de uma profundidade.',
    'post.name.grbl-router': 'GRBL — fresadora (router)',
    'post.about.grbl-router': 'Uma fresadora GRBL 1.1: M3 S para o fuso, mergulhos no avanço de mergulho, alturas de recuo e segura em Z, comentários com ponto e vírgula. Precisa de uma profundidade.',
    'post.name.': 'LinuxCNC — simples (padrão)',
    'post.about.': 'G21 G90, arcos em G2/G3 com I J, M3/M5 em volta de cada corte, G4 na perfuração: qualquer máquina LinuxCNC (o programa que o rs274 confere).',
    'post.name.qtplasmac': 'LinuxCNC — plasma (QtPlasmaC)',
    'post.about.qtplasmac': 'O QtPlasmaC completo: o material (M190, M66), a sua velocidade de corte, M3 $0/$1/$2 para cortar, riscar e marcar, THC travado em furos pequenos; sem movimentos em Z.',
    'post.name.linuxcnc-plasma': 'LinuxCNC — plasma, só a tocha',
    'post.about.linuxcnc-plasma': 'Só as palavras da tocha do QtPlasmaC: M3 $0 S1 / M5 $0, o seu cabeçalho modal; alturas e velocidades vêm da tabela de corte da máquina.',
    'post.name.linuxcnc-z': 'LinuxCNC — plasma, Z apalpado',
    'post.about.linuxcnc-z': 'Para mesas sem controle de altura: G38.2 apalpa a chapa, depois altura de perfuração, tempo de perfuração, altura de corte e recuo em Z.',
    'post.name.mach3-plasma': 'Mach3 / Mach4 — plasma',
    'post.about.mach3-plasma': 'Mach3 e Mach4 plasma: M3/M5 para a tocha, G4 para o tempo de perfuração, arcos com I J a partir do início.',
    'post.name.grbl-plasma': 'GRBL — plasma',
    'post.about.grbl-plasma': 'GRBL 1.1 com relé da tocha: M3 S1000 / M5, comentários com ponto e vírgula, G4 para o tempo de perfuração.',
    'post.name.grbl-laser': 'GRBL — laser',
    'post.about.grbl-laser': 'GRBL 1.1 em modo laser: M4 (potência segue a velocidade) / M5 S0, comentários com ponto e vírgula.',
    'post.name.knife-relative': 'Faca tangencial, mov. relativos',
    'post.about.knife-relative': 'Movimentos relativos para uma cortadora de faca tangencial, a lâmina virada para cada corte; arcos em retas.',
    'post.name.knife-gcode': 'Faca tangencial, eixo rotativo A',
    'post.about.knife-gcode': 'G-code com o ângulo da lâmina num eixo rotativo A, Z desce para cortar e sobe nas curvas fechadas; arcos em retas.',
    'post.name.iso6983': 'ISO 6983 genérico',
    'post.about.iso6983': 'ISO 6983 / EIA-274-D com números de linha, G00/G01/G02/G03 e M03/M05: para um comando que não está na lista.',
    'post.name.annex-h': 'Dialeto do anexo H do artigo 001',
    'post.about.annex-h': 'O dialeto do comando GE-550 do artigo 001, anexo H (Ebisui 1993): número de programa com %, comentários com $, números N, pré-aquecimento M25/M26.',
    'post.name.point-list': 'Lista x;y, mesa de motor de passo',
    'post.about.point-list': 'Não é G-code: um ponto x;y por linha (Richetti), arcos em retas curtas, para mesas movidas ponto a ponto por motores de passo.',
    'post.presets': 'Modelos', 'post.default': 'LinuxCNC — simples (padrão)', 'post.mine': 'Meus pós-processadores',
    'post.about.mine': 'O seu pós-processador, guardado neste navegador: "Editar pós-processador…" mostra as suas palavras.',
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
    if (selected === `preset:${SAME_AS_DEFAULT}`) selected = ''; // kept from before: the same program
    const groups = [];
    for (const [group, name] of PRESETS) {
      if (name && !this.presets[name]) continue; // an engine without it
      let g = groups.find((o) => o.dataset.group === group);
      if (!g) {
        g = Object.assign(document.createElement('optgroup'), { label: t(`post.group.${group}`) });
        g.dataset.group = group;
        groups.push(g);
      }
      g.append(option(name ? `preset:${name}` : '', t(`post.name.${name}`)));
    }
    // A preset of a newer engine, not named here yet: listed under its own name.
    const known = new Set([...PRESETS.map(([, n]) => n), SAME_AS_DEFAULT]);
    const other = groups.find((o) => o.dataset.group === 'other');
    for (const name of Object.keys(this.presets)) if (!known.has(name)) other?.append(option(`preset:${name}`, this.presets[name].name || name));
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
    this.showAbout();
  }

  /** The selected post's one-line description under the menu. */
  showAbout() {
    const v = this.ui.select.value;
    const key = v.startsWith('mine:') ? 'post.about.mine' : `post.about.${v.replace(/^preset:/, '')}`;
    const text = t(key);
    this.ui.about.textContent = text === key ? '' : text;
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
    ui.select.addEventListener('change', () => {
      this.showAbout();
      this.onChange();
    });
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
