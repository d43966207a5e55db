//! The machine's number grid: coordinates as integers of `10^-decimals` mm,
//! so positions are tracked exactly and printed without float noise.

use crate::geom::Point;

/// A fixed-decimal grid.
#[derive(Clone, Copy, Debug)]
pub struct Grid {
    decimals: u32,
    scale: f64,
    zeros: bool,
}

/// Grid points tried around an arc's true centre, each way.
const CENTRE_SEARCH: i64 = 3;

impl Grid {
    /// A grid of `decimals` places (clamped to 1..=6).
    pub fn new(decimals: u32) -> Self {
        let decimals = decimals.clamp(1, 6);
        Grid {
            decimals,
            scale: 10f64.powi(decimals as i32),
            zeros: false,
        }
    }
    /// The same grid printing every decimal (`10.0`) when `keep` is true.
    pub fn with_trailing_zeros(mut self, keep: bool) -> Self {
        self.zeros = keep;
        self
    }
    /// Grid units per mm (10^decimals).
    pub fn scale(&self) -> f64 {
        self.scale
    }
    /// One grid step in mm.
    pub fn step(&self) -> f64 {
        1.0 / self.scale
    }
    /// The grid point nearest `p`.
    pub fn snap(&self, p: Point) -> (i64, i64) {
        (
            (p.x * self.scale).round() as i64,
            (p.y * self.scale).round() as i64,
        )
    }
    /// A grid value as text: no exponent, no trailing zeros, no "-0".
    pub fn fmt(&self, v: i64) -> String {
        let mut s = String::with_capacity(12);
        self.push(&mut s, v);
        s
    }
    /// [`Grid::fmt`] appended to `out`, without allocating: a program of
    /// hundreds of thousands of blocks writes millions of numbers.
    pub fn push(&self, out: &mut String, v: i64) {
        let a = v.unsigned_abs();
        let unit = 10u64.pow(self.decimals);
        let (int, mut frac) = (a / unit, a % unit);
        if v < 0 {
            out.push('-');
        }
        push_digits(out, int);
        if frac != 0 || self.zeros {
            let mut width = self.decimals as usize;
            if !self.zeros {
                while frac % 10 == 0 && width > 0 {
                    frac /= 10;
                    width -= 1;
                }
            }
            out.push('.');
            let mut buf = [b'0'; 6];
            for d in buf[..width].iter_mut().rev() {
                *d = b'0' + (frac % 10) as u8;
                frac /= 10;
            }
            // ASCII digits only.
            out.extend(buf[..width].iter().map(|&b| b as char));
        }
    }
    /// A millimetre value (not a position) as text on this grid.
    pub fn fmt_mm(&self, v: f64) -> String {
        if v.is_finite() {
            // `as` saturates: a huge value cannot wrap or panic.
            self.fmt((v * self.scale).round() as i64)
        } else {
            "0".into()
        }
    }
    /// I/J (grid units, relative to `start`) of the grid point near the
    /// true centre `c` whose distances to `start` and `end` differ least;
    /// None when no candidate gets within one grid step.
    pub fn arc_center(&self, start: (i64, i64), end: (i64, i64), c: Point) -> Option<(i64, i64)> {
        let c0 = self.snap(c);
        let mut best: Option<(f64, f64, (i64, i64))> = None;
        for dx in -CENTRE_SEARCH..=CENTRE_SEARCH {
            for dy in -CENTRE_SEARCH..=CENTRE_SEARCH {
                let q = (c0.0 + dx, c0.1 + dy);
                let rs =
                    (((start.0 - q.0) as f64).powi(2) + ((start.1 - q.1) as f64).powi(2)).sqrt();
                let re = (((end.0 - q.0) as f64).powi(2) + ((end.1 - q.1) as f64).powi(2)).sqrt();
                let diff = (rs - re).abs();
                let moved = ((dx * dx + dy * dy) as f64).sqrt();
                if best
                    .is_none_or(|(bd, bm, _)| diff < bd - 1e-9 || (diff <= bd + 1e-9 && moved < bm))
                {
                    best = Some((diff, moved, q));
                }
            }
        }
        let (diff, _, q) = best?;
        // A zero radius would be no arc at all.
        (diff <= 1.0 && q != start).then_some((q.0 - start.0, q.1 - start.1))
    }
}

