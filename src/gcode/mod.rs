//! Stage 5: [`CutPlan`] → program text, as a [`Post`] says.
//!
//! # Output contract
//! - A post is data ([`Post`], JSON): units, decimals, arc mode, block
//!   numbers and framing, comments, modal suppression, header/footer and
//!   torch templates with typed variables. Ten presets ([`PRESET_NAMES`]):
//!   LinuxCNC (plain and QtPlasmaC), GRBL (laser, plasma), Mach3/4 plasma,
//!   ISO 6983, paper 001's annex H dialect, paper 002's point list, paper
//!   003's knife rows and a tangential-knife G-code.
//! - [`emit`] keeps the first pipeline's LinuxCNC program (the `linuxcnc`
//!   preset); [`emit_post`] writes any post; [`est_time_s`] is the time on the
//!   post's machine; [`backplot`] re-reads a program into moves.
//! - Every coordinate is rounded to a fixed grid of `decimals` places, and
//!   the machine position is tracked on that grid, so what the program says
//!   is where the machine is; arc centres are grid points whose distances to
//!   both rounded ends agree within one grid step (see `emit.rs`).
//! - Comments carry only our own words and numbers, sanitised ([`sanitise`]);
//!   numbers never print as `-0`, `NaN`, an exponent or with a comma.

mod backplot;
mod backplot_json;
mod bytes;
mod check;
mod emit;
mod flatten;
mod knife;
mod motion;
mod number;
mod passes;
mod point_list;
mod post;
mod presets;
mod router;
mod router_time;
mod runs;
mod section;
mod step;
mod tabs;
mod thc;
mod validate;
mod writer;

pub use backplot::{backplot, Backplot, BackplotMove, BackplotWarning};
pub use backplot_json::backplot_web_json;
pub use check::PostError;
pub use check::VARS;
pub use post::{ArcMode, CommentStyle, Format, Knife, LineNumbers, Post, Units};
pub use presets::{preset, presets_json, PRESET_NAMES};
pub use router::emit_router;
pub use section::releads;
pub use router_time::{dwell_s, is_router, job_time_s, tool_change_s, TOOL_CHANGE_S};
pub(crate) use writer::Writer;

use crate::par::Threads;
use crate::plan::CutPlan;

/// The job's typed values that templates may use (never DXF text): the
/// process as resolved (its one home, [`crate::process::Process`]), the
/// program number and the writer's threads.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct JobInfo {
    /// Kerf, feed, delay, rapid, heights, small holes, passes, torches,
    /// height locks and material number, as the planner applied them.
    pub process: crate::process::Process,
    /// Program number (annex H's `%52100`).
    pub program: u32,
    /// Threads that may write the program (never a template value: the
    /// program is the same with any).
    pub threads: Threads,
}

impl JobInfo {
    /// What a post may write of `p`; program number 1, one thread.
    pub fn from_process(p: &crate::process::Process) -> JobInfo {
        JobInfo {
            process: *p,
            program: 1,
            threads: Threads::ONE,
        }
    }
}

/// Text safe inside `( )`: no parentheses, no `;`, no line breaks or other
/// control characters, ASCII only (some controllers choke on anything else).
pub fn comment(text: &str) -> String {
    format!("({})", sanitise(text))
}

/// Printable ASCII without any comment or block delimiter of our dialects
/// (`( ) ; % $ #`), one line, at most 120 characters: a layer named
/// `A)\nM30\n(` cannot end a comment and start a block.
pub fn sanitise(text: &str) -> String {
    let mut s = String::with_capacity(text.len().min(120));
    push_sanitised(&mut s, text);
    s
}

/// [`sanitise`] appended to `out` (a program writes one a cut).
fn push_sanitised(out: &mut String, text: &str) {
    let start = out.len();
    let mut leading = true;
    for c in text.chars().take(120) {
        let c = match c {
            '(' | ')' | ';' | '%' | '$' | '#' => ' ',
            c if c.is_ascii_graphic() || c == ' ' => c,
            _ => '?',
        };
        // Trimmed: every character left is ASCII, the only blank a space.
        if leading && c == ' ' {
            continue;
        }
        leading = false;
        out.push(c);
    }
    let end = out[start..].trim_end_matches(' ').len();
    out.truncate(start + end);
}

/// A comment in the post's style (None when the post writes none).
pub fn comment_as(style: CommentStyle, text: &str) -> Option<String> {
    match style {
        CommentStyle::Parens => Some(comment(text)),
        CommentStyle::Semicolon => Some(format!("; {}", sanitise(text))),
        CommentStyle::Dollar => Some(format!("$ {}", sanitise(text))),
        CommentStyle::None => None,
    }
}

/// Writes the LinuxCNC program of the first pipeline (the `linuxcnc`
/// preset) with `decimals` places and the job's process values.
pub fn emit(plan: &CutPlan, decimals: u32, job: &JobInfo) -> String {
    runs::gcode(plan, &plain_post(decimals), job)
}

