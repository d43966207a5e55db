//! The JavaScript boundary (the only file that knows JS): a `Job` handle that
//! runs the pipeline once and answers small questions about the result.
//!
//! ```js
//! const job = new Job(bytes, { kerf: 1.5, tolerance: 0.001, feed: 2000 });
//! job.report_json(); job.gcode(); job.bbox(); job.render(w, h, cx, cy, scale, pixel_ratio);
//! ```

use serde::Deserialize;
use wasm_bindgen::prelude::*;

use crate::dxf::Units;
use crate::gcode::{backplot, preset, Post, PRESET_NAMES};
use crate::geom::{BBox, Point};
use crate::inspect;
use crate::origin::ProgramOrigin;
use crate::plan::{
    ccw_from_name, EulerMode, LeadKind, LeadOptions, Move, Order, PlanOptions, Role,
};
use crate::preview::{self, View};
use crate::process::{LayerOps, Operation, Passes, SmallHole};
use crate::report::{OrderReport, Report};
use crate::text;
use crate::warning::{Lang, Text};
use crate::{compare_orders, run_with_progress, Output, Settings, SettingsError};

// A DXF's code page by the browser's TextDecoder (src/dxf/text.rs, issue 17).
pub(crate) mod code_page;

// Nesting (issue 16): its own file, the page's Sheet mode (issue 18). Only in
// the second wasm module (feature "nester", issue 17): the page loads it when
// Sheet mode first nests, so the cutting core stays small.
#[cfg(feature = "nester")]
mod nest_edit;
#[cfg(feature = "nester")]
mod nesting;
#[cfg(feature = "nester")]
pub use nesting::{NestResult, Nester};

/// Settings as the page sends them; missing fields take the defaults.
#[derive(Deserialize)]
#[serde(default)]
struct WebSettings {
    kerf: f64,
    tolerance: f64,
    feed: f64,
    /// Unit name ("mm", "in", "cm", "m", "ft", …) to read the file in, or none for the file's own.
    units: Option<String>,
    /// Layer names to cut, or none for the visible layers.
    layers: Option<Vec<String>>,
    /// Open ends up to this far apart are joined (mm), or none for the default.
    gap: Option<f64>,
    /// "contour", "chained", "eulerian" or "drawing".
    order: String,
    /// "repeat" or "rapid".
    euler_mode: String,
    /// "perpendicular", "tangential", "bisector", "arc" or "none".
    lead: String,
    lead_outer: f64,
    lead_hole: f64,
    overcut: f64,
    max_link: f64,
    /// "cw" or "ccw".
    outer_dir: String,
    hole_dir: String,
    cut_open: bool,
    /// Leave the kerf to the controller (G41.1/G42.1 … G40).
    controller_comp: bool,
    rapid: f64,
    pierce_delay: f64,
    /// Start points the user clicked: `[contour, x, y]`.
    starts: Vec<[f64; 3]>,
    /// A preset's name, or none for plain LinuxCNC.
    post: Option<String>,
    /// A user's post as JSON (wins over `post`).
    post_json: Option<String>,
    /// "en" (default) or "pt-BR": the language of the report's messages and of errors.
    lang: Option<String>,
    /// The program's zero: "auto" (default), "drawing", "lower-left" or "point".
    origin: String,
    /// The picked point for "point", drawing coordinates, mm.
    origin_point: Option<[f64; 2]>,
    /// Operations of layers by name: `[["MARK", "mark"], ["DIM", "cut"]]`
    /// ("cut", "mark", "spot", "ignore"); other layers by their name's meaning.
    layer_ops: Vec<[String; 2]>,
    /// False: every layer without a given operation is cut.
    layer_ops_by_name: bool,
    /// Holes narrower than this are small holes, mm (0 = off).
    small_hole_diameter: f64,
    /// Their speed, % of the feed.
    small_hole_speed: f64,
    /// Holes narrower than this are centre-spotted, not cut, mm.
    small_hole_min: f64,
    /// Sweep the kerf over the parts and report it (`verification`).
    verify: bool,
    /// Material thickness cut in depth passes, mm (0 = off).
    depth: f64,
    /// Deepest pass, mm (0 = off): n = ceil(depth / pass_depth) passes.
    pass_depth: f64,
    /// Tabs per part (issue 20 §6; 0 = none).
    tabs: u32,
    /// Material left in each tab, mm.
    tab_width: f64,
    /// Tabs on holes too.
    tab_holes: bool,
    /// Height locked from this far before a sharp corner to this far
    /// after it, mm (0 = off; issue 20 §4).
    thc_corner_distance: f64,
    /// Corners with an included angle below this are sharp, degrees.
    thc_corner_angle: f64,
    /// Height locked this far before the contour's end, mm (0 = off).
    thc_end_distance: f64,
}

