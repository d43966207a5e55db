//! Stage 4: contours and kerf paths → [`CutPlan`]: which contour is cut when,
//! where the torch pierces, how it enters and leaves, and in which direction.
//!
//! # Output contract
//! - [`CutPlan::moves`] is the single description of the program: the G-code,
//!   the preview, the animation and the report are all drawn from it.
//! - A [`Cut`] is one pierce: torch on at [`Cut::pierce`], feed moves
//!   ([`Step`]s) each tagged with its [`Role`] (lead-in, contour, lead-out,
//!   chain link, repeated edge), torch off. A spot (a DXF POINT) is a cut
//!   with no steps.
//! - In every order except "eulerian", every hole of a part is cut before the
//!   part's outer contour, and an island before the hole around it (paper 000
//!   "Sequence", paper 001 §3: a part that drops free cannot be cut any more).
//! - Outer contours are cut clockwise and holes counter-clockwise by default,
//!   so a clockwise-swirl torch keeps its square side on the part.

mod build;
mod chained;
pub mod choice;
mod clearance;
pub mod closeness;
mod crossing;
mod cut_plan;
mod cuts;
mod drawing;
mod euler;
mod fit;
pub mod heat;
mod lead;
mod marks;
pub mod narrow;
mod nearest;
mod open;
mod options;
mod part_boxes;
mod process_figures;
mod router_lead;
mod scrap;
mod shared;
pub mod tabs;
mod tsp;
mod verify;

pub use tabs::Tabs;
pub use verify::{verify, PartLoss, Verification};

pub use scrap::Intrusion;

pub use cut_plan::{ArcFit, CommonCut, Cut, CutPlan, Move, PlanStats, Role, Step, TourLengths};
pub use fit::fit_arcs;
pub use options::{ccw_from_name, EulerMode, LeadKind, LeadOptions, Order, PlanOptions};

use crate::process::layers::Mark;
use crate::process::Process;

use crate::contour::Contours;
use crate::dxf::{Drawing, Entity, Spot};
use crate::geom::Point;
use crate::kerf::KerfPaths;

/// The drawn entities in the file's own order, with the POINTs among
/// them: what the drawing order (paper 002) cuts, on the drawn lines. No
/// other order reads it; they plan from the contours and kerf paths.
#[derive(Clone, Copy, Debug)]
pub struct FileOrder<'a> {
    /// Geometry entities, in file order.
    pub entities: &'a [Entity],
    /// POINTs, each placed after the entities read before it.
    pub spots: &'a [Spot],
}

impl<'a> FileOrder<'a> {
    /// The entities and POINTs of `drawing`.
    pub fn of(drawing: &'a Drawing) -> FileOrder<'a> {
        FileOrder {
            entities: &drawing.entities,
            spots: &drawing.spots,
        }
    }
}

/// What the planner plans from.
#[derive(Clone, Copy, Debug)]
pub struct PlanInput<'a> {
    /// The drawn entities in the file's order (the drawing order's input).
    pub file: FileOrder<'a>,
    /// The contours as drawn (the Eulerian order cuts on them; leads must not cross them).
    pub contours: &'a Contours,
    /// The compensated paths.
    pub kerf: &'a KerfPaths,
    /// The one tolerance, mm.
    pub tolerance: f64,
    /// How the job cuts: the kerf the paths were compensated for, the
    /// small-hole rule (the job's one [`Process`]).
    pub process: &'a Process,
}

/// How far the torch-on moves of `plan` cut into the drawn parts of
/// `input` (every order's plan is checked the same way, [`scrap::intrusion`]).
pub fn intrusion(input: &PlanInput, plan: &CutPlan) -> Intrusion {
    let obstacles = clearance::Obstacles::new(input.contours, input.tolerance);
    let scrap = scrap::Scrap::new(
        &obstacles,
        input.contours,
        input.process.kerf,
        input.tolerance,
    );
    scrap::intrusion(plan, &scrap)
}

