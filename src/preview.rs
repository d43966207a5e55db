//! Preview: [`Output`] + [`View`] → RGBA pixels (tiny-skia), the same pixels
//! native, in Node and in the browser.
//!
//! What is drawn is the job's own data: part areas and contour outlines from
//! the contours, and the cutting program from [`CutPlan::moves`] — the very
//! moves the G-code is written from —, so the preview shows the program.
//!
//! | what | look |
//! |---|---|
//! | part area (even-odd: holes empty, islands filled) | fill `#cfe3f7` |
//! | outer contour | `#1f5fa8`, 2 px |
//! | hole | `#e07b00`, 2 px |
//! | open contour (not cut) | `#f2c200`, 3 px |
//! | kerf path (cutting moves on contours) | `#d62828`, 2 px, dashed 6/4 |
//! | lead-in, lead-out | `#1a9e3a`, 1.5 px |
//! | chain link / bridge (torch on through scrap) | `#8b1a1a`, 2 px |
//! | repeated edge (tool down, already cut) | `#7048e8`, 2.5 px, dashed 2/3 |
//! | rapid | `#7a7a7a`, 1 px, dashed 3/3 |
//! | pierce point | `#1a9e3a` dot, r 4 px |
//! | invalid vertex | `#b000b0` dot, r 5 px |
//! | POINT (spot) | `#6a3d9a` cross, 5 px |
//! | healing fix (duplicate, overlap, gap, zero length) | `#00a0b0` diamond, 4 px |
//!
//! Sizes are CSS pixels, multiplied by [`View::pixel_ratio`].
//! The background is opaque white, so premultiplied RGBA equals the straight
//! RGBA that `ImageData` wants.

use tiny_skia::{
    Color, FillRule, LineCap, Paint, PathBuilder, Pixmap, Stroke, StrokeDash, Transform,
};

use crate::contour::ContourKind;
use crate::geom::{BBox, Point, Segment};
use crate::plan::{Move, Role};
use crate::Output;

/// What part of the drawing the pixels show.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct View {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// Drawing point (mm) at the centre of the image.
    pub center: Point,
    /// Pixels per mm.
    pub scale: f64,
    /// Device pixels per CSS pixel: line widths and dot sizes are multiplied
    /// by it, so a high-density screen shows them at the same size.
    pub pixel_ratio: f32,
}

/// Largest image side rendered, in pixels.
pub const MAX_SIDE: u32 = 8192;

impl View {
    /// A view, if the size is 1..=[`MAX_SIDE`] and the scale positive and finite.
    pub fn new(width: u32, height: u32, center: Point, scale: f64) -> Option<View> {
        let ok = (1..=MAX_SIDE).contains(&width)
            && (1..=MAX_SIDE).contains(&height)
            && center.is_finite()
            && scale.is_finite()
            && scale > 0.0;
        ok.then_some(View {
            width,
            height,
            center,
            scale,
            pixel_ratio: 1.0,
        })
    }
    /// The same view for a screen with `ratio` device pixels per CSS pixel (clamped to 0.5..=4).
    pub fn with_pixel_ratio(mut self, ratio: f64) -> View {
        self.pixel_ratio = if ratio.is_finite() {
            ratio.clamp(0.5, 4.0) as f32
        } else {
            1.0
        };
        self
    }
    /// The view that shows `bbox` whole, with a 5 % margin.
    pub fn fit(bbox: &BBox, width: u32, height: u32) -> Option<View> {
        if bbox.is_empty() {
            return View::new(width, height, Point::default(), 1.0);
        }
        let w = (bbox.max.x - bbox.min.x).max(1e-6);
        let h = (bbox.max.y - bbox.min.y).max(1e-6);
        let scale = (width as f64 / w).min(height as f64 / h) * 0.95;
        let c = Point::new(
            (bbox.min.x + bbox.max.x) / 2.0,
            (bbox.min.y + bbox.max.y) / 2.0,
        );
        View::new(width, height, c, scale)
    }
    /// Pixel position of a drawing point (Y flipped).
    fn px(&self, p: Point) -> (f32, f32) {
        let x = (p.x - self.center.x) * self.scale + self.width as f64 / 2.0;
        let y = self.height as f64 / 2.0 - (p.y - self.center.y) * self.scale;
        // Far-away points are clamped so the rasteriser never sees huge floats.
        (x.clamp(-1e6, 1e6) as f32, y.clamp(-1e6, 1e6) as f32)
    }
}

fn rgb(hex: u32) -> Color {
    Color::from_rgba8((hex >> 16) as u8, (hex >> 8) as u8, hex as u8, 255)
}

fn paint(hex: u32) -> Paint<'static> {
    let mut p = Paint::default();
    p.set_color(rgb(hex));
    p.anti_alias = true;
    p
}

