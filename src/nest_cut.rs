//! Cutting a nest: one sheet of a [`nest::Nest`] through the ordinary
//! pipeline (its drawing → contours → kerf → plan → program, unchanged),
//! then the remnant's crop line as the last cut.
//!
//! The crop line is cut last and on its own pierce at the sheet's edge, on
//! the line, no lead-in (paper 001 §6.7: "CORTE DO RETALHO" at the end of
//! the program, starting on the sheet edge with a full pierce cycle). It is
//! not handed to the planner as an open contour: the planner cuts open
//! contours first (markings must be made while the parts are in place),
//! and a crop line cut first would free the remnant under parts still to
//! be cut. The program's zero is the sheet's lower-left corner (the
//! nest's own coordinates), whatever origin the settings ask for.

use crate::contour::{self, ContourKind};
use crate::nest::{output, Nest, NestJob};
use crate::plan::{self, Cut, Role, Step};
use crate::{gcode, kerf, origin, Error, Output, Settings, SettingsError};

/// The crop cuts of sheet `k` (none unless it is the last sheet and keeps
/// a remnant), each pierced at its upper end on the sheet's edge.
pub fn crop_cuts(job: &NestJob, n: &Nest, k: usize) -> Vec<Cut> {
    output::crop_segments(job, n, k)
        .into_iter()
        .map(|segment| Cut {
            pierce: segment.a,
            steps: vec![Step {
                segment,
                role: Role::Contour,
                contour: None,
            }],
            contours: Vec::new(),
            part: None,
            kind: ContourKind::Open,
            spot: false,
        })
        .collect()
}

/// Sheet `k` of the nest cut with `settings`: the pipeline's [`Output`],
/// its plan ending with the crop line.
pub fn cut_sheet(job: &NestJob, n: &Nest, k: usize, settings: &Settings) -> Result<Output, Error> {
    let mut drawing = output::sheet_drawing(job, n, k);
    let origin = origin::apply(
        &mut drawing,
        origin::ProgramOrigin::Drawing,
        settings.tolerance.mm(),
    );
    let contours = contour::extract(&drawing, settings.tolerance, settings.gap);
    let kerf = kerf::offset(&contours, settings.kerf, settings.tolerance);
    let mut plan = plan::plan(
        &plan::PlanInput {
            drawing: &drawing,
            contours: &contours,
            kerf: &kerf,
            tolerance: settings.tolerance.mm(),
            kerf_width: settings.kerf.width,
        },
        &settings.plan,
    );
    plan.cuts.extend(crop_cuts(job, n, k));
    let gcode = match &settings.post {
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
        origin,
    })
}

/// Every sheet of the nest cut, in order.
pub fn cut_all(job: &NestJob, n: &Nest, settings: &Settings) -> Result<Vec<Output>, Error> {
    (0..n.sheets.len())
        .map(|k| cut_sheet(job, n, k, settings))
        .collect()
}
