// kerfcam page: open a DXF, run the wasm Job in the engine worker, show the preview and summary,
// download the G-code. The page's main thread never runs the pipeline: it stays responsive and can cancel.
// Everything that comes from the file or the report is shown with textContent: layer names and messages are data.
// This module starts the page and wires the settings; each panel has its own module (issue 15 item 7):
// app.js (what they share), job.js (running a job), view.js (the preview), layers.js, backplot.js,
// jobsheet.js, layout.js (glance, compare box, folds); Sheet mode: sheet.js (parts, sheet) and
// nest-run.js (the nest, its progress and result, the sheet into the cut plan).

import { $, CHOICES, app, messageOf, setStatus, showError, state, ui, keepChoices } from './app.js';
import { showBackplotInfo, wireBackplot } from './backplot.js';
import { Batch, programName } from './batch.js';
import { download } from './download.js';
import { engineSupported } from './browser-check.js';
import { Engine } from './engine.js';
import { loadFiles } from './file-store.js';
import { applyTranslations, bindSwitch, getLang, onLangChange, t } from './i18n.js';
import { Inspector } from './inspect.js';
import { fail, openFiles, readSettings, run, showJob, showSummary } from './job.js';
import { closeSheet, wireSheet } from './jobsheet.js';
import { refreshLayerTools, showLayers, wireLayers } from './layers.js';
import { CostPanel } from './cost.js';
import { CompareBox, Glance, SheetViews, keepFolds, orderHelp, reveal } from './layout.js';
import { NestEdit } from './nest-edit.js';
import { NestFile } from './nest-file.js';
import { NestRun } from './nest-run.js';
import { NumberFields, parseNumber } from './numbers.js';
import { Origin, frameOf } from './origin.js';
import './page-strings.js';
import { PlanLayer, showComparison } from './plan.js';
import { Posts } from './posts.js';
import { ProcessPanel } from './process.js';
import { Materials } from './materials.js';
import { Losses } from './losses.js';
import { TabsTool } from './tabs-tool.js';
import { SideTool } from './side-tool.js';
import { Progress } from './progress.js';
import { Summary } from './summary.js';
import { ToolPanel } from './tool.js';
import { resetSettings, restoreSettings, saveSettings } from './settings-store.js';
import { SheetPanel, sheetName } from './sheet.js';
import { baseName, fitView, overlayView, pointAt, requestDraw, setPicking, showBox, wireView, zoomTo } from './view.js';

const utf8 = new TextDecoder();
// The shown program as text, decoded when asked (the page itself keeps and saves the bytes).
Object.defineProperty(window.kerfcam, 'lastGcode', { get: () => (state.gcode ? utf8.decode(state.gcode) : null) });

function wire() {
  ui.file.addEventListener('change', () => {
    openFiles(ui.file.files);
    ui.file.value = ''; // picking the same file again adds it again
  });

  let typing; // re-run shortly after typing stops, at once when a value is committed
  const rerun = (delay) => {
    clearTimeout(typing);
    typing = setTimeout(run, delay);
  };
  // Cancel also drops a re-run still waiting for typing to stop: it would start the job again
  // right after the operator stopped it.
  ui.cancel.addEventListener('click', () => {
    clearTimeout(typing);
    app.engine?.cancel();
  });
  for (const input of Object.values(app.numbers.inputs)) {
    input.addEventListener('input', () => rerun(400));
    input.addEventListener('change', () => rerun(0));
  }
  ui.form.addEventListener('submit', (e) => e.preventDefault());
  ui.planForm.addEventListener('submit', (e) => e.preventDefault());
  for (const select of [...Object.values(CHOICES).map((id) => ui[id]), ui.cutOpen]) {
    select.addEventListener('change', () => rerun(0));
  }
  ui.order.addEventListener('change', () => { if (state.current) state.current.order = ui.order.value; });
  ui.compare.addEventListener('click', async () => {
    if (!state.job) return;
    try {
      setStatus('working');
      const rows = JSON.parse(await app.engine.call('compare'));
      setStatus('ready');
      window.kerfcam.lastComparison = rows;
      showComparison(ui.comparison, rows);
      app.compareBox.shown();
    } catch (e) {
      showError(t('error.compare', { message: messageOf(e) }));
    }
  });
  ui.clearStarts.addEventListener('click', () => {
    state.starts = [];
    keepChoices();
    run();
  });
  ui.origin.addEventListener('change', () => {
    clearTimeout(typing);
    run({ fit: true }); // everything moves: fit it again
  });
  ui.units.addEventListener('change', () => {
    clearTimeout(typing);
    run({ fit: true }); // a new unit rescales the drawing: fit it again
  });

  const dragging = (on) => document.body.classList.toggle('dragging', on);
  document.addEventListener('dragover', (e) => {
    e.preventDefault();
    dragging(true);
  });
  document.addEventListener('dragleave', (e) => {
    if (!e.relatedTarget) dragging(false); // left the window
  });
  document.addEventListener('drop', (e) => {
    e.preventDefault();
    dragging(false);
    openFiles(e.dataTransfer?.files);
  });

  ui.download.addEventListener('click', () => {
    if (!state.job) return;
    download(new Blob([state.gcode], { type: 'text/plain' }), programName(state.name));
  });
}

