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

mod chained;
mod clearance;
mod cuts;
mod drawing;
mod euler;
pub mod heat;
mod lead;
mod marks;
mod process_figures;
mod scrap;
pub mod tabs;
mod tsp;
mod verify;

pub use tabs::Tabs;
pub use verify::{verify, Verification};

pub use scrap::Intrusion;

use crate::process::layers::Mark;
use crate::process::SmallHole;

use crate::contour::{ContourKind, Contours};
use crate::dxf::Drawing;
use crate::geom::{Point, Segment};
use crate::kerf::KerfPaths;
use crate::warning::Warning;

/// How the contours are sequenced.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Order {
    /// One contour at a time, holes first, short rapids.
    Contour,
    /// Consecutive contours linked through scrap with the torch on (paper 001
    /// "encadeamento", paper 002): one pierce per chain.
    Chained,
    /// One graph of all drawn edges, shared edges cut once (paper 003).
    Eulerian,
    /// The DXF's own entity order (paper 002).
    Drawing,
}

impl Order {
    /// Every order, for comparisons.
    pub const ALL: [Order; 4] = [
        Order::Contour,
        Order::Chained,
        Order::Eulerian,
        Order::Drawing,
    ];
    /// The name used by the CLI, the page and the report.
    pub fn name(self) -> &'static str {
        match self {
            Order::Contour => "contour",
            Order::Chained => "chained",
            Order::Eulerian => "eulerian",
            Order::Drawing => "drawing",
        }
    }
    /// The order called `name`.
    pub fn from_name(name: &str) -> Option<Order> {
        Order::ALL.into_iter().find(|o| o.name() == name)
    }
}

/// How the Eulerian order makes every vertex even (paper 003).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum EulerMode {
    /// The tool stays down and re-travels drawn edges (a knife).
    Repeat,
    /// The tool lifts and moves to the paired odd vertex.
    Rapid,
}

impl EulerMode {
    /// The name used by the CLI and the report.
    pub fn name(self) -> &'static str {
        match self {
            EulerMode::Repeat => "repeat",
            EulerMode::Rapid => "rapid",
        }
    }
    /// The mode called `name`.
    pub fn from_name(name: &str) -> Option<EulerMode> {
        [EulerMode::Repeat, EulerMode::Rapid]
            .into_iter()
            .find(|m| m.name() == name)
    }
}

/// True for "ccw", false for "cw" (the direction settings' names), None otherwise.
pub fn ccw_from_name(name: &str) -> Option<bool> {
    match name {
        "ccw" => Some(true),
        "cw" => Some(false),
        _ => None,
    }
}

/// Shape of the entry from the pierce point to the contour (paper 001 §2.2).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LeadKind {
    /// No lead: pierce on the contour.
    None,
    /// Straight, perpendicular to the first edge ("PV").
    Perpendicular,
    /// Straight, continuing the first edge backwards ("TV"; outer contours,
    /// on a straight edge).
    Tangential,
    /// Straight, along the bisector of the corner ("BV").
    Bisector,
    /// A quarter arc ending tangent to the first edge.
    Arc,
}

impl LeadKind {
    /// The name used by the CLI and the page.
    pub fn name(self) -> &'static str {
        match self {
            LeadKind::None => "none",
            LeadKind::Perpendicular => "perpendicular",
            LeadKind::Tangential => "tangential",
            LeadKind::Bisector => "bisector",
            LeadKind::Arc => "arc",
        }
    }
    /// The kind called `name`.
    pub fn from_name(name: &str) -> Option<LeadKind> {
        [
            LeadKind::None,
            LeadKind::Perpendicular,
            LeadKind::Tangential,
            LeadKind::Bisector,
            LeadKind::Arc,
        ]
        .into_iter()
        .find(|k| k.name() == name)
    }
}

/// Lead-in and lead-out settings.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LeadOptions {
    /// Shape of the lead-in.
    pub kind: LeadKind,
    /// Lead-in length on outer contours, mm.
    pub outer_length: f64,
    /// Lead-in length on holes, mm (shortened in small holes).
    pub hole_length: f64,
    /// Length cut past the pierce point's contour point at the end (overcut), mm.
    pub overcut: f64,
}

impl LeadOptions {
    /// Perpendicular leads of 5 mm outside, 3 mm inside, no overcut.
    pub const DEFAULT: LeadOptions = LeadOptions {
        kind: LeadKind::Perpendicular,
        outer_length: 5.0,
        hole_length: 3.0,
        overcut: 0.0,
    };
    /// No leads at all.
    pub const NONE: LeadOptions = LeadOptions {
        kind: LeadKind::None,
        outer_length: 0.0,
        hole_length: 0.0,
        overcut: 0.0,
    };
}

