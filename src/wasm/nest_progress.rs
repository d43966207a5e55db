//! A search's progress told to the page: the callback `nest` and a team's
//! `run` are given hears the best nest so far, with its placements when
//! they changed (the page redraws the sheet then) and, for sheets at a
//! cost, the combination under trial.

use serde::Serialize;
use wasm_bindgen::prelude::*;

use crate::nest::Progress;

/// What a cheapest nest's progress adds: the combination under trial
/// (the nest's sheet numbers refer to its sheets).
#[derive(Clone, PartialEq, Serialize)]
pub(super) struct WebTrial {
    pub(super) counts: Vec<usize>,
    pub(super) passed_over: usize,
}

/// What the progress callback hears: the best nest so far.
#[derive(Serialize)]
struct WebProgress {
    evaluations: u64,
    sheets: usize,
    length: f64,
    unplaced: usize,
    elapsed_s: f64,
    /// The best nest's copies when it changed since the last report, 7
    /// numbers each: part index, copy, sheet, rotation, mirror (0/1), x, y.
    placements: Option<Vec<f64>>,
    /// A team's search (nest_team.rs): with the placements, the best nest
    /// as the other workers adopt it and Stop keeps it.
    #[serde(skip_serializing_if = "Option::is_none")]
    best: Option<crate::nest::Best>,
    /// Sheets at a cost: the combination nested now.
    #[serde(skip_serializing_if = "Option::is_none")]
    combination: Option<WebTrial>,
}

/// Seconds from `clock()`; a clock that throws or answers nonsense ends
/// the search (the budget is spent), never the page.
pub(super) fn js_clock(clock: &js_sys::Function) -> f64 {
    clock
        .call0(&JsValue::NULL)
        .ok()
        .and_then(|v| v.as_f64())
        .filter(|t| t.is_finite())
        .unwrap_or(f64::INFINITY)
}

/// Tells `f` of a search's progress; false when it said stop. `shown`:
/// the placements sent last (they go out only when the best nest changed:
/// the page redraws the sheet then, not at every report); `team`: with
/// the best nest to adopt.
pub(super) fn tell(
    f: Option<&js_sys::Function>,
    shown: &mut Option<Vec<crate::nest::Placement>>,
    p: Progress,
    team: bool,
) -> bool {
    tell_trial(f, shown, p, team, None)
}

/// [`tell`], with the combination under trial of a cheapest nest (whose
/// best nest goes out too: Stop keeps it).
pub(super) fn tell_trial(
    f: Option<&js_sys::Function>,
    shown: &mut Option<Vec<crate::nest::Placement>>,
    p: Progress,
    team: bool,
    combination: Option<WebTrial>,
) -> bool {
    let Some(f) = f else {
        return true;
    };
    let changed = shown.as_ref() != Some(&p.best);
    let best = (changed && team).then(|| p.as_best());
    let placements = changed.then(|| {
        let flat = super::nest_json::flat_placements(&p.best);
        *shown = Some(p.best.clone());
        flat
    });
    let value = serde_wasm_bindgen::to_value(&WebProgress {
        evaluations: p.evaluations,
        sheets: p.sheets,
        length: p.length,
        unplaced: p.unplaced,
        elapsed_s: p.elapsed_s,
        placements,
        best,
        combination,
    })
    .unwrap_or(JsValue::NULL);
    // Only an explicit `false` stops; a throwing callback does not.
    f.call1(&JsValue::NULL, &value)
        .map_or(true, |v| v.as_bool() != Some(false))
}
