//! Shared helpers of the integration tests: paths to `../shared`, running
//! the pipeline, and checking programs with LinuxCNC's own interpreter.
#![allow(dead_code)]

use std::path::{Path, PathBuf};
use std::process::Command;

use kerfcam::{Output, Settings};

pub mod mill_sweep;
pub mod program_xy;
pub mod sampled;
pub mod sweep;

/// `../shared` beside the project.
pub fn shared() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("..")
        .join("shared")
}

/// A fixture file.
pub fn fixture(name: &str) -> PathBuf {
    shared().join("fixtures").join(name)
}

/// Every DXF of the corpus, sorted.
pub fn corpus_files() -> Vec<PathBuf> {
    fn walk(dir: &Path, out: &mut Vec<PathBuf>) {
        let Ok(rd) = std::fs::read_dir(dir) else {
            return;
        };
        for e in rd.flatten() {
            let p = e.path();
            if p.is_dir() {
                walk(&p, out);
            } else if p.extension().is_some_and(|x| x.eq_ignore_ascii_case("dxf")) {
                out.push(p);
            }
        }
    }
    let mut v = Vec::new();
    walk(&shared().join("corpus"), &mut v);
    v.sort();
    v
}

/// The settings of [`corpus_runs`]: a 1.5 mm kerf, the contour order and
/// default leads, the kerf's sweep verified.
pub fn corpus_settings() -> Settings {
    kerf(1.5).with_verify(true)
}

/// One corpus file through the pipeline with [`corpus_settings`].
pub struct CorpusRun {
    pub path: PathBuf,
    /// The file's name.
    pub name: String,
    pub out: Result<Output, kerfcam::Error>,
}

/// Every corpus file run once per test binary with [`corpus_settings`]:
/// the corpus-wide tests that ask these settings (corpus, posts, i18n,
/// verify) read these runs instead of each running the corpus again
/// (issue 40: four passes became one). The sweep only adds to the report:
/// the program is the one without it.
pub fn corpus_runs() -> &'static [CorpusRun] {
    corpus_runs_with(&corpus_settings())
}

/// Every corpus file run with `settings`, once per test binary for equal
/// settings: tests that sweep the corpus with the same settings (i18n's
/// Eulerian order and eulerian.rs's, say) share one pass.
pub fn corpus_runs_with(settings: &Settings) -> &'static [CorpusRun] {
    type Passes = Vec<(Settings, &'static std::sync::OnceLock<Vec<CorpusRun>>)>;
    static PASSES: std::sync::Mutex<Passes> = std::sync::Mutex::new(Vec::new());
    // The pass's cell under the lock, its runs outside it: a pass being
    // made holds up only the tests that wait for the same settings.
    let cell = {
        let mut passes = PASSES.lock().unwrap_or_else(|e| e.into_inner());
        match passes.iter().find(|(s, _)| s == settings) {
            Some((_, cell)) => *cell,
            None => {
                let cell: &'static std::sync::OnceLock<Vec<CorpusRun>> =
                    Box::leak(Box::default());
                passes.push((settings.clone(), cell));
                cell
            }
        }
    };
    cell.get_or_init(|| {
        corpus_files()
            .into_iter()
            .map(|path| CorpusRun {
                name: path.file_name().unwrap().to_string_lossy().into_owned(),
                out: run(&path, settings),
                path,
            })
            .collect()
    })
}

/// Runs the pipeline on a file.
pub fn run(path: &Path, settings: &Settings) -> Result<Output, kerfcam::Error> {
    let bytes =
        std::fs::read(path).unwrap_or_else(|e| panic!("cannot read {}: {e}", path.display()));
    kerfcam::run(&bytes, settings)
}

