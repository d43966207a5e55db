//! Program origin: which point of the drawing becomes the program's (0, 0).
//!
//! A drawing's own zero is wherever its author's CAD put it: real files
//! place parts 13 m from it, or around it (a panel drawn centred on zero
//! cuts at negative X and Y, and the first rapid from (0, 0) starts inside
//! the part). The machine's zero is a corner of the sheet. So the drawing
//! is moved, once, right after reading: every later stage (contours, kerf,
//! plan, program, preview) works in program coordinates, and what is
//! previewed is what is cut.
//!
//! [`ProgramOrigin::Auto`] (the default) keeps the drawing's zero when the
//! parts lie near it in the positive quadrant, and otherwise takes the
//! lower-left corner of the parts, with an `origin-moved` note.

use serde::Serialize;

use crate::dxf::Drawing;
use crate::geom::{BBox, Point};
use crate::text;
use crate::warning::{dec, Warning};

/// Parts whose box starts farther than this from the drawing's zero (mm)
/// are "far away": no table's zero is meant to be that far from the work.
pub const FAR_FROM_ZERO_MM: f64 = 1000.0;

/// Where the program's zero is, as the user chose.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ProgramOrigin {
    /// The drawing's zero, unless the parts reach below it or lie far from
    /// it (more than [`FAR_FROM_ZERO_MM`]): then their lower-left corner.
    Auto,
    /// The drawing's own zero.
    Drawing,
    /// The lower-left corner of the parts' box.
    LowerLeft,
    /// A point picked in the drawing (drawing coordinates, mm).
    Point(Point),
}

impl ProgramOrigin {
    /// "auto", "drawing", "lower-left", or "X,Y" for a point.
    pub fn from_name(name: &str) -> Option<ProgramOrigin> {
        match name.trim() {
            "auto" => Some(ProgramOrigin::Auto),
            "drawing" => Some(ProgramOrigin::Drawing),
            "lower-left" => Some(ProgramOrigin::LowerLeft),
            other => {
                let (x, y) = other.split_once(',')?;
                let p = Point::new(x.trim().parse().ok()?, y.trim().parse().ok()?);
                (p.x.is_finite() && p.y.is_finite()).then_some(ProgramOrigin::Point(p))
            }
        }
    }
}

/// The origin as applied to one drawing (for the report and the page).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Origin {
    /// "drawing", "lower-left" or "point".
    pub mode: &'static str,
    /// True when [`ProgramOrigin::Auto`] chose the mode.
    pub auto: bool,
    /// The drawing point (drawing coordinates, mm) that is the program's (0, 0).
    pub at: [f64; 2],
}

/// Moves `d` so the chosen origin is at (0, 0); returns what was done.
/// The move is exact for the drawing's own zero (nothing moves).
pub fn apply(d: &mut Drawing, choice: ProgramOrigin, tolerance: f64) -> Origin {
    let bb = d.extent;
    let (mode, auto, at) = match choice {
        ProgramOrigin::Drawing => ("drawing", false, Point::new(0.0, 0.0)),
        ProgramOrigin::LowerLeft if !bb.is_empty() => ("lower-left", false, bb.min),
        ProgramOrigin::LowerLeft => ("drawing", false, Point::new(0.0, 0.0)),
        ProgramOrigin::Point(p) => ("point", false, p),
        ProgramOrigin::Auto => match far_reason(&bb, tolerance) {
            Some(why) => {
                let t = why.text(&bb);
                d.warnings.push(Warning::new(
                    "origin-moved",
                    text!("program zero set at the lower-left corner of the parts, ({:.2}, {:.2}) in the drawing: {} (choose the program origin to change it)", bb.min.x, bb.min.y, t.en;
                          "zero do programa no canto inferior esquerdo das peças, ({:.2}; {:.2}) no desenho: {} (escolha a origem do programa para mudar)", dec(bb.min.x), dec(bb.min.y), t.pt),
                ));
                ("lower-left", true, bb.min)
            }
            None => ("drawing", true, Point::new(0.0, 0.0)),
        },
    };
    if at.x != 0.0 || at.y != 0.0 {
        translate(d, Point::new(-at.x, -at.y));
    }
    Origin {
        mode,
        auto,
        at: [at.x + 0.0, at.y + 0.0],
    }
}

/// Why the drawing's zero is no good as the program's.
enum Far {
    /// Parts reach below zero in X or Y.
    Negative,
    /// The parts start this far from zero, mm.
    Distant(f64),
}

impl Far {
    fn text(&self, bb: &BBox) -> crate::warning::Text {
        match self {
            Far::Negative => {
                let (x, y) = (bb.min.x, bb.min.y);
                text!("the parts reach below the drawing's zero (to X {x:.2}, Y {y:.2})";
                      "as peças passam abaixo do zero do desenho (até X {:.2}, Y {:.2})", dec(x), dec(y))
            }
            Far::Distant(d) => {
                let m = d / 1000.0;
                text!("the parts start {m:.2} m from the drawing's zero";
                      "as peças começam a {:.2} m do zero do desenho", dec(m))
            }
        }
    }
}

