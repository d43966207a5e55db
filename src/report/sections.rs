//! The report's sections: one contour, one warning, sizes and extents,
//! the plan's totals, common lines, layers, healing, the verification, and
//! one order of a comparison. Field names are the JSON's.

use serde::Serialize;

use crate::warning::{Loss, Severity, Text};

/// One contour in the report.
#[derive(Clone, Debug, Serialize)]
pub struct ContourReport {
    /// Closed loop?
    pub closed: bool,
    /// "outer", "hole" or "open".
    pub kind: &'static str,
    /// Containment depth.
    pub depth: usize,
    /// Part number (1-based) of closed contours.
    pub part: Option<usize>,
    /// Enclosed area, mm² (absolute; 0 for open).
    pub area: f64,
    /// Length, mm.
    pub length: f64,
    /// "ccw" or "cw" as drawn (None for open).
    pub direction: Option<&'static str>,
    /// `[x0, y0, x1, y1]`, mm.
    pub bbox: [f64; 4],
    /// Layer of its first entity.
    pub layer: String,
    /// Its part, copy and loop (`{part, copy, contour}`; on a nested
    /// sheet the part is the nest's, 1-based), which stay true through
    /// layers and nesting where the index does not.
    pub source: crate::source::ContourRef,
}

/// One warning in the report.
#[derive(Clone, Debug, Serialize)]
pub struct WarningReport {
    /// Stable short name of the kind ("units-assumed"): scripts match this, not the text.
    pub code: &'static str,
    /// The message in the report's language (English unless asked otherwise).
    pub message: String,
    /// The message in every language (`{"en": …, "pt-BR": …}`), so a page
    /// can switch language without running the job again.
    pub messages: Text,
    /// Where, mm (the first place of a group).
    pub at: Option<[f64; 2]>,
    /// "error", "warning" or "info" (repairs and notes).
    pub severity: Severity,
    /// How many identical warnings this one stands for.
    pub count: usize,
    /// The first places of the group, mm.
    pub places: Vec<[f64; 2]>,
    /// "cuts-into" (the cuts take material from parts) or "not-cut"
    /// (drawn loops left uncut); absent for other warnings.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub loss: Option<Loss>,
    /// The drawn loops it is about (`{part, copy, contour}`), those the
    /// page marks on the preview; absent when none are named.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub loops: Vec<crate::source::ContourRef>,
}

/// The drawing's overall size.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct SizeReport {
    /// Width, mm.
    pub w: f64,
    /// Height, mm.
    pub h: f64,
}

/// A box in program coordinates.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct ExtentReport {
    /// Lower-left corner, mm.
    pub min: [f64; 2],
    /// Upper-right corner, mm.
    pub max: [f64; 2],
}

/// What the swept kerf takes from the parts.
#[derive(Clone, Debug, Serialize)]
pub struct VerificationReport {
    /// Part material inside the swept kerf, mm².
    pub overcut_mm2: f64,
    /// Parts the kerf does not cut free all round.
    pub parts_not_freed: usize,
    /// Deepest reach past a drawn edge, mm.
    pub max_overcut_mm: f64,
    /// Parts held only by their tabs (issue 20 §6); absent when none.
    #[serde(skip_serializing_if = "is_zero_count")]
    pub parts_held_by_tabs: usize,
    /// What the kerf takes from each part it takes from (parts that share
    /// edges lose half the kerf along them: issue 39 §6); absent when none.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub parts: Vec<PartLossReport>,
    /// A router's pockets swept by the tool's disc (issue 43 §6); absent
    /// without pockets.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub milling: Option<MillSweepReport>,
}

/// What the tool's disc swept along a router's pockets does.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct MillSweepReport {
    /// Material to keep (walls, islands) the disc takes, mm².
    pub gouge_mm2: f64,
    /// Pocket area the tool can reach left uncut at the full depth, mm².
    pub left_mm2: f64,
    /// Pocket area no disc of the tool's radius can reach, mm².
    pub unreachable_mm2: f64,
}

/// The part material one part loses to the swept kerf.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct PartLossReport {
    /// Part number (1-based).
    pub part: usize,
    /// Area taken, mm².
    pub overcut_mm2: f64,
    /// Deepest reach past a drawn edge into it, mm.
    pub max_overcut_mm: f64,
}

/// The tabs left on one part.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct TabsReport {
    /// Part number (1-based).
    pub part: usize,
    /// Tabs left on it.
    pub tabs: usize,
}