impl Default for WebSettings {
    fn default() -> Self {
        WebSettings {
            kerf: 1.5,
            tolerance: 0.001,
            feed: 2000.0,
            units: None,
            layers: None,
            gap: None,
            order: "contour".into(),
            euler_mode: "repeat".into(),
            lead: "perpendicular".into(),
            lead_outer: LeadOptions::DEFAULT.outer_length,
            lead_hole: LeadOptions::DEFAULT.hole_length,
            overcut: 0.0,
            max_link: PlanOptions::DEFAULT.max_link,
            outer_dir: "cw".into(),
            hole_dir: "ccw".into(),
            cut_open: false,
            controller_comp: false,
            rapid: crate::DEFAULT_RAPID,
            pierce_delay: 0.0,
            starts: Vec::new(),
            post: None,
            post_json: None,
            lang: None,
            origin: "auto".into(),
            origin_point: None,
            layer_ops: Vec::new(),
            layer_ops_by_name: true,
            small_hole_diameter: 0.0,
            small_hole_speed: SmallHole::OFF.speed_pct,
            small_hole_min: 0.0,
            verify: false,
            depth: 0.0,
            pass_depth: 0.0,
            tabs: 0,
            tab_width: 3.0,
            tab_holes: false,
            thc_corner_distance: 0.0,
            thc_corner_angle: crate::process::ThcLock::OFF.corner_angle_deg,
            thc_end_distance: 0.0,
        }
    }
}

/// One DXF file run through the whole pipeline.
#[wasm_bindgen]
pub struct Job {
    out: Output,
    report: String,
    settings: Settings,
}

/// The plan settings the page sent, by name.
fn plan_options(web: &WebSettings, lang: Lang) -> Result<PlanOptions, JsError> {
    let bad = |field: &str, v: &str| {
        let t = text!("settings: {field} '{v}' is not known"; "configuração: {field} '{v}' desconhecido");
        JsError::new(t.get(lang))
    };
    let dir = |field: &str, v: &str| ccw_from_name(v).ok_or_else(|| bad(field, v));
    Ok(PlanOptions {
        order: Order::from_name(&web.order).ok_or_else(|| bad("order", &web.order))?,
        euler_mode: EulerMode::from_name(&web.euler_mode)
            .ok_or_else(|| bad("euler_mode", &web.euler_mode))?,
        leads: LeadOptions {
            kind: LeadKind::from_name(&web.lead).ok_or_else(|| bad("lead", &web.lead))?,
            outer_length: web.lead_outer,
            hole_length: web.lead_hole,
            overcut: web.overcut,
        },
        max_link: web.max_link,
        outer_ccw: dir("outer_dir", &web.outer_dir)?,
        hole_ccw: dir("hole_dir", &web.hole_dir)?,
        cut_open: web.cut_open,
        controller_comp: web.controller_comp,
        tabs: crate::plan::Tabs {
            count: web.tabs as usize,
            width: web.tab_width,
            holes: web.tab_holes,
        },
        starts: web
            .starts
            .iter()
            .filter(|s| s[0] >= 0.0 && s[0] < u32::MAX as f64)
            .map(|s| (s[0] as usize, Point::new(s[1], s[2])))
            .collect(),
        ..PlanOptions::DEFAULT
    })
}

