//! The `transform` attribute (SVG 1.1 §7.6): a list of matrix, translate,
//! scale, rotate (about a point), skewX and skewY, applied right to left.

use svgtypes::{TransformListParser, TransformListToken};

use crate::geom::Affine;

/// The map a `transform` list makes: `"a b"` is a(b(p)). Err with the
/// attribute's text when it does not parse or is not finite (SVG: an
/// invalid transform is not applied; the caller says so).
pub fn parse(text: &str) -> Result<Affine, String> {
    let mut m = Affine::IDENTITY;
    for t in TransformListParser::from(text) {
        let t = t.map_err(|_| excerpt(text))?;
        m = m.then_after(&of_token(t));
    }
    if m.is_finite() {
        Ok(m)
    } else {
        Err(excerpt(text))
    }
}

fn excerpt(text: &str) -> String {
    text.chars().take(60).collect()
}

/// One transform function as a map. SVG's matrix(a b c d e f) is
/// x' = a x + c y + e, y' = b x + d y + f.
fn of_token(t: TransformListToken) -> Affine {
    match t {
        TransformListToken::Matrix { a, b, c, d, e, f } => Affine {
            a,
            b: c,
            c: e,
            d: b,
            e: d,
            f,
        },
        TransformListToken::Translate { tx, ty } => Affine::translate(tx, ty),
        TransformListToken::Scale { sx, sy } => Affine::scale_xy(sx, sy),
        // The same matrix as a counter-clockwise turn in y-up axes; in
        // SVG's y-down user space it turns clockwise on screen.
        TransformListToken::Rotate { angle } => Affine::rotate_deg(angle),
        TransformListToken::SkewX { angle } => Affine {
            b: angle.to_radians().tan(),
            ..Affine::IDENTITY
        },
        TransformListToken::SkewY { angle } => Affine {
            d: angle.to_radians().tan(),
            ..Affine::IDENTITY
        },
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::Point;

    fn close(a: Point, b: Point) {
        assert!(a.dist(b) < 1e-9, "{a:?} != {b:?}");
    }

    #[test]
    fn a_list_applies_right_to_left() {
        // translate(10,0) scale(2): (1,1) → (2,2) → (12,2).
        let m = parse("translate(10,0) scale(2)").unwrap();
        close(m.apply(Point::new(1.0, 1.0)), Point::new(12.0, 2.0));
        // The other order: (1,1) → (11,1) → (22,2).
        let m = parse("scale(2), translate(10 0)").unwrap();
        close(m.apply(Point::new(1.0, 1.0)), Point::new(22.0, 2.0));
    }

    #[test]
    fn rotate_about_a_point_and_skews_by_hand() {
        // rotate(90, 10, 10): (20,10) → (10,20) (x toward y).
        let m = parse("rotate(90 10 10)").unwrap();
        close(m.apply(Point::new(20.0, 10.0)), Point::new(10.0, 20.0));
        // skewX(45): x += y.
        let m = parse("skewX(45)").unwrap();
        close(m.apply(Point::new(1.0, 2.0)), Point::new(3.0, 2.0));
        let m = parse("skewY(45)").unwrap();
        close(m.apply(Point::new(2.0, 1.0)), Point::new(2.0, 3.0));
        // matrix(a b c d e f): x' = a x + c y + e = 1+6+5, y' = b x + d y + f = 2+8+6.
        let m = parse("matrix(1 2 3 4 5 6)").unwrap();
        close(m.apply(Point::new(1.0, 2.0)), Point::new(12.0, 16.0));
    }

    #[test]
    fn bad_lists_are_refused() {
        assert!(parse("translate(1,").is_err());
        assert!(parse("scale(1e400)").is_err());
        assert!(parse("wobble(3)").is_err());
        assert_eq!(parse("").unwrap(), Affine::IDENTITY);
    }
}
