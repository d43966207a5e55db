//! A job as the user gives it — names and numbers, as typed on the command
//! line or sent by the page — and the one way from it to validated
//! [`Settings`] (issue 15 §5). Both front ends fill a [`Spec`] and call
//! [`Spec::build`]; neither assembles `Settings` on its own, so an option
//! cannot exist in one and drift in the other.
//!
//! Field names are the page's wire names (`serde`), so the page's settings
//! object deserialises straight into a `Spec`; missing fields take
//! [`Spec::default`], the defaults written in the CLI's help.

use serde::Deserialize;

use crate::plan::{LeadOptions, PlanOptions};
use crate::process::{ThcLock, Tool};

/// A choice made on the drawing (a start point, a tab), as the page sends
/// it: `{"at": [x, y], "on": {loop key}}` (program coordinates, mm; the
/// key as the engine gave it, [`crate::plan::choice::LoopKey`]), or as
/// pages before issue 39 stored it, `[contour, x, y]`: the contour number
/// is not trusted (any change of the drawing renumbers contours), the
/// point takes the loop nearest it within [`LEGACY_REACH_MM`].
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(untagged)]
pub enum Choice {
    /// A point and the loop it was set on.
    Keyed {
        /// The point, mm.
        at: [f64; 2],
        /// The loop's key; none: the loop nearest the point.
        #[serde(default)]
        on: Option<LoopKeySpec>,
    },
    /// `[contour, x, y]`; a negative contour is a click on nothing.
    Numbered([f64; 3]),
}

/// A router profile's side chosen on one loop (issue 43 §1), as the page
/// sends it: `{"at": [x, y], "on": {loop key}, "side": "inside"}`; the
/// CLI's `--side-at X,Y=SIDE` has no key (the loop nearest the point).
#[derive(Clone, Debug, Deserialize, PartialEq)]
pub struct SideChoice {
    /// The point, mm.
    pub at: [f64; 2],
    /// The loop's key; none: the loop nearest the point.
    #[serde(default)]
    pub on: Option<LoopKeySpec>,
    /// "outside", "inside" or "on".
    pub side: String,
}

/// A router tool of the job's list beside its own (issue 43 §1), as the
/// CLI's `--tool N=DIAMETER,key=value…` and the page give it. Not given:
/// the job's tool's feeds, spindle speed and stepover; a flat end mill;
/// the diameter's own defaults for the helix, the allowance, drilling and
/// a V engraving.
#[derive(Clone, Debug, Default, Deserialize, PartialEq)]
#[serde(default)]
pub struct ToolSpec {
    /// Its number in the machine's tool table (1 to 99999).
    pub number: u32,
    /// Cutting diameter, mm.
    pub diameter: f64,
    /// Feed across material, mm/min.
    pub feed: Option<f64>,
    /// Feed down into material, mm/min.
    pub plunge_feed: Option<f64>,
    /// Spindle speed, rev/min.
    pub spindle_rpm: Option<f64>,
    /// Distance between pocket passes, % of its diameter.
    pub stepover: Option<f64>,
    /// A V-bit's included angle, degrees (0: flat).
    pub v_angle: f64,
    /// Stock left on pocket walls for the finishing pass, mm.
    pub allowance: f64,
    /// Helix diameter, mm (0: its radius).
    pub helix_diameter: f64,
    /// Drilling: circles up to this diameter, mm (0: its diameter).
    pub drill_max: f64,
    /// V engraving's width, mm (0: from the depth).
    pub engrave_width: f64,
    /// V engraving's depth, mm (0: from the width, else the job's).
    pub engrave_depth: f64,
}

/// A milling layer's own depth (issue 43 §1), as the CLI's
/// `--layer-depth LAYER=H[,pass-depth=D][,milling=…]` and the page give
/// it. Not given: the job's pass depth and direction.
#[derive(Clone, Debug, Default, Deserialize, PartialEq)]
#[serde(default)]
pub struct LayerDepthSpec {
    /// The layer's name.
    pub layer: String,
    /// Its depth, mm (none: the job's — the page's layer milled only in
    /// its own direction).
    pub depth: Option<f64>,
    /// Its deepest pass, mm (none: the job's).
    pub pass_depth: Option<f64>,
    /// "climb" or "conventional" (none: the job's).
    pub milling: Option<String>,
}

