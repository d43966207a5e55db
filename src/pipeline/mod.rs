//! The pipeline run end to end on one drawing: read, place at the program
//! origin, split layers by operation, chain, offset, plan, verify, write
//! the program — with a progress report after each stage.

use crate::scene::Scene;
use crate::{
    contour, dxf, gcode, geom, kerf, origin, plan, process, text, Error, Output, Settings,
    SettingsError, Stage, StageDone,
};

mod milling;
use milling::{mill_by_tool, mill_layers};

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
    run_watched(dxf_bytes, settings, progress, &mut |_| {})
}

/// [`run_with_progress`], showing `chained` the drawing's contours as soon
/// as they are made (a scene with an empty plan), before the kerf and the
/// plan: the page previews them while the plan is made (issue 17 item 4).
pub fn run_watched(
    dxf_bytes: &[u8],
    settings: &Settings,
    progress: &mut dyn FnMut(StageDone),
    chained: &mut dyn FnMut(Scene<'_>),
) -> Result<Output, Error> {
    check_controller_comp(settings)?;
    let mut drawing = crate::input::read(dxf_bytes, &settings.read)?;
    let origin = origin::apply(&mut drawing, settings.origin, settings.tolerance.mm());
    progress(StageDone {
        stage: Stage::Reading,
        count: drawing.entities.len(),
    });
    cut_watched(drawing, origin, settings, Vec::new(), progress, chained)
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
/// a nested sheet's: [`crate::nest_cut`]) through the rest of the pipeline:
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
    cut_watched(drawing, origin, settings, last_cuts, progress, &mut |_| {})
}

/// [`cut_drawing`], showing `chained` the contours once made ([`run_watched`]).
fn cut_watched(
    drawing: dxf::Drawing,
    origin: origin::Origin,
    settings: &Settings,
    last_cuts: Vec<plan::Cut>,
    progress: &mut dyn FnMut(StageDone),
    chained: &mut dyn FnMut(Scene<'_>),
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
    let mut contours = contour::extract_repairing(
        cut_drawing,
        settings.tolerance,
        settings.gap,
        settings.threads,
        settings.repair,
    );
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
    // Said on every run, whatever the order: only the kerf's width is
    // needed to say what one cut along a shared line takes from each side.
    // The faces are named by identity, for the page to mark (issue 45 §3).
    let shared = contours.shared.warning(settings.kerf().width).map(|w| {
        let faces = contours.shared.contours.iter();
        w.with_loops(faces.filter_map(|&c| contours.contours.get(c).map(|c| c.source)))
    });
    contours.warnings.extend(shared);
    done(Stage::Chaining, contours.contours.len());
    chained(Scene {
        file: plan::FileOrder::of(cut_drawing),
        contours: &contours,
        invalid_vertices: &[],
        plan: &plan::CutPlan::default(),
        milling: None,
        rapids: None,
    });
    // The operator's sides for single profiles (issue 43 §1), matched to
    // their loops before the offset; those not applied are said.
    let sided = plan::choice::sides(
        &settings.plan.sides_at,
        &contours,
        settings.tolerance.mm(),
        settings.process.tool.on(),
        settings.plan.controller_comp || settings.plan.order == plan::Order::Eulerian,
    );
    let mut kerf = kerf::offset_sided(&contours, settings.kerf(), settings.tolerance, &sided.sides);
    if settings.plan.controller_comp {
        // The controller offsets the tool (issue 20 §7): the paths are the
        // nominal contours; what the kerf cannot reproduce is still said.
        let nominal = kerf::offset(
            &contours,
            kerf::Kerf {
                width: 0.0,
                ..settings.kerf()
            },
            settings.tolerance,
        );
        kerf.paths = nominal.paths;
    }
    // What the controller will cut: our own offset (for the verification).
    let controller_paths = (settings.plan.controller_comp && settings.verify)
        .then(|| kerf::offset(&contours, settings.kerf(), settings.tolerance));
    let mut spots: Vec<geom::Point> = layered.as_ref().map_or(Vec::new(), |l| l.spots.clone());
    spots.extend(process::holes::spot_too_small(
        &contours,
        &mut kerf,
        &settings.process,
    ));
    done(Stage::Offset, kerf.paths.len());
    let marks = layered.as_ref().map_or(&[][..], |l| &l.marks[..]);
    let input = plan::PlanInput {
        file: plan::FileOrder::of(cut_drawing),
        contours: &contours,
        kerf: &kerf,
        tolerance: settings.tolerance.mm(),
        process: &settings.process,
    };
    // The router's pockets, engravings and holes (issue 43): their own
    // toolpath, from where the tool starts, cut before the profiles; the
    // profiles are planned, counted and drawn from where it ends.
    let milled = match layered.as_ref().map(|l| &l.milling) {
        Some(g)
            if !g.is_empty() && settings.tools.is_empty() && settings.layer_depths.is_empty() =>
        {
            Some(mill_layers(g, settings, settings.plan.origin)?)
        }
        Some(g) if !g.is_empty() => {
            let profiles = !kerf.paths.is_empty() || !marks.is_empty() || !spots.is_empty();
            Some(mill_by_tool(&drawing, g, settings, profiles)?)
        }
        _ => None,
    };
    let after_milling = milled.as_ref().map(|m| plan::PlanOptions {
        origin: m.toolpath.end(),
        ..settings.plan.clone()
    });
    let options = after_milling.as_ref().unwrap_or(&settings.plan);
    let mut plan = plan::plan_with_marks(&input, marks, &spots, options);
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
                settings.threads,
            )
        }
        None => plan::verify(&input, &plan, settings.threads),
    });
    if let Some(v) = &verification {
        // The parts the sweep finds losing material, by their outlines.
        let losing: std::collections::HashSet<usize> = v.parts.iter().map(|l| l.part).collect();
        let outlines = (contours.contours.iter())
            .filter(|c| c.kind == contour::ContourKind::Outer)
            .filter(|c| c.part.is_some_and(|p| losing.contains(&p)))
            .map(|c| c.source);
        plan.warnings
            .extend(v.warning().map(|w| w.with_loops(outlines)));
    }
    // Without the full sweep, what the cuts take from other parts is still
    // said, in every order (issue 45 §1; the Eulerian order also names the
    // pairs its spacing finds). Left to the sweep under the controller's
    // compensation: the plan's paths are then the drawn lines, not where
    // the kerf goes.
    let mut closeness = plan::closeness::Closeness::default();
    if verification.is_none() && !settings.plan.controller_comp {
        closeness = plan::closeness::closeness(&input, &plan, settings.threads);
        plan.warnings
            .extend(closeness.warning(settings.process.kerf));
    }
    // Slots and notches of one part narrower than the kerf are left uncut:
    // said on every run, from the drawn outlines alone (issue 45 §1).
    let narrow = plan::narrow::narrow(&input, settings.threads);
    plan.warnings
        .extend(narrow.warning(settings.process.kerf, settings.plan.controller_comp));
    if let Some(m) = &milled {
        plan.warnings.extend(m.warnings.iter().cloned());
    }
    plan.warnings
        .extend(sides_missed(&sided, settings, layered.as_ref(), &contours));
    done(Stage::Planning, plan.pierces());
    // The process's values; the threads are the job's (never a template value).
    let job = settings.job();
    let gcode = match (&settings.post, &milled) {
        (Some(post), Some(m)) => {
            gcode::emit_router(&plan, &m.toolpath, post, &job).map_err(|e| {
                Error::Settings(SettingsError {
                    field: "post",
                    reason: e.text(),
                })
            })?
        }
        (None, Some(_)) => {
            return Err(Error::Settings(SettingsError {
                field: "post",
                reason: text!("layers to pocket, engrave or drill need a router post (grbl-router, linuxcnc-router or one of your own with M3 S{{spindle_rpm}})";
                              "camadas de bolsão, gravação ou furação precisam de um pós-processador de fresadora (grbl-router, linuxcnc-router ou um seu com M3 S{{spindle_rpm}})"),
            }))
        }
        // Validated by `Settings::with_post`; an error here is a job value out of range.
        (Some(post), None) => gcode::emit_post(&plan, post, &job).map_err(|e| {
            Error::Settings(SettingsError {
                field: "post",
                reason: e.text(),
            })
        })?,
        (None, None) => gcode::emit(&plan, settings.decimals(), &job),
    };
    done(Stage::GCode, gcode.len());
    let est_time_s = gcode::job_time_s(
        &plan,
        milled.as_ref().map(|m| &m.toolpath),
        settings.post.as_ref(),
        &job,
    );
    Ok(Output {
        est_time_s,
        drawing,
        contours,
        kerf,
        plan,
        gcode,
        process: settings.process,
        material: settings.material.clone(),
        origin,
        verification,
        closeness,
        milled,
    })
}

