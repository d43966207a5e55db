//! The `kerfcam` command: one DXF in, a G-code program and/or a JSON report out.
//! Native only: in wasm the library is used through `Job` (src/wasm.rs).

#[cfg(not(target_arch = "wasm32"))]
mod cli;

#[cfg(not(target_arch = "wasm32"))]
fn main() -> std::process::ExitCode {
    cli::main()
}

#[cfg(target_arch = "wasm32")]
fn main() {}
