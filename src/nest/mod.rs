//! Nesting: [`NestJob`] (parts, sheets, settings) → [`Nest`] (where every
//! copy goes), a stage of its own beside the cutting pipeline (issue 16).
//!
//! # Contract
//! - A part is one outer outline and its holes from [`crate::contour`],
//!   arcs kept; it is cut from them. Collisions are judged on a polygon
//!   that holds the part grown by half the spacing, never smaller, at most
//!   the tolerance larger ([`shape`]). A hole's room (shrunk by half the
//!   spacing, never larger) takes smaller copies (part-in-part), tried
//!   before the sheet; such a copy says whose hole it is in.
//! - Placement: copy `c` of part `p` on sheet `s`, turned by `rotation`
//!   degrees counter-clockwise after an optional mirror x → −x, then moved
//!   by `translation` (sheet coordinates, the sheet's lower-left corner at
//!   0, 0). The part's own drawing coordinates are what is turned.
//! - Sheets are rectangles W × H (N of them), filled one after the other;
//!   one irregular remnant (its outline, its holes and defects no-go
//!   zones); or a strip of height H and no end (benchmarks). The objective: every
//!   copy placed, on the fewest sheets, then the shortest length used on
//!   the last one (for a strip, the shortest length).
//! - Parts that cannot be placed are listed with the reason; the others
//!   are nested. Nothing here panics on bad input; settings out of range
//!   are a [`NestError`].
//! - Deterministic: the same job, seed and number of evaluations give the
//!   same nest. The time budget is read from a clock the caller passes (no
//!   `Instant` in a browser), no threads here: several searches at once
//!   (threads natively, web workers in the page) are [`team`]'s, each a
//!   [`Search`] paused at evaluation counts to exchange the best nest.

mod assemble;
mod best;
pub mod collide;
mod decode;
pub mod edit;
mod error;
pub mod figures;
pub mod instance;
mod live;
pub mod output;
pub mod place;
pub mod remnant;
pub mod rows;
mod rng;
mod rotations;
mod search;
mod separate;
pub mod shape;
mod sheet;
pub mod simplify;
pub mod stock;
pub mod snap;
pub mod spec;
pub mod svg_out;
pub mod team;
pub mod torches;

use crate::contour::{ContourKind, Contours};
use crate::geom::{loop_area, Affine, Point, Segment};
use crate::text;
use crate::warning::{dec, Text};

pub use error::NestError;
pub use rotations::{Rotations, FREE_STEPS};
pub use best::{pick, Best};
pub use search::{Progress, Search};
pub use sheet::{sheet_from_contours, SheetSize, Sheets};
pub use spec::{read_parts, read_sheet, NestSpec, SPACING_OVER_KERF};

/// Most copies of one part a job may ask for: beyond it the quantity is a
/// typing error (the placer's work grows with the square of the copies).
pub const MAX_QUANTITY: usize = 10_000;

/// One part to cut, with how many copies.
#[derive(Clone, Debug)]
pub struct Part {
    /// Its name (file name and part number; the layer in the nest DXF).
    pub name: String,
    /// Its outer outline, closed, arcs kept.
    pub outer: Vec<Segment>,
    /// Its holes.
    pub holes: Vec<Vec<Segment>>,
    /// Copies wanted.
    pub quantity: usize,
    /// Turns allowed.
    pub rotations: Rotations,
    /// Mirror allowed.
    pub mirror: bool,
}

impl Part {
    /// Net area (outer minus holes), mm².
    pub fn area(&self) -> f64 {
        loop_area(&self.outer).abs() - self.holes.iter().map(|h| loop_area(h).abs()).sum::<f64>()
    }
}

/// A part that was not nested (or copies of it), and why.
#[derive(Clone, Debug, PartialEq)]
pub struct Unplaced {
    /// The part's name.
    pub part: String,
    /// How many copies.
    pub copies: usize,
    /// Why, in every language (the page and the CLI's `--lang` pick one).
    pub reason: Text,
}

