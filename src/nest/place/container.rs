//! What the placer works with: a part one allowed way ([`Variant`]), the
//! box it must lie in ([`Container`]) and a copy where it was put
//! ([`Placed`]).

use crate::geom::{fmax, Point};
use crate::nest::collide::Shape;

/// A part turned and mirrored one allowed way, its collision shape at the
/// origin.
#[derive(Clone, Debug)]
pub struct Variant {
    /// Degrees, counter-clockwise.
    pub rotation: f64,
    /// Mirrored x → −x before turning.
    pub mirror: bool,
    /// The grown collision polygon, untranslated.
    pub shape: Shape,
    /// The room in each of its holes (shrunk by half the spacing),
    /// untranslated: where smaller parts may go (part-in-part).
    pub holes: Vec<Shape>,
}

/// Where grown shapes may lie: `x0 ≤ x ≤ x1`, `y0 ≤ y ≤ y1` (x1 infinite in strip mode).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Container {
    /// Left.
    pub x0: f64,
    /// Bottom.
    pub y0: f64,
    /// Right (∞ for a strip).
    pub x1: f64,
    /// Top.
    pub y1: f64,
}

impl Container {
    /// No bounds.
    pub const EVERYWHERE: Container = Container {
        x0: f64::NEG_INFINITY,
        y0: f64::NEG_INFINITY,
        x1: f64::INFINITY,
        y1: f64::INFINITY,
    };

    /// True when a variant's box fits at all.
    pub fn fits(&self, v: &Variant) -> bool {
        let b = v.shape.bbox();
        b.max.x - b.min.x <= self.x1 - self.x0 && b.max.y - b.min.y <= self.y1 - self.y0
    }
}

/// The translations keeping a shape with box `b` inside the room: (least,
/// most) along x and y (most = least when it does not fit).
pub(crate) fn range_of(room: &Container, b: &crate::geom::BBox) -> (Point, Point) {
    let lo = Point::new(room.x0 - b.min.x, room.y0 - b.min.y);
    let hi = Point::new(fmax(room.x1 - b.max.x, lo.x), fmax(room.y1 - b.max.y, lo.y));
    (lo, hi)
}

/// One copy placed in a container.
#[derive(Clone, Debug)]
pub struct Placed {
    /// Which part (index into the items).
    pub item: usize,
    /// Which of its variants.
    pub variant: usize,
    /// Translation.
    pub t: Point,
    /// The grown shape where it is.
    pub shape: Shape,
}
