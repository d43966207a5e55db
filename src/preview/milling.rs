//! A router's milling in the preview (issue 43 §6): drawn from the
//! [`Toolpath`](crate::mill::Toolpath)'s own moves, the ones
//! `gcode::emit_router` writes, so the picture is the program.
//!
//! | what | look |
//! |---|---|
//! | cleared area (the tool's disc swept along every cut below the top; a V-bit's width at the cut's depth) | fill `#eadcc6` |
//! | pocket and drilled shape as drawn | `#8a6d3b`, 1 px |
//! | tool-centre path at a depth | `#b7a6e0` (first depth) to `#2e1a87` (deepest), 3.5 to 1.5 px: a deeper pass is darker, narrower and over the ones above it |
//! | ramp, helix (Z going down along the path) | `#1a9e3a`, 1.5 px (an entry, as a lead-in) |
//! | plunge (straight down into material) | `#1a9e3a` dot (as a pierce) |
//! | rapid | the plan's rapid look |

use super::pen::{add_segment, draw_lines, path_of};
use super::raster::{Area, Raster};
use super::stroke::{stroke, Polylines};
use super::View;
use crate::geom::{BBox, Point, Segment};
use crate::mill::MillMove;
use crate::scene::Milling;

/// The cleared area's colour.
pub const CLEARED: u32 = 0xeadcc6;
/// The pockets' outlines as drawn.
pub const DRAWN: u32 = 0x8a6d3b;
/// Ramps and helices.
pub const ENTRY: u32 = 0x1a9e3a;
/// The first (shallowest) depth's path.
pub const SHALLOW: u32 = 0xb7a6e0;
/// The deepest depth's path.
pub const DEEP: u32 = 0x2e1a87;

/// Heights closer than this are one depth, mm.
const SAME_Z: f64 = 1e-6;

/// The colour of depth `i` of `n` (0 the shallowest): from [`SHALLOW`] to
/// [`DEEP`]; one depth alone is [`DEEP`].
pub fn depth_colour(i: usize, n: usize) -> u32 {
    let t = if n > 1 {
        i as f64 / (n - 1) as f64
    } else {
        1.0
    };
    let ch = |hex: u32, s: u32| f64::from((hex >> s) & 0xff);
    [16, 8, 0].iter().fold(0, |acc, &s| {
        let v = ch(SHALLOW, s) + (ch(DEEP, s) - ch(SHALLOW, s)) * t;
        acc | ((v.round() as u32) << s)
    })
}

/// The depths of the flat cuts below the stock's top, shallowest first.
pub fn depths(m: &Milling) -> Vec<f64> {
    let mut zs: Vec<f64> = Vec::new();
    let mut z = f64::INFINITY;
    for mv in &m.toolpath.moves {
        match mv {
            MillMove::Cut { z: h, .. } => {
                if (h - z).abs() <= SAME_Z
                    && *h < 0.0
                    && !zs.iter().any(|d| (d - h).abs() <= SAME_Z)
                {
                    zs.push(*h);
                }
                z = *h;
            }
            MillMove::RapidZ(h) | MillMove::Plunge(h) => z = *h,
            _ => {}
        }
    }
    zs.sort_by(|a, b| b.total_cmp(a));
    zs
}

/// Which depth of `zs` a flat cut at `z` is.
fn level(zs: &[f64], z: f64) -> usize {
    zs.iter()
        .position(|d| (d - z).abs() <= SAME_Z)
        .unwrap_or(zs.len().saturating_sub(1))
}