/// The nestable parts of a drawing's contours: one per outer outline with
/// the holes inside it. Open contours cannot be nested (they enclose
/// nothing) and come back as [`Unplaced`] with the reason.
///
/// A part is named `name` (the file's), plus `/BLOCK` when its outline was
/// drawn as a block ([`Contour::block`](crate::contour::Contour::block)),
/// else `/GROUP` when the file's parts no block names are not all in one
/// named layer or SVG group ([`Contour::group`](crate::contour::Contour::group):
/// a layer every part is on tells none apart), plus `#n` (its number in the file)
/// when the file holds several parts and that name does not tell it from
/// the others (issue 42 §1).
pub fn parts_from_contours(
    contours: &Contours,
    name: &str,
    quantity: usize,
) -> (Vec<Part>, Vec<Unplaced>) {
    let mut parts = Vec::new();
    let mut notes = Vec::new();
    let outers = || contours.contours.iter().filter(|c| c.kind == ContourKind::Outer);
    // The groups of the parts no block names: all one, it tells none apart.
    let unblocked = || outers().filter(|c| c.block.is_none());
    let first_group = unblocked().next().map(|c| c.group.as_deref());
    let by_group = unblocked().any(|c| Some(c.group.as_deref()) != first_group);
    fn named(c: &crate::contour::Contour, by_group: bool) -> Option<&str> {
        c.block.as_deref().or(c.group.as_deref().filter(|_| by_group))
    }
    // Parts of each name: a block inserted twice, or a layer, names two parts.
    let mut names = std::collections::HashMap::<&str, usize>::new();
    for n in outers().filter_map(|c| named(c, by_group)) {
        *names.entry(n).or_default() += 1;
    }
    for c in outers() {
        let holes = contours
            .contours
            .iter()
            .filter(|h| h.kind == ContourKind::Hole && h.part == c.part)
            .map(|h| h.segments.clone())
            .collect();
        let number = c.part.unwrap_or(parts.len() + 1);
        let shared = |b: &str| names.get(b).is_some_and(|&n| n > 1);
        parts.push(Part {
            name: match named(c, by_group) {
                Some(b) if shared(b) => format!("{name}/{b}#{number}"),
                Some(b) => format!("{name}/{b}"),
                None if contours.parts > 1 => format!("{name}#{number}"),
                None => name.to_owned(),
            },
            outer: c.segments.clone(),
            holes,
            quantity,
            rotations: Rotations::Quarter,
            mirror: false,
        });
    }
    let open = contours
        .contours
        .iter()
        .filter(|c| c.kind == ContourKind::Open)
        .count();
    if open > 0 {
        // No copy is missing: the contours are (the closed parts are nested), so the note counts none.
        notes.push(Unplaced {
            part: name.to_owned(),
            copies: 0,
            reason: text!("{open} open contour(s) left out: not nestable (an open outline encloses no part)";
                          "{open} contorno(s) aberto(s) deixado(s) de fora: não pode(m) ser encaixado(s) (um contorno aberto não encerra peça)"),
        });
    }
    if parts.is_empty() && open == 0 {
        notes.push(Unplaced {
            part: name.to_owned(),
            copies: 0,
            reason: text!("no closed outline: nothing to nest"; "nenhum contorno fechado: nada a encaixar"),
        });
    }
    (parts, notes)
}

/// How to nest.
#[derive(Clone, Debug, PartialEq)]
pub struct NestSettings {
    /// Least distance between two parts, mm.
    pub spacing: f64,
    /// Least distance between a part and the sheet's edge, mm.
    pub margin: f64,
    /// Largest excess of the collision polygon over the grown part, mm.
    pub tolerance: f64,
    /// Time budget, s, the first nest included: cut short, it is the nest
    /// of the copies placed so far (0: the first nest whole, nothing more).
    pub time_s: f64,
    /// Seed of the improvement's choices.
    pub seed: u64,
    /// Stop after this many evaluations (for reproducible runs): a copy
    /// placed in the first nest, an order decoded, a separation move.
    pub max_evaluations: Option<u64>,
    /// The budget the operator set, s, when `time_s` is not it (None:
    /// `time_s`): the sequence search's share of the work is sized from
    /// it ([`NestSettings::budget`]). A replay of a stopped run gives the
    /// clock more time and this the run's budget, and a trial of one
    /// sheet combination a part of the clock and this the whole, so that
    /// each is the same run as the one it stands for.
    pub budget_s: Option<f64>,
}

impl Default for NestSettings {
    /// [`NestSettings::for_kerf`] of the default process's kerf.
    fn default() -> Self {
        NestSettings::for_kerf(crate::process::Process::DEFAULT.kerf)
    }
}

/// Everything a nest is made from.
#[derive(Clone, Debug)]
pub struct NestJob {
    /// The parts.
    pub parts: Vec<Part>,
    /// Where they go.
    pub sheets: Sheets,
    /// How.
    pub settings: NestSettings,
}

#[cfg(test)]
impl NestJob {
    /// `parts` on `sheets` with no spacing and no margin (the other
    /// settings their defaults): the tests' copies may touch each other and
    /// the sheet's edge.
    pub(crate) fn touching(parts: Vec<Part>, sheets: Sheets) -> Self {
        NestJob {
            parts,
            sheets,
            settings: NestSettings {
                spacing: 0.0,
                margin: 0.0,
                ..Default::default()
            },
        }
    }
}

/// One copy's place.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Placement {
    /// Index into the job's parts.
    pub part: usize,
    /// Which copy (0-based).
    pub copy: usize,
    /// Which sheet (0-based; 0 in strip mode).
    pub sheet: usize,
    /// Degrees counter-clockwise, after the mirror.
    pub rotation: f64,
    /// Mirrored x → −x first.
    pub mirror: bool,
    /// Then moved by this, mm (sheet coordinates).
    pub translation: Point,
    /// Placed inside a hole of this copy: (part index, copy).
    pub in_hole_of: Option<(usize, usize)>,
}