/// The post [`emit`] writes with: plain LinuxCNC at `decimals` places,
/// with the `linuxcnc` preset's Z words for depth passes (unused when the
/// job has none).
pub fn plain_post(decimals: u32) -> Post {
    Post {
        name: "LinuxCNC".into(),
        decimals: decimals.clamp(1, 6),
        pass_z: vec!["G1 Z{pass_z}".into()],
        pass_retract: vec!["G0 Z{safe_height}".into()],
        ..Post::default()
    }
}

/// Writes the plan as `post` says; an invalid post names its field.
pub fn emit_post(plan: &CutPlan, post: &Post, job: &JobInfo) -> Result<String, PostError> {
    post.validate()?;
    for (field, v, max) in [
        ("job.process.feed", job.process.feed, 1e6),
        ("job.process.kerf", job.process.kerf, 100.0),
        ("job.process.pierce_delay", job.process.pierce_delay, 60.0),
        ("job.process.pierce_height", job.process.pierce_height, 100.0),
        ("job.process.cut_height", job.process.cut_height, 100.0),
        ("job.process.small_hole.speed_pct", job.process.small_hole.speed_pct, 100.0),
        ("job.depth", job.process.passes.depth, 1000.0),
        ("job.pass_depth", job.process.passes.pass_depth, 1000.0),
    ] {
        if !(v.is_finite() && (0.0..=max).contains(&v)) {
            return Err(PostError {
                field: field.into(),
                reason: crate::text!("{v} is not between 0 and {max}"; "{} não está entre 0 e {}", crate::warning::dec(v), crate::warning::dec(max)),
            });
        }
    }
    router::needs_depth(post, job)?;
    if job.process.passes.on() && (post.format != Format::Gcode || post.pass_z.is_empty()) {
        // A post that cannot move Z would cut every pass at the same depth,
        // n times over the same line: refused, not written.
        let name = &post.name;
        return Err(PostError {
            field: "pass_z".into(),
            reason: crate::text!("post '{name}' has no Z word for depth passes (a G-code post with a 'pass_z' template, e.g. 'G1 Z{{pass_z}}'): multi-pass refused";
                                 "o pós-processador '{name}' não tem palavra Z para passes em profundidade (um pós de G-code com o modelo 'pass_z', p. ex. 'G1 Z{{pass_z}}'): multipasse recusado"),
        });
    }
    if job.process.torches.is_some() && post.format != Format::Gcode {
        // Without comments or a program stop, the operator would not learn
        // from the program that the other torches cut too.
        let name = &post.name;
        return Err(PostError {
            field: "torches".into(),
            reason: crate::text!("post '{name}' is not G-code: it cannot name the torch setup or stop for it; several torches refused";
                                 "o pós-processador '{name}' não é G-code: não pode nomear a montagem das tochas nem parar para ela; várias tochas recusadas"),
        });
    }
    let tabs = plan
        .cuts
        .iter()
        .any(|c| c.steps.iter().any(|s| s.role == crate::plan::Role::Tab));
    if tabs && post.format != Format::Gcode {
        // Paper 002's and 003's row formats have no torch switch within a
        // path: a tab would be cut through. Refused, not written wrong.
        let name = &post.name;
        return Err(PostError {
            field: "format".into(),
            reason: crate::text!("post '{name}' cannot leave tabs (its rows cut a path without stopping): tabs refused";
                                 "o pós-processador '{name}' não deixa pontes (suas linhas cortam um caminho sem parar): pontes recusadas"),
        });
    }
    Ok(match post.format {
        Format::Gcode => runs::gcode(plan, post, job),
        Format::PointList => point_list::write(plan, post),
        Format::KnifeRelative => knife::write(plan, post),
    })
}

/// Estimated machine time of the plan, s: feed moves at the process's feed
/// (slowed in small holes), rapids at its rapid speed, a dwell per pierce,
/// each contour once per depth pass.
pub fn est_time_s(plan: &CutPlan, job: &JobInfo) -> f64 {
    plan.stats().est_time_s(&job.process)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn comments_cannot_break_out_or_inject_blocks() {
        let c = comment("layer (x)\nG0 X0; M3");
        assert_eq!(c, "(layer  x ?G0 X0  M3)");
        assert_eq!(c.matches('(').count(), 1);
        assert_eq!(c.matches(')').count(), 1);
        assert!(!c.contains('\n') && !c.contains(';'));
        let evil = "A)\nM30\n(";
        for style in [
            CommentStyle::Parens,
            CommentStyle::Semicolon,
            CommentStyle::Dollar,
        ] {
            let c = comment_as(style, evil).unwrap();
            assert!(!c.contains('\n') && !c.contains(')') || style == CommentStyle::Parens);
            assert_eq!(c.lines().count(), 1);
        }
        assert_eq!(comment_as(CommentStyle::None, evil), None);
    }
}