fn far_reason(bb: &BBox, tolerance: f64) -> Option<Far> {
    if bb.is_empty() {
        return None;
    }
    if bb.min.x < -tolerance || bb.min.y < -tolerance {
        return Some(Far::Negative);
    }
    let distance = bb.min.x.hypot(bb.min.y);
    (distance > FAR_FROM_ZERO_MM).then_some(Far::Distant(distance))
}

/// Moves every coordinate of the drawing by `v`.
fn translate(d: &mut Drawing, v: Point) {
    for e in &mut d.entities {
        for s in &mut e.segments {
            s.a = s.a.add(v);
            s.b = s.b.add(v);
        }
    }
    for s in &mut d.spots {
        s.at = s.at.add(v);
    }
    for w in &mut d.warnings {
        if let Some(p) = &mut w.at {
            *p = p.add(v);
        }
        for p in &mut w.places {
            *p = p.add(v);
        }
    }
    if !d.extent.is_empty() {
        d.extent.min = d.extent.min.add(v);
        d.extent.max = d.extent.max.add(v);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dxf::{parse, ReadOptions};

    fn square_at(x: f64, y: f64) -> Drawing {
        let dxf = format!(
            "0\nSECTION\n2\nHEADER\n9\n$INSUNITS\n70\n4\n0\nENDSEC\n0\nSECTION\n2\nENTITIES\n0\nLWPOLYLINE\n90\n4\n70\n1\n10\n{x}\n20\n{y}\n10\n{}\n20\n{y}\n10\n{}\n20\n{}\n10\n{x}\n20\n{}\n0\nENDSEC\n0\nEOF\n",
            x + 100.0, x + 100.0, y + 50.0, y + 50.0
        );
        parse(dxf.as_bytes(), &ReadOptions::DEFAULT).unwrap()
    }

    #[test]
    fn auto_keeps_a_near_zero_and_moves_a_far_or_negative_one() {
        let mut d = square_at(10.0, 20.0);
        let o = apply(&mut d, ProgramOrigin::Auto, 0.001);
        assert_eq!((o.mode, o.auto, o.at), ("drawing", true, [0.0, 0.0]));
        assert_eq!(d.extent.min, Point::new(10.0, 20.0));

        let mut d = square_at(13000.0, 500.0);
        let o = apply(&mut d, ProgramOrigin::Auto, 0.001);
        assert_eq!((o.mode, o.at), ("lower-left", [13000.0, 500.0]));
        assert_eq!(d.extent.min, Point::new(0.0, 0.0));
        assert!(d.warnings.iter().any(|w| w.code == "origin-moved"));

        let mut d = square_at(-50.0, -706.0);
        let o = apply(&mut d, ProgramOrigin::Auto, 0.001);
        assert_eq!(o.mode, "lower-left");
        let min = d.entities[0]
            .segments
            .iter()
            .fold(f64::INFINITY, |m, s| m.min(s.a.y));
        assert_eq!(min, 0.0);
    }

    #[test]
    fn chosen_origins() {
        let mut d = square_at(-50.0, -706.0);
        let o = apply(&mut d, ProgramOrigin::Drawing, 0.001);
        assert_eq!((o.mode, o.auto), ("drawing", false));
        assert_eq!(d.extent.min, Point::new(-50.0, -706.0));
        let o = apply(
            &mut d,
            ProgramOrigin::Point(Point::new(-50.0, -656.0)),
            0.001,
        );
        assert_eq!(o.mode, "point");
        assert_eq!(d.extent.min, Point::new(0.0, -50.0));
        // Warnings move with the drawing, every place of a group too.
        let mut d = square_at(5000.0, 3000.0);
        d.warnings.push(Warning::at(
            "x",
            crate::text!("x"; "x"),
            Point::new(5010.0, 3020.0),
        ));
        apply(&mut d, ProgramOrigin::LowerLeft, 0.001);
        let w = d.warnings.iter().find(|w| w.code == "x").unwrap();
        assert_eq!(
            (w.at, w.places.clone()),
            (Some(Point::new(10.0, 20.0)), vec![Point::new(10.0, 20.0)])
        );
        assert_eq!(
            ProgramOrigin::from_name("lower-left"),
            Some(ProgramOrigin::LowerLeft)
        );
        assert_eq!(
            ProgramOrigin::from_name(" 1.5, -2"),
            Some(ProgramOrigin::Point(Point::new(1.5, -2.0)))
        );
        assert_eq!(ProgramOrigin::from_name("nan,1"), None);
        assert_eq!(ProgramOrigin::from_name("up"), None);
    }
}