/// How far an old `[contour, x, y]` choice may be from its loop, mm: it
/// was the raw click, up to 12 screen pixels off.
pub const LEGACY_REACH_MM: f64 = 5.0;

/// [`crate::plan::choice::LoopKey`] on the wire.
#[derive(Clone, Debug, Deserialize, PartialEq)]
pub struct LoopKeySpec {
    /// Part, copy and loop ([`crate::source::ContourRef`]).
    pub part: u32,
    /// See [`crate::source::ContourRef::copy`].
    pub copy: u32,
    /// See [`crate::source::ContourRef::contour`].
    pub contour: u32,
    /// Area, mm².
    pub area: f64,
    /// Length, mm.
    pub length: f64,
    /// Box width and height, mm.
    pub size: [f64; 2],
    /// Layer.
    #[serde(default)]
    pub layer: String,
}

/// One job's settings as given: numbers unchecked, choices by name.
/// `None` is "not given": the cut-chart entry's value, else the default.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(default)]
pub struct Spec {
    /// Kerf width, mm (default 1.5, or the material's).
    pub kerf: Option<f64>,
    /// The one tolerance, mm.
    pub tolerance: f64,
    /// Cutting feed, mm/min (default 2000, or the material's).
    pub feed: Option<f64>,
    /// Dwell after the torch fires, s (default 0, or the material's).
    pub pierce_delay: Option<f64>,
    /// Rapid speed, mm/min (default: the post's, else [`crate::DEFAULT_RAPID`]).
    pub rapid: Option<f64>,
    /// Convex corners of the kerf path: "round" or "miter".
    pub join: String,
    /// Decimal places in the program.
    pub decimals: u32,
    /// Unit name ("mm", "in", …) to read the file in; none: the file's own.
    pub units: Option<String>,
    /// Layers to cut; none: the visible layers.
    pub layers: Option<Vec<String>>,
    /// Open ends up to this far apart are joined, mm; none: the default.
    pub gap: Option<f64>,
    /// "contour", "chained", "eulerian" or "drawing".
    pub order: String,
    /// "repeat" or "rapid".
    pub euler_mode: String,
    /// "perpendicular", "tangential", "bisector", "arc" or "none".
    pub lead: String,
    /// Lead-in on outer contours, mm.
    pub lead_outer: f64,
    /// Lead-in in holes, mm.
    pub lead_hole: f64,
    /// Cut past the start at the end, mm.
    pub overcut: f64,
    /// Longest chain link through scrap, mm.
    pub max_link: f64,
    /// "cw" or "ccw".
    pub outer_dir: String,
    /// "cw" or "ccw".
    pub hole_dir: String,
    /// Cut open contours on the line.
    pub cut_open: bool,
    /// Leave the kerf to the controller (G41.1/G42.1 … G40).
    pub controller_comp: bool,
    /// Runs of short feed moves as lines and arcs within the tolerance
    /// (issue 43 §5).
    pub fit_arcs: bool,
    /// Motion in incremental coordinates, G91 (the post's `incremental`).
    pub incremental: bool,
    /// Where the tool starts, program coordinates, mm.
    pub tool_start: [f64; 2],
    /// Start points the operator picked, each on the loop it was set on
    /// ([`Choice`]).
    pub starts: Vec<Choice>,
    /// Tabs the operator placed by clicking (issue 20 §6), as `starts`.
    pub tabs_at: Vec<Choice>,
    /// Router profiles' sides chosen on single loops ([`SideChoice`]).
    pub sides_at: Vec<SideChoice>,
    /// A preset's name; none: plain LinuxCNC.
    pub post: Option<String>,
    /// A post as JSON (wins over `post`).
    pub post_json: Option<String>,
    /// "en" (default) or "pt-BR".
    pub lang: Option<String>,
    /// The program's zero: "auto", "drawing", "lower-left", "point" (with
    /// `origin_point`) or "X,Y".
    pub origin: String,
    /// The picked point for "point", drawing coordinates, mm.
    pub origin_point: Option<[f64; 2]>,
    /// Operations of layers by name: `[["MARK", "mark"]]` (cut, mark,
    /// spot, ignore).
    pub layer_ops: Vec<[String; 2]>,
    /// False: every layer without a given operation is cut.
    pub layer_ops_by_name: bool,
    /// Holes narrower than this are small, mm (default off, or 1.5 ×
    /// the material's thickness).
    pub small_hole_diameter: Option<f64>,
    /// Their speed, % of the feed (default 60, or the material's).
    pub small_hole_speed: Option<f64>,
    /// Holes narrower than this are centre-spotted, mm.
    pub small_hole_min: f64,
    /// Torch heights of a Z post, mm (default QtPlasmaC's examples, or the
    /// material's).
    pub pierce_height: Option<f64>,
    /// See `pierce_height`.
    pub cut_height: Option<f64>,
    /// The controller's material number (QtPlasmaC `M190 Pn`; default 0,
    /// or the chart entry's).
    pub material_number: Option<u32>,
    /// Material thickness cut in depth passes, mm (default off, or the
    /// material's thickness when `pass_depth` is given).
    pub depth: Option<f64>,
    /// Deepest pass, mm (0 = off).
    pub pass_depth: f64,
    /// Tabs per part (0 = none).
    pub tabs: u32,
    /// Material left in each tab, mm.
    pub tab_width: f64,
    /// Tabs on holes too.
    pub tab_holes: bool,
    /// Height locked this far around a sharp corner, mm (0 = off).
    pub thc_corner_distance: f64,
    /// Corners with an included angle below this are sharp, degrees.
    pub thc_corner_angle: f64,
    /// Height locked this far before the contour's end, mm (0 = off).
    pub thc_end_distance: f64,
    /// Router (issue 43): the end mill's diameter, mm (none: no tool; a
    /// profile's kerf when `kerf` is not given).
    pub tool_diameter: Option<f64>,
    /// Distance between passes, % of the tool's diameter.
    pub stepover: f64,
    /// Feed of moves into material, mm/min.
    pub plunge_feed: f64,
    /// Spindle speed, rev/min.
    pub spindle_rpm: f64,
    /// The tool's number in the machine's tool table (1 to 99999).
    pub tool_number: u32,
    /// The job's other tools, in the order they work (before its own).
    pub tools: Vec<ToolSpec>,
    /// `[layer, tool number]`: the tool a milling layer is machined with
    /// (none given: the job's own).
    pub layer_tools: Vec<(String, u32)>,
    /// Milling layers at their own depth, pass depth and direction (none
    /// given: the job's).
    pub layer_depths: Vec<LayerDepthSpec>,
    /// "climb" or "conventional".
    pub milling: String,
    /// "zigzag" or "offset".
    pub pocket: String,
    /// Contour-parallel clearing: "centre" (outwards) or "walls" (inwards).
    pub pocket_from: String,
    /// Direction of zig-zag passes, degrees from X.
    pub pocket_angle: f64,
    /// "plunge", "ramp" or "helix".
    pub entry: String,
    /// Ramp angle, degrees.
    pub ramp_angle: f64,
    /// Helix diameter, mm (0: the tool's radius).
    pub helix_diameter: f64,
    /// Stock left on the walls for the finishing pass, mm.
    pub allowance: f64,
    /// Drilling peck, mm (0: the deepest pass).
    pub peck: f64,
    /// Circles up to this diameter are drilled, mm (0: the tool's).
    pub drill_max: f64,
    /// A V-bit's included angle, degrees (0: a flat end mill).
    pub v_angle: f64,
    /// Engraving width with a V-bit, mm (0: from the depth).
    pub engrave_width: f64,
    /// Engraving depth with a V-bit, mm (0: from the width, else the depth).
    pub engrave_depth: f64,
    /// Radius of a router profile's lead arcs (with `lead` "arc"), mm (0:
    /// the tool's diameter).
    pub lead_radius: f64,
    /// A router's tabs: the bridge's height at the bottom, mm (0: the
    /// tool lifts out over each tab).
    pub tab_height: f64,
    /// Sweep the kerf over the parts and report it.
    pub verify: bool,
    /// Repair outlines that cross themselves (false: leave them uncut).
    pub repair_self_crossing: bool,
    /// The cut-chart entry the page's operator chose, as JSON: its kerf,
    /// feed, delay, heights, height control and number win over the fields
    /// above (the page shows them there, locked; `Settings::with_material`).
    pub material: Option<String>,
    /// A cut-chart entry by name (the CLI's `--material`): its values fill
    /// only the fields above that are not given.
    pub material_name: Option<String>,
    /// The cut chart to find `material_name` in (kerfcam JSON or a
    /// QtPlasmaC material file); none: kerfcam's example chart.
    pub materials: Option<String>,
}

