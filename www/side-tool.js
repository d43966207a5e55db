// kerfcam page: a router profile's side chosen per loop (issue 43 §1). With the tool on, a click on a contour
// in the preview cuts that loop outside, inside or on the line (the side chosen beside the button); the other
// loops go to their waste side. A new side on the same loop replaces the old; "Undo" takes the last one back.
// The sides are the file's own (like its start points and tabs), kept by the loop they were set on
// (choices.js), and go to the engine as `sides_at`; one that cannot apply (not a router profile, an open
// contour) is named in the engine's "sides-not-applied" warning, never moved to another loop.

import { onLangChange, register, t } from './i18n.js';
import { choiceOf, sameLoop } from './choices.js';

register({
  en: {
    'sides.label': 'Profile side of one contour',
    'sides.outside': 'outside',
    'sides.inside': 'inside',
    'sides.on': 'on the line',
    'sides.place': 'Set by clicking',
    'sides.undo': 'Undo the last side',
    'sides.clear': 'Remove the sides set',
    'sides.hint': 'Click on a contour in the preview: it is cut on the side chosen. Escape ends.',
    'sides.count': '{count} contour(s) with their own side.',
    'sides.none': 'No closed contour there: an open one has no inside or outside.',
  },
  'pt-BR': {
    'sides.label': 'Lado do perfil de um contorno',
    'sides.outside': 'por fora',
    'sides.inside': 'por dentro',
    'sides.on': 'sobre a linha',
    'sides.place': 'Definir clicando',
    'sides.undo': 'Desfazer o último lado',
    'sides.clear': 'Remover os lados definidos',
    'sides.hint': 'Clique em um contorno na visualização: ele é cortado do lado escolhido. Esc encerra.',
    'sides.count': '{count} contorno(s) com lado próprio.',
    'sides.none': 'Nenhum contorno fechado ali: um aberto não tem lado de dentro nem de fora.',
  },
});

export class SideTool {
  /**
   * `ui`: { side (select), place, undo, clear, hint, status, stage }; `ctx`: { job() (the file shown, whose
   * `sidesAt` holds `{ at, on, side }` each), pickAt(x, y, reach) (engine), keep(placed), scale() (CSS px per
   * mm), run(), stopOthers() }.
   */
  constructor(ui, ctx) {
    Object.assign(this, { ui, ctx, active: false });
    ui.place.addEventListener('click', () => this.setActive(!this.active));
    ui.undo.addEventListener('click', () => this.change((list) => list.pop()));
    ui.clear.addEventListener('click', () => this.change((list) => list.splice(0)));
    document.addEventListener('keydown', (e) => e.key === 'Escape' && this.active && this.setActive(false));
    onLangChange(() => this.show()); // the count in the page's language
    this.show();
  }

  setActive(on) {
    if (on) this.ctx.stopOthers();
    this.active = on;
    this.ui.place.setAttribute('aria-pressed', String(on));
    this.ui.hint.hidden = !on;
    this.ui.stage.classList.toggle('picking', on);
  }

  sides() {
    return this.ctx.job()?.sidesAt ?? [];
  }

  /** Adds the job's sides to the settings. */
  settings(settings, job) {
    settings.sides_at = (job ?? this.ctx.job())?.sidesAt ?? [];
    return settings;
  }

  /** The tool's buttons and count for the file shown. */
  show(said = '') {
    const n = this.sides().length;
    this.ui.undo.disabled = !n;
    this.ui.clear.disabled = !n;
    this.ui.status.textContent = said || (n ? t('sides.count', { count: n }) : '');
  }

  change(edit) {
    const job = this.ctx.job();
    if (!job?.sidesAt?.length) return;
    edit(job.sidesAt);
    this.ctx.keep(false);
    this.show();
    this.ctx.run();
  }

  /** A click at program point (x, y) mm while the tool is on: the loop there gets the side chosen. */
  async click(x, y) {
    const job = this.ctx.job();
    if (!job) return;
    const pick = await this.ctx.pickAt(x, y, 12 / this.ctx.scale());
    if (!pick) {
      this.show(t('sides.none'));
      return;
    }
    // One side a loop: a new one on the same loop replaces it.
    const list = (job.sidesAt ??= []);
    job.sidesAt = [...list.filter((c) => !sameLoop(c, pick)), { ...choiceOf(pick), side: this.ui.side.value }];
    this.ctx.keep(true);
    this.show();
    this.ctx.run();
  }
}
