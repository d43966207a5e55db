//! Marks and centre-spots (issue 20 §2): scribed on the drawn line — no
//! kerf offset, no leads — and spotted, all before the first cut (a part
//! cut free may shift, and its marks with it), nearest next from the
//! origin. A closed mark starts at its vertex nearest the tool, an open
//! one at its nearer end.

use super::{nearest, Cut, Role};
use crate::geom::{Point, Segment};
use crate::process::layers::Mark;

/// The marking cuts, in order, and where the tool is after them: nearest
/// entry next ([`nearest::visit_nearest`]; on a tie a mark's points are
/// met before a spot's).
pub fn plan(marks: &[Mark], spots: &[Point], from: Point) -> (Vec<Cut>, Point) {
    // Entry points: a closed mark's vertices, an open one's ends, the spots.
    let mut points = Vec::new();
    let mut owners = Vec::new();
    for (i, m) in marks.iter().enumerate() {
        let (Some(first), Some(last)) = (m.segments.first(), m.segments.last()) else {
            continue; // nothing to scribe
        };
        if m.closed {
            points.extend(m.segments.iter().map(|s| s.a));
            owners.extend(std::iter::repeat_n(i, m.segments.len()));
        } else {
            points.extend([first.a, last.b]);
            owners.extend([i, i]);
        }
    }
    points.extend_from_slice(spots);
    owners.extend((0..spots.len()).map(|j| marks.len() + j));
    let mut at = from;
    let mut cuts = Vec::with_capacity(marks.len() + spots.len());
    nearest::visit_nearest(&points, &owners, marks.len() + spots.len(), from, |i| {
        if let Some(m) = marks.get(i) {
            let segs = entry(m, at);
            if let Some(pierce) = segs.first().map(|s| s.a) {
                let cut = Cut::loose(pierce, segs, Role::Mark);
                at = cut.end();
                cuts.push(cut);
            }
        } else {
            let p = spots[i - marks.len()];
            cuts.push(Cut {
                spot: true,
                ..Cut::loose(p, Vec::new(), Role::Mark)
            });
            at = p;
        }
        at
    });
    (cuts, at)
}

/// `m` travelled from its entry nearest `at`: a closed mark from its
/// vertex nearest, an open one from its nearer end.
fn entry(m: &Mark, at: Point) -> Vec<Segment> {
    let segs = &m.segments;
    if m.closed {
        let k = segs
            .iter()
            .enumerate()
            .map(|(k, s)| (k, s.a.dist(at)))
            .min_by(|a, b| a.1.total_cmp(&b.1))
            .map_or(0, |(k, _)| k);
        let mut v = segs.clone();
        v.rotate_left(k);
        return v;
    }
    match (segs.first(), segs.last()) {
        (Some(f), Some(l)) if l.b.dist(at) < f.a.dist(at) => {
            segs.iter().rev().map(Segment::reversed).collect()
        }
        _ => segs.clone(),
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
