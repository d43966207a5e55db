//! The JavaScript boundary (the only file that knows JS): a `Job` handle that
//! runs the pipeline once and answers small questions about the result.
//!
//! ```js
//! const job = new Job(bytes, { kerf: 1.5, tolerance: 0.001, feed: 2000 });
//! job.report_json(); job.gcode(); job.bbox(); job.render(w, h, cx, cy, scale, pixel_ratio);
//! ```

use wasm_bindgen::prelude::*;

// The kinds of move in the page's flat move lists ([`Job::moves`],
// [`backplot_json`]): one table, mirrored by `KIND` in `www/plan.js`.
use crate::animation::kind;
use crate::gcode::{backplot, Post};
use crate::geom::{BBox, Point};
use crate::inspect;
use crate::plan::Order;
use crate::preview::{self, View};
use crate::report::{OrderReport, Report};
use crate::warning::Lang;
use crate::{compare_orders, run_watched, Output, Settings, Spec};

// Nesting (issue 16): its own file, the page's Sheet mode (issue 18). Only in
// the second wasm module (feature "nester", issue 17): the page loads it when
// Sheet mode first nests, so the cutting core stays small.
#[cfg(feature = "nester")]
mod nest_edit;
#[cfg(feature = "nester")]
mod nest_job;
#[cfg(feature = "nester")]
mod nest_json;
#[cfg(feature = "nester")]
mod nest_progress;
#[cfg(feature = "nester")]
mod nest_result;
#[cfg(feature = "nester")]
mod nest_settings;
#[cfg(feature = "nester")]
mod nest_team;
#[cfg(feature = "nester")]
mod nest_trials;
#[cfg(feature = "nester")]
mod nesting;
#[cfg(feature = "nester")]
pub use nest_result::NestResult;
#[cfg(feature = "nester")]
pub use nest_team::NestSearch;
#[cfg(feature = "nester")]
pub use nest_trials::NestTrials;
#[cfg(feature = "nester")]
pub use nesting::Nester;
// Cut charts (issue 20 §1): the page's material library.
mod materials;
// The verification's heat map (issue 20 §9).
mod heat;
// The parts the cuts take from, marked before the download (issue 45 §3).
mod losses;
// Cost and time (issue 42 §3): the Cost panel's quote.
mod quote;
pub use materials::{materials_cfg, materials_check, materials_read, materials_starter};
pub use quote::check_cost;

/// One DXF file run through the whole pipeline.
#[wasm_bindgen]
pub struct Job {
    out: Output,
    report: Report,
    settings: Settings,
    /// Part names by part number − 1 (a nest's sheet), for the plan's SVG.
    names: Vec<String>,
    /// The rapids the preview draws, made once
    /// ([`crate::animation::preview_rapids`]).
    rapids: Option<Vec<crate::geom::Segment>>,
}

/// The page's settings object as validated settings: a Spec by its wire
/// names, checked by the one builder the CLI uses (issue 15 §5); errors
/// in the page's language. The object is read as its JSON text (the JSON
/// reader is in the module anyway; serde-wasm-bindgen's cost ~9 KB of it,
/// issue 17 item 5): what JSON cannot say (undefined, a function) is absent.
pub(crate) fn settings_of(settings: JsValue) -> Result<Settings, JsError> {
    let spec: Spec = if settings.is_undefined() || settings.is_null() {
        Spec::default()
    } else {
        let text = js_sys::JSON::stringify(&settings)
            .ok()
            .and_then(|t| t.as_string())
            .ok_or_else(|| JsError::new("settings: not an object"))?;
        serde_json::from_str(&text).map_err(|e| JsError::new(&format!("settings: {e}")))?
    };
    let lang = spec.lang();
    spec.build().map_err(|e| JsError::new(&e.message(lang)))
}

