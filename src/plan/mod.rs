//! Stage 4: [`KerfPaths`] → [`CutPlan`]: which contour is cut when, where it
//! is pierced, and in which direction.
//!
//! # Output contract
//! - Every hole of a part is cut before the part's outer contour, and a part
//!   sitting in a hole (an island) before that hole (paper 000 "Sequence",
//!   paper 001 §4: a part that drops free cannot be cut any more).
//! - Parts, and holes within a part, are visited nearest-next from the
//!   current tool position ([`order`]).
//! - Each contour is pierced once, at the path vertex nearest to the tool,
//!   and cut once around, ending where it was pierced.
//! - Outer contours are cut clockwise and holes counter-clockwise by default,
//!   so a clockwise-swirl torch keeps its square side on the part.
//! - [`CutPlan::moves`] is the single description of the program: the G-code
//!   and the preview are both drawn from it.

mod order;

use crate::contour::ContourKind;
use crate::geom::{path_length, Point, Segment};
use crate::kerf::KerfPaths;

/// Planning settings.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PlanOptions {
    /// Where the tool starts (mm).
    pub origin: Point,
    /// Cut outer contours counter-clockwise (default false: clockwise).
    pub outer_ccw: bool,
    /// Cut holes counter-clockwise (default true).
    pub hole_ccw: bool,
}

impl PlanOptions {
    /// Start at (0, 0); outers clockwise, holes counter-clockwise.
    pub const DEFAULT: PlanOptions = PlanOptions {
        origin: Point::new(0.0, 0.0),
        outer_ccw: false,
        hole_ccw: true,
    };
}

/// One contour cut: pierce, go around, torch off.
#[derive(Clone, Debug)]
pub struct Cut {
    /// Index of the source contour.
    pub contour: usize,
    /// Part number (1-based).
    pub part: Option<usize>,
    /// Outer or hole.
    pub kind: ContourKind,
    /// Where the torch pierces (the first segment's start).
    pub pierce: Point,
    /// The loop, starting and ending at `pierce`.
    pub segments: Vec<Segment>,
}

/// One step of the machine program.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Move {
    /// Rapid traverse, torch off.
    Rapid(Point),
    /// Torch on at the current position (a pierce), for cut number `cut`.
    Pierce(usize),
    /// A cutting move.
    Cut(Segment),
    /// Torch off.
    TorchOff,
}

/// The ordered cuts of a job.
#[derive(Clone, Debug, Default)]
pub struct CutPlan {
    /// Where the tool starts.
    pub origin: Point,
    /// Cuts in order.
    pub cuts: Vec<Cut>,
}

impl CutPlan {
    /// The program as moves: for each cut, a rapid to its pierce point,
    /// torch on, the cutting moves, torch off.
    pub fn moves(&self) -> impl Iterator<Item = Move> + '_ {
        self.cuts.iter().enumerate().flat_map(|(i, c)| {
            [Move::Rapid(c.pierce), Move::Pierce(i)]
                .into_iter()
                .chain(c.segments.iter().map(|s| Move::Cut(*s)))
                .chain(std::iter::once(Move::TorchOff))
        })
    }
    /// Total cutting length in mm.
    pub fn cut_length(&self) -> f64 {
        self.cuts.iter().map(|c| path_length(&c.segments)).sum()
    }
    /// Total rapid length in mm, from the origin on.
    pub fn rapid_length(&self) -> f64 {
        let mut at = self.origin;
        let mut total = 0.0;
        for c in &self.cuts {
            total += at.dist(c.pierce);
            at = c.segments.last().map_or(c.pierce, |s| s.b);
        }
        total
    }
    /// Number of pierces.
    pub fn pierces(&self) -> usize {
        self.cuts.len()
    }
}

/// Orders the compensated paths into a plan.
pub fn plan(paths: &KerfPaths, parents: &[Option<usize>], options: &PlanOptions) -> CutPlan {
    let sequence = order::holes_first_nearest(paths, parents, options.origin);
    let mut at = options.origin;
    let mut cuts = Vec::with_capacity(sequence.len());
    for k in sequence {
        let p = &paths.paths[k];
        if p.segments.is_empty() {
            continue;
        }
        let ccw = if p.kind == ContourKind::Hole {
            options.hole_ccw
        } else {
            options.outer_ccw
        };
        // Kerf paths are counter-clockwise.
        let mut segs: Vec<Segment> = if ccw {
            p.segments.clone()
        } else {
            p.segments.iter().rev().map(Segment::reversed).collect()
        };
        let start = nearest_vertex(&segs, at);
        segs.rotate_left(start);
        let pierce = segs[0].a;
        at = pierce;
        cuts.push(Cut {
            contour: p.contour,
            part: p.part,
            kind: p.kind,
            pierce,
            segments: segs,
        });
    }
    CutPlan {
        origin: options.origin,
        cuts,
    }
}

/// Index of the segment whose start is nearest to `p`.
fn nearest_vertex(segs: &[Segment], p: Point) -> usize {
    segs.iter()
        .enumerate()
        .min_by(|(_, a), (_, b)| a.a.dist(p).total_cmp(&b.a.dist(p)))
        .map_or(0, |(i, _)| i)
}