/// Plans a job with marks and spots (issue 20 §2): they are marked first,
/// nearest next from the origin (a plate moves once parts are cut free),
/// and the cuts planned from where marking ended. Its feed moves are
/// arc-fitted within the job's tolerance when the options ask
/// ([`PlanOptions::fit_arcs`]).
pub fn plan_with_marks(
    input: &PlanInput,
    marks: &[Mark],
    spots: &[Point],
    options: &PlanOptions,
) -> CutPlan {
    let mut p = plan_marked(input, marks, spots, options);
    if options.fit_arcs {
        fit_arcs(&mut p, input.tolerance);
    }
    p
}

/// [`plan_with_marks`] before arc fitting.
fn plan_marked(
    input: &PlanInput,
    marks: &[Mark],
    spots: &[Point],
    options: &PlanOptions,
) -> CutPlan {
    if marks.is_empty() && spots.is_empty() {
        return plan(input, options);
    }
    let (mut first, at) = marks::plan(marks, spots, options.origin);
    let mut from_there = options.clone();
    from_there.origin = at;
    let mut p = plan(input, &from_there);
    p.origin = options.origin;
    first.append(&mut p.cuts);
    p.cuts = first;
    p
}

/// Orders the compensated paths into a plan, with tabs where asked. The
/// operator's start points and tabs are matched to the loops they were
/// set on ([`choice::place`]); those that cannot be applied are named in
/// a warning, never moved to another loop.
pub fn plan(input: &PlanInput, options: &PlanOptions) -> CutPlan {
    use choice::Unapplied;
    let start_on = choice::place(&options.starts, input.contours, input.tolerance);
    let tab_on = choice::place(&options.tabs_at, input.contours, input.tolerance);
    let own_entries = matches!(options.order, Order::Eulerian | Order::Drawing);
    let starts = if own_entries {
        Vec::new()
    } else {
        choice::applied(&options.starts, &start_on)
    };
    let mut p = plan_order(input, options, &starts);
    let tabs_at = choice::applied(&options.tabs_at, &tab_on);
    let tab_held = tabs::apply(
        &mut p,
        input.contours,
        &options.tabs,
        &tabs_at,
        input.process.kerf,
    );
    // A start on a loop that is not cut as a loop (a small hole entered
    // from its centre, a loop the kerf closed) is not applied either.
    let as_loop = if starts.is_empty() {
        Default::default()
    } else {
        loops_cut(&p)
    };
    let why = |placed: Option<usize>, room: bool| match placed {
        None => Some(Unapplied::Gone),
        Some(_) if !room => Some(Unapplied::NoRoom),
        Some(_) => None,
    };
    let starts_missed: Vec<_> = options
        .starts
        .iter()
        .zip(&start_on)
        .filter_map(|(pick, &c)| {
            if own_entries && c.is_some() {
                return Some((pick, Unapplied::Order));
            }
            why(c, c.is_some_and(|c| as_loop.contains(&c))).map(|w| (pick, w))
        })
        .collect();
    // `tab_held[k]`: the k-th applied tab found room on its loop.
    let mut held = tab_held.iter();
    let tabs_missed: Vec<_> = options
        .tabs_at
        .iter()
        .zip(&tab_on)
        .filter_map(|(pick, &c)| {
            let room = c.is_some() && held.next().copied().unwrap_or(false);
            why(c, room).map(|w| (pick, w))
        })
        .collect();
    p.warnings.extend(choice::not_applied(
        &starts_missed,
        &tabs_missed,
        input.contours,
    ));
    p
}

/// The contours cut as loops by `plan`: their steps in a cut that is not
/// a small hole's.
fn loops_cut(plan: &CutPlan) -> std::collections::HashSet<usize> {
    plan.cuts
        .iter()
        .filter(|c| !c.small_hole)
        .flat_map(|c| &c.steps)
        .filter(|s| s.role == Role::Contour)
        .filter_map(|s| s.contour)
        .collect()
}

