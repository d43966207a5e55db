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
pub mod contour;
pub mod dxf;
pub mod gcode;
pub mod geom;
pub mod inspect;
pub mod kerf;
pub mod materials;
pub mod nest;
pub mod nest_cut;
pub mod origin;
pub mod plan;
pub mod preview;
pub mod process;
pub mod report;
pub mod scene;
mod settings;
mod sort;
pub mod source;
pub mod warning;
#[cfg(target_arch = "wasm32")]
pub mod wasm;

pub use settings::{MaterialUsed, Settings, SettingsError, Spec, DEFAULT_RAPID};

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
    orders
        .iter()
        .map(|&order| {
            let mut options = settings.plan.clone();
            options.order = order;
            let input = plan::PlanInput {
                file: plan::FileOrder::of(&out.drawing),
                contours: &out.contours,
                kerf: &out.kerf,
                tolerance: settings.tolerance.mm(),
                kerf_width: settings.kerf.width,
            };
            let p = plan::plan(&input, &options);
            let stats = p.stats();
            OrderSummary {
                order,
                stats,
                est_time_s: stats.est_time_s(&out.timing),
                intrusion: plan::intrusion(&input, &p),
            }
        })
        .collect()
}

impl Output {
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

/// Runs the whole pipeline on a DXF file's bytes.
pub fn run(dxf_bytes: &[u8], settings: &Settings) -> Result<Output, Error> {
    run_with_progress(dxf_bytes, settings, &mut |_| {})
}

/// [`run`], calling `progress` after each stage (in [`Stage::ALL`] order).
pub fn run_with_progress(
    dxf_bytes: &[u8],
    settings: &Settings,
    progress: &mut dyn FnMut(StageDone),
) -> Result<Output, Error> {
    check_controller_comp(settings)?;
    let mut drawing = dxf::parse(dxf_bytes, &settings.read)?;
    let origin = origin::apply(&mut drawing, settings.origin, settings.tolerance.mm());
    progress(StageDone {
        stage: Stage::Reading,
        count: drawing.entities.len(),
    });
    cut_drawing(drawing, origin, settings, Vec::new(), progress)
}

/// Refuses controller compensation with a post that has no codes for it.
fn check_controller_comp(settings: &Settings) -> Result<(), Error> {
    if settings.plan.controller_comp {
        if let Some(p) = settings.post.as_ref().filter(|p| {
            p.format != gcode::Format::Gcode || p.comp_left.is_empty() || p.comp_right.is_empty()
        }) {
            let name = p.name.clone();
            return Err(Error::Settings(SettingsError {
                field: "controller_comp",
                reason: text!("the post '{name}' has no cutter compensation codes (comp_left, comp_right)";
                              "o pós-processador '{name}' não tem códigos de compensação (comp_left, comp_right)"),
            }));
        }
    }
    Ok(())
}

/// A drawing already read and placed at its program origin (a DXF's, or
/// a nested sheet's: [`nest_cut`]) through the rest of the pipeline:
/// layers, contours, kerf, plan, verification, program. `last_cuts` are
/// cut after everything the planner ordered (a nest's crop line, which
/// would free the remnant under parts still to be cut if cut earlier).
pub fn cut_drawing(
    drawing: dxf::Drawing,
    origin: origin::Origin,
    settings: &Settings,
    last_cuts: Vec<plan::Cut>,
    progress: &mut dyn FnMut(StageDone),
) -> Result<Output, Error> {
    check_controller_comp(settings)?;
    let mut done = |stage, count| progress(StageDone { stage, count });
    // Layers marked, spotted or ignored leave the cutting pipeline here
    // (issue 20 §2); None when every layer is cut.
    let layered = process::layers::split(
        &drawing,
        &settings.layer_ops,
        settings.tolerance,
        settings.gap,
    );
    let cut_drawing = layered.as_ref().map_or(&drawing, |l| &l.cut);
    let mut contours = contour::extract(cut_drawing, settings.tolerance, settings.gap);
    if let Some(l) = &layered {
        // Entity numbers of the whole drawing, as the report and the
        // drawing order's checks read them.
        for c in &mut contours.contours {
            for e in &mut c.entities {
                *e = l.cut_entities.get(*e).copied().unwrap_or(*e);
            }
        }
        contours.warnings.extend(l.warnings.iter().cloned());
    }
    done(Stage::Chaining, contours.contours.len());
    let mut kerf = kerf::offset(&contours, settings.kerf, settings.tolerance);
    if settings.plan.controller_comp {
        // The controller offsets the tool (issue 20 §7): the paths are the
        // nominal contours; what the kerf cannot reproduce is still said.
        let nominal = kerf::offset(
            &contours,
            kerf::Kerf {
                width: 0.0,
                ..settings.kerf
            },
            settings.tolerance,
        );
        kerf.paths = nominal.paths;
    }
    // What the controller will cut: our own offset (for the verification).
    let controller_paths = (settings.plan.controller_comp && settings.verify)
        .then(|| kerf::offset(&contours, settings.kerf, settings.tolerance));
    let mut spots: Vec<geom::Point> = layered.as_ref().map_or(Vec::new(), |l| l.spots.clone());
    spots.extend(process::holes::spot_too_small(
        &contours,
        &mut kerf,
        &settings.plan.small_hole,
        settings.kerf.width,
    ));
    done(Stage::Offset, kerf.paths.len());
    let marks = layered.as_ref().map_or(&[][..], |l| &l.marks[..]);
    let input = plan::PlanInput {
        file: plan::FileOrder::of(cut_drawing),
        contours: &contours,
        kerf: &kerf,
        tolerance: settings.tolerance.mm(),
        kerf_width: settings.kerf.width,
    };
    let mut plan = plan::plan_with_marks(&input, marks, &spots, &settings.plan);
    plan.cuts.extend(last_cuts);
    let verification = settings.verify.then(|| match &controller_paths {
        // The controller offsets the tool: the cut is the compensated paths'.
        Some(paths) => {
            let input = plan::PlanInput {
                kerf: paths,
                ..input
            };
            let mut options = settings.plan.clone();
            options.controller_comp = false;
            plan::verify(
                &input,
                &plan::plan_with_marks(&input, marks, &spots, &options),
            )
        }
        None => plan::verify(&input, &plan),
    });
    if let Some(w) = verification.as_ref().and_then(plan::Verification::warning) {
        plan.warnings.push(w);
    }
    done(Stage::Planning, plan.pierces());
    let gcode = match &settings.post {
        // Validated by `Settings::with_post`; an error here is a job value out of range.
        Some(post) => gcode::emit_post(
            &plan,
            post,
            &gcode::JobInfo::from_process(&settings.process),
        )
        .map_err(|e| {
            Error::Settings(SettingsError {
                field: "post",
                reason: e.text(),
            })
        })?,
        None => gcode::emit_job(
            &plan,
            &settings.gcode,
            &gcode::JobInfo::from_process(&settings.process),
        ),
    };
    done(Stage::GCode, gcode.len());
    Ok(Output {
        drawing,
        contours,
        kerf,
        plan,
        gcode,
        timing: settings.timing(),
        origin,
        verification,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn progress_reports_every_stage_in_order_with_what_it_made() {
        let dxf = b"0\nSECTION\n2\nENTITIES\n0\nCIRCLE\n10\n50\n20\n50\n40\n10\n0\nCIRCLE\n10\n50\n20\n50\n40\n3\n0\nENDSEC\n0\nEOF\n";
        let settings = Settings::new(1.5, 0.001, 2000.0).unwrap();
        let mut seen = Vec::new();
        let out = run_with_progress(dxf, &settings, &mut |d| seen.push(d)).unwrap();
        let stages: Vec<Stage> = seen.iter().map(|d| d.stage).collect();
        assert_eq!(stages, Stage::ALL);
        let counts: Vec<usize> = seen.iter().map(|d| d.count).collect();
        assert_eq!(counts, [2, 2, 2, 2, out.gcode.len()]);
    }

    #[test]
    fn no_progress_after_a_failed_read() {
        let settings = Settings::new(1.5, 0.001, 2000.0).unwrap();
        let mut seen = Vec::new();
        assert!(
            run_with_progress(b"\x00\x01 not a dxf", &settings, &mut |d| seen.push(d)).is_err()
        );
        assert!(seen.is_empty());
    }
}
