//! Questions about one place of a finished job, for the page's hover
//! inspector and measure tool (issue 6 §6; paper 001 lists "measure distance
//! and angle" among the operator's tools): which contour is under the
//! pointer, what it is, and which drawn point a measurement snaps to.

use serde::Serialize;

use crate::geom::{dist_to_segment, loop_area, BBox, Point};
use crate::plan::Role;
use crate::scene::Scene;

/// What the inspector shows about one contour. Names come from the file
/// (`layer`, `entity_types`): data, escaped by whoever shows them.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct ContourInfo {
    /// Index in [`crate::contour::Contours::contours`].
    pub contour: usize,
    /// "outer", "hole" or "open".
    pub kind: &'static str,
    /// Layer of its first entity.
    pub layer: String,
    /// DXF types of its entities with counts, e.g. `[("LINE", 4), ("ARC", 2)]`.
    pub entity_types: Vec<(&'static str, usize)>,
    /// Segments (lines and arcs) after reading.
    pub segments: usize,
    /// Drawn length, mm.
    pub length: f64,
    /// Enclosed area, mm² (0 when open).
    pub area: f64,
    /// Direction as drawn: "ccw", "cw", or "open".
    pub drawn: &'static str,
    /// Direction the torch goes round it, when the plan cuts it as one loop.
    pub cut: Option<&'static str>,
    /// Part number (1-based), for closed contours.
    pub part: Option<usize>,
    /// Nesting depth (0 = outside of a part).
    pub depth: usize,
    /// 1-based number of the cut (pierce) that cuts it, when it is cut.
    pub sequence: Option<usize>,
    /// Bounding box `[x0, y0, x1, y1]`, mm.
    pub bbox: [f64; 4],
    /// Its part, copy and loop ([`crate::source::ContourRef`]).
    pub source: crate::source::ContourRef,
}

/// Index of the contour (closed ones only unless `open`) passing nearest
/// `p`, within `reach` mm.
pub fn contour_near(out: &Scene, p: Point, reach: f64, open: bool) -> Option<usize> {
    let mut best: (f64, Option<usize>) = (reach, None);
    for (i, c) in out.contours.contours.iter().enumerate() {
        if (!open && !c.is_closed()) || !c.bbox.overlaps(&BBox::at(p), reach) {
            continue;
        }
        for s in &c.segments {
            let d = dist_to_segment(p, s);
            if d < best.0 {
                best = (d, Some(i));
            }
        }
    }
    best.1
}

