// kerfcam page: the layers panel — the report's layers as checkboxes (names are file data: textContent
// only); the checked ones are cut. Split out of main.js (issue 15 item 7).

import { app, el, keepChoices, state, ui } from './app.js';
import { register, t } from './i18n.js';
import { formatValue, parseNumber } from './numbers.js';

// Each layer's operation (issue 20 item 2): by its name (MARK, ETCH, SPOT, DIM… as the engine reads
// them), or as chosen here.
// A router's operations (issue 43) with the tool of the Router tool panel.
const OPS = ['', 'cut', 'mark', 'spot', 'ignore', 'profile', 'pocket', 'engrave', 'drill'];
register({
  en: {
    'layers.op': 'Operation of layer {name}', 'layers.op.': 'by name', 'layers.op.cut': 'cut', 'layers.op.mark': 'mark',
    'layers.op.spot': 'centre-spot', 'layers.op.ignore': 'ignore', 'layers.op.profile': 'profile (router)',
    'layers.op.pocket': 'pocket (router)', 'layers.op.engrave': 'engrave (router)', 'layers.op.drill': 'drill (router)',
    'layers.depth': 'Depth', 'layers.pass': 'pass', 'layers.depth.of': 'Depth of layer {name}, mm (blank: the job\'s, {job})',
    'layers.pass.of': 'Deepest pass of layer {name}, mm (blank: the job\'s, {job})',
    'layers.depth.bad': 'a number above 0, at most the job\'s depth',
    'layers.milling.of': 'Direction of layer {name}', 'layers.milling.job': 'job\'s ({dir})',
  },
  'pt-BR': {
    'layers.op': 'Operação da camada {name}', 'layers.op.': 'pelo nome', 'layers.op.cut': 'cortar', 'layers.op.mark': 'marcar',
    'layers.op.spot': 'pontear', 'layers.op.ignore': 'ignorar', 'layers.op.profile': 'perfil (fresadora)',
    'layers.op.pocket': 'bolsão (fresadora)', 'layers.op.engrave': 'gravar (fresadora)', 'layers.op.drill': 'furar (fresadora)',
    'layers.depth': 'Profundidade', 'layers.pass': 'passe', 'layers.depth.of': 'Profundidade da camada {name}, mm (vazio: a do trabalho, {job})',
    'layers.pass.of': 'Passe mais fundo da camada {name}, mm (vazio: o do trabalho, {job})',
    'layers.depth.bad': 'um número acima de 0, no máximo a profundidade do trabalho',
    'layers.milling.of': 'Sentido da camada {name}', 'layers.milling.job': 'do trabalho ({dir})',
  },
});

/** The listed tools chosen for `job`'s layers (issue 43 §1), as the engine takes them: [[layer, number], …]. */
export function layerTools(job) {
  return Object.entries(job?.layerTools ?? {}).map(([l, n]) => [l, Number(n)]).filter(([, n]) => Number.isInteger(n));
}

const DIRECTIONS = ['climb', 'conventional'];

/** The depths, deepest passes and directions given to `job`'s milling layers (issue 43 §1), as the
 * engine takes them: [{layer, depth, pass_depth, milling}, …], null where the job's is kept. */
export function layerDepths(job) {
  const mm = (v) => (Number.isFinite(v) && v > 0 ? v : null);
  return Object.entries(job?.layerDepths ?? {})
    .map(([layer, d]) => ({ layer, depth: mm(d?.depth), pass_depth: mm(d?.pass), milling: DIRECTIONS.includes(d?.milling) ? d.milling : null }))
    .filter((d) => d.depth !== null || d.pass_depth !== null || d.milling !== null);
}

const MILLED = ['pocket', 'engrave', 'drill'];

/** The operations chosen for `job`'s layers, as the engine takes them: [[layer, op], …]. */
export function layerOps(job) {
  return Object.entries(job?.layerOps ?? {}).filter(([, op]) => OPS.includes(op) && op);
}

// AutoCAD colour index 1..7; everything else (0 = BYBLOCK, 256 = BYLAYER, 8..255) is shown grey.
const ACI = ['', '#e02020', '#e8c800', '#22a83a', '#20b8c8', '#2050e0', '#c020c0', '#1d2329'];
const aciColour = (c) => ACI[Math.abs(Number(c))] || '#9aa5b1'; // negative = layer off, same colour

/**
 * Shows the report's layers as checkboxes. The list is rebuilt only when the names change, so
 * toggling a layer keeps the keyboard focus on its checkbox. Names are file data: textContent only.
 */