/// The router tests' drawing (mm): a 60 × 40 pocket around a round island
/// of R 8 on layer POCKET and, with `profile`, a 30 × 30 square on PROFILE.
pub fn pocket_island_dxf(profile: bool) -> Vec<u8> {
    let mut e = String::from(
        "0\nLWPOLYLINE\n8\nPOCKET\n90\n4\n70\n1\n10\n0\n20\n0\n10\n60\n20\n0\n10\n60\n20\n40\n10\n0\n20\n40\n",
    );
    e += "0\nCIRCLE\n8\nPOCKET\n10\n30\n20\n20\n40\n8\n";
    if profile {
        e += "0\nLWPOLYLINE\n8\nPROFILE\n90\n4\n70\n1\n10\n80\n20\n0\n10\n110\n20\n0\n10\n110\n20\n30\n10\n80\n20\n30\n";
    }
    format!("0\nSECTION\n2\nHEADER\n9\n$INSUNITS\n70\n4\n0\nENDSEC\n0\nSECTION\n2\nENTITIES\n{e}0\nENDSEC\n0\nEOF\n").into_bytes()
}

/// Settings with a kerf, default tolerance and feed, the program's zero
/// at the drawing's zero (the fixtures' known answers are in drawing
/// coordinates; `ProgramOrigin::Auto` has tests of its own).
pub fn kerf(width: f64) -> Settings {
    Settings::new(width, 0.001, 2000.0)
        .and_then(|s| s.with_origin(kerfcam::origin::ProgramOrigin::Drawing))
        .unwrap()
}