/// Plan totals.
#[derive(Clone, Debug, Serialize)]
pub struct PlanReport {
    /// "contour", "chained", "eulerian" or "drawing".
    pub order: &'static str,
    /// Cutting length on contours, mm (each drawn edge once).
    pub cut_length: f64,
    /// Lead-ins, lead-outs and chain links, mm.
    pub lead_length: f64,
    /// Edges travelled again with the tool down, mm.
    pub repeated_length: f64,
    /// Cuts that cut more than one contour on one pierce.
    pub chains: usize,
    /// Spots marked.
    pub spots: usize,
    /// Length marked on the line (scribe, issue 20), mm; absent when none.
    #[serde(skip_serializing_if = "is_zero")]
    pub mark_length: f64,
    /// Small holes cut at the reduced speed; absent when none.
    #[serde(skip_serializing_if = "is_zero_count")]
    pub small_holes: usize,
    /// Tabs left uncut (issue 20 §6; each a torch restart, counted in
    /// `pierces`); absent when none.
    #[serde(skip_serializing_if = "is_zero_count")]
    pub tabs: usize,
    /// The tabs of each part that has some, by part; absent when none.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub tabs_per_part: Vec<TabsReport>,
    /// Estimated machine time, s (feed, rapid speed, pierce delay).
    pub est_time_s: f64,
    /// The contour order's rapid tour between contours (entry points on the
    /// contours, before leads) as the nearest-neighbour construction built
    /// it, mm, and as improved.
    pub tour_nn_length: Option<f64>,
    /// The same tour after 2-opt, Or-opt and entry re-choice, mm.
    pub tour_length: Option<f64>,
    /// Rapid length from the origin, mm.
    pub rapid_length: f64,
    /// Number of pierces.
    pub pierces: usize,
    /// Parts (outer contours).
    pub parts: usize,
    /// Holes.
    pub holes: usize,
    /// Open contours (not cut).
    pub open: usize,
    /// Length of paths cut once for two parts (common-line cutting), mm.
    pub common_line_length: f64,
    /// Those paths in the direction cut, at most [`MAX_COMMON_LINES`].
    pub common_line: Vec<CommonLineReport>,
    /// Feed moves before and after arc fitting (`--fit-arcs`), the
    /// plan's and a router's milling's; absent when the job did not fit
    /// them.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub arc_fit: Option<ArcFitReport>,
    /// A router's engravings with a V-bit (`--v-angle`): their depth and
    /// width; absent otherwise.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub engraving: Option<EngravingReport>,
    /// A router job with several tools (issue 43 §1): each tool's work in
    /// the order they work; absent with one tool.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub tools: Vec<ToolReport>,
    /// Milling layers at their own depth (issue 43 §1): each depth's
    /// layers in the order they are machined; absent when every layer is
    /// at the job's depth (the profiles always are: `process.depth`).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub layer_depths: Vec<LayerDepthReport>,
}

/// Layers milled at one depth, by one tool.
#[derive(Clone, Debug, Serialize)]
pub struct LayerDepthReport {
    /// The layers' names.
    pub layers: Vec<String>,
    /// Their tool's number.
    pub tool: u32,
    /// Depth, mm.
    pub depth: f64,
    /// Passes, n = ceil(depth / deepest pass).
    pub passes: usize,
    /// Each pass's depth, mm (depth / passes).
    pub pass_depth: f64,
    /// "climb" or "conventional".
    pub milling: &'static str,
}

/// What one tool of a router job machines, at its own feeds.
#[derive(Clone, Debug, Serialize)]
pub struct ToolReport {
    /// Its number (`T`, `H`).
    pub number: u32,
    /// Its diameter, mm.
    pub diameter: f64,
    /// A V-bit's angle, degrees; absent for a flat end mill.
    #[serde(skip_serializing_if = "is_zero")]
    pub v_angle: f64,
    /// Feed across material, mm/min.
    pub feed: f64,
    /// Feed down into material, mm/min.
    pub plunge_feed: f64,
    /// Spindle speed, rev/min.
    pub spindle_rpm: f64,
    /// Pockets it clears.
    pub pockets: usize,
    /// Paths it engraves.
    pub engravings: usize,
    /// Holes it drills.
    pub holes: usize,
    /// Its milling's moves across and into material, mm.
    pub cut_length: f64,
    /// Its rapid moves, mm.
    pub rapid_length: f64,
    /// Its milling's time at its feeds, s (the tool change before it not
    /// included; the profiles' time is the plan's).
    pub est_time_s: f64,
    /// True for the job's own tool when it then cuts the profiles.
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub profiles: bool,
}