export function showLayers(layers) {
  layers = Array.isArray(layers) ? layers : null;
  ui.layersBox.disabled = !layers?.length;
  if (!layers?.length) {
    state.layerNames = null;
    ui.layerCount.textContent = '';
    ui.layers.replaceChildren(el('li', layers ? t('layers.none-in-file') : t('layers.no-file'), { className: 'muted small' }));
    return;
  }
  const names = layers.map((l) => String(l.name));
  const same = state.layerNames && names.length === state.layerNames.length && names.every((n, i) => n === state.layerNames[i]);
  if (!same) {
    state.layerNames = names;
    ui.layers.replaceChildren(...layers.map((l, i) => layerRow(l, i)));
  }
  layers.forEach((l, i) => {
    const li = ui.layers.children[i];
    li.querySelector('input').checked = !!l.selected;
    li.classList.toggle('empty', !l.entities);
    li.querySelector('.layer-count').firstChild.textContent = String(l.entities ?? 0);
    li.querySelector('.layer-note').textContent = l.visible === false ? t('layers.off') : '';
    li.querySelector('.layer-count .sr-only').textContent = t('layers.entities');
    const unnamed = li.querySelector('.layer-name.muted');
    if (unnamed) unnamed.textContent = t('layers.no-name');
    const op = li.querySelector('select.layer-op');
    op.value = state.current?.layerOps?.[names[i]] ?? '';
    op.setAttribute('aria-label', t('layers.op', { name: names[i] || t('layers.no-name') }));
    for (const o of op.options) o.textContent = t(`layers.op.${o.value}`);
    depthFields(li, names[i], state.current?.layerOps?.[names[i]], state.current?.layerDepths?.[names[i]]);
  });
  refreshLayerTools();
  const selected = layers.filter((l) => l.selected).length;
  ui.layerCount.textContent = t('layers.count', { selected, total: layers.length });
}

/** Each layer's tool select from the Router tool panel's list as it is now (the list edited: no run needed). */
export function refreshLayerTools() {
  (state.layerNames ?? []).forEach((name, i) => {
    const sel = ui.layers.children[i]?.querySelector('select.layer-tool');
    if (sel) toolSelect(sel, name || t('layers.no-name'), state.current?.layerOps?.[name], state.current?.layerTools?.[name]);
  });
}

/** A milling layer's tool (issue 43 §1): the Router tool panel's, or one of its other tools; shown when
 * the layer mills and the panel lists some. */
function toolSelect(sel, name, op, chosen) {
  const listed = app.tool?.listed() ?? [];
  sel.hidden = !listed.length || !['pocket', 'engrave', 'drill'].includes(op);
  const options = [['', t('layers.tool.job', { n: app.tool?.jobNumber() ?? 1 })],
    ...listed.map((l) => [String(l.number), t('layers.tool.listed', { n: l.number, d: formatValue(l.diameter, 3) })])];
  sel.replaceChildren(...options.map(([v, text]) => el('option', text, { value: v })));
  sel.value = options.some(([v]) => v === String(chosen ?? '')) ? String(chosen ?? '') : '';
  sel.setAttribute('aria-label', t('layers.tool', { name }));
}

/** A milling layer's depth and deepest pass (issue 43 §1), blank for the job's (Process technology's,
 * shown as the placeholder); shown when the layer is pocketed, engraved or drilled. */
function depthFields(li, name, op, given) {
  const box = li.querySelector('.layer-depths');
  box.hidden = !MILLED.includes(op);
  const shown = name || t('layers.no-name');
  const job = { depth: document.getElementById('depth')?.value ?? '', pass: document.getElementById('pass-depth')?.value ?? '' };
  box.querySelector('.layer-depths-label').textContent = t('layers.depth');
  box.querySelector('.layer-pass-label').textContent = t('layers.pass');
  for (const [cls, key, label] of [['layer-depth', 'depth', 'layers.depth.of'], ['layer-pass', 'pass', 'layers.pass.of']]) {
    const input = box.querySelector(`input.${cls}`);
    input.placeholder = job[key];
    input.setAttribute('aria-label', t(label, { name: shown, job: job[key] || '—' }));
    input.title = input.getAttribute('aria-invalid') === 'true' ? t('layers.depth.bad') : input.getAttribute('aria-label');
    // Not while typed in (a run finishing elsewhere keeps what is being typed), unless it is the value
    // given, then written in the page's language (a language change while the field has the focus).
    const typing = document.activeElement === input && parseNumber(input.value) !== given?.[key];
    if (!typing && input.getAttribute('aria-invalid') !== 'true') {
      input.value = Number.isFinite(given?.[key]) ? formatValue(given[key]) : '';
    }
  }
  // Its direction: the Router tool panel's (named), climb or conventional.
  const dir = box.querySelector('select.layer-milling');
  const jobDir = document.getElementById('milling');
  const named = jobDir?.selectedOptions?.[0]?.textContent ?? '';
  dir.replaceChildren(el('option', t('layers.milling.job', { dir: named }), { value: '' }),
    ...DIRECTIONS.map((v) => el('option', t(`tool.milling.${v}`), { value: v })));
  dir.value = DIRECTIONS.includes(given?.milling) ? given.milling : '';
  dir.setAttribute('aria-label', t('layers.milling.of', { name: shown }));
}

