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
use crate::geom::Point;
use crate::preview::{self, View};
use crate::report::Report;
use crate::{run, Output, Settings};

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
        }
    }
}

/// One DXF file run through the whole pipeline.
#[wasm_bindgen]
pub struct Job {
    out: Output,
    report: String,
}

#[wasm_bindgen]
impl Job {
    /// Runs the pipeline; throws an Error with a one-line message for an
    /// unreadable file or a setting out of range.
    #[wasm_bindgen(constructor)]
    pub fn new(dxf: &[u8], settings: JsValue) -> Result<Job, JsError> {
        console_error_panic_hook::set_once();
        let web: WebSettings = if settings.is_undefined() || settings.is_null() {
            WebSettings::default()
        } else {
            serde_wasm_bindgen::from_value(settings)
                .map_err(|e| JsError::new(&format!("settings: {e}")))?
        };
        let mut settings = Settings::new(web.kerf, web.tolerance, web.feed)?;
        if let Some(name) = web.units.filter(|n| !n.is_empty()) {
            let u = Units::from_name(&name)
                .ok_or_else(|| JsError::new(&format!("settings: unknown unit '{name}'")))?;
            settings = settings.with_units(u);
        }
        if let Some(gap) = web.gap {
            settings = settings.with_gap(gap)?;
        }
        if let Some(layers) = web.layers {
            settings = settings.with_layers(layers);
        }
        let out = run(dxf, &settings)?;
        let report = Report::new(&out).to_json();
        Ok(Job { out, report })
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

/// The crate version.
#[wasm_bindgen]
pub fn version() -> String {
    env!("CARGO_PKG_VERSION").to_string()
}