impl Placement {
    /// The map from the part's drawing to the sheet.
    pub fn affine(&self) -> Affine {
        let m = Affine::scale_xy(if self.mirror { -1.0 } else { 1.0 }, 1.0);
        let r = Affine::rotate_deg(self.rotation);
        Affine::translate(self.translation.x, self.translation.y).then_after(&r.then_after(&m))
    }
}

/// One sheet's figures.
#[derive(Clone, Debug, PartialEq)]
pub struct SheetUse {
    /// Along x, mm (the used length in strip mode).
    pub width: f64,
    /// Along y, mm.
    pub height: f64,
    /// Copies on it.
    pub parts: usize,
    /// From the left edge to the rightmost part, mm.
    pub used_length: f64,
    /// Part area / useful area: the sheet less its no-go zones and the
    /// remnant right of the crop line (paper 001, §6.3); in strip mode,
    /// part area / (height × used length).
    pub utilisation: f64,
    /// The crop line's x (sheet coordinates), the last sheet only, when
    /// the remnant beyond it is worth keeping ([`remnant`]).
    pub crop_x: Option<f64>,
}

/// The result.
#[derive(Clone, Debug)]
pub struct Nest {
    /// Every placed copy.
    pub placements: Vec<Placement>,
    /// Sheets used, in order.
    pub sheets: Vec<SheetUse>,
    /// What could not be placed.
    pub unplaced: Vec<Unplaced>,
    /// Strip mode: the length used.
    pub strip_length: Option<f64>,
    /// Part area over sheet height × used length, all sheets.
    pub density: f64,
    /// Nests tried by the improvement.
    pub evaluations: u64,
}

/// Sheet sizes that are sizes, and 1..=[`MAX_QUANTITY`] sheets in all.
fn check_rects(sizes: &[SheetSize]) -> Result<(), NestError> {
    let setting = |reason: Text| NestError::Setting {
        field: "sheet",
        reason,
    };
    for &SheetSize { width, height, .. } in sizes {
        if !(width.is_finite() && height.is_finite() && width > 0.0 && height > 0.0) {
            return Err(setting(text!("{width} × {height} is not a sheet size";
                                     "{} × {} não é um tamanho de chapa", dec(width), dec(height))));
        }
    }
    let count = sizes
        .iter()
        .map(|s| s.count)
        .fold(0usize, usize::saturating_add);
    if count == 0 || count > MAX_QUANTITY || sizes.iter().any(|s| s.count == 0) {
        return Err(setting(text!(
            "{count} sheets: between 1 and {MAX_QUANTITY}, at least one of each size";
            "{count} chapas: entre 1 e {MAX_QUANTITY}, ao menos uma de cada tamanho"
        )));
    }
    Ok(())
}

/// Nests `job`. `clock` gives seconds from any fixed start; `progress` is
/// called after each better nest and now and then, and returns false to
/// stop (the best nest so far is returned).
pub fn nest(
    job: &NestJob,
    clock: &dyn Fn() -> f64,
    progress: &mut dyn FnMut(Progress) -> bool,
) -> Result<Nest, NestError> {
    search::run(job, clock, progress)
}

/// The job's settings, sheets and quantities checked.
fn check(job: &NestJob) -> Result<(), NestError> {
    let s = &job.settings;
    let setting = |field, reason: Text| Err(NestError::Setting { field, reason });
    for (field, v) in [
        ("spacing", s.spacing),
        ("margin", s.margin),
        ("time", s.time_s),
        ("budget", s.budget()),
    ] {
        if !(v.is_finite() && v >= 0.0) {
            return setting(field, text!("{v} is not a distance or time ≥ 0";
                                        "{} não é uma distância ou um tempo ≥ 0", dec(v)));
        }
    }
    if !(s.tolerance.is_finite() && s.tolerance > 0.0) {
        return setting(
            "tolerance",
            text!("{} is not a distance > 0", s.tolerance; "{} não é uma distância > 0", dec(s.tolerance)),
        );
    }
    match &job.sheets {
        Sheets::Rect {
            width,
            height,
            count,
        } => check_rects(&[SheetSize {
            width: *width,
            height: *height,
            count: *count,
        }])?,
        Sheets::Mixed(sizes) => check_rects(sizes)?,
        &Sheets::Strip { height } => {
            if !(height.is_finite() && height > 0.0) {
                return setting("strip-height", text!("{height} is not a height"; "{} não é uma altura", dec(height)));
            }
        }
        Sheets::Remnant { outline, .. } => {
            let a = loop_area(outline);
            if !(a.is_finite() && a != 0.0) {
                return setting("sheet-dxf", text!("the sheet's outline encloses no area"; "o contorno da chapa não encerra área"));
            }
        }
    }
    for p in &job.parts {
        if p.quantity > MAX_QUANTITY {
            return Err(NestError::TooMany {
                part: p.name.clone(),
                quantity: p.quantity,
            });
        }
    }
    if job.parts.iter().all(|p| p.quantity == 0) {
        return Err(NestError::NoParts);
    }
    Ok(())
}
