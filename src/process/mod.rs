//! Process technology (issue 20): the one [`Process`] a job cuts with —
//! what a cut chart entry ([`crate::materials::Entry::process`]) or the
//! user's settings give — and the [`Operation`] each DXF layer gets.
//!
//! Kerf, feed, pierce delay, rapid speed, the heights, the torch-height lock
//! and the small-hole rule live here and nowhere else in a job's settings;
//! the stages read views of it: the offset its width
//! ([`crate::Settings::kerf`]), the planner its [`SmallHole`], the posts
//! [`crate::gcode::JobInfo::from_process`], the time estimate its speeds
//! ([`crate::Output::timing`]), the report and the job sheet its values
//! (the report's `process`).

pub mod depths;
pub mod holes;
pub mod layers;
pub mod passes;
pub mod thc;
pub mod tool;
pub mod tools;
pub mod torches;

pub use depths::{LayerDepth, LayerDepths};
pub use passes::Passes;
pub use thc::ThcLock;
pub use tool::{Entry, OffsetFrom, PocketStrategy, Tool};
pub use tools::{MillTool, Tools};
pub use torches::Torches;

/// Rapid traverse of a typical plasma table, mm/min: the one default the
/// CLI, the page's engine and the posts use.
pub const DEFAULT_RAPID: f64 = 10_000.0;

/// What is done with the geometry of one layer.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Operation {
    /// Cut through, kerf compensated, with leads (the default).
    Cut,
    /// Marked on the line (scribe, etch): no kerf offset, no leads, the
    /// post's own marking codes, done before any cut (a plate moves once
    /// parts are cut free).
    Mark,
    /// A centre-spot: every point and the centre of every closed shape
    /// marked with the post's spot codes.
    Spot,
    /// Not cut (dimensions, text, the sheet outline); reported.
    Ignore,
    /// Router (issue 43): the region inside each closed contour cleared to
    /// the depth, the closed contours inside it (islands) left standing.
    Pocket,
    /// Router: cut through like [`Operation::Cut`], outside outers and
    /// inside holes, with the tool's diameter as the kerf.
    Profile,
    /// Router: on the line, at the depth.
    Engrave,
    /// Router: points, and circles up to [`Tool::drill_max`] at their
    /// centre, drilled in pecks.
    Drill,
}

impl Operation {
    /// Every operation.
    pub const ALL: [Operation; 8] = [
        Operation::Cut,
        Operation::Mark,
        Operation::Spot,
        Operation::Ignore,
        Operation::Pocket,
        Operation::Profile,
        Operation::Engrave,
        Operation::Drill,
    ];
    /// The name used by the CLI, the page and the report.
    pub fn name(self) -> &'static str {
        match self {
            Operation::Cut => "cut",
            Operation::Mark => "mark",
            Operation::Spot => "spot",
            Operation::Ignore => "ignore",
            Operation::Pocket => "pocket",
            Operation::Profile => "profile",
            Operation::Engrave => "engrave",
            Operation::Drill => "drill",
        }
    }
    /// True for the router's own operations (a tool path with depth, not
    /// a kerf path): pocket, engrave, drill.
    pub fn is_milling(self) -> bool {
        matches!(
            self,
            Operation::Pocket | Operation::Engrave | Operation::Drill
        )
    }
    /// The operation called `name`.
    pub fn from_name(name: &str) -> Option<Operation> {
        Operation::ALL.into_iter().find(|o| o.name() == name)
    }
}

/// Words in layer names that say what the layer is for (whole words of
/// the name, upper case; a word may carry more letters: MARKING, DIMS).
/// Paper 001 (notes-001 §6.1, §6.5) keeps the sheet outline on layer
/// `CHAPA` and the other torches' copies on the inactive layer `NULL`:
/// neither is cut by this program. A nest's part labels (layer `LABELS`,
/// issue 42 §2) are scribed when the nest's DXF is cut again.
const MARK_WORDS: [&str; 7] = ["MARK", "ETCH", "SCRIB", "ENGRAV", "GRAV", "MARCA", "LABEL"];
const SPOT_WORDS: [&str; 4] = ["SPOT", "PUNCH", "CENTERPUNCH", "PONTO"];
const IGNORE_WORDS: [&str; 16] = [
    "DIM",
    "TEXT",
    "TXT",
    "COTA",
    "ANNOT",
    "NOTE",
    "TITLE",
    "BORDER",
    "HATCH",
    "HIDDEN",
    "DEFPOINTS",
    "NULL",
    "CHAPA",
    "CONSTR",
    "LEGEND",
    "VIEWPORT",
];

/// The operation a layer's name suggests ([`Operation::Cut`] when it
/// suggests none).
pub fn op_by_name(layer: &str) -> Operation {
    let upper = crate::case::upper(layer);
    let words: Vec<&str> = upper
        .split(|c: char| !c.is_ascii_alphanumeric())
        .filter(|w| !w.is_empty())
        .collect();
    let has = |list: &[&str]| words.iter().any(|w| list.iter().any(|k| w.starts_with(k)));
    if has(&IGNORE_WORDS) {
        Operation::Ignore
    } else if has(&SPOT_WORDS) {
        Operation::Spot
    } else if has(&MARK_WORDS) {
        Operation::Mark
    } else {
        Operation::Cut
    }
}

/// The operation of each layer: the user's choices, else the name's.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct LayerOps {
    /// Layer name (compared without case) and its operation, as given.
    pub given: Vec<(String, Operation)>,
    /// Take the operation from the layer's name where none is given
    /// (default true through [`LayerOps::new`]).
    pub by_name: bool,
}

