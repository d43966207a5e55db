//! The machine's number grid: coordinates as integers of `10^-decimals` mm,
//! so positions are tracked exactly and printed without float noise.

use super::bytes::Bytes;
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
        (round_i64(p.x * self.scale), round_i64(p.y * self.scale))
    }
    /// A grid value as text: no exponent, no trailing zeros, no "-0".
    pub fn fmt(&self, v: i64) -> String {
        let mut s = String::with_capacity(12);
        self.push(&mut s, v);
        s
    }
    /// [`Grid::fmt`] appended to `out`, without allocating: a program of
    /// hundreds of thousands of blocks writes millions of numbers. The
    /// digits are put together in a buffer on the stack and appended in
    /// one go (a character at a time was a tenth of the writer's time).
    pub fn push(&self, out: &mut String, v: i64) {
        let mut buf = [b'0'; WINDOW];
        let len = self.write(&mut buf, v);
        // ASCII digits, '.' and '-' only: always UTF-8.
        out.push_str(std::str::from_utf8(&buf[..len]).unwrap_or_default());
    }
    /// [`Grid::push`] onto bytes (the writer's program: no UTF-8 check a
    /// number, one for the whole program). The whole buffer is copied, a
    /// copy of fixed size (a few moves, where one of the number's length
    /// was a call into `memcpy`), and only the number's length kept
    /// ([`Bytes::put_window`]).
    pub(crate) fn push_bytes(&self, out: &mut Bytes, v: i64) {
        let mut buf = [b'0'; WINDOW];
        let len = self.write(&mut buf, v);
        out.put_window(&buf, len);
    }
    /// The text of `v` at the start of `buf` (at least [`WINDOW`] bytes
    /// of '0'), by the grid's decimals (each a division by a constant: a
    /// multiplication, where a division by the run-time `10^decimals` was
    /// two hardware divides a number); its length.
    fn write(&self, buf: &mut [u8], v: i64) -> usize {
        match self.decimals {
            1 => write_of::<1>(buf, v, self.zeros),
            2 => write_of::<2>(buf, v, self.zeros),
            3 => write_of::<3>(buf, v, self.zeros),
            4 => write_of::<4>(buf, v, self.zeros),
            5 => write_of::<5>(buf, v, self.zeros),
            _ => write_of::<6>(buf, v, self.zeros),
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
        // Equal squared radii are equal radii (a corner or a circle on
        // round numbers): no square root needed to see it.
        let (s0, e0) = (sq(start, c0), sq(end, c0));
        if s0 == e0 || (s0.sqrt() - e0.sqrt()).abs() <= 1e-9 {
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
pub(crate) fn push_u64_bytes(out: &mut Bytes, n: u64) {
    let (buf, i) = u64_digits(n);
    out.extend_from_slice(&buf[i..]);
}

/// The decimal digits of `n` in `buf[i..]`.
fn u64_digits(n: u64) -> ([u8; 20], usize) {
    let mut buf = [b'0'; 20];
    let i = put_int(&mut buf, 20, n);
    (buf, i)
}

/// "00", "01", … "99": two digits a division.
const PAIRS: &[u8; 200] = b"\
0001020304050607080910111213141516171819\
2021222324252627282930313233343536373839\
4041424344454647484950515253545556575859\
6061626364656667686970717273747576777879\
8081828384858687888990919293949596979899";

/// `n` in decimal written into `buf` ending before `end`, two digits at a
/// time; the index of its first digit.
#[inline]
fn put_int(buf: &mut [u8], end: usize, mut n: u64) -> usize {
    let mut i = end;
    while n >= 100 {
        let r = (n % 100) as usize * 2;
        n /= 100;
        i -= 2;
        buf[i..i + 2].copy_from_slice(&PAIRS[r..r + 2]);
    }
    if n >= 10 {
        let r = n as usize * 2;
        i -= 2;
        buf[i..i + 2].copy_from_slice(&PAIRS[r..r + 2]);
    } else {
        i -= 1;
        buf[i] = b'0' + n as u8;
    }
    i
}

/// The longest number: sign, 20 integer digits, point, 6 decimals.
const WINDOW: usize = 28;

/// A grid value of `D` decimals as text at the start of `buf` (at least
/// [`WINDOW`] bytes of '0'): no exponent, no trailing zeros unless
/// `zeros`, no "-0"; its length.
#[inline]
fn write_of<const D: u32>(buf: &mut [u8], v: i64, zeros: bool) -> usize {
    let unit = 10u64.pow(D);
    let a = v.unsigned_abs();
    let (int, mut frac) = (a / unit, a % unit);
    let mut width = 0;
    if frac != 0 || zeros {
        width = D as usize;
        if !zeros {
            while frac % 10 == 0 {
                frac /= 10;
                width -= 1;
            }
        }
    }
    let sign = usize::from(v < 0);
    let point = sign + int.checked_ilog10().map_or(1, |l| l as usize + 1);
    buf[0] = b'-';
    put_int(buf, point, int);
    if width == 0 {
        return point;
    }
    buf[point] = b'.';
    // `frac` has at most `width` digits; the ones it lacks are the
    // buffer's zeros.
    let len = point + 1 + width;
    put_int(buf, len, frac);
    len
}

/// `x.round() as i64` (half away from zero, saturating, NaN to 0) without
/// `round`, which the x86-64 baseline has no instruction for (a call a
/// coordinate): the truncation is exact, and so is `x` minus it.
#[inline]
pub(crate) fn round_i64(x: f64) -> i64 {
    let t = x as i64;
    let rest = x - t as f64;
    if rest >= 0.5 {
        t.saturating_add(1)
    } else if rest <= -0.5 {
        t.saturating_sub(1)
    } else {
        t
    }
}

#[cfg(test)]
#[path = "number_tests.rs"]
mod tests;
