//! Any bytes through the whole pipeline: reader, contours, kerf, plan,
//! G-code and report must not panic, hang or blow up memory.
//!
//! `RUSTC_BOOTSTRAP=1 cargo fuzz run dxf_pipeline` (see fuzz/README.md).
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let Ok(settings) = kerfcam::Settings::new(1.5, 0.001, 2000.0) else { return };
    if let Ok(out) = kerfcam::run(data, &settings) {
        let _ = kerfcam::report::Report::new(&out).to_json();
    }
});
