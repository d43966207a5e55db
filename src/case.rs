//! Case folding of names (layers, materials): `str::to_lowercase` and
//! `to_uppercase`, whose Unicode tables were 13 KiB of the page's gzipped
//! wasm (issue 17). ASCII, nearly every name, is folded here; other text
//! natively by the standard library and in wasm by JavaScript's own
//! `toLowerCase`/`toUpperCase` (the same Unicode default case mapping,
//! final sigma included).

/// `s.to_lowercase()`.
pub(crate) fn lower(s: &str) -> String {
    if s.is_ascii() {
        return s.to_ascii_lowercase();
    }
    #[cfg(target_arch = "wasm32")]
    {
        crate::wasm_text::lower(s)
    }
    #[cfg(not(target_arch = "wasm32"))]
    {
        s.to_lowercase()
    }
}

/// `s.to_uppercase()`.
pub(crate) fn upper(s: &str) -> String {
    if s.is_ascii() {
        return s.to_ascii_uppercase();
    }
    #[cfg(target_arch = "wasm32")]
    {
        crate::wasm_text::upper(s)
    }
    #[cfg(not(target_arch = "wasm32"))]
    {
        s.to_uppercase()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn folds_as_the_standard_library() {
        for s in [
            "Layer-1",
            "CORTE",
            "Ärger ÉTÉ",
            "ΟΔΟΣ",
            "straße",
            "İstanbul",
            "",
        ] {
            assert_eq!(lower(s), s.to_lowercase());
            assert_eq!(upper(s), s.to_uppercase());
        }
    }
}
