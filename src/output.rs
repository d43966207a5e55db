//! What the pipeline made from one file ([`Output`]), and its warnings.

use crate::{contour, dxf, kerf, origin, plan, process, warning, MaterialUsed};

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
    /// ([`crate::Settings::with_verify`]).
    pub verification: Option<plan::Verification>,
    /// What the cuts take from parts lying closer than the kerf, found on
    /// every run without the verification (issue 45 §1; empty with it).
    pub closeness: plan::closeness::Closeness,
    /// The program's estimated time, s ([`crate::gcode::job_time_s`]: a
    /// router's milling and Z moves too): what its header's
    /// `{est_time_s}`, the report and the quote say.
    pub est_time_s: f64,
    /// The router's pockets, engravings and holes (issue 43), when a layer
    /// has a milling operation; written before the profiles.
    pub milled: Option<crate::mill::Milled>,
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
    /// Feed moves before and after arc fitting over the whole program:
    /// the plan's and the router's milling's (None when the job did not
    /// fit arcs).
    pub fn arc_fit(&self) -> Option<plan::ArcFit> {
        let mill = self.milled.as_ref().and_then(|m| m.arc_fit);
        match (self.plan.arc_fit, mill) {
            (Some(a), Some(b)) => Some(plan::ArcFit {
                lines_before: a.lines_before + b.lines_before,
                arcs_before: a.arcs_before + b.arcs_before,
                lines_after: a.lines_after + b.lines_after,
                arcs_after: a.arcs_after + b.arcs_after,
                tolerance: a.tolerance,
            }),
            (a, b) => a.or(b),
        }
    }
}
