//! The command's own words (issue 40 §4): `--version` and `-V` print the
//! version, `kerfcam help nest` is `kerfcam nest --help`, and an unknown
//! option names the closest one.

#![cfg(not(target_arch = "wasm32"))]

fn kerfcam(args: &[&str]) -> std::process::Output {
    std::process::Command::new(env!("CARGO_BIN_EXE_kerfcam"))
        .args(args)
        .output()
        .expect("kerfcam runs")
}

fn stdout(o: &std::process::Output) -> String {
    String::from_utf8_lossy(&o.stdout).into_owned()
}

#[test]
fn version_long_and_short() {
    let want = format!("kerfcam {}\n", env!("CARGO_PKG_VERSION"));
    for flag in ["--version", "-V"] {
        let o = kerfcam(&[flag]);
        assert!(o.status.success(), "{flag}: {o:?}");
        assert_eq!(stdout(&o), want, "{flag}");
    }
    let o = kerfcam(&["nest", "--version"]);
    assert!(o.status.success());
    assert_eq!(stdout(&o), want);
}

#[test]
fn help_nest_is_the_nest_commands_help() {
    let help = kerfcam(&["help", "nest"]);
    let nest = kerfcam(&["nest", "--help"]);
    assert!(help.status.success() && nest.status.success());
    assert!(
        stdout(&help).starts_with("usage: kerfcam nest"),
        "{}",
        stdout(&help)
    );
    assert_eq!(stdout(&help), stdout(&nest));
    let plain = kerfcam(&["help"]);
    assert!(plain.status.success());
    assert_eq!(stdout(&plain), stdout(&kerfcam(&["--help"])));
    let other = kerfcam(&["help", "frobnicate"]);
    assert_eq!(other.status.code(), Some(2));
}

#[test]
fn an_unknown_option_names_the_closest() {
    let o = kerfcam(&["--kerff", "0.8", "x.dxf"]);
    assert_eq!(o.status.code(), Some(2));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(
        err.contains("unknown option --kerff (did you mean --kerf?)"),
        "{err}"
    );
    let o = kerfcam(&["nest", "a.dxf", "--sheeet", "100x100"]);
    assert_eq!(o.status.code(), Some(2));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(
        err.contains("unknown option --sheeet (did you mean --sheet?)"),
        "{err}"
    );
    let o = kerfcam(&["nest", "a.dxf", "--kerff", "1"]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("(did you mean --kerf?)"), "{err}");
}

#[test]
fn a_reader_that_stops_early_ends_the_command_quietly() {
    // `kerfcam plate.dxf | head -c 100`: the program (well past a pipe's
    // buffer) meets a closed pipe; the command ends with no panic.
    use std::io::Read;
    let dir = std::env::temp_dir().join(format!("kerfcam-pipe-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("plates.dxf");
    let mut body = String::new();
    for i in 0..1600 {
        let (x, y) = (12.0 * (i % 40) as f64, 12.0 * (i / 40) as f64);
        body += &format!("0\nCIRCLE\n8\n0\n10\n{x}\n20\n{y}\n40\n5\n");
    }
    std::fs::write(
        &file,
        format!("0\nSECTION\n2\nHEADER\n9\n$INSUNITS\n70\n4\n0\nENDSEC\n0\nSECTION\n2\nENTITIES\n{body}0\nENDSEC\n0\nEOF\n"),
    )
    .unwrap();
    let mut child = std::process::Command::new(env!("CARGO_BIN_EXE_kerfcam"))
        .arg(&file)
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    let mut first = [0u8; 100];
    child.stdout.take().unwrap().read_exact(&mut first).unwrap();
    let o = child.wait_with_output().unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(!err.contains("panicked"), "{err}");
    assert!(o.status.success(), "{o:?}");
    let _ = std::fs::remove_dir_all(&dir);
}
