//! Text services the browser already has (issue 17): case folding of
//! names (src/case.rs) and a DXF's code page decoded by `TextDecoder`:
//! the WHATWG Encoding Standard that encoding_rs implements natively, so
//! the page's wasm does not carry encoding_rs's East-Asian tables (a fifth
//! of its size). Node and every browser the page supports have it, with
//! the legacy encodings (Shift_JIS, GBK, EUC-KR, Big5, the Windows pages).
//!
//! Beside `wasm`, not in it: the ground floor (src/case.rs, src/dxf/text.rs)
//! calls these, and `wasm`, the page's API, calls everything.

use wasm_bindgen::prelude::*;

#[wasm_bindgen]
extern "C" {
    type TextDecoder;
    #[wasm_bindgen(constructor, catch)]
    fn new(label: &str, options: &JsValue) -> Result<TextDecoder, JsValue>;
    #[wasm_bindgen(method, getter)]
    fn encoding(this: &TextDecoder) -> String;
    #[wasm_bindgen(method, catch)]
    fn decode(this: &TextDecoder, input: &[u8]) -> Result<String, JsValue>;
}

/// The encodings of the Encoding Standard by their names, as `TextDecoder`
/// reports them (its `encoding`), so a decoder can be kept as a `'static` name.
const NAMES: &[&str] = &[
    "utf-8",
    "ibm866",
    "iso-8859-2",
    "iso-8859-3",
    "iso-8859-4",
    "iso-8859-5",
    "iso-8859-6",
    "iso-8859-7",
    "iso-8859-8",
    "iso-8859-8-i",
    "iso-8859-10",
    "iso-8859-13",
    "iso-8859-14",
    "iso-8859-15",
    "iso-8859-16",
    "koi8-r",
    "koi8-u",
    "macintosh",
    "windows-874",
    "windows-1250",
    "windows-1251",
    "windows-1252",
    "windows-1253",
    "windows-1254",
    "windows-1255",
    "windows-1256",
    "windows-1257",
    "windows-1258",
    "x-mac-cyrillic",
    "gbk",
    "gb18030",
    "big5",
    "euc-jp",
    "iso-2022-jp",
    "shift_jis",
    "euc-kr",
    "utf-16be",
    "utf-16le",
    "x-user-defined",
];

/// A decoder as `decode_without_bom_handling`: a BOM is text like any
/// other, bad bytes become U+FFFD (not an error).
fn decoder(label: &str) -> Option<TextDecoder> {
    let options = js_sys::Object::new();
    js_sys::Reflect::set(&options, &"ignoreBOM".into(), &JsValue::TRUE).ok()?;
    TextDecoder::new(label, &options).ok()
}

/// The encoding named by `label` (any of the standard's labels), if the
/// browser knows it.
pub(crate) fn known(label: &str) -> Option<&'static str> {
    let name = decoder(label)?.encoding();
    NAMES.iter().copied().find(|n| *n == name)
}

/// `bytes` decoded as `name` (one of [`NAMES`]); lossy, never fails.
pub(crate) fn decode(name: &'static str, bytes: &[u8]) -> String {
    decoder(name)
        .and_then(|d| d.decode(bytes).ok())
        .unwrap_or_else(|| String::from_utf8_lossy(bytes).into_owned())
}

/// `s.to_lowercase()` by JavaScript's `toLowerCase` (src/case.rs).
pub(crate) fn lower(s: &str) -> String {
    js_sys::JsString::from(s).to_lower_case().into()
}

/// `s.to_uppercase()` by JavaScript's `toUpperCase` (src/case.rs).
pub(crate) fn upper(s: &str) -> String {
    js_sys::JsString::from(s).to_upper_case().into()
}
