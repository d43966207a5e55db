// kerfcam page: the preview — the view (centre and scale), the engine's raster under the plan overlay,
// fit, zoom and pan, the picture and SVG saved, and the mouse and keyboard on the preview.
// Split out of main.js (issue 15 item 7).

import { $, MAX_DPR, app, keepChoices, messageOf, showError, state, ui } from './app.js';
import { baseName as baseOf } from './batch.js';
import { download } from './download.js';
import { t } from './i18n.js';
import { frameOf } from './origin.js';
import { choiceOf, sameLoop } from './choices.js';
import { movesToSvg } from './plan.js';

export const stageSize = () => ui.stage.getBoundingClientRect();

export function fitView() {
  const [x0, y0, x1, y1] = (state.backplot || state.job).bbox;
  const { width, height } = stageSize();
  const w = Math.max(x1 - x0, 1e-3);
  const h = Math.max(y1 - y0, 1e-3);
  state.view = [x0, y0, x1, y1].every(Number.isFinite)
    // A stage not shown (Sheet mode, the nest alone) has no size: fitted again when it is (SheetViews).
    ? { cx: (x0 + x1) / 2, cy: (y0 + y1) / 2, scale: Math.min(width / (w * 1.1), height / (h * 1.1)) || 1 }
    : { cx: 0, cy: 0, scale: 1 };
}

// One render in flight at a time; views asked for meanwhile collapse into one more render.
let rendering = null;
let renderAgain = false;

export async function draw() {
  if (state.backplot && state.view) {
    // A program re-read from its text: nothing but the overlay's moves.
    const { width, height } = stageSize();
    const dpr = Math.min(window.devicePixelRatio || 1, MAX_DPR);
    ui.canvas.width = Math.max(1, Math.round(width * dpr));
    ui.canvas.height = Math.max(1, Math.round(height * dpr));
    const ctx = ui.canvas.getContext('2d');
    ctx.fillStyle = '#fff';
    ctx.fillRect(0, 0, ui.canvas.width, ui.canvas.height);
    app.planLayer.draw();
    return;
  }
  if (!state.job || !state.view) return;
  const shown = stageSize();
  if (!shown.width || !shown.height) return; // the stage not shown (Sheet mode, the nest alone): drawn when it is
  if (rendering) {
    renderAgain = true;
    return rendering;
  }
  rendering = (async () => {
    do {
      renderAgain = false;
      const dpr = Math.min(window.devicePixelRatio || 1, MAX_DPR);
      const { width, height } = stageSize();
      const w = Math.max(1, Math.round(width * dpr));
      const h = Math.max(1, Math.round(height * dpr));
      const { cx, cy, scale } = state.view;
      let rgba;
      window.kerfcam.renders = (window.kerfcam.renders || 0) + 1; // engine renders asked for (tests count them)
      try {
        rgba = await app.engine.call('render', { width: w, height: h, cx, cy, scale: scale * dpr, dpr });
      } catch (e) {
        if (!e.cancelled && state.job) showError(t('error.draw', { message: messageOf(e) }));
        return;
      }
      if (!state.job) return;
      if (ui.canvas.width !== w) ui.canvas.width = w;
      if (ui.canvas.height !== h) ui.canvas.height = h;
      const pixels = new Uint8ClampedArray(rgba.buffer, rgba.byteOffset, rgba.byteLength);
      ui.canvas.getContext('2d').putImageData(new ImageData(pixels, w, h), 0, 0);
      app.planLayer.draw();
    } while (renderAgain);
  })();
  try {
    await rendering;
  } finally {
    rendering = null;
  }
}

/** Fits the preview to the box [x0, y0, x1, y1] mm with a margin (at least 20 mm across: a speck stays in context). */
export function showBox([x0, y0, x1, y1]) {
  if (!state.view || ![x0, y0, x1, y1].every(Number.isFinite)) return;
  const { width, height } = stageSize();
  const w = Math.max(x1 - x0, 20);
  const h = Math.max(y1 - y0, 20);
  state.view = { cx: (x0 + x1) / 2, cy: (y0 + y1) / 2, scale: Math.min(1e4, width / (w * 1.3), height / (h * 1.3)) };
  requestDraw();
}

/** Centres the preview on (x, y) mm, zoomed in to about 40 mm across (never out). */
export function zoomTo(x, y) {
  if (!state.view || !Number.isFinite(x) || !Number.isFinite(y)) return;
  const { width, height } = stageSize();
  const scale = Math.max(state.view.scale, Math.min(width, height) / 40);
  state.view = { cx: x, cy: y, scale: Math.min(scale, 1e4) };
  requestDraw();
  ui.canvas.focus();
}

