//! Pens: the marks the preview draws (paths of lines and arcs, strokes,
//! dots, crosses, diamonds), in a [`View`]'s pixels, by the preview's own
//! raster ([`super::raster`], [`super::stroke`]).

use super::raster::{Area, Raster};
use super::stroke::{stroke, Polylines};
use super::View;
use crate::geom::{Point, Segment};

/// Adds a segment to the path, arcs flattened to a quarter pixel.
pub(super) fn add_segment(pb: &mut Polylines, view: &View, s: &Segment) {
    match s.arc_center() {
        Some((_, r)) => {
            let r_px = r * view.scale;
            let step = if r_px > 0.25 {
                2.0 * (1.0 - 0.25 / r_px).acos()
            } else {
                std::f64::consts::PI
            };
            let n = ((s.sweep().abs() / step).ceil() as usize).clamp(1, 256);
            for k in 1..=n {
                let (x, y) = view.px(s.point_at(k as f64 / n as f64));
                pb.line_to(x, y);
            }
        }
        None => {
            let (x, y) = view.px(s.b);
            pb.line_to(x, y);
        }
    }
}

pub(super) fn path_of(view: &View, segs: &[Segment], close: bool, pb: &mut Polylines) {
    let Some(first) = segs.first() else { return };
    let (x, y) = view.px(first.a);
    pb.move_to(x, y);
    for s in segs {
        add_segment(pb, view, s);
    }
    if close {
        pb.close();
    }
}

/// The polylines in `hex`, `width` device pixels wide, dashed `[on, off]`
/// when asked: 1 px and under, Wu's lines; wider, a stroke with round
/// caps and joins.
pub(super) fn draw_lines(
    raster: &mut Raster,
    area: &mut Area,
    lines: &Polylines,
    hex: u32,
    width: f32,
    dash: Option<[f32; 2]>,
) {
    let dashed;
    let lines = match dash {
        Some([on, off]) if on > 0.0 && off > 0.0 => {
            dashed = lines.dashed(on, off);
            &dashed
        }
        _ => lines,
    };
    if width <= 1.0 {
        for pl in lines.each() {
            for w in pl.windows(2) {
                raster.line(w[0], w[1], hex);
            }
        }
    } else {
        raster.paint(area, hex, false, &|a| stroke(a, lines, width));
    }
}

/// Filled dots of one colour at `points`.
pub(super) fn dots(raster: &mut Raster, view: &View, points: &[Point], r: f32, hex: u32) {
    let px: Vec<(f32, f32)> = points.iter().map(|p| view.px(*p)).collect();
    raster.discs(&px, r, hex);
}

pub(super) fn cross(raster: &mut Raster, area: &mut Area, view: &View, p: Point, r: f32, hex: u32) {
    let (x, y) = view.px(p);
    let mut pb = Polylines::default();
    pb.move_to(x - r, y - r);
    pb.line_to(x + r, y + r);
    pb.move_to(x - r, y + r);
    pb.line_to(x + r, y - r);
    draw_lines(raster, area, &pb, hex, 1.5 * r / 5.0, None);
}

pub(super) fn diamond(
    raster: &mut Raster,
    area: &mut Area,
    view: &View,
    p: Point,
    r: f32,
    hex: u32,
) {
    let (x, y) = view.px(p);
    raster.paint(area, hex, false, &|a| {
        a.polygon(&[(x, y - r), (x + r, y), (x, y + r), (x - r, y)])
    });
}
