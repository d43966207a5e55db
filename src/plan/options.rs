//! Planning settings: the order, the cutting directions, leads, chain
//! links, user start points, small holes, controller compensation, tabs.

use crate::geom::Point;
use crate::par::Threads;

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

/// How many tabs, how wide, on which contours.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Tabs {
    /// Tabs per contour (0 = off).
    pub count: usize,
    /// Material left in each tab, mm.
    pub width: f64,
    /// Tabs on holes too (their slug stays in the part); outer contours only
    /// by default.
    pub holes: bool,
}

impl Tabs {
    /// No tabs.
    pub const OFF: Tabs = Tabs {
        count: 0,
        width: 0.0,
        holes: false,
    };
    /// True when tabs are asked for.
    pub fn on(&self) -> bool {
        self.count > 0 && self.width > 0.0
    }
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
    /// Start points chosen by the operator, each kept by the loop it was
    /// set on ([`super::choice`]); the last on a loop wins.
    pub starts: Vec<super::choice::Pick>,
    /// Leave the kerf to the controller (G41/G42 on the lead-in, G40
    /// after): the paths are the nominal contours (contour order).
    pub controller_comp: bool,
    /// Tabs left uncut on each part (issue 20 §6); [`Tabs::OFF`] by default.
    pub tabs: Tabs,
    /// Tabs placed by the operator, `tabs.width` wide, each kept by the
    /// loop it was set on ([`super::choice`]) and centred where its point
    /// falls on the loop's kerf path; on top of the automatic ones, which
    /// give way where they would overlap.
    pub tabs_at: Vec<super::choice::Pick>,
    /// Router profiles' sides chosen on single loops (issue 43 §1), each
    /// kept by the loop it was set on ([`super::choice::sides`]); the
    /// other loops go to their scrap side.
    pub sides_at: Vec<super::choice::SidePick>,
    /// Threads that may build the plan (the plan is the same with any).
    pub threads: Threads,
    /// Runs of short feed moves rewritten as lines and arcs within the
    /// job's tolerance (issue 43 §5, [`super::fit_arcs`]).
    pub fit_arcs: bool,
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
        controller_comp: false,
        tabs: Tabs::OFF,
        tabs_at: Vec::new(),
        sides_at: Vec::new(),
        threads: Threads::ONE,
        fit_arcs: false,
    };
}