function layerRow(l, i) {
  const box = el('input', '', { type: 'checkbox' });
  box.dataset.index = String(i);
  const swatch = el('span', '', { className: 'layer-swatch' });
  swatch.style.background = aciColour(l.color);
  swatch.setAttribute('aria-hidden', 'true');
  const name = String(l.name);
  const nameEl = name ? el('span', name, { className: 'layer-name' }) : el('span', t('layers.no-name'), { className: 'layer-name muted' });
  const count = el('span', '', { className: 'layer-count' });
  count.append(document.createTextNode(''), el('span', t('layers.entities'), { className: 'sr-only' }));
  const label = el('label', '');
  label.append(box, swatch, nameEl, el('span', '', { className: 'layer-note muted small' }), count);
  const li = el('li', '', { className: 'layer' });
  li.dataset.index = String(i);
  const op = el('select', '', { className: 'layer-op small' });
  op.dataset.index = String(i);
  op.append(...OPS.map((v) => el('option', t(`layers.op.${v}`), { value: v })));
  const tool = el('select', '', { className: 'layer-tool small' });
  tool.dataset.index = String(i);
  tool.hidden = true;
  const depths = el('div', '', { className: 'layer-depths small' });
  depths.hidden = true;
  const field = (cls) => {
    const input = el('input', '', { type: 'text', className: cls, inputMode: 'decimal', autocomplete: 'off', spellcheck: false });
    input.dataset.index = String(i);
    return input;
  };
  depths.append(el('span', '', { className: 'layer-depths-label' }), field('layer-depth'),
    el('span', '', { className: 'layer-pass-label' }), field('layer-pass'), el('span', 'mm', { className: 'muted' }));
  const dir = el('select', '', { className: 'layer-milling small' });
  dir.dataset.index = String(i);
  depths.append(dir);
  li.append(label, op, tool, depths);
  return li;
}

/** Cuts the checked layers (or `names`) of the current file. */
function selectLayers(names) {
  if (!state.layerNames) return;
  state.layers = names ?? [...ui.layers.querySelectorAll('input[type=checkbox]')]
    .filter((b) => b.checked)
    .map((b) => state.layerNames[Number(b.dataset.index)]);
  keepChoices();
  app.run();
}

export function wireLayers() {
  ui.layers.addEventListener('change', (e) => {
    if (e.target.matches('input[type=checkbox]')) selectLayers();
    if (e.target.matches('select.layer-op') && state.current && state.layerNames) {
      const name = state.layerNames[Number(e.target.dataset.index)];
      const ops = { ...(state.current.layerOps ?? {}) };
      if (e.target.value) ops[name] = e.target.value;
      else delete ops[name];
      state.current.layerOps = ops;
      keepChoices();
      app.run();
    }
    if (e.target.matches('select.layer-tool') && state.current && state.layerNames) {
      const name = state.layerNames[Number(e.target.dataset.index)];
      const tools = { ...(state.current.layerTools ?? {}) };
      if (e.target.value) tools[name] = Number(e.target.value);
      else delete tools[name];
      state.current.layerTools = tools;
      keepChoices();
      app.run();
    }
  });
  ui.layers.addEventListener('change', (e) => {
    if (!e.target.matches('select.layer-milling') || !state.current || !state.layerNames) return;
    const name = state.layerNames[Number(e.target.dataset.index)];
    const all = { ...(state.current.layerDepths ?? {}) };
    const d = { ...(all[name] ?? {}) };
    if (DIRECTIONS.includes(e.target.value)) d.milling = e.target.value;
    else delete d.milling;
    if (Object.keys(d).length) all[name] = d;
    else delete all[name];
    state.current.layerDepths = all;
    keepChoices();
    app.run();
  });
  ui.layers.addEventListener('change', (e) => {
    if (!e.target.matches('input.layer-depth, input.layer-pass') || !state.current || !state.layerNames) return;
    const name = state.layerNames[Number(e.target.dataset.index)];
    const key = e.target.matches('.layer-depth') ? 'depth' : 'pass';
    const text = e.target.value.trim();
    const v = parseNumber(text);
    const job = parseNumber(document.getElementById('depth')?.value);
    const bad = text !== '' && !(v > 0 && v <= 1000 && (key === 'pass' || !(job > 0) || v <= job));
    e.target.setAttribute('aria-invalid', String(bad));
    e.target.title = bad ? t('layers.depth.bad') : e.target.getAttribute('aria-label');
    if (bad) return; // said at the field; the last good program stays
    const all = { ...(state.current.layerDepths ?? {}) };
    const d = { ...(all[name] ?? {}) };
    if (text === '') delete d[key];
    else d[key] = v;
    if (Number.isFinite(d.depth) || Number.isFinite(d.pass) || d.milling) all[name] = d;
    else delete all[name];
    state.current.layerDepths = all;
    keepChoices();
    app.run();
  });
  ui.layersAll.addEventListener('click', () => selectLayers(state.layerNames ? [...state.layerNames] : null));
  ui.layersNone.addEventListener('click', () => selectLayers([]));
}
