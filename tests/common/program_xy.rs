//! A G-code program's path in X and Y, read from its text alone (not
//! kerfcam's backplot): G0 rapids, G1 lines and G2/G3 arcs with I, J from
//! the start, absolute coordinates (G90), Z carried along. What the
//! Play-list and plan-SVG tests hold the page's pictures against.

use std::f64::consts::TAU;

/// One move in X and Y.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct XyMove {
    /// A G0.
    pub rapid: bool,
    pub a: (f64, f64),
    pub b: (f64, f64),
    /// An arc's centre and whether it turns counter-clockwise (G3).
    pub arc: Option<((f64, f64), bool)>,
    /// Z at the start and the end.
    pub z: (f64, f64),
}

impl XyMove {
    /// A straight line or an arc from `a` to `b` (`arc`: centre and
    /// counter-clockwise).
    pub fn new(rapid: bool, a: (f64, f64), b: (f64, f64), arc: Option<((f64, f64), bool)>) -> XyMove {
        XyMove {
            rapid,
            a,
            b,
            arc,
            z: (0.0, 0.0),
        }
    }

    /// Radius, start angle and signed sweep of an arc (a full turn when
    /// the ends meet).
    fn arc_parts(&self) -> Option<((f64, f64), f64, f64, f64)> {
        let ((cx, cy), ccw) = self.arc?;
        let r = (self.a.0 - cx).hypot(self.a.1 - cy);
        let a0 = (self.a.1 - cy).atan2(self.a.0 - cx);
        let a1 = (self.b.1 - cy).atan2(self.b.0 - cx);
        let mut sweep = if ccw { a1 - a0 } else { a0 - a1 };
        while sweep <= 1e-9 {
            sweep += TAU;
        }
        Some(((cx, cy), r, a0, if ccw { sweep } else { -sweep }))
    }

    /// Length in X and Y.
    pub fn length(&self) -> f64 {
        match self.arc_parts() {
            Some((_, r, _, sweep)) => r * sweep.abs(),
            None => (self.b.0 - self.a.0).hypot(self.b.1 - self.a.1),
        }
    }

    /// The point at fraction `t` along the move.
    pub fn at(&self, t: f64) -> (f64, f64) {
        match self.arc_parts() {
            Some(((cx, cy), r, a0, sweep)) => {
                let a = a0 + sweep * t;
                (cx + r * a.cos(), cy + r * a.sin())
            }
            None => (
                self.a.0 + (self.b.0 - self.a.0) * t,
                self.a.1 + (self.b.1 - self.a.1) * t,
            ),
        }
    }

    /// Points along the move at most `step` apart, both ends included.
    pub fn samples(&self, step: f64) -> Vec<(f64, f64)> {
        let n = (self.length() / step).ceil().clamp(1.0, 100_000.0) as usize;
        (0..=n).map(|k| self.at(k as f64 / n as f64)).collect()
    }

    /// Distance from `p` to the move.
    pub fn dist(&self, p: (f64, f64)) -> f64 {
        let ends = (p.0 - self.a.0)
            .hypot(p.1 - self.a.1)
            .min((p.0 - self.b.0).hypot(p.1 - self.b.1));
        match self.arc_parts() {
            Some(((cx, cy), r, a0, sweep)) => {
                let ang = (p.1 - cy).atan2(p.0 - cx);
                let mut rel = (ang - a0) * sweep.signum();
                rel = rel.rem_euclid(TAU);
                if rel <= sweep.abs() {
                    ((p.0 - cx).hypot(p.1 - cy) - r).abs().min(ends)
                } else {
                    ends
                }
            }
            None => {
                let (dx, dy) = (self.b.0 - self.a.0, self.b.1 - self.a.1);
                let l2 = dx * dx + dy * dy;
                if l2 == 0.0 {
                    return ends;
                }
                let t = (((p.0 - self.a.0) * dx + (p.1 - self.a.1) * dy) / l2).clamp(0.0, 1.0);
                (p.0 - self.a.0 - t * dx).hypot(p.1 - self.a.1 - t * dy)
            }
        }
    }
}

/// The program's moves (comments, dwells and M words skipped), from
/// (0, 0) at `z0`, in absolute coordinates: X, Y and Z words after a G91
/// are added to where the tool is, until a G90 (I and J are from the
/// start either way). Panics on a word it cannot read.
pub fn read(text: &str, z0: f64) -> Vec<XyMove> {
    let (mut x, mut y, mut z, mut g) = (0.0, 0.0, z0, 0);
    let mut rel = false;
    let mut out = Vec::new();
    for line in text.lines() {
        let mut block = line.split(';').next().unwrap_or("").to_string();
        while let (Some(a), Some(b)) = (block.find('('), block.find(')')) {
            block.replace_range(a..=b, " ");
        }
        let words: Vec<(char, f64)> = block
            .split_whitespace()
            .filter(|w| *w != "%")
            .map(|w| {
                let c = w.chars().next().unwrap().to_ascii_uppercase();
                (c, w[1..].parse::<f64>().unwrap_or_else(|_| panic!("word {w}")))
            })
            .collect();
        let word = |c: char| words.iter().find(|w| w.0 == c).map(|w| w.1);
        let mut motion = false;
        for &(c, v) in &words {
            if c == 'G' {
                match v as i32 {
                    0..=3 => {
                        g = v as i32;
                        motion = true;
                    }
                    90 if v == 90.0 => rel = false,
                    91 if v == 91.0 => rel = true,
                    _ => {}
                }
            }
        }
        let has_axis = ['X', 'Y', 'Z'].iter().any(|c| word(*c).is_some());
        if word('G') == Some(4.0) || (!motion && !has_axis) {
            continue;
        }
        let axis = |c: char, at: f64| match word(c) {
            Some(v) if rel => at + v,
            Some(v) => v,
            None => at,
        };
        let (nx, ny, nz) = (axis('X', x), axis('Y', y), axis('Z', z));
        let arc = matches!(g, 2 | 3).then(|| {
            (
                (x + word('I').unwrap_or(0.0), y + word('J').unwrap_or(0.0)),
                g == 3,
            )
        });
        out.push(XyMove {
            rapid: g == 0,
            a: (x, y),
            b: (nx, ny),
            arc,
            z: (z, nz),
        });
        (x, y, z) = (nx, ny, nz);
    }
    out
}

/// The largest distance from a point sampled every `step` mm along
/// `from` to the nearest move of `to`, and where.
pub fn farthest(from: &[XyMove], to: &[XyMove], step: f64) -> (f64, (f64, f64)) {
    let mut worst = (0.0, (0.0, 0.0));
    for m in from {
        for p in m.samples(step) {
            let d = to.iter().map(|n| n.dist(p)).fold(f64::INFINITY, f64::min);
            if d > worst.0 {
                worst = (d, p);
            }
        }
    }
    worst
}