impl Job {
    /// The handle on a finished pipeline run, its report made once.
    pub(crate) fn of(out: Output, settings: Settings) -> Job {
        let report = Report::in_lang(&out, settings.lang);
        let rapids =
            crate::animation::preview_rapids(&out.scene(), &out.process, settings.post());
        Job {
            out,
            report,
            settings,
            names: Vec::new(),
            rapids,
        }
    }
    /// The same job, its parts named (a nest's sheet: the plan's SVG labels
    /// each copy with its part's name).
    #[cfg(feature = "nester")]
    pub(crate) fn with_names(mut self, names: Vec<String>) -> Job {
        self.names = names;
        self
    }
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
        Job::watched(dxf, settings, on_stage, None, None)
    }

    /// [`Job::new`], and `on_contours(rgba, view)`, when given with `preview` = `[width,
    /// height, pixel_ratio]` (the canvas in CSS pixels), is called once the
    /// contours are made, before the plan (issue 17 item 4): the contours
    /// rendered fitted in the canvas as [`Job::render`] would, and the view,
    /// `[cx, cy, scale]` (scale in CSS pixels per mm, as the page keeps it).
    pub fn watched(
        dxf: &[u8],
        settings: JsValue,
        on_stage: Option<js_sys::Function>,
        preview: Option<Vec<f64>>,
        on_contours: Option<js_sys::Function>,
    ) -> Result<Job, JsError> {
        console_error_panic_hook::set_once();
        let settings = settings_of(settings)?;
        let lang = settings.lang;
        let mut stage = |done: crate::StageDone| {
            if let Some(f) = &on_stage {
                // A failing progress callback must not stop the job.
                let _ = f.call2(
                    &JsValue::NULL,
                    &JsValue::from_str(done.stage.name()),
                    &JsValue::from_f64(done.count as f64),
                );
            }
        };
        let mut chained = |scene: crate::scene::Scene<'_>| {
            let (Some(f), Some(&[w, h, ratio])) = (&on_contours, preview.as_deref()) else {
                return;
            };
            if let Some((rgba, fit)) = fitted_render(&scene, w, h, ratio) {
                let _ = f.call2(
                    &JsValue::NULL,
                    &js_sys::Uint8Array::from(&rgba[..]),
                    &js_sys::Float64Array::from(&fit[..]),
                );
            }
        };
        let out = run_watched(dxf, &settings, &mut stage, &mut chained)
            .map_err(|e| JsError::new(&e.message(lang)))?;
        Ok(Job::of(out, settings))
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
    /// `[kind, x0, y0, x1, y1, bulge, t_end]` ([`crate::animation`]: kind 0
    /// rapid, 1 lead-in, 2 contour, 3 lead-out, 4 link, 5 repeat, 6 pierce,
    /// 7 spot, 9 mark, 10 tab, 11 a Z move in place, 12 a milling cut, 13 a
    /// ramp or helix); `t_end` the estimated seconds from the start when
    /// the move ends. A router's milling first, each depth pass listed:
    /// the moves the program is written from, in its order.
    pub fn moves(&self) -> Vec<f64> {
        crate::animation::moves(&self.out.scene(), &self.out.process, self.settings.post())
    }

    /// The closed contour passing nearest `(x, y)` within `reach` mm as a
    /// choice the page keeps (issue 39 §1), JSON `{"contour": i, "at":
    /// [x, y], "on": {part, copy, contour, area, length, size, layer}}`:
    /// the point moved onto the loop and the loop's key, which the next
    /// plans match again whatever the contours' numbers; or "null".
    pub fn pick_at(&self, x: f64, y: f64, reach: f64) -> String {
        let Some((i, pick)) =
            crate::plan::choice::pick_at(&self.out.contours, Point::new(x, y), reach)
        else {
            return "null".into();
        };
        let Some(key) = pick.on else {
            return "null".into();
        };
        serde_json::json!({
            "contour": i,
            "at": [pick.at.x, pick.at.y],
            "on": {
                "part": key.source.part,
                "copy": key.source.copy,
                "contour": key.source.contour,
                "area": key.area,
                "length": key.length,
                "size": key.size,
                "layer": key.layer,
            },
        })
        .to_string()
    }

    /// What is under `(x, y)` within `reach` mm (any contour, open ones
    /// too), as JSON ([`inspect::ContourInfo`]), or "null".
    pub fn inspect_json(&self, x: f64, y: f64, reach: f64) -> String {
        inspect::contour_near(&self.out.scene(), Point::new(x, y), reach, true)
            .and_then(|i| inspect::contour_info(&self.out.scene(), i))
            .and_then(|info| serde_json::to_string(&info).ok())
            .unwrap_or_else(|| "null".into())
    }

    /// The drawn point (segment end, arc centre, POINT) nearest `(x, y)`
    /// within `reach` mm, else `(x, y)`: where a measurement starts or ends.
    pub fn snap(&self, x: f64, y: f64, reach: f64) -> Vec<f64> {
        inspect::snap(&self.out.scene(), Point::new(x, y), reach)
            .xy()
            .to_vec()
    }

    /// The JSON report (same as the CLI's `--json`).
    pub fn report_json(&self) -> String {
        self.report.to_json()
    }

    /// The report as the page shows it: above `max_contours` contours
    /// without the per-contour list (the page shows counts; the list of a
    /// 125k-contour nest is 18 MB of JSON to write and read again), its
    /// length given as `contours_omitted`.
    pub fn page_report_json(&mut self, max_contours: usize) -> String {
        self.report.to_json_listing_at_most(max_contours)
    }

    /// The G-code program: the one the preview shows.
    pub fn gcode(&self) -> String {
        self.out.gcode.clone()
    }

    /// The cut plan as an SVG drawing in mm (`kerfcam FILE -o OUT.svg`):
    /// one layer, labelled `label`, with a layer per part holding the
    /// drawing, kerf path, leads and pierces.
    pub fn plan_svg(&self, label: &str) -> String {
        let scene = self.out.scene();
        let rapids = crate::animation::rapids(&scene, &self.out.process, self.settings.post());
        crate::svg::plan::to_svg(&[crate::svg::plan::SheetPlan {
            label,
            scene,
            names: &self.names,
            rapids: &rapids,
        }])
    }

    /// The program as UTF-8 bytes (a Uint8Array the worker moves to the
    /// page, which saves it as it is: no string made and encoded again).
    pub fn program(&self) -> Vec<u8> {
        self.out.gcode.as_bytes().to_vec()
    }

    /// `[x0, y0, x1, y1]` (mm) of everything drawn.
    pub fn bbox(&self) -> Vec<f64> {
        let b = preview::extent(&self.out.scene());
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
        let scene = crate::scene::Scene {
            rapids: self.rapids.as_deref(),
            ..self.out.scene()
        };
        let pixmap = preview::render(&scene, &view)
            .ok_or_else(|| JsError::new("preview: cannot allocate the image"))?;
        Ok(pixmap.take())
    }
}

