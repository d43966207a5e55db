// kerfcam progress bar: the pipeline's stages (reading, chaining, offset, planning, G-code) as the
// engine worker finishes them, each with what it made and how long it took, so the operator sees
// a big file move along and can cancel it (issue 6 §2).

import { fmtNumber, onLangChange, register, t } from './i18n.js';

export const STAGES = ['reading', 'chaining', 'offset', 'planning', 'gcode'];

register({
  en: {
    'progress.label': 'Progress',
    'stage.reading': 'reading the DXF',
    'stage.chaining': 'finding contours',
    'stage.offset': 'kerf offset',
    'stage.planning': 'planning the cuts',
    'stage.gcode': 'writing G-code',
    'stage.working': '{stage}…',
    'stage.done.reading': { one: '{n} entity read', other: '{n} entities read' },
    'stage.done.chaining': { one: '{n} contour', other: '{n} contours' },
    'stage.done.offset': { one: '{n} kerf path', other: '{n} kerf paths' },
    'stage.done.planning': { one: '{n} pierce', other: '{n} pierces' },
    'stage.done.gcode': '{kb} kB of G-code',
    'stage.time': '{s} s',
  },
  'pt-BR': {
    'progress.label': 'Progresso',
    'stage.reading': 'lendo o DXF',
    'stage.chaining': 'achando os contornos',
    'stage.offset': 'compensação da sangria',
    'stage.planning': 'planejando os cortes',
    'stage.gcode': 'gerando o código G',
    'stage.working': '{stage}…',
    'stage.done.reading': { one: '{n} entidade lida', other: '{n} entidades lidas' },
    'stage.done.chaining': { one: '{n} contorno', other: '{n} contornos' },
    'stage.done.offset': { one: '{n} trajetória compensada', other: '{n} trajetórias compensadas' },
    'stage.done.planning': { one: '{n} perfuração', other: '{n} perfurações' },
    'stage.done.gcode': '{kb} kB de código G',
    'stage.time': '{s} s',
  },
});

/** What one finished stage made, e.g. "12 345 entities read (0.8 s)". */
export function stageDoneText({ stage, count, ms }) {
  const made = stage === 'gcode'
    ? t('stage.done.gcode', { kb: fmtNumber(count / 1024, 1) })
    : t(`stage.done.${stage}`, { n: fmtNumber(count), count });
  return `${made} (${t('stage.time', { s: fmtNumber(ms / 1000, 2) })})`;
}

export class Progress {
  /** `box` holds `bar` (a <progress>) and `text` (where the stages are written). */
  constructor({ box, bar, text }) {
    Object.assign(this, { box, bar, text });
    this.bar.max = STAGES.length;
    this.done = [];
    onLangChange(() => this.render());
  }

  /** A job starts: the bar at 0, the first stage named. */
  start() {
    this.done = [];
    this.box.classList.remove('idle');
    this.render();
  }

  /** The engine finished a stage. */
  stage(p) {
    if (!STAGES.includes(p.stage)) return;
    this.done.push(p);
    this.render();
  }

  /** The job ended (result, error or cancel): the bar goes out of sight. */
  finish() {
    // Hidden but still taking its place: the preview below must not change size (that would
    // render a big job twice).
    this.box.classList.add('idle');
  }

  /** The finished stages so far, for a caller that keeps them (e.g. the batch list). */
  get stages() {
    return [...this.done];
  }

  render() {
    const n = this.done.length;
    this.bar.value = n;
    const next = STAGES[n];
    const lines = this.done.map((p) => `${t(`stage.${p.stage}`)}: ${stageDoneText(p)}`);
    if (next) lines.push(t('stage.working', { stage: t(`stage.${next}`) }));
    this.text.textContent = lines.join(' · ');
    this.bar.setAttribute('aria-valuetext', next ? t(`stage.${next}`) : t('stage.gcode'));
  }
}
