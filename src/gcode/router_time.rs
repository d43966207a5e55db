//! A router program's time (issue 43 §6): the plan's, the milling
//! toolpath's and the Z moves of the profiles' depth passes — the one
//! figure the header's `{est_time_s}`, the report and the quote give.
//! Apart from `router.rs` (which writes through `writer.rs`, which fills
//! `{est_time_s}` from here): no import cycle.

use super::post::{Format, Post};
use super::JobInfo;
use crate::mill::Toolpath;
use crate::plan::{CutPlan, Role};

/// True for a post that can run a router: G-code with a spindle speed in
/// its header and a Z word for depth passes.
pub fn is_router(post: &Post) -> bool {
    post.format == Format::Gcode
        && post.header.iter().any(|l| l.contains("{spindle_rpm}"))
        && !post.pass_z.is_empty()
}

/// The router program's time, s — what its `{est_time_s}`, the report and
/// the quote say: the plan's ([`crate::plan::PlanStats::est_time_s`]),
/// the milling toolpath's moves ([`crate::mill::MillStats::time_s`]: cuts
/// at the feed; plunges, ramps and helices at the plunge feed; rapids),
/// the dwells the header and footer write once (`G4 P3`, the spindle's
/// spin-up), the first move down from the safe height the header leaves
/// the tool at to the retract height (`pass_retract`), and the Z moves of each profile as the router presets write
/// them: down at rapid from the safe height to the retract height
/// (`torch_on`; not the first profile's, which finds the tool there), the
/// passes' plunges at the plunge feed (`pass_z`: retract height + depth in
/// all), up at rapid to the retract height after the last pass
/// (`pass_retract`) and to the safe height (`torch_off`); and each tab
/// crossed on every pass ([`super::tabs::cross`]): up at rapid to the safe
/// height, down to the retract height, across at rapid, the pierce's
/// dwell, down to the pass's depth at the plunge feed — or, with a tab
/// height ([`crate::process::Tool::tab_top`]), across at the feed on
/// every pass, after going up to the bridge's top at rapid and before
/// going down again at the plunge feed on the passes deeper than it. A
/// closed profile
/// with leads ([`super::section::releads`]) cuts them again on every pass after
/// the first, with the tool up from the pass's depth to the retract height
/// at rapid, across to the lead-in's start at rapid, and down from there
/// to the next depth at the plunge feed.
pub fn est_time_s(plan: &CutPlan, milling: Option<&Toolpath>, post: &Post, job: &JobInfo) -> f64 {
    let p = &job.process;
    let mut t = plan.stats().est_time_s(p);
    if let Some(m) = milling {
        // Each tool's moves at its own feeds; each change after the first
        // (the header's) with its template's dwells and Z moves.
        for (tool, st) in m.by_tool(post.retract_height) {
            t += st.time_with(p, tool.as_ref());
        }
        let changes = (m.moves.iter().skip(1))
            .filter(|mv| matches!(mv, crate::mill::MillMove::ToolChange(_)))
            .count();
        t += changes as f64 * tool_change_s(post, p);
    }
    t += [&post.program_start, &post.header, &post.footer, &post.program_end]
        .into_iter()
        .map(|l| dwell_s(l, p.pierce_delay))
        .sum::<f64>();
    if p.passes.on() {
        let cuts = (plan.cuts.iter()).filter(|c| !c.spot && !c.is_mark());
        let n = cuts.clone().count() as f64;
        let (safe, retract, h) = (post.safe_height, post.retract_height, p.passes.depth);
        let down_up = (safe - retract).max(0.0);
        // The header leaves the tool at the safe height; the program goes
        // down to the retract height before its first move (`emit.rs`).
        let mut rapid_z = down_up + (n - 1.0).max(0.0) * down_up + n * (h + retract + down_up);
        let mut plunge = n * (retract + h);
        // Tabs: the plan counted each once, across at rapid along it, with
        // one pierce's dwell; the program crosses each on every pass, in a
        // straight line, at depths d, 2d … H (their sum H (n + 1) / 2).
        let passes = p.passes.count() as f64;
        let depths = h * (passes + 1.0) / 2.0;
        let mut rapid_xy = 0.0;
        let mut tabs = 0.0;
        let bridge = p.tool.tab_top(h);
        let mut bridge_s = 0.0;
        for c in cuts {
            for s in c.steps.iter().filter(|s| s.role == Role::Tab) {
                let len = s.segment.length();
                let Some(top) = bridge else {
                    tabs += 1.0;
                    rapid_xy += passes * s.segment.a.dist(s.segment.b) - len;
                    continue;
                };
                // A bridge ([`super::tabs::cross`]): no restart; the plan
                // counted the tab once at rapid with a pierce's dwell.
                bridge_s -= 60.0 * len / p.rapid.max(1e-9) + p.pierce_delay;
                for k in 1..=p.passes.count() {
                    let z = p.passes.z(k);
                    bridge_s += 60.0 * len / c.feed(p).max(1e-9);
                    if z < top - 1e-9 {
                        rapid_z += top - z;
                        plunge += top - z;
                    }
                }
            }
        }
        t += bridge_s;
        rapid_z += tabs * (passes * (safe - retract).max(0.0) + passes * safe + depths);
        plunge += tabs * (passes * retract + depths);
        let mut lead_s = 0.0;
        for c in (plan.cuts.iter()).filter(|c| !c.spot && !c.is_mark()) {
            let Some((first, last, closed)) = super::section::section(c) else {
                continue;
            };
            if !super::section::releads(c, first, last, closed, true) {
                continue;
            }
            let leads: f64 = (c.steps[..first].iter())
                .chain(&c.steps[last + 1..])
                .map(|s| s.segment.length())
                .sum();
            let across = c.end().dist(c.pierce);
            for k in 1..p.passes.count() {
                let up = retract - p.passes.z(k);
                rapid_z += up;
                rapid_xy += across;
                // From the retract height instead of from this depth.
                plunge += up;
                lead_s += 60.0 * leads / c.feed(p).max(1e-9);
            }
        }
        t += lead_s;
        t += 60.0 * ((rapid_z + rapid_xy) / p.rapid.max(1e-9) + plunge / p.tool.plunge_feed.max(1e-9))
            + tabs * (passes - 1.0) * p.pierce_delay;
    }
    t
}