/** The preview as the user sees it: the plan raster with the overlay (numbers, animation) on top. */
export function composite() {
  const out = document.createElement('canvas');
  out.width = ui.canvas.width;
  out.height = ui.canvas.height;
  const ctx = out.getContext('2d');
  ctx.drawImage(ui.canvas, 0, 0);
  ctx.drawImage(ui.overlay, 0, 0, out.width, out.height);
  return out;
}

/** The preview as the user sees it (plan raster and overlay) as a PNG download. */
export function savePicture() {
  if (!state.job && !state.backplot) return;
  composite().toBlob((blob) => {
    if (!blob) return showError(t('error.picture'));
    download(blob, `${baseName()}.png`);
  }, 'image/png');
}

/**
 * The cut plan as an SVG drawing in mm, written by the engine from the plan the preview shows
 * (`kerfcam FILE -o OUT.svg`: a layer per part with the drawing, kerf path, leads and pierces); a
 * program re-read from its text (a backplot) has only its moves, drawn here.
 */
export async function saveSvg() {
  if (state.backplot) {
    download(new Blob([movesToSvg(state.backplot.moves)], { type: 'image/svg+xml' }), `${baseName()}.svg`);
    return;
  }
  if (!state.job) return;
  try {
    const svg = await app.engine.call('planSvg', { label: state.name || 'drawing' });
    download(new Blob([svg], { type: 'image/svg+xml' }), `${baseName()}.svg`);
  } catch (e) {
    showError(t('error.picture') + ' ' + messageOf(e));
  }
}

/** The open file's name without its extension, for the files the page saves. */
export const baseName = () => baseOf(state.name);

/** The view for the overlay: the same mapping as the preview's pixels. */
export function overlayView() {
  if (!state.view) return null;
  const { width, height } = stageSize();
  return { ...state.view, width, height, dpr: Math.min(window.devicePixelRatio || 1, MAX_DPR) };
}

/** The CSS pixel of the canvas where the drawing point (x, y) mm is shown (for tests and tools). */
window.kerfcam.screenOf = (x, y) => {
  const { width, height } = stageSize();
  const v = state.view;
  return v ? [width / 2 + (x - v.cx) * v.scale, height / 2 - (y - v.cy) * v.scale] : null;
};

/** Puts the drawing point (x, y) mm at the centre of the preview, at the same zoom (for tests and tools). */
window.kerfcam.centreOn = (x, y) => {
  if (!state.view) return;
  state.view = { ...state.view, cx: x, cy: y };
  requestDraw();
};

/** The drawing point (mm) under a CSS pixel of the canvas. */
export function pointAt(px, py) {
  const { width, height } = stageSize();
  const v = state.view;
  return [v.cx + (px - width / 2) / v.scale, v.cy - (py - height / 2) / v.scale];
}

export function setPicking(on) {
  if (on && app.inspector?.measuring) app.inspector.setMeasuring(false);
  if (on && app.tabsTool?.active) app.tabsTool.setActive(false);
  if (on && app.sideTool?.active) app.sideTool.setActive(false);
  if (on && app.origin?.picking) app.origin.setPicking(false);
  state.picking = on;
  ui.setStart.setAttribute('aria-pressed', String(on));
  ui.startHint.hidden = !on;
  ui.stage.classList.toggle('picking', on);
}

let drawQueued = false;
export function requestDraw() {
  if (drawQueued) return;
  drawQueued = true;
  requestAnimationFrame(() => {
    drawQueued = false;
    draw();
  });
}

/** Zooms by `factor` keeping the mm point under the CSS pixel (px, py) where it is. */
export function zoomAt(factor, px, py) {
  const v = state.view;
  if (!v) return;
  const { width, height } = stageSize();
  const scale = Math.min(Math.max(v.scale * factor, 1e-4), 1e4);
  const dx = px - width / 2;
  const dy = py - height / 2;
  state.view = { cx: v.cx + dx / v.scale - dx / scale, cy: v.cy - dy / v.scale + dy / scale, scale };
  requestDraw();
}

export function pan(dx, dy) {
  if (!state.view) return;
  state.view.cx -= dx / state.view.scale;
  state.view.cy += dy / state.view.scale;
  requestDraw();
}

