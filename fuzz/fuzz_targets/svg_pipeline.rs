//! Any bytes as an SVG (issue 41) through the whole pipeline: the input is
//! put inside an `<svg>` root unless it is XML already, so the fuzzer spends
//! its time in the SVG reader's grammars rather than on XML well-formedness.
//!
//! `RUSTC_BOOTSTRAP=1 cargo fuzz run svg_pipeline` (see fuzz/README.md).
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let Ok(settings) = kerfcam::Settings::new(1.5, 0.001, 2000.0) else { return };
    let mut bytes = Vec::with_capacity(data.len() + 80);
    if !kerfcam::svg::looks_like_svg(data) {
        bytes.extend_from_slice(b"<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"100mm\" height=\"100mm\" viewBox=\"0 0 100 100\">");
        bytes.extend_from_slice(data);
        bytes.extend_from_slice(b"</svg>");
    } else {
        bytes.extend_from_slice(data);
    }
    if let Ok(out) = kerfcam::run(&bytes, &settings) {
        let _ = kerfcam::report::Report::new(&out).to_json();
    }
});
