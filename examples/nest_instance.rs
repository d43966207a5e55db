//! Real-part nesting instances (issue 44 §1): shop jobs made of parts of
//! real drawings, written in the ESICUP JSON that `kerfcam nest
//! --instance` and sparrow read, so real parts are benchmarked beside the
//! ESICUP polygons (`scripts/bench-nest.sh`).
//!
//! `cargo run --release --example nest_instance -- JOBS.txt CORPUS_DIR OUT_DIR`
//! writes `OUT_DIR/JOB.json` for every job of the list;
//! `… -- --list CORPUS_DIR FILE.dxf...` prints every part of the files
//! (number, size, area, vertices of its collision polygon) to choose from.
//!
//! An example rather than a `kerfcam nest` option: it is a benchmark tool
//! (the geometry stays in the shared corpus, the repository holds the job
//! list: file, part, quantity), and the parts are read exactly as `kerfcam
//! nest PART.dxf` reads them ([`kerfcam::nest::read_parts`], the default
//! cutting settings) and grown exactly as the nest grows them
//! ([`kerfcam::nest::shape`]): each part's outline grown by half the
//! spacing (arcs as circumscribed lines within the tolerance), each hole
//! shrunk by half of it (chords inside), so the instance is nested with
//! spacing 0 and a valid nest of it is a valid nest of the job.
//!
//! Job list format, one job a block, `#` starts a comment:
//! ```text
//! job NAME STRIP_HEIGHT_MM [spacing MM] [tolerance MM] [rotations 0,90,180,270] [holes none]
//!   FILE PART QUANTITY      (PART: the part's number in the file, 1-based)
//! ```
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use kerfcam::geom::Point;
use kerfcam::nest::shape::{collision_polygon, room_polygon, Polygon};
use kerfcam::nest::{read_parts, Part};

struct Item {
    file: String,
    part: usize,
    quantity: usize,
}

struct Job {
    name: String,
    height: f64,
    spacing: f64,
    tolerance: f64,
    rotations: Vec<f64>,
    /// Holes kept (`holes none`: every part solid, the nest without
    /// part-in-hole to compare with).
    holes: bool,
    items: Vec<Item>,
}

fn die(why: String) -> ! {
    eprintln!("nest_instance: {why}");
    std::process::exit(2)
}

fn parse_jobs(text: &str) -> Vec<Job> {
    let mut jobs: Vec<Job> = Vec::new();
    for (n, line) in text.lines().enumerate() {
        let line = line.split('#').next().unwrap_or("").trim();
        if line.is_empty() {
            continue;
        }
        let at = format!("jobs line {}: {line}", n + 1);
        let bad = |why: &str| -> f64 { die(format!("{at}: {why}")) };
        let w: Vec<&str> = line.split_whitespace().collect();
        if w[0] == "job" {
            if w.len() < 3 {
                bad("job NAME STRIP_HEIGHT");
            }
            let mut job = Job {
                name: w[1].to_owned(),
                height: w[2].parse().unwrap_or_else(|_| bad("strip height")),
                spacing: 2.5,
                tolerance: 0.05,
                rotations: vec![0.0, 90.0, 180.0, 270.0],
                holes: true,
                items: Vec::new(),
            };
            let mut k = 3;
            while k + 1 < w.len() {
                let v = w[k + 1];
                match w[k] {
                    "spacing" => job.spacing = v.parse().unwrap_or_else(|_| bad("spacing")),
                    "tolerance" => {
                        job.tolerance = v.parse().unwrap_or_else(|_| bad("tolerance"))
                    }
                    "rotations" => {
                        job.rotations = v
                            .split(',')
                            .map(|a| a.parse().unwrap_or_else(|_| bad("rotations")))
                            .collect()
                    }
                    "holes" if v == "none" => job.holes = false,
                    _ => {
                        bad("unknown job option");
                    }
                }
                k += 2;
            }
            jobs.push(job);
        } else {
            // FILE may hold spaces: the last two words are part and quantity.
            if w.len() < 3 {
                bad("FILE PART QUANTITY");
            }
            let int = |v: &str, what: &str| -> usize {
                v.parse().unwrap_or_else(|_| die(format!("{at}: {what}")))
            };
            let quantity = int(w[w.len() - 1], "quantity");
            let part = int(w[w.len() - 2], "part");
            let file = w[..w.len() - 2].join(" ");
            match jobs.last_mut() {
                Some(j) => j.items.push(Item {
                    file,
                    part,
                    quantity,
                }),
                None => {
                    bad("a part before any job");
                }
            }
        }
    }
    jobs
}

/// Every part of `file`, read as `kerfcam nest` reads it.
fn parts_of(corpus: &Path, file: &str) -> Vec<Part> {
    let path = corpus.join(file);
    let bytes = std::fs::read(&path).unwrap_or_else(|e| die(format!("{}: {e}", path.display())));
    let settings = kerfcam::Spec::default()
        .build()
        .unwrap_or_else(|e| die(format!("default settings: {e:?}")));
    let (parts, _) = read_parts(&bytes, file, 1, &settings)
        .unwrap_or_else(|e| die(format!("{}: {}", path.display(), e.en)));
    parts
}