/// The warning naming the side picks not applied; a pick on a pocket,
/// engraving or drilling is said to be on no profile (those contours are
/// not in the cutting pipeline's).
fn sides_missed(
    sided: &plan::choice::Sided,
    settings: &Settings,
    layered: Option<&process::layers::Layered>,
    contours: &contour::Contours,
) -> Option<crate::warning::Warning> {
    use plan::choice::Unapplied;
    let picks = &settings.plan.sides_at;
    let tol = settings.tolerance.mm();
    let missed: Vec<(usize, Unapplied)> = (sided.missed.iter())
        .map(|&(k, why)| match (why, layered, picks.get(k)) {
            (Unapplied::Gone, Some(l), Some(p))
                if l.milling.passes_near(p.pick.at, p.pick.reach_at(tol)) =>
            {
                (k, Unapplied::NotProfile)
            }
            _ => (k, why),
        })
        .collect();
    plan::choice::sides_not_applied(picks, &missed, contours)
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
    fn the_contours_are_shown_once_chained_before_the_plan_is_made() {
        let dxf = b"0\nSECTION\n2\nENTITIES\n0\nCIRCLE\n10\n50\n20\n50\n40\n10\n0\nCIRCLE\n10\n50\n20\n50\n40\n3\n0\nENDSEC\n0\nEOF\n";
        let settings = Settings::new(1.5, 0.001, 2000.0).unwrap();
        let mut stages = Vec::new();
        let mut seen = Vec::new();
        let out = {
            let stages = std::cell::RefCell::new(&mut stages);
            run_watched(
                dxf,
                &settings,
                &mut |d| stages.borrow_mut().push(d.stage),
                &mut |s| {
                    seen.push((
                        s.contours.contours.len(),
                        s.plan.cuts.len(),
                        stages.borrow().len(),
                    ))
                },
            )
            .unwrap()
        };
        // Once, with both contours, no cut yet, after reading and chaining only.
        assert_eq!(seen, [(2, 0, 2)]);
        assert_eq!(out.plan.cuts.len(), 2);
        assert_eq!(stages, Stage::ALL);
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
