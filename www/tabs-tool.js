// kerfcam page: tabs placed by a click (issue 20 §6). With the tool on, a click on a contour in the
// preview leaves a tab there (the engine centres it where the click falls on the contour's kerf path,
// Tab width wide, beside the automatic tabs per part); a click on a placed tab removes it; "Undo" takes
// the last one back. The points are the file's own (like its start points) and go to the engine as
// `tabs_at`; the plan it returns draws the tabs and writes them in the program, as the automatic ones.

import { register, t } from './i18n.js';
import { choiceOf, pointOf } from './choices.js';

register({
  en: {
    'tabs.place': 'Place tabs by clicking',
    'tabs.undo': 'Undo the last tab',
    'tabs.clear': 'Remove placed tabs',
    'tabs.hint': 'Click on a contour in the preview: a tab is left there. Click on a placed tab to remove it; Escape ends.',
    'tabs.count': '{count} tab(s) placed by hand.',
  },
  'pt-BR': {
    'tabs.place': 'Colocar pontes clicando',
    'tabs.undo': 'Desfazer a última ponte',
    'tabs.clear': 'Remover as pontes colocadas',
    'tabs.hint': 'Clique em um contorno na visualização: uma ponte fica ali. Clique em uma ponte colocada para removê-la; Esc encerra.',
    'tabs.count': '{count} ponte(s) colocada(s) à mão.',
  },
});

export class TabsTool {
  /**
   * `ui`: { place, undo, clear, hint, status, stage }; `ctx`: { job() (the file shown, whose `tabsAt` holds
   * the tabs as choices.js keeps them), pickAt(x, y, reach) (engine), keep(placed) (the file's choices kept;
   * `placed`: a new point, in the frame of the plan shown), scale() (CSS px per mm), width() (the tab width, mm), run(), stopOthers() (other preview tools off) }.
   */
  constructor(ui, ctx) {
    Object.assign(this, { ui, ctx, active: false });
    ui.place.addEventListener('click', () => this.setActive(!this.active));
    ui.undo.addEventListener('click', () => this.change((list) => list.pop()));
    ui.clear.addEventListener('click', () => this.change((list) => list.splice(0)));
    document.addEventListener('keydown', (e) => e.key === 'Escape' && this.active && this.setActive(false));
    this.show();
  }

  setActive(on) {
    if (on) this.ctx.stopOthers();
    this.active = on;
    this.ui.place.setAttribute('aria-pressed', String(on));
    this.ui.hint.hidden = !on;
    this.ui.stage.classList.toggle('picking', on);
  }

  points() {
    return this.ctx.job()?.tabsAt ?? [];
  }

  /** Adds the job's placed tabs to the settings (`{ at, on }` each, choices.js). */
  settings(settings, job) {
    settings.tabs_at = (job ?? this.ctx.job())?.tabsAt ?? [];
    return settings;
  }

  /** The tool's buttons and count for the file shown. */
  show() {
    const n = this.points().length;
    this.ui.undo.disabled = !n;
    this.ui.clear.disabled = !n;
    this.ui.status.textContent = n ? t('tabs.count', { count: n }) : '';
  }

  change(edit) {
    const job = this.ctx.job();
    if (!job?.tabsAt?.length) return;
    edit(job.tabsAt);
    this.ctx.keep(false);
    this.show();
    this.ctx.run();
  }

  /** A click at program point (x, y) mm while the tool is on: remove the placed tab there, or place one. */
  async click(x, y) {
    const job = this.ctx.job();
    if (!job) return;
    const reach = 12 / this.ctx.scale();
    const list = (job.tabsAt ??= []);
    const near = list.findIndex((c) => {
      const [tx, ty] = pointOf(c);
      return Math.hypot(tx - x, ty - y) <= Math.max(reach, this.ctx.width() / 2);
    });
    if (near >= 0) {
      list.splice(near, 1);
    } else {
      const pick = await this.ctx.pickAt(x, y, reach);
      if (!pick) return;
      list.push(choiceOf(pick));
    }
    this.ctx.keep(near < 0);
    this.show();
    this.ctx.run();
  }
}