#[wasm_bindgen]
impl Job {
    /// Runs the pipeline; throws an Error with a one-line message for an
    /// unreadable file or a setting out of range.
    ///
    /// `on_stage(name, count)`, when given, is called after each stage
    /// ("reading", "chaining", "offset", "planning", "gcode") with what it
    /// made (entities, contours, kerf paths, pierces, program bytes).
    #[wasm_bindgen(constructor)]
    pub fn new(
        dxf: &[u8],
        settings: JsValue,
        on_stage: Option<js_sys::Function>,
    ) -> Result<Job, JsError> {
        console_error_panic_hook::set_once();
        let web: WebSettings = if settings.is_undefined() || settings.is_null() {
            WebSettings::default()
        } else {
            serde_wasm_bindgen::from_value(settings)
                .map_err(|e| JsError::new(&format!("settings: {e}")))?
        };
        let lang = lang_of(web.lang.as_deref());
        // Errors in the page's language (their Display is English).
        let js = |t: Text| JsError::new(t.get(lang));
        let tr = |e: SettingsError| JsError::new(&e.message(lang));
        let mut settings = Settings::new(web.kerf, web.tolerance, web.feed)
            .map_err(tr)?
            .with_lang(lang);
        if let Some(name) = web.units.clone().filter(|n| !n.is_empty()) {
            let u = Units::from_name(&name).ok_or_else(|| {
                js(text!("settings: unknown unit '{name}'"; "configuração: unidade '{name}' desconhecida"))
            })?;
            settings = settings.with_units(u);
        }
        let origin = match (web.origin.as_str(), web.origin_point) {
            ("point", Some([x, y])) => ProgramOrigin::Point(Point::new(x, y)),
            (name, _) => ProgramOrigin::from_name(name).filter(|o| !matches!(o, ProgramOrigin::Point(_))).ok_or_else(|| {
                js(text!("settings: program origin '{name}' is not auto, drawing, lower-left or point";
                         "configuração: origem do programa '{name}' não é auto, drawing, lower-left ou point"))
            })?,
        };
        settings = settings.with_origin(origin).map_err(tr)?;
        if let Some(gap) = web.gap {
            settings = settings.with_gap(gap).map_err(tr)?;
        }
        if let Some(layers) = web.layers.clone() {
            settings = settings.with_layers(layers);
        }
        let mut ops = LayerOps::new();
        ops.by_name = web.layer_ops_by_name;
        for [layer, op] in &web.layer_ops {
            let op = Operation::from_name(op).ok_or_else(|| {
                js(text!("settings: layer '{layer}': operation '{op}' is not cut, mark, spot or ignore";
                         "configuração: camada '{layer}': operação '{op}' não é cut, mark, spot ou ignore"))
            })?;
            ops.given.push((layer.clone(), op));
        }
        settings = settings
            .with_layer_ops(ops)
            .with_verify(web.verify)
            .with_small_hole(SmallHole {
                diameter: web.small_hole_diameter,
                speed_pct: web.small_hole_speed,
                min_diameter: web.small_hole_min,
                ..SmallHole::OFF
            })
            .map_err(tr)?
            .with_passes(Passes {
                depth: web.depth,
                pass_depth: web.pass_depth,
            })
            .map_err(tr)?
            .with_thc_lock(crate::process::ThcLock {
                corner_angle_deg: web.thc_corner_angle,
                corner_distance: web.thc_corner_distance,
                end_distance: web.thc_end_distance,
            })
            .map_err(tr)?;
        let post = match (&web.post_json, &web.post) {
            (Some(json), _) if !json.is_empty() => Some(Post::from_json(json).map_err(|e| {
                let t = e.text();
                js(text!("post: {}", t.en; "pós-processador: {}", t.pt))
            })?),
            (_, Some(name)) if !name.is_empty() => Some(preset(name).ok_or_else(|| {
                js(text!("post: no preset '{name}'"; "pós-processador: não existe o modelo '{name}'"))
            })?),
            _ => None,
        };
        if let Some(p) = post {
            settings = settings.with_post(p).map_err(tr)?;
        }
        let settings = settings
            .with_rapid(web.rapid)
            .map_err(tr)?
            .with_pierce_delay(web.pierce_delay)
            .map_err(tr)?
            .with_plan(plan_options(&web, lang)?)
            .map_err(tr)?;
        let out = run_with_progress(dxf, &settings, &mut |done| {
            if let Some(f) = &on_stage {
                // A failing progress callback must not stop the job.
                let _ = f.call2(
                    &JsValue::NULL,
                    &JsValue::from_str(done.stage.name()),
                    &JsValue::from_f64(done.count as f64),
                );
            }
        })
        .map_err(|e| JsError::new(&e.message(lang)))?;
        let report = Report::in_lang(&out, lang).to_json();
        Ok(Job {
            out,
            report,
            settings,
        })
    }

    /// Every order's figures (contour, chained, eulerian) as JSON, for the
    /// side-by-side table.
    pub fn compare_json(&self) -> String {
        let orders = [Order::Contour, Order::Chained, Order::Eulerian];
        let rows: Vec<OrderReport> = compare_orders(&self.out, &self.settings, &orders)
            .iter()
            .map(OrderReport::from)
            .collect();
        serde_json::to_string(&rows).unwrap_or_else(|_| "[]".into())
    }

