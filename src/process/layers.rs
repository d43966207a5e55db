//! Operations per layer (issue 20 §2): the drawing split into what is cut
//! (kerf compensated, the usual pipeline), what is marked on the line,
//! what is centre-spotted and what is left alone — the last reported, layer
//! by layer, never dropped in silence.
//!
//! Marks and spots are chained on their own, so a scribed outline drawn
//! around a part never becomes a "hole" of it nor a part of its own.

use super::{LayerOps, Operation};
use crate::contour;
use crate::dxf::Drawing;
use crate::geom::{Point, Segment, Tolerance};
use crate::text;
use crate::warning::Warning;

/// One path marked on the line.
#[derive(Clone, Debug, PartialEq)]
pub struct Mark {
    /// Segments end to end, as drawn (after chaining).
    pub segments: Vec<Segment>,
    /// True when it closes on itself.
    pub closed: bool,
    /// The layer it was drawn on.
    pub layer: String,
}

/// The drawing split by operation.
#[derive(Clone, Debug, Default)]
pub struct Layered {
    /// The cut layers' entities and points (what the cutting pipeline reads).
    pub cut: Drawing,
    /// For each entity of `cut`, its index in the whole drawing.
    pub cut_entities: Vec<usize>,
    /// Paths to mark on the line.
    pub marks: Vec<Mark>,
    /// Points to centre-spot.
    pub spots: Vec<Point>,
    /// One per ignored layer, and anything a spot layer could not spot.
    pub warnings: Vec<Warning>,
    /// The router's pockets, engravings and holes to drill (issue 43).
    pub milling: MillGeometry,
}

/// What the router's own operations take from the drawing, chained on
/// their own (a pocket's islands are the closed contours inside it, on
/// its layers).
#[derive(Clone, Debug, Default)]
pub struct MillGeometry {
    /// Every contour of the pocket layers (open ones are refused by
    /// [`crate::mill`], by name).
    pub pockets: Vec<contour::Contour>,
    /// Paths engraved on the line.
    pub engraves: Vec<Mark>,
    /// Points to drill.
    pub drill_points: Vec<Point>,
    /// Contours of the drill layers (circles drilled at their centre).
    pub drill_loops: Vec<contour::Contour>,
}

impl MillGeometry {
    /// True when a pocket, engraving or drilled loop passes within
    /// `reach` mm of `p`.
    pub fn passes_near(&self, p: Point, reach: f64) -> bool {
        let near = |segs: &[Segment]| {
            segs.iter()
                .any(|s| s.point_at(crate::geom::nearest_param(s, p)).dist(p) <= reach)
        };
        (self.pockets.iter().chain(&self.drill_loops)).any(|c| near(&c.segments))
            || self.engraves.iter().any(|m| near(&m.segments))
    }
    /// True when there is nothing to mill.
    pub fn is_empty(&self) -> bool {
        self.pockets.is_empty()
            && self.engraves.is_empty()
            && self.drill_points.is_empty()
            && self.drill_loops.is_empty()
    }
}

/// The drawing's header (units, layers, counts) with no geometry.
fn header(d: &Drawing) -> Drawing {
    Drawing {
        units: d.units,
        units_source: d.units_source,
        measurement: d.measurement,
        extent: d.extent,
        version: d.version.clone(),
        binary: d.binary,
        svg: d.svg,
        entities: Vec::new(),
        spots: Vec::new(),
        inserts: d.inserts.clone(),
        layers: d.layers.clone(),
        counts: d.counts.clone(),
        skipped: d.skipped.clone(),
        warnings: Vec::new(),
    }
}