/// Where tests write programs (for rs274 and for eyes).
pub fn out_dir() -> PathBuf {
    let d = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests")
        .join("out");
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// Runs LinuxCNC's `rs274 -g` on a program and returns its error lines
/// (anything that is not a canonical call or "executing"). rs274's exit
/// code is not trusted: versions differ.
///
/// Without rs274 this fails, unless KERFCAM_NO_RS274=1 (then it returns no errors).
pub fn rs274_errors(program: &str, name: &str) -> Vec<String> {
    rs274_output(program, name).map_or_else(Vec::new, |text| rs274_error_lines(&text))
}

/// Writes `program` to `tests/out/NAME.ngc` and returns everything `rs274 -g`
/// prints for it (canonical calls and errors); None when rs274 is missing
/// and KERFCAM_NO_RS274=1 (said on standard error).
pub fn rs274_output(program: &str, name: &str) -> Option<String> {
    if let Some(e) = torch_cycle_without_motion(program) {
        panic!("{name}: {e}");
    }
    let file = out_dir().join(format!("{name}.ngc"));
    std::fs::write(&file, program).unwrap();
    run_rs274(None, &file, name)
}

/// The first place where `program` fires the torch and crosses a tab
/// (or starts the next tab) with nothing cut since it came on (issue 39
/// §3: a tab split around a corner fired and stopped the torch on the
/// spot), as a message; read from the text alone. A torch comes on with
/// M3/M03 (any spindle), a feed move is a G1/G2/G3 block with X or Y
/// (modal too), a tab crossing starts at its "(tab)" comment; the
/// crossing's own first move (a post that feeds over the tab with the
/// torch switched off) is not a cut. A spot (on, dwell, off) has no tab.
pub fn torch_cycle_without_motion(program: &str) -> Option<String> {
    let mut mode = 0u32; // the modal motion: 0 rapid, 1-3 feed
    let mut cut = false; // a feed move since the torch came on
    let mut skip = false; // the next feed move is the tab's own
    let mut on = false;
    for (n, raw) in program.lines().enumerate() {
        let line = raw.trim();
        if line.contains("(tab)") {
            if on && !cut {
                return Some(format!(
                    "line {}: a tab crossed with nothing cut since the torch came on: {line}",
                    n + 1
                ));
            }
            cut = false;
            skip = true;
            continue;
        }
        // Words, comments stripped.
        let text: String = {
            let mut depth = 0;
            line.chars()
                .take_while(|&c| c != ';')
                .filter(|&c| {
                    depth += i32::from(c == '(') - i32::from(c == ')');
                    depth == 0 && c != ')'
                })
                .collect()
        };
        let upper = text.to_ascii_uppercase();
        let words: Vec<(char, f64)> = words_of(&upper);
        let mut xy = false;
        for &(l, v) in &words {
            match l {
                'G' if [0.0, 1.0, 2.0, 3.0].contains(&v) => mode = v as u32,
                'X' | 'Y' => xy = true,
                'M' if v == 3.0 || v == 4.0 => {
                    on = true;
                    cut = false;
                    skip = false;
                }
                'M' if v == 5.0 => on = false,
                _ => {}
            }
        }
        if xy && mode > 0 {
            if skip {
                skip = false;
            } else {
                cut = true;
            }
        }
    }
    None
}

/// The words of a block: letter and number.
fn words_of(block: &str) -> Vec<(char, f64)> {
    let mut out = Vec::new();
    let cs: Vec<char> = block.chars().filter(|c| !c.is_whitespace()).collect();
    let mut i = 0;
    while i < cs.len() {
        let l = cs[i];
        i += 1;
        if !l.is_ascii_alphabetic() {
            continue;
        }
        let start = i;
        while i < cs.len() && (cs[i].is_ascii_digit() || "+-.".contains(cs[i])) {
            i += 1;
        }
        let num: String = cs[start..i].iter().collect();
        if let Ok(v) = num.parse::<f64>() {
            out.push((l, v));
        }
    }
    out
}

#[test]
fn the_torch_cycle_check_sees_a_tab_after_nothing_cut() {
    let good = "G0 X0 Y0\nM3 S1\nG1 X10 F100\n(tab)\nM5\nG0 X13\nM3 S1\nG1 X20\nM5\n";
    assert_eq!(torch_cycle_without_motion(good), None);
    // A spot: on, dwell, off.
    assert_eq!(
        torch_cycle_without_motion("G0 X5 Y5\nM3 S1\nG4 P0.5\nM5\n"),
        None
    );
    let split = "M3 S1\nG1 X10 F100\n(tab)\nM5\nG0 X13\nM3 S1\n(tab)\nM5\nG0 X14\nM3 S1\nX20\nM5\n";
    assert!(torch_cycle_without_motion(split)
        .unwrap()
        .starts_with("line 7"));
    // A post that feeds over the tab with the torch switched off.
    let fed = "M3 S1\nG1 X10 F100\n(tab)\nM62 P3\nG1 X13\nM63 P3\n(tab)\nM62 P3\nG1 X14\nM63 P3\nX20\nM5\n";
    assert!(torch_cycle_without_motion(fed).is_some());
}

/// Many rs274 checks at once, as the tests run, each read their tool
/// changes: under one HOME a quarter of such runs died of SIGBUS or lost
/// the tool table ([`run_rs274`]).
#[test]
fn rs274_checks_run_at_once_each_keep_their_tool_table() {
    if std::env::var("KERFCAM_NO_RS274").as_deref() == Ok("1") {
        return;
    }
    let program = "G21 G90\nT1 M6\nG0 X1 Y1\nT2 M6\nG0 X2\nM2\n";
    for round in 0..3 {
        let runs: Vec<_> = (0..30)
            .map(|i| {
                let name = format!("rs274-at-once-{round}-{i}");
                std::thread::spawn(move || rs274_errors(program, &name))
            })
            .collect();
        for r in runs {
            assert_eq!(r.join().unwrap(), Vec::<String>::new());
        }
    }
}

/// Everything `rs274 [-i INI] -g FILE` prints, or None when rs274 is
/// missing and KERFCAM_NO_RS274=1 (said on standard error).
fn run_rs274(ini: Option<&Path>, file: &Path, name: &str) -> Option<String> {
    // rs274 keeps its tool table in `$HOME/.tool.mmap`, opened with
    // O_TRUNC by every run (libtooldata, tooldata_mmap.cc). Runs at once
    // under one HOME truncate each other's map: a run dies of SIGBUS, or
    // says "Requested tool 1 not found in the tool table" of a program
    // that has it (30 runs at once: 36 of 150 failed under one HOME, 0 of
    // 300 each with its own, 2026-12-01). So each run gets its own HOME.
    let home = Rs274Home::new();
    let mut cmd = Command::new("rs274");
    cmd.env("HOME", &home.0);
    if let Some(ini) = ini {
        cmd.arg("-i").arg(ini);
    }
    let out = match cmd.arg("-g").arg(file).output() {
        Ok(o) => o,
        Err(e) => {
            if std::env::var("KERFCAM_NO_RS274").as_deref() == Ok("1") {
                // A skip, said out loud: nothing about this program was checked.
                eprintln!("SKIPPED: rs274 check of {name} (rs274 not found, KERFCAM_NO_RS274=1)");
                return None;
            }
            panic!("rs274 (linuxcnc-uspace) is needed to check programs: {e}; set KERFCAM_NO_RS274=1 to skip");
        }
    };
    let text =
        String::from_utf8_lossy(&out.stdout).into_owned() + &String::from_utf8_lossy(&out.stderr);
    assert!(
        out.status.code().is_some(),
        "rs274 on {name} was killed ({}):\n{text}",
        out.status
    );
    Some(text)
}

/// A HOME of one rs274 run, under the system's temporary directory,
/// removed with it.
struct Rs274Home(PathBuf);

impl Rs274Home {
    fn new() -> Rs274Home {
        use std::sync::atomic::{AtomicUsize, Ordering};
        static NEXT: AtomicUsize = AtomicUsize::new(0);
        let n = NEXT.fetch_add(1, Ordering::Relaxed);
        let dir = std::env::temp_dir().join(format!("kerfcam-rs274-{}-{n}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        Rs274Home(dir)
    }
}

impl Drop for Rs274Home {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

/// The lines of rs274's output that are neither canonical calls nor "executing".
pub fn rs274_error_lines(text: &str) -> Vec<String> {
    let canon = |l: &str| {
        let t = l.trim_start();
        let digits = t.chars().take_while(|c| c.is_ascii_digit()).count();
        digits > 0 && t[digits..].trim_start().starts_with("N.....")
    };
    text.lines()
        .filter(|l| !l.trim().is_empty() && l.trim() != "executing" && !canon(l))
        .map(String::from)
        .collect()
}

/// rs274 with an INI of three spindles (QtPlasmaC's torch, scribe and
/// spot: `M3 $0/$1/$2`). Two things of a QtPlasmaC program need the
/// machine's HAL and cannot be checked here: `M190 Pn` (a user M-code
/// QtPlasmaC installs; the stand-alone interpreter has none) and
/// `F#<_hal[plasmac.cut-feed-rate]>` (a HAL pin). They are checked as
/// text, then replaced by a comment and a plain F word for rs274; nothing
/// else is changed.
pub fn rs274_qtplasmac(program: &str, name: &str) -> Vec<String> {
    if let Some(e) = torch_cycle_without_motion(program) {
        panic!("{name}: {e}");
    }
    assert_eq!(program.matches("\nM190 P").count(), 1, "{program}");
    assert_eq!(
        program
            .matches("\nF#<_hal[plasmac.cut-feed-rate]>\n")
            .count(),
        1
    );
    let checked: String = program
        .lines()
        .map(|l| {
            if l.starts_with("M190 P") {
                "(M190: needs QtPlasmaC)".to_string()
            } else if l == "F#<_hal[plasmac.cut-feed-rate]>" {
                "F2000".to_string()
            } else {
                l.to_string()
            }
        })
        .collect::<Vec<_>>()
        .join("\n");
    let dir = out_dir();
    // One INI per program: tests run in parallel and a shared file could be
    // read while another test rewrites it.
    let ini = dir.join(format!("{name}.ini"));
    std::fs::write(&ini, "[TRAJ]\nSPINDLES = 3\n").unwrap();
    let file = dir.join(format!("{name}.ngc"));
    std::fs::write(&file, checked + "\n").unwrap();
    run_rs274(Some(&ini), &file, name).map_or_else(Vec::new, |text| rs274_error_lines(&text))
}

/// A `w` × `h` rectangle part at the origin, `quantity` copies, turned by
/// quarter turns.
pub fn rect_part(name: &str, w: f64, h: f64, quantity: usize) -> kerfcam::nest::Part {
    use kerfcam::geom::{Point, Segment};
    let c = [(0.0, 0.0), (w, 0.0), (w, h), (0.0, h)].map(|(x, y)| Point::new(x, y));
    kerfcam::nest::Part {
        name: name.into(),
        outer: (0..4)
            .map(|i| Segment::line(c[i], c[(i + 1) % 4]))
            .collect(),
        holes: vec![],
        quantity,
        rotations: kerfcam::nest::Rotations::Quarter,
        mirror: false,
    }
}
