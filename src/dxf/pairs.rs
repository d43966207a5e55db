//! Group-code/value pairs of an ASCII DXF file (DXF reference, "DXF Format":
//! every item is two lines, an integer group code then its value).
//!
//! The reader borrows slices of the input: no string is allocated per pair,
//! so big files stream through in one pass. Values stay bytes; text is decoded
//! only where it is kept (layer names), so a later code-page decoder fits here.

use std::fmt;

/// One group code and its value, with the 1-based line of the code.
#[derive(Clone, Copy, Debug)]
pub struct Pair<'a> {
    /// The group code.
    pub code: i32,
    /// The raw value line, without its line ending.
    pub value: &'a [u8],
    /// Line number (1-based) of the group code.
    pub line: usize,
}

impl<'a> Pair<'a> {
    /// The value with surrounding blanks removed.
    pub fn trimmed(&self) -> &'a [u8] {
        self.value.trim_ascii()
    }
    /// True when the value equals `s` (blanks ignored).
    pub fn is(&self, s: &str) -> bool {
        self.trimmed() == s.as_bytes()
    }
    /// The value as a number, if it is one.
    pub fn f64(&self) -> Option<f64> {
        std::str::from_utf8(self.trimmed()).ok()?.parse().ok()
    }
    /// The value as an integer (some writers put "1.0" in integer codes).
    pub fn int(&self) -> Option<i64> {
        let s = std::str::from_utf8(self.trimmed()).ok()?;
        s.parse::<i64>().ok().or_else(|| {
            s.parse::<f64>()
                .ok()
                .filter(|v| v.is_finite())
                .map(|v| v as i64)
        })
    }
    /// The value as text (invalid UTF-8 replaced), for names and messages.
    pub fn text(&self) -> String {
        String::from_utf8_lossy(self.trimmed()).into_owned()
    }
}

/// A line that should hold a group code but does not.
#[derive(Clone, Debug, PartialEq)]
pub struct BadCode {
    /// 1-based line number.
    pub line: usize,
    /// The offending text (shortened).
    pub text: String,
}

impl fmt::Display for BadCode {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "line {}: expected a group code, found '{}'",
            self.line, self.text
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
            return Some(Err(BadCode { line, text }));
        };
        match self.next_line() {
            Some(value) => Some(Ok(Pair { code, value, line })),
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
        assert_eq!(pairs[1].line, 3);
        assert_eq!(pairs[2].f64(), Some(1.5));
    }

    #[test]
    fn a_non_numeric_code_is_reported_with_its_line() {
        let mut it = AsciiPairs::new(b"0\nSECTION\nhello\nx\n");
        assert!(it.next().unwrap().is_ok());
        let err = it.next().unwrap().unwrap_err();
        assert_eq!(err.line, 3);
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
            value: b" 1.0",
            line: 1,
        };
        assert_eq!(p.int(), Some(1));
    }
}