/// Planning settings.
#[derive(Clone, Debug, PartialEq)]
pub struct PlanOptions {
    /// Where the tool starts (mm).
    pub origin: Point,
    /// Cut outer contours counter-clockwise (default false: clockwise).
    pub outer_ccw: bool,
    /// Cut holes counter-clockwise (default true).
    pub hole_ccw: bool,
    /// The sequencing.
    pub order: Order,
    /// Odd-vertex pairing of the Eulerian order.
    pub euler_mode: EulerMode,
    /// Entries and exits.
    pub leads: LeadOptions,
    /// Longest chain link cut through scrap, mm (chained order).
    pub max_link: f64,
    /// Cut open contours on the line (welding, marking, engraving).
    pub cut_open: bool,
    /// Start points chosen by the user: (contour index, point near it).
    pub starts: Vec<(usize, Point)>,
    /// Small holes: slower, entered from the centre, overcut (issue 20 §3).
    pub small_hole: SmallHole,
    /// Leave the kerf to the controller (G41/G42 on the lead-in, G40
    /// after): the paths are the nominal contours (contour order).
    pub controller_comp: bool,
    /// Tabs left uncut on each part (issue 20 §6); [`Tabs::OFF`] by default.
    pub tabs: Tabs,
    /// Tabs placed by the user, `tabs.width` wide: (contour index, point
    /// near it), each centred where the point falls on its kerf path; on
    /// top of the automatic ones, which give way where they would overlap.
    pub tabs_at: Vec<(usize, Point)>,
}

impl PlanOptions {
    /// Start at (0, 0); outers clockwise, holes counter-clockwise; one
    /// contour at a time with default leads.
    pub const DEFAULT: PlanOptions = PlanOptions {
        origin: Point::new(0.0, 0.0),
        outer_ccw: false,
        hole_ccw: true,
        order: Order::Contour,
        euler_mode: EulerMode::Repeat,
        leads: LeadOptions::DEFAULT,
        max_link: 50.0,
        cut_open: false,
        starts: Vec::new(),
        small_hole: SmallHole::OFF,
        controller_comp: false,
        tabs: Tabs::OFF,
        tabs_at: Vec::new(),
    };
}

/// What a feed move (torch on) is for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Role {
    /// From the pierce point to the contour.
    LeadIn,
    /// On a contour (the first time that edge is cut).
    Contour,
    /// Past the contour's start, or away from it, at the end.
    LeadOut,
    /// Through scrap from one contour to the next, torch on (chained order)
    /// or a bridge between edge groups (Eulerian order).
    Link,
    /// Along an edge already cut (Eulerian order, "repeat" mode).
    Repeat,
    /// Marked on the drawn line (scribe, etch), before any cut.
    Mark,
    /// Over a tab (issue 20 §6): along the contour with the torch off or
    /// the knife up, the material left to hold the part ([`tabs`]).
    Tab,
}

impl Role {
    /// The name used by the report and the page.
    pub fn name(self) -> &'static str {
        match self {
            Role::LeadIn => "lead_in",
            Role::Contour => "contour",
            Role::LeadOut => "lead_out",
            Role::Link => "link",
            Role::Repeat => "repeat",
            Role::Mark => "mark",
            Role::Tab => "tab",
        }
    }
}

/// One feed move.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Step {
    /// The path.
    pub segment: Segment,
    /// What it is for.
    pub role: Role,
    /// The contour it belongs to (contour and lead moves).
    pub contour: Option<usize>,
}

/// One pierce: torch on, feed moves, torch off.
#[derive(Clone, Debug)]
pub struct Cut {
    /// Where the torch pierces (the first step's start).
    pub pierce: Point,
    /// Feed moves, end to end, from `pierce` on. Empty for a spot.
    pub steps: Vec<Step>,
    /// Contours cut in this cut, in order.
    pub contours: Vec<usize>,
    /// Part number (1-based) of the first contour.
    pub part: Option<usize>,
    /// Kind of the first contour.
    pub kind: ContourKind,
    /// A marking at `pierce` (a DXF POINT), not a cut.
    pub spot: bool,
    /// A small hole: cut at the reduced speed with the height control
    /// locked ([`PlanOptions::small_hole`]).
    pub small_hole: bool,
    /// Controller compensation (issue 20 §7): the steps are the nominal
    /// contour and the controller offsets the tool, to the left of the
    /// cutting direction (`Some(true)`, G41) or the right (G42), from the
    /// lead-in line on.
    pub comp: Option<bool>,
}

