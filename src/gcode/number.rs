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
    /// hundreds of thousands of blocks writes millions of numbers. The
    /// digits are put together in a buffer on the stack, right to left, and
    /// appended in one go (a character at a time was a tenth of the
    /// writer's time).
    pub fn push(&self, out: &mut String, v: i64) {
        let (buf, i) = self.digits(v);
        // ASCII digits, '.' and '-' only: always UTF-8.
        out.push_str(std::str::from_utf8(&buf[i..]).unwrap_or_default());
    }
    /// [`Grid::push`] onto bytes (the writer's program: no UTF-8 check
    /// a number, one for the whole program).
    pub(crate) fn push_bytes(&self, out: &mut Vec<u8>, v: i64) {
        let (buf, i) = self.digits(v);
        out.extend_from_slice(&buf[i..]);
    }
    /// The text of `v` in `buf[i..]`.
    fn digits(&self, v: i64) -> ([u8; 28], usize) {
        let a = v.unsigned_abs();
        let unit = POW10[self.decimals as usize];
        let (mut int, mut frac) = (a / unit, a % unit);
        // Sign, 20 integer digits, point, 6 decimals.
        let mut buf = [b'0'; 28];
        let mut i = buf.len();
        if frac != 0 || self.zeros {
            let mut width = self.decimals as usize;
            if !self.zeros {
                while frac % 10 == 0 && width > 0 {
                    frac /= 10;
                    width -= 1;
                }
            }
            for _ in 0..width {
                i -= 1;
                buf[i] = b'0' + (frac % 10) as u8;
                frac /= 10;
            }
            i -= 1;
            buf[i] = b'.';
        }
        loop {
            i -= 1;
            buf[i] = b'0' + (int % 10) as u8;
            int /= 10;
            if int == 0 {
                break;
            }
        }
        if v < 0 {
            i -= 1;
            buf[i] = b'-';
        }
        (buf, i)
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
        let sq = |p: (i64, i64), q: (i64, i64)| {
            ((p.0 - q.0) as f64).powi(2) + ((p.1 - q.1) as f64).powi(2)
        };
        // The two radii differ by |rs² − re²| / (rs + re): with `reach` at
        // least rs + re for every candidate, `|rs² − re²| / reach` is a
        // lower bound on the difference that needs no square root (compared
        // multiplied out: no division either). A
        // candidate whose bound already loses to the best so far (beyond
        // the tie margin, and beyond rounding: `slack`) is skipped, so the
        // search takes the same candidates in the same order as a full
        // scan and returns the same point; on a circle most of the 49 are
        // skipped (the search was a quarter of the G-code writer's time).
        // The nearest grid point first: when its radii agree within the tie
        // margin (most arcs of a drawing on round numbers) it wins the scan
        // below whatever came before it (no difference is below 0 − 1e-9,
        // and on a tie it has moved least: 0), and nothing after beats it
        // (the same two reasons), so it is the answer without the scan.
        let (s0, e0) = (sq(start, c0), sq(end, c0));
        if (s0.sqrt() - e0.sqrt()).abs() <= 1e-9 {
            return (c0 != start).then_some((c0.0 - start.0, c0.1 - start.1));
        }
        let far = (CENTRE_SEARCH as f64) * std::f64::consts::SQRT_2;
        let reach = sq(start, c0).sqrt() + sq(end, c0).sqrt() + 2.0 * far + 1.0;
        let slack = 1e-12 * reach;
        let mut best: Option<(f64, f64, (i64, i64))> = None;
        for dx in -CENTRE_SEARCH..=CENTRE_SEARCH {
            for dy in -CENTRE_SEARCH..=CENTRE_SEARCH {
                let q = (c0.0 + dx, c0.1 + dy);
                let (s2, e2) = (sq(start, q), sq(end, q));
                if let Some((bd, _, _)) = best {
                    if (s2 - e2).abs() > (bd + 1e-9 + slack) * reach {
                        continue;
                    }
                }
                let diff = (s2.sqrt() - e2.sqrt()).abs();
                let wins = |moved: f64, (bd, bm): (f64, f64)| {
                    diff < bd - 1e-9 || (diff <= bd + 1e-9 && moved < bm)
                };
                let moved = || ((dx * dx + dy * dy) as f64).sqrt();
                if best.is_none_or(|(bd, bm, _)| wins(moved(), (bd, bm))) {
                    best = Some((diff, moved(), q));
                }
            }
        }
        let (diff, _, q) = best?;
        // A zero radius would be no arc at all.
        (diff <= 1.0 && q != start).then_some((q.0 - start.0, q.1 - start.1))
    }
}

/// `n` in decimal appended to `out`.
pub(crate) fn push_u64(out: &mut String, n: u64) {
    let (buf, i) = u64_digits(n);
    out.push_str(std::str::from_utf8(&buf[i..]).unwrap_or_default());
}

/// [`push_u64`] onto bytes.
pub(crate) fn push_u64_bytes(out: &mut Vec<u8>, n: u64) {
    let (buf, i) = u64_digits(n);
    out.extend_from_slice(&buf[i..]);
}

