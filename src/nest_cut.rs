//! Cutting a nest: one sheet of a [`crate::nest::Nest`] through the ordinary
//! pipeline (its drawing → contours → kerf → plan → program, unchanged),
//! then the remnant's crop line as the last cut.
//!
//! The crop line is cut last and on its own pierce at the sheet's edge, on
//! the line, no lead-in (paper 001 §6.7: "CORTE DO RETALHO" at the end of
//! the program, starting on the sheet edge with a full pierce cycle). It is
//! not handed to the planner as an open contour: the planner cuts open
//! contours first (markings must be made while the parts are in place),
//! and a crop line cut first would free the remnant under parts still to
//! be cut. The program's zero is the sheet's lower-left corner (the
//! nest's own coordinates), whatever origin the settings ask for.

use crate::geom::{Point, Segment};
use crate::label::Labels;
use crate::nest::{output, Nest, NestJob, Sheets};
use crate::plan::{Cut, Role};
use crate::process::{Operation, Torches};
use crate::{origin, Error, Output, Settings};

/// The crop cuts of sheet `k` (none unless it is the last sheet and keeps
/// a remnant), each pierced at its upper end on the sheet's edge.
///
/// With several torches every torch cuts the crop line too, each
/// `spacing` further up: torch 1 cuts it only from y = 0 to H − (N−1)·D,
/// so the last torch ends on the sheet's top edge and none cuts past it
/// (torches 2…N pierce on the line, in the scrap between the parts and
/// the remnant).
pub fn crop_cuts(job: &NestJob, n: &Nest, k: usize, torches: Option<&Torches>) -> Vec<Cut> {
    let top = torches.map(|t| {
        let h = match job.sheets.sheet(k) {
            Sheets::Remnant { outline, .. } => crate::geom::path_bbox(&outline).max.y,
            one => one.size(0).1,
        };
        h - t.offset(t.count - 1)
    });
    output::crop_segments(job, n, k)
        .into_iter()
        .filter_map(|s| match top {
            Some(top) => below(s, top),
            None => Some(s),
        })
        .map(|segment| Cut::loose(segment.a, vec![segment], Role::Contour))
        .collect()
}

/// The part of a straight crop segment at or below `top` (None when none is).
fn below(s: Segment, top: f64) -> Option<Segment> {
    let at = |p: Point, q: Point| {
        let t = (top - p.y) / (q.y - p.y);
        Point::new(p.x + t * (q.x - p.x), top)
    };
    match (s.a.y <= top, s.b.y <= top) {
        (true, true) => Some(s),
        (false, false) => None,
        (false, true) => Some(Segment::line(at(s.a, s.b), s.b)),
        (true, false) => Some(Segment::line(s.a, at(s.a, s.b))),
    }
}

/// Sheet `k` of the nest cut with `settings`: the pipeline's [`Output`]
/// (every cutting setting applies: layers, process, posts, verification),
/// its plan ending with the crop line.
pub fn cut_sheet(job: &NestJob, n: &Nest, k: usize, settings: &Settings) -> Result<Output, Error> {
    cut_sheet_labelled(job, n, k, settings, None)
}

/// [`cut_sheet`], scribing `labels` (issue 42 §2): their strokes join
/// the sheet's drawing on a layer of their own, marked as any marking
/// layer is — on the line, before every cut.
pub fn cut_sheet_labelled(
    job: &NestJob,
    n: &Nest,
    k: usize,
    settings: &Settings,
    labels: Option<&Labels>,
) -> Result<Output, Error> {
    let mut drawing = output::sheet_drawing(job, n, k);
    let marking;
    let settings = match labels {
        Some(labels) => {
            let layer = crate::label::output::add_to_drawing(&mut drawing, labels, k);
            let mut s = settings.clone();
            s.layer_ops.given.push((layer, Operation::Mark));
            marking = s;
            &marking
        }
        None => settings,
    };
    let origin = origin::apply(
        &mut drawing,
        origin::ProgramOrigin::Drawing,
        settings.tolerance.mm(),
    );
    let last = crop_cuts(job, n, k, settings.process.torches.as_ref());
    crate::cut_drawing(drawing, origin, settings, last, &mut |_| {})
}

/// Every sheet of the nest cut, in order.
pub fn cut_all(job: &NestJob, n: &Nest, settings: &Settings) -> Result<Vec<Output>, Error> {
    (0..n.sheets.len())
        .map(|k| cut_sheet(job, n, k, settings))
        .collect()
}
