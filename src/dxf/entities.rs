//! Geometry entities → segments: LINE, ARC, CIRCLE, LWPOLYLINE, POLYLINE.
//!
//! Each builder gets the pairs of one entity (the `0 TYPE` pair excluded)
//! and returns its segments in drawing units and world X/Y (the OCS applied),
//! or the reason it cannot be used; the reader then scales and places them.
//! Group codes are those of the DXF reference, ENTITIES section; paper 000 reads LINE (10/20, 11/21), ARC (10/20, 40, 50/51 in
//! degrees, counter-clockwise) and CIRCLE (10/20, 40).

use super::pairs::Pair;
pub use super::pairs::Place;
use crate::geom::{arc_pieces, split_big_bulge, Affine, Point, Segment};
use crate::text;
use crate::warning::{dec, Text};

/// What one geometry entity contributed.
#[derive(Clone, Debug, PartialEq)]
pub struct Entity {
    /// DXF type name ("LINE", "ARC", …).
    pub kind: &'static str,
    /// Index of its layer in [`super::Drawing::layers`].
    pub layer: u32,
    /// Where its `0 TYPE` pair is (for an entity inside a block, the block's entity).
    pub place: Place,
    /// Its segments in mm, in drawing order, each arc at most 180°.
    pub segments: Vec<Segment>,
    /// True when the entity is a closed loop by itself (CIRCLE, closed polyline).
    pub closed: bool,
    /// The part copy and loop it was placed from (a nested sheet's
    /// drawing); None for what a DXF file holds.
    pub source: Option<crate::source::ContourRef>,
    /// The INSERT copy that drew it (an index of
    /// [`super::Drawing::inserts`]); None when drawn in model space itself.
    pub insert: Option<u32>,
}

/// The first value of `code` as an integer.
pub fn int(pairs: &[Pair], code: i32) -> Option<i64> {
    pairs.iter().find(|p| p.code == code).and_then(|p| p.int())
}

/// The first value of `code` as a number.
pub fn num(pairs: &[Pair], code: i32) -> Option<f64> {
    pairs.iter().find(|p| p.code == code).and_then(|p| p.f64())
}

/// The map from an entity's Object Coordinate System to world X/Y, by the
/// DXF reference's "Arbitrary Axis Algorithm": with extrusion N, Ax = Wy × N
/// when |Nx| and |Ny| are under 1/64, else Wz × N; Ay = N × Ax; a point
/// (x, y, z) of the OCS is x·Ax + y·Ay + z·N, seen from above. `elevation`
/// is the entity's OCS z (group 30 or 38). Extrusion (0,0,−1) gives the
/// mirror x → −x, which turns arcs the other way. The flag is true when the
/// plane is tilted (not along ±Z), so the entity is projected.
pub fn ocs(pairs: &[Pair], elevation_code: i32) -> (Affine, bool) {
    let n = [
        num(pairs, 210).unwrap_or(0.0),
        num(pairs, 220).unwrap_or(0.0),
        num(pairs, 230).unwrap_or(1.0),
    ];
    let len = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
    if !(len.is_finite() && len > 1e-12) {
        return (Affine::IDENTITY, false);
    }
    let n = n.map(|v| v / len);
    // Exactly ±Z (nearly every entity): exact identity / mirror, no rounding
    // noise from the cross products; known before computing them (and
    // before looking for the elevation, which this map ignores).
    if n[0] == 0.0 && n[1] == 0.0 {
        return (
            if n[2] < 0.0 {
                Affine::scale_xy(-1.0, 1.0)
            } else {
                Affine::IDENTITY
            },
            false,
        );
    }
    let cross = |a: [f64; 3], b: [f64; 3]| {
        [
            a[1] * b[2] - a[2] * b[1],
            a[2] * b[0] - a[0] * b[2],
            a[0] * b[1] - a[1] * b[0],
        ]
    };
    let unit = |v: [f64; 3]| {
        let l = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
        v.map(|x| x / l)
    };
    let along_z = n[0].abs() < 1.0 / 64.0 && n[1].abs() < 1.0 / 64.0;
    let ax = unit(if along_z {
        cross([0.0, 1.0, 0.0], n)
    } else {
        cross([0.0, 0.0, 1.0], n)
    });
    let ay = unit(cross(n, ax));
    let z = num(pairs, elevation_code)
        .filter(|v| v.is_finite())
        .unwrap_or(0.0);
    let m = Affine {
        a: ax[0],
        b: ay[0],
        c: z * n[0],
        d: ax[1],
        e: ay[1],
        f: z * n[1],
    };
    (m, !along_z || n[2].abs() < 1.0 - 1e-9)
}

/// A finite coordinate (0 when absent, the DXF default).
fn coord(v: Option<f64>, what: (&str, &str)) -> Result<f64, Text> {
    let v = v.unwrap_or(0.0);
    if v.is_finite() && v.abs() <= 1e12 {
        Ok(v)
    } else {
        Err(text!("{} is out of range ({v})", what.0; "{} fora da faixa ({})", what.1, dec(v)))
    }
}