/// Adds a segment to the path builder, arcs flattened to a quarter pixel.
fn add_segment(pb: &mut PathBuilder, view: &View, s: &Segment) {
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

fn path_of(view: &View, segs: &[Segment], close: bool, pb: &mut PathBuilder) {
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

fn stroke(width: f32, dash: Option<[f32; 2]>, k: f32) -> Stroke {
    Stroke {
        width: width * k,
        line_cap: LineCap::Round,
        dash: dash.and_then(|d| StrokeDash::new(vec![d[0] * k, d[1] * k], 0.0)),
        ..Stroke::default()
    }
}

fn dot(pixmap: &mut Pixmap, view: &View, p: Point, r: f32, hex: u32) {
    let (x, y) = view.px(p);
    if let Some(c) = PathBuilder::from_circle(x, y, r) {
        pixmap.fill_path(
            &c,
            &paint(hex),
            FillRule::Winding,
            Transform::identity(),
            None,
        );
    }
}

fn cross(pixmap: &mut Pixmap, view: &View, p: Point, r: f32, hex: u32) {
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

fn diamond(pixmap: &mut Pixmap, view: &View, p: Point, r: f32, hex: u32) {
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

/// Renders the job; None when the view is invalid.
pub fn render(out: &Output, view: &View) -> Option<Pixmap> {
    let k = view.pixel_ratio;
    let view =
        View::new(view.width, view.height, view.center, view.scale)?.with_pixel_ratio(k as f64);
    let mut pixmap = Pixmap::new(view.width, view.height)?;
    pixmap.fill(Color::WHITE);
    let id = Transform::identity();
    let contours = &out.contours.contours;

    // Part areas: every closed contour in one even-odd path.
    let mut pb = PathBuilder::new();
    for c in contours.iter().filter(|c| c.is_closed()) {
        path_of(&view, &c.segments, true, &mut pb);
    }
    if let Some(p) = pb.finish() {
        pixmap.fill_path(&p, &paint(0xcfe3f7), FillRule::EvenOdd, id, None);
    }
    for (kind, hex, width) in [
        (ContourKind::Outer, 0x1f5fa8, 2.0),
        (ContourKind::Hole, 0xe07b00, 2.0),
        (ContourKind::Open, 0xf2c200, 3.0),
    ] {
        let mut pb = PathBuilder::new();
        for c in contours.iter().filter(|c| c.kind == kind) {
            path_of(&view, &c.segments, kind != ContourKind::Open, &mut pb);
        }
        if let Some(p) = pb.finish() {
            pixmap.stroke_path(&p, &paint(hex), &stroke(width, None, k), id, None);
        }
    }

    // The program, from the plan's moves: one path per look.
    let mut rapids = PathBuilder::new();
    // Contour, lead (in and out), link, repeat.
    let mut feeds: [PathBuilder; 4] = Default::default();
    let mut pierces = Vec::new();
    let mut at = out.plan.origin;
    for m in out.plan.moves() {
        match m {
            Move::Rapid(p) => {
                let (x0, y0) = view.px(at);
                let (x1, y1) = view.px(p);
                rapids.move_to(x0, y0);
                rapids.line_to(x1, y1);
                at = p;
            }
            Move::Pierce(_) => pierces.push(at),
            Move::Feed(s) => {
                let pb = &mut feeds[match s.role {
                    Role::Contour => 0,
                    Role::LeadIn | Role::LeadOut => 1,
                    Role::Link => 2,
                    Role::Repeat => 3,
                }];
                let (x, y) = view.px(s.segment.a);
                pb.move_to(x, y);
                add_segment(pb, &view, &s.segment);
                at = s.segment.b;
            }
            Move::TorchOff | Move::Spot(_) => {}
        }
    }
    if let Some(p) = rapids.finish() {
        pixmap.stroke_path(
            &p,
            &paint(0x7a7a7a),
            &stroke(1.0, Some([3.0, 3.0]), k),
            id,
            None,
        );
    }
    let looks: [(u32, f32, Option<[f32; 2]>); 4] = [
        (0xd62828, 2.0, Some([6.0, 4.0])),
        (0x1a9e3a, 1.5, None),
        (0x8b1a1a, 2.0, None),
        (0x7048e8, 2.5, Some([2.0, 3.0])),
    ];
    for (pb, (hex, width, dash)) in feeds.into_iter().zip(looks) {
        if let Some(p) = pb.finish() {
            pixmap.stroke_path(&p, &paint(hex), &stroke(width, dash, k), id, None);
        }
    }
    for p in pierces {
        dot(&mut pixmap, &view, p, 4.0 * k, 0x1a9e3a);
    }
    for s in &out.drawing.spots {
        cross(&mut pixmap, &view, s.at, 5.0 * k, 0x6a3d9a);
    }
    for (_, p) in &out.contours.healing.locations {
        diamond(&mut pixmap, &view, *p, 4.0 * k, 0x00a0b0);
    }
    for &p in &out.kerf.invalid_vertices {
        dot(&mut pixmap, &view, p, 5.0 * k, 0xb000b0);
    }
    Some(pixmap)
}

/// Box holding everything the preview draws (contours, kerf paths, origin).
pub fn extent(out: &Output) -> BBox {
    let mut bb = BBox::EMPTY;
    for c in &out.contours.contours {
        bb.union(&c.bbox);
    }
    for c in &out.plan.cuts {
        for s in &c.steps {
            bb.union(&s.segment.bbox());
        }
    }
    bb
}
