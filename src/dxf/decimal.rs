//! Decimal numbers of a DXF read without allocating: Clinger's fast path
//! for the short decimals files are made of, eight digits at a time.

/// Powers of ten exactly representable as f64.
const EXACT_POW10: [f64; 23] = [
    1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15, 1e16,
    1e17, 1e18, 1e19, 1e20, 1e21, 1e22,
];

/// Parses a decimal number without allocating.
///
/// DXF numbers are mostly short decimals ("123.456789"): those take
/// Clinger's fast path — an integer mantissa below 2^53 and a power of ten
/// up to 10^22 are both exact doubles, so one multiplication or division
/// gives the correctly rounded result, bit for bit what `str::parse` gives.
/// Anything else (exponents, long mantissas, junk) goes to `str::parse`.
pub(super) fn fast_float(t: &[u8]) -> Option<f64> {
    let (neg, digits) = match t.first() {
        Some(b'-') => (true, &t[1..]),
        Some(b'+') => (false, &t[1..]),
        _ => (false, t),
    };
    let (mut i, int_part) = digit_run(digits, 0, 0);
    let int_digits = i;
    let mut frac = 0;
    if digits.get(i) == Some(&b'.') {
        (i, frac) = digit_run(digits, i + 1, 0);
    }
    let frac_digits = (i - int_digits).saturating_sub(1);
    let n_digits = int_digits + frac_digits;
    // Junk after the digits, no digits, or too many for an exact mantissa.
    if i != digits.len() || n_digits == 0 || n_digits > 15 {
        return std::str::from_utf8(t).ok()?.parse().ok();
    }
    // Whole numbers ("1250.000000", most coordinates of a nest) need no
    // division: the quotient is exactly the integer part, below 2^53.
    let v = if frac == 0 {
        int_part as f64
    } else {
        (int_part * POW10_U64[frac_digits] + frac) as f64 / EXACT_POW10[frac_digits]
    };
    Some(if neg { -v } else { v })
}

/// Powers of ten as integers up to 10^15: to join integer and fraction
/// digits, and to append up to 8 digits to a mantissa.
const POW10_U64: [u64; 16] = [
    1,
    10,
    100,
    1_000,
    10_000,
    100_000,
    1_000_000,
    10_000_000,
    100_000_000,
    1_000_000_000,
    10_000_000_000,
    100_000_000_000,
    1_000_000_000_000,
    10_000_000_000_000,
    100_000_000_000_000,
    1_000_000_000_000_000,
];

/// The digits of `t` from `i` appended to `mantissa` (wrapping: callers
/// count the digits and refuse more than 15); returns the index after them.
/// Eight bytes at a time when the text has eight (numbers are most of a
/// DXF's bytes, and a digit at a time costs a branch each).
#[inline]
pub(super) fn digit_run(t: &[u8], mut i: usize, mut mantissa: u64) -> (usize, u64) {
    if t.len() >= 8 {
        while let Some(w) = word_at(t, i) {
            let (n, v) = leading_digits(w);
            mantissa = mantissa.wrapping_mul(POW10_U64[n]).wrapping_add(v);
            i += n;
            if n < 8 {
                return (i, mantissa);
            }
        }
    }
    while let Some(&b) = t.get(i) {
        let d = b.wrapping_sub(b'0');
        if d > 9 {
            break;
        }
        mantissa = mantissa.wrapping_mul(10).wrapping_add(d as u64);
        i += 1;
    }
    (i, mantissa)
}

/// Bytes `i..i + 8` of `t` as a little-endian word, with zero bytes past the
/// end of `t`; None when `t` is shorter than 8 bytes or `i` past its end.
#[inline]
pub(super) fn word_at(t: &[u8], i: usize) -> Option<u64> {
    if let Some(c) = t.get(i..i + 8) {
        return Some(u64::from_le_bytes(c.try_into().ok()?));
    }
    // Near the end: the last 8 bytes, shifted down past those before `i`.
    let c = t.get(t.len().checked_sub(8)?..)?;
    let drop = (i + 8).checked_sub(t.len()).filter(|&d| d <= 8)?;
    let w = u64::from_le_bytes(c.try_into().ok()?);
    Some(if drop == 8 { 0 } else { w >> (8 * drop) })
}

/// How many ASCII digits the word starts with (its lowest bytes, 0 to 8) and
/// their value: the SWAR digit test and combine of simdjson and fast_float
/// (mark non-digits with two masks; then pairs, quads and halves with three
/// multiplications).
#[inline]
pub(super) fn leading_digits(w: u64) -> (usize, u64) {
    const LO: u64 = 0x0101_0101_0101_0101;
    // Digits become 0..=9; a byte is a non-digit when its high nibble is set,
    // or when adding 6 sets it (10..=15). A carry out of a non-digit byte
    // can only disturb bytes after it, never the first non-digit.
    let x = w ^ (LO * b'0' as u64);
    let not_digit = (x | x.wrapping_add(LO * 6)) & (LO * 0xF0);
    let n = (not_digit.trailing_zeros() / 8) as usize;
    if n == 0 {
        return (0, 0);
    }
    // The n digits to the top bytes, zeros (leading zeros) below them.
    let mut v = x << (8 * (8 - n));
    v = (v.wrapping_mul(10).wrapping_add(v >> 8)) & 0x00FF_00FF_00FF_00FF;
    v = (v.wrapping_mul(100).wrapping_add(v >> 16)) & 0x0000_FFFF_0000_FFFF;
    v = v.wrapping_mul(10_000).wrapping_add(v >> 32) & 0xFFFF_FFFF;
    (n, v)
}