impl Default for Spec {
    fn default() -> Self {
        let plan = PlanOptions::DEFAULT;
        Spec {
            kerf: None,
            tolerance: 0.001,
            feed: None,
            pierce_delay: None,
            rapid: None,
            join: "round".into(),
            decimals: 3,
            units: None,
            layers: None,
            gap: None,
            order: plan.order.name().into(),
            euler_mode: "repeat".into(),
            lead: "perpendicular".into(),
            lead_outer: LeadOptions::DEFAULT.outer_length,
            lead_hole: LeadOptions::DEFAULT.hole_length,
            overcut: LeadOptions::DEFAULT.overcut,
            max_link: plan.max_link,
            outer_dir: "cw".into(),
            hole_dir: "ccw".into(),
            cut_open: false,
            controller_comp: false,
            fit_arcs: plan.fit_arcs,
            incremental: false,
            tool_start: [0.0, 0.0],
            starts: Vec::new(),
            tabs_at: Vec::new(),
            sides_at: Vec::new(),
            post: None,
            post_json: None,
            lang: None,
            origin: "auto".into(),
            origin_point: None,
            layer_ops: Vec::new(),
            layer_ops_by_name: true,
            small_hole_diameter: None,
            small_hole_speed: None,
            small_hole_min: 0.0,
            pierce_height: None,
            cut_height: None,
            material_number: None,
            depth: None,
            pass_depth: 0.0,
            tabs: 0,
            tab_width: 3.0,
            tab_holes: false,
            thc_corner_distance: 0.0,
            thc_corner_angle: ThcLock::OFF.corner_angle_deg,
            thc_end_distance: 0.0,
            tool_diameter: None,
            stepover: Tool::OFF.stepover_pct,
            plunge_feed: Tool::OFF.plunge_feed,
            spindle_rpm: Tool::OFF.spindle_rpm,
            tool_number: Tool::OFF.number,
            tools: Vec::new(),
            layer_tools: Vec::new(),
            layer_depths: Vec::new(),
            milling: "climb".into(),
            pocket: "zigzag".into(),
            pocket_from: "centre".into(),
            pocket_angle: 0.0,
            entry: "plunge".into(),
            ramp_angle: Tool::OFF.ramp_angle_deg,
            helix_diameter: 0.0,
            allowance: 0.0,
            peck: 0.0,
            drill_max: 0.0,
            v_angle: 0.0,
            engrave_width: 0.0,
            engrave_depth: 0.0,
            lead_radius: 0.0,
            tab_height: 0.0,
            verify: false,
            repair_self_crossing: true,
            material: None,
            material_name: None,
            materials: None,
        }
    }
}

#[cfg(test)]
#[path = "spec_tests.rs"]
mod tests;
