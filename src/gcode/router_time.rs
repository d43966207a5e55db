//! A router program's time (issue 43 §6): the plan's, the milling
//! toolpath's and the Z moves of the profiles' depth passes — the one
//! figure the header's `{est_time_s}`, the report and the quote give.
//! Apart from `router.rs` (which writes through `writer.rs`, which fills
//! `{est_time_s}` from here): no import cycle.

use super::post::{Format, Post};
use super::JobInfo;
use crate::mill::Toolpath;
use crate::plan::CutPlan;

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
/// and the Z moves of each profile as the router presets write them: down
/// at rapid from the safe height to the retract height (`torch_on`; not
/// the first profile's, which finds the tool there), the passes' plunges
/// at the plunge feed (`pass_z`: retract height + depth in all), up at
/// rapid to the retract height after the last pass (`pass_retract`) and
/// to the safe height (`torch_off`).
pub fn est_time_s(plan: &CutPlan, milling: Option<&Toolpath>, post: &Post, job: &JobInfo) -> f64 {
    let p = &job.process;
    let mut t = plan.stats().est_time_s(p);
    if let Some(m) = milling {
        t += m.stats(m.start, post.retract_height).time_s(p);
    }
    if p.passes.on() {
        let n = (plan.cuts.iter())
            .filter(|c| !c.spot && !c.is_mark())
            .count() as f64;
        let (safe, retract, h) = (post.safe_height, post.retract_height, p.passes.depth);
        let down_up = (safe - retract).max(0.0);
        let rapid_z = (n - 1.0).max(0.0) * down_up + n * (h + retract + down_up);
        let plunge = n * (retract + h);
        t += 60.0 * (rapid_z / p.rapid.max(1e-9) + plunge / p.tool.plunge_feed.max(1e-9));
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
