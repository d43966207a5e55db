//! The command line: arguments, files, exit codes (`anyhow` lives here only).

use std::path::PathBuf;
use std::process::ExitCode;

use anyhow::{anyhow, bail, Context, Result};
use kerfcam::plan::Order;
use kerfcam::preview::{self, View};
use kerfcam::report::Report;
use kerfcam::warning::{dec, Lang};
use kerfcam::{Settings, Spec};

use crate::cut_options;
use crate::quote_cli::{self, QuoteArgs};

const USAGE: &str = "\
usage: kerfcam FILE.dxf|FILE.svg [options]

Reads a DXF or SVG drawing, finds its parts, compensates the kerf, orders the cuts
and writes a LinuxCNC G-code program.

options:
  --kerf MM             kerf width (default 1.5; 0 cuts on the line)
  --tolerance MM        end points closer than this are joined (default 0.001)
  --gap MM              open ends up to this far apart are joined and
                        reported (default 50 x tolerance = 0.05)
  --feed MM_PER_MIN     cutting feed (default 2000)
  --join round|miter    convex corners of the kerf path (default round)
  --decimals N          decimal places in the program (default 3)
  --materials FILE      a cut chart: kerfcam JSON or a LinuxCNC
                        QtPlasmaC material file (default: kerfcam's examples)
  --material NAME       take kerf, feed and pierce delay from this chart
                        entry (--kerf, --feed, --pierce-delay still win)
  --pierce-delay S      dwell after torch on, seconds (default 0)
  --layer-op LAYER=OP   what a layer is for: cut, mark (scribed on the line
                        before any cut, no kerf), spot (points and closed
                        shapes' centres spotted) or ignore (reported, not
                        cut); repeatable. Without it a layer's name decides:
                        MARK, ETCH, SCRIBE… mark; SPOT, PUNCH spot; DIM,
                        TEXT, NULL, CHAPA… ignore; anything else is cut
                        Router layers: pocket (the region inside each
                        closed contour cleared, the closed contours in it
                        left standing), profile (cut like cut, the tool's
                        diameter as the kerf), engrave (on the line at the
                        depth), drill (points and small circles, pecked);
                        they need --tool-diameter, --depth, --pass-depth and
                        a router post (grbl-router, linuxcnc-router)
  --no-layer-names      cut every layer not given a --layer-op
  --tool-diameter MM    the router's end mill (default none; also the
                        profile's kerf unless --kerf is given)
  --stepover P          distance between pocket passes, % of the tool's
                        diameter (default 40)
  --plunge-feed MM_PER_MIN  feed of moves down into material: plunges,
                        ramps, helices, drilling (default 300)
  --spindle-rpm N       spindle speed, the post's {spindle_rpm} (default
                        18000)
  --tool-number N       the tool's number in the machine's tool table, the
                        post's {tool_number} (linuxcnc-router and
                        mach3-router: T N M6, G43 H N; default 1)
  --tool N=MM[,KEY=V…]  another tool for the job's list: number N,
                        diameter MM; keys feed, plunge-feed, spindle-rpm,
                        stepover (default the job tool's), v-angle,
                        allowance, helix-diameter, drill-max,
                        engrave-width, engrave-depth; repeatable. The
                        listed tools work in their order, the job's own
                        (--tool-diameter, --tool-number) last, with the
                        profiles; a tool change between
  --layer-tool LAYER=N  the tool a pocket, engrave or drill layer is
                        milled with (default the job's); repeatable
  --layer-depth LAYER=H[,pass-depth=D][,milling=climb|conventional]
                        a pocket, engrave or drill layer's own depth
                        (at most the job's --depth), deepest pass and
                        direction (default the job's); repeatable
  --conventional        finishing passes conventional (default climb: the
                        wall on the tool's right, clockwise spindle)
  --pocket zigzag|offset  pocket clearing: zig-zag passes staying down
                        where the link stays in the pocket (default) or
                        contour-parallel offsets
  --pocket-from centre|walls  contour-parallel offsets cut from the centre
                        outwards (default) or from the walls inwards
  --pocket-angle DEG    direction of the zig-zag passes (default 0: along X)
  --entry plunge|ramp|helix  how the tool goes down into a pocket
                        (default plunge)
  --ramp-angle DEG      ramp and helix angle (default 3)
  --helix-diameter MM   helix diameter (default half the tool's)
  --allowance MM        stock left on a pocket's walls by the roughing,
                        taken by the finishing pass (default 0)
  --peck MM             drilling peck depth (default the deepest pass)
  --drill-max MM        circles up to this diameter on a drill layer are
                        drilled at their centre (default the tool's)
  --v-angle DEG         a V-bit's included angle (e.g. 60, 90; default 0:
                        a flat end mill): an engraving is 2 x depth x
                        tan(angle/2) wide
  --engrave-width MM    with --v-angle: the engraving's width; its depth
                        follows (default 0: the depth gives the width)
  --engrave-depth MM    with --v-angle: the engraving's own depth; its
                        width follows (default 0: from the width, else
                        --depth); not with --engrave-width
  --small-hole MM       holes narrower than this are cut slower, entered
                        from the centre, overcut, height locked (default
                        off; 1.5 x thickness with a --material)
  --small-hole-speed P  their speed, % of the feed (default 60)
  --small-hole-min MM   holes narrower than this (or than the kerf) are
                        centre-spotted, not cut (default 0)
  --pierce-height MM    torch height at the pierce (Z posts, default 3.8)
  --cut-height MM       torch height while cutting (Z posts, default 1.5)
  --material-number N   the controller's material (QtPlasmaC M190 Pn)
  --depth MM            material thickness cut in depth passes (knife,
                        router, thick stock; default: the --material's
                        thickness when --pass-depth is given)
  --pass-depth MM       deepest pass: n = ceil(depth / this) passes of
                        depth / n at decreasing Z (default off; the post
                        needs a Z word, pass_z)
  --post NAME|FILE.json the program's dialect: a preset (see --list-posts)
                        or a post saved as JSON (default linuxcnc)
  --list-posts          print the preset names and exit
  --units UNIT          read the drawing in this unit whatever it says
                        (mm, cm, m, in, ft, …; for an SVG's px:
                        px at 96 per inch, px72 at 72)
  --layers A,B          cut only these layers (default: the visible ones)
  --rapid MM_PER_MIN    rapid traverse speed, for time estimates (default:
                        the post's, else 10000)
  --order ORDER         contour (default: one contour at a time, holes first,
                        short rapids), chained (outer contours linked through
                        scrap, one pierce per chain), eulerian (common-line:
                        kerf paths shared by parts spaced by the kerf cut
                        once, paper 003), drawing (the DXF's own entity
                        order, on the drawn lines; paper 002)
  --euler-mode MODE     repeat (default: the tool stays down and re-travels
                        edges) or rapid (the tool lifts between odd vertices)
  --lead KIND           lead-in: perpendicular (default), tangential, bisector,
                        arc or none
  --lead-outer MM       lead-in length on outer contours (default 5)
  --lead-hole MM        lead-in length in holes (default 3)
  --lead-radius MM      a router's profiles with --lead arc: each depth pass
                        entered and left on tangent arcs of this radius in
                        the waste, the tool up and across between passes;
                        an arc that would gouge a part is not cut, and
                        said (default 0: the tool's diameter)
  --overcut MM          cut this far past the start at the end (default 0)
  --max-link MM         longest chain link through scrap (default 50)
  --outer-dir cw|ccw    direction of outer contours (default cw)
  --hole-dir cw|ccw     direction of holes (default ccw)
  --origin X,Y          where the tool starts, in program coordinates
                        (default 0,0)
  --start X,Y           start the loop through X,Y (program coordinates,
                        within 1 mm of it) there; repeatable. Refused when
                        no cut loop passes that near
  --tab-at X,Y          leave a tab (--tab-width wide) where X,Y falls on
                        the loop through it (within 1 mm); repeatable
  --side-at X,Y=SIDE    with a tool: the profile through X,Y (within 1 mm)
                        cut outside, inside or on the line; the others go
                        to their waste side; repeatable. One that cannot
                        apply (no tool, an open contour) is said
  --program-origin O    which drawing point is the program's zero: auto
                        (default: the drawing's zero, unless the parts reach
                        below it or start over 1 m from it; then their
                        lower-left corner, with a note), drawing, lower-left,
                        or X,Y (a point in the drawing, mm)
  --cut-open            cut open contours on the line (marking, welding)
  --fit-arcs            runs of short feed moves (a polyline of tiny lines)
                        written as the fewest lines and arcs within
                        --tolerance, each from a drawn vertex to another;
                        the report gives the moves before and after
  --incremental         motion in G91 incremental coordinates (any G-code
                        post but a knife's; heights stay absolute, G90
                        around the templates)
  --controller-comp     leave the kerf to the controller: the drawn contours
                        with G41.1/G42.1 D<kerf> on a straight lead-in
                        and G40 after (contour order)
  --thc-corner MM       lock the torch height from MM before each sharp
                        corner to MM after it (the post's thc_lock and
                        thc_unlock: QtPlasmaC M62 P2 / M63 P2; default off)
  --thc-corner-angle DEG  corners with an included angle below this are
                        sharp (default 120; 90 = a square corner)
  --thc-end MM          lock the height MM before the contour's end
                        (default off: from the lead-out)
  --tabs N              leave N tabs (micro-joints) uncut on each part's
                        outer contour, on its longest straight edges, clear
                        of corners and leads; the torch goes off over each
                        and pierces again after it (default 0)
  --tab-width MM        material left in each tab (default 3; the torch is
                        off for this plus the kerf)
  --tab-holes           tabs on holes too
  --tab-height MM       a router's tabs leave a bridge MM high at the bottom:
                        the passes deeper than depth - MM go up to it over
                        each tab and across, those above cut through
                        (default 0: the tool lifts out over each tab)
  --compare             add every order's figures to the JSON report
  --verify              sweep the kerf along the planned cuts and report
                        what it takes from the parts (overcut area and
                        depth, parts not cut free); a router's pockets: the
                        tool along their moves (gouge, material left)
  --no-repair           leave outlines that cross themselves uncut, as drawn
                        (default: cut the outline of the region they enclose,
                        by the non-zero rule, and say where)
  -o, --output OUT.ngc  write the program here (default: standard output,
                        unless --json is given); OUT.svg: write the cut plan
                        instead, as an SVG drawing in mm (contours, kerf
                        paths, leads, pierces, rapids; a layer per part)
  --json                print the JSON report on standard output
  --cost FILE.json      a cost model (machine rate, per pierce, per metre,
                        material, setup, markup: docs/quote.md): the job
                        quoted per part, its totals on standard error and
                        in the JSON report's quote section
  --quote FILE.csv      write the quote as CSV: a row per part, the sheet,
                        the job (needs --cost)
  --quote-locale L      the CSV's convention: en (default: `,` between cells,
                        `.` decimals) or pt-BR (`;` and `,` decimals,
                        Portuguese headers, as a Brazilian spreadsheet reads)
  --png OUT.png         also write the preview image (1200 x 900)
  --threads N           threads the stages may use (default: the machine's
                        cores, at most 8; the program is the same with any)
  -q, --quiet           do not print warnings on standard error
  --lang en|pt-BR       language of the warnings, errors and JSON report
                        messages (default en; the program is the same)
  -h, --help            this text (kerfcam help nest: the nest command's)
  -V, --version         the version";

struct Args {
    input: PathBuf,
    output: Option<PathBuf>,
    json: bool,
    png: Option<PathBuf>,
    quiet: bool,
    compare: bool,
    /// Threads for the stages (None: the machine's cores).
    threads: Option<usize>,
    /// Every cutting setting, as given (checked by `Spec::build`).
    spec: Spec,
    /// `--cost` and `--quote`.
    quote: QuoteArgs,
}

fn parse_args() -> Result<Option<Args>> {
    let mut args = std::env::args_os().skip(1);
    let mut a = Args {
        input: PathBuf::new(),
        output: None,
        json: false,
        png: None,
        quiet: false,
        compare: false,
        threads: None,
        spec: Spec::default(),
        quote: QuoteArgs::default(),
    };
    let mut input = None;
    while let Some(arg) = args.next() {
        let s = arg.to_string_lossy().into_owned();
        let mut value = |name: &str| -> Result<String> {
            args.next()
                .map(|v| v.to_string_lossy().into_owned())
                .with_context(|| format!("{name} needs a value"))
        };
        if cut_options::apply(&mut a.spec, &s, &mut value)? || a.quote.take(&s, &mut value)? {
            continue;
        }
        match s.as_str() {
            "-h" | "--help" => return Ok(None),
            "-V" | "--version" => {
                crate::out(&format!("{}\n", version()));
                std::process::exit(0);
            }
            "-o" | "--output" => a.output = Some(PathBuf::from(value("-o")?)),
            "--list-posts" => {
                crate::out(&format!("{}\n", kerfcam::gcode::PRESET_NAMES.join("\n")));
                std::process::exit(0);
            }
            "--compare" => a.compare = true,
            "--threads" => {
                let v = value("--threads")?;
                let n = v
                    .parse::<usize>()
                    .ok()
                    .filter(|&n| n >= 1)
                    .with_context(|| {
                        format!("--threads: '{v}' is not a whole number of 1 or more")
                    })?;
                a.threads = Some(n);
            }
            "--json" => a.json = true,
            "--png" => a.png = Some(PathBuf::from(value("--png")?)),
            "-q" | "--quiet" => a.quiet = true,
            _ if s.starts_with('-') && s.len() > 1 => {
                bail!("{} (see --help)", unknown_option(&s, &[USAGE]))
            }
            _ => {
                if input.is_some() {
                    bail!("only one input file, please (got a second: {s})");
                }
                input = Some(PathBuf::from(arg));
            }
        }
    }
    a.input = input.context("no input file (see --help)")?;
    Ok(Some(a))
}

/// Says which cut-chart entry set the job, and that an example entry is
/// not the machine's chart.
fn material_note(settings: &Settings, lang: Lang) {
    let Some(m) = settings.material() else {
        return;
    };
    let p = settings.process();
    let (name, kerf, feed, delay) = (&m.name, p.kerf, p.feed, p.pierce_delay);
    let note = match (m.example, lang) {
        (false, _) => "",
        (true, Lang::En) => " — an example: check it against your machine's cut chart",
        (true, Lang::PtBr) => " — um exemplo: confira na tabela de corte da sua máquina",
    };
    let line = kerfcam::text!(
        "material: {} (kerf {} mm, feed {} mm/min, pierce delay {} s){}",
        name, kerf, feed, delay, note;
        "material: {} (sangria {} mm, velocidade {} mm/min, tempo de perfuração {} s){}",
        name, dec(kerf), dec(feed), dec(delay), note
    );
    eprintln!("{}", line.get(lang));
}

fn run() -> Result<()> {
    let Some(args) = parse_args()? else {
        crate::out(&format!("{USAGE}\n"));
        return Ok(());
    };
    let lang = args.spec.lang();
    // Setting errors in the asked language (the English is their Display).
    let mut settings = args
        .spec
        .build()
        .map_err(|e| cut_options::settings_error(&e, lang))?;
    if let Some(n) = args.threads {
        settings = settings.with_threads(kerfcam::par::Threads::new(n));
    }
    let model = args.quote.model(lang)?;
    if !args.quiet {
        material_note(&settings, lang);
    }
    let bytes = std::fs::read(&args.input)
        .with_context(|| format!("cannot read {}", args.input.display()))?;
    let out = kerfcam::run(&bytes, &settings)
        .map_err(|e| anyhow!(e.message(lang)))
        .with_context(|| format!("{}", args.input.display()))?;
    refuse_unplaced(&settings, &out)?;
    if let (Some(f), false) = (out.arc_fit(), args.quiet) {
        let (before, after) = (f.lines_before + f.arcs_before, f.lines_after + f.arcs_after);
        match lang {
            Lang::En => eprintln!(
                "arc fitting: {before} feed moves ({} lines, {} arcs) -> {after} ({} lines, {} arcs) within {} mm",
                f.lines_before, f.arcs_before, f.lines_after, f.arcs_after, f.tolerance
            ),
            Lang::PtBr => eprintln!(
                "ajuste de arcos: {before} movimentos de corte ({} retas, {} arcos) -> {after} ({} retas, {} arcos) dentro de {} mm",
                f.lines_before, f.arcs_before, f.lines_after, f.arcs_after, dec(f.tolerance)
            ),
        }
    }
    if !args.quiet {
        for w in out.warnings() {
            let m = w.message_in(lang);
            match (w.at, lang) {
                (Some(p), Lang::En) => eprintln!("warning: {m} (at {:.3}, {:.3})", p.x, p.y),
                (Some(p), Lang::PtBr) => {
                    eprintln!("aviso: {m} (em {:.3}; {:.3})", dec(p.x), dec(p.y))
                }
                (None, Lang::En) => eprintln!("warning: {m}"),
                (None, Lang::PtBr) => eprintln!("aviso: {m}"),
            }
        }
    }
    match &args.output {
        Some(path) => {
            let svg = path
                .extension()
                .is_some_and(|e| e.eq_ignore_ascii_case("svg"));
            let written = if svg {
                // The sheet's layer is named after the file (escaped: data).
                let label = args.input.file_name().unwrap_or_default().to_string_lossy();
                // The program's rapids, as Play walks them.
                let rapids =
                    kerfcam::animation::rapids(&out.scene(), &out.process, settings.post());
                std::fs::write(
                    path,
                    kerfcam::svg::plan::to_svg(&[kerfcam::svg::plan::SheetPlan {
                        label: &label,
                        scene: out.scene(),
                        names: &[],
                        rapids: &rapids,
                    }]),
                )
            } else {
                std::fs::write(path, &out.gcode)
            };
            written.with_context(|| format!("cannot write {}", path.display()))?
        }
        None if !args.json => crate::out(&out.gcode),
        None => {}
    }
    if let Some(path) = &args.png {
        let view = View::fit(&preview::extent(&out.scene()), 1200, 900).context("preview size")?;
        // A router's rapids as its program makes them (Play and the SVG's).
        let rapids =
            kerfcam::animation::preview_rapids(&out.scene(), &out.process, settings.post());
        let scene = kerfcam::scene::Scene {
            rapids: rapids.as_deref(),
            ..out.scene()
        };
        let pixmap = preview::render(&scene, &view).context("preview")?;
        pixmap
            .save_png(path)
            .with_context(|| format!("cannot write {}", path.display()))?;
    }
    let quote = match &model {
        Some(m) => {
            // One drawing, no sheet: its parts are named after the file.
            let stem = args
                .input
                .file_stem()
                .map_or("part".into(), |s| s.to_string_lossy().into_owned());
            let sheet = kerfcam::quote::SheetInput {
                out: &out,
                used_area_mm2: None,
                cost: None,
            };
            let q = quote_cli::make(m, &[sheet], &|p| format!("{stem}#{p}"), lang)?;
            quote_cli::write(&q, &args.quote, args.quiet, lang)?;
            Some(q)
        }
        None => None,
    };
    if args.json {
        let mut report = Report::in_lang(&out, lang);
        if let Some(q) = quote {
            report = report.with_quote(q);
        }
        if args.compare {
            let orders = [Order::Contour, Order::Chained, Order::Eulerian];
            report = report.with_comparison(&kerfcam::compare_orders(&out, &settings, &orders));
        }
        crate::out(&format!("{}\n", report.to_json()));
    }
    Ok(())
}

/// `--start` and `--tab-at` points that no cut loop passes near: refused
/// (the page keeps such a choice for when its loop comes back; on the
/// command line it is a typing error).
fn refuse_unplaced(settings: &Settings, out: &kerfcam::Output) -> Result<()> {
    let plan = settings.plan();
    let tol = settings.tolerance().mm();
    for (opt, picks) in [("--start", &plan.starts), ("--tab-at", &plan.tabs_at)] {
        let placed = kerfcam::plan::choice::place(picks, &out.contours, tol);
        if let Some((p, _)) = picks.iter().zip(&placed).find(|(_, c)| c.is_none()) {
            bail!(
                "{opt} {},{}: no cut loop passes within {} mm of it",
                p.at.x,
                p.at.y,
                kerfcam::plan::choice::REACH_MM
            );
        }
    }
    Ok(())
}

/// `kerfcam 0.1.0`: `kerfcam --version` and `-V`.
pub fn version() -> String {
    format!("kerfcam {}", env!("CARGO_PKG_VERSION"))
}

/// The plain command's help (`kerfcam --help`, `kerfcam help`).
pub fn usage() -> &'static str {
    USAGE
}

/// "unknown option --kerff (did you mean --kerf?)": the closest of the
/// options the usage texts name, when one is close enough to be a typo.
pub fn unknown_option(given: &str, usages: &[&str]) -> String {
    let options = usages.iter().flat_map(|u| options_in(u));
    match closest(given, options) {
        Some(o) => format!("unknown option {given} (did you mean {o}?)"),
        None => format!("unknown option {given}"),
    }
}

/// Every `-x` and `--word` a usage text names.
fn options_in(usage: &str) -> impl Iterator<Item = &str> + '_ {
    usage
        .split(|c: char| !(c.is_ascii_alphanumeric() || c == '-'))
        .filter(|w| {
            let name = w.trim_start_matches('-');
            (w.starts_with("--") && name.len() > 1 || w.len() == 2 && w.starts_with('-'))
                && name.starts_with(|c: char| c.is_ascii_alphabetic())
        })
}

/// The candidate nearest `given` in edit distance, if within a third of
/// its length (at least 1 edit, at most 3); ties go to the first named.
fn closest<'a>(given: &str, candidates: impl Iterator<Item = &'a str>) -> Option<&'a str> {
    let bound = (given.len() / 3).clamp(1, 3);
    let mut best: Option<(usize, &str)> = None;
    for c in candidates {
        let d = edit_distance(given, c);
        if d <= bound && best.is_none_or(|(b, _)| d < b) {
            best = Some((d, c));
        }
    }
    best.map(|(_, c)| c)
}

/// Levenshtein distance over chars.
fn edit_distance(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut row: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut diag = row[0];
        row[0] = i + 1;
        for (j, &cb) in b.iter().enumerate() {
            let next = (diag + usize::from(ca != cb))
                .min(row[j] + 1)
                .min(row[j + 1] + 1);
            diag = row[j + 1];
            row[j + 1] = next;
        }
    }
    row[b.len()]
}

/// Runs the command; exit code 2 with a one-line error on failure.
pub fn main() -> ExitCode {
    match run() {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            // One line: the context chain joined.
            eprintln!("kerfcam: error: {e:#}");
            ExitCode::from(2)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_typo_suggests_the_closest_option() {
        assert_eq!(
            unknown_option("--kerff", &[USAGE]),
            "unknown option --kerff (did you mean --kerf?)"
        );
        assert_eq!(
            unknown_option("--jsn", &[USAGE]),
            "unknown option --jsn (did you mean --json?)"
        );
        assert_eq!(
            unknown_option("--verison", &[USAGE]),
            "unknown option --verison (did you mean --version?)"
        );
        assert_eq!(
            unknown_option("--frobnicate", &[USAGE]),
            "unknown option --frobnicate"
        );
    }

    #[test]
    fn options_are_read_from_the_usage() {
        let o: Vec<&str> = options_in(USAGE).collect();
        for name in [
            "-o",
            "--output",
            "--json",
            "--tabs",
            "--tab-width",
            "-V",
            "--version",
            "-h",
        ] {
            assert!(o.contains(&name), "{name} in {o:?}");
        }
        assert!(
            !o.iter().any(|w| w.starts_with("--") && w.len() < 4),
            "{o:?}"
        );
    }

    #[test]
    fn edit_distances() {
        assert_eq!(edit_distance("--kerf", "--kerf"), 0);
        assert_eq!(edit_distance("--kref", "--kerf"), 2);
        assert_eq!(edit_distance("", "abc"), 3);
        assert_eq!(edit_distance("--tab", "--tabs"), 1);
    }
}