impl Cut {
    /// Where the torch goes off.
    pub fn end(&self) -> Point {
        self.steps.last().map_or(self.pierce, |s| s.segment.b)
    }
    /// True for a path marked on the line (the marking tool, not the torch).
    pub fn is_mark(&self) -> bool {
        self.steps.first().is_some_and(|s| s.role == Role::Mark)
    }
}

/// One step of the machine program.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Move {
    /// Rapid traverse, torch off.
    Rapid(Point),
    /// Torch on at the current position (a pierce), for cut number `cut`.
    Pierce(usize),
    /// A feed move with the torch on.
    Feed(Step),
    /// Torch off.
    TorchOff,
    /// A marking at the current position, for cut number `cut`.
    Spot(usize),
}

/// Speeds that turn lengths into time.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Timing {
    /// Cutting feed, mm/min.
    pub feed: f64,
    /// Rapid traverse, mm/min.
    pub rapid: f64,
    /// Dwell at each pierce, s.
    pub pierce_delay: f64,
    /// Depth passes over each contour (1 = one cut through;
    /// [`crate::process::Passes`]).
    pub passes: usize,
    /// Feed in small holes, % of `feed` (issue 20 §3; 100: no change).
    pub small_hole_speed: f64,
}

impl Timing {
    /// The feed of cut `c`, mm/min: slowed in a small hole.
    pub fn feed_of(&self, c: &Cut) -> f64 {
        if c.small_hole && self.small_hole_speed > 0.0 {
            self.feed * self.small_hole_speed / 100.0
        } else {
            self.feed
        }
    }
}

/// Lengths and counts of a plan, for comparisons (paper 003's table).
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct PlanStats {
    /// Length cut on contours, mm (each drawn edge once).
    pub cut_length: f64,
    /// Lead-ins, lead-outs and chain links, mm.
    pub lead_length: f64,
    /// Edges travelled again with the tool down, mm.
    pub repeated_length: f64,
    /// Rapid traverse from the origin on, mm.
    pub rapid_length: f64,
    /// Pierces (spots not counted).
    pub pierces: usize,
    /// Chains: cuts that cut more than one contour.
    pub chains: usize,
    /// Spots marked.
    pub spots: usize,
    /// Length marked on the line (scribe), mm.
    pub mark_length: f64,
    /// Small holes cut at the reduced speed.
    pub small_holes: usize,
    /// Tabs left (each a torch restart, counted in `pierces` too).
    pub tabs: usize,
    /// Length crossed over tabs with the torch off, mm.
    pub tab_length: f64,
    /// Of the lengths above, cut in small holes at their own speed:
    /// (contour and repeated, leads), mm.
    pub small_hole_length: (f64, f64),
}

impl PlanStats {
    /// Estimated machine time, s: feed moves at the feed, rapids at the
    /// rapid speed, a dwell per pierce and spot.
    pub fn est_time_s(&self, t: &Timing) -> f64 {
        // Depth passes cut the contours again (and, in a chain, the links
        // between them, counted here once: an estimate slightly low); leads
        // and marks once.
        let passes = t.passes.max(1) as f64;
        let (sh_cut, sh_lead) = self.small_hole_length;
        let feed = (self.cut_length + self.repeated_length - sh_cut) * passes + self.lead_length
            - sh_lead
            + self.mark_length;
        // Small holes at their own speed (as the posts write them).
        let slow = if t.small_hole_speed > 0.0 {
            100.0 / t.small_hole_speed
        } else {
            1.0
        };
        let feed = feed + (sh_cut * passes + sh_lead) * slow;
        // A tab is crossed at the rapid speed (the torch off) and the
        // torch restarts after it (a pierce, counted in `pierces`).
        60.0 * feed / t.feed.max(1e-9)
            + 60.0 * (self.rapid_length + self.tab_length) / t.rapid.max(1e-9)
            + (self.pierces + self.spots) as f64 * t.pierce_delay
    }
}

/// The ordered cuts of a job.
#[derive(Clone, Debug)]
pub struct CutPlan {
    /// Where the tool starts.
    pub origin: Point,
    /// The order used.
    pub order: Order,
    /// Cuts in order.
    pub cuts: Vec<Cut>,
    /// Leads moved or shortened, links refused, shared edges cut on the line…
    pub warnings: Vec<Warning>,
    /// The contour order's rapid tour, improved and as nearest-neighbour
    /// built it (entry points on the contours, before leads).
    pub tour: Option<TourLengths>,
    /// Paths cut once for two parts (Eulerian order), in the direction cut.
    pub common_line: Vec<CommonCut>,
}

