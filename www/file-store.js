// kerfcam's kept input files: every DXF the user opened stays in this browser (IndexedDB) with its
// layer choices and start points until the user clears it, so closing the tab mid-work loses
// nothing (issue 6 §3). The user's file is only ever read: these are copies of its bytes.
//
// Two stores: 'files' holds { id, name, layers: string[] | null, starts, tabsAt, sidesAt (choices.js), shown, added },
// rewritten whenever a choice changes; 'bytes' holds { id, blob: Blob }, written once per file (a 25 MB
// drawing is not copied again for each layer click). A Blob, not an ArrayBuffer: putting a 25 MB
// ArrayBuffer serialises it on the page's main thread (a 216 ms task, measured); a Blob is written
// by the browser in the background.
// A third store, 'nests' (version 2, issue 18), keeps the Sheet mode's saved nests: { id, name, saved,
// copies, sheets, blob } where blob is the nest file's JSON (nest-file.js), the very file Save nest downloads.
// The database is versioned; `upgrade` migrates older versions step by step.

const DB_NAME = 'kerfcam';
const DB_VERSION = 2;
const FILES = 'files';
const BYTES = 'bytes';
const NESTS = 'nests';

let opening = null;

function upgrade(db, oldVersion) {
  // Version 1: the file store. Later versions add their steps below, each from the one before.
  if (oldVersion < 1) {
    db.createObjectStore(FILES, { keyPath: 'id' });
    db.createObjectStore(BYTES, { keyPath: 'id' });
  }
  if (oldVersion < 2) db.createObjectStore(NESTS, { keyPath: 'id' });
}

/** The database, or null where IndexedDB is unavailable (some private modes): files are then not kept. */
function open() {
  if (!opening) {
    opening = new Promise((resolve) => {
      let req;
      try {
        req = globalThis.indexedDB?.open(DB_NAME, DB_VERSION);
      } catch {
        req = null;
      }
      if (!req) return resolve(null);
      req.onupgradeneeded = (e) => upgrade(req.result, e.oldVersion);
      req.onsuccess = () => resolve(req.result);
      req.onerror = () => resolve(null);
      req.onblocked = () => resolve(null);
    });
  }
  return opening;
}

/** Runs `body(files, bytes)` in one transaction; resolves with its request's result when it completes. */
async function withStore(mode, body) {
  const db = await open();
  if (!db) return null;
  return new Promise((resolve, reject) => {
    const tx = db.transaction([FILES, BYTES], mode);
    const req = body(tx.objectStore(FILES), tx.objectStore(BYTES));
    tx.oncomplete = () => resolve(req ? req.result : null);
    tx.onerror = () => reject(tx.error);
    tx.onabort = () => reject(tx.error || new Error('storage aborted'));
  });
}

/** Every kept file with its contents (`blob`), oldest first. */
export async function loadFiles() {
  try {
    const [files, bytes] = await Promise.all([
      withStore('readonly', (f) => f.getAll()),
      withStore('readonly', (f, b) => b.getAll()),
    ]);
    const byId = new Map((bytes || []).map((r) => [r.id, r.blob]));
    const kept = (files || []).filter((r) => r && typeof r.name === 'string' && byId.get(r.id) instanceof Blob);
    return kept.sort((a, b) => a.added - b.added).map((r) => ({ ...r, blob: byId.get(r.id) }));
  } catch {
    return [];
  }
}

/**
 * Keeps one file's record (its choices), and its contents when given (a Blob or File, once, when it
 * is added). Storage failures (quota) are reported, not thrown.
 */
export async function keepFile(record, blob = null) {
  try {
    await withStore('readwrite', (f, b) => {
      if (blob) b.put({ id: record.id, blob });
      return f.put(record);
    });
    return true;
  } catch (e) {
    console.warn(`kerfcam: ${record.name} is not kept in this browser: ${(e && e.message) || e}`);
    return false;
  }
}

export async function forgetFile(id) {
  try {
    await withStore('readwrite', (f, b) => {
      b.delete(id);
      return f.delete(id);
    });
  } catch {
    // nothing kept to forget
  }
}

export async function forgetAllFiles() {
  try {
    await withStore('readwrite', (f, b) => {
      b.clear();
      return f.clear();
    });
  } catch {
    // nothing kept to forget
  }
}

/** Runs `body(nests)` in one transaction on the nests store; resolves with its request's result. */
async function withNests(mode, body) {
  const db = await open();
  if (!db) return null;
  return new Promise((resolve, reject) => {
    const tx = db.transaction([NESTS], mode);
    const req = body(tx.objectStore(NESTS));
    tx.oncomplete = () => resolve(req ? req.result : null);
    tx.onerror = () => reject(tx.error);
    tx.onabort = () => reject(tx.error || new Error('storage aborted'));
  });
}

/** Every kept nest ({ id, name, saved, copies, sheets, blob }), newest first; [] when none or no storage. */
export async function loadNests() {
  try {
    const all = (await withNests('readonly', (n) => n.getAll())) || [];
    return all.filter((r) => r && typeof r.name === 'string' && r.blob instanceof Blob).sort((a, b) => b.saved - a.saved);
  } catch {
    return [];
  }
}

/** Keeps a nest file; false (and a console note) when it cannot be kept (no storage, quota). */
export async function keepNest(record) {
  try {
    return (await withNests('readwrite', (n) => n.put(record))) !== null;
  } catch (e) {
    console.warn(`kerfcam: ${record.name} is not kept in this browser: ${(e && e.message) || e}`);
    return false;
  }
}

export async function forgetNest(id) {
  try {
    await withNests('readwrite', (n) => n.delete(id));
  } catch {
    // nothing kept to forget
  }
}
