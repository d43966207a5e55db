//! Marks and centre-spots (issue 20 §2): scribed on the drawn line — no
//! kerf offset, no leads — and spotted, all before the first cut (a part
//! cut free may shift, and its marks with it), nearest next from the
//! origin. A closed mark starts at its vertex nearest the tool, an open
//! one at its nearer end.

use super::{Cut, Role};
use crate::geom::{Point, Segment};
use crate::process::layers::Mark;

/// The marking cuts, in order, and where the tool is after them.
pub fn plan(marks: &[Mark], spots: &[Point], from: Point) -> (Vec<Cut>, Point) {
    let mut left_marks: Vec<usize> = (0..marks.len())
        .filter(|&i| !marks[i].segments.is_empty())
        .collect();
    let mut left_spots: Vec<usize> = (0..spots.len()).collect();
    let mut at = from;
    let mut cuts = Vec::with_capacity(left_marks.len() + left_spots.len());
    loop {
        let mark = left_marks
            .iter()
            .enumerate()
            .map(|(k, &i)| (k, entry(&marks[i], at).1))
            .min_by(|a, b| a.1.total_cmp(&b.1));
        let spot = left_spots
            .iter()
            .enumerate()
            .map(|(k, &i)| (k, spots[i].dist(at)))
            .min_by(|a, b| a.1.total_cmp(&b.1));
        match (mark, spot) {
            (Some((k, dm)), s) if s.is_none_or(|(_, ds)| dm <= ds) => {
                let m = &marks[left_marks.swap_remove(k)];
                let segs = entry(m, at).0;
                let cut = Cut::loose(segs[0].a, segs, Role::Mark);
                at = cut.end();
                cuts.push(cut);
            }
            (_, Some((k, _))) => {
                let p = spots[left_spots.swap_remove(k)];
                cuts.push(Cut {
                    spot: true,
                    ..Cut::loose(p, Vec::new(), Role::Mark)
                });
                at = p;
            }
            _ => break,
        }
    }
    (cuts, at)
}

/// `m` travelled from its entry nearest `at`, and that distance.
fn entry(m: &Mark, at: Point) -> (Vec<Segment>, f64) {
    let segs = &m.segments;
    if m.closed {
        let (k, d) = segs
            .iter()
            .enumerate()
            .map(|(k, s)| (k, s.a.dist(at)))
            .min_by(|a, b| a.1.total_cmp(&b.1))
            .unwrap_or((0, f64::INFINITY));
        let mut v = segs.clone();
        v.rotate_left(k);
        return (v, d);
    }
    let (first, last) = match (segs.first(), segs.last()) {
        (Some(f), Some(l)) => (f.a, l.b),
        _ => return (Vec::new(), f64::INFINITY),
    };
    if last.dist(at) < first.dist(at) {
        (
            segs.iter().rev().map(Segment::reversed).collect(),
            last.dist(at),
        )
    } else {
        (segs.clone(), first.dist(at))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn marks_and_spots_go_nearest_next_from_the_nearer_end() {
        let line = |a: (f64, f64), b: (f64, f64)| Mark {
            segments: vec![Segment::line(Point::new(a.0, a.1), Point::new(b.0, b.1))],
            closed: false,
            layer: "MARK".into(),
        };
        let marks = [
            line((100.0, 0.0), (50.0, 0.0)),
            line((10.0, 0.0), (20.0, 0.0)),
        ];
        let spots = [Point::new(30.0, 0.0)];
        let (cuts, end) = plan(&marks, &spots, Point::new(0.0, 0.0));
        assert_eq!(cuts.len(), 3);
        assert_eq!(cuts[0].pierce, Point::new(10.0, 0.0));
        assert!(cuts[0].is_mark());
        assert!(cuts[1].spot);
        // Entered at its nearer end, (50, 0), and travelled backwards.
        assert_eq!(cuts[2].pierce, Point::new(50.0, 0.0));
        assert_eq!(end, Point::new(100.0, 0.0));
    }
}
