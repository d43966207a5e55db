//! A router's program (issue 43 §5): the milling [`Toolpath`] — pockets,
//! engravings, holes, in X, Y and Z — then the plan's profiles in depth
//! passes, through one post. The spindle starts in the post's header
//! (`M3 S{spindle_rpm}`) and stops in its footer; moves into material go
//! at the tool's plunge feed, moves across it at the job's feed, each F
//! written when it changes; arcs are G2/G3 on the post's grid, a helix
//! an arc with a Z word.

use super::emit::Cutter;
use super::motion::State;
use super::number::{round_i64, Grid};
use super::post::{ArcMode, Format, Post};
use super::{JobInfo, PostError};
use crate::geom::Segment;
use crate::mill::{MillMove, Toolpath};
use crate::plan::CutPlan;
use crate::text;

/// True for a post that can run a router: G-code with a spindle speed in
/// its header and a Z word for depth passes.
pub fn is_router(post: &Post) -> bool {
    post.format == Format::Gcode
        && post.header.iter().any(|l| l.contains("{spindle_rpm}"))
        && !post.pass_z.is_empty()
}

/// Refused, naming the setting, when `post` runs a router and the job has
/// no depth: its profiles would be cut at the retract height, in the air
/// (its `pass_z` template, the only cutting Z word, is written per pass).
pub fn needs_depth(post: &Post, job: &JobInfo) -> Result<(), PostError> {
    if !is_router(post) || job.process.passes.on() {
        return Ok(());
    }
    let name = &post.name;
    Err(PostError {
        field: "job.depth".into(),
        reason: text!("post '{name}' runs a router, and a router post needs a depth: --depth MM and --pass-depth MM (the deepest pass); without them the tool would move at the retract height, cutting nothing: program refused";
                      "o pós-processador '{name}' comanda uma fresadora, e um pós de fresadora precisa de uma profundidade: --depth MM e --pass-depth MM (o passe mais fundo); sem elas a ferramenta andaria na altura de recuo, sem cortar: programa recusado"),
    })
}

/// Writes `milling` then `plan`'s cuts as `post` says. Refused (naming the
/// field) when the post cannot run a router or the job has no depth.
pub fn emit_router(
    plan: &CutPlan,
    milling: &Toolpath,
    post: &Post,
    job: &JobInfo,
) -> Result<String, PostError> {
    post.validate()?;
    if !is_router(post) {
        let name = &post.name;
        return Err(PostError {
            field: "header".into(),
            reason: text!("post '{name}' cannot run a router (a G-code post with 'M3 S{{spindle_rpm}}' in its header and a 'pass_z' template, as the grbl-router and linuxcnc-router presets): milling refused";
                          "o pós-processador '{name}' não comanda uma fresadora (um pós G-code com 'M3 S{{spindle_rpm}}' no cabeçalho e um modelo 'pass_z', como os modelos grbl-router e linuxcnc-router): fresamento recusado"),
        });
    }
    needs_depth(post, job)?;
    let mut c = Cutter::with_milling(plan, Some(milling), post, job);
    let end = write(&mut c, milling, job);
    c.st = State::at(end);
    c.w.reset_feed();
    for i in 0..plan.cuts.len() {
        c.cut(i);
    }
    Ok(c.finish())
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

#[derive(Clone, Copy, PartialEq)]
enum Feed {
    Cut,
    Plunge,
}

/// The toolpath's blocks; where the tool ends, on the grid.
fn write(c: &mut Cutter, t: &Toolpath, job: &JobInfo) -> (i64, i64) {
    let post = c.post;
    let grid = Grid::new(post.decimals).with_trailing_zeros(post.trailing_zeros);
    let k = post.unit_scale();
    let zq = |z: f64| round_i64(z * k * grid.scale());
    let mut at = grid.snap(t.start.scale(k));
    let mut feed: Option<Feed> = None;
    // The Toolpath starts at the retract height (the header's safe height
    // or above): the first move down is a rapid or a plunge.
    let mut cur_z = f64::NAN;
    let f_of = |f: Feed| match f {
        Feed::Cut => job.process.feed * k,
        Feed::Plunge => job.process.tool.plunge_feed * k,
    };
    let w = &mut c.w;
    for m in &t.moves {
        match m {
            MillMove::Note(text) => w.comment(text),
            MillMove::Rapid(p) => {
                let q = grid.snap(p.scale(k));
                w.block_of(|b| {
                    b.text(&post.rapid);
                    b.num("X", &grid, q.0);
                    b.num("Y", &grid, q.1);
                });
                at = q;
            }
            MillMove::RapidZ(z) => {
                cur_z = *z;
                w.block_of(|b| {
                    b.text(&post.rapid);
                    b.num("Z", &grid, zq(*z));
                })
            }
            MillMove::Plunge(z) => {
                let f = (feed != Some(Feed::Plunge)).then(|| grid.fmt_mm(f_of(Feed::Plunge)));
                feed = Some(Feed::Plunge);
                cur_z = *z;
                w.block_of(|b| {
                    b.text(&post.line);
                    b.num("Z", &grid, zq(*z));
                    if let Some(f) = &f {
                        b.text(&format!("F{f}"));
                    }
                });
            }
            MillMove::Cut { seg, z } => {
                // A ramp or a helix (Z changes along it) goes at the plunge feed.
                let want = if *z != cur_z { Feed::Plunge } else { Feed::Cut };
                cur_z = *z;
                let f = (feed != Some(want)).then(|| grid.fmt_mm(f_of(want)));
                feed = Some(want);
                at = cut(w, post, &grid, at, seg, k, zq(*z), f);
            }
        }
    }
    at
}

/// One cutting move (pieces of at most the post's sweep), Z to `z` along it.
#[allow(clippy::too_many_arguments)]
fn cut(
    w: &mut super::Writer,
    post: &Post,
    grid: &Grid,
    at: (i64, i64),
    seg: &Segment,
    k: f64,
    z: i64,
    f: Option<String>,
) -> (i64, i64) {
    let s = Segment {
        a: seg.a.scale(k),
        b: seg.b.scale(k),
        bulge: seg.bulge,
    };
    let end = grid.snap(s.b);
    let arc = s
        .arc_center()
        .filter(|_| post.arcs != ArcMode::Lines && post.arcs != ArcMode::R);
    let Some((centre, _)) = arc else {
        w.block_of(|b| {
            b.text(&post.line);
            b.num("X", grid, end.0);
            b.num("Y", grid, end.1);
            b.num("Z", grid, z);
            if let Some(f) = &f {
                b.text(&format!("F{f}"));
            }
        });
        return end;
    };
    // I and J from the start, on the grid (LinuxCNC's and GRBL's radius checks hold).
    let Some(ij) = grid.arc_center(at, end, centre) else {
        // No grid centre fits both ends (a tiny arc): a line, within a grid step.
        return cut(w, post, grid, at, &Segment::line(seg.a, seg.b), k, z, f);
    };
    let (i, j) = match post.arcs {
        ArcMode::IjAbsolute => (at.0 + ij.0, at.1 + ij.1),
        _ => ij,
    };
    let word = if s.bulge > 0.0 { &post.ccw } else { &post.cw };
    w.block_of(|b| {
        b.text(word);
        b.num("X", grid, end.0);
        b.num("Y", grid, end.1);
        b.num("Z", grid, z);
        b.num("I", grid, i);
        b.num("J", grid, j);
        if let Some(f) = &f {
            b.text(&format!("F{f}"));
        }
    });
    end
}
