//! SPLINE, a curve that is not lines or arcs, turned into
//! arcs (biarcs, [`super::biarc`]) within a chord tolerance (paper 004's
//! chord criterion: the distance between the curve and what replaces it
//! stays under the tolerance; `notes-004-oliveira-1997.md`).
//!
//! SPLINE (DXF reference): degree 71, flags 70 (1 closed, 2 periodic,
//! 4 rational), knots 40, weights 41, control points 10/20, fit points 11/21.
//! NURBS are evaluated with de Boor's algorithm in homogeneous coordinates
//! over the knot domain [u_p, u_n]; fit-point-only splines are interpolated
//! by a centripetal Catmull-Rom curve through the fit points (AutoCAD's own
//! fit differs by a small amount: it is reported). ELLIPSE is
//! [`super::ellipse`], by the same biarcs.

use super::biarc;
use super::pairs::Pair;
use crate::geom::{Point, Segment};
use crate::text;
use crate::warning::Text;

/// Largest number of segments one curve may become.
pub(super) const MAX_LINES: usize = 200_000;
/// A SPLINE as arcs, whether it closes, and a note for the user (or None).
pub type Flattened = (Vec<Segment>, bool, Option<Text>);

/// A NURBS curve.
struct Nurbs {
    degree: usize,
    knots: Vec<f64>,
    /// Control points with weights: (x·w, y·w, w).
    ctrl: Vec<[f64; 3]>,
}

impl Nurbs {
    fn domain(&self) -> (f64, f64) {
        (self.knots[self.degree], self.knots[self.ctrl.len()])
    }

    /// The knot span k holding `u`: knots[k] <= u < knots[k+1], within [p, n-1].
    #[cfg(test)]
    fn span_of(&self, u: f64) -> usize {
        let (p, n) = (self.degree, self.ctrl.len());
        (self.knots[..n].partition_point(|&x| x <= u))
            .saturating_sub(1)
            .clamp(p, n - 1)
    }

    /// de Boor's algorithm at `u` (homogeneous, then divided by the weight).
    /// The fitting evaluates [`BezierSpan`]s instead; this is the reference
    /// the tests hold them to.
    #[cfg(test)]
    fn eval(&self, u: f64) -> Point {
        let (lo, hi) = self.domain();
        let u = u.clamp(lo, hi);
        let d = self.blossom(self.span_of(u), &[u; 11][..self.degree]);
        Point::new(d[0] / d[2], d[1] / d[2])
    }

    /// The blossom (polar form) of the curve's piece on knot span `k` at
    /// `args` (p of them): de Boor's triangle with `args[r − 1]` in place of
    /// u at level r (Ramshaw 1989; with every argument u it is the point at
    /// u). Homogeneous coordinates (x·w, y·w, w).
    fn blossom(&self, k: usize, args: &[f64]) -> [f64; 3] {
        let p = self.degree;
        let mut d = [[0.0f64; 3]; 12];
        d[..=p].copy_from_slice(&self.ctrl[k - p..=k]);
        for r in 1..=p {
            let u = args[r - 1];
            for j in (r..=p).rev() {
                let i = j + k - p;
                let den = self.knots[i + 1 + p - r] - self.knots[i];
                let a = if den.abs() > 0.0 {
                    (u - self.knots[i]) / den
                } else {
                    0.0
                };
                let prev = d[j - 1];
                for (c, v) in d[j].iter_mut().enumerate() {
                    *v = (1.0 - a) * prev[c] + a * *v;
                }
            }
        }
        d[p]
    }

    /// Knot span `k` as a rational Bézier curve: its control points are the
    /// blossom at (a, …, a, b, …, b) with i b's for the i-th (Bézier
    /// extraction, Piegl & Tiller, "The NURBS Book" §5.6, by blossoming).
    fn bezier_span(&self, k: usize) -> BezierSpan {
        let p = self.degree;
        let (a, b) = (self.knots[k], self.knots[k + 1]);
        let mut pts = [[0.0f64; 3]; 12];
        let mut args = [a; 11];
        for (i, q) in pts.iter_mut().enumerate().take(p + 1) {
            if i > 0 {
                args[p - i] = b;
            }
            *q = self.blossom(k, &args[..p]);
        }
        BezierSpan {
            degree: p,
            pts,
            a,
            len: b - a,
        }
    }
}

/// One knot span of a NURBS, [a, a + len] in the spline's parameter, as a
/// rational Bézier curve. The fitting evaluates a span hundreds of times;
/// de Casteljau on p + 1 fixed points needs no knot search and no division
/// but the weight's, and gives the exact tangent from its last-but-one
/// level (the biarcs' end tangents; a finite difference took four more
/// evaluations per try).
struct BezierSpan {
    degree: usize,
    /// Homogeneous control points (x·w, y·w, w).
    pts: [[f64; 3]; 12],
    a: f64,
    len: f64,
}

