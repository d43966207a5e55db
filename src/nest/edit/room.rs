//! Where copies may lie on one sheet, for the hand-edit checks of
//! [`super::Checker`]: the box (or a remnant's outline) less the margin,
//! the no-go zones grown by it, for grown shapes and for the parts.

use crate::geom::path_bbox;
use crate::nest::collide::Shape;
use crate::nest::shape::{collision_polygon, room_polygon};
use crate::nest::{NestJob, Sheets};

/// Where copies may lie: grown shapes in `grown`, parts in `raw`.
pub(in crate::nest) struct Room {
    /// x0, y0, x1, y1 of the box grown shapes may take (x1 ∞ for a strip).
    pub(in crate::nest) bounds: [f64; 4],
    /// An irregular sheet's outline shrunk by the margin (less half the spacing).
    pub(in crate::nest) bound: Option<Shape>,
    /// Its no-go zones grown likewise.
    pub(in crate::nest) obstacles: Vec<Shape>,
    /// The same for the parts themselves (grown by nothing).
    pub(super) raw_bounds: [f64; 4],
    pub(super) raw_bound: Option<Shape>,
    pub(super) raw_obstacles: Vec<Shape>,
}

/// True when `s`'s box lies in `b` = [x0, y0, x1, y1], `eps` either way.
pub(super) fn inside_box(s: &Shape, b: [f64; 4], eps: f64) -> bool {
    let bb = s.bbox();
    bb.min.x >= b[0] - eps
        && bb.min.y >= b[1] - eps
        && bb.max.x <= b[2] + eps
        && bb.max.y <= b[3] + eps
}

/// Where grown shapes and parts may lie on one sheet of `sheets`.
pub(super) fn room(job: &NestJob, sheets: &Sheets) -> Room {
    let s = &job.settings;
    let (grow, tol) = (s.spacing / 2.0, s.tolerance);
    let (m, inf) = (s.margin, f64::INFINITY);
    match sheets {
        Sheets::Mixed(_) => room(job, &sheets.sheet(0)),
        Sheets::Rect { width, height, .. } => Room {
            bounds: [m - grow, m - grow, width - m + grow, height - m + grow],
            raw_bounds: [0.0, 0.0, *width, *height],
            bound: None,
            obstacles: Vec::new(),
            raw_bound: None,
            raw_obstacles: Vec::new(),
        },
        Sheets::Strip { height } => Room {
            bounds: [m - grow, m - grow, inf, height - m + grow],
            raw_bounds: [0.0, 0.0, inf, *height],
            bound: None,
            obstacles: Vec::new(),
            raw_bound: None,
            raw_obstacles: Vec::new(),
        },
        Sheets::Remnant { outline, no_go } => {
            let shapes = |d: f64| -> Vec<Shape> {
                no_go
                    .iter()
                    .filter_map(|z| collision_polygon(z, d, tol))
                    .map(Shape::new)
                    .collect()
            };
            let bound = room_polygon(outline, m - grow, tol).map(Shape::new);
            let raw_bound = room_polygon(outline, 0.0, tol).map(Shape::new);
            let b = path_bbox(outline);
            Room {
                bounds: bound.as_ref().map_or([inf, inf, -inf, -inf], |s| {
                    [
                        s.bbox().min.x,
                        s.bbox().min.y,
                        s.bbox().max.x,
                        s.bbox().max.y,
                    ]
                }),
                raw_bounds: [b.min.x, b.min.y, b.max.x, b.max.y],
                bound,
                obstacles: shapes(m - grow),
                raw_bound,
                raw_obstacles: shapes(0.0),
            }
        }
    }
}
