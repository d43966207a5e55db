//! Tests of [`super`]: pairs, group codes and numbers against the plain
//! definitions (the standard parser, a byte-by-byte scan).
use super::*;
use crate::dxf::decimal::{leading_digits, word_at};

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
        x = crate::test_rng::Xorshift(x).next();
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
        "-0.000000",
        "-0",
        "+0.0",
        "1250.000000",
        "-999999999999999.0",
        "999999999999999",
        "12.0000000000000",
        "00000000000012.5",
    ] {
        assert_eq!(
            fast_float(text.as_bytes()).map(f64::to_bits),
            text.parse::<f64>().ok().map(f64::to_bits),
            "{text}"
        );
    }
}

#[test]
fn the_quick_path_gives_the_pairs_of_the_general_one() {
    // Random lines from pieces that sit on both sides of the quick
    // path's edges: padding, signs, tabs, CR, blank lines, long codes.
    let pieces: [&[u8]; 20] = [
        b"  0\r",
        b"7\r",
        b"       5",
        b"1234567",
        b"0",
        b"  10",
        b"-5",
        b"\t8",
        b" 999999999",
        b"1234567890",
        b"20 ",
        b"",
        b"LINE",
        b"1.5\r",
        b"\r",
        b"abc",
        b" ",
        b"\xff\xfe",
        b"42\r\r",
        b"+3",
    ];
    let mut x = 0x2545_f491_4f6c_dd1du64;
    for _ in 0..50_000 {
        let mut text = Vec::new();
        for _ in 0..(x % 9) {
            x = crate::test_rng::Xorshift(x).next();
            text.extend_from_slice(pieces[(x % 20) as usize]);
            if x & 0x100 != 0 {
                text.push(b'\n');
            }
        }
        let quick: Vec<_> = AsciiPairs::new(&text).collect();
        let mut g = AsciiPairs::new(&text);
        let general: Vec<_> = std::iter::from_fn(|| g.general()).collect();
        let show = |v: &[Result<Pair, BadCode>]| format!("{v:?}");
        assert_eq!(
            show(&quick),
            show(&general),
            "{:?}",
            String::from_utf8_lossy(&text)
        );
        let mut q = AsciiPairs::new(&text);
        q.by_ref().for_each(drop);
        assert_eq!(q.truncated, g.truncated);
    }
}

#[test]
fn fast_float_with_long_fractions_matches_the_standard_parser() {
    // Eight or more decimals (the eight-digit step), leading zeros,
    // and junk right after eight digits.
    let mut x = 0x1234_5678_9abc_def1u64;
    for _ in 0..200_000 {
        x = crate::test_rng::Xorshift(x).next();
        let int = x % 10u64.pow((x >> 50) as u32 % 10);
        let frac_len = (x >> 40) as usize % 13;
        let frac = (x >> 8) % 10u64.pow(frac_len as u32);
        let text = match (x >> 4) % 4 {
            0 => format!("{int:08}.{frac:0frac_len$}"),
            1 => format!("-{int}.{frac:0frac_len$}"),
            2 => format!("{int}.{frac:0frac_len$}e1"),
            _ => format!("{int}{frac:0frac_len$}"),
        };
        assert_eq!(
            fast_float(text.as_bytes()).map(f64::to_bits),
            text.parse::<f64>().ok().map(f64::to_bits),
            "{text}"
        );
    }
}

#[test]
fn leading_digits_reads_up_to_eight_digits() {
    for text in [
        &b"12345678"[..],
        b"00000000",
        b"99999999",
        b"1234567/",
        b"123:5678",
        b"1234.678",
        b" 2345678",
        b"\x7f2345678",
        b"9\xff\xff\xff\xff\xff\xff\xff",
        b"0\0\0\0\0\0\0\0",
    ] {
        let w = u64::from_le_bytes(text.try_into().unwrap());
        let n = text.iter().take_while(|b| b.is_ascii_digit()).count();
        let v = std::str::from_utf8(&text[..n])
            .unwrap()
            .parse()
            .unwrap_or(0);
        assert_eq!(leading_digits(w), (n, v), "{text:?}");
    }
    let t = b"0123456789";
    for i in 0..=t.len() {
        let w = word_at(t, i).unwrap();
        let mut want = [0u8; 8];
        let k = (t.len() - i).min(8);
        want[..k].copy_from_slice(&t[i..i + k]);
        assert_eq!(w, u64::from_le_bytes(want), "{i}");
    }
    assert_eq!(word_at(t, 11), None);
    assert_eq!(word_at(b"1234567", 0), None);
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
