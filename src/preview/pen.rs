//! Pens: colours, strokes, and the marks the preview draws (paths of
//! lines and arcs, dots, crosses, diamonds), in a [`View`]'s pixels.

use tiny_skia::{
    Color, FillRule, LineCap, Paint, PathBuilder, Pixmap, Stroke, StrokeDash, Transform,
};

use super::View;
use crate::geom::{Point, Segment};

pub(super) fn rgb(hex: u32) -> Color {
    Color::from_rgba8((hex >> 16) as u8, (hex >> 8) as u8, hex as u8, 255)
}

pub(super) fn paint(hex: u32) -> Paint<'static> {
    let mut p = Paint::default();
    p.set_color(rgb(hex));
    p.anti_alias = true;
    p
}

/// Where flattened outlines go (pixels): a tiny-skia path to stroke or
/// fill, or the overview's own lines and areas ([`super::raster`]).
pub(super) trait Sink {
    fn move_to(&mut self, x: f32, y: f32);
    fn line_to(&mut self, x: f32, y: f32);
    fn close(&mut self);
}

impl Sink for PathBuilder {
    fn move_to(&mut self, x: f32, y: f32) {
        PathBuilder::move_to(self, x, y);
    }
    fn line_to(&mut self, x: f32, y: f32) {
        PathBuilder::line_to(self, x, y);
    }
    fn close(&mut self) {
        PathBuilder::close(self);
    }
}

/// Adds a segment to the path, arcs flattened to a quarter pixel.
pub(super) fn add_segment(pb: &mut dyn Sink, view: &View, s: &Segment) {
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

pub(super) fn path_of(view: &View, segs: &[Segment], close: bool, pb: &mut dyn Sink) {
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

pub(super) fn stroke(width: f32, dash: Option<[f32; 2]>, k: f32) -> Stroke {
    Stroke {
        width: width * k,
        line_cap: LineCap::Round,
        dash: dash.and_then(|d| StrokeDash::new(vec![d[0] * k, d[1] * k], 0.0)),
        ..Stroke::default()
    }
}

/// Filled dots of one colour at `points`, in one path: one fill for
/// thousands of pierces instead of thousands of fills (25k dots took 0.7 s);
/// in an overview (`own`) straight into the pixels (125k dots took 0.6 s as
/// one path).
pub(super) fn dots(
    pixmap: &mut Pixmap,
    view: &View,
    points: &[Point],
    r: f32,
    hex: u32,
    own: bool,
) {
    if own {
        let px: Vec<(f32, f32)> = points.iter().map(|p| view.px(*p)).collect();
        return super::Raster::new(pixmap).discs(&px, r, hex);
    }
    let mut pb = PathBuilder::new();
    for &p in points {
        let (x, y) = view.px(p);
        pb.push_circle(x, y, r);
    }
    if let Some(path) = pb.finish() {
        pixmap.fill_path(
            &path,
            &paint(hex),
            FillRule::Winding,
            Transform::identity(),
            None,
        );
    }
}

pub(super) fn cross(pixmap: &mut Pixmap, view: &View, p: Point, r: f32, hex: u32) {
    let (x, y) = view.px(p);
    let mut pb = PathBuilder::new();
    pb.move_to(x - r, y - r);
    pb.line_to(x + r, y + r);
    pb.move_to(x - r, y + r);
    pb.line_to(x + r, y - r);
    if let Some(path) = pb.finish() {
        pixmap.stroke_path(
            &path,
            &paint(hex),
            &stroke(1.5 * r / 5.0, None, 1.0),
            Transform::identity(),
            None,
        );
    }
}

pub(super) fn diamond(pixmap: &mut Pixmap, view: &View, p: Point, r: f32, hex: u32) {
    let (x, y) = view.px(p);
    let mut pb = PathBuilder::new();
    pb.move_to(x, y - r);
    pb.line_to(x + r, y);
    pb.line_to(x, y + r);
    pb.line_to(x - r, y);
    pb.close();
    if let Some(path) = pb.finish() {
        pixmap.fill_path(
            &path,
            &paint(hex),
            FillRule::Winding,
            Transform::identity(),
            None,
        );
    }
}
