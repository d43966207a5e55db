// kerfcam page: the settings survive a reload (localStorage, versioned), and "Reset to defaults" puts
// back each control's default: the engine's for numbers (NumberFields.setDefaults), index.html's for
// choices. Only the form's own values are kept, never file contents.

const KEY = 'kerfcam.settings';
const VERSION = 1;

/** The inputs and selects whose values are kept: every named control of the given forms, plus extras. */
function controls(forms, extras) {
  return [...forms.flatMap((f) => [...f.elements]), ...extras].filter((c) => c.id && c.type !== 'button' && c.type !== 'submit');
}

/** Older saved settings brought up to this version (none yet: version 1 is the first). */
function migrate(saved) {
  if (!saved || typeof saved !== 'object' || typeof saved.values !== 'object') return null;
  if (saved.version === VERSION) return saved;
  return null; // unknown version: start from the defaults rather than guess
}

export function restoreSettings(forms, extras = []) {
  let saved = null;
  try {
    saved = migrate(JSON.parse(localStorage.getItem(KEY) || 'null'));
  } catch {
    saved = null;
  }
  if (!saved) return false;
  for (const c of controls(forms, extras)) {
    if (!(c.id in saved.values)) continue;
    const v = saved.values[c.id];
    if (c.type === 'checkbox') c.checked = Boolean(v);
    else if (c.tagName === 'SELECT') {
      if ([...c.options].some((o) => o.value === v)) c.value = v;
    } else c.value = String(v);
  }
  return true;
}

export function saveSettings(forms, extras = []) {
  const values = {};
  for (const c of controls(forms, extras)) values[c.id] = c.type === 'checkbox' ? c.checked : c.value;
  try {
    localStorage.setItem(KEY, JSON.stringify({ version: VERSION, values }));
  } catch {
    // storage full or disabled: settings just are not kept
  }
}

/** Puts back the controls' defaults and forgets the saved values. */
export function resetSettings(forms, extras = []) {
  for (const c of controls(forms, extras)) {
    if (c.type === 'checkbox') c.checked = c.defaultChecked;
    else if (c.tagName === 'SELECT') {
      const d = [...c.options].find((o) => o.defaultSelected) ?? c.options[0];
      if (d) c.value = d.value;
    } else c.value = c.defaultValue;
  }
  localStorage.removeItem(KEY);
}