/** After a language switch: everything the page wrote itself, again, from what it kept (no re-run). */
function retranslate() {
  setStatus(ui.status.dataset.state);
  const report = window.kerfcam.lastReport;
  if (report) showSummary(report);
  else if (!state.job) {
    app.summary?.clear(state.name);
    app.glance?.clear(state.name);
    if (state.layersOf) showLayers(state.layersOf.layers); // kept through a failed run
  }
  app.origin?.update();
  app.planLayer?.draw(); // the overlay's own words (the note on numbers left out)
  if (window.kerfcam.lastComparison && state.job && ui.comparison.rows.length) showComparison(ui.comparison, window.kerfcam.lastComparison);
  showBackplotInfo();
}

/**
 * Sheet mode (issue 18): the parts list and sheet (sheet.js), the nest (nest-run.js); app.sheet is what
 * job.js asks: active, cutting() (the nest's sheet to cut) and settings() (the page's, for the nest).
 */
function wireSheetMode() {
  let nest = null;
  let edit = null;
  const panel = new SheetPanel({
    engine: () => app.engine,
    kerf: () => parseNumber(ui.kerf.value),
    cutting: () => {
      try {
        // The nest is in mm and reads every layer of a parts file; the rest is the page's.
        return { ...readSettings(), units: null, layers: null, layer_ops: [], starts: [], tabs_at: [], sides_at: [], lang: getLang() };
      } catch {
        return null; // a field out of range is marked on it; the parts are read with the defaults meanwhile
      }
    },
    onChange: () => nest?.changed(),
    // The sheet costs are in the Cost panel's currency (issue 44 item 3): said beside them and in the nest's result.
    currency: () => $('cost-currency')?.value.trim() ?? '',
    onMode: (on) => {
      edit.shown(on);
      if (on) {
        state.runId++; // a drawing's run in flight no longer matters
        Object.assign(state, { current: null, file: null, name: '', layers: null, layersOf: null, starts: [] });
        app.batch?.setShown(null);
        fail('', 'waiting for a file');
        if (nest.cutting()) {
          state.name = sheetName(nest.k);
          run({ fit: true });
        }
      } else {
        state.name = '';
        showJob(app.batch?.shown ?? app.batch?.jobs?.[0] ?? null);
      }
    },
  });
  edit = new NestEdit({
    engine: () => app.engine,
    panel,
    k: () => nest.k,
    changed: () => nest.edited(edit.state),
  });
  nest = new NestRun(panel, {
    engine: () => app.engine,
    edit,
    recut: () => run(),
    show: (k) => {
      state.name = sheetName(k);
      state.starts = [];
      run({ fit: true });
    },
  });
  $('cost-currency').addEventListener('input', () => app.sheet.currencyChanged());
  ui.kerf.addEventListener('input', () => panel.kerfChanged());
  ui.kerf.addEventListener('change', () => panel.kerfChanged());
  app.sheet = {
    get active() { return panel.active; },
    addFiles: (files) => panel.addFiles(files),
    cutting: () => nest.cutting(),
    settings: (s) => nest.settings(s),
    bbox: (b) => nest.bbox(b),
    // The job report (issue 42 §4): every sheet cut with the settings the preview cuts the sheet shown with.
    report: () => nest.report({ ...nest.settings(readSettings()), lang: getLang() }),
    files: () => panel.parts.map((p) => p.name),
    setDefaults: (d) => panel.setDefaults(d),
    currencyChanged: () => {
      panel.currencyChanged();
      nest.showResult();
    },
  };
  app.planLayer.decorations.push((ctx, px, dpr) => nest.decorate(ctx, px, dpr));
  // Issue 42 §5: the nest, the cut plan or both in the window; the preview shown again is fitted to its size.
  app.sheetViews = new SheetViews($('sheet-views'), {
    shown: () => {
      if (!state.job) return;
      fitView();
      requestDraw();
    },
  });
  const file = new NestFile({ engine: () => app.engine, panel, nest, edit });
  window.kerfcam.sheet = { panel, nest, edit, file };
}

