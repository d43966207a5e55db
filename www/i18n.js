// kerfcam page languages: English and Brazilian Portuguese. Each module registers its own strings
// (register({ en: {...}, 'pt-BR': {...} })), so a new module never edits a shared catalogue file.
// A key missing in Portuguese falls back to English and is recorded (missingKeys()), so a test can
// assert that nothing the user saw was left untranslated.
// Numbers are formatted in the chosen locale for the UI only: G-code and downloaded files keep the
// C locale ('.' decimals), so nothing that leaves the page goes through fmtNumber.

export const LANGS = [
  ['en', 'English'],
  ['pt-BR', 'Português (Brasil)'],
];
const STORAGE_KEY = 'kerfcam.lang';
const FALLBACK = 'en';

const catalogs = Object.fromEntries(LANGS.map(([code]) => [code, Object.create(null)]));
const listeners = new Set();
const missing = new Set();
let lang = FALLBACK;
let numberFormats = new Map(); // digits → Intl.NumberFormat, for the current language
let pluralRules = null; // Intl.PluralRules of the current language, made on first use

/** 'pt', 'pt-PT', 'PT-br' → 'pt-BR'; anything else → 'en'. */
export function normaliseLang(tag) {
  return /^pt\b/i.test(String(tag || '')) ? 'pt-BR' : FALLBACK;
}

/** The language to start with: the one kept in this browser, else the browser's first preference. */
function initialLang() {
  try {
    const kept = globalThis.localStorage?.getItem(STORAGE_KEY);
    if (kept && catalogs[kept]) return kept;
  } catch {
    // storage blocked (private mode, file://): fall through to the browser's languages
  }
  const prefs = globalThis.navigator?.languages?.length ? globalThis.navigator.languages : [globalThis.navigator?.language];
  // The first preference that we have decides: ['de', 'pt-BR'] gives Portuguese, ['en', 'pt'] English.
  for (const p of prefs || []) {
    if (/^pt\b/i.test(p || '')) return 'pt-BR';
    if (/^en\b/i.test(p || '')) return 'en';
  }
  return FALLBACK;
}

/**
 * Adds a module's strings. `catalog` is { en: { key: text }, 'pt-BR': { key: text } }. A text is a
 * string with {name} placeholders, or { one, other } chosen by params.count (plural rules of the language).
 */
export function register(catalog) {
  for (const [code, entries] of Object.entries(catalog || {})) {
    if (!catalogs[code]) throw new Error(`i18n: unknown language ${code}`);
    Object.assign(catalogs[code], entries);
  }
}

/** The text for `key` in the current language, with {name} placeholders filled from `params`. */
export function t(key, params) {
  let text = catalogs[lang][key];
  if (text === undefined) {
    if (lang !== FALLBACK) missing.add(`${lang}:${key}`);
    text = catalogs[FALLBACK][key];
  }
  if (text === undefined) {
    missing.add(`${FALLBACK}:${key}`);
    return key;
  }
  if (typeof text === 'object') {
    const count = Number(params?.count);
    pluralRules ??= new Intl.PluralRules(lang);
    const form = pluralRules.select(Number.isFinite(count) ? count : 0);
    text = text[form] ?? text.other;
  }
  return String(text).replace(/\{(\w+)\}/g, (m, name) => (params && name in params ? String(params[name]) : m));
}

export const getLang = () => lang;

/** Keys looked up that the current (or fallback) catalogue lacked, as 'lang:key'. */
export const missingKeys = () => [...missing].sort();

/** Keys some language has that another lacks, as 'lang:key' (whether or not they were shown). */
export function catalogGaps() {
  const all = new Set(Object.values(catalogs).flatMap((c) => Object.keys(c)));
  const gaps = [];
  for (const [code, c] of Object.entries(catalogs)) for (const k of all) if (!(k in c)) gaps.push(`${code}:${k}`);
  return gaps.sort();
}

/** Calls fn(lang) after every language change; returns a function that stops it. */
export function onLangChange(fn) {
  listeners.add(fn);
  return () => listeners.delete(fn);
}

/** Switches language: keeps the choice, sets <html lang>, re-translates the static page, tells the listeners. */
export function setLang(tag) {
  const next = catalogs[tag] ? tag : normaliseLang(tag);
  const changed = next !== lang;
  lang = next;
  numberFormats = new Map();
  pluralRules = null;
  try {
    globalThis.localStorage?.setItem(STORAGE_KEY, lang);
  } catch {
    // not kept: the browser's languages decide again next time
  }
  if (globalThis.document) {
    document.documentElement.lang = lang;
    applyTranslations(document);
  }
  if (changed) for (const fn of listeners) fn(lang);
  return lang;
}

/**
 * Translates static HTML under `root`: data-i18n="key" sets the element's text (so it must hold
 * text only: wrap text that sits next to an <input> in a <span>); data-i18n-attr="title:key;aria-label:key2"
 * sets attributes.
 */
export function applyTranslations(root = globalThis.document) {
  if (!root?.querySelectorAll) return;
  const all = (sel) => [...(root.matches?.(sel) ? [root] : []), ...root.querySelectorAll(sel)];
  for (const node of all('[data-i18n]')) node.textContent = t(node.dataset.i18n);
  for (const node of all('[data-i18n-attr]')) {
    for (const pair of node.dataset.i18nAttr.split(';')) {
      const [attr, key] = pair.split(':').map((s) => s.trim());
      if (attr && key) node.setAttribute(attr, t(key));
    }
  }
}

/** Fills `select` with the languages and switches when it changes. */
export function bindSwitch(select) {
  select.replaceChildren(...LANGS.map(([code, name]) => Object.assign(document.createElement('option'), { value: code, textContent: name })));
  select.value = lang;
  select.addEventListener('change', () => setLang(select.value));
  onLangChange((l) => {
    select.value = l;
  });
}

/**
 * `x` with exactly `digits` decimals and the user's decimal sign (UI only; never for G-code); '?' when not
 * a number. No thousands grouping: "1.234" would read as a decimal to half the users and "1,234" to the other.
 */
export function fmtNumber(x, digits = 0) {
  const n = Number(x);
  if (x === null || x === undefined || x === '' || !Number.isFinite(n)) return '?';
  let f = numberFormats.get(digits);
  if (!f) {
    f = new Intl.NumberFormat(lang, { minimumFractionDigits: digits, maximumFractionDigits: digits, useGrouping: false });
    numberFormats.set(digits, f);
  }
  return f.format(n);
}

/** A length in mm for the UI: "1234.5 mm" / "1234,5 mm". */
export const fmtLength = (mm, digits = 1) => (Number.isFinite(Number(mm)) && mm !== null ? `${fmtNumber(mm, digits)} mm` : '?');

register({
  en: { 'lang.label': 'Language / Idioma' },
  'pt-BR': { 'lang.label': 'Language / Idioma' },
});

lang = initialLang();
if (globalThis.document?.documentElement) document.documentElement.lang = lang;
