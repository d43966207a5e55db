//! kerfcam: DXF drawings to cutting programs for 2-D thermal and knife
//! cutting, natively and in WebAssembly.
//!
//! The pipeline, one module per stage, each with one input and one output:
//!
//! ```text
//! &[u8] ─dxf::parse→ Drawing ─contour::extract→ Contours ─kerf::offset→ KerfPaths
//!       ─plan::plan→ CutPlan ─┬─gcode::emit→ String
//!                             ├─preview::render→ Pixmap   (of a scene::Scene:
//!                             │                            contours + plan)
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

mod case;
mod cell_lists;
pub mod contour;
pub mod dxf;
mod fx;
pub mod gcode;
pub mod geom;
pub mod inspect;
pub mod kerf;
pub mod materials;
pub mod nest;
pub mod nest_cut;
pub mod origin;
pub mod par;
mod pipeline;
pub mod plan;
pub mod preview;
pub mod process;
pub mod report;
pub mod scene;
mod settings;
mod sort;
pub mod source;
#[cfg(test)]
mod test_rng;
pub mod warning;
#[cfg(target_arch = "wasm32")]
pub mod wasm;

pub use pipeline::{cut_drawing, run, run_watched, run_with_progress};
pub use settings::{page_defaults, MaterialUsed, Settings, SettingsError, Spec, DEFAULT_RAPID};

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
    /// The process the plan and the program were made with (the time
    /// estimate's speeds too: [`Output::timing`]).
    pub process: process::Process,
    /// The cut-chart entry the process came from, if any.
    pub material: Option<MaterialUsed>,
    /// Which drawing point is the program's zero (everything above is
    /// already moved there).
    pub origin: origin::Origin,
    /// The plan's kerf swept over the parts (issue 20 §9), when asked
    /// ([`Settings::with_verify`]).
    pub verification: Option<plan::Verification>,
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
    /// How far its torch-on moves cut into parts (issue 14): an order that
    /// cuts into parts is never the one to choose, however fast.
    pub intrusion: plan::Intrusion,
}

/// Plans the same contours in each of `orders`, for comparison; each plan's
/// torch-on moves are checked against the drawn parts ([`plan::intrusion`]).
pub fn compare_orders(
    out: &Output,
    settings: &Settings,
    orders: &[plan::Order],
) -> Vec<OrderSummary> {
    // The drawing order cuts the cut layers' entities only, as the
    // pipeline's plan does: marked, spotted and ignored layers are not cut.
    let layered = process::layers::split(
        &out.drawing,
        &settings.layer_ops,
        settings.tolerance,
        settings.gap,
    );
    let cut_drawing = layered.as_ref().map_or(&out.drawing, |l| &l.cut);
    orders
        .iter()
        .map(|&order| {
            let mut options = settings.plan.clone();
            options.order = order;
            let input = plan::PlanInput {
                file: plan::FileOrder::of(cut_drawing),
                contours: &out.contours,
                kerf: &out.kerf,
                tolerance: settings.tolerance.mm(),
                kerf_width: settings.process.kerf,
            };
            let p = plan::plan(&input, &options);
            let stats = p.stats();
            OrderSummary {
                order,
                stats,
                est_time_s: stats.est_time_s(&out.timing()),
                intrusion: plan::intrusion(&input, &p),
            }
        })
        .collect()
}

impl Output {
    /// The speeds of the time estimate: the process's.
    pub fn timing(&self) -> plan::Timing {
        plan::Timing::of(&self.process)
    }
    /// All warnings of all stages, most serious first (units, truncation,
    /// parts cut into…; notes last), in pipeline order within a rank.
    pub fn warnings(&self) -> impl Iterator<Item = &warning::Warning> {
        warning::by_severity(
            self.drawing
                .warnings
                .iter()
                .chain(&self.contours.warnings)
                .chain(&self.kerf.warnings)
                .chain(&self.plan.warnings),
        )
        .into_iter()
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

/// A pipeline stage, for progress reports (the page's progress bar).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Stage {
    /// DXF bytes → Drawing.
    Reading,
    /// Drawing → Contours (healing, chaining, containment depth).
    Chaining,
    /// Contours → kerf paths.
    Offset,
    /// Kerf paths → CutPlan.
    Planning,
    /// CutPlan → program text.
    GCode,
}

impl Stage {
    /// Every stage, in pipeline order.
    pub const ALL: [Stage; 5] = [
        Stage::Reading,
        Stage::Chaining,
        Stage::Offset,
        Stage::Planning,
        Stage::GCode,
    ];

    /// Stable name: "reading", "chaining", "offset", "planning", "gcode".
    pub fn name(self) -> &'static str {
        match self {
            Stage::Reading => "reading",
            Stage::Chaining => "chaining",
            Stage::Offset => "offset",
            Stage::Planning => "planning",
            Stage::GCode => "gcode",
        }
    }
}

/// What one finished stage made: `stage` and a count of what it produced
/// (entities read, contours, kerf paths, pierces, program bytes), so a
/// progress display can show results as they come.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct StageDone {
    /// The stage that finished.
    pub stage: Stage,
    /// Entities, contours, kerf paths, pierces or program bytes.
    pub count: usize,
}
