//! The command line: arguments, files, exit codes (`anyhow` lives here only).

use std::path::PathBuf;
use std::process::ExitCode;

use anyhow::{anyhow, bail, Context, Result};
use kerfcam::geom::Point;
use kerfcam::kerf::Join;
use kerfcam::materials::Library;
use kerfcam::origin::ProgramOrigin;
use kerfcam::plan::{EulerMode, LeadKind, Order, PlanOptions};
use kerfcam::preview::{self, View};
use kerfcam::process::{LayerOps, Process, SmallHole};
use kerfcam::report::Report;
use kerfcam::warning::{dec, Lang};
use kerfcam::Settings;

const USAGE: &str = "\
usage: kerfcam FILE.dxf [options]

Reads a DXF drawing, finds its parts, compensates the kerf, orders the cuts
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
  --no-layer-names      cut every layer not given a --layer-op
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
                        (mm, cm, m, in, ft, …)
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
  --overcut MM          cut this far past the start at the end (default 0)
  --max-link MM         longest chain link through scrap (default 50)
  --outer-dir cw|ccw    direction of outer contours (default cw)
  --hole-dir cw|ccw     direction of holes (default ccw)
  --origin X,Y          where the tool starts, in program coordinates
                        (default 0,0)
  --program-origin O    which drawing point is the program's zero: auto
                        (default: the drawing's zero, unless the parts reach
                        below it or start over 1 m from it; then their
                        lower-left corner, with a note), drawing, lower-left,
                        or X,Y (a point in the drawing, mm)
  --cut-open            cut open contours on the line (marking, welding)
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
  --compare             add every order's figures to the JSON report
  --verify              sweep the kerf along the planned cuts and report
                        what it takes from the parts (overcut area and
                        depth, parts not cut free)
  -o, --output OUT.ngc  write the program here (default: standard output,
                        unless --json is given)
  --json                print the JSON report on standard output
  --png OUT.png         also write the preview image (1200 x 900)
  -q, --quiet           do not print warnings on standard error
  --lang en|pt-BR       language of the warnings, errors and JSON report
                        messages (default en; the program is the same)
  -h, --help            this text";

struct Args {
    input: PathBuf,
    kerf: f64,
    tolerance: f64,
    feed: f64,
    join: Join,
    decimals: u32,
    pierce_delay: f64,
    output: Option<PathBuf>,
    units: Option<kerfcam::dxf::Units>,
    gap: Option<f64>,
    layers: Option<Vec<String>>,
    json: bool,
    png: Option<PathBuf>,
    quiet: bool,
    lang: Lang,
    plan: PlanOptions,
    rapid: Option<f64>,
    compare: bool,
    verify: bool,
    program_origin: ProgramOrigin,
    material: Option<String>,
    materials: Option<PathBuf>,
    /// Options given on the command line (a material does not override them).
    given: Vec<&'static str>,
    post: Option<kerfcam::gcode::Post>,
    layer_ops: LayerOps,
    small_hole: SmallHole,
    heights: (f64, f64),
    material_number: u32,
    passes: kerfcam::process::Passes,
    thc_lock: kerfcam::process::ThcLock,
}

/// A preset by name, else a JSON file.
fn load_post(v: &str) -> Result<kerfcam::gcode::Post> {
    if let Some(p) = kerfcam::gcode::preset(v) {
        return Ok(p);
    }
    if !v.ends_with(".json") {
        bail!(
            "--post: '{v}' is not a preset ({}) nor a .json file",
            kerfcam::gcode::PRESET_NAMES.join(", ")
        );
    }
    let text = std::fs::read_to_string(v).with_context(|| format!("cannot read {v}"))?;
    kerfcam::gcode::Post::from_json(&text).with_context(|| format!("--post {v}"))
}

