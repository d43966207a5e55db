//! Every real DXF of `../shared/corpus` through the whole pipeline: a
//! result or a clear error, never a panic; every program passes LinuxCNC's
//! interpreter; the preview renders.
#![cfg(not(target_arch = "wasm32"))]

use crate::common;


use kerfcam::preview::{self, View};

#[test]
fn every_corpus_file_gives_a_program_linuxcnc_accepts_or_a_clear_error() {
    let runs = common::corpus_runs();
    assert!(
        runs.len() >= 50,
        "corpus not found beside the project: {}",
        runs.len()
    );
    let mut failures = Vec::new();
    let mut summary = Vec::new();
    for common::CorpusRun { name, out, .. } in runs {
        match out {
            Ok(out) => {
                let safe: String = name
                    .chars()
                    .map(|c| if c.is_ascii_alphanumeric() { c } else { '_' })
                    .collect();
                let errors = common::rs274_errors(&out.gcode, &format!("corpus-{safe}"));
                if !errors.is_empty() {
                    failures.push(format!(
                        "{name}: rs274: {:?}",
                        &errors[..errors.len().min(3)]
                    ));
                }
                let view = View::fit(&preview::extent(&out.scene()), 200, 150).unwrap();
                assert!(
                    preview::render(&out.scene(), &view).is_some(),
                    "{name}: preview"
                );
                let open = out
                    .contours
                    .contours
                    .iter()
                    .filter(|c| !c.is_closed())
                    .count();
                summary.push(format!(
                    "{name}: {} pierces, {} open, {} warnings",
                    out.plan.pierces(),
                    open,
                    out.warnings().count()
                ));
            }
            Err(e) => {
                let msg = e.to_string();
                assert!(
                    !msg.is_empty() && !msg.contains('\n'),
                    "{name}: error must be one line: {msg:?}"
                );
                summary.push(format!("{name}: error: {msg}"));
            }
        }
    }
    println!("{}", summary.join("\n"));
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
