// kerfcam page, Sheet mode (issue 18 item 8): nest files. Save nest writes one JSON file with everything
// the nest was made from (each part file's DXF text, quantity, rotation and mirror choices, the sheet's
// settings, a sheet DXF if one was used) and the nest as it stands (placements after any hand edit, the
// crop line); Open nest reads it back: the parts list and sheet fields are filled from it and the engine
// makes the same nest again without a search (Nester.restore), checked as a hand edit is. Part names and
// DXF text are data: they go to the engine and to textContent only.

import { $ } from './app.js';
import { download } from './download.js';
import { getLang, register, t } from './i18n.js';
import { copies, row } from './nest-view.js';
import { KeptNests } from './nest-store.js';

register({
  en: {
    'file.save': 'Save nest', 'file.open': 'Open a nest file…', 'file.export-dxf': 'Export nest DXF', 'file.export-svg': 'Export nest SVG',
    'file.export-svg-torches': 'A multi-torch nest is exported as DXF only',
    'file.bad': '{name} is not a kerfcam nest file: {why}', 'file.opened': 'Opened {name}: {n} copies on {sheets} sheet(s).',
  },
  'pt-BR': {
    'file.save': 'Salvar encaixe', 'file.open': 'Abrir arquivo de encaixe…', 'file.export-dxf': 'Exportar DXF do encaixe', 'file.export-svg': 'Exportar SVG do encaixe',
    'file.export-svg-torches': 'Um encaixe com várias tochas é exportado só em DXF',
    'file.bad': '{name} não é um arquivo de encaixe do kerfcam: {why}', 'file.opened': '{name} aberto: {n} cópias em {sheets} chapa(s).',
  },
});

/** The format's name and version, first in every nest file. */
const FORMAT = 'kerfcam-nest';
const VERSION = 1;

export class NestFile {
  /** `hooks`: { engine(), panel (SheetPanel), nest (NestRun), edit (NestEdit) } */
  constructor(hooks) {
    this.hooks = hooks;
    this.kept = new KeptNests({ open: (file) => this.open(file), say: (text) => hooks.nest.say(text) });
    $('nest-save').addEventListener('click', () => this.save());
    $('nest-export-dxf').addEventListener('click', () => this.exportDxf());
    $('nest-export-svg').addEventListener('click', () => this.exportSvg());
    $('nest-open-input').addEventListener('change', async (e) => {
      const file = e.target.files?.[0];
      e.target.value = '';
      if (file) await this.open(file);
    });
  }

  /**
   * The nest as it stands as a DXF (the engine's nest writer, as `kerfcam nest -o NEST.dxf`): every copy
   * placed, each sheet's outline on layer SHEET, the crop line on REMNANT. Not while copies are in conflict.
   */
  async exportDxf() {
    if (!this.hooks.nest.result || this.hooks.edit.blocked) return;
    const dxf = await this.hooks.engine().call('nestDxf');
    download(new Blob([dxf], { type: 'application/dxf' }), 'nest.dxf');
  }

  /** The nest as an SVG at true size (mm; a layer per sheet, a group per copy, labelled), for Inkscape. */
  async exportSvg() {
    if (!this.hooks.nest.result || this.hooks.edit.blocked) return;
    const svg = await this.hooks.engine().call('nestSvg');
    if (!svg) {
      this.hooks.nest.say(t('file.export-svg-torches'));
      return;
    }
    download(new Blob([svg], { type: 'image/svg+xml' }), 'nest.svg');
  }

