//! The verification's heat map for the page (issue 20 §9): the very cells
//! the report's `overcut_mm2` counts ([`crate::plan::heat::binned`]) and
//! the outline points of parts not freed, flat for a canvas.

use wasm_bindgen::prelude::*;

use super::Job;

/// The most squares the page draws.
const SQUARES_MAX: usize = 50_000;

#[wasm_bindgen]
impl Job {
    /// `[side, x, y, depth, x, y, depth, …]`: squares of `side` mm centred
    /// on `(x, y)` where the kerf takes part material, `depth` mm the
    /// deepest reach into the part there; empty without a verification or
    /// an overcut.
    pub fn overcut_heat(&self) -> Vec<f64> {
        let Some(v) = &self.out.verification else {
            return Vec::new();
        };
        let (side, squares) = crate::plan::heat::binned(&v.overcut_cells, v.cell, SQUARES_MAX);
        if squares.is_empty() {
            return Vec::new();
        }
        let mut out = Vec::with_capacity(1 + 3 * squares.len());
        out.push(side);
        for (p, d) in squares {
            out.extend([p.x, p.y, d]);
        }
        out
    }

    /// `[x, y, …]`: points of the outlines of parts not freed that no cut
    /// reaches (where they stay attached to the sheet).
    pub fn attached_points(&self) -> Vec<f64> {
        self.out.verification.as_ref().map_or_else(Vec::new, |v| {
            v.attached.iter().flat_map(|p| p.xy()).collect()
        })
    }
}
