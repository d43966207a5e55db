//! `kerfcam nest`: parts from DXF files (or an ESICUP instance) nested on
//! sheets or a strip; the nest written as DXF, JSON and G-code.

use std::path::PathBuf;
use std::process::ExitCode;
use std::time::Instant;

use anyhow::{anyhow, bail, Context, Result};
use kerfcam::label::{self, LabelOptions, Labels, Naming};
use kerfcam::nest::{
    self, output, Nest, NestJob, NestSettings, NestSpec, Rotations, SheetSize, Sheets,
};
use kerfcam::text;
use kerfcam::warning::{dec, Lang};
use kerfcam::Settings;

const USAGE: &str = "\
usage: kerfcam nest PART.dxf[:QTY]... (--sheet WxH[:N[:COST]] | --sheet-dxf FILE | --strip-height H) [options]
       kerfcam nest --instance FILE.json [--sheet WxH[:N[:COST]]] [--time S] [-o NEST.dxf] [--json]

Nests every part found in the DXF or SVG files (an outer outline with its holes;
QTY copies of each, default 1) on sheets W x H mm (N of them, default 1;
--sheet again for more sizes, filled in the order given; with a COST for
every size, N is the stock and the nest takes the cheapest combination of
sheets that holds every copy, its cost in the report), on one irregular sheet drawn in a DXF (its largest outline; its holes and
closed outlines on layer DEFECT are no-go zones) or on a strip H mm high,
and writes the nest. Small parts go inside the holes of bigger ones.

