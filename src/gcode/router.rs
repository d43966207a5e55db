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
    let changes = (milling.moves.iter())
        .filter(|m| matches!(m, MillMove::ToolChange(_)))
        .count();
    if changes > 1 && post.tool_change.is_empty() {
        let name = &post.name;
        return Err(PostError {
            field: "tool_change".into(),
            reason: text!("the job mills with {changes} tools, and post '{name}' has no tool change (its 'tool_change' template): one program per tool, or a post with one";
                          "o trabalho fresa com {changes} ferramentas, e o pós-processador '{name}' não tem troca de ferramenta (o modelo 'tool_change'): um programa por ferramenta, ou um pós com ela"),
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

/// Where the tool is, on the grid: what a G91 block's increments are
/// taken from (the rounded target less the rounded position, exact
/// integers: no rounding accumulates over the moves, Z included).
#[derive(Clone, Copy)]
struct At {
    xy: (i64, i64),
    z: i64,
    /// Blocks in G91.
    rel: bool,
}

impl At {
    fn x(&self, v: i64) -> i64 {
        if self.rel {
            v - self.xy.0
        } else {
            v
        }
    }
    fn y(&self, v: i64) -> i64 {
        if self.rel {
            v - self.xy.1
        } else {
            v
        }
    }
    fn z(&self, v: i64) -> i64 {
        if self.rel {
            v - self.z
        } else {
            v
        }
    }
}

/// The toolpath's blocks; where the tool ends, on the grid.
fn write(c: &mut Cutter, t: &Toolpath, job: &JobInfo) -> (i64, i64) {
    let post = c.post;
    let grid = Grid::new(post.decimals).with_trailing_zeros(post.trailing_zeros);
    let k = post.unit_scale();
    let zq = |z: f64| round_i64(z * k * grid.scale());
    // The Toolpath starts at the retract height (where the header's
    // `pass_retract` left the tool): the first move down is a rapid or a
    // plunge.
    let mut at = At {
        xy: grid.snap(t.start.scale(k)),
        z: zq(post.retract_height),
        rel: post.incremental,
    };
    let mut feed: Option<Feed> = None;
    let mut cur_z = f64::NAN;
    // The tool cutting now: the job's, or the last change's.
    let mut speeds = (job.process.feed, job.process.tool.plunge_feed);
    let f_of = |f: Feed, (cut, plunge): (f64, f64)| match f {
        Feed::Cut => cut * k,
        Feed::Plunge => plunge * k,
    };
    let w = &mut c.w;
    for (i, m) in t.moves.iter().enumerate() {
        if let MillMove::ToolChange(tc) = m {
            speeds = (tc.feed, tc.tool.plunge_feed);
            if i > 0 {
                // The header changed to the first (`Cutter::with_milling`).
                tool_change(w, tc);
                at.z = zq(post.retract_height);
                feed = None;
                cur_z = f64::NAN;
            }
            continue;
        }
        // G91 is set by the first motion block that needs it (a template
        // with an axis word sets G90 again: `Writer::templates`).
        let to_g91 = at.rel && !w.g91 && !matches!(m, MillMove::Note(_));
        w.g91 |= to_g91;
        let g91 = |b: &mut super::writer::Words| {
            if to_g91 {
                b.text("G91");
            }
        };
        match m {
            MillMove::Note(text) => w.comment(text),
            MillMove::ToolChange(_) => {}
            MillMove::Rapid(p) => {
                let q = grid.snap(p.scale(k));
                w.block_of(|b| {
                    g91(b);
                    b.text(&post.rapid);
                    b.num("X", &grid, at.x(q.0));
                    b.num("Y", &grid, at.y(q.1));
                });
                at.xy = q;
            }
            MillMove::RapidZ(z) => {
                cur_z = *z;
                let q = zq(*z);
                w.block_of(|b| {
                    g91(b);
                    b.text(&post.rapid);
                    b.num("Z", &grid, at.z(q));
                });
                at.z = q;
            }
            MillMove::Plunge(z) => {
                let f = (feed != Some(Feed::Plunge)).then(|| grid.fmt_mm(f_of(Feed::Plunge, speeds)));
                feed = Some(Feed::Plunge);
                cur_z = *z;
                let q = zq(*z);
                w.block_of(|b| {
                    g91(b);
                    b.text(&post.line);
                    b.num("Z", &grid, at.z(q));
                    if let Some(f) = &f {
                        b.text(&format!("F{f}"));
                    }
                });
                at.z = q;
            }
            MillMove::Cut { seg, z } => {
                // A ramp or a helix (Z changes along it) goes at the plunge feed.
                let want = if *z != cur_z { Feed::Plunge } else { Feed::Cut };
                cur_z = *z;
                let f = (feed != Some(want)).then(|| grid.fmt_mm(f_of(want, speeds)));
                feed = Some(want);
                let s = Segment {
                    a: seg.a.scale(k),
                    b: seg.b.scale(k),
                    bulge: seg.bulge,
                };
                at = cut(w, post, &grid, at, &s, zq(*z), f, to_g91);
            }
        }
    }
    at.xy
}

/// The change to `tc` (issue 43 §1): a comment naming the tool, the
/// post's `tool_change` with the new tool's `{tool_number}`,
/// `{spindle_rpm}` and `{plunge_feed}`, then `pass_retract` (the tool at
/// the retract height, where its moves start).
fn tool_change(w: &mut super::Writer, tc: &crate::process::MillTool) {
    w.tool_comment("tool change", &tc.tool);
    w.set_tool(tc);
    let post = w.post;
    w.templates(&post.tool_change);
    w.templates(&post.pass_retract);
}

/// One cutting move `s` (in program units), Z to `z` along it; where the
/// tool ends.
#[allow(clippy::too_many_arguments)]
fn cut(
    w: &mut super::Writer,
    post: &Post,
    grid: &Grid,
    at: At,
    s: &Segment,
    z: i64,
    f: Option<String>,
    to_g91: bool,
) -> At {
    let end = grid.snap(s.b);
    let done = At { xy: end, z, ..at };
    let arc = s
        .arc_center()
        .filter(|_| post.arcs != ArcMode::Lines && post.arcs != ArcMode::R);
    // I and J from the start, on the grid (LinuxCNC's and GRBL's radius
    // checks hold); none fits both ends of a tiny arc: a line, within a
    // grid step.
    let ij = arc.and_then(|(centre, _)| grid.arc_center(at.xy, end, centre));
    w.block_of(|b| {
        if to_g91 {
            b.text("G91");
        }
        let word = match ij {
            None => &post.line,
            Some(_) if s.bulge > 0.0 => &post.ccw,
            Some(_) => &post.cw,
        };
        b.text(word);
        b.num("X", grid, at.x(end.0));
        b.num("Y", grid, at.y(end.1));
        b.num("Z", grid, at.z(z));
        if let Some(ij) = ij {
            let (i, j) = match post.arcs {
                ArcMode::IjAbsolute => (at.xy.0 + ij.0, at.xy.1 + ij.1),
                _ => ij,
            };
            b.num("I", grid, i);
            b.num("J", grid, j);
        }
        if let Some(f) = &f {
            b.text(&format!("F{f}"));
        }
    });
    done
}
