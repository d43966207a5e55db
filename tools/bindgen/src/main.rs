//! `kerfcam-bindgen IN.wasm --out-dir DIR --out-name NAME`: writes NAME.js, NAME.d.ts, NAME_bg.wasm and
//! NAME_bg.wasm.d.ts into DIR, as `wasm-bindgen IN.wasm --out-dir DIR --typescript --target web --out-name NAME`
//! does (the options that command leaves at their defaults are set to the same values here, so the output is
//! the same bytes: scripts/setup.sh's check compares them where wasm-bindgen-cli is also installed).
use std::path::PathBuf;
use std::process::ExitCode;

use wasm_bindgen_cli_support::Bindgen;

const USAGE: &str = "usage: kerfcam-bindgen IN.wasm --out-dir DIR --out-name NAME";

struct Args {
    input: PathBuf,
    out_dir: PathBuf,
    out_name: String,
}

fn parse(mut args: impl Iterator<Item = String>) -> Result<Option<Args>, String> {
    let (mut input, mut out_dir, mut out_name) = (None, None, None);
    while let Some(a) = args.next() {
        match a.as_str() {
            "--version" | "-V" => return Ok(None),
            "--out-dir" => out_dir = Some(args.next().ok_or("--out-dir needs a folder")?),
            "--out-name" => out_name = Some(args.next().ok_or("--out-name needs a name")?),
            _ if a.starts_with('-') => return Err(format!("unknown option {a}")),
            _ if input.is_none() => input = Some(a),
            _ => return Err(format!("one input only (got {a} too)")),
        }
    }
    match (input, out_dir, out_name) {
        (Some(i), Some(d), Some(n)) => Ok(Some(Args {
            input: i.into(),
            out_dir: d.into(),
            out_name: n,
        })),
        _ => Err("IN.wasm, --out-dir and --out-name are needed".into()),
    }
}

fn main() -> ExitCode {
    let args = match parse(std::env::args().skip(1)) {
        Ok(Some(a)) => a,
        Ok(None) => {
            // The version the glue is made by: the build stamp (scripts/build-wasm.sh) keys on it.
            println!("kerfcam-bindgen {} (wasm-bindgen)", env!("CARGO_PKG_VERSION"));
            return ExitCode::SUCCESS;
        }
        Err(e) => {
            eprintln!("kerfcam-bindgen: {e}\n{USAGE}");
            return ExitCode::from(2);
        }
    };
    let mut b = Bindgen::new();
    // As the CLI: its hidden --reference-types flag is false unless given (the module's features decide).
    #[allow(deprecated)]
    let made = b.web(true).and_then(|b| {
        b.input_path(&args.input)
            .typescript(true)
            .omit_default_module_path(false)
            .reference_types(false)
            .out_name(&args.out_name)
            .generate(&args.out_dir)
    });
    match made {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("kerfcam-bindgen: {}: {e:#}", args.input.display());
            ExitCode::FAILURE
        }
    }
}