options:
  --spacing MM          least distance between parts (default kerf + 1)
  --margin MM           least distance to the sheet's edge (default 5)
  --kerf MM             kerf width for --gcode and the default spacing (default
                        1.5, or the --material's)
  --rotations R         none, 180, 90, free or N (N equal steps; default 90)
  --mirror              parts may be mirrored
  --time S              time budget, seconds, the first nest included
                        (default 30; 0 = the first nest whole, nothing more)
  --evaluations N       stop after N evaluations: a copy placed in the first
                        nest, an order tried, a move (reproducible runs)
  --seed N              seed of the improvement (default 1)
  --threads N           N searches at once, one a thread, exchanging their
                        best nest every 10 000 evaluations (default 1; at
                        most 8; the nest depends on N: with --evaluations,
                        the same seed and N give the same nest; the budget
                        holds for each search)
  --tolerance MM        largest excess of the collision polygons (default 0.05)
  -o, --output FILE     the nest as DXF (parts on a layer each, sheets on SHEET),
                        or as SVG when FILE ends in .svg (mm, a layer per sheet)
  --json                print the nest's figures as JSON
  --remnant FILE        the remnant kept beyond the crop line of the last
                        sheet, as a DXF to give back as --sheet-dxf
  --gcode FILE          cut the nest: the first sheet's program to FILE, sheet k
                        to FILE-k (k = 2, 3, ...)
  --instance FILE       an ESICUP strip-packing instance (JSON): strip mode
                        (or the --sheet sizes given), the instance's
                        rotations, no mirror, spacing 0
  --torches N           N torches cut at once, across the sheet (paper 001
                        §6.5): the nest is made for torch 1's band, quantities
                        divided by N (rounded up); the program drives torch 1
  --torch-spacing MM    distance between torches along Y (needed with --torches)
  --torch-park X,Y      park there and stop (M0) for the operator to set the
                        torches before the first cut
  --cost FILE.json      a cost model (docs/quote.md): every sheet cut as
                        --gcode cuts it and the job quoted per part, per
                        sheet and in all (material by the sheet used up to
                        the crop line with material_share sheet);
                        totals on standard error, a quote section in --json
  --quote FILE.csv      write the quote as CSV: a row per part, per sheet,
                        the job (needs --cost)
  --quote-locale L      the CSV's convention: en (default: `,` between cells,
                        `.` decimals) or pt-BR (`;` and `,` decimals,
                        Portuguese headers, as a Brazilian spreadsheet reads)
  --labels KIND         label every placed copy inside the part, in -o (layer
                        LABELS; a group in SVG) and --json: name (the part's
                        name and copy, BRACKET#3) or code (A3: a letter per part)
  --label-mark          scribe the labels with --gcode, as marks before the
                        cuts (with --labels name unless --labels is given)
  --label-height MM     largest label height (default 10)
  --label-min MM        smallest label height: a copy with no room for it gets
                        none, with a note naming the part (default 3)
  --label-margin MM     least distance from a label to the part's edges and
                        holes (default 2)

Every cutting option of `kerfcam FILE.dxf` (see kerfcam --help) applies to
--gcode and to reading the parts (--units, --layers, --material, --post,
--order, --lead…), except --tolerance, which here is the nest's.
";

#[derive(Default)]
struct Args {
    parts: Vec<(PathBuf, usize)>,
    sheet: Vec<SheetSize>,
    /// Each `--sheet`'s cost, when given.
    sheet_cost: Vec<Option<f64>>,
    strip: Option<f64>,
    sheet_dxf: Option<PathBuf>,
    remnant: Option<PathBuf>,
    rotations: Option<Rotations>,
    mirror: bool,
    output: Option<PathBuf>,
    json: bool,
    gcode: Option<PathBuf>,
    instance: Option<PathBuf>,
    /// The nest's own options (spacing, margin, budget, torches…), read
    /// as the page's are.
    nest: NestSpec,
    /// The cutting options of `kerfcam FILE.dxf` (for reading the parts'
    /// units and layers, and for `--gcode`).
    spec: kerfcam::Spec,
    /// `--cost` and `--quote`.
    quote: crate::quote_cli::QuoteArgs,
    /// What the labels say; None: no labels.
    labels: Option<Naming>,
    /// Scribe them with `--gcode`.
    label_mark: bool,
    /// Their sizes and margin.
    label: LabelOptions,
    /// Searches at once (`--threads`; 0 read as 1).
    searches: usize,
}

fn number<T: std::str::FromStr>(flag: &str, v: Option<String>) -> Result<T> {
    let v = v.ok_or_else(|| anyhow!("{flag} needs a value"))?;
    v.parse()
        .map_err(|_| anyhow!("{flag}: '{v}' is not a number"))
}

fn parse(mut it: impl Iterator<Item = String>) -> Result<Option<Args>> {
    let mut a = Args::default();
    while let Some(arg) = it.next() {
        match arg.as_str() {
            "-h" | "--help" => return Ok(None),
            "-V" | "--version" => {
                crate::out(&format!("{}\n", crate::cli::version()));
                std::process::exit(0);
            }
            "--sheet" => {
                let v: String = number("--sheet", it.next())?;
                let (size, n) = v.split_once(':').map_or((v.as_str(), "1"), |(s, n)| (s, n));
                let (n, cost) = match n.split_once(':') {
                    Some((n, c)) => {
                        let c: f64 = c.parse().map_err(|_| {
                            anyhow!("--sheet: '{v}': the cost '{c}' is not a number")
                        })?;
                        (n, Some(c))
                    }
                    None => (n, None),
                };
                a.sheet_cost.push(cost);
                let (w, h) = size
                    .split_once(['x', 'X'])
                    .ok_or_else(|| anyhow!("--sheet: '{v}' is not WxH[:N[:COST]]"))?;
                let w: f64 = w
                    .parse()
                    .map_err(|_| anyhow!("--sheet: '{v}' is not WxH[:N[:COST]]"))?;
                let h: f64 = h
                    .parse()
                    .map_err(|_| anyhow!("--sheet: '{v}' is not WxH[:N[:COST]]"))?;
                let n: usize = n
                    .parse()
                    .map_err(|_| anyhow!("--sheet: '{v}' is not WxH[:N[:COST]]"))?;
                a.sheet.push(SheetSize {
                    width: w,
                    height: h,
                    count: n,
                });
            }
            "--strip-height" => a.strip = Some(number(&arg, it.next())?),
            "--spacing" => a.nest.spacing = Some(number(&arg, it.next())?),
            "--margin" => a.nest.margin = Some(number(&arg, it.next())?),
            "--time" => a.nest.time_s = Some(number(&arg, it.next())?),
            "--evaluations" => a.nest.max_evaluations = Some(number(&arg, it.next())?),
            "--seed" => a.nest.seed = Some(number(&arg, it.next())?),
            "--threads" => {
                let n: usize = number(&arg, it.next())?;
                if n == 0 {
                    return Err(anyhow!("--threads: 1 or more"));
                }
                a.searches = n;
            }
            "--tolerance" => a.nest.tolerance = Some(number(&arg, it.next())?),
            "--torches" => a.nest.torches = Some(number(&arg, it.next())?),
            "--torch-spacing" => a.nest.torch_spacing = Some(number(&arg, it.next())?),
            "--torch-park" => {
                let v: String = number(&arg, it.next())?;
                let xy = v
                    .split_once(',')
                    .and_then(|(x, y)| Some([x.trim().parse().ok()?, y.trim().parse().ok()?]));
                a.nest.torch_park =
                    Some(xy.ok_or_else(|| anyhow!("--torch-park: '{v}' is not X,Y in mm"))?);
            }
            "--labels" => {
                let v: String = number(&arg, it.next())?;
                a.labels = Some(
                    Naming::from_name(&v)
                        .ok_or_else(|| anyhow!("--labels: '{v}' is not name or code"))?,
                );
            }
            "--label-mark" => a.label_mark = true,
            "--label-height" => a.label.height_max = number(&arg, it.next())?,
            "--label-min" => a.label.height_min = number(&arg, it.next())?,
            "--label-margin" => a.label.margin = number(&arg, it.next())?,
            "--mirror" => a.mirror = true,
            "--json" => a.json = true,
            "--rotations" => {
                let v: String = number(&arg, it.next())?;
                a.rotations = Some(Rotations::from_name(&v).ok_or_else(|| {
                    anyhow!(
                        "--rotations: '{v}' is not none, 180, 90, free or a number of steps 1..360"
                    )
                })?);
            }
            "-o" | "--output" => a.output = Some(number::<String>(&arg, it.next())?.into()),
            "--gcode" => a.gcode = Some(number::<String>(&arg, it.next())?.into()),
            "--sheet-dxf" => a.sheet_dxf = Some(number::<String>(&arg, it.next())?.into()),
            "--remnant" => a.remnant = Some(number::<String>(&arg, it.next())?.into()),
            "--instance" => a.instance = Some(number::<String>(&arg, it.next())?.into()),
            f if f.starts_with('-') => {
                // Every cutting option of the plain command (one parser).
                let mut value =
                    |name: &str| it.next().ok_or_else(|| anyhow!("{name} needs a value"));
                if !crate::cut_options::apply(&mut a.spec, f, &mut value)?
                    && !a.quote.take(f, &mut value)?
                {
                    let usages = [USAGE, crate::cli::usage()];
                    bail!(
                        "{} (see kerfcam nest --help)",
                        crate::cli::unknown_option(f, &usages)
                    );
                }
            }
            file => {
                // PART.dxf:12 — the last ':' followed by digits only.
                let (path, qty) = match file.rsplit_once(':') {
                    Some((p, q)) if !q.is_empty() && q.bytes().all(|b| b.is_ascii_digit()) => (
                        p,
                        q.parse::<usize>()
                            .map_err(|_| anyhow!("{file}: quantity too large"))?,
                    ),
                    _ => (file, 1),
                };
                a.parts.push((path.into(), qty));
            }
        }
    }
    Ok(Some(a))
}

fn job(
    a: &Args,
    read: &Settings,
    settings: NestSettings,
    lang: Lang,
) -> Result<(NestJob, Vec<nest::Unplaced>)> {
    if let Some(path) = &a.instance {
        let text = std::fs::read_to_string(path)
            .with_context(|| format!("cannot read {}", path.display()))?;
        let i =
            nest::instance::read(&text, settings).with_context(|| path.display().to_string())?;
        let mut job = i.job;
        // --sheet with an instance: its parts cut on fixed sheets (the
        // sheet-vs-strip measure of scripts/bench-nest-sheets.sh).
        if !a.sheet.is_empty() {
            job.sheets = Sheets::rects(a.sheet.clone());
        }
        return Ok((job, Vec::new()));
    }
    if a.parts.is_empty() {
        bail!("no part files (see kerfcam nest --help)");
    }
    let (mut parts, mut notes) = (Vec::new(), Vec::new());
    let sheets = match (a.sheet.is_empty(), a.strip, &a.sheet_dxf) {
        (false, None, None) => Sheets::rects(a.sheet.clone()),
        (true, Some(height), None) => Sheets::Strip { height },
        (true, None, Some(path)) => {
            let bytes =
                std::fs::read(path).with_context(|| format!("cannot read {}", path.display()))?;
            let (sheets, said) = nest::read_sheet(&bytes, read)
                .map_err(|e| anyhow!("{}: {}", path.display(), e.get(lang)))?;
            for s in said {
                eprintln!("kerfcam nest: {}: {}", path.display(), s.get(lang));
            }
            sheets
        }
        _ => bail!("give one of --sheet WxH[:N], --sheet-dxf FILE or --strip-height H"),
    };
    for (path, qty) in &a.parts {
        let bytes =
            std::fs::read(path).with_context(|| format!("cannot read {}", path.display()))?;
        let name = path
            .file_stem()
            .map_or("part".into(), |s| s.to_string_lossy().into_owned());
        let (mut p, n) = nest::read_parts(&bytes, &name, *qty, read)
            .map_err(|e| anyhow!("{}: {}", path.display(), e.get(lang)))?;
        for part in &mut p {
            part.rotations = a.rotations.clone().unwrap_or(Rotations::Quarter);
            part.mirror = a.mirror;
        }
        parts.extend(p);
        notes.extend(n);
    }
    Ok((
        NestJob {
            parts,
            sheets,
            settings,
        },
        notes,
    ))
}

/// Each sheet cut with the ordinary pipeline ([`kerfcam::nest_cut`]: the
/// nest's drawing → contours → kerf → plan → program, the crop line last),
/// with the labels scribed as marks before the cuts when given.
fn cut_sheets(
    job: &NestJob,
    n: &Nest,
    settings: &Settings,
    labels: Option<&Labels>,
) -> Result<Vec<kerfcam::Output>> {
    (0..n.sheets.len())
        .map(|k| {
            kerfcam::nest_cut::cut_sheet_labelled(job, n, k, settings, labels)
                .map_err(|e| anyhow!("sheet {}: {e}", k + 1))
        })
        .collect()
}

/// The sheets' programs: the first to `path`, sheet k to `path`-k.
fn write_gcode(sheets: &[kerfcam::Output], path: &std::path::Path) -> Result<()> {
    for (k, out) in sheets.iter().enumerate() {
        let program = &out.gcode;
        let file = if k == 0 {
            path.to_path_buf()
        } else {
            let stem = path
                .file_stem()
                .map_or("nest".into(), |s| s.to_string_lossy().into_owned());
            let ext = path
                .extension()
                .map_or(String::new(), |e| format!(".{}", e.to_string_lossy()));
            path.with_file_name(format!("{stem}-{}{ext}", k + 1))
        };
        std::fs::write(&file, program)
            .with_context(|| format!("cannot write {}", file.display()))?;
    }
    Ok(())
}

/// The quote of the cut sheets: parts named as the nest names them, each
/// sheet used up to its crop line (its box for an irregular sheet).
fn quote(
    m: &kerfcam::quote::CostModel,
    job: &NestJob,
    n: &Nest,
    sheets: &[kerfcam::Output],
    costs: Option<&[f64]>,
    lang: Lang,
) -> Result<kerfcam::quote::Quote> {
    let inputs: Vec<kerfcam::quote::SheetInput> = sheets
        .iter()
        .zip(&n.sheets)
        .enumerate()
        .map(|(k, (out, s))| kerfcam::quote::SheetInput {
            out,
            used_area_mm2: Some(s.height * s.crop_x.unwrap_or(s.width)),
            cost: costs.and_then(|c| c.get(k).copied()),
        })
        .collect();
    let name = |p: u32| {
        (p as usize)
            .checked_sub(1)
            .and_then(|i| job.parts.get(i))
            .map_or(format!("#{p}"), |part| part.name.clone())
    };
    crate::quote_cli::make(m, &inputs, &name, lang)
}

fn run(args: impl Iterator<Item = String>) -> Result<()> {
    let Some(mut a) = parse(args)? else {
        crate::out(USAGE);
        return Ok(());
    };
    if a.label_mark && a.labels.is_none() {
        a.labels = Some(Naming::Name);
    }
    if let Some(naming) = a.labels {
        a.label.naming = naming;
        if let Err((field, why)) = a.label.check() {
            let flag = match field {
                "label_height_min" => "--label-min",
                "label_margin" => "--label-margin",
                _ => "--label-height",
            };
            bail!("{flag}: {}", why.get(a.spec.lang()));
        }
    }
    let lang = a.spec.lang();
    let model = a.quote.model(lang)?;
    let cutting = a
        .spec
        .build()
        .map_err(|e| crate::cut_options::settings_error(&e, lang))?;
    // Spacing by the kerf given, or the material's.
    let settings = a.nest.settings(cutting.process().kerf);
    let torches = a
        .nest
        .torches()
        .map_err(|e| crate::cut_options::settings_error(&e, lang))?;
    if model.is_some() && torches.is_some() {
        bail!("--cost: a multi-torch nest is not quoted (every torch cuts each copy): quote it without --torches");
    }
    let (mut job, notes) = job(&a, &cutting, settings, lang)?;
    // Sheets at a cost: for every size or none, and one torch (the page's rule too).
    let stock = nest::stock::stock_of(&a.sheet, &a.sheet_cost, torches.is_some()).map_err(|e| {
        let why = e.text();
        match e {
            nest::stock::CostError::SomeSizes => anyhow!("--sheet: {} (WxH:N:COST)", why.get(lang)),
            nest::stock::CostError::Torches => anyhow!("--sheet with a cost: {}", why.get(lang)),
        }
    })?;
    if a.instance.is_some() {
        job.settings.tolerance = a.nest.tolerance.unwrap_or(match job.sheets {
            // Instances have no unit: a tolerance relative to their size.
            Sheets::Strip { height } => height * 1e-4,
            Sheets::Rect { height, .. } => height * 1e-4,
            Sheets::Mixed(_) | Sheets::Remnant { .. } => 0.05,
        });
    }
    let start = Instant::now();
    let clock = || start.elapsed().as_secs_f64();
    // A setting the nester refuses, said in --lang's language.
    let said = |e: nest::NestError| anyhow!("{}", e.text().get(lang));
    let mut chosen = None;
    let (mut n, tn) = match &torches {
        Some(t) => {
            if a.searches > 1 {
                let t = text!(
                    "--threads: several torches are nested by one search";
                    "--threads: várias tochas são encaixadas por uma só busca"
                );
                eprintln!("kerfcam nest: {}", t.get(lang));
            }
            let tn = nest::torches::nest_torches(&job, t, &clock, &mut |_| true).map_err(said)?;
            (tn.nest.clone(), Some(tn))
        }
        None => match &stock {
            Some(stock) => {
                let c = nest::stock::nest_cheapest(&job, stock, a.searches, &clock, &mut |_| true)
                    .map_err(said)?;
                job = c.job.clone();
                let n = c.nest.clone();
                chosen = Some(c);
                (n, None)
            }
            None => (
                nest::team::nest_team(&job, a.searches, &clock, &mut |_| true).map_err(said)?,
                None,
            ),
        },
    };
    let seconds = clock();
    n.unplaced.splice(0..0, notes);
    let labels = match a.labels {
        Some(_) if tn.is_some() => {
            bail!("--labels: a multi-torch nest is not labelled yet (its other torches' copies)")
        }
        Some(_) => {
            let t = Instant::now();
            let l = label::label_nest(&job, &n, &a.label, job.settings.tolerance);
            if !a.json {
                let (n, s) = (l.labels.len(), t.elapsed().as_secs_f64());
                eprintln!(
                    "kerfcam nest: {}",
                    text!(
                        "{} label(s) placed in {:.3} s", n, s;
                        "{} etiqueta(s) colocada(s) em {:.3} s", n, dec(s)
                    )
                    .get(lang)
                );
            }
            for w in &l.warnings {
                eprintln!("kerfcam nest: {}", w.message_in(lang));
            }
            Some(l)
        }
        None => None,
    };
    if let Some(path) = &a.output {
        let svg = path
            .extension()
            .is_some_and(|e| e.eq_ignore_ascii_case("svg"));
        let dxf = match &tn {
            Some(_) if svg => bail!(
                "-o {}: a multi-torch nest is written as DXF only (its other torches' copies)",
                path.display()
            ),
            Some(tn) => nest::torches::to_dxf(&job, tn),
            None => {
                let overlays = labels.as_ref().map_or(Vec::new(), label::output::overlays);
                if svg {
                    nest::svg_out::to_svg_with(&job, &n, &overlays)
                } else {
                    output::to_dxf_with(&job, &n, &overlays)
                }
            }
        };
        std::fs::write(path, dxf).with_context(|| format!("cannot write {}", path.display()))?;
    }
    let sheets = if a.gcode.is_some() || model.is_some() {
        let cutting = match &torches {
            Some(t) => cutting
                .with_torches(t.count, t.spacing, t.park)
                .map_err(|e| anyhow!(e.message(lang)))?,
            None => cutting,
        };
        let scribed = labels.as_ref().filter(|_| a.label_mark);
        cut_sheets(&job, &n, &cutting, scribed)?
    } else {
        Vec::new()
    };
    if let Some(path) = &a.gcode {
        write_gcode(&sheets, path)?;
    }
    let quote = match &model {
        Some(m) => {
            // Sheets at a cost: each sheet's cost is its material.
            let costs = stock
                .as_deref()
                .zip(chosen.as_ref())
                .map(|(stock, c)| nest::stock::sheet_costs(stock, &c.counts, n.sheets.len()));
            let q = quote(m, &job, &n, &sheets, costs.as_deref(), lang)?;
            crate::quote_cli::write(&q, &a.quote, false, lang)?;
            Some(q)
        }
        None => None,
    };
    if let Some(path) = &a.remnant {
        match output::remnant_dxf(&job, &n) {
            Some(dxf) => std::fs::write(path, dxf)
                .with_context(|| format!("cannot write {}", path.display()))?,
            None => eprintln!(
                "kerfcam nest: {}",
                text!(
                    "no remnant kept (the last sheet is used to within its margin), {} not written",
                    path.display();
                    "nenhum retalho guardado (a última chapa é usada até a margem), {} não gravado",
                    path.display()
                )
                .get(lang)
            ),
        }
    }
    if a.json {
        let mut json = match &tn {
            Some(tn) => nest::torches::to_json(
                &job,
                &nest::torches::TorchNest {
                    nest: n.clone(),
                    ..tn.clone()
                },
                seconds,
                lang,
            ),
            None => output::to_json(&job, &n, seconds, lang),
        };
        if let Some(q) = &quote {
            json["quote"] = serde_json::to_value(q)?;
        }
        if let (Some(c), Some(stock)) = (&chosen, &stock) {
            for (key, value) in nest::stock::json_fields(stock, &c.used, c.cost, c.tried) {
                json[key] = value;
            }
        }
        if let Some(l) = &labels {
            let (placed, left_out) = label::output::to_json(&job, l);
            json["labels"] = placed;
            json["labels_left_out"] = left_out;
        }
        crate::out(&format!("{json}\n"));
    } else {
        let (placed, sheets, tried) = (n.placements.len(), n.sheets.len(), n.evaluations);
        let density = n.density * 100.0;
        let summary = text!(
            "{} placed on {} sheet(s), density {:.2} %, {} nests tried in {:.1} s",
            placed, sheets, density, tried, seconds;
            "{} cópia(s) colocada(s) em {} chapa(s), densidade {:.2} %, {} encaixes testados em {:.1} s",
            placed, sheets, dec(density), tried, dec(seconds)
        );
        eprintln!("kerfcam nest: {}", summary.get(lang));
        if let Some(tn) = &tn {
            let (count, spacing) = (tn.torches.count, tn.torches.spacing);
            let line = text!(
                "{} torches {} mm apart: every copy is cut {} times", count, spacing, count;
                "{} tochas a {} mm: cada cópia é cortada {} vezes", count, dec(spacing), count
            );
            eprintln!("  {}", line.get(lang));
            for (p, &(asked, placed)) in job.parts.iter().zip(&tn.made) {
                let made = placed * count;
                let line = text!(
                    "{}: asked {}, {} under torch 1, {} made", p.name, asked, placed, made;
                    "{}: pedidas {}, {} sob a tocha 1, {} cortadas", p.name, asked, placed, made
                );
                eprintln!("  {}", line.get(lang));
            }
        }
        if let (Some(c), Some(stock)) = (&chosen, &stock) {
            let each = |lang: Lang| {
                let each: Vec<String> = stock
                    .iter()
                    .zip(&c.used)
                    .filter(|(_, &u)| u > 0)
                    .map(|(s, u)| {
                        let (w, h, cost) = (s.size.width, s.size.height, s.cost);
                        match lang {
                            Lang::En => format!("{u} x {w}x{h} at {cost}"),
                            Lang::PtBr => format!("{u} x {}x{} a {}", dec(w), dec(h), dec(cost)),
                        }
                    })
                    .collect();
                each.join(" + ")
            };
            let line = text!(
                "sheets used: {} = cost {} (the costs given with --sheet; {} cheaper combination(s) nested first did not hold every copy)",
                each(Lang::En), c.cost, c.tried;
                "chapas usadas: {} = custo {} (os custos dados em --sheet; em {} combinação(ões) mais barata(s), encaixada(s) antes, nem todas as cópias couberam)",
                each(Lang::PtBr), dec(c.cost), c.tried
            );
            eprintln!("  {}", line.get(lang));
        }
        for u in n.unplaced.iter().filter(|u| u.copies == 0) {
            eprintln!("  {}: {}", u.part, u.reason.get(lang));
        }
        for u in n.unplaced.iter().filter(|u| u.copies > 0) {
            let one = u.copies == 1;
            let (en, pt) = if one {
                ("copy", "cópia")
            } else {
                ("copies", "cópias")
            };
            let line = text!(
                "not placed: {} ({} {}): {}", u.part, u.copies, en, u.reason.en;
                "não colocada: {} ({} {}): {}", u.part, u.copies, pt, u.reason.pt
            );
            eprintln!("  {}", line.get(lang));
        }
    }
    Ok(())
}

/// Entry point for `kerfcam nest …` (the arguments after `nest`).
pub fn main(args: impl Iterator<Item = String>) -> ExitCode {
    match run(args) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("kerfcam nest: error: {e:#}");
            ExitCode::from(2)
        }
    }
}