/// Splits `drawing` by the operation of each layer; None when every layer
/// holding geometry is cut (the drawing is then used as it is).
pub fn split(drawing: &Drawing, ops: &LayerOps, tol: Tolerance, gap: f64) -> Option<Layered> {
    // A profile is a cut with the tool's width as the kerf: one pipeline.
    let op_of: Vec<Operation> = (drawing.layers.iter())
        .map(|l| match ops.op(&l.name) {
            Operation::Profile => Operation::Cut,
            o => o,
        })
        .collect();
    let op = |layer: u32| op_of.get(layer as usize).copied().unwrap_or(Operation::Cut);
    let used = drawing
        .entities
        .iter()
        .map(|e| e.layer)
        .chain(drawing.spots.iter().map(|s| s.layer));
    if used.clone().all(|l| op(l) == Operation::Cut) {
        return None;
    }
    let mut out = Layered::default();
    let part = |want: Operation| {
        let mut d = header(drawing);
        let mut index = Vec::new();
        // Kept entities before each original index (to move the points' places).
        let mut before = Vec::with_capacity(drawing.entities.len() + 1);
        before.push(0);
        for (i, e) in drawing.entities.iter().enumerate() {
            if op(e.layer) == want {
                d.entities.push(e.clone());
                index.push(i);
            }
            before.push(index.len());
        }
        for s in drawing.spots.iter().filter(|s| op(s.layer) == want) {
            let mut s = *s;
            s.after_entities = before[s.after_entities.min(drawing.entities.len())];
            d.spots.push(s);
        }
        (d, index)
    };
    let (cut, cut_entities) = part(Operation::Cut);
    out.cut = cut;
    out.cut_entities = cut_entities;
    // Marks: chained like contours, kept whole (closed or open).
    let (marks, _) = part(Operation::Mark);
    out.spots.extend(marks.spots.iter().map(|s| s.at));
    for c in contour::extract(&marks, tol, gap).contours {
        out.marks.push(Mark {
            closed: c.is_closed(),
            segments: c.segments,
            layer: c.layer.to_string(),
        });
    }
    // Spots: every point, and the centre of every closed shape (a drill
    // mark drawn as a small circle); an open line cannot be spotted.
    let (spots, _) = part(Operation::Spot);
    out.spots.extend(spots.spots.iter().map(|s| s.at));
    let mut open = Vec::new();
    for c in contour::extract(&spots, tol, gap).contours {
        if c.is_closed() {
            out.spots.push(Point::new(
                (c.bbox.min.x + c.bbox.max.x) / 2.0,
                (c.bbox.min.y + c.bbox.max.y) / 2.0,
            ));
        } else {
            open.push(c.start());
        }
    }
    if let Some(&at) = open.first() {
        let n = open.len();
        out.warnings.push(Warning::at(
            "spot-not-closed",
            text!("{n} open line(s) on a spot layer: only points and closed shapes (their centre) are spotted, these are not marked";
                  "{n} linha(s) aberta(s) em camada de pontos: só pontos e formas fechadas (o centro) são marcados; estas não são marcadas"),
            at,
        ));
    }
    // The router's operations: chained on their own, planned by `mill`.
    let (pockets, _) = part(Operation::Pocket);
    out.milling.pockets = contour::extract(&pockets, tol, gap).contours;
    let (engraves, _) = part(Operation::Engrave);
    out.milling
        .drill_points
        .extend(engraves.spots.iter().map(|s| s.at));
    for c in contour::extract(&engraves, tol, gap).contours {
        out.milling.engraves.push(Mark {
            closed: c.is_closed(),
            segments: c.segments,
            layer: c.layer.to_string(),
        });
    }
    let (drills, _) = part(Operation::Drill);
    out.milling
        .drill_points
        .extend(drills.spots.iter().map(|s| s.at));
    out.milling.drill_loops = contour::extract(&drills, tol, gap).contours;
    // Ignored layers, one warning each, with what they held.
    for (l, layer) in drawing.layers.iter().enumerate() {
        if op_of[l] != Operation::Ignore {
            continue;
        }
        let n = drawing
            .entities
            .iter()
            .filter(|e| e.layer as usize == l)
            .count()
            + drawing
                .spots
                .iter()
                .filter(|s| s.layer as usize == l)
                .count();
        if n == 0 {
            continue;
        }
        let name = &layer.name;
        out.warnings.push(Warning::new(
            "layer-ignored",
            text!("layer '{name}' is not cut (operation: ignore): {n} entit(y/ies) left out; give it another operation to cut or mark it";
                  "a camada '{name}' não é cortada (operação: ignorar): {n} entidade(s) deixada(s) de fora; dê a ela outra operação para cortar ou marcar"),
        ));
    }
    Some(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    const DXF: &str = "0\nSECTION\n2\nENTITIES\n\
0\nCIRCLE\n8\nCUT\n10\n50\n20\n50\n40\n20\n\
0\nLINE\n8\nMARK\n10\n40\n20\n50\n11\n60\n21\n50\n\
0\nCIRCLE\n8\nMARK\n10\n50\n20\n50\n40\n30\n\
0\nCIRCLE\n8\nSPOT\n10\n50\n20\n50\n40\n1\n\
0\nPOINT\n8\nSPOT\n10\n5\n20\n5\n\
0\nLINE\n8\nDIM\n10\n0\n20\n0\n11\n100\n21\n0\n\
0\nENDSEC\n0\nEOF\n";

    #[test]
    fn a_drawing_splits_by_layer_and_ignored_layers_are_reported() {
        let d = crate::dxf::parse(DXF.as_bytes(), &crate::dxf::ReadOptions::DEFAULT).unwrap();
        let tol = Tolerance(0.001);
        let s = split(&d, &LayerOps::new(), tol, 0.05).unwrap();
        assert_eq!(s.cut.entities.len(), 1);
        assert_eq!(s.cut_entities, [0]);
        assert_eq!(s.marks.len(), 2);
        assert_eq!(s.marks.iter().filter(|m| m.closed).count(), 1);
        assert_eq!(s.spots.len(), 2);
        assert!(s
            .spots
            .iter()
            .any(|p| p.dist(Point::new(50.0, 50.0)) < 1e-9));
        let ignored: Vec<_> = s
            .warnings
            .iter()
            .filter(|w| w.code == "layer-ignored")
            .collect();
        assert_eq!(ignored.len(), 1);
        assert!(ignored[0].message().contains("'DIM'"));
        // Every layer cut: no split at all.
        let all_cut = LayerOps {
            given: Vec::new(),
            by_name: false,
        };
        assert!(split(&d, &all_cut, tol, 0.05).is_none());
    }
}
