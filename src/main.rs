//! The `kerfcam` command: one DXF in, a G-code program and/or a JSON report out.
//! Native only: in wasm the library is used through `Job` (src/wasm.rs).

#[cfg(not(target_arch = "wasm32"))]
mod cli;
#[cfg(not(target_arch = "wasm32"))]
mod cut_options;
#[cfg(not(target_arch = "wasm32"))]
mod nest_cli;

#[cfg(not(target_arch = "wasm32"))]
fn main() -> std::process::ExitCode {
    // `kerfcam nest …` is a command of its own (src/nest_cli.rs).
    if std::env::args().nth(1).as_deref() == Some("nest") {
        return nest_cli::main(std::env::args().skip(2));
    }
    cli::main()
}

#[cfg(target_arch = "wasm32")]
fn main() {}
