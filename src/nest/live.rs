//! The best nest so far as placements, for a live display (issue 18: the
//! page draws the nest as the search improves it). The search reports its
//! best decoded order through [`super::Progress`]; this turns it into the
//! same [`Placement`]s the finished [`super::Nest`] holds: sheet copies
//! first, then copies in holes in the order the holes were opened, copies
//! of each part numbered in that order. The finished nest is assembled
//! from the same function ([`super::assemble`]).

use super::decode::{At, Decoded, Item};
use super::Placement;

/// The placements of a decoded order.
pub(super) fn placements(items: &[Item], d: &Decoded, parts: usize) -> Vec<Placement> {
    let mut copies = vec![0usize; parts];
    let mut out = Vec::new();
    let mut place = |p: &super::place::Placed, sheet: usize, host: Option<(usize, usize)>| {
        let item = &items[p.item];
        let v = &item.variants[p.variant];
        let pl = Placement {
            part: item.part,
            copy: copies[item.part],
            sheet,
            rotation: v.rotation,
            mirror: v.mirror,
            translation: p.t,
            in_hole_of: host,
        };
        copies[item.part] += 1;
        out.push(pl);
        (pl.part, pl.copy)
    };
    let mut id_sheet: Vec<Vec<(usize, usize)>> = Vec::new();
    let mut id_hole: Vec<Vec<(usize, usize)>> = Vec::new();
    for (k, bin) in d.bins.iter().enumerate() {
        id_sheet.push(bin.placed.iter().map(|p| place(p, k, None)).collect());
    }
    for h in &d.holes {
        let host = match h.host {
            At::Sheet(b, i) => id_sheet[b][i],
            At::Hole(j, i) => id_hole[j][i],
        };
        id_hole.push(
            h.bin
                .placed
                .iter()
                .map(|p| place(p, h.sheet, Some(host)))
                .collect(),
        );
    }
    out
}

#[cfg(test)]
mod tests {
    use crate::geom::{Point, Segment};
    use crate::nest::{nest, NestJob, NestSettings, Part, Rotations, Sheets};

    fn rect(w: f64, h: f64) -> Vec<Segment> {
        let c = [(0.0, 0.0), (w, 0.0), (w, h), (0.0, h)].map(|(x, y)| Point::new(x, y));
        (0..4)
            .map(|i| Segment::line(c[i], c[(i + 1) % 4]))
            .collect()
    }

    #[test]
    fn the_last_best_heard_is_the_nest_returned() {
        let part = |name: &str, w, h, q| Part {
            name: name.into(),
            outer: rect(w, h),
            holes: if w > 100.0 {
                vec![rect(60.0, 40.0)
                    .into_iter()
                    .map(|s| {
                        Segment::line(
                            s.a.add(Point::new(20.0, 20.0)),
                            s.b.add(Point::new(20.0, 20.0)),
                        )
                    })
                    .collect()]
            } else {
                Vec::new()
            },
            quantity: q,
            rotations: Rotations::Quarter,
            mirror: false,
        };
        let job = NestJob {
            parts: vec![part("big", 120.0, 80.0, 4), part("small", 30.0, 20.0, 9)],
            sheets: Sheets::Rect {
                width: 300.0,
                height: 200.0,
                count: 3,
            },
            settings: NestSettings {
                max_evaluations: Some(300),
                time_s: 100.0,
                ..NestSettings::default()
            },
        };
        let t = std::cell::Cell::new(0.0);
        let clock = || {
            t.set(t.get() + 1e-4);
            t.get()
        };
        let mut heard = Vec::new();
        let n = nest(&job, &clock, &mut |p| {
            heard.push(p.best);
            true
        })
        .unwrap();
        assert!(heard.len() > 1);
        assert_eq!(heard.last().unwrap(), &n.placements);
        // Some copies went into the big parts' holes: their hosts are named alike.
        assert!(n.placements.iter().any(|p| p.in_hole_of.is_some()));
    }
}
