//! Pairs of a binary DXF (DXF reference, "Binary DXF Files"): the sentinel
//! `AutoCAD Binary DXF\r\n\x1a\0`, then group codes of one byte (R12 and
//! before; 255 announces a 2-byte extended code) or two bytes (R13 on), each
//! followed by a value whose size is fixed by the code's type.

use super::pairs::{BadCode, Pair, Place, Value};

/// The 22-byte sentinel that opens every binary DXF.
pub const SENTINEL: &[u8] = b"AutoCAD Binary DXF\r\n\x1a\0";

/// How a value of a group code is stored.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Kind {
    Str,
    F64,
    I16,
    I32,
    I64,
    Bool,
    Chunk,
}

/// The value type of a group code ("Group Code Value Types"); None for codes
/// the reference does not define, whose size cannot be known.
fn kind(code: i32) -> Option<Kind> {
    use Kind::*;
    Some(match code {
        0..=9
        | 100..=105
        | 300..=309
        | 320..=369
        | 390..=399
        | 410..=419
        | 430..=439
        | 470..=481
        | 999 => Str,
        1000..=1003 | 1005..=1009 => Str,
        10..=59 | 110..=149 | 210..=239 | 460..=469 | 1010..=1059 => F64,
        60..=79 | 170..=179 | 270..=289 | 370..=389 | 400..=409 | 1060..=1070 => I16,
        90..=99 | 420..=429 | 440..=459 | 1071 => I32,
        160..=169 => I64,
        290..=299 => Bool,
        310..=319 | 1004 => Chunk,
        _ => return None,
    })
}

/// Iterator over the pairs of a binary DXF.
pub struct BinaryPairs<'a> {
    data: &'a [u8],
    pos: usize,
    wide_codes: bool,
    /// Set when the input ended in the middle of a pair.
    pub truncated: bool,
}

impl<'a> BinaryPairs<'a> {
    /// Reads the pairs after the sentinel; `bytes` must start with [`SENTINEL`].
    pub fn new(bytes: &'a [u8]) -> Self {
        let pos = SENTINEL.len().min(bytes.len());
        // The first pair is `0 SECTION`: with 2-byte codes its second byte is 0,
        // with 1-byte codes it is the 'S' of SECTION.
        let wide_codes = bytes.get(pos + 1) == Some(&0);
        BinaryPairs {
            data: bytes,
            pos,
            wide_codes,
            truncated: false,
        }
    }

    fn take(&mut self, n: usize) -> Option<&'a [u8]> {
        let s = self.data.get(self.pos..self.pos + n)?;
        self.pos += n;
        Some(s)
    }

    fn code(&mut self) -> Option<i32> {
        if self.wide_codes {
            let b = self.take(2)?;
            Some(i16::from_le_bytes([b[0], b[1]]) as i32)
        } else {
            let b = self.take(1)?[0];
            if b == 255 {
                let e = self.take(2)?;
                Some(i16::from_le_bytes([e[0], e[1]]) as i32)
            } else {
                Some(b as i32)
            }
        }
    }

    fn value(&mut self, k: Kind) -> Option<Value<'a>> {
        Some(match k {
            Kind::Str => {
                let rest = self.data.get(self.pos..)?;
                let end = rest.iter().position(|&b| b == 0)?;
                self.pos += end + 1;
                Value::Text(&rest[..end])
            }
            Kind::F64 => Value::Real(f64::from_le_bytes(self.take(8)?.try_into().ok()?)),
            Kind::I16 => Value::Int(i16::from_le_bytes(self.take(2)?.try_into().ok()?) as i64),
            Kind::I32 => Value::Int(i32::from_le_bytes(self.take(4)?.try_into().ok()?) as i64),
            Kind::I64 => Value::Int(i64::from_le_bytes(self.take(8)?.try_into().ok()?)),
            Kind::Bool => Value::Int(self.take(1)?[0] as i64),
            Kind::Chunk => {
                let n = self.take(1)?[0] as usize;
                Value::Text(self.take(n)?)
            }
        })
    }
}

impl<'a> super::pairs::Source<'a> for BinaryPairs<'a> {}

impl<'a> Iterator for BinaryPairs<'a> {
    type Item = Result<Pair<'a>, BadCode>;

    fn next(&mut self) -> Option<Self::Item> {
        if self.pos >= self.data.len() {
            return None;
        }
        let at = self.pos;
        let Some(code) = self.code() else {
            self.truncated = true;
            return None;
        };
        let Some(k) = kind(code) else {
            self.pos = self.data.len();
            return Some(Err(BadCode {
                place: Place::Byte(at),
                text: format!("group code {code}"),
            }));
        };
        match self.value(k) {
            Some(value) => Some(Ok(Pair { code, value, at })),
            None => {
                self.truncated = true;
                self.pos = self.data.len();
                None
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn file(wide: bool, pairs: &[(i32, &[u8])]) -> Vec<u8> {
        let mut v = SENTINEL.to_vec();
        for (code, val) in pairs {
            if wide {
                v.extend_from_slice(&(*code as i16).to_le_bytes());
            } else {
                v.push(*code as u8);
            }
            v.extend_from_slice(val);
        }
        v
    }

    #[test]
    fn reads_one_and_two_byte_codes() {
        for wide in [false, true] {
            let v = file(
                wide,
                &[
                    (0, b"SECTION\0"),
                    (10, &1.5f64.to_le_bytes()),
                    (70, &7i16.to_le_bytes()),
                ],
            );
            let pairs: Vec<_> = BinaryPairs::new(&v).map(Result::unwrap).collect();
            assert_eq!(pairs.len(), 3, "wide {wide}");
            assert!(pairs[0].is("SECTION"));
            assert_eq!(pairs[1].f64(), Some(1.5));
            assert_eq!(pairs[2].int(), Some(7));
        }
    }

    #[test]
    fn a_cut_value_marks_the_file_truncated() {
        let v = file(true, &[(0, b"SECTION\0"), (10, &[1, 2, 3])]);
        let mut it = BinaryPairs::new(&v);
        assert!(it.next().unwrap().is_ok());
        assert!(it.next().is_none());
        assert!(it.truncated);
    }

    #[test]
    fn an_unknown_code_is_an_error_with_its_byte_offset() {
        let v = file(true, &[(0, b"SECTION\0"), (3000, b"x")]);
        let mut it = BinaryPairs::new(&v);
        it.next();
        let e = it.next().unwrap().unwrap_err();
        assert_eq!(e.place, Place::Byte(22 + 2 + 8));
    }
}