/// The decimal digits of `n`.
fn push_digits(out: &mut String, mut n: u64) {
    let mut buf = [0u8; 20];
    let mut i = buf.len();
    loop {
        i -= 1;
        buf[i] = b'0' + (n % 10) as u8;
        n /= 10;
        if n == 0 {
            break;
        }
    }
    out.extend(buf[i..].iter().map(|&b| b as char));
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn formats_without_noise() {
        let g = Grid::new(3);
        assert_eq!(g.fmt(0), "0");
        assert_eq!(g.fmt(-1), "-0.001");
        assert_eq!(g.fmt(12_500), "12.5");
        assert_eq!(g.fmt(-40_000), "-40");
        assert_eq!(g.fmt_mm(-0.0001), "0");
        let z = Grid::new(1).with_trailing_zeros(true);
        assert_eq!(z.fmt(100), "10.0");
        assert_eq!(z.fmt(0), "0.0");
        assert_eq!(z.fmt(-5), "-0.5");
        assert_eq!(g.fmt(i64::MIN + 1), "-9223372036854775.807");
        assert_eq!(Grid::new(6).fmt(1_000_001), "1.000001");
        assert_eq!(Grid::new(6).fmt(1_100_000), "1.1");
        assert_eq!(
            Grid::new(6).with_trailing_zeros(true).fmt(1_100_000),
            "1.100000"
        );
    }

    #[test]
    fn no_number_prints_as_minus_zero_nan_exponent_or_comma() {
        // A deterministic sweep over awkward values (property test).
        let mut x: u64 = 0x9E37_79B9_7F4A_7C15;
        for d in 1..=6 {
            let g = Grid::new(d);
            for _ in 0..2000 {
                x ^= x << 13;
                x ^= x >> 7;
                x ^= x << 17;
                let mag = 10f64.powi((x % 20) as i32 - 10);
                let v = ((x >> 11) as f64 / (1u64 << 53) as f64 - 0.5) * mag;
                for s in [
                    g.fmt_mm(v),
                    g.fmt_mm(-v),
                    g.fmt_mm(f64::NAN),
                    g.fmt_mm(1e300),
                ] {
                    assert!(s.parse::<f64>().is_ok(), "{s}");
                    assert!(!s.contains(['e', 'E', ',', 'N', 'i']), "{s}");
                    assert!(s
                        .chars()
                        .all(|c| c.is_ascii_digit() || c == '-' || c == '.'));
                    if let Some(rest) = s.strip_prefix('-') {
                        assert!(rest.chars().any(|c| ('1'..='9').contains(&c)), "{s}");
                    }
                }
            }
        }
    }

    #[test]
    fn arc_centre_keeps_both_radii_within_a_step() {
        let g = Grid::new(3);
        // Quarter circle r = 7.0711 from an awkward angle.
        let c = Point::new(1.23456, -2.34567);
        let r = 7.07107;
        let a = Point::new(c.x + r * 0.3f64.cos(), c.y + r * 0.3f64.sin());
        let b = Point::new(c.x + r * 1.9f64.cos(), c.y + r * 1.9f64.sin());
        let (s, e) = (g.snap(a), g.snap(b));
        let (i, j) = g.arc_center(s, e, c).unwrap();
        let q = (s.0 + i, s.1 + j);
        let rs = (((s.0 - q.0) as f64).powi(2) + ((s.1 - q.1) as f64).powi(2)).sqrt();
        let re = (((e.0 - q.0) as f64).powi(2) + ((e.1 - q.1) as f64).powi(2)).sqrt();
        assert!((rs - re).abs() <= 1.0);
    }
}