/** Offline: the service worker keeps a copy of the app (served over http only; file:// has none). */
function registerOffline() {
  if (!('serviceWorker' in navigator) || !location.protocol.startsWith('http')) return;
  navigator.serviceWorker.register('./sw.js').catch((e) => console.warn(`offline copy unavailable: ${messageOf(e)}`));
}

// The forms whose values survive a reload, and the controls outside them.
const kept = () => [[ui.form, ui.planForm, $('process-settings'), $('tool-settings')], [$('post'), ui.speed]];

async function start() {
  registerOffline();
  applyTranslations(document);
  setStatus('loading');
  bindSwitch($('lang'));
  onLangChange(retranslate);
  restoreSettings(...kept());
  app.numbers = new NumberFields([ui.form, ui.planForm, $('process-settings'), $('tool-settings')]);
  app.numbers.relocalise(); // the kept or default values with this language's decimal sign
  for (const f of kept()[0]) f.addEventListener('change', () => saveSettings(...kept()));
  app.process = new ProcessPanel(
    {
      tabHoles: $('tab-holes'), repair: $('repair'), controllerComp: $('controller-comp'), verify: $('verify'), result: $('verify-result'),
      fitArcs: $('fit-arcs'), incremental: $('incremental'),
      heat: $('verify-heat'), legend: [$('legend-overcut'), $('legend-attached')],
    },
    () => run(),
    () => app.planLayer.draw(),
  );
  $('process-settings').addEventListener('submit', (e) => e.preventDefault());
  app.tool = new ToolPanel({
    panel: $('panel-tool'), form: $('tool-settings'), engraving: $('v-engraving'),
    list: $('tool-list'), listHead: $('tool-list-head'), listTable: $('tool-list-table'), addTool: $('add-tool'),
    onList: () => refreshLayerTools(),
  }, () => run());
  $('tool-settings').addEventListener('submit', (e) => e.preventDefault());
  for (const c of [$('post'), ui.speed]) c.addEventListener('change', () => saveSettings(...kept()));
  $('reset-settings').addEventListener('click', () => {
    resetSettings(...kept());
    app.materials?.lockJobFields(); // a chosen material's values stay in its locked fields
    app.numbers.relocalise();
    app.updateOrderHelp();
    ui.origin.dispatchEvent(new Event('change')); // stops picking a point when the origin goes back to automatic
    ui.speed.dispatchEvent(new Event('change'));
    run();
  });
  keepFolds(document.querySelector('.side'));
  app.updateOrderHelp = orderHelp(ui.order, $('order-help'));
  app.glance = new Glance($('glance'), () => reveal($('panel-summary'), ui.warnings));
  app.compareBox = new CompareBox({ box: $('compare-box'), table: ui.comparison, close: $('compare-close'), button: ui.compare });
  app.planLayer = new PlanLayer(
    { overlay: ui.overlay, play: ui.play, speed: ui.speed, scrub: ui.scrub, time: ui.animTime },
    overlayView,
  );
  app.progress = new Progress({ box: ui.progress, bar: ui.progressBar, text: ui.progressText });
  app.inspector = new Inspector(
    { canvas: ui.canvas, tip: ui.tip, readout: ui.readout, measureButton: ui.measure },
    {
      engine: { call: (...a) => app.engine.call(...a) },
      pointAt,
      scale: () => state.view?.scale || 1,
      planLayer: app.planLayer,
      active: () => !!state.job && !state.backplot && !state.picking && !app.origin?.picking && app.engineReady,
    },
  );
  app.losses = new Losses({ download: ui.download, legend: $('legend-loss') }, { redraw: () => app.planLayer.draw(), showBox });
  window.kerfcam.losses = () => app.losses; // what is marked and whether it was seen, for tests
  window.kerfcam.lastMeasure = () => app.inspector.result ?? null;
  window.kerfcam.heat = () => app.process.heat; // the verification's squares drawn, for tests
  window.kerfcam.playMoves = () => state.job?.moves ?? null; // what Play animates (Job.moves()), for tests
  window.kerfcam.inspected = () => app.inspector.pinned ?? null;
  window.kerfcam.labelStats = () => app.planLayer.labelStats ?? null; // the sequence numbers drawn (level of detail)
  app.summary = new Summary(
    {
      summary: ui.summary, warnings: ui.warnings, warningCount: ui.warningCount, notes: ui.notes, notesList: ui.notesList,
      notesCount: ui.notesCount, healing: ui.healing, healingList: ui.healingList, healingCount: ui.healingCount,
    },
    {
      zoomTo,
      units: () => ({ chosen: state.current?.units ?? null, global: ui.units.value }),
      losses: app.losses,
      onUnits: (unit) => {
        if (!state.current) return;
        state.current.units = unit; // kept with the file: it opens in this unit next time
        keepChoices();
        run({ fit: true });
      },
    },
  );
  app.origin = new Origin(
    { select: ui.origin, pick: ui.pickOrigin, hint: ui.originHint, row: ui.originRow },
    {
      current: () => state.current,
      report: () => window.kerfcam.lastReport,
      snap: (x, y, reach) => app.engine.call('snap', { x, y, reach }),
      scale: () => state.view?.scale || 1,
      onPicked: () => {
        keepChoices();
        run({ fit: true });
      },
      onPicking: (on) => {
        if (on && state.picking) setPicking(false);
        if (on && app.inspector.measuring) app.inspector.setMeasuring(false);
        ui.stage.classList.toggle('picking', on || state.picking); // the crosshair cursor
        app.planLayer.draw(); // the keyboard's aim
      },
    },
  );
  app.planLayer.decorations.push((ctx, px, dpr) => app.origin.decorate(ctx, px, dpr));
  app.tabsTool = new TabsTool(
    { place: $('place-tabs'), undo: $('undo-tab'), clear: $('clear-tabs'), hint: $('tabs-hint'), status: $('tabs-status'), stage: ui.stage },
    {
      job: () => state.current,
      pickAt: (x, y, reach) => app.engine.call('pickAt', { x, y, reach }),
      keep: (placed) => {
        // A tab placed now is in the frame of the plan shown; kept with the file (batch.js record).
        if (placed && state.current) state.current.startsFrame = frameOf(window.kerfcam.lastReport);
        keepChoices();
      },
      scale: () => state.view?.scale || 1,
      width: () => app.numbers.value('tab_width') || 0,
      run: () => run(),
      stopOthers: () => {
        if (state.picking) setPicking(false);
        if (app.origin?.picking) app.origin.setPicking(false);
        if (app.inspector?.measuring) app.inspector.setMeasuring(false);
        if (app.sideTool?.active) app.sideTool.setActive(false);
      },
    },
  );
  app.sideTool = new SideTool(
    { side: $('side-choice'), place: $('place-sides'), undo: $('undo-side'), clear: $('clear-sides'), hint: $('sides-hint'), status: $('sides-status'), stage: ui.stage },
    {
      job: () => state.current,
      pickAt: (x, y, reach) => app.engine.call('pickAt', { x, y, reach }),
      keep: (placed) => {
        // A side set now is in the frame of the plan shown; kept with the file (batch.js record).
        if (placed && state.current) state.current.startsFrame = frameOf(window.kerfcam.lastReport);
        keepChoices();
      },
      scale: () => state.view?.scale || 1,
      run: () => run(),
      stopOthers: () => {
        if (state.picking) setPicking(false);
        if (app.origin?.picking) app.origin.setPicking(false);
        if (app.inspector?.measuring) app.inspector.setMeasuring(false);
        if (app.tabsTool?.active) app.tabsTool.setActive(false);
      },
    },
  );
  // The verification's heat map, over the plan it checked (not over a program re-read by the backplot).
  app.planLayer.decorations.push((ctx, px, dpr) => !state.backplot && app.process.decorate(ctx, px, dpr));
  // The parts the cuts take from, on every plan (issue 45 §3); not over a program re-read by the backplot.
  app.planLayer.decorations.push((ctx, px, dpr) => !state.backplot && app.losses.decorate(ctx, px, dpr));
  app.run = run;
  app.closeSheet = closeSheet;
  wire();
  wireView();
  wireLayers();
  wireBackplot();
  wireSheet();
  wireSheetMode();
  if (!engineSupported()) {
    showError(t('error.no-simd'));
    setStatus('error');
    return;
  }
  try {
    app.engine = new Engine();
    // The Cost panel (issue 42 §3): the quote of the shown job — every sheet of the nest in Sheet mode
    // (cut with the settings its sheets are cut with), else the drawing on the preview.
    app.cost = new CostPanel($('panel-cost'), app.engine, () => {
      if (!state.job) return null;
      try {
        if (app.sheet?.active) return { sheet: true, settings: { ...app.sheet.settings(readSettings()), lang: getLang() }, name: 'nest' };
        return { sheet: false, name: baseName() };
      } catch {
        return null; // a setting out of range: the last good quote stays
      }
    });
    window.kerfcam.quote = () => app.cost.last(); // the quote shown, for tests
    app.sheet.currencyChanged(); // the Cost panel's kept currency, restored just now
    app.batch = new Batch(
      { list: ui.jobs, count: ui.jobCount, downloadAll: ui.downloadAll, clear: ui.clearFiles, message: ui.jobMessage },
      {
        engine: app.engine,
        settingsFor: (job) => readSettings(job),
        onShow: (job) => showJob(job),
        previewBusy: () => state.running?.catch(() => {}),
        runShown: async () => {
          await run();
          await state.running?.catch(() => {});
        },
      },
    );
    ui.version.textContent = `v${await app.engine.ready}`;
    // The form's defaults are the engine's: each field shows its default unless a kept value is there.
    app.defaults = JSON.parse(await app.engine.call('defaults'));
    app.numbers.setDefaults(app.defaults);
    app.sheet.setDefaults(app.defaults.nest);
    app.posts = new Posts(
      {
        select: $('post'), about: $('post-about'), edit: $('post-edit'), exportButton: $('post-export'), importInput: $('post-import'),
        message: $('post-message'), dialog: $('post-dialog'), form: $('post-form'), error: $('post-error'),
        cancel: $('post-cancel'),
      },
      app.engine,
      () => {
        const p = app.posts.current();
        if (p && Number.isFinite(p.rapid_speed)) ui.rapid.value = String(p.rapid_speed);
        run();
      },
    );
    await app.posts.load();
    restoreSettings([], [$('post')]); // the post menu is filled only now
    app.posts.fillMenu($('post').value); // its description, and a kept "linuxcnc" shown as the default it equals
    app.materials = new Materials(
      {
        choose: $('material'), note: $('material-note'), list: $('material-list'), form: $('material-form'),
        message: $('material-message'), newButton: $('material-new'), remove: $('material-delete'),
        exportJson: $('material-export-json'), exportCfg: $('material-export-cfg'), importInput: $('material-import'),
        starter: $('material-starter'),
      },
      app.engine,
      () => run(),
    );
    app.materials.defaults = app.defaults;
    await app.materials.load(); // the chart kept in this browser, or the examples
    app.engineReady = true;
    setStatus('waiting for a file');
    if (state.file) {
      await run({ fit: true }); // a file dropped while the wasm was loading
    } else {
      const kept = app.batch.restore(await loadFiles()); // the files of the last visit
      if (kept) await showJob(kept);
    }
  } catch (e) {
    showError(t('error.engine', { message: messageOf(e) }));
    setStatus('error');
  }
}

window.addEventListener('error', (e) => showError(t('error.unexpected', { message: e.message })));
window.addEventListener('unhandledrejection', (e) => showError(t('error.unexpected', { message: messageOf(e.reason) })));
start();
