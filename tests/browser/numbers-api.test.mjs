// Unit test of www/numbers.js and the pure parts of www/origin.js and www/units.js without a browser:
// numbers typed the local way, steps that never drift, the scale bar's lengths, sizes in both units.
// (The page itself is tested in trust.test.mjs.)

import assert from 'node:assert/strict';
import { test } from 'node:test';
import { setLang } from '../../www/i18n.js';
import { FIELDS, formatValue, parseNumber, stepValue } from '../../www/numbers.js';
import { niceLength, rebaseStarts } from '../../www/origin.js';
import { sizeText } from '../../www/units.js';

test('a number typed with a decimal comma or point means the same, in both languages', () => {
  for (const lang of ['en', 'pt-BR']) {
    setLang(lang);
    const cases = [
      ['1,5', 1.5], ['1.5', 1.5], [' 2000 ', 2000], ['-100', -100], ['+3', 3], [',5', 0.5], ['.5', 0.5], ['5,', 5],
      ['1e3', 1000], ['0,001', 0.001], ['10\u00a0000', 10000],
    ];
    for (const [text, value] of cases) assert.equal(parseNumber(text), value, `${lang}: ${JSON.stringify(text)}`);
    // One decimal sign at most (the page never groups thousands): anything else is not a number.
    for (const text of ['', '1,2,3', '1.2.3', '1,234.5', 'abc', '1,5mm', '-', '.', '--1', '0x10', 'Infinity']) {
      assert.ok(Number.isNaN(parseNumber(text)), `${lang}: ${JSON.stringify(text)} is not a number`);
    }
  }
  setLang('en');
});

test('values are written with the language\'s decimal sign and no needless zeros', () => {
  setLang('en');
  assert.equal(formatValue(1.5), '1.5');
  assert.equal(formatValue(2000), '2000');
  assert.equal(formatValue(0.001), '0.001');
  assert.equal(formatValue(0.000001), '0.000001');
  setLang('pt-BR');
  assert.equal(formatValue(1.5), '1,5');
  assert.equal(formatValue(10000), '10000');
  setLang('en');
});

test('each field steps by its own step onto the step\'s grid, within its range, and never drifts', () => {
  assert.equal(FIELDS.kerf.step, 0.1);
  assert.equal(FIELDS.feed.step, 100);
  assert.equal(FIELDS.rapid.step, 1000);
  // The drift: 2000 → 2001 → 1801 with min 1 as the step's base. Here: 2000 → 2100 → 2000.
  assert.equal(stepValue(2000, FIELDS.feed, 1), 2100);
  assert.equal(stepValue(2100, FIELDS.feed, -1), 2000);
  assert.equal(stepValue(2001, FIELDS.feed, 1), 2100);
  assert.equal(stepValue(2001, FIELDS.feed, -1), 2000);
  assert.equal(stepValue(100, FIELDS.feed, -1), 1, 'not below the range');
  assert.equal(stepValue(NaN, FIELDS.feed, 1), 1, 'from nothing: the range\'s start');
  for (const [key, field] of Object.entries(FIELDS)) {
    const start = Math.max(field.min, Number((field.step * 7).toFixed(6)));
    let v = start;
    const seen = [];
    for (let i = 0; i < 60; i++) seen.push((v = stepValue(v, field, 1)));
    for (let i = 0; i < 60; i++) v = stepValue(v, field, -1);
    assert.equal(v, start, `${key}: 60 steps up and down come back`);
    for (const s of seen) {
      const k = s / field.step;
      assert.ok(s === field.max || Math.abs(k - Math.round(k)) < 1e-9, `${key}: ${s} is on the grid of ${field.step}`);
      assert.equal(String(s).length <= 12, true, `${key}: ${s} has no float noise`);
      assert.ok(s >= field.min && s <= field.max, `${key}: ${s} within the range`);
    }
    assert.equal(stepValue(field.max, field, 1), field.max, `${key}: not above the range`);
  }
  assert.equal(stepValue(0.2, FIELDS.kerf, 1), 0.3, 'no 0.30000000000000004');
  assert.equal(stepValue(1.5, FIELDS.kerf, 1, 10), 2.5, 'PageUp: ten steps');
});

test('the scale bar takes a round length; sizes are given in mm and inches', () => {
  assert.equal(niceLength(123), 100);
  assert.equal(niceLength(99), 50);
  assert.equal(niceLength(4.9), 2);
  assert.equal(niceLength(0.07), 0.05);
  assert.equal(niceLength(1), 1);
  setLang('en');
  assert.equal(sizeText({ w: 254, h: 50.8 }), '254.0 × 50.8 mm (10.00 × 2.00 in)');
  assert.equal(sizeText(null), null);
  assert.equal(sizeText({ w: 'x', h: 1 }), null);
  setLang('pt-BR');
  assert.equal(sizeText({ w: 254, h: 50.8 }), '254,0 × 50,8 mm (10,00 × 2,00 pol)');
  setLang('en');
});

test('start points follow the drawing when the origin moves or the file is read in another unit', () => {
  const starts = [[3, 10, 20]];
  const mm0 = { at: [0, 0], units: 'mm' };
  assert.equal(rebaseStarts(starts, mm0, { at: [0, 0], units: 'mm' }), null, 'same frame: nothing moves');
  assert.equal(rebaseStarts([], mm0, { at: [5, 5], units: 'mm' }), null);
  assert.equal(rebaseStarts(starts, null, mm0), null, 'an unknown frame: left as they are');
  assert.deepEqual(rebaseStarts(starts, mm0, { at: [10, 10], units: 'mm' }), [[3, 0, 10]]);
  assert.deepEqual(rebaseStarts([[3, 0, 10]], { at: [10, 10], units: 'mm' }, mm0), starts, 'and back');
  // Read in inches: the file's (10, 20) is (254, 508) mm; the origin (1 in, 1 in) of the drawing.
  assert.deepEqual(rebaseStarts(starts, mm0, { at: [25.4, 25.4], units: 'in' }), [[3, 228.6, 482.6]]);
  assert.deepEqual(rebaseStarts([[3, 228.6, 482.6]], { at: [25.4, 25.4], units: 'in' }, mm0), starts);
});
