//! What the cuts take from the parts, for the page to mark before the
//! download (issue 45 §3): thin wrappers of [`crate::losses`].

use wasm_bindgen::prelude::*;

use super::Job;

/// The most outline segments the page is sent (a sheet where every part
/// loses material is marked by its first ones; the count is the report's).
const SEGMENTS_MAX: usize = 200_000;
/// The most squares the page draws (as the heat map's).
const SQUARES_MAX: usize = 50_000;

#[wasm_bindgen]
impl Job {
    /// `[x0, y0, x1, y1, bulge, …]`: the segments of the drawn loops the
    /// loss warnings name (program coordinates, mm), 5 numbers each.
    pub fn loss_outlines(&self) -> Vec<f64> {
        crate::losses::outlines(&self.out, SEGMENTS_MAX)
    }

    /// `[side, x, y, depth, …]`: squares of `side` mm centred on `(x, y)`
    /// where a cut comes within half the kerf of another part, `depth` mm
    /// its deepest reach there; empty when none (or when the verification
    /// ran: its heat map says it).
    pub fn closeness_heat(&self) -> Vec<f64> {
        crate::losses::closeness_squares(&self.out, SQUARES_MAX)
    }
}