/** The preview's own controls: fit, pictures, start points, and the mouse and keys on the preview. */
export function wireView() {
  ui.setStart.addEventListener('click', () => setPicking(!state.picking));
  $('save-png').addEventListener('click', savePicture);
  $('save-svg').addEventListener('click', saveSvg);
  ui.fit.addEventListener('click', () => {
    fitView();
    requestDraw();
  });

  let drag = null;
  ui.canvas.addEventListener('pointerdown', async (e) => {
    if (e.button !== 0) return;
    if (app.origin.picking && state.job) {
      const rect = ui.canvas.getBoundingClientRect();
      await app.origin.pick(...pointAt(e.clientX - rect.left, e.clientY - rect.top));
      return;
    }
    if (app.tabsTool?.active && state.job) {
      const rect = ui.canvas.getBoundingClientRect();
      await app.tabsTool.click(...pointAt(e.clientX - rect.left, e.clientY - rect.top));
      return;
    }
    if (app.sideTool?.active && state.job) {
      const rect = ui.canvas.getBoundingClientRect();
      await app.sideTool.click(...pointAt(e.clientX - rect.left, e.clientY - rect.top));
      return;
    }
    if (state.picking && state.job) {
      const rect = ui.canvas.getBoundingClientRect();
      const [x, y] = pointAt(e.clientX - rect.left, e.clientY - rect.top);
      const pick = await app.engine.call('pickAt', { x, y, reach: 12 / state.view.scale });
      if (pick) {
        // One start point a loop: a new one on the same loop replaces it.
        state.starts = [...state.starts.filter((s) => !sameLoop(s, pick)), choiceOf(pick)];
        if (state.current) state.current.startsFrame = frameOf(window.kerfcam.lastReport); // their frame
        keepChoices();
        setPicking(false);
        app.run();
      }
      return;
    }
    drag = { x: e.clientX, y: e.clientY, x0: e.clientX, y0: e.clientY };
    ui.canvas.setPointerCapture(e.pointerId);
  });
  ui.canvas.addEventListener('pointermove', (e) => {
    if (!drag) return;
    pan(e.clientX - drag.x, e.clientY - drag.y);
    Object.assign(drag, { x: e.clientX, y: e.clientY });
  });
  ui.canvas.addEventListener('pointerup', (e) => {
    // A press that did not move is a click: a measuring point, or inspect what is there.
    if (drag && Math.hypot(e.clientX - drag.x0, e.clientY - drag.y0) < 4) app.inspector.click(e).catch(() => {});
    drag = null;
  });
  ui.canvas.addEventListener('pointercancel', () => (drag = null));
  ui.canvas.addEventListener('wheel', (e) => {
    e.preventDefault();
    const unit = [1, 16, 400][e.deltaMode] ?? 1; // pixels, lines, pages
    const rect = ui.canvas.getBoundingClientRect();
    zoomAt(Math.exp(-e.deltaY * unit * 0.0015), e.clientX - rect.left, e.clientY - rect.top);
  }, { passive: false });
  for (const type of ['focus', 'blur']) ui.canvas.addEventListener(type, () => app.planLayer.draw()); // the keyboard's aim
  ui.canvas.addEventListener('keydown', (e) => {
    const keys = {
      ArrowLeft: () => pan(50, 0), ArrowRight: () => pan(-50, 0), ArrowUp: () => pan(0, 50), ArrowDown: () => pan(0, -50),
      // Inspect, measure or pick the origin at the cross in the middle.
      Enter: () => (app.origin.picking
        ? app.origin.pick(...pointAt(stageSize().width / 2, stageSize().height / 2)).catch(() => {})
        : app.inspector.atCentre().catch(() => {})),
    };
    if (!keys[e.key] || !state.job) return;
    e.preventDefault();
    keys[e.key]();
  });
  // Shortcuts anywhere on the page except while typing in a field: F fit, + and - zoom, Space play,
  // M measure, Escape leaves the measure and start-point tools.
  document.addEventListener('keydown', (e) => {
    if (!ui.sheetView.hidden) {
      if (e.key === 'Escape') app.closeSheet(); // the sheet covers the app: no other shortcut
      return;
    }
    if (e.ctrlKey || e.metaKey || e.altKey || e.target.closest?.('input, select, textarea, dialog, [contenteditable]')) return;
    if (e.key === ' ' && e.target.closest?.('button, a, summary')) return; // Space presses the focused button
    const { width, height } = stageSize();
    const zoom = (f) => zoomAt(f, width / 2, height / 2);
    const keys = {
      '+': () => zoom(1.25), '=': () => zoom(1.25), '-': () => zoom(0.8), f: () => ui.fit.click(), F: () => ui.fit.click(),
      ' ': () => app.planLayer.toggle(), m: () => ui.measure.click(), M: () => ui.measure.click(),
      Escape: () => {
        if (app.inspector.measuring) app.inspector.setMeasuring(false);
        if (state.picking) setPicking(false);
        if (app.origin.picking) app.origin.setPicking(false);
      },
    };
    if (!keys[e.key] || !state.job) return;
    e.preventDefault();
    keys[e.key]();
  });
  new ResizeObserver(requestDraw).observe(ui.stage);
}
