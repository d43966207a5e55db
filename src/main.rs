//! The `kerfcam` command: one DXF in, a G-code program and/or a JSON report out.
//! Native only: in wasm the library is used through `Job` (src/wasm.rs).

#[cfg(not(target_arch = "wasm32"))]
mod cli;
#[cfg(not(target_arch = "wasm32"))]
mod cut_options;
#[cfg(not(target_arch = "wasm32"))]
mod nest_cli;
#[cfg(not(target_arch = "wasm32"))]
mod quote_cli;

#[cfg(not(target_arch = "wasm32"))]
fn main() -> std::process::ExitCode {
    // `kerfcam nest …` is a command of its own (src/nest_cli.rs); `kerfcam help nest` its --help.
    let first = std::env::args().nth(1);
    let second = std::env::args().nth(2);
    match (first.as_deref(), second.as_deref()) {
        (Some("nest"), _) => nest_cli::main(std::env::args().skip(2)),
        (Some("help"), Some("nest")) => nest_cli::main(["--help".to_string()].into_iter()),
        (Some("help"), None) => {
            out(&format!("{}\n", cli::usage()));
            std::process::ExitCode::SUCCESS
        }
        (Some("help"), Some(other)) => {
            eprintln!("kerfcam: error: no command {other} (kerfcam help nest, or kerfcam --help)");
            std::process::ExitCode::from(2)
        }
        _ => cli::main(),
    }
}

/// Writes `text` to standard output. A reader that stops early (`kerfcam
/// part.dxf | head`) ends the command quietly, as other tools do, where
/// `print!` panicked on the closed pipe.
#[cfg(not(target_arch = "wasm32"))]
pub(crate) fn out(text: &str) {
    use std::io::Write;
    let mut o = std::io::stdout().lock();
    if let Err(e) = o.write_all(text.as_bytes()).and_then(|()| o.flush()) {
        if e.kind() == std::io::ErrorKind::BrokenPipe {
            std::process::exit(0);
        }
        eprintln!("kerfcam: error: standard output: {e}");
        std::process::exit(1);
    }
}

#[cfg(target_arch = "wasm32")]
fn main() {}
