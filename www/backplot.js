// kerfcam page: the backplot — a G-code file re-read by the engine and drawn in place of the plan,
// with its own legend, and "Back to the plan". Split out of main.js (issue 15 item 7).

import { app, messageOf, setStatus, showError, state, ui, $ } from './app.js';
import { fmtNumber, getLang, t } from './i18n.js';
import { draw, fitView } from './view.js';

/** Leaves the backplot and shows the current job's plan again. */
export function closeBackplot() {
  if (!state.backplot) return;
  state.backplot = null;
  ui.backplotClose.hidden = true;
  ui.backplotInfo.hidden = true;
  showLegend(false);
  // The status the plan had (it stayed at "backplot"): ready, or the error or wait it was in.
  setStatus(state.job ? 'ready' : state.statusBefore || 'waiting for a file');
  app.planLayer.setMoves(state.job ? state.job.moves : null);
  if (state.job) fitView();
  else ui.placeholder.hidden = !!state.file;
  draw();
}

/** The plan's legend, or the backplot's (a program re-read: cuts, feeds with the torch off, rapids). */
export function showLegend(backplot) {
  $('legend').hidden = backplot;
  $('legend-backplot').hidden = !backplot;
}

/** What the backplot re-read, in the current language. */
export function showBackplotInfo() {
  const info = state.backplot?.info;
  if (!info) return;
  const w = info.warnings[0];
  ui.backplotInfo.textContent = t('backplot.info', { name: info.name, moves: fmtNumber(info.moves) }) +
    (w ? t('backplot.not-understood', {
      count: info.warnings.length, line: w.line, message: w.messages?.[getLang()] ?? w.message,
    }) : '');
}

export function wireBackplot() {
  ui.backplotInput.addEventListener('change', async () => {
    const file = ui.backplotInput.files[0];
    ui.backplotInput.value = '';
    if (!file || !app.engineReady) return;
    try {
      setStatus('working');
      const text = await file.text();
      const b = JSON.parse(await app.engine.call('backplot', {
        text, feed: app.numbers.value('feed') || app.defaults.feed, rapid: app.numbers.value('rapid') || app.defaults.rapid,
      }));
      app.inspector.reset(); // no inspect text nor measure of the plan over a program being looked at
      if (!state.backplot) state.statusBefore = ui.status.dataset.state; // what "Back to the plan" puts back
      state.backplot = { bbox: b.bbox, moves: new Float64Array(b.moves), name: file.name };
      window.kerfcam.lastBackplot = { name: file.name, moves: b.moves.length / 7, warnings: b.warnings };
      app.planLayer.setMoves(state.backplot.moves, { showAll: true });
      state.backplot.info = { name: file.name, moves: b.moves.length / 7, warnings: b.warnings };
      showBackplotInfo();
      showLegend(true);
      ui.backplotInfo.hidden = false;
      ui.backplotClose.hidden = false;
      ui.placeholder.hidden = true;
      fitView();
      await draw();
      setStatus('backplot');
    } catch (e) {
      showError(t('error.backplot', { name: file.name, message: messageOf(e) }));
      setStatus('error');
    }
  });
  ui.backplotClose.addEventListener('click', () => closeBackplot());
}