fn parse_args() -> Result<Option<Args>> {
    let mut args = std::env::args_os().skip(1);
    let mut a = Args {
        input: PathBuf::new(),
        kerf: 1.5,
        tolerance: 0.001,
        feed: 2000.0,
        join: Join::Round,
        decimals: 3,
        pierce_delay: 0.0,
        output: None,
        units: None,
        gap: None,
        layers: None,
        json: false,
        png: None,
        quiet: false,
        lang: Lang::En,
        plan: PlanOptions::DEFAULT,
        rapid: None,
        compare: false,
        verify: false,
        program_origin: ProgramOrigin::Auto,
        material: None,
        materials: None,
        given: Vec::new(),
        post: None,
        layer_ops: LayerOps::new(),
        small_hole: SmallHole::OFF,
        heights: (Process::DEFAULT.pierce_height, Process::DEFAULT.cut_height),
        material_number: 0,
        passes: kerfcam::process::Passes::OFF,
        thc_lock: kerfcam::process::ThcLock::OFF,
    };
    let mut input = None;
    while let Some(arg) = args.next() {
        let s = arg.to_string_lossy().into_owned();
        let mut value = |name: &str| -> Result<String> {
            args.next()
                .map(|v| v.to_string_lossy().into_owned())
                .with_context(|| format!("{name} needs a value"))
        };
        let num = |name: &str, v: String| -> Result<f64> {
            v.parse::<f64>()
                .with_context(|| format!("{name}: '{v}' is not a number"))
        };
        match s.as_str() {
            "-h" | "--help" => return Ok(None),
            "--kerf" => {
                a.kerf = num("--kerf", value("--kerf")?)?;
                a.given.push("kerf");
            }
            "--material" => a.material = Some(value("--material")?),
            "--materials" => a.materials = Some(PathBuf::from(value("--materials")?)),
            "--tolerance" => a.tolerance = num("--tolerance", value("--tolerance")?)?,
            "--feed" => {
                a.feed = num("--feed", value("--feed")?)?;
                a.given.push("feed");
            }
            "--pierce-delay" => {
                a.pierce_delay = num("--pierce-delay", value("--pierce-delay")?)?;
                a.given.push("pierce-delay");
            }
            "--decimals" => {
                let v = value("--decimals")?;
                a.decimals = v
                    .parse()
                    .with_context(|| format!("--decimals: '{v}' is not a whole number"))?;
            }
            "--join" => {
                a.join = match value("--join")?.as_str() {
                    "round" => Join::Round,
                    "miter" | "mitre" => Join::Miter,
                    other => bail!("--join: '{other}' is not round or miter"),
                }
            }
            "-o" | "--output" => a.output = Some(PathBuf::from(value("-o")?)),
            "--units" => {
                let v = value("--units")?;
                a.units = Some(
                    kerfcam::dxf::Units::from_name(&v)
                        .with_context(|| format!("--units: unknown unit '{v}'"))?,
                );
            }
            "--gap" => a.gap = Some(num("--gap", value("--gap")?)?),
            "--layers" => {
                a.layers = Some(
                    value("--layers")?
                        .split(',')
                        .map(|s| s.trim().to_string())
                        .collect(),
                )
            }
            "--rapid" => a.rapid = Some(num("--rapid", value("--rapid")?)?),
            "--order" => {
                let v = value("--order")?;
                a.plan.order = Order::from_name(&v).with_context(|| {
                    format!("--order: '{v}' is not contour, chained, eulerian or drawing")
                })?;
            }
            "--euler-mode" => {
                let v = value("--euler-mode")?;
                a.plan.euler_mode = EulerMode::from_name(&v)
                    .with_context(|| format!("--euler-mode: '{v}' is not repeat or rapid"))?;
            }
            "--lead" => {
                let v = value("--lead")?;
                a.plan.leads.kind = LeadKind::from_name(&v).with_context(|| {
                    format!("--lead: '{v}' is not perpendicular, tangential, bisector, arc or none")
                })?;
            }
            "--lead-outer" => {
                a.plan.leads.outer_length = num("--lead-outer", value("--lead-outer")?)?
            }
            "--lead-hole" => a.plan.leads.hole_length = num("--lead-hole", value("--lead-hole")?)?,
            "--overcut" => a.plan.leads.overcut = num("--overcut", value("--overcut")?)?,
            "--max-link" => a.plan.max_link = num("--max-link", value("--max-link")?)?,
            "--outer-dir" => a.plan.outer_ccw = direction("--outer-dir", &value("--outer-dir")?)?,
            "--hole-dir" => a.plan.hole_ccw = direction("--hole-dir", &value("--hole-dir")?)?,
            "--origin" => {
                let v = value("--origin")?;
                let (x, y) = v
                    .split_once(',')
                    .with_context(|| format!("--origin: '{v}' is not X,Y"))?;
                a.plan.origin = Point::new(
                    num("--origin", x.trim().into())?,
                    num("--origin", y.trim().into())?,
                );
            }
            "--program-origin" => {
                let v = value("--program-origin")?;
                a.program_origin = ProgramOrigin::from_name(&v).with_context(|| {
                    format!("--program-origin: '{v}' is not auto, drawing, lower-left or X,Y")
                })?;
            }
            "--cut-open" => a.plan.cut_open = true,
            "--layer-op" => {
                let v = value("--layer-op")?;
                a.layer_ops
                    .given
                    .push(LayerOps::parse_one(&v).with_context(|| {
                        format!("--layer-op: '{v}' is not LAYER=cut, mark, spot or ignore")
                    })?);
            }
            "--no-layer-names" => a.layer_ops.by_name = false,
            "--small-hole" => {
                a.small_hole.diameter = num("--small-hole", value("--small-hole")?)?;
                a.given.push("small-hole");
            }
            "--small-hole-speed" => {
                a.small_hole.speed_pct = num("--small-hole-speed", value("--small-hole-speed")?)?;
                a.given.push("small-hole-speed");
            }
            "--small-hole-min" => {
                a.small_hole.min_diameter = num("--small-hole-min", value("--small-hole-min")?)?
            }
            "--pierce-height" => {
                a.heights.0 = num("--pierce-height", value("--pierce-height")?)?;
                a.given.push("pierce-height");
            }
            "--cut-height" => {
                a.heights.1 = num("--cut-height", value("--cut-height")?)?;
                a.given.push("cut-height");
            }
            "--depth" => {
                a.passes.depth = num("--depth", value("--depth")?)?;
                a.given.push("depth");
            }
            "--pass-depth" => a.passes.pass_depth = num("--pass-depth", value("--pass-depth")?)?,
            "--material-number" => {
                let v = value("--material-number")?;
                a.given.push("material-number");
                a.material_number = v
                    .parse()
                    .with_context(|| format!("--material-number: '{v}' is not a whole number"))?;
            }
            "--thc-corner" => {
                a.thc_lock.corner_distance = num("--thc-corner", value("--thc-corner")?)?
            }
            "--thc-corner-angle" => {
                a.thc_lock.corner_angle_deg =
                    num("--thc-corner-angle", value("--thc-corner-angle")?)?
            }
            "--thc-end" => a.thc_lock.end_distance = num("--thc-end", value("--thc-end")?)?,
            "--tabs" => {
                let v = value("--tabs")?;
                a.plan.tabs.count = v
                    .parse()
                    .with_context(|| format!("--tabs: '{v}' is not a whole number"))?;
                if a.plan.tabs.width == 0.0 {
                    a.plan.tabs.width = 3.0;
                }
            }
            "--tab-width" => a.plan.tabs.width = num("--tab-width", value("--tab-width")?)?,
            "--tab-holes" => a.plan.tabs.holes = true,
            "--compare" => a.compare = true,
            "--controller-comp" => a.plan.controller_comp = true,
            "--verify" => a.verify = true,
            "--post" => a.post = Some(load_post(&value("--post")?)?),
            "--list-posts" => {
                println!("{}", kerfcam::gcode::PRESET_NAMES.join("\n"));
                std::process::exit(0);
            }
            "--json" => a.json = true,
            "--png" => a.png = Some(PathBuf::from(value("--png")?)),
            "-q" | "--quiet" => a.quiet = true,
            "--lang" => {
                let v = value("--lang")?;
                a.lang = Lang::from_name(&v)
                    .with_context(|| format!("--lang: '{v}' is not en or pt-BR"))?;
            }
            _ if s.starts_with('-') && s.len() > 1 => bail!("unknown option {s} (see --help)"),
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

/// True for "ccw", false for "cw".
fn direction(name: &str, v: &str) -> Result<bool> {
    kerfcam::plan::ccw_from_name(v).with_context(|| format!("{name}: '{v}' is not cw or ccw"))
}

/// Kerf, feed and pierce delay from the chosen cut-chart entry, where the
/// command line does not give them.
fn apply_material(args: &mut Args) -> Result<()> {
    let lib = match &args.materials {
        Some(path) => {
            let text = std::fs::read_to_string(path)
                .with_context(|| format!("cannot read {}", path.display()))?;
            Library::from_text(&text)
                .map_err(|e| anyhow!(e.message(args.lang)))
                .with_context(|| format!("--materials {}", path.display()))?
        }
        None => Library::starter(),
    };
    let Some(name) = &args.material else {
        return Ok(());
    };
    let e = lib.find(name).map_err(|e| anyhow!(e.message(args.lang)))?;
    if !args.given.contains(&"kerf") {
        args.kerf = e.kerf;
    }
    if !args.given.contains(&"feed") {
        args.feed = e.feed;
    }
    if !args.given.contains(&"pierce-delay") {
        args.pierce_delay = e.pierce_delay;
    }
    // Heights and the small-hole rule from the entry's process.
    let p = e.process(kerfcam::DEFAULT_RAPID);
    if !args.given.contains(&"pierce-height") {
        args.heights.0 = p.pierce_height;
    }
    if !args.given.contains(&"cut-height") {
        args.heights.1 = p.cut_height;
    }
    if !args.given.contains(&"depth") && args.passes.pass_depth > 0.0 {
        args.passes.depth = e.thickness;
    }
    if !args.given.contains(&"material-number") {
        args.material_number = p.material;
    }
    if !args.given.contains(&"small-hole") {
        args.small_hole.diameter = p.small_hole.diameter;
    }
    if !args.given.contains(&"small-hole-speed") {
        args.small_hole.speed_pct = p.small_hole.speed_pct;
    }
    if !args.quiet {
        let note = if e.example {
            " — an example: check it against your machine's cut chart"
        } else {
            ""
        };
        eprintln!(
            "material: {} (kerf {} mm, feed {} mm/min, pierce delay {} s){note}",
            e.name, args.kerf, args.feed, args.pierce_delay
        );
    }
    Ok(())
}

fn run() -> Result<()> {
    let Some(mut args) = parse_args()? else {
        println!("{USAGE}");
        return Ok(());
    };
    apply_material(&mut args)?;
    let bytes = std::fs::read(&args.input)
        .with_context(|| format!("cannot read {}", args.input.display()))?;
    let lang = args.lang;
    // Setting errors in the asked language (the English is their Display).
    let tr = |e: kerfcam::SettingsError| anyhow!(e.message(lang));
    let settings = Settings::new(args.kerf, args.tolerance, args.feed)
        .map_err(tr)?
        .with_lang(lang)
        .with_join(args.join)
        .with_decimals(args.decimals)
        .map_err(tr)?
        .with_pierce_delay(args.pierce_delay)
        .map_err(tr)?
        .with_rapid(
            args.rapid
                .or(args.post.as_ref().map(|p| p.rapid_speed))
                .unwrap_or(kerfcam::DEFAULT_RAPID),
        )
        .map_err(tr)?
        .with_plan(args.plan.clone())
        .map_err(tr)?;
    let settings = match args.post.clone() {
        Some(p) => settings.with_post(p).map_err(tr)?,
        None => settings,
    };
    let settings = settings
        .with_origin(args.program_origin)
        .map_err(tr)?
        .with_layer_ops(args.layer_ops.clone())
        .with_verify(args.verify)
        .with_small_hole(args.small_hole)
        .map_err(tr)?
        .with_heights(args.heights.0, args.heights.1)
        .map_err(tr)?
        .with_material_number(args.material_number)
        .map_err(tr)?
        .with_passes(args.passes)
        .map_err(tr)?
        .with_thc_lock(args.thc_lock)
        .map_err(tr)?;
    let settings = match args.units {
        Some(u) => settings.with_units(u),
        None => settings,
    };
    let settings = match args.gap {
        Some(g) => settings.with_gap(g).map_err(tr)?,
        None => settings,
    };
    let settings = match args.layers.clone() {
        Some(l) => settings.with_layers(l),
        None => settings,
    };
    let out = kerfcam::run(&bytes, &settings)
        .map_err(|e| anyhow!(e.message(lang)))
        .with_context(|| format!("{}", args.input.display()))?;
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
        Some(path) => std::fs::write(path, &out.gcode)
            .with_context(|| format!("cannot write {}", path.display()))?,
        None if !args.json => print!("{}", out.gcode),
        None => {}
    }
    if let Some(path) = &args.png {
        let view = View::fit(&preview::extent(&out), 1200, 900).context("preview size")?;
        let pixmap = preview::render(&out, &view).context("preview")?;
        pixmap
            .save_png(path)
            .with_context(|| format!("cannot write {}", path.display()))?;
    }
    if args.json {
        let mut report = Report::in_lang(&out, lang);
        if args.compare {
            let orders = [Order::Contour, Order::Chained, Order::Eulerian];
            report = report.with_comparison(&kerfcam::compare_orders(&out, &settings, &orders));
        }
        println!("{}", report.to_json());
    }
    Ok(())
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
