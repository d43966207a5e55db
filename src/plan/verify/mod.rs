//! kerfcam checks its own cut (issue 20 §9, paper 004's swept-envelope
//! verification): the kerf disc (radius w/2) swept along every cutting move
//! of the plan, compared with the drawn parts.
//!
//! - **Overcut**: where the swept disc takes a part's material. Its area is
//!   counted on a raster of cells (w/8 wide, 0.02–0.5 mm) stamped only
//!   around the moves that reach into a part, so a clean plan costs no
//!   raster at all; its depth (how far the disc reaches past the drawn edge)
//!   is exact at samples at most a cell apart.
//! - **Parts not freed**: a part is free when the disc reaches every point
//!   of its outline; a stretch of outline no cutting move comes within w/2
//!   of (a missing cut, a tab) leaves it attached to the sheet.
//!
//! Marks (scribing) cut nothing and are left out; so are spots. What counts
//! as reaching is the geometry's rounding: ten tolerances.

mod freed;
mod material;
mod moves;
mod overcut;
mod raster;

use super::{CutPlan, PlanInput, Role};
use crate::geom::{Point, Segment};
use crate::par::Threads;
use freed::not_freed;
use material::Material;

/// What the swept kerf does to the parts.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct Verification {
    /// Area of part material inside the swept kerf, mm².
    pub overcut_mm2: f64,
    /// Parts whose outline the kerf does not reach all round (not counting
    /// those held only by their tabs).
    pub parts_not_freed: usize,
    /// Parts that would be free but for their tabs (issue 20 §6): held on
    /// purpose, not a missing cut.
    pub parts_held_by_tabs: usize,
    /// Deepest reach of the kerf past a drawn edge into a part, mm.
    pub max_overcut_mm: f64,
    /// The first part not freed (1-based), for the warning.
    pub first_not_freed: Option<usize>,
    /// Where the deepest overcut is.
    pub deepest_at: Option<Point>,
    /// The raster `overcut_mm2` counts (the preview's heat map): each cell
    /// of part material the kerf takes, its centre and the depth of the
    /// deepest disc that took it, mm, in raster order.
    pub overcut_cells: Vec<(Point, f64)>,
    /// The raster's cell side, mm.
    pub cell: f64,
    /// True when the raster was coarsened past its first cell side (too
    /// much overcut to count finely, `raster.rs`): `overcut_mm2` counts
    /// every `cell`-sized cell the swept kerf reaches, an upper bound.
    pub area_coarsened: bool,
    /// Points of the outlines of parts not freed that no cutting move
    /// reaches, about a cell apart: where they stay attached to the sheet
    /// (at most [`ATTACHED_MAX`]).
    pub attached: Vec<Point>,
    /// What the swept kerf takes from each part it takes from, by part
    /// number: parts that share edges (issue 39 §6) each lose half the
    /// kerf along them, and this is where it shows part by part.
    pub parts: Vec<PartLoss>,
}

/// The part material one part loses to the swept kerf.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct PartLoss {
    /// Part number (1-based).
    pub part: usize,
    /// Area taken, mm² (the raster's cells whose centre is in the part).
    pub overcut_mm2: f64,
    /// Deepest reach past a drawn edge into it, mm (the deepest of those
    /// cells' discs).
    pub max_overcut_mm: f64,
}

/// The most attachment points kept for the preview.
pub const ATTACHED_MAX: usize = 100_000;
/// The cutting moves of `plan` (no marks, no spots, no tabs: the torch is
/// off over them), and the tabs too when `tabs` (to ask whether a part
/// would be free but for its tabs).
pub(super) fn cutting(plan: &CutPlan, tabs: bool) -> impl Iterator<Item = &Segment> {
    plan.cuts
        .iter()
        .filter(|c| !c.spot)
        .flat_map(|c| c.steps.iter())
        .filter(move |s| s.role != Role::Mark && (tabs || s.role != Role::Tab))
        .map(|s| &s.segment)
}

/// Sweeps the plan's kerf over the parts of `input`; the same answer with
/// any number of `threads`.
pub fn verify(input: &PlanInput, plan: &CutPlan, threads: Threads) -> Verification {
    let tol = input.tolerance.max(1e-6);
    let r = (input.process.kerf / 2.0).max(0.0);
    let slack = 10.0 * tol;
    let cell = (r / 4.0).clamp(0.02, 0.5);
    // The overcut on one thread while the parts freed are checked on the
    // others: neither reads what the other finds.
    let (swept, (held, _)) = crate::par::join(
        threads,
        || overcut::sweep(input, plan, r, cell, slack),
        || not_freed(input, plan, r, cell, slack, false, threads),
    );
    let raster = swept.raster;
    let material = swept.material;
    let mut out = Verification {
        max_overcut_mm: swept.deepest,
        deepest_at: swept.deepest_at,
        ..Verification::default()
    };
    out.cell = raster.cell;
    out.area_coarsened = raster.cell > raster.first;
    out.overcut_cells = raster.material_cells();
    out.overcut_mm2 = out.overcut_cells.len() as f64 * out.cell * out.cell;
    out.parts = by_part(&out.overcut_cells, out.cell, &material);
    let has_tabs = plan
        .cuts
        .iter()
        .any(|c| c.steps.iter().any(|s| s.role == Role::Tab));
    let (still, attached) = if has_tabs && !held.is_empty() {
        not_freed(input, plan, r, cell, slack, true, threads)
    } else {
        // Again for where they are attached, only when some are.
        match held.is_empty() {
            true => (held.clone(), Vec::new()),
            false => not_freed(input, plan, r, cell, slack, false, threads),
        }
    };
    out.attached = attached;
    out.parts_held_by_tabs = held.iter().filter(|c| !still.contains(c)).count();
    out.parts_not_freed = still.len();
    out.first_not_freed = still
        .iter()
        .find_map(|&c| input.contours.contours.get(c).and_then(|c| c.part));
    out
}

