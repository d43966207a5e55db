//! Text of a DXF: layer and block names decoded with the file's code page
//! (`$DWGCODEPAGE`, DXF reference HEADER section) before AutoCAD 2007, UTF-8
//! from 2007 (`$ACADVER` AC1021) on; `\\U+XXXX` escapes decoded in both.
//!
//! Windows and East-Asian code pages come from encoding_rs natively and,
//! in wasm, from the browser's own `TextDecoder` (the same WHATWG Encoding
//! Standard tables encoding_rs implements: its East-Asian tables were a
//! fifth of the page's wasm, issue 17); the DOS code pages 437 and 850,
//! which neither carries, from the tables here.

#[cfg(not(target_arch = "wasm32"))]
use encoding_rs::Encoding;

/// A WHATWG encoding (a code page encoding_rs knows): natively the
/// encoding itself, in wasm its label, checked by the browser's decoder.
#[cfg(not(target_arch = "wasm32"))]
pub type Page = &'static Encoding;
/// A WHATWG encoding (a code page encoding_rs knows): natively the
/// encoding itself, in wasm its label, checked by the browser's decoder.
#[cfg(target_arch = "wasm32")]
pub type Page = &'static str;

#[cfg(not(target_arch = "wasm32"))]
fn page_for_label(label: &str) -> Option<Page> {
    Encoding::for_label(label.as_bytes())
}
#[cfg(target_arch = "wasm32")]
fn page_for_label(label: &str) -> Option<Page> {
    crate::wasm_text::known(label)
}

#[cfg(not(target_arch = "wasm32"))]
fn page_decode(page: Page, bytes: &[u8]) -> String {
    page.decode_without_bom_handling(bytes).0.into_owned()
}
#[cfg(target_arch = "wasm32")]
fn page_decode(page: Page, bytes: &[u8]) -> String {
    crate::wasm_text::decode(page, bytes)
}

/// How the file's text bytes become strings.
#[derive(Clone, Copy, Debug)]
pub enum Decoder {
    /// UTF-8 (AutoCAD 2007 and later, and files that say nothing).
    Utf8,
    /// A code page encoding_rs knows.
    Page(Page),
    /// A DOS code page: the characters of bytes 128–255.
    Dos(&'static str),
}

/// Bytes 128–255 of DOS code page 437.
const CP437: &str = "\u{c7}\u{fc}\u{e9}\u{e2}\u{e4}\u{e0}\u{e5}\u{e7}\u{ea}\u{eb}\u{e8}\u{ef}\u{ee}\u{ec}\u{c4}\u{c5}\u{c9}\u{e6}\u{c6}\u{f4}\u{f6}\u{f2}\u{fb}\u{f9}\u{ff}\u{d6}\u{dc}\u{a2}\u{a3}\u{a5}\u{20a7}\u{192}\u{e1}\u{ed}\u{f3}\u{fa}\u{f1}\u{d1}\u{aa}\u{ba}\u{bf}\u{2310}\u{ac}\u{bd}\u{bc}\u{a1}\u{ab}\u{bb}\u{2591}\u{2592}\u{2593}\u{2502}\u{2524}\u{2561}\u{2562}\u{2556}\u{2555}\u{2563}\u{2551}\u{2557}\u{255d}\u{255c}\u{255b}\u{2510}\u{2514}\u{2534}\u{252c}\u{251c}\u{2500}\u{253c}\u{255e}\u{255f}\u{255a}\u{2554}\u{2569}\u{2566}\u{2560}\u{2550}\u{256c}\u{2567}\u{2568}\u{2564}\u{2565}\u{2559}\u{2558}\u{2552}\u{2553}\u{256b}\u{256a}\u{2518}\u{250c}\u{2588}\u{2584}\u{258c}\u{2590}\u{2580}\u{3b1}\u{df}\u{393}\u{3c0}\u{3a3}\u{3c3}\u{b5}\u{3c4}\u{3a6}\u{398}\u{3a9}\u{3b4}\u{221e}\u{3c6}\u{3b5}\u{2229}\u{2261}\u{b1}\u{2265}\u{2264}\u{2320}\u{2321}\u{f7}\u{2248}\u{b0}\u{2219}\u{b7}\u{221a}\u{207f}\u{b2}\u{25a0}\u{a0}";
/// Bytes 128–255 of DOS code page 850.
const CP850: &str = "\u{c7}\u{fc}\u{e9}\u{e2}\u{e4}\u{e0}\u{e5}\u{e7}\u{ea}\u{eb}\u{e8}\u{ef}\u{ee}\u{ec}\u{c4}\u{c5}\u{c9}\u{e6}\u{c6}\u{f4}\u{f6}\u{f2}\u{fb}\u{f9}\u{ff}\u{d6}\u{dc}\u{f8}\u{a3}\u{d8}\u{d7}\u{192}\u{e1}\u{ed}\u{f3}\u{fa}\u{f1}\u{d1}\u{aa}\u{ba}\u{bf}\u{ae}\u{ac}\u{bd}\u{bc}\u{a1}\u{ab}\u{bb}\u{2591}\u{2592}\u{2593}\u{2502}\u{2524}\u{c1}\u{c2}\u{c0}\u{a9}\u{2563}\u{2551}\u{2557}\u{255d}\u{a2}\u{a5}\u{2510}\u{2514}\u{2534}\u{252c}\u{251c}\u{2500}\u{253c}\u{e3}\u{c3}\u{255a}\u{2554}\u{2569}\u{2566}\u{2560}\u{2550}\u{256c}\u{a4}\u{f0}\u{d0}\u{ca}\u{cb}\u{c8}\u{131}\u{cd}\u{ce}\u{cf}\u{2518}\u{250c}\u{2588}\u{2584}\u{a6}\u{cc}\u{2580}\u{d3}\u{df}\u{d4}\u{d2}\u{f5}\u{d5}\u{b5}\u{fe}\u{de}\u{da}\u{db}\u{d9}\u{fd}\u{dd}\u{af}\u{b4}\u{ad}\u{b1}\u{2017}\u{be}\u{b6}\u{a7}\u{f7}\u{b8}\u{b0}\u{a8}\u{b7}\u{b9}\u{b3}\u{b2}\u{25a0}\u{a0}";

impl Decoder {
    /// The decoder for a file's `$ACADVER` and `$DWGCODEPAGE`; None when the
    /// code page is unknown (the caller warns and falls back to Windows-1252).
    pub fn for_file(acadver: Option<&[u8]>, codepage: Option<&[u8]>) -> Option<Decoder> {
        // AC1021 = AutoCAD 2007: from then on the file is UTF-8 whatever the code page says.
        if let Some(v) = acadver.and_then(|v| std::str::from_utf8(v).ok()) {
            if v.len() == 6 && v.starts_with("AC") && v[2..].parse::<u32>().is_ok_and(|n| n >= 1021)
            {
                return Some(Decoder::Utf8);
            }
        }
        let Some(cp) = codepage else {
            return Some(Decoder::Utf8);
        };
        let name = String::from_utf8_lossy(cp).trim().to_ascii_lowercase();
        let label = match name.as_str() {
            "" | "utf8" | "utf-8" => return Some(Decoder::Utf8),
            "dos437" => return Some(Decoder::Dos(CP437)),
            "dos850" => return Some(Decoder::Dos(CP850)),
            "dos866" => "ibm866",
            "ansi_874" => "windows-874",
            "ansi_932" | "dos932" => "shift_jis",
            "ansi_936" | "gb2312" => "gbk",
            "ansi_949" | "johab" => "euc-kr",
            "ansi_950" | "big5" => "big5",
            other => match other.strip_prefix("ansi_") {
                Some(n) if n.len() == 4 && n.starts_with("125") => {
                    return page_for_label(&format!("windows-{n}")).map(Decoder::Page)
                }
                _ => return page_for_label(other).map(Decoder::Page),
            },
        };
        page_for_label(label).map(Decoder::Page)
    }

