use super::*;
use crate::contour::Contours;
use crate::test_dxf;

/// A drawing of squares `(x, y, side)` run through the pipeline (kerf 0).
fn contours(squares: &[(f64, f64, f64)]) -> Contours {
    let body: String = squares
        .iter()
        .map(|&(x, y, s)| test_dxf::rect(x, y, s, s))
        .collect();
    let s = crate::Settings::new(0.0, 0.001, 1000.0).unwrap();
    crate::run(&test_dxf::file(&body), &s).unwrap().contours
}

fn index_at(c: &Contours, x0: f64) -> usize {
    c.contours
        .iter()
        .position(|c| (c.bbox.min.x - x0).abs() < 1e-9)
        .unwrap()
}

#[test]
fn a_pick_follows_its_loop_when_contours_are_renumbered() {
    let all = contours(&[(0.0, 0.0, 10.0), (20.0, 0.0, 10.0), (40.0, 0.0, 10.0)]);
    let b1 = index_at(&all, 20.0);
    // Clicked 2 mm right of B1's right edge: moved onto it, keyed.
    let (i, pick) = pick_at(&all, Point::new(32.0, 5.0), 3.0).unwrap();
    assert_eq!(i, b1);
    assert_eq!(pick.at, Point::new(30.0, 5.0));
    assert_eq!(place(std::slice::from_ref(&pick), &all, 0.001), [Some(b1)]);
    // The first square gone: B1 is another number now, and still found.
    let fewer = contours(&[(20.0, 0.0, 10.0), (40.0, 0.0, 10.0)]);
    let now = index_at(&fewer, 20.0);
    assert_ne!(now, b1);
    assert_eq!(
        place(std::slice::from_ref(&pick), &fewer, 0.001),
        [Some(now)]
    );
    // B1 gone: nothing, though B2 is nearest and was B1's number.
    let gone = contours(&[(0.0, 0.0, 10.0), (40.0, 0.0, 10.0)]);
    assert_eq!(place(std::slice::from_ref(&pick), &gone, 0.001), [None]);
}

#[test]
fn a_keyed_pick_never_lands_on_another_shape_through_its_point() {
    let all = contours(&[(0.0, 0.0, 10.0)]);
    let (_, pick) = pick_at(&all, Point::new(10.0, 5.0), 1.0).unwrap();
    // Another loop through the same point (a bigger square sharing the
    // edge's line): not the loop the pick was set on.
    let other = contours(&[(-10.0, -5.0, 20.0)]);
    assert_eq!(place(std::slice::from_ref(&pick), &other, 0.001), [None]);
    // The same shape moved away: its point is not on it.
    let moved = contours(&[(0.5, 0.0, 10.0)]);
    assert_eq!(place(std::slice::from_ref(&pick), &moved, 0.001), [None]);
}

#[test]
fn a_pick_without_key_takes_the_nearest_loop_within_its_reach() {
    let all = contours(&[(0.0, 0.0, 10.0), (20.0, 0.0, 10.0)]);
    let near = |x, y, r| place(&[Pick::near(Point::new(x, y), r)], &all, 0.001)[0];
    assert_eq!(near(10.5, 5.0, 1.0), Some(index_at(&all, 0.0)));
    assert_eq!(near(19.2, 5.0, 1.0), Some(index_at(&all, 20.0)));
    assert_eq!(near(15.0, 5.0, 1.0), None);
    assert_eq!(near(f64::NAN, 5.0, 1.0), None);
}

#[test]
fn the_warning_names_what_is_not_applied_and_why() {
    let all = contours(&[(0.0, 0.0, 10.0)]);
    let (_, mut pick) = pick_at(&all, Point::new(10.0, 5.0), 1.0).unwrap();
    pick.on.as_mut().unwrap().layer = "A".into();
    let w = not_applied(
        &[(&pick, Unapplied::Gone), (&pick, Unapplied::Order)],
        &[(&pick, Unapplied::NoRoom)],
        &all,
    )
    .unwrap();
    assert_eq!(w.code, "choices-not-applied");
    let en = &w.text.en;
    assert!(en.starts_with("2 start point(s) and 1 tab(s)"), "{en}");
    assert!(en.contains("layer A is not cut now"), "{en}");
    assert!(en.contains("chooses its own entries"), "{en}");
    assert!(en.contains("no room"), "{en}");
    assert!(not_applied(&[], &[], &all).is_none());
}