/// Draws `m` (cleared area, drawn outlines, paths per depth, entries);
/// its rapids go into `rapids`. Returns where the tool plunged into the
/// material (drawn by the caller with the pierces). `seen` culls.
pub(super) fn draw(
    raster: &mut Raster,
    area: &mut Area,
    view: &View,
    m: &Milling,
    k: f32,
    seen: &dyn Fn(&BBox) -> bool,
    rapids: &mut Polylines,
) -> Vec<Point> {
    let tools = tools(m);
    let r = tools.iter().map(|t| t.0).fold(0.0, f64::max) / 2.0;
    let zs = depths(m);
    // The cleared area per tool and width: a V-bit's per depth (the
    // cone's width there), the tool's diameter last (plunges; every cut of
    // an end mill).
    let widths: Vec<Vec<f64>> = (tools.iter())
        .map(|&(d, angle)| {
            (zs.iter())
                .map(|z| {
                    let cone = 2.0 * z.abs() * (angle.to_radians() / 2.0).tan();
                    if angle > 0.0 {
                        cone.min(d)
                    } else {
                        d
                    }
                })
                .chain([d])
                .collect()
        })
        .collect();
    let mut cleared_of: Vec<Vec<Polylines>> = (widths.iter())
        .map(|w| w.iter().map(|_| Polylines::default()).collect())
        .collect();
    let full = zs.len();
    // The tool cutting now (a change moves to the next).
    let mut tool = 0;
    let mut changes = 0;
    let mut per_depth: Vec<Polylines> = zs.iter().map(|_| Polylines::default()).collect();
    let mut entries = Polylines::default();
    let mut plunges: Vec<Point> = Vec::new();
    let mut at = m.toolpath.start;
    let mut z = f64::INFINITY;
    let line = |pb: &mut Polylines, s: &Segment| {
        let (x, y) = view.px(s.a);
        pb.move_to(x, y);
        add_segment(pb, view, s);
    };
    for mv in &m.toolpath.moves {
        let v = tools[tool].1 > 0.0;
        let cleared_at = &mut cleared_of[tool];
        match mv {
            MillMove::ToolChange(_) => {
                changes += 1;
                tool = (changes - 1).min(tools.len() - 1);
            }
            MillMove::Rapid(p) => {
                let s = Segment::line(at, *p);
                if seen(&s.bbox()) {
                    line(rapids, &s);
                }
                at = *p;
            }
            MillMove::RapidZ(h) => z = *h,
            MillMove::Plunge(h) => {
                if *h < 0.0 && plunges.last() != Some(&at) {
                    plunges.push(at);
                }
                if *h < 0.0 && seen(&BBox::at(at)) {
                    // The tool's disc where it went down (a drilled hole).
                    let (x, y) = view.px(at);
                    cleared_at[full].move_to(x, y);
                    cleared_at[full].line_to(x, y);
                }
                z = *h;
            }
            MillMove::Cut { seg, z: h } => {
                let mut bb = seg.bbox();
                bb.min = Point::new(bb.min.x - r, bb.min.y - r);
                bb.max = Point::new(bb.max.x + r, bb.max.y + r);
                if seen(&bb) {
                    if *h < 0.0 {
                        let i = if v && (h - z).abs() <= SAME_Z {
                            level(&zs, *h)
                        } else {
                            full
                        };
                        line(&mut cleared_at[i], seg);
                    }
                    if (h - z).abs() > SAME_Z {
                        line(&mut entries, seg);
                    } else if *h < 0.0 {
                        line(&mut per_depth[level(&zs, *h)], seg);
                    }
                }
                at = seg.b;
                z = *h;
            }
            MillMove::Note(_) => {}
        }
    }
    for (cleared, width) in cleared_of.iter().flatten().zip(widths.iter().flatten()) {
        let w = (width * view.scale) as f32;
        raster.paint(area, CLEARED, false, &|a| stroke(a, cleared, w.max(k)));
    }
    let mut drawn = Polylines::default();
    for segs in m.drawn {
        path_of(view, segs, true, &mut drawn);
    }
    draw_lines(raster, area, &drawn, DRAWN, k, None);
    let n = zs.len();
    for (i, lines) in per_depth.iter().enumerate() {
        let t = if n > 1 {
            i as f32 / (n - 1) as f32
        } else {
            1.0
        };
        draw_lines(
            raster,
            area,
            lines,
            depth_colour(i, n),
            (1.5 + 2.0 * (1.0 - t)) * k,
            None,
        );
    }
    draw_lines(raster, area, &entries, ENTRY, 1.5 * k, None);
    plunges
}

/// Diameter and V angle of each tool in the order they work: the
/// toolpath's changes' ([`MillMove::ToolChange`]), else the job's one.
fn tools(m: &Milling) -> Vec<(f64, f64)> {
    let changed: Vec<(f64, f64)> = (m.toolpath.moves.iter())
        .filter_map(|mv| match mv {
            MillMove::ToolChange(t) => Some((t.tool.diameter, t.tool.v_angle_deg)),
            _ => None,
        })
        .collect();
    if changed.is_empty() {
        vec![(m.tool_diameter, m.v_angle_deg)]
    } else {
        changed
    }
}

/// The box of what [`draw`] draws: every cut grown by the tool's radius
/// (the widest's).
pub(super) fn extent(m: &Milling) -> BBox {
    let r = tools(m).iter().map(|t| t.0).fold(0.0, f64::max) / 2.0;
    let mut bb = BBox::EMPTY;
    let mut at = m.toolpath.start;
    for mv in &m.toolpath.moves {
        match mv {
            MillMove::Cut { seg, .. } => {
                let b = seg.bbox();
                bb.add(Point::new(b.min.x - r, b.min.y - r));
                bb.add(Point::new(b.max.x + r, b.max.y + r));
                at = seg.b;
            }
            MillMove::Plunge(_) => {
                bb.add(Point::new(at.x - r, at.y - r));
                bb.add(Point::new(at.x + r, at.y + r));
            }
            MillMove::Rapid(p) => at = *p,
            _ => {}
        }
    }
    for segs in m.drawn {
        for s in segs {
            bb.union(&s.bbox());
        }
    }
    bb
}
