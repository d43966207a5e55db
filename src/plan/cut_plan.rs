//! What the planner makes: cuts (one pierce each) of feed steps tagged by
//! role, the program as moves, and the lengths, counts and time estimate
//! read from them.

use crate::contour::ContourKind;
use crate::geom::{Point, Segment};
use crate::process::Process;
use crate::warning::Warning;

use super::Order;

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
    /// the knife up, the material left to hold the part ([`super::tabs`]).
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
    /// locked ([`crate::process::SmallHole`]).
    pub small_hole: bool,
    /// Controller compensation (issue 20 §7): the steps are the nominal
    /// contour and the controller offsets the tool, to the left of the
    /// cutting direction (`Some(true)`, G41) or the right (G42), from the
    /// lead-in line on.
    pub comp: Option<bool>,
}

impl Cut {
    /// Its feed with the process `p`, mm/min: slowed in a small hole.
    pub fn feed(&self, p: &Process) -> f64 {
        if self.small_hole && p.small_hole.speed_pct > 0.0 {
            p.feed * p.small_hole.speed_pct / 100.0
        } else {
            p.feed
        }
    }
    /// Where the torch goes off.
    pub fn end(&self) -> Point {
        self.steps.last().map_or(self.pierce, |s| s.segment.b)
    }
    /// True for a path marked on the line (the marking tool, not the torch).
    pub fn is_mark(&self) -> bool {
        self.steps.first().is_some_and(|s| s.role == Role::Mark)
    }
    /// A cut of loose segments that belong to no contour and no part, all
    /// of one role (a sheet's crop line, a marking's path), pierced at
    /// `pierce`.
    pub fn loose(pierce: Point, segments: Vec<Segment>, role: Role) -> Cut {
        Cut {
            pierce,
            steps: segments
                .into_iter()
                .map(|segment| Step {
                    segment,
                    role,
                    contour: None,
                })
                .collect(),
            contours: Vec::new(),
            part: None,
            kind: ContourKind::Open,
            spot: false,
            small_hole: false,
            comp: None,
        }
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
    /// Counts one feed move of `length` mm and role `role`, in a small
    /// hole or not (what [`CutPlan::stats`] does for each step; the quote
    /// adds each step to the stats of the part it is charged to, so the
    /// parts' times sum to the plan's).
    pub fn add_step(&mut self, role: Role, length: f64, small_hole: bool) {
        let l = length;
        if small_hole {
            match role {
                Role::Contour | Role::Repeat => self.small_hole_length.0 += l,
                Role::LeadIn | Role::LeadOut | Role::Link => self.small_hole_length.1 += l,
                Role::Mark | Role::Tab => {}
            }
        }
        match role {
            Role::Contour => self.cut_length += l,
            Role::Repeat => self.repeated_length += l,
            Role::LeadIn | Role::LeadOut | Role::Link => self.lead_length += l,
            Role::Mark => self.mark_length += l,
            Role::Tab => {
                self.tab_length += l;
                self.tabs += 1;
                self.pierces += 1;
            }
        }
    }
    /// Estimated machine time, s, with the process's speeds: feed moves at
    /// the feed (slowed in small holes), rapids at the rapid speed, a dwell
    /// per pierce and spot, contours once per depth pass.
    pub fn est_time_s(&self, t: &Process) -> f64 {
        // Depth passes cut the contours again (and, in a chain, the links
        // between them, counted here once: an estimate slightly low); leads
        // and marks once.
        let passes = t.passes.count().max(1) as f64;
        let (sh_cut, sh_lead) = self.small_hole_length;
        let feed = (self.cut_length + self.repeated_length - sh_cut) * passes + self.lead_length
            - sh_lead
            + self.mark_length;
        // Small holes at their own speed (as the posts write them).
        let slow = if t.small_hole.speed_pct > 0.0 {
            100.0 / t.small_hole.speed_pct
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
    /// Feed moves before and after arc fitting, when the job fitted them
    /// ([`super::fit`]).
    pub arc_fit: Option<ArcFit>,
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
            arc_fit: None,
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
                st.add_step(s.role, s.segment.length(), c.small_hole);
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
    pub fn est_time_s(&self, t: &Process) -> f64 {
        self.stats().est_time_s(t)
    }
}

/// Feed moves of a plan before and after arc fitting (the report's figures).
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct ArcFit {
    /// Straight feed moves before.
    pub lines_before: usize,
    /// Arc feed moves before.
    pub arcs_before: usize,
    /// Straight feed moves after.
    pub lines_after: usize,
    /// Arc feed moves after.
    pub arcs_after: usize,
    /// The tolerance fitted to, mm.
    pub tolerance: f64,
}
