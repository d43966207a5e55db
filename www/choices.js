// The operator's choices on a drawing — start points and tabs — kept by the loop they were set on
// (issue 39 §1), never by a contour number: the engine renumbers contours whenever the drawing changes
// (a layer switched off, the units, the gap, a reload). A choice is `{ at: [x, y], on: key }`: the point
// on the loop (program coordinates, mm) and the loop's key as the engine gave it (`pickAt`: part, copy
// and loop, area, length, box size, layer). Every plan matches each choice again to the loop through its
// point with that shape (src/plan/choice.rs); one whose loop is not cut now is kept here and named in
// the engine's "choices-not-applied" warning, and applies again when its loop comes back.
// Pages before issue 39 stored `[contour, x, y]`: still read (the engine takes the loop nearest the point).

/** The point of a choice, either form. */
export const pointOf = (c) => (Array.isArray(c) ? [c[1], c[2]] : c.at);

/** True when `c` (a kept choice) was set on the loop of `pick` (the engine's answer to pickAt). */
export function sameLoop(c, pick) {
  if (Array.isArray(c)) return c[0] === pick.contour;
  const [a, b] = [c.on, pick.on];
  if (!a || !b) return false;
  const near = (x, y) => Math.abs(x - y) <= 1e-6 * Math.max(1, Math.abs(x), Math.abs(y));
  return a.part === b.part && a.copy === b.copy && a.contour === b.contour && near(a.area, b.area) && near(a.length, b.length);
}

/** A choice from the engine's pick: the point on the loop and its key. */
export const choiceOf = (pick) => ({ at: pick.at, on: pick.on });

// Millimetres per drawing unit, for the units the page offers (report.units names them).
const MM_PER_UNIT = { mm: 1, cm: 10, m: 1000, in: 25.4, ft: 304.8, px: 25.4 / 96, px72: 25.4 / 72 };

/** Micrometres: the engine's own rounding of coordinates in the report. */
const round = (v) => Math.round(v * 1000) / 1000;

/**
 * Choices (program coordinates) set in the frame `from` ({ at: drawing point at zero, mm; units }), in
 * the frame `to`: the same places of the drawing, wherever the origin and whatever unit the file is read
 * in; a key's sizes scale with the unit. Null when nothing moves (no choices, an unknown frame, the same
 * frame).
 */
export function rebaseChoices(choices, from, to) {
  if (!choices?.length || !Array.isArray(from?.at) || !Array.isArray(to?.at)) return null;
  const s0 = MM_PER_UNIT[from.units] ?? 1;
  const s1 = MM_PER_UNIT[to.units] ?? 1;
  const k = from.units === to.units ? 1 : s1 / s0;
  if (k === 1 && from.at[0] === to.at[0] && from.at[1] === to.at[1]) return null;
  // Drawing mm in the old reading → the file's own numbers → drawing mm in the new reading.
  const move = (v, i) => round((v + from.at[i]) * k - to.at[i]);
  return choices.map((c) => {
    if (Array.isArray(c)) return [c[0], move(c[1], 0), move(c[2], 1)];
    const on = c.on && { ...c.on, area: c.on.area * k * k, length: c.on.length * k, size: c.on.size.map((v) => v * k) };
    return { ...c, at: [move(c.at[0], 0), move(c.at[1], 1)], on };
  });
}