/// The point of codes `cx`/`cx+10`.
pub fn point(pairs: &[Pair], cx: i32) -> Result<Point, Text> {
    Ok(Point::new(
        coord(num(pairs, cx), COORDINATE)?,
        coord(num(pairs, cx + 10), COORDINATE)?,
    ))
}

const COORDINATE: (&str, &str) = ("coordinate", "coordenada");
const VERTEX: (&str, &str) = ("vertex", "vértice");

fn radius(pairs: &[Pair]) -> Result<f64, Text> {
    let r = coord(num(pairs, 40), ("radius", "raio"))?;
    if r > 0.0 {
        Ok(r)
    } else {
        Err(text!("radius {r} is not positive"; "raio {} não é positivo", dec(r)))
    }
}

/// LINE: start 10/20, end 11/21, in world coordinates.
pub fn line(pairs: &[Pair]) -> Result<(Vec<Segment>, bool), Text> {
    let a = point(pairs, 10)?;
    let b = point(pairs, 11)?;
    Ok((vec![Segment::line(a, b)], false))
}

/// ARC: centre 10/20, radius 40, angles 50→51 in degrees, counter-clockwise in its OCS.
pub fn arc(pairs: &[Pair]) -> Result<(Vec<Segment>, bool), Text> {
    let c = point(pairs, 10)?;
    let r = radius(pairs)?;
    let a0 = num(pairs, 50).unwrap_or(0.0);
    let a1 = num(pairs, 51).unwrap_or(360.0);
    if !(a0.is_finite() && a1.is_finite()) {
        return Err(text!("arc angle is not a number"; "ângulo do arco não é um número"));
    }
    let mut sweep = (a1 - a0).rem_euclid(360.0);
    if sweep == 0.0 {
        // Equal angles: the DXF convention is a full circle.
        sweep = 360.0;
    }
    let segs = arc_pieces(c, r, a0.to_radians(), sweep.to_radians());
    Ok((segs, sweep == 360.0))
}

/// CIRCLE: centre 10/20, radius 40; two half arcs, counter-clockwise in its OCS.
pub fn circle(pairs: &[Pair]) -> Result<(Vec<Segment>, bool), Text> {
    let c = point(pairs, 10)?;
    let r = radius(pairs)?;
    // `arc_pieces(c, r, 0, 2π)` with its sines, cosines and tangent taken
    // once: the same two half arcs, bit for bit, without trigonometry per circle.
    static HALVES: std::sync::OnceLock<[f64; 7]> = std::sync::OnceLock::new();
    let t = HALVES.get_or_init(|| {
        let step = std::f64::consts::TAU / 2.0;
        let (a0, a1, a2) = (0.0 + step * 0.0, 0.0 + step * 1.0, 0.0 + step * 2.0);
        [
            a0.cos(),
            a0.sin(),
            a1.cos(),
            a1.sin(),
            a2.cos(),
            a2.sin(),
            (step / 4.0).tan(),
        ]
    });
    let at = |k: usize| Point::new(c.x + r * t[2 * k], c.y + r * t[2 * k + 1]);
    let (p0, p1, p2) = (at(0), at(1), at(2));
    let segs = vec![
        Segment {
            a: p0,
            b: p1,
            bulge: t[6],
        },
        Segment {
            a: p1,
            b: p2,
            bulge: t[6],
        },
    ];
    Ok((segs, true))
}

/// One polyline vertex: position and the bulge of the segment that leaves it.
#[derive(Clone, Copy, Debug)]
pub struct Vertex {
    /// Position in mm (OCS).
    pub p: Point,
    /// Bulge of the segment from this vertex to the next.
    pub bulge: f64,
}

/// Segments of a polyline from its vertices (bulge > 1 arcs split).
pub fn polyline_segments(vertices: &[Vertex], closed: bool) -> Vec<Segment> {
    let n = vertices.len();
    let count = if closed { n } else { n.saturating_sub(1) };
    let mut segs = Vec::with_capacity(count);
    for i in 0..count {
        let v = vertices[i];
        let w = vertices[(i + 1) % n];
        let bulge = if v.bulge.is_finite() { v.bulge } else { 0.0 };
        segs.extend(split_big_bulge(v.p, w.p, bulge));
    }
    segs
}

/// LWPOLYLINE vertices gathered pair by pair, so the reader can stream a
/// polyline of millions of vertices without keeping its pairs (24 bytes a
/// vertex instead of 80 for its two pairs). At most `cap` vertices are kept;
/// `seen` counts them all.
#[derive(Default)]
pub struct LwVertices {
    /// The vertices kept.
    pub v: Vec<Vertex>,
    /// All vertices met.
    pub seen: usize,
    /// Why the polyline cannot be used, once known.
    pub error: Option<Text>,
    pending_x: Option<f64>,
}