    /// The program as a flat list for the animation, 7 numbers per move:
    /// `[kind, x0, y0, x1, y1, bulge, t_end]`, kind 0 rapid, 1 lead-in,
    /// 2 contour, 3 lead-out, 4 link, 5 repeat, 6 pierce, 7 spot, 9 mark,
    /// 10 tab; `t_end`
    /// the estimated seconds from the start when the move ends.
    pub fn moves(&self) -> Vec<f64> {
        let t = &self.out.timing;
        let mut v = Vec::new();
        let mut at = self.out.plan.origin;
        let mut time = 0.0;
        // The feed of the cut being written (slowed in a small hole), and
        // its depth passes: the times are `PlanStats::est_time_s`'s, move
        // by move.
        let mut feed = t.feed;
        let passes = t.passes.max(1) as f64;
        for m in self.out.plan.moves() {
            let (kind, a, b, bulge) = match m {
                Move::Rapid(p) => {
                    time += 60.0 * at.dist(p) / t.rapid.max(1e-9);
                    (kind::RAPID, at, p, 0.0)
                }
                Move::Pierce(i) | Move::Spot(i) => {
                    time += t.pierce_delay;
                    feed = self.out.plan.cuts.get(i).map_or(t.feed, |c| t.feed_of(c));
                    let k = if matches!(m, Move::Spot(_)) {
                        kind::SPOT
                    } else {
                        kind::PIERCE
                    };
                    (k, at, at, 0.0)
                }
                Move::Feed(s) if s.role == Role::Tab => {
                    // Crossed at the rapid speed, then a new pierce (as
                    // `PlanStats::est_time_s` counts it).
                    time += 60.0 * s.segment.length() / t.rapid.max(1e-9) + t.pierce_delay;
                    (kind::TAB, s.segment.a, s.segment.b, s.segment.bulge)
                }
                Move::Feed(s) => {
                    let times = match s.role {
                        Role::Contour | Role::Repeat => passes,
                        _ => 1.0,
                    };
                    time += times * 60.0 * s.segment.length() / feed.max(1e-9);
                    let k = match s.role {
                        Role::LeadIn => kind::LEAD_IN,
                        Role::Contour => kind::CONTOUR,
                        Role::LeadOut => kind::LEAD_OUT,
                        Role::Link => kind::LINK,
                        Role::Repeat => kind::REPEAT,
                        Role::Mark => kind::MARK,
                        Role::Tab => kind::TAB, // (above)
                    };
                    (k, s.segment.a, s.segment.b, s.segment.bulge)
                }
                Move::TorchOff => continue,
            };
            at = b;
            v.extend_from_slice(&[kind, a.x, a.y, b.x, b.y, bulge, time]);
        }
        v
    }

    /// Index of the closed contour passing nearest `(x, y)` within `reach`
    /// mm, or -1: where the user clicked to move a start point.
    pub fn contour_at(&self, x: f64, y: f64, reach: f64) -> i32 {
        inspect::contour_near(&self.out, Point::new(x, y), reach, false).map_or(-1, |i| i as i32)
    }

    /// What is under `(x, y)` within `reach` mm (any contour, open ones
    /// too), as JSON ([`inspect::ContourInfo`]), or "null".
    pub fn inspect_json(&self, x: f64, y: f64, reach: f64) -> String {
        inspect::contour_near(&self.out, Point::new(x, y), reach, true)
            .and_then(|i| inspect::contour_info(&self.out, i))
            .and_then(|info| serde_json::to_string(&info).ok())
            .unwrap_or_else(|| "null".into())
    }

    /// The drawn point (segment end, arc centre, POINT) nearest `(x, y)`
    /// within `reach` mm, else `(x, y)`: where a measurement starts or ends.
    pub fn snap(&self, x: f64, y: f64, reach: f64) -> Vec<f64> {
        inspect::snap(&self.out, Point::new(x, y), reach)
            .xy()
            .to_vec()
    }

    /// The JSON report (same as the CLI's `--json`).
    pub fn report_json(&self) -> String {
        self.report.clone()
    }

    /// The G-code program: the one the preview shows.
    pub fn gcode(&self) -> String {
        self.out.gcode.clone()
    }

    /// `[x0, y0, x1, y1]` (mm) of everything drawn.
    pub fn bbox(&self) -> Vec<f64> {
        let b = preview::extent(&self.out);
        if b.is_empty() {
            vec![0.0, 0.0, 1.0, 1.0]
        } else {
            b.to_array().to_vec()
        }
    }