/// A path two parts share, cut once (common-line cutting, issue 14): which
/// way it was cut decides which part gets the side a swirling plasma arc
/// leaves square (the right-hand side for a clockwise swirl, paper 000).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CommonCut {
    /// The path piece, from where the cut entered it to where it left.
    pub segment: Segment,
    /// The two parts (1-based) on either side.
    pub parts: (Option<usize>, Option<usize>),
    /// The part on the right of the cut direction.
    pub right: Option<usize>,
}

/// Rapid lengths of the contour order's tour, mm.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TourLengths {
    /// Nearest-neighbour construction.
    pub nearest_neighbour: f64,
    /// After 2-opt, Or-opt and entry re-choice.
    pub improved: f64,
}

impl Default for CutPlan {
    fn default() -> Self {
        CutPlan {
            origin: Point::new(0.0, 0.0),
            order: Order::Contour,
            cuts: Vec::new(),
            warnings: Vec::new(),
            tour: None,
            common_line: Vec::new(),
        }
    }
}

impl CutPlan {
    /// The program as moves: for each cut, a rapid to its pierce point,
    /// torch on, the feed moves, torch off (or a spot).
    pub fn moves(&self) -> impl Iterator<Item = Move> + '_ {
        self.cuts.iter().enumerate().flat_map(|(i, c)| {
            let (on, off) = if c.spot {
                (Move::Spot(i), None)
            } else {
                (Move::Pierce(i), Some(Move::TorchOff))
            };
            [Move::Rapid(c.pierce), on]
                .into_iter()
                .chain(c.steps.iter().map(|s| Move::Feed(*s)))
                .chain(off)
        })
    }
    /// Lengths and counts.
    pub fn stats(&self) -> PlanStats {
        let mut st = PlanStats::default();
        let mut at = self.origin;
        for c in &self.cuts {
            st.rapid_length += at.dist(c.pierce);
            at = c.end();
            if c.spot {
                st.spots += 1;
                continue;
            }
            st.pierces += 1;
            st.small_holes += usize::from(c.small_hole);
            if c.contours.len() > 1 {
                st.chains += 1;
            }
            for s in &c.steps {
                let l = s.segment.length();
                if c.small_hole {
                    match s.role {
                        Role::Contour | Role::Repeat => st.small_hole_length.0 += l,
                        Role::LeadIn | Role::LeadOut | Role::Link => st.small_hole_length.1 += l,
                        Role::Mark | Role::Tab => {}
                    }
                }
                match s.role {
                    Role::Contour => st.cut_length += l,
                    Role::Repeat => st.repeated_length += l,
                    Role::LeadIn | Role::LeadOut | Role::Link => st.lead_length += l,
                    Role::Mark => st.mark_length += l,
                    Role::Tab => {
                        st.tab_length += l;
                        st.tabs += 1;
                        st.pierces += 1;
                    }
                }
            }
        }
        st
    }
    /// Length cut on contours, mm.
    pub fn cut_length(&self) -> f64 {
        self.stats().cut_length
    }
    /// Total rapid length in mm, from the origin on.
    pub fn rapid_length(&self) -> f64 {
        self.stats().rapid_length
    }
    /// Number of pierces.
    pub fn pierces(&self) -> usize {
        self.stats().pierces
    }
    /// Estimated machine time, s ([`PlanStats::est_time_s`]).
    pub fn est_time_s(&self, t: &Timing) -> f64 {
        self.stats().est_time_s(t)
    }
}

/// What the planner plans from.
#[derive(Clone, Copy, Debug)]
pub struct PlanInput<'a> {
    /// The drawing (entity order and spots, for the drawing order).
    pub drawing: &'a Drawing,
    /// The contours as drawn (the Eulerian order cuts on them; leads must not cross them).
    pub contours: &'a Contours,
    /// The compensated paths.
    pub kerf: &'a KerfPaths,
    /// The one tolerance, mm.
    pub tolerance: f64,
    /// Kerf width the paths were compensated for, mm.
    pub kerf_width: f64,
}