/// Engravings cut with a V-bit: width = 2·depth·tan(angle/2), at most the
/// tool's diameter.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct EngravingReport {
    /// The V's included angle, degrees.
    pub v_angle: f64,
    /// Depth, mm.
    pub depth: f64,
    /// Width at the stock's top, mm.
    pub width: f64,
}

/// Feed moves (G1 lines, G2/G3 arcs) before and after arc fitting.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct ArcFitReport {
    /// Straight feed moves before fitting.
    pub lines_before: usize,
    /// Arc feed moves before fitting.
    pub arcs_before: usize,
    /// Straight feed moves after.
    pub lines_after: usize,
    /// Arc feed moves after.
    pub arcs_after: usize,
    /// The tolerance fitted to, mm.
    pub tolerance: f64,
}

/// Common-line pieces listed one by one in the report; the length counts all.
pub const MAX_COMMON_LINES: usize = 1000;

/// A path two parts share, cut once: which way, and which part is on the
/// right of the cut (the square side of a clockwise-swirl plasma arc).
#[derive(Clone, Debug, Serialize)]
pub struct CommonLineReport {
    /// The two parts (1-based; 0 for none).
    pub parts: [usize; 2],
    /// The part on the right of the cut direction (0: not found).
    pub right: usize,
    /// Where the cut entered the piece, mm.
    pub from: [f64; 2],
    /// Where it left it, mm.
    pub to: [f64; 2],
    /// Length, mm.
    pub length: f64,
}

/// One layer in the report.
#[derive(Clone, Debug, Serialize)]
pub struct LayerReport {
    /// Name (text from the file: escape it wherever it is shown).
    pub name: String,
    /// AutoCAD colour index.
    pub color: i16,
    /// On and thawed in the file.
    pub visible: bool,
    /// Cut in this job.
    pub selected: bool,
    /// Geometry entities on it.
    pub entities: usize,
}

/// What healing changed.
#[derive(Clone, Debug, Serialize)]
pub struct HealingReport {
    /// Copies dropped.
    pub duplicates: usize,
    /// Overlaps merged.
    pub overlaps: usize,
    /// Gaps closed.
    pub gaps_closed: usize,
    /// Zero-length entities and segments dropped.
    pub zero_length: usize,
    /// Loops that crossed themselves, repaired (issue 45 §2).
    pub self_crossings: usize,
    /// Each fix: `{"kind": "duplicate"|"overlap"|"gap"|"zero_length"|"self_crossing", "at": [x, y]}`.
    pub locations: Vec<HealLocation>,
}

/// One healing fix.
#[derive(Clone, Debug, Serialize)]
pub struct HealLocation {
    /// What was done.
    pub kind: &'static str,
    /// Where, mm.
    pub at: [f64; 2],
}

/// One order's figures in a comparison.
#[derive(Clone, Debug, Serialize)]
pub struct OrderReport {
    /// The order's name.
    pub order: &'static str,
    /// Cutting length on contours, mm.
    pub cut_length: f64,
    /// Leads and links, mm.
    pub lead_length: f64,
    /// Repeated length, mm.
    pub repeated_length: f64,
    /// Rapid length, mm.
    pub rapid_length: f64,
    /// Pierces.
    pub pierces: usize,
    /// Chains.
    pub chains: usize,
    /// Estimated time, s.
    pub est_time_s: f64,
    /// True when some torch-on move cuts into a part (issue 14).
    pub cuts_into_parts: bool,
    /// Length of torch-on travel whose kerf reaches into a part, mm.
    pub into_parts_length: f64,
    /// Deepest reach of the kerf into a part, mm.
    pub into_parts_depth: f64,
}

impl From<&crate::OrderSummary> for OrderReport {
    fn from(o: &crate::OrderSummary) -> Self {
        OrderReport {
            order: o.order.name(),
            cut_length: um(o.stats.cut_length),
            lead_length: um(o.stats.lead_length),
            repeated_length: um(o.stats.repeated_length),
            rapid_length: um(o.stats.rapid_length),
            pierces: o.stats.pierces,
            chains: o.stats.chains,
            est_time_s: (o.est_time_s * 10.0).round() / 10.0,
            cuts_into_parts: o.intrusion.cuts_parts(),
            into_parts_length: um(o.intrusion.length),
            into_parts_depth: um(o.intrusion.depth),
        }
    }
}

/// Rounds to a micrometre, so reports do not carry float noise.
pub(super) fn um(v: f64) -> f64 {
    // `+ 0.0` turns -0 into 0.
    (v * 1000.0).round() / 1000.0 + 0.0
}

fn is_zero(v: &f64) -> bool {
    *v == 0.0
}

fn is_zero_count(v: &usize) -> bool {
    *v == 0
}
