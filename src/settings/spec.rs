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

use super::{Settings, SettingsError, DEFAULT_RAPID};
use crate::dxf::Units;
use crate::gcode::{preset, Post, PRESET_NAMES};
use crate::geom::Point;
use crate::kerf::Join;
use crate::materials::{Entry, Library};
use crate::origin::ProgramOrigin;
use crate::plan::{ccw_from_name, EulerMode, LeadKind, LeadOptions, Order, PlanOptions, Tabs};
use crate::process::{LayerOps, Operation, Passes, Process, SmallHole, ThcLock};
use crate::text;
use crate::warning::Lang;

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
    /// Rapid speed, mm/min (default: the post's, else [`DEFAULT_RAPID`]).
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
    /// Where the tool starts, program coordinates, mm.
    pub tool_start: [f64; 2],
    /// Start points the user picked: `[contour, x, y]`.
    pub starts: Vec<[f64; 3]>,
    /// Tabs the user placed by clicking: `[contour, x, y]` (issue 20 §6).
    pub tabs_at: Vec<[f64; 3]>,
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
    /// Sweep the kerf over the parts and report it.
    pub verify: bool,
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
            tool_start: [0.0, 0.0],
            starts: Vec::new(),
            tabs_at: Vec::new(),
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
            verify: false,
            material: None,
            material_name: None,
            materials: None,
        }
    }
}

/// `field` holds a name that is none of `known`.
fn unknown(field: &'static str, v: &str, known: &str) -> SettingsError {
    SettingsError {
        field,
        reason: text!("'{v}' is not {known}"; "'{v}' não é {known}"),
    }
}

/// Points the user clicked, `[contour, x, y]`: negative or huge contour
/// numbers are clicks on nothing.
fn clicked(points: &[[f64; 3]]) -> Vec<(usize, Point)> {
    points
        .iter()
        .filter(|s| s[0] >= 0.0 && s[0] < u32::MAX as f64)
        .map(|s| (s[0] as usize, Point::new(s[1], s[2])))
        .collect()
}

impl Spec {
    /// The language of messages (English for an unknown name).
    pub fn lang(&self) -> Lang {
        self.lang
            .as_deref()
            .and_then(Lang::from_name)
            .unwrap_or(Lang::En)
    }

    /// The plan options named here (lengths checked by [`Settings::with_plan`]).
    fn plan_options(&self) -> Result<PlanOptions, SettingsError> {
        let dir = |field, v: &str| ccw_from_name(v).ok_or_else(|| unknown(field, v, "cw or ccw"));
        Ok(PlanOptions {
            origin: Point::new(self.tool_start[0], self.tool_start[1]),
            order: Order::from_name(&self.order).ok_or_else(|| {
                unknown(
                    "order",
                    &self.order,
                    "contour, chained, eulerian or drawing",
                )
            })?,
            euler_mode: EulerMode::from_name(&self.euler_mode)
                .ok_or_else(|| unknown("euler_mode", &self.euler_mode, "repeat or rapid"))?,
            leads: LeadOptions {
                kind: LeadKind::from_name(&self.lead).ok_or_else(|| {
                    unknown(
                        "lead",
                        &self.lead,
                        "perpendicular, tangential, bisector, arc or none",
                    )
                })?,
                outer_length: self.lead_outer,
                hole_length: self.lead_hole,
                overcut: self.overcut,
            },
            max_link: self.max_link,
            outer_ccw: dir("outer_dir", &self.outer_dir)?,
            hole_ccw: dir("hole_dir", &self.hole_dir)?,
            cut_open: self.cut_open,
            controller_comp: self.controller_comp,
            tabs: Tabs {
                count: self.tabs as usize,
                width: self.tab_width,
                holes: self.tab_holes,
            },
            starts: clicked(&self.starts),
            tabs_at: clicked(&self.tabs_at),
            ..PlanOptions::DEFAULT
        })
    }

    /// The post named here: a user's JSON, a preset, or none.
    fn post(&self) -> Result<Option<Post>, SettingsError> {
        let bad = |reason| SettingsError {
            field: "post",
            reason,
        };
        if let Some(json) = self.post_json.as_deref().filter(|j| !j.is_empty()) {
            return Post::from_json(json).map(Some).map_err(|e| bad(e.text()));
        }
        match self.post.as_deref().filter(|n| !n.is_empty()) {
            None => Ok(None),
            Some(name) => preset(name).map(Some).ok_or_else(|| {
                let known = PRESET_NAMES.join(", ");
                bad(text!("no preset '{name}' (the presets: {known})";
                          "não existe o modelo '{name}' (os modelos: {known})"))
            }),
        }
    }

