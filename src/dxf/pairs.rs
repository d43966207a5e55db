//! Group-code/value pairs, from ASCII or binary DXF (DXF reference, "DXF
//! Format": every item is a group code and a value; in binary DXF the value's
//! type follows from the code, "Group Code Value Types").
//!
//! Readers borrow slices of the input: no string is allocated per pair, so
//! big files stream through in one pass. Text stays bytes until it is kept
//! (layer names), where [`super::text`] decodes it with the file's code page.

use std::fmt;

/// A value as the file holds it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Value<'a> {
    /// ASCII DXF values, and strings of binary DXF (raw bytes, no line end).
    Text(&'a [u8]),
    /// A binary DXF double.
    Real(f64),
    /// A binary DXF integer (8, 16, 32 or 64 bits).
    Int(i64),
}

/// One group code and its value, with where it is: the 1-based line of the
/// code in ASCII DXF, the byte offset in binary DXF.
#[derive(Clone, Copy, Debug)]
pub struct Pair<'a> {
    /// The group code.
    pub code: i32,
    /// The value.
    pub value: Value<'a>,
    /// Line (ASCII) or byte offset (binary) of the group code.
    pub at: usize,
}

impl<'a> Pair<'a> {
    /// The text value with surrounding blanks removed (empty for numbers).
    pub fn trimmed(&self) -> &'a [u8] {
        match self.value {
            Value::Text(t) => t.trim_ascii(),
            _ => b"",
        }
    }
    /// True when the value is the text `s` (blanks ignored).
    pub fn is(&self, s: &str) -> bool {
        self.trimmed() == s.as_bytes()
    }
    /// The value as a number, if it is one.
    pub fn f64(&self) -> Option<f64> {
        match self.value {
            Value::Text(t) => fast_float(t.trim_ascii()),
            Value::Real(v) => Some(v),
            Value::Int(i) => Some(i as f64),
        }
    }
    /// The value as an integer (some writers put "1.0" in integer codes).
    pub fn int(&self) -> Option<i64> {
        match self.value {
            Value::Text(t) => {
                let s = std::str::from_utf8(t.trim_ascii()).ok()?;
                s.parse::<i64>().ok().or_else(|| {
                    s.parse::<f64>()
                        .ok()
                        .filter(|v| v.is_finite())
                        .map(|v| v as i64)
                })
            }
            Value::Int(i) => Some(i),
            Value::Real(v) => v.is_finite().then_some(v as i64),
        }
    }
}

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
fn fast_float(t: &[u8]) -> Option<f64> {
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
fn digit_run(t: &[u8], mut i: usize, mut mantissa: u64) -> (usize, u64) {
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
fn word_at(t: &[u8], i: usize) -> Option<u64> {
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
fn leading_digits(w: u64) -> (usize, u64) {
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

/// Pairs from (code, text) tuples, for tests.
#[cfg(test)]
pub fn text_pairs(src: &[(i32, &'static str)]) -> Vec<Pair<'static>> {
    src.iter()
        .map(|&(code, v)| Pair {
            code,
            value: Value::Text(v.as_bytes()),
            at: 1,
        })
        .collect()
}

/// Where a pair or an error is, for messages.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Place {
    /// 1-based line of an ASCII DXF.
    Line(usize),
    /// Byte offset in a binary DXF.
    Byte(usize),
}

impl fmt::Display for Place {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Place::Line(n) => write!(f, "line {n}"),
            Place::Byte(n) => write!(f, "byte {n}"),
        }
    }
}

/// A place where the next item should be a group code but is not.
#[derive(Clone, Debug, PartialEq)]
pub struct BadCode {
    /// Where.
    pub place: Place,
    /// The offending text (shortened).
    pub text: String,
}

impl fmt::Display for BadCode {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{}: expected a group code, found '{}'",
            self.place, self.text
        )
    }
}

/// A group code: an optionally signed decimal integer (no allocation, no UTF-8 check).
fn parse_code(t: &[u8]) -> Option<i32> {
    let (neg, digits) = match t.first() {
        Some(b'-') => (true, &t[1..]),
        _ => (false, t),
    };
    if digits.is_empty() || digits.len() > 9 || !digits.iter().all(u8::is_ascii_digit) {
        return None;
    }
    let v = digits
        .iter()
        .fold(0i32, |acc, &b| acc * 10 + (b - b'0') as i32);
    Some(if neg { -v } else { v })
}

/// Index of the first `\n`, eight bytes at a time ("SIMD within a
/// register": Mycroft's zero-byte test, as in memchr's fallback). DXF lines
/// are short (a code, a number), so one or two words usually settle it.
fn find_newline(s: &[u8]) -> Option<usize> {
    const LO: u64 = 0x0101_0101_0101_0101;
    const HI: u64 = 0x8080_8080_8080_8080;
    const NL: u64 = LO * b'\n' as u64;
    let mut chunks = s.chunks_exact(8);
    let mut at = 0;
    for c in chunks.by_ref() {
        let w = u64::from_le_bytes([c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7]]) ^ NL;
        // Exact for the lowest zero byte, which is the one wanted.
        let z = w.wrapping_sub(LO) & !w & HI;
        if z != 0 {
            return Some(at + (z.trailing_zeros() / 8) as usize);
        }
        at += 8;
    }
    chunks
        .remainder()
        .iter()
        .position(|&b| b == b'\n')
        .map(|i| at + i)
}

/// Iterator over the pairs of an ASCII DXF.
pub struct AsciiPairs<'a> {
    rest: &'a [u8],
    line: usize,
    /// Set when the input ended in the middle of a pair.
    pub truncated: bool,
}