/// Everything the inspector shows about contour `index`, or `None` when
/// there is no such contour.
pub fn contour_info(out: &Scene, index: usize) -> Option<ContourInfo> {
    let c = out.contours.contours.get(index)?;
    let mut entity_types: Vec<(&'static str, usize)> = Vec::new();
    for &e in &c.entities {
        let Some(kind) = out.file.entities.get(e).map(|e| e.kind) else {
            continue;
        };
        match entity_types.iter_mut().find(|(k, _)| *k == kind) {
            Some((_, n)) => *n += 1,
            None => entity_types.push((kind, 1)),
        }
    }
    let direction = |area: f64| if area > 0.0 { "ccw" } else { "cw" };
    let sequence = out
        .plan
        .cuts
        .iter()
        .position(|cut| cut.contours.contains(&index))
        .map(|i| i + 1);
    // The torch's direction: the contour steps of this contour form its loop
    // (absent when the contour is not cut, or cut as part of a network).
    let cut = sequence.and_then(|s| {
        let steps: Vec<_> = out.plan.cuts[s - 1]
            .steps
            .iter()
            // With the tabs: they are stretches of the same loop.
            .filter(|st| matches!(st.role, Role::Contour | Role::Tab) && st.contour == Some(index))
            .map(|st| st.segment)
            .collect();
        let closed = steps.len() > 1 && steps[0].a.dist(steps[steps.len() - 1].b) < 1e-6;
        let area = loop_area(&steps);
        (c.is_closed() && closed && area.abs() > 0.0).then(|| direction(area))
    });
    Some(ContourInfo {
        contour: index,
        kind: c.kind.name(),
        layer: c.layer.to_string(),
        entity_types,
        segments: c.segments.len(),
        length: c.length,
        area: c.area.abs(),
        drawn: if c.is_closed() {
            direction(c.area)
        } else {
            "open"
        },
        cut,
        part: c.part,
        depth: c.depth,
        sequence,
        bbox: c.bbox.to_array(),
        source: c.source,
    })
}

/// The drawn point a measurement snaps to near `p`: the nearest segment end
/// or arc centre within `reach` mm, else `p` itself.
pub fn snap(out: &Scene, p: Point, reach: f64) -> Point {
    let mut best = (reach, p);
    let mut consider = |q: Point| {
        let d = q.dist(p);
        if d < best.0 {
            best = (d, q);
        }
    };
    for c in &out.contours.contours {
        if !c.bbox.overlaps(&BBox::at(p), reach) {
            // A shallow arc's centre can lie outside its contour's box; it is
            // then not offered (snapping is to what is near the pointer).
            continue;
        }
        for s in &c.segments {
            consider(s.a);
            consider(s.b);
            if let Some((centre, _)) = s.arc_center() {
                consider(centre);
            }
        }
    }
    for spot in out.file.spots {
        consider(spot.at);
    }
    best.1
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{run, Output, Settings};

    // A 100×50 rectangle (LWPOLYLINE, drawn ccw) with a Ø20 hole at (30, 25).
    const PLATE: &[u8] = b"0\nSECTION\n2\nENTITIES\n\
0\nLWPOLYLINE\n8\nSheet A\n90\n4\n70\n1\n10\n0\n20\n0\n10\n100\n20\n0\n10\n100\n20\n50\n10\n0\n20\n50\n\
0\nCIRCLE\n8\nHoles\n10\n30\n20\n25\n40\n10\n0\nENDSEC\n0\nEOF\n";

    fn job() -> Output {
        run(PLATE, &Settings::new(1.5, 0.001, 2000.0).unwrap()).unwrap()
    }

    #[test]
    fn finds_the_outer_and_the_hole_by_their_lines() {
        let out = job();
        let outer = contour_near(&out.scene(), Point::new(50.0, 0.3), 1.0, false).unwrap();
        let hole = contour_near(&out.scene(), Point::new(40.2, 25.0), 1.0, false).unwrap();
        assert_ne!(outer, hole);
        assert_eq!(
            contour_near(&out.scene(), Point::new(60.0, 25.0), 1.0, false),
            None
        );
        let o = contour_info(&out.scene(), outer).unwrap();
        assert_eq!(
            (o.kind, o.layer.as_str(), o.part, o.depth),
            ("outer", "Sheet A", Some(1), 0)
        );
        assert_eq!(o.entity_types, [("LWPOLYLINE", 1)]);
        assert!((o.length - 300.0).abs() < 1e-9 && (o.area - 5000.0).abs() < 1e-9);
        assert_eq!((o.drawn, o.cut), ("ccw", Some("cw"))); // outers are cut clockwise by default
        let h = contour_info(&out.scene(), hole).unwrap();
        assert_eq!(
            (h.kind, h.layer.as_str(), h.part, h.depth),
            ("hole", "Holes", Some(1), 1)
        );
        assert_eq!(h.cut, Some("ccw"));
        // Holes are cut before their part falls out.
        assert!(h.sequence.unwrap() < o.sequence.unwrap());
        assert!((h.area - std::f64::consts::PI * 100.0).abs() < 1e-6);
        assert_eq!(contour_info(&out.scene(), 99), None);
    }

    #[test]
    fn a_measurement_snaps_to_corners_and_centres_within_reach_only() {
        let out = job();
        assert_eq!(
            snap(&out.scene(), Point::new(99.6, 49.7), 1.0),
            Point::new(100.0, 50.0)
        );
        assert_eq!(
            snap(&out.scene(), Point::new(30.4, 24.8), 1.0),
            Point::new(30.0, 25.0)
        );
        let free = Point::new(60.0, 20.0);
        assert_eq!(snap(&out.scene(), free, 1.0), free);
    }
}
