//! Tests of `kerf`.

use super::*;

fn run(points: &[(f64, f64)]) -> KerfPaths {
    let mut body = format!("0\nLWPOLYLINE\n8\n0\n90\n{}\n70\n1\n", points.len());
    for (x, y) in points {
        body += &format!("10\n{x}\n20\n{y}\n");
    }
    let dxf = format!("0\nSECTION\n2\nENTITIES\n{body}0\nENDSEC\n0\nEOF\n");
    let s = crate::Settings::new(1.0, 0.001, 1000.0).unwrap();
    let d = crate::dxf::parse(dxf.as_bytes(), s.read()).unwrap();
    let c = crate::contour::extract(&d, s.tolerance(), s.gap());
    offset(&c, s.kerf(), s.tolerance())
}

#[test]
fn a_loop_that_crosses_itself_is_said_where_and_not_cut() {
    // A lopsided bow tie (a symmetric one has no area and is open):
    // y = x and y = 20 − 2x cross at (20/3, 20/3).
    let k = run(&[(0.0, 0.0), (10.0, 10.0), (10.0, 0.0), (0.0, 20.0)]);
    let w: Vec<_> = k
        .warnings
        .iter()
        .filter(|w| w.code == "self-crossing")
        .collect();
    assert_eq!(w.len(), 1, "{:?}", k.warnings);
    let at = w[0].at.unwrap();
    assert!(at.dist(Point::new(20.0 / 3.0, 20.0 / 3.0)) < 1e-9, "{at:?}");
    assert!(
        w[0].message().contains("(1 crossing(s))"),
        "{}",
        w[0].message()
    );
    assert!(k.paths.is_empty());
    // A square does not cross itself: one path, nothing said.
    let k = run(&[(0.0, 0.0), (10.0, 0.0), (10.0, 10.0), (0.0, 10.0)]);
    assert_eq!(k.paths.len(), 1);
    assert!(!k.warnings.iter().any(|w| w.code == "self-crossing"));
}
