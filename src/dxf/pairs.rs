//! Group-code/value pairs, from ASCII or binary DXF (DXF reference, "DXF
//! Format": every item is a group code and a value; in binary DXF the value's
//! type follows from the code, "Group Code Value Types").
//!
//! Readers borrow slices of the input: no string is allocated per pair, so
//! big files stream through in one pass. Text stays bytes until it is kept
//! (layer names), where [`super::text`] decodes it with the file's code page.

use std::fmt;

use super::decimal::fast_float;

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
pub(super) fn parse_code(t: &[u8]) -> Option<i32> {
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
pub(super) fn find_newline(s: &[u8]) -> Option<usize> {
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
    /// The bytes not read yet.
    pub(super) rest: &'a [u8],
    /// Lines read so far (the next pair's code is on line `line + 1`).
    pub(super) line: usize,
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

/// A source of pairs that can also append an entity's body in one call.
pub trait Source<'a>: Iterator<Item = Result<Pair<'a>, BadCode>> + Sized {
    /// The ASCII reader, whose ENTITIES section may be cut into chunks
    /// read on several threads ([`super::chunks`]); None for binary DXF.
    fn ascii(&mut self) -> Option<&mut AsciiPairs<'a>> {
        None
    }

    /// Appends pairs to `buf` up to the next `0` pair and returns that one
    /// (or the bad group code met, or None at the end of the input).
    fn body_into(&mut self, buf: &mut Vec<Pair<'a>>) -> Option<Result<Pair<'a>, BadCode>> {
        for r in self.by_ref() {
            match r {
                Ok(p) if p.code != 0 => buf.push(p),
                other => return Some(other),
            }
        }
        None
    }
}

impl<'a> Source<'a> for AsciiPairs<'a> {
    fn ascii(&mut self) -> Option<&mut AsciiPairs<'a>> {
        Some(self)
    }

    #[inline]
    fn body_into(&mut self, buf: &mut Vec<Pair<'a>>) -> Option<Result<Pair<'a>, BadCode>> {
        loop {
            match self.quick() {
                Some(p) if p.code != 0 => buf.push(p),
                Some(p) => return Some(Ok(p)),
                None => match self.general()? {
                    Ok(p) if p.code != 0 => buf.push(p),
                    other => return Some(other),
                },
            }
        }
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
