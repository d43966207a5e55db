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
    let mut mantissa: u64 = 0;
    let mut n_digits = 0;
    let mut frac_digits: usize = 0;
    let mut seen_dot = false;
    for &b in digits {
        match b {
            b'0'..=b'9' => {
                mantissa = mantissa.wrapping_mul(10).wrapping_add((b - b'0') as u64);
                n_digits += 1;
                if seen_dot {
                    frac_digits += 1;
                }
            }
            b'.' if !seen_dot => seen_dot = true,
            _ => return std::str::from_utf8(t).ok()?.parse().ok(),
        }
    }
    if n_digits == 0 || n_digits > 15 || frac_digits > 22 {
        return std::str::from_utf8(t).ok()?.parse().ok();
    }
    let v = mantissa as f64 / EXACT_POW10[frac_digits];
    Some(if neg { -v } else { v })
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

impl<'a> Iterator for AsciiPairs<'a> {
    type Item = Result<Pair<'a>, BadCode>;

    fn next(&mut self) -> Option<Self::Item> {
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
mod tests {
    use super::*;

    #[test]
    fn reads_pairs_with_crlf_and_padding() {
        let src = b"  0\r\nSECTION\r\n  2\r\nENTITIES\r\n 10\r\n1.5 \r\n";
        let pairs: Vec<_> = AsciiPairs::new(src).map(Result::unwrap).collect();
        assert_eq!(pairs.len(), 3);
        assert!(pairs[0].is("SECTION"));
        assert_eq!(pairs[1].at, 3);
        assert_eq!(pairs[2].f64(), Some(1.5));
    }

    #[test]
    fn a_non_numeric_code_is_reported_with_its_line() {
        let mut it = AsciiPairs::new(b"0\nSECTION\nhello\nx\n");
        assert!(it.next().unwrap().is_ok());
        let err = it.next().unwrap().unwrap_err();
        assert_eq!(err.place, Place::Line(3));
        assert!(it.next().is_none());
    }

    #[test]
    fn a_missing_value_marks_the_input_truncated() {
        let mut it = AsciiPairs::new(b"0\nLINE\n10");
        assert!(it.next().unwrap().is_ok());
        assert!(it.next().is_none());
        assert!(it.truncated);
    }

    #[test]
    fn fast_float_matches_the_standard_parser_bit_for_bit() {
        let mut x = 0x9e37_79b9_7f4a_7c15u64;
        for _ in 0..200_000 {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            let int = x % 1_000_000_000;
            let frac_len = (x >> 40) as usize % 8;
            let frac = (x >> 20) % 10u64.pow(frac_len as u32);
            let sign = if x & 1 == 1 { "-" } else { "" };
            let text = if frac_len == 0 {
                format!("{sign}{int}")
            } else {
                format!("{sign}{int}.{frac:0frac_len$}")
            };
            let want: f64 = text.parse().unwrap();
            assert_eq!(
                fast_float(text.as_bytes()).map(f64::to_bits),
                Some(want.to_bits()),
                "{text}"
            );
        }
        for text in [
            "1e3",
            "-2.5E-3",
            "0.000000000000000000000001",
            "12345678901234567890.5",
            "nan",
            "inf",
            ".5",
            "5.",
            "-",
        ] {
            assert_eq!(
                fast_float(text.as_bytes()).map(f64::to_bits),
                text.parse::<f64>().ok().map(f64::to_bits),
                "{text}"
            );
        }
    }

    #[test]
    fn newline_search_agrees_with_a_plain_scan() {
        let text = b"0\nLINE\n  10\n12345.678901\r\nabcdefghijklmnopq\n\n\xff\x8a\n\n\n";
        for from in 0..text.len() {
            for to in from..=text.len() {
                let s = &text[from..to];
                assert_eq!(find_newline(s), s.iter().position(|&b| b == b'\n'));
            }
        }
    }

    #[test]
    fn group_codes_parse_without_utf8_checks() {
        assert_eq!(parse_code(b"999"), Some(999));
        assert_eq!(parse_code(b"-5"), Some(-5));
        for bad in [&b""[..], b"-", b"1x", b"1234567890", b"\xff"] {
            assert_eq!(parse_code(bad), None);
        }
    }

    #[test]
    fn integer_codes_accept_float_text() {
        let p = Pair {
            code: 70,
            value: Value::Text(b" 1.0"),
            at: 1,
        };
        assert_eq!(p.int(), Some(1));
        assert_eq!(
            Pair {
                code: 10,
                value: Value::Int(3),
                at: 0
            }
            .f64(),
            Some(3.0)
        );
    }
}