impl<'a> AsciiPairs<'a> {
    /// Reads pairs from the start of `bytes` (a UTF-8 BOM is skipped).
    pub fn new(bytes: &'a [u8]) -> Self {
        let rest = bytes.strip_prefix(b"\xEF\xBB\xBF").unwrap_or(bytes);
        AsciiPairs {
            rest,
            line: 0,
            truncated: false,
        }
    }

    fn next_line(&mut self) -> Option<&'a [u8]> {
        if self.rest.is_empty() {
            return None;
        }
        self.line += 1;
        let (line, rest) = match find_newline(self.rest) {
            Some(i) => (&self.rest[..i], &self.rest[i + 1..]),
            None => (self.rest, &self.rest[self.rest.len()..]),
        };
        self.rest = rest;
        Some(line.strip_suffix(b"\r").unwrap_or(line))
    }
}

impl<'a> AsciiPairs<'a> {
    /// The common shape of a pair, read in one pass over the bytes: a code
    /// line of blanks and up to 9 digits ending in `\n` or `\r\n`, then a
    /// value line ending in `\n`. Anything else (signs, tabs, blank lines,
    /// the last line of the file, bad codes) is left to the general path,
    /// which gives the same pairs: this only saves splitting the code line,
    /// trimming it and parsing it in three passes.
    #[inline(always)]
    fn quick(&mut self) -> Option<Pair<'a>> {
        let r = self.rest;
        let mut i = 0;
        while r.get(i) == Some(&b' ') {
            i += 1;
        }
        let start = i;
        let mut code: i32 = 0;
        while let Some(&b) = r.get(i) {
            let d = b.wrapping_sub(b'0');
            if d > 9 || i - start == 9 {
                break;
            }
            code = code * 10 + d as i32;
            i += 1;
        }
        if i == start {
            return None;
        }
        if r.get(i) == Some(&b'\r') {
            i += 1;
        }
        if r.get(i) != Some(&b'\n') {
            return None;
        }
        let v = &r[i + 1..];
        let n = find_newline(v)?;
        let value = &v[..n];
        self.rest = &v[n + 1..];
        self.line += 2;
        Some(Pair {
            code,
            value: Value::Text(value.strip_suffix(b"\r").unwrap_or(value)),
            at: self.line - 1,
        })
    }
}

impl<'a> Iterator for AsciiPairs<'a> {
    type Item = Result<Pair<'a>, BadCode>;

    #[inline(always)]
    fn next(&mut self) -> Option<Self::Item> {
        if let Some(p) = self.quick() {
            return Some(Ok(p));
        }
        self.general()
    }
}

impl<'a> AsciiPairs<'a> {
    /// Any pair: blank lines before the code skipped, the code trimmed and
    /// parsed, a missing value marks the input truncated.
    fn general(&mut self) -> Option<Result<Pair<'a>, BadCode>> {
        let code_line = loop {
            let l = self.next_line()?;
            // Blank lines where a code is due are trailing junk some writers add.
            if !l.trim_ascii().is_empty() {
                break l;
            }
        };
        let line = self.line;
        let code = parse_code(code_line.trim_ascii());
        let Some(code) = code else {
            let text: String = String::from_utf8_lossy(code_line)
                .chars()
                .take(40)
                .collect();
            self.rest = &[];
            return Some(Err(BadCode {
                place: Place::Line(line),
                text,
            }));
        };
        match self.next_line() {
            Some(value) => Some(Ok(Pair {
                code,
                value: Value::Text(value),
                at: line,
            })),
            None => {
                self.truncated = true;
                None
            }
        }
    }
}

#[cfg(test)]
#[path = "pairs_tests.rs"]
mod tests;