/// A part's outer ring grown by `grow`, its holes shrunk by it (holes that
/// close up are dropped: no room left).
fn grown(p: &Part, grow: f64, tol: f64) -> Option<(Polygon, Vec<Polygon>)> {
    let outer = collision_polygon(&p.outer, grow, tol)?;
    let holes = p
        .holes
        .iter()
        .filter_map(|h| room_polygon(h, grow, tol))
        .collect();
    Some((outer, holes))
}

fn ring_json(out: &mut String, poly: &Polygon, origin: Point) {
    out.push('[');
    for (k, p) in poly.pts.iter().chain(poly.pts.first()).enumerate() {
        if k > 0 {
            out.push(',');
        }
        // Six decimals: a micrometre's thousandth, nothing a nest can see.
        let _ = write!(out, "[{:.6},{:.6}]", p.x - origin.x, p.y - origin.y);
    }
    out.push(']');
}

fn write_job(job: &Job, corpus: &Path, dir: &Path) {
    let mut items = String::new();
    let (mut copies, mut area, mut verts) = (0usize, 0.0, (usize::MAX, 0usize));
    for (id, it) in job.items.iter().enumerate() {
        let parts = parts_of(corpus, &it.file);
        let Some(p) = it.part.checked_sub(1).and_then(|i| parts.get(i)) else {
            die(format!(
                "{}: no part {} (it has {})",
                it.file,
                it.part,
                parts.len()
            ))
        };
        let Some((outer, mut holes)) = grown(p, job.spacing / 2.0, job.tolerance) else {
            die(format!("{} part {}: no area", it.file, it.part))
        };
        if !job.holes {
            holes.clear();
        }
        let o = outer.bbox.min;
        let mut shape = String::new();
        if holes.is_empty() {
            shape.push_str("{\"type\":\"simple_polygon\",\"data\":");
            ring_json(&mut shape, &outer, o);
            shape.push('}');
        } else {
            shape.push_str("{\"type\":\"polygon\",\"data\":{\"outer\":");
            ring_json(&mut shape, &outer, o);
            shape.push_str(",\"inner\":[");
            for (k, h) in holes.iter().enumerate() {
                if k > 0 {
                    shape.push(',');
                }
                ring_json(&mut shape, h, o);
            }
            shape.push_str("]}}");
        }
        let rot: Vec<String> = job.rotations.iter().map(|r| format!("{r}")).collect();
        if id > 0 {
            items.push_str(",\n");
        }
        let _ = write!(
            items,
            "  {{\"id\":{id},\"demand\":{},\"allowed_orientations\":[{}],\"source\":\"{}#{}\",\"shape\":{shape}}}",
            it.quantity,
            rot.join(","),
            it.file.replace('\\', "/").replace('"', "'"),
            it.part
        );
        copies += it.quantity;
        area += (outer.area() - holes.iter().map(Polygon::area).sum::<f64>()) * it.quantity as f64;
        verts = (verts.0.min(outer.pts.len()), verts.1.max(outer.pts.len()));
    }
    let json = format!(
        "{{\"name\":\"{}\",\"strip_height\":{},\"items\":[\n{items}\n]}}\n",
        job.name, job.height
    );
    let path = dir.join(format!("{}.json", job.name));
    std::fs::write(&path, json).unwrap_or_else(|e| die(format!("{}: {e}", path.display())));
    eprintln!(
        "{}: {} parts, {copies} copies, {}–{} vertices, grown area {:.0} mm² (a full strip {:.0} mm long)",
        job.name,
        job.items.len(),
        verts.0,
        verts.1,
        area,
        area / job.height
    );
}

fn list(corpus: &Path, files: &[String]) {
    for f in files {
        for (k, p) in parts_of(corpus, f).iter().enumerate() {
            let Some((outer, holes)) = grown(p, 1.25, 0.05) else {
                continue;
            };
            let b = outer.bbox;
            println!(
                "{f}\t{}\t{:.1}x{:.1}\tarea {:.0}\tverts {}\tholes {} (largest {:.0} mm²)",
                k + 1,
                b.max.x - b.min.x,
                b.max.y - b.min.y,
                p.area(),
                outer.pts.len(),
                holes.len(),
                holes.iter().map(Polygon::area).fold(0.0, f64::max)
            );
        }
    }
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    match args.as_slice() {
        [flag, corpus, files @ ..] if flag == "--list" => list(Path::new(corpus), files),
        [jobs, corpus, out] => {
            let text = std::fs::read_to_string(jobs).unwrap_or_else(|e| die(format!("{jobs}: {e}")));
            let out = PathBuf::from(out);
            std::fs::create_dir_all(&out).unwrap_or_else(|e| die(format!("{}: {e}", out.display())));
            for job in parse_jobs(&text) {
                write_job(&job, Path::new(corpus), &out);
            }
        }
        _ => die("usage: nest_instance JOBS.txt CORPUS_DIR OUT_DIR | --list CORPUS_DIR FILE...".into()),
    }
}