/// The decimal digits of `n` in `buf[i..]`.
fn u64_digits(mut n: u64) -> ([u8; 20], usize) {
    let mut buf = [b'0'; 20];
    let mut i = buf.len();
    loop {
        i -= 1;
        buf[i] = b'0' + (n % 10) as u8;
        n /= 10;
        if n == 0 {
            break;
        }
    }
    (buf, i)
}

/// 10^k for the grid's 0..=6 decimals.
const POW10: [u64; 7] = [1, 10, 100, 1_000, 10_000, 100_000, 1_000_000];

#[cfg(test)]
mod tests {
    use super::*;

    /// The text `Grid::push` must write, by `format!` (independent of it).
    fn reference(v: i64, decimals: u32, zeros: bool) -> String {
        let unit = 10u64.pow(decimals);
        let a = v.unsigned_abs();
        let sign = if v < 0 { "-" } else { "" };
        let frac = format!("{:0w$}", a % unit, w = decimals as usize);
        let frac = if zeros {
            frac.as_str()
        } else {
            frac.trim_end_matches('0')
        };
        if frac.is_empty() {
            format!("{sign}{}", a / unit)
        } else {
            format!("{sign}{}.{frac}", a / unit)
        }
    }

    #[test]
    fn push_writes_what_format_writes() {
        let mut x: u64 = 0x2545_F491_4F6C_DD1D;
        for d in 1..=6 {
            for zeros in [false, true] {
                let g = Grid::new(d).with_trailing_zeros(zeros);
                for k in 0..4000 {
                    x ^= x << 13;
                    x ^= x >> 7;
                    x ^= x << 17;
                    // Every magnitude, small ones often, and the extremes.
                    let v = match k {
                        0 => i64::MIN,
                        1 => i64::MAX,
                        2 => 0,
                        _ => (x as i64) >> (x % 64),
                    };
                    assert_eq!(g.fmt(v), reference(v, d, zeros), "{v} at {d} decimals");
                }
            }
        }
        let mut n = String::new();
        push_u64(&mut n, 0);
        push_u64(&mut n, u64::MAX);
        assert_eq!(n, format!("0{}", u64::MAX));
    }

    /// The centre search without the pruning: every one of the 49 points.
    fn full_scan(start: (i64, i64), end: (i64, i64), c0: (i64, i64)) -> Option<(i64, i64)> {
        let mut best: Option<(f64, f64, (i64, i64))> = None;
        for dx in -CENTRE_SEARCH..=CENTRE_SEARCH {
            for dy in -CENTRE_SEARCH..=CENTRE_SEARCH {
                let q = (c0.0 + dx, c0.1 + dy);
                let r = |p: (i64, i64)| {
                    (((p.0 - q.0) as f64).powi(2) + ((p.1 - q.1) as f64).powi(2)).sqrt()
                };
                let diff = (r(start) - r(end)).abs();
                let moved = ((dx * dx + dy * dy) as f64).sqrt();
                if best
                    .is_none_or(|(bd, bm, _)| diff < bd - 1e-9 || (diff <= bd + 1e-9 && moved < bm))
                {
                    best = Some((diff, moved, q));
                }
            }
        }
        let (diff, _, q) = best?;
        (diff <= 1.0 && q != start).then_some((q.0 - start.0, q.1 - start.1))
    }

    #[test]
    fn pruned_centre_search_picks_what_the_full_scan_picks() {
        let mut x: u64 = 77;
        let mut f = || {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            (x >> 11) as f64 / (1u64 << 53) as f64
        };
        for d in [1, 3, 4, 6] {
            let g = Grid::new(d);
            for _ in 0..3000 {
                // Arcs of every size and sweep, centres on and off the grid,
                // some axis-aligned (ties along a grid line).
                let r = 10f64.powf(f() * 6.0 - 2.0);
                let c = Point::new((f() - 0.5) * 2000.0, (f() - 0.5) * 2000.0);
                // A third on round numbers: the centre and radius on the grid
                // (the nearest point's radii agree: the search's shortcut).
                let (r, c) = if f() < 0.33 {
                    let on = |v: f64| (v * g.scale()).round() / g.scale();
                    (on(r).max(g.step()), Point::new(on(c.x), on(c.y)))
                } else {
                    (r, c)
                };
                let (a0, sweep) = if f() < 0.3 {
                    (
                        (f() * 4.0).floor() * std::f64::consts::FRAC_PI_2,
                        std::f64::consts::PI * (1.0 + (f() * 2.0).floor()) / 2.0,
                    )
                } else {
                    (
                        f() * std::f64::consts::TAU,
                        (f() - 0.5) * 2.0 * std::f64::consts::PI,
                    )
                };
                let at = |t: f64| g.snap(Point::new(c.x + r * t.cos(), c.y + r * t.sin()));
                let (s, e) = (at(a0), at(a0 + sweep));
                assert_eq!(
                    g.arc_center(s, e, c),
                    full_scan(s, e, g.snap(c)),
                    "r {r} at {d} decimals"
                );
            }
        }
    }

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