    /// Decodes text bytes, then `\\U+XXXX` escapes.
    pub fn decode(&self, bytes: &[u8]) -> String {
        let s = match self {
            Decoder::Utf8 => String::from_utf8_lossy(bytes).into_owned(),
            Decoder::Page(e) => page_decode(e, bytes),
            Decoder::Dos(table) => bytes
                .iter()
                .map(|&b| {
                    if b < 128 {
                        b as char
                    } else {
                        table.chars().nth(b as usize - 128).unwrap_or('?')
                    }
                })
                .collect(),
        };
        unescape_unicode(&s)
    }
}

/// Replaces AutoCAD's `\\U+XXXX` escapes by their characters.
pub fn unescape_unicode(s: &str) -> String {
    if !s.contains("\\U+") {
        return s.to_string();
    }
    let mut out = String::with_capacity(s.len());
    let mut rest = s;
    while let Some(i) = rest.find("\\U+") {
        out.push_str(&rest[..i]);
        let hex = rest
            .get(i + 3..i + 7)
            .filter(|h| h.bytes().all(|b| b.is_ascii_hexdigit()));
        match hex
            .and_then(|h| u32::from_str_radix(h, 16).ok())
            .and_then(char::from_u32)
        {
            Some(c) => {
                out.push(c);
                rest = &rest[i + 7..];
            }
            None => {
                out.push_str("\\U+");
                rest = &rest[i + 3..];
            }
        }
    }
    out.push_str(rest);
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn windows_1250_layer_name_decodes_polish_letters() {
        let d = Decoder::for_file(Some(b"AC1015"), Some(b"ANSI_1250")).unwrap();
        assert_eq!(d.decode(b"Cz\xea\x9c\xe6"), "Część");
    }

    #[test]
    fn files_from_2007_on_are_utf8_whatever_the_code_page() {
        let d = Decoder::for_file(Some(b"AC1021"), Some(b"ANSI_1252")).unwrap();
        assert_eq!(d.decode("Über".as_bytes()), "Über");
    }

    #[test]
    fn unicode_escapes_and_dos_pages_decode() {
        let d = Decoder::for_file(Some(b"AC1009"), Some(b"DOS850")).unwrap();
        assert_eq!(d.decode(b"\\U+00C4rger \x81"), "Ärger ü");
        assert_eq!(unescape_unicode("a\\U+zz"), "a\\U+zz");
        let gb = Decoder::for_file(Some(b"AC1012"), Some(b"gb2312")).unwrap();
        assert_eq!(gb.decode(b"\xd6\xd0"), "中");
    }

    #[test]
    fn east_asian_pages_decode_as_in_the_page() {
        // The same bytes and names as tests/wasm.rs checks through the
        // browser's TextDecoder (Python's codecs gave the bytes).
        for (page, bytes, name) in [
            (&b"ANSI_932"[..], &b"\x82\xa0\x8a\xbf"[..], "あ漢"),
            (b"ANSI_949", b"\xc7\xd1\xb1\xdb", "한글"),
            (b"ANSI_950", b"\xa4\xa4\xa4\xe5", "中文"),
        ] {
            let d = Decoder::for_file(Some(b"AC1015"), Some(page)).unwrap();
            assert_eq!(d.decode(bytes), name);
        }
        assert!(Decoder::for_file(Some(b"AC1015"), Some(b"ANSI_9999")).is_none());
    }
}