/// The scene fitted in a `w × h` CSS-pixel canvas as the page fits a job
/// (`fitView` in www/view.js: its extent with a 10 % margin) and rendered
/// at `ratio` device pixels per CSS pixel; with the view `[cx, cy, scale]`.
fn fitted_render(
    scene: &crate::scene::Scene<'_>,
    w: f64,
    h: f64,
    ratio: f64,
) -> Option<(Vec<u8>, [f64; 3])> {
    let b = preview::extent(scene);
    if b.is_empty() {
        return None;
    }
    let scale =
        (w / ((b.max.x - b.min.x).max(1e-3) * 1.1)).min(h / ((b.max.y - b.min.y).max(1e-3) * 1.1));
    let c = b.centre();
    let px = |v: f64| (v * ratio).round().max(1.0) as u32;
    let view = View::new(px(w), px(h), c, scale * ratio)?.with_pixel_ratio(ratio);
    Some((preview::render(scene, &view)?.take(), [c.x, c.y, scale]))
}

/// The post presets as JSON: `{"name": post, …}` in menu order.
#[wasm_bindgen]
pub fn presets_json() -> String {
    crate::gcode::presets_json()
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

/// An error in the page's language.
#[cfg(feature = "nester")]
fn say(lang: Lang, t: crate::warning::Text) -> JsError {
    JsError::new(t.get(lang))
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
    crate::gcode::backplot_web_json(&moves, &b.warnings, bbox)
}

/// The defaults of the page's number fields by their settings' wire names
/// (the nest's under `nest`), JSON: the form's initial values and what
/// "Reset to defaults" puts back ([`crate::page_defaults`]).
#[wasm_bindgen]
pub fn defaults_json() -> String {
    crate::page_defaults().to_string()
}

/// The crate version.
#[wasm_bindgen]
pub fn version() -> String {
    env!("CARGO_PKG_VERSION").to_string()
}