impl LwVertices {
    /// Empties it for the next polyline.
    pub fn clear(&mut self) {
        self.v.clear();
        self.seen = 0;
        self.error = None;
        self.pending_x = None;
    }
    /// Takes a vertex pair (10, 20, 42; widths 40/41/43 and the count 91
    /// are dropped) and returns true, or returns false for a header pair.
    pub fn feed(&mut self, p: &Pair, cap: usize) -> bool {
        match p.code {
            10 => match coord(p.f64(), VERTEX) {
                Ok(x) => self.pending_x = Some(x),
                Err(e) => self.fail(e),
            },
            20 => match (self.pending_x.take(), coord(p.f64(), VERTEX)) {
                (Some(x), Ok(y)) => {
                    self.seen += 1;
                    if self.v.len() < cap {
                        self.v.push(Vertex {
                            p: Point::new(x, y),
                            bulge: 0.0,
                        });
                    }
                }
                (None, _) => self.fail(text!("vertex Y without X"; "vértice com Y sem X")),
                (_, Err(e)) => self.fail(e),
            },
            42 => {
                if let Some(v) = self.v.last_mut() {
                    v.bulge = p.f64().unwrap_or(0.0);
                }
            }
            40 | 41 | 43 | 91 => {}
            _ => return false,
        }
        true
    }
    fn fail(&mut self, e: Text) {
        self.error.get_or_insert(e);
    }
}

/// LWPOLYLINE: flags 70 (bit 1 = closed), vertices 10/20 each followed by an
/// optional bulge 42; widths (40/41/43) are ignored.
pub fn lwpolyline(pairs: &[Pair]) -> Result<(Vec<Segment>, bool), Text> {
    let mut lw = LwVertices::default();
    for p in pairs {
        lw.feed(p, usize::MAX);
    }
    lwpolyline_from(pairs, &lw)
}

/// An LWPOLYLINE from its header pairs and its gathered vertices.
pub fn lwpolyline_from(header: &[Pair], lw: &LwVertices) -> Result<(Vec<Segment>, bool), Text> {
    if let Some(e) = &lw.error {
        return Err(e.clone());
    }
    let closed = int(header, 70).unwrap_or(0) & 1 == 1;
    if lw.seen < 2 {
        return Err(vertex_count(lw.seen));
    }
    Ok((polyline_segments(&lw.v, closed), closed))
}

/// A POLYLINE's segments, closed flag, and Z range (for 3-D polylines).
pub type Polyline3d = (Vec<Segment>, bool, Option<(f64, f64)>);

/// POLYLINE header flag of a 3-D polyline (vertices in world coordinates, no bulges).
const POLYLINE_3D: i64 = 8;
/// POLYLINE header flags of meshes: 16 = polygon mesh, 64 = polyface mesh.
const POLYLINE_MESH: i64 = 16 | 64;

/// POLYLINE with its VERTEX entities: header flags 70 (1 = closed), each
/// vertex 10/20 and bulge 42; vertices flagged 16 (spline frame control
/// points) are not on the curve and are left out.
///
/// A 3-D polyline (flag 8) is read in world X/Y; many programs write flat
/// outlines that way. Its Z values are returned so the caller can warn
/// when it is not flat.
pub fn polyline(header: &[Pair], vertices: &[&[Pair]]) -> Result<Polyline3d, Text> {
    let flags = int(header, 70).unwrap_or(0);
    if flags & POLYLINE_MESH != 0 {
        return Err(
            text!("POLYLINE with flags {flags} is a mesh, not an outline";
                         "POLYLINE com flags {flags} é uma malha, não um contorno"),
        );
    }
    let is_3d = flags & POLYLINE_3D != 0;
    let mut z_range: Option<(f64, f64)> = None;
    let mut vs = Vec::with_capacity(vertices.len());
    for v in vertices {
        let vflags = int(v, 70).unwrap_or(0);
        if vflags & 16 != 0 {
            continue;
        }
        let bulge = if is_3d {
            0.0
        } else {
            num(v, 42).unwrap_or(0.0)
        };
        vs.push(Vertex {
            p: point(v, 10)?,
            bulge,
        });
        if is_3d {
            let z = num(v, 30).unwrap_or(0.0);
            z_range = Some(z_range.map_or((z, z), |(lo, hi)| (lo.min(z), hi.max(z))));
        }
    }
    if vs.len() < 2 {
        return Err(vertex_count(vs.len()));
    }
    let closed = flags & 1 == 1;
    Ok((polyline_segments(&vs, closed), closed, z_range))
}

/// "polyline has 1 vertex" in every language.
fn vertex_count(n: usize) -> Text {
    text!("polyline has {n} vertex(es)"; "polilinha com {n} vértice(s)")
}

#[cfg(test)]
#[path = "entities_tests.rs"]
mod tests;
