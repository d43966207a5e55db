//! kerfcam: DXF drawings to cutting programs for 2-D thermal and knife
//! cutting, natively and in WebAssembly.
//!
//! The pipeline, one module per stage, each with one input and one output:
//!
//! ```text
//! &[u8] ─dxf::parse→ Drawing ─contour::extract→ Contours ─kerf::offset→ KerfPaths
//!       ─plan::plan→ CutPlan ─┬─gcode::emit→ String
//!                             ├─preview::render→ Pixmap
//!                             └─report::Report::new→ JSON
//! ```
//!
//! ```
//! let dxf = b"0\nSECTION\n2\nENTITIES\n0\nCIRCLE\n10\n50\n20\n50\n40\n10\n0\nENDSEC\n0\nEOF\n";
//! let settings = kerfcam::Settings::new(1.5, 0.001, 2000.0)?;
//! let out = kerfcam::run(dxf, &settings)?;
//! assert_eq!(out.plan.pierces(), 1);
//! assert!(out.gcode.contains("G21"));
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

pub mod contour;
pub mod dxf;
pub mod gcode;
pub mod geom;
pub mod kerf;
pub mod plan;
pub mod preview;
pub mod report;
mod settings;
pub mod warning;
#[cfg(target_arch = "wasm32")]
pub mod wasm;

pub use settings::{Settings, SettingsError};

use std::fmt;

/// Everything the pipeline made from one file.
#[derive(Clone, Debug)]
pub struct Output {
    /// What was read.
    pub drawing: dxf::Drawing,
    /// Chained and classified contours.
    pub contours: contour::Contours,
    /// Kerf-compensated paths.
    pub kerf: kerf::KerfPaths,
    /// The ordered cuts.
    pub plan: plan::CutPlan,
    /// The program, written from `plan`.
    pub gcode: String,
    /// Speeds for time estimates.
    pub timing: plan::Timing,
}

/// One order's figures, for a side-by-side comparison (paper 003's table).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct OrderSummary {
    /// The order.
    pub order: plan::Order,
    /// Its lengths and counts.
    pub stats: plan::PlanStats,
    /// Estimated machine time, s.
    pub est_time_s: f64,
}

/// Plans the same contours in each of `orders`, for comparison.
pub fn compare_orders(
    out: &Output,
    settings: &Settings,
    orders: &[plan::Order],
) -> Vec<OrderSummary> {
    orders
        .iter()
        .map(|&order| {
            let mut options = settings.plan.clone();
            options.order = order;
            let p = plan::plan(
                &plan::PlanInput {
                    drawing: &out.drawing,
                    contours: &out.contours,
                    kerf: &out.kerf,
                    tolerance: settings.tolerance.mm(),
                    kerf_width: settings.kerf.width,
                },
                &options,
            );
            let stats = p.stats();
            OrderSummary {
                order,
                stats,
                est_time_s: stats.est_time_s(&out.timing),
            }
        })
        .collect()
}

impl Output {
    /// All warnings of all stages, in pipeline order.
    pub fn warnings(&self) -> impl Iterator<Item = &warning::Warning> {
        self.drawing
            .warnings
            .iter()
            .chain(&self.contours.warnings)
            .chain(&self.kerf.warnings)
            .chain(&self.plan.warnings)
    }
}

/// Why a job could not run.
#[derive(Clone, Debug, PartialEq)]
pub enum Error {
    /// The file could not be read.
    Dxf(dxf::DxfError),
    /// A setting is out of range.
    Settings(SettingsError),
}

impl Error {
    /// The message in `lang`.
    pub fn message(&self, lang: warning::Lang) -> String {
        match self {
            Error::Dxf(e) => e.message(lang),
            Error::Settings(e) => e.message(lang),
        }
    }
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Error::Dxf(e) => e.fmt(f),
            Error::Settings(e) => e.fmt(f),
        }
    }
}

impl std::error::Error for Error {}

impl From<dxf::DxfError> for Error {
    fn from(e: dxf::DxfError) -> Self {
        Error::Dxf(e)
    }
}

impl From<SettingsError> for Error {
    fn from(e: SettingsError) -> Self {
        Error::Settings(e)
    }
}

/// Runs the whole pipeline on a DXF file's bytes.
pub fn run(dxf_bytes: &[u8], settings: &Settings) -> Result<Output, Error> {
    let drawing = dxf::parse(dxf_bytes, &settings.read)?;
    let contours = contour::extract(&drawing, settings.tolerance, settings.gap);
    let kerf = kerf::offset(&contours, settings.kerf, settings.tolerance);
    let plan = plan::plan(
        &plan::PlanInput {
            drawing: &drawing,
            contours: &contours,
            kerf: &kerf,
            tolerance: settings.tolerance.mm(),
            kerf_width: settings.kerf.width,
        },
        &settings.plan,
    );
    let gcode = match &settings.post {
        // Validated by `Settings::with_post`; an error here is a job value out of range.
        Some(post) => gcode::emit_post(&plan, post, &gcode::JobInfo::from_options(&settings.gcode))
            .map_err(|e| {
                Error::Settings(SettingsError {
                    field: "post",
                    reason: e.text(),
                })
            })?,
        None => gcode::emit(&plan, &settings.gcode),
    };
    Ok(Output {
        drawing,
        contours,
        kerf,
        plan,
        gcode,
        timing: settings.timing(),
    })
}
