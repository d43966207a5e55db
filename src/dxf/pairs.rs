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

/// Parses a decimal number without allocating.
fn fast_float(t: &[u8]) -> Option<f64> {
    std::str::from_utf8(t).ok()?.parse().ok()
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
        let (line, rest) = match self.rest.iter().position(|&b| b == b'\n') {
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
        let code = std::str::from_utf8(code_line.trim_ascii())
            .ok()
            .and_then(|s| s.parse::<i32>().ok());
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