impl BezierSpan {
    /// The homogeneous point at s ∈ [0, 1] and its derivative d/ds.
    #[inline]
    fn casteljau<const N: usize>(&self, s: f64) -> ([f64; 3], [f64; 3]) {
        let p = self.degree;
        let mut d = [[0.0f64; 3]; N];
        d[..=p].copy_from_slice(&self.pts[..=p]);
        let lerp = |x: [f64; 3], y: [f64; 3]| {
            [
                x[0] + s * (y[0] - x[0]),
                x[1] + s * (y[1] - x[1]),
                x[2] + s * (y[2] - x[2]),
            ]
        };
        for r in 1..p {
            for j in 0..=p - r {
                d[j] = lerp(d[j], d[j + 1]);
            }
        }
        // The two points left: the derivative is p times their difference.
        let pf = p as f64;
        let dv = [
            pf * (d[1][0] - d[0][0]),
            pf * (d[1][1] - d[0][1]),
            pf * (d[1][2] - d[0][2]),
        ];
        (lerp(d[0], d[1]), dv)
    }

    fn homogeneous(&self, u: f64) -> ([f64; 3], [f64; 3]) {
        let s = (u - self.a) / self.len;
        match self.degree {
            1 => self.casteljau::<2>(s),
            2 => self.casteljau::<3>(s),
            3 => self.casteljau::<4>(s),
            _ => self.casteljau::<12>(s),
        }
    }
}

impl biarc::Curve for BezierSpan {
    fn at(&self, u: f64) -> Point {
        let (h, _) = self.homogeneous(u);
        Point::new(h[0] / h[2], h[1] / h[2])
    }
    fn at_with_velocity(&self, u: f64) -> (Point, Option<Point>) {
        let (h, dh) = self.homogeneous(u);
        let c = Point::new(h[0] / h[2], h[1] / h[2]);
        // (x·w)' = x'·w + x·w', so x' = ((x·w)' − x·w') / w; d/du = d/ds / len.
        let k = 1.0 / (h[2] * self.len);
        let v = Point::new((dh[0] - c.x * dh[2]) * k, (dh[1] - c.y * dh[2]) * k);
        (c, Some(v))
    }
}

/// Collects x/y pairs of the given codes, in order.
fn points(pairs: &[Pair], cx: i32) -> Vec<Point> {
    let mut out = Vec::new();
    let mut x = None;
    for p in pairs {
        if p.code == cx {
            x = p.f64();
        } else if p.code == cx + 10 {
            if let (Some(xv), Some(y)) = (x.take(), p.f64()) {
                out.push(Point::new(xv, y));
            }
        }
    }
    out
}

/// SPLINE → arcs within `tol` (drawing units).
pub fn spline(pairs: &[Pair], tol: f64) -> Result<Flattened, Text> {
    let flags = super::entities::int(pairs, 70).unwrap_or(0);
    let degree = super::entities::int(pairs, 71).unwrap_or(3);
    let closed = flags & 1 == 1;
    let knots: Vec<f64> = pairs
        .iter()
        .filter(|p| p.code == 40)
        .filter_map(|p| p.f64())
        .collect();
    let weights: Vec<f64> = pairs
        .iter()
        .filter(|p| p.code == 41)
        .filter_map(|p| p.f64())
        .collect();
    let ctrl = points(pairs, 10);
    let fit = points(pairs, 11);
    if ![&knots, &weights]
        .iter()
        .all(|v| v.iter().all(|x| x.is_finite()))
        || !ctrl.iter().chain(&fit).all(|p| p.is_finite())
    {
        return Err(text!("a knot, weight or point is not a number";
                         "um nó, peso ou ponto não é um número"));
    }
    if !(1..=11).contains(&degree) {
        return Err(text!("degree {degree} is not 1 to 11"; "grau {degree} não está entre 1 e 11"));
    }
    let p = degree as usize;
    if ctrl.len() > p {
        let mut note = None;
        let knots = if knots.len() == ctrl.len() + p + 1 && knots.windows(2).all(|w| w[0] <= w[1]) {
            knots
        } else {
            let (k, c) = (knots.len(), ctrl.len());
            note = Some(text!(
                "{k} knots for {c} control points of degree {p}: a clamped uniform knot vector was used";
                "{k} nós para {c} pontos de controle de grau {p}: usado um vetor de nós uniforme fixado"
            ));
            clamped_uniform(ctrl.len(), p)
        };
        let use_w = weights.len() == ctrl.len() && weights.iter().all(|w| *w > 0.0);
        let c: Vec<[f64; 3]> = ctrl
            .iter()
            .enumerate()
            .map(|(i, q)| {
                let w = if use_w { weights[i] } else { 1.0 };
                [q.x * w, q.y * w, w]
            })
            .collect();
        let curve = Nurbs {
            degree: p,
            knots,
            ctrl: c,
        };
        let (lo, hi) = curve.domain();
        if hi.partial_cmp(&lo) != Some(std::cmp::Ordering::Greater) {
            return Err(text!("the knot vector spans no parameter range";
                             "o vetor de nós não cobre nenhum intervalo de parâmetro"));
        }
        // Each distinct knot span (a polynomial piece; the curve may turn a
        // corner only at a knot), split in four so no bend is skipped.
        // (Knots are non-decreasing: the distinct spans are those of positive length.)
        let mut segs = Vec::new();
        for k in p..curve.ctrl.len() {
            let (u0, u1) = (curve.knots[k], curve.knots[k + 1]);
            if u1 <= u0 {
                continue;
            }
            let piece = curve.bezier_span(k);
            let joint = segs.len();
            for q in 0..4 {
                let a = u0 + (u1 - u0) * q as f64 / 4.0;
                let b = u0 + (u1 - u0) * (q + 1) as f64 / 4.0;
                biarc::fit(&piece, a, b, tol, MAX_LINES, &mut segs);
            }
            // Two pieces meet at their knot up to rounding (each is its
            // own Bézier curve): the chain continues from exactly where
            // the last piece ended.
            if joint > 0 && joint < segs.len() {
                segs[joint].a = segs[joint - 1].b;
                if segs[joint].a == segs[joint].b {
                    segs.remove(joint);
                }
            }
        }
        let closes = close_up(&mut segs, closed, tol);
        return Ok((segs, closes, note));
    }
    if fit.len() >= 2 {
        let mut segs = catmull_rom(&fit, closed, tol);
        let closes = close_up(&mut segs, closed, 0.0);
        let note = Some(text!(
            "spline defined by fit points only: interpolated through them (may differ slightly from the CAD program's own fit)";
            "spline definida só por pontos de ajuste: interpolada por eles (pode diferir um pouco do ajuste do próprio CAD)"
        ));
        return Ok((segs, closes, note));
    }
    let (c, f) = (ctrl.len(), fit.len());
    Err(text!(
        "{c} control points for degree {p} and {f} fit points: no curve";
        "{c} pontos de controle para grau {p} e {f} pontos de ajuste: nenhuma curva"
    ))
}