    /// Straight RGBA pixels, `width * height * 4` bytes; `(cx, cy)` is the
    /// drawing point at the centre, `scale` device pixels per mm, and
    /// `pixel_ratio` device pixels per CSS pixel (line widths scale with it).
    pub fn render(
        &self,
        width: u32,
        height: u32,
        cx: f64,
        cy: f64,
        scale: f64,
        pixel_ratio: f64,
    ) -> Result<Vec<u8>, JsError> {
        let view = View::new(width, height, Point::new(cx, cy), scale)
            .ok_or_else(|| JsError::new("preview: size or scale out of range"))?
            .with_pixel_ratio(pixel_ratio);
        let pixmap = preview::render(&self.out, &view)
            .ok_or_else(|| JsError::new("preview: cannot allocate the image"))?;
        Ok(pixmap.take())
    }
}

/// The post presets as JSON: `{"name": post, …}` in menu order.
#[wasm_bindgen]
pub fn presets_json() -> String {
    let map: serde_json::Map<String, serde_json::Value> = PRESET_NAMES
        .iter()
        .filter_map(|n| Some((n.to_string(), serde_json::to_value(preset(n)?).ok()?)))
        .collect();
    serde_json::Value::Object(map).to_string()
}

/// Checks a post given as JSON: "" when it is valid, else the message
/// naming the field, in `lang` ("en" when absent).
#[wasm_bindgen]
pub fn check_post(json: &str, lang: Option<String>) -> String {
    match Post::from_json(json) {
        Ok(_) => String::new(),
        Err(e) => e.message(lang_of(lang.as_deref())),
    }
}

/// "pt-BR" (or "pt…") → Portuguese; anything else, or nothing, English.
fn lang_of(name: Option<&str>) -> Lang {
    name.and_then(Lang::from_name).unwrap_or_default()
}

/// The kinds of move in the page's flat move lists ([`Job::moves`],
/// [`backplot_json`]): one table, mirrored by `KIND` in `www/plan.js`
/// (`tests/browser/numbers-api.test.mjs` checks the two agree).
mod kind {
    pub const RAPID: f64 = 0.0;
    pub const LEAD_IN: f64 = 1.0;
    pub const CONTOUR: f64 = 2.0;
    pub const LEAD_OUT: f64 = 3.0;
    pub const LINK: f64 = 4.0;
    pub const REPEAT: f64 = 5.0;
    pub const PIERCE: f64 = 6.0;
    pub const SPOT: f64 = 7.0;
    /// A feed move with the torch off (only in programs re-read by the backplot).
    pub const DRY_FEED: f64 = 8.0;
    pub const MARK: f64 = 9.0;
    /// Over a tab, the torch off (issue 20 §6).
    pub const TAB: f64 = 10.0;
    /// Numbers per move: `[kind, x0, y0, x1, y1, bulge, t_end]`.
    pub const STRIDE: usize = 7;
}

/// Re-reads a G-code program for the page's backplot: JSON `{"moves": [...],
/// "warnings": [{"line","message"}], "bbox": [x0,y0,x1,y1]}` with `moves`
/// flat as [`Job::moves`] (kind 0 rapid, 2 torch-on move, 8 torch-off feed
/// move), timed at `feed` and `rapid` mm/min.
#[wasm_bindgen]
pub fn backplot_json(text: &str, feed: f64, rapid: f64) -> String {
    let b = backplot(text);
    let (feed, rapid) = (feed.max(1e-3), rapid.max(1e-3));
    let mut moves = Vec::with_capacity(b.moves.len() * kind::STRIDE);
    let mut bbox = BBox::EMPTY;
    let mut time = 0.0;
    for m in &b.moves {
        // 0 rapid, 2 torch-on feed, 8 torch-off feed.
        let (kind, speed) = match m.torch() {
            None => (kind::RAPID, rapid),
            Some(true) => (kind::CONTOUR, feed),
            Some(false) => (kind::DRY_FEED, feed),
        };
        for s in m.segments() {
            time += 60.0 * s.length() / speed;
            bbox.union(&s.bbox());
            moves.extend_from_slice(&[kind, s.a.x, s.a.y, s.b.x, s.b.y, s.bulge, time]);
        }
    }
    let bbox = if bbox.is_empty() {
        [0.0, 0.0, 1.0, 1.0]
    } else {
        bbox.to_array()
    };
    serde_json::json!({ "moves": moves, "warnings": b.warnings, "bbox": bbox }).to_string()
}

/// The crate version.
#[wasm_bindgen]
pub fn version() -> String {
    env!("CARGO_PKG_VERSION").to_string()
}