    /// The validated settings. The first bad value names its field; a
    /// material not in the chart names the chart's fault.
    pub fn build(&self) -> Result<Settings, SettingsError> {
        let lang = self.lang();
        let material = |field, e: crate::materials::MaterialError| SettingsError {
            field,
            reason: e.text(),
        };
        // A chart given is read even when no entry is chosen: a broken
        // chart is said now, not when an entry is first picked.
        let lib = match &self.materials {
            Some(text) => Some(Library::from_text(text).map_err(|e| material("materials", e))?),
            None => None,
        };
        let entry = match &self.material_name {
            None => None,
            Some(name) => {
                let lib = lib.unwrap_or_else(Library::starter);
                Some(lib.find(name).map_err(|e| material("material", e))?.clone())
            }
        };
        // The entry's process fills what is not given (the CLI's rule:
        // options typed win over the chart).
        let chart = entry.as_ref().map(|e| e.process(DEFAULT_RAPID));
        let pick = |given: Option<f64>, from: fn(&Process) -> f64, default: f64| {
            given.unwrap_or_else(|| chart.as_ref().map_or(default, from))
        };
        let d = Process::DEFAULT;
        let kerf = pick(self.kerf, |p| p.kerf, 1.5);
        let feed = pick(self.feed, |p| p.feed, 2000.0);
        let post = self.post()?;
        let mut s = Settings::new(kerf, self.tolerance, feed)?.with_lang(lang);
        s = s
            .with_join(match self.join.as_str() {
                "round" => Join::Round,
                "miter" | "mitre" => Join::Miter,
                other => return Err(unknown("join", other, "round or miter")),
            })
            .with_decimals(self.decimals)?
            .with_pierce_delay(pick(self.pierce_delay, |p| p.pierce_delay, 0.0))?;
        let rapid = self
            .rapid
            .or(post.as_ref().map(|p| p.rapid_speed))
            .unwrap_or(DEFAULT_RAPID);
        s = s.with_rapid(rapid)?.with_plan(self.plan_options()?)?;
        if let Some(p) = post {
            s = s.with_post(p)?;
        }
        let origin = match (self.origin.as_str(), self.origin_point) {
            ("point", Some([x, y])) => ProgramOrigin::Point(Point::new(x, y)),
            (name, _) => ProgramOrigin::from_name(name).ok_or_else(|| {
                unknown("origin", name, "auto, drawing, lower-left, point or X,Y")
            })?,
        };
        let mut ops = LayerOps::new();
        ops.by_name = self.layer_ops_by_name;
        for [layer, op] in &self.layer_ops {
            let op = Operation::from_name(op).ok_or_else(|| SettingsError {
                field: "layer_ops",
                reason: text!("layer '{layer}': '{op}' is not cut, mark, spot or ignore";
                              "camada '{layer}': '{op}' não é cut, mark, spot ou ignore"),
            })?;
            ops.given.push((layer.clone(), op));
        }
        let depth = match (self.depth, &entry) {
            (Some(d), _) => d,
            (None, Some(e)) if self.pass_depth > 0.0 => e.thickness,
            (None, _) => 0.0,
        };
        s = s
            .with_origin(origin)?
            .with_layer_ops(ops)
            .with_verify(self.verify)
            .with_small_hole(SmallHole {
                diameter: pick(self.small_hole_diameter, |p| p.small_hole.diameter, 0.0),
                speed_pct: pick(
                    self.small_hole_speed,
                    |p| p.small_hole.speed_pct,
                    SmallHole::OFF.speed_pct,
                ),
                min_diameter: self.small_hole_min,
                ..SmallHole::OFF
            })?
            .with_heights(
                pick(self.pierce_height, |p| p.pierce_height, d.pierce_height),
                pick(self.cut_height, |p| p.cut_height, d.cut_height),
            )?
            .with_material_number(
                self.material_number
                    .or(entry.as_ref().and_then(|e| e.number))
                    .unwrap_or(0),
            )?
            .with_passes(Passes {
                depth,
                pass_depth: self.pass_depth,
            })?
            .with_thc_lock(ThcLock {
                corner_angle_deg: self.thc_corner_angle,
                corner_distance: self.thc_corner_distance,
                end_distance: self.thc_end_distance,
            })?;
        if let Some(name) = self.units.as_deref().filter(|n| !n.is_empty()) {
            let u = Units::from_name(name).ok_or_else(|| SettingsError {
                field: "units",
                reason: text!("unknown unit '{name}'"; "unidade '{name}' desconhecida"),
            })?;
            s = s.with_units(u);
        }
        if let Some(g) = self.gap {
            s = s.with_gap(g)?;
        }
        if let Some(l) = &self.layers {
            s = s.with_layers(l.clone());
        }
        let entry = match self.material.as_deref().filter(|j| !j.is_empty()) {
            // The page's chosen entry: its values are the job's.
            Some(json) => {
                let e = Entry::from_json(json).map_err(|e| material("material", e))?;
                s = s.with_material(&e)?;
                Some(e)
            }
            None => entry,
        };
        s.material = entry.map(|e| super::MaterialUsed {
            name: e.name,
            example: e.example,
        });
        Ok(s)
    }
}

#[cfg(test)]
#[path = "spec_tests.rs"]
mod tests;
