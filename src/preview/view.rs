//! What part of the drawing the pixels show: size, centre, scale, pixel
//! ratio, and the drawing-to-pixel transform.

use crate::geom::{BBox, Point};

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
    /// The drawing-space rectangle (mm) the image shows, grown by `margin`
    /// pixels: what lies wholly outside it cannot touch a pixel.
    pub(super) fn visible(&self, margin: f64) -> BBox {
        let half_w = (self.width as f64 / 2.0 + margin) / self.scale;
        let half_h = (self.height as f64 / 2.0 + margin) / self.scale;
        BBox {
            min: Point::new(self.center.x - half_w, self.center.y - half_h),
            max: Point::new(self.center.x + half_w, self.center.y + half_h),
        }
    }
    /// Pixel position of a drawing point (Y flipped).
    pub(super) fn px(&self, p: Point) -> (f32, f32) {
        let x = (p.x - self.center.x) * self.scale + self.width as f64 / 2.0;
        let y = self.height as f64 / 2.0 - (p.y - self.center.y) * self.scale;
        // Far-away points are clamped so the rasteriser never sees huge floats.
        (x.clamp(-1e6, 1e6) as f32, y.clamp(-1e6, 1e6) as f32)
    }
}