/// The change itself, s, whether a changer's few seconds or a manual
/// change with its touch-off at an `M0` pause: what a tool change is
/// counted beyond its template's dwells and Z moves.
pub const TOOL_CHANGE_S: f64 = 30.0;

/// One tool change's time, s: up to the safe height and back down to the
/// retract height at rapid, the template's dwells (the spindle's
/// spin-up), and [`TOOL_CHANGE_S`].
pub fn tool_change_s(post: &Post, p: &crate::process::Process) -> f64 {
    let z = 2.0 * (post.safe_height - post.retract_height).max(0.0);
    TOOL_CHANGE_S + dwell_s(&post.tool_change, p.pierce_delay) + 60.0 * z / p.rapid.max(1e-9)
}

/// Seconds dwelt by `lines` (templates written once): each `G4 P…` block,
/// P in seconds (GRBL's and LinuxCNC's), `{pierce_delay}` the job's.
pub fn dwell_s(lines: &[String], pierce_delay: f64) -> f64 {
    let mut t = 0.0;
    for l in lines {
        let words: Vec<&str> = l.split_whitespace().collect();
        let g4 = |w: &&str| w.eq_ignore_ascii_case("G4") || w.eq_ignore_ascii_case("G04");
        if !words.iter().any(g4) {
            continue;
        }
        let p = words.iter().find_map(|w| w.strip_prefix('P').or(w.strip_prefix('p')));
        t += match p {
            Some("{pierce_delay}") => pierce_delay,
            Some(v) => v.parse::<f64>().ok().filter(|v| v.is_finite() && *v > 0.0).unwrap_or(0.0),
            None => 0.0,
        };
    }
    t
}

/// The program's time, s, for any post ([`est_time_s`] for a router's,
/// the plan's otherwise): the one figure the header, the report and the
/// quote give.
pub fn job_time_s(
    plan: &CutPlan,
    milling: Option<&Toolpath>,
    post: Option<&Post>,
    job: &JobInfo,
) -> f64 {
    match post {
        Some(post) if is_router(post) => est_time_s(plan, milling, post, job),
        _ => plan.stats().est_time_s(&job.process),
    }
}

#[cfg(test)]
mod tests {
    use super::dwell_s;

    #[test]
    fn a_dwell_is_read_from_its_g4_block_only() {
        let l = |v: &[&str]| v.iter().map(|s| s.to_string()).collect::<Vec<_>>();
        assert_eq!(dwell_s(&l(&["G21 G90", "M3 S{spindle_rpm}", "G4 P3"]), 0.5), 3.0);
        assert_eq!(dwell_s(&l(&["G04 P1.5", "g4 p{pierce_delay}"]), 0.5), 2.0);
        // A P word without G4 (LinuxCNC's G64 P0.02) is no dwell.
        assert_eq!(dwell_s(&l(&["G64 P0.02", "G4"]), 0.5), 0.0);
    }
}