impl LayerOps {
    /// No choices; operations from layer names.
    pub fn new() -> LayerOps {
        LayerOps {
            given: Vec::new(),
            by_name: true,
        }
    }
    /// The operation of `layer`.
    pub fn op(&self, layer: &str) -> Operation {
        let want = crate::case::lower(layer.trim());
        if let Some((_, op)) = self
            .given
            .iter()
            .rev()
            .find(|(l, _)| crate::case::lower(l.trim()) == want)
        {
            return *op;
        }
        if self.by_name {
            op_by_name(layer)
        } else {
            Operation::Cut
        }
    }
    /// Parses `LAYER=op` (the CLI's `--layer-op`).
    pub fn parse_one(spec: &str) -> Option<(String, Operation)> {
        let (layer, op) = spec.rsplit_once('=')?;
        Some((layer.trim().to_string(), Operation::from_name(op.trim())?))
    }
}

/// Holes cut slower, with the height control locked, entered from the
/// centre and overcut, without a lead-out (issue 20 §3; ProNest's "True
/// Hole", QtPlasmaC's hole modes).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SmallHole {
    /// Holes narrower than this (mm) are small; 0 = no small-hole rule.
    pub diameter: f64,
    /// Their speed, % of the feed.
    pub speed_pct: f64,
    /// Holes narrower than this (mm) cannot be cut: a centre-spot is
    /// marked instead (never below the kerf width).
    pub min_diameter: f64,
    /// Length cut past the start at the end of a small hole, mm.
    pub overcut: f64,
}

impl SmallHole {
    /// Off.
    pub const OFF: SmallHole = SmallHole {
        diameter: 0.0,
        speed_pct: 60.0,
        min_diameter: 0.0,
        overcut: 1.0,
    };
    /// The rule of thumb the issue and torch makers give: holes below
    /// 1.5 × the plate's thickness, at 60 %.
    pub fn for_thickness(thickness: f64) -> SmallHole {
        SmallHole {
            diameter: 1.5 * thickness,
            ..SmallHole::OFF
        }
    }
}

/// The one description of how the job cuts: speeds, times, heights, the
/// kerf. Lengths mm, speeds mm/min, times s.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Process {
    /// Width of the cut.
    pub kerf: f64,
    /// Cutting speed.
    pub feed: f64,
    /// Dwell after the torch comes on.
    pub pierce_delay: f64,
    /// Rapid traverse.
    pub rapid: f64,
    /// Torch height while piercing (Z posts).
    pub pierce_height: f64,
    /// Torch height while cutting (Z posts).
    pub cut_height: f64,
    /// The height control may run (a THC post switches it on after the
    /// pierce and locks it in small holes).
    pub thc: bool,
    /// The small-hole rule.
    pub small_hole: SmallHole,
    /// The controller's material number (QtPlasmaC `M190 Pn`), 0 = none.
    pub material: u32,
    /// Depth passes (knife, router, thick stock); [`Passes::OFF`] by default.
    pub passes: Passes,
    /// Several torches cutting the same moves (paper 001 §6.5); None: one.
    pub torches: Option<Torches>,
    /// Height locks before sharp corners and a contour's end; off by default.
    pub thc_lock: ThcLock,
    /// The router's end mill; [`Tool::OFF`] for a cutting job.
    pub tool: Tool,
}

impl Process {
    /// 1.5 mm kerf, 2000 mm/min, no delay, the default rapid, QtPlasmaC's
    /// example heights (3.8 mm pierce, 1.5 mm cut), THC on, no small-hole rule.
    pub const DEFAULT: Process = Process {
        kerf: 1.5,
        feed: 2000.0,
        pierce_delay: 0.0,
        rapid: DEFAULT_RAPID,
        pierce_height: 3.8,
        cut_height: 1.5,
        thc: true,
        small_hole: SmallHole::OFF,
        material: 0,
        passes: Passes::OFF,
        torches: None,
        thc_lock: ThcLock::OFF,
        tool: Tool::OFF,
    };
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn layer_names_suggest_operations_and_given_ones_win() {
        for (name, op) in [
            ("MARK", Operation::Mark),
            ("marking-1", Operation::Mark),
            ("Scribe lines", Operation::Mark),
            ("ETCH", Operation::Mark),
            ("LABELS", Operation::Mark),
            ("SPOT", Operation::Spot),
            ("Dimensions", Operation::Ignore),
            ("DIM", Operation::Ignore),
            ("TEXT_NOTES", Operation::Ignore),
            ("CHAPA", Operation::Ignore),
            ("NULL", Operation::Ignore),
            ("0", Operation::Cut),
            ("CUT", Operation::Cut),
            ("Outline", Operation::Cut),
            ("RETALHO", Operation::Cut),
        ] {
            assert_eq!(op_by_name(name), op, "{name}");
        }
        let mut ops = LayerOps::new();
        ops.given.push(LayerOps::parse_one("dim=cut").unwrap());
        assert_eq!(ops.op("DIM"), Operation::Cut);
        assert_eq!(ops.op("MARK"), Operation::Mark);
        ops.by_name = false;
        assert_eq!(ops.op("MARK"), Operation::Cut);
        assert_eq!(LayerOps::parse_one("A=B=mark").unwrap().0, "A=B");
        assert_eq!(LayerOps::parse_one("A=drill").unwrap().1, Operation::Drill);
        assert!(LayerOps::parse_one("A=mill").is_none());
        assert!(LayerOps::parse_one("A").is_none());
    }
}