fn clamped_uniform(n: usize, p: usize) -> Vec<f64> {
    let inner = n - p;
    (0..n + p + 1)
        .map(|i| {
            if i <= p {
                0.0
            } else if i >= n {
                1.0
            } else {
                (i - p) as f64 / inner as f64
            }
        })
        .collect()
}

/// Makes a closed (or end-to-start within `tol`) chain end exactly where it
/// starts; true when it is a loop.
pub(super) fn close_up(segs: &mut [Segment], closed: bool, tol: f64) -> bool {
    let Some(first) = segs.first().map(|s| s.a) else {
        return false;
    };
    let n = segs.len();
    let Some(last) = segs.last_mut() else {
        return false;
    };
    let closes = (closed || last.b.dist(first) <= tol) && n >= 2;
    if closes {
        last.b = first;
    }
    closes
}

/// A centripetal Catmull-Rom curve through `pts`, as biarcs within `tol`.
fn catmull_rom(pts: &[Point], closed: bool, tol: f64) -> Vec<Segment> {
    let n = pts.len();
    let get = |i: isize| -> Point {
        if closed {
            pts[i.rem_euclid(n as isize) as usize]
        } else if i < 0 {
            pts[0].add(pts[0].sub(pts[1]))
        } else if i as usize >= n {
            pts[n - 1].add(pts[n - 1].sub(pts[n - 2]))
        } else {
            pts[i as usize]
        }
    };
    let spans = if closed { n } else { n - 1 };
    let mut out = Vec::new();
    for i in 0..spans as isize {
        let (p0, p1, p2, p3) = (get(i - 1), get(i), get(i + 1), get(i + 2));
        let knot = |a: Point, b: Point| a.dist(b).sqrt().max(1e-12);
        let (t1, t2, t3) = {
            let t1 = knot(p0, p1);
            let t2 = t1 + knot(p1, p2);
            (t1, t2, t2 + knot(p2, p3))
        };
        let lerp = |a: Point, b: Point, ta: f64, tb: f64, t: f64| {
            a.scale((tb - t) / (tb - ta))
                .add(b.scale((t - ta) / (tb - ta)))
        };
        let f = |s: f64| {
            let t = t1 + (t2 - t1) * s;
            let a1 = lerp(p0, p1, 0.0, t1, t);
            let a2 = lerp(p1, p2, t1, t2, t);
            let a3 = lerp(p2, p3, t2, t3, t);
            let b1 = lerp(a1, a2, 0.0, t2, t);
            let b2 = lerp(a2, a3, t1, t3, t);
            lerp(b1, b2, t1, t2, t)
        };
        biarc::fit(&f, 0.0, 1.0, tol, MAX_LINES, &mut out);
    }
    out
}

#[cfg(test)]
#[path = "curves_tests.rs"]
mod tests;
