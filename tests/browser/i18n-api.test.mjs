// Unit test of www/i18n.js without a browser: catalogues per module, fallback and its record,
// plurals, placeholders and locale numbers. (The page itself is tested in i18n.test.mjs.)

import assert from 'node:assert/strict';
import { test } from 'node:test';
import {
  catalogGaps, fmtLength, fmtNumber, getLang, missingKeys, normaliseLang, onLangChange, register, setLang, t,
} from '../../www/i18n.js';

register({
  en: { 'x.hello': 'Hello {name}', 'x.holes': { one: '{count} hole', other: '{count} holes' }, 'x.only-en': 'only English' },
  'pt-BR': { 'x.hello': 'Olá {name}', 'x.holes': { one: '{count} furo', other: '{count} furos' } },
});

test('placeholders, plurals and the fallback to English, recorded', () => {
  setLang('en');
  assert.equal(t('x.hello', { name: 'Ana' }), 'Hello Ana');
  assert.equal(t('x.holes', { count: 1 }), '1 hole');
  assert.equal(t('x.holes', { count: 3 }), '3 holes');
  assert.deepEqual(missingKeys(), []);
  const seen = [];
  const stop = onLangChange((l) => seen.push(l));
  setLang('pt-BR');
  stop();
  assert.deepEqual(seen, ['pt-BR']);
  assert.equal(getLang(), 'pt-BR');
  assert.equal(t('x.hello', { name: 'Ana' }), 'Olá Ana');
  assert.equal(t('x.holes', { count: 1 }), '1 furo');
  assert.equal(t('x.holes', { count: 2 }), '2 furos');
  assert.deepEqual(missingKeys(), []);
  assert.equal(t('x.only-en'), 'only English');
  assert.deepEqual(missingKeys(), ['pt-BR:x.only-en']);
  assert.ok(catalogGaps().includes('pt-BR:x.only-en'));
  assert.equal(t('x.nowhere'), 'x.nowhere');
  assert.ok(missingKeys().includes('en:x.nowhere'));
});

test('numbers in the locale, never NaN', () => {
  setLang('pt-BR');
  assert.equal(fmtNumber(1234.5, 1), '1234,5');
  assert.equal(fmtLength(12.345), '12,3 mm');
  setLang('en');
  assert.equal(fmtNumber(1234.5, 1), '1234.5');
  assert.equal(fmtLength(12.345), '12.3 mm');
  assert.equal(fmtNumber(NaN, 1), '?');
  assert.equal(fmtLength(undefined), '?');
  assert.equal(fmtLength(null), '?');
});

test('language tags', () => {
  assert.equal(normaliseLang('pt'), 'pt-BR');
  assert.equal(normaliseLang('pt-PT'), 'pt-BR');
  assert.equal(normaliseLang('de-DE'), 'en');
  assert.equal(setLang('PT-br'), 'pt-BR');
  assert.equal(setLang('fr'), 'en');
});
