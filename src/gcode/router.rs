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
use super::post::{ArcMode, Post};
use super::router_time::is_router;
use super::{JobInfo, PostError};
use crate::geom::Segment;
use crate::mill::{MillMove, Toolpath};
use crate::plan::CutPlan;
use crate::text;

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
    if post.incremental && !milling.moves.is_empty() {
        return Err(PostError {
            field: "incremental".into(),
            reason: text!("G91 is written for profiles and cuts; pockets, engravings and drilling are written in G90 only: turn 'incremental' off for this job";
                          "G91 é escrito para perfis e cortes; bolsões, gravações e furações só em G90: desligue 'incremental' neste trabalho"),
        });
    }
    let mut c = Cutter::with_milling(plan, Some(milling), post, job);
    let end = write(&mut c, milling, job);
    c.st = State::at(end);
    c.w.reset_feed();
    for i in 0..plan.cuts.len() {
        c.cut(i);
    }
    Ok(c.finish())
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