/// How far the torch-on moves of `plan` cut into the drawn parts of
/// `input` (every order's plan is checked the same way, [`scrap::intrusion`]).
pub fn intrusion(input: &PlanInput, plan: &CutPlan) -> Intrusion {
    let obstacles = clearance::Obstacles::new(input.contours, input.tolerance);
    let scrap = scrap::Scrap::new(
        &obstacles,
        input.contours,
        input.kerf_width,
        input.tolerance,
    );
    scrap::intrusion(plan, &scrap)
}

/// Plans a job with marks and spots (issue 20 §2): they are marked first,
/// nearest next from the origin (a plate moves once parts are cut free),
/// and the cuts planned from where marking ended.
pub fn plan_with_marks(
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

/// Orders the compensated paths into a plan, with tabs where asked.
pub fn plan(input: &PlanInput, options: &PlanOptions) -> CutPlan {
    let mut p = plan_order(input, options);
    tabs::apply(
        &mut p,
        input.contours,
        &options.tabs,
        &options.tabs_at,
        input.kerf_width,
    );
    p
}

/// Orders the compensated paths into a plan.
fn plan_order(input: &PlanInput, options: &PlanOptions) -> CutPlan {
    match options.order {
        Order::Eulerian => return euler::plan(input, options),
        Order::Drawing => return drawing::plan(input, options),
        Order::Contour | Order::Chained => {}
    }
    let obstacles = clearance::Obstacles::new(input.contours, input.tolerance);
    let mut builder = cuts::Builder::new(input, options, &obstacles);
    let mut at = options.origin;
    let mut cuts = Vec::with_capacity(input.kerf.paths.len());
    if options.cut_open {
        // Markings and open cuts first: the parts they lie on must still be in place.
        for c in open_order(input, at) {
            if let Some(cut) = builder.open_cut(c, at) {
                at = cut.end();
                cuts.push(cut);
            }
        }
    }
    let parents: Vec<Option<usize>> = input.contours.contours.iter().map(|c| c.parent).collect();
    let path_of = paths_by_contour(input, parents.len());
    let (sites, tour) = rapid_tour(input, options, &parents, &path_of, at);
    for (k, c) in tour.visits.iter().copied() {
        let near = sites[k].candidates.get(c).copied().unwrap_or(at);
        if let Some(cut) = builder.contour_cut(k, near) {
            cuts.push(cut);
        }
    }
    if options.order == Order::Chained {
        let top = |c: usize| parents.get(c).is_some_and(|p| p.is_none());
        let mut replan = |c: &Cut, near: Point| {
            let k = path_of.get(*c.contours.first()?).copied().flatten()?;
            builder.contour_cut(k, near)
        };
        let scrap = scrap::Scrap::new(
            &obstacles,
            input.contours,
            input.kerf_width,
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
    }
}

/// The contour order as a generalised TSP with precedence ([`tsp`]): one
/// site per kerf path, its candidates the path's vertices (or the user's
/// start point), its parent the nearest enclosing contour that is cut.
fn rapid_tour(
    input: &PlanInput,
    options: &PlanOptions,
    parents: &[Option<usize>],
    path_of: &[Option<usize>],
    from: Point,
) -> (Vec<tsp::Site>, tsp::Tour) {
    let sites: Vec<tsp::Site> = input
        .kerf
        .paths
        .iter()
        .map(|p| {
            let user = options.starts.iter().rev().find(|(c, _)| *c == p.contour);
            let candidates = match user {
                Some((_, at)) => vec![*at],
                None => p.segments.iter().map(|s| s.a).collect(),
            };
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
            tsp::Site { candidates, parent }
        })
        .collect();
    let tour = tsp::order(&sites, from);
    (sites, tour)
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

/// Open contours, nearest end next from `from`.
fn open_order(input: &PlanInput, from: Point) -> Vec<usize> {
    let mut left: Vec<usize> = (0..input.contours.contours.len())
        .filter(|&c| input.contours.contours[c].kind == ContourKind::Open)
        .collect();
    let mut at = from;
    let mut out = Vec::with_capacity(left.len());
    while !left.is_empty() {
        let ends = |c: usize| {
            let k = &input.contours.contours[c];
            (k.start(), k.segments.last().map_or(k.start(), |s| s.b))
        };
        let Some((i, _)) = left
            .iter()
            .enumerate()
            .map(|(i, &c)| {
                let (a, b) = ends(c);
                (i, a.dist(at).min(b.dist(at)))
            })
            .min_by(|x, y| x.1.total_cmp(&y.1))
        else {
            break;
        };
        let c = left.swap_remove(i);
        let (a, b) = ends(c);
        at = if a.dist(at) <= b.dist(at) { b } else { a };
        out.push(c);
    }
    out
}