  /** The nest shown, with what it was made from, as a JSON file: downloaded, and kept in this browser. */
  async save() {
    const r = this.hooks.nest.result;
    if (!r?.inputs) return;
    const { parts, settings, sheetFile } = r.inputs;
    const doc = {
      format: FORMAT,
      version: VERSION,
      parts: await Promise.all(parts.map(async (p) => ({
        name: p.name, dxf: await p.file.text(), quantity: p.quantity, rotations: p.rotations, mirror: p.mirror,
        grain: !!p.grain, units: p.units || null, each: p.each ?? null,
      }))),
      settings,
      // Sheets at a cost: the sheets of each size the nest is on, and the combinations passed over before it.
      ...(r.json.stock ? { combination: r.json.stock.map((s) => s.used), passed_over: r.json.combinations_passed_over } : {}),
      sheet_dxf: sheetFile ? { name: sheetFile.name, dxf: await sheetFile.text() } : null,
      sheets: r.json.sheets.length,
      placements: copies(r.json.flat).map(row),
      crop: this.hooks.edit.crop ?? 'auto',
    };
    const blob = new Blob([JSON.stringify(doc)], { type: 'application/json' });
    const name = 'nest.kerfcam-nest.json';
    download(blob, name);
    await this.kept.keep(blob, { name, copies: doc.placements.length, sheets: doc.sheets });
  }

  /** Reads a nest file into the parts list and sheet, and the engine makes its nest again. */
  async open(file) {
    const { panel, nest } = this.hooks;
    let doc;
    try {
      doc = JSON.parse(await file.text());
      const why = doc?.format !== FORMAT ? `no "format": "${FORMAT}"`
        : doc.version !== VERSION ? `version ${doc.version} (this page reads ${VERSION})`
          : !Array.isArray(doc.parts) || !doc.parts.every((p) => typeof p?.name === 'string' && typeof p.dxf === 'string') ? 'its parts are not a list of {name, dxf}'
            : !Array.isArray(doc.placements) || !Number.isInteger(doc.sheets) || typeof doc.settings !== 'object' ? 'no placements, sheets or settings' : '';
      if (why) throw new Error(why);
    } catch (e) {
      return nest.say(t('file.bad', { name: file.name, why: e.message || String(e) }));
    }
    const files = doc.parts.map((p) => new File([p.dxf], p.name, { type: 'application/dxf' }));
    panel.parts = [];
    await panel.addFiles(files, doc.parts.map((p) => ({
      quantity: String(p.quantity), rotations: String(p.rotations), mirror: !!p.mirror, grain: !!p.grain,
      units: typeof p.units === 'string' && p.units ? p.units : null,
      // Each part's own choices (issue 42 §1), as the nest was made; kept when the file still has as many parts.
      each: Array.isArray(p.each) ? p.each.map((c) => ({
        quantity: String(c?.quantity ?? 0), rotations: String(c?.rotations ?? p.rotations), mirror: !!c?.mirror, grain: !!c?.grain,
      })) : undefined,
    })));
    panel.setSheetValues(doc.settings);
    panel.setSheetFile(doc.sheet_dxf ? new File([doc.sheet_dxf.dxf], doc.sheet_dxf.name, { type: 'application/dxf' }) : null);
    try {
      const parts = panel.read();
      const sheetFile = panel.sheetFile;
      const json = JSON.stringify({ placements: doc.placements, crop: doc.crop ?? 'auto' });
      // A nest at a cost is on the combination it was made on, not the whole stock.
      const settings = Array.isArray(doc.combination)
        ? { ...doc.settings, combination: doc.combination, passed_over: doc.passed_over ?? 0 } : doc.settings;
      const res = await this.hooks.engine().call('restoreNest', {
        parts, settings, cutting: panel.cutting(), lang: getLang(), sheet: sheetFile, sheets: doc.sheets, json,
        labels: nest.labels.spec(),
      });
      nest.say('');
      nest.k = 0;
      nest.take(res, { asked: nest.asked(parts), inputs: { parts, settings: doc.settings, sheetFile }, crop: doc.crop });
      nest.ui.progress.textContent = t('file.opened', { name: file.name, n: String(doc.placements.length), sheets: String(doc.sheets) });
    } catch (e) {
      nest.say(t('file.bad', { name: file.name, why: e.message || String(e) }));
    }
  }
}