/// Orders the compensated paths into a plan; `starts` are the operator's
/// start points, (contour, point).
fn plan_order(input: &PlanInput, options: &PlanOptions, starts: &[(usize, Point)]) -> CutPlan {
    match options.order {
        Order::Eulerian => return euler::plan(input, options),
        // Parts drawn sharing their edges: each shared line cut once (issue 39 §6).
        Order::Contour | Order::Chained if shared::cuts_faces(input) => {
            return shared::plan(input, options, |i, o| plan_order(i, o, starts))
        }
        Order::Drawing => return drawing::plan(input, options),
        Order::Contour | Order::Chained => {}
    }
    let threads = options.threads;
    let parents: Vec<Option<usize>> = input.contours.contours.iter().map(|c| c.parent).collect();
    // The clearance index is built while the tour is made: the tour does
    // not read it (~20 ms of the 25 MB nest's plan, issue 17).
    let ((open, path_of, tour), obstacles) = crate::par::join(
        threads,
        || {
            let mut at = options.origin;
            let mut open = Vec::new();
            if options.cut_open {
                // Markings and open cuts first: the parts they lie on must still be in place.
                for c in open::order(input, at) {
                    if let Some(cut) = open::cut(input, c, at) {
                        at = cut.end();
                        open.push(cut);
                    }
                }
            }
            let path_of = paths_by_contour(input, parents.len());
            let tour = rapid_tour(input, options, starts, &parents, &path_of, at);
            (open, path_of, tour)
        },
        || clearance::Obstacles::new(input.contours, input.tolerance),
    );
    let mut builder = cuts::Builder::new(input, options, starts, &obstacles);
    let mut cuts = build::in_ranges(
        &mut builder,
        input,
        options,
        starts,
        &obstacles,
        &tour,
        open,
    );
    if options.order == Order::Chained {
        let top = |c: usize| parents.get(c).is_some_and(|p| p.is_none());
        let mut replan = |c: &Cut, near: Point| {
            let k = path_of.get(*c.contours.first()?).copied().flatten()?;
            builder.contour_cut(k, near)
        };
        let scrap = scrap::Scrap::new(
            &obstacles,
            input.contours,
            input.process.kerf,
            input.tolerance,
        );
        cuts = chained::chain(
            cuts,
            options.max_link,
            &obstacles,
            &scrap,
            &top,
            &mut replan,
        );
    }
    CutPlan {
        origin: options.origin,
        order: options.order,
        cuts,
        warnings: crate::warning::group(builder.warnings()),
        tour: Some(TourLengths {
            nearest_neighbour: tour.nn_length,
            improved: tour.length,
        }),
        common_line: Vec::new(),
        arc_fit: None,
    }
}

/// The contour order as a generalised TSP with precedence ([`tsp`]): one
/// site per kerf path, its candidates the path's vertices (or the user's
/// start point), its parent the nearest enclosing contour that is cut.
/// The sites are stored flat ([`tsp::Sites`]): a vector of candidates per
/// path was 137k allocations on the 25 MB nest, copied and dropped.
fn rapid_tour(
    input: &PlanInput,
    options: &PlanOptions,
    starts: &[(usize, Point)],
    parents: &[Option<usize>],
    path_of: &[Option<usize>],
    from: Point,
) -> tsp::Tour {
    let paths = &input.kerf.paths;
    let mut sites =
        tsp::Sites::with_capacity(paths.len(), paths.iter().map(|p| p.segments.len()).sum());
    for p in paths {
        let user = starts.iter().rev().find(|(c, _)| *c == p.contour);
        // The nearest enclosing contour that has a path (a hole that
        // vanished under the kerf passes its islands on to the part).
        let mut up = parents.get(p.contour).copied().flatten();
        let mut guard = 0;
        let parent = loop {
            match up {
                Some(c) if guard < parents.len() => match path_of.get(c).copied().flatten() {
                    Some(k) => break Some(k),
                    None => {
                        up = parents.get(c).copied().flatten();
                        guard += 1;
                    }
                },
                _ => break None,
            }
        };
        match user {
            Some((_, at)) => sites.push([*at], parent),
            None => sites.push(p.segments.iter().map(|s| s.a), parent),
        }
    }
    tsp::order_sites(&sites, from, None, options.threads)
}

/// For each of the `n` contours, the index of its kerf path (None when it
/// has none: open, or vanished under the kerf).
fn paths_by_contour(input: &PlanInput, n: usize) -> Vec<Option<usize>> {
    let mut path_of = vec![None; n];
    for (k, p) in input.kerf.paths.iter().enumerate() {
        if let Some(slot) = path_of.get_mut(p.contour) {
            *slot = Some(k);
        }
    }
    path_of
}