/// The overcut cells (centre, depth) of side `cell` summed part by part,
/// in part order.
fn by_part(cells: &[(Point, f64)], cell: f64, material: &Material) -> Vec<PartLoss> {
    let mut parts: Vec<PartLoss> = Vec::new();
    for &(p, depth) in cells {
        let Some(part) = material.part_at(p) else {
            continue;
        };
        if parts.len() < part {
            parts.resize_with(part, PartLoss::default);
        }
        let loss = &mut parts[part - 1];
        loss.part = part;
        loss.overcut_mm2 += cell * cell;
        loss.max_overcut_mm = loss.max_overcut_mm.max(depth);
    }
    parts.retain(|l| l.part > 0);
    parts
}

/// The corpus for the unit tests (a test module: it runs the pipeline).
#[cfg(test)]
mod corpus {
    /// Every DXF drawing of `../shared/corpus`, sorted.
    fn files() -> Vec<std::path::PathBuf> {
        fn walk(dir: &std::path::Path, out: &mut Vec<std::path::PathBuf>) {
            for e in std::fs::read_dir(dir).into_iter().flatten().flatten() {
                let p = e.path();
                if p.is_dir() {
                    walk(&p, out);
                } else if p.extension().is_some_and(|x| x.eq_ignore_ascii_case("dxf")) {
                    out.push(p);
                }
            }
        }
        let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/../shared/corpus");
        let mut files = Vec::new();
        walk(std::path::Path::new(dir), &mut files);
        files.sort();
        assert!(files.len() > 5, "no corpus at {dir}");
        files
    }

    /// Every corpus drawing that runs, through the whole pipeline at kerf
    /// 1.5: run once for all the tests that read them.
    pub(in crate::plan::verify) fn runs() -> &'static [(std::path::PathBuf, crate::Output)] {
        static RUNS: std::sync::OnceLock<Vec<(std::path::PathBuf, crate::Output)>> =
            std::sync::OnceLock::new();
        RUNS.get_or_init(|| {
            let s = crate::Settings::new(1.5, 0.001, 2000.0).unwrap();
            files()
                .into_iter()
                .filter_map(|path| {
                    let bytes = std::fs::read(&path).unwrap();
                    crate::run(&bytes, &s).ok().map(|out| (path, out))
                })
                .collect()
        })
    }
}

#[cfg(test)]
mod tests {
    use crate::plan::Order;

    fn square_with_hole() -> Vec<u8> {
        let sq = "0\nLWPOLYLINE\n8\n0\n90\n4\n70\n1\n10\n0\n20\n0\n10\n100\n20\n0\n10\n100\n20\n60\n10\n0\n20\n60\n";
        let hole = "0\nCIRCLE\n8\n0\n10\n50\n20\n30\n40\n10\n";
        format!("0\nSECTION\n2\nENTITIES\n{sq}{hole}0\nENDSEC\n0\nEOF\n").into_bytes()
    }

    fn check(order: Order) -> super::Verification {
        let mut s = crate::Settings::new(2.0, 0.001, 1000.0).unwrap();
        s.plan.order = order;
        let out = crate::run(&square_with_hole(), &s).unwrap();
        let input = crate::plan::PlanInput {
            file: crate::plan::FileOrder::of(&out.drawing),
            contours: &out.contours,
            kerf: &out.kerf,
            tolerance: 0.001,
            process: &out.process,
        };
        super::verify(&input, &out.plan, crate::par::Threads::ONE)
    }

    #[test]
    fn a_compensated_plan_passes_and_one_on_the_lines_is_flagged() {
        let v = check(Order::Contour);
        assert_eq!(v.overcut_mm2, 0.0, "{v:?}");
        assert_eq!(v.max_overcut_mm, 0.0);
        assert_eq!(v.parts_not_freed, 0);
        // The drawing order cuts on the drawn lines: half the kerf (1 mm) is
        // taken all round the outline (320 mm) and the hole (62.8 mm).
        let v = check(Order::Drawing);
        assert!((v.max_overcut_mm - 1.0).abs() < 0.01, "{v:?}");
        let want = 320.0 + 20.0 * std::f64::consts::PI;
        assert!(
            (v.overcut_mm2 - want).abs() < 0.1 * want,
            "{} vs {want}",
            v.overcut_mm2
        );
        assert_eq!(v.parts_not_freed, 0);
    }
}
