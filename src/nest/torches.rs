//! Nesting for several torches (issue 18 §7; paper 001 §6.5): the nest is
//! made for the band under torch 1 and every copy there is cut again by
//! each other torch, `spacing` mm further along Y.
//!
//! With part spacing `s`, sheet margin `m` and torches `D` apart, torch 1's
//! parts lie in y ∈ [m, m + D − s]: then torch k's copies lie in
//! [m + kD, m + (k+1)D − s], at least `s` from torch k−1's whatever the
//! parts, and the nest of the band is an ordinary nest on a sheet of
//! height 2m + D − s. The last torch's band must end inside the margin,
//! so the band is cut to H − 2m − (N−1)D where that is less. Quantities are divided by N and rounded up
//! (the report says how many are made). A part taller than the band in
//! every allowed turn cannot be cut this way and is listed with the reason.

use super::{nest, Nest, NestError, NestJob, Progress, SheetUse, Sheets, Unplaced};
use crate::geom::{path_bbox, transform_segments, Affine};
use crate::process::Torches;
use crate::text;
use crate::warning::{dec, Lang, Text};

/// A nest for several torches: [`TorchNest::nest`] holds torch 1's copies
/// in the whole sheet's coordinates, with figures for the whole sheet.
#[derive(Clone, Debug)]
pub struct TorchNest {
    /// Torch 1's copies; sheets' parts and utilisation count every torch.
    pub nest: Nest,
    /// The setup.
    pub torches: Torches,
    /// Height of the band under one torch, mm (D − s).
    pub band: f64,
    /// Per part: (asked, placed under torch 1); made = placed × count.
    pub made: Vec<(usize, usize)>,
}

/// A setting that makes the torches impossible.
fn refuse(reason: Text) -> NestError {
    NestError::Setting {
        field: "torches",
        reason,
    }
}

/// The part's least height over its allowed turns, mm.
fn least_height(p: &super::Part, tol: f64) -> f64 {
    p.rotations
        .angles_for(&p.outer, false)
        .into_iter()
        .map(|a| {
            let mut out = Vec::new();
            transform_segments(&p.outer, &Affine::rotate_deg(a), tol, &mut out);
            let b = path_bbox(&out);
            b.max.y - b.min.y
        })
        .fold(f64::INFINITY, f64::min)
}

/// Nests `job` for the torches `t` (see the module's text).
pub fn nest_torches(
    job: &NestJob,
    t: &Torches,
    clock: &dyn Fn() -> f64,
    progress: &mut dyn FnMut(Progress) -> bool,
) -> Result<TorchNest, NestError> {
    let (s, m, n) = (job.settings.spacing, job.settings.margin, t.count);
    let height = match job.sheets {
        Sheets::Rect { height, .. } | Sheets::Strip { height } => height,
        Sheets::Remnant { .. } | Sheets::Mixed(_) => {
            return Err(refuse(text!(
                "several torches need one size of rectangular sheet or a strip, not a remnant or a list of sizes";
                "várias tochas precisam de um só tamanho de chapa retangular ou de uma tira, não de um retalho ou de uma lista de tamanhos"
            )))
        }
    };
    // The band is D − s high, less where the last torch's band would run
    // past the margin at the sheet's top.
    let room = height - 2.0 * m - (n - 1) as f64 * t.spacing;
    let band = (t.spacing - s).min(room);
    if t.spacing - s <= 0.0 {
        return Err(refuse(text!(
            "torches {} mm apart leave no room for parts {s} mm apart", t.spacing;
            "tochas a {} mm uma da outra não deixam espaço para peças a {} mm uma da outra", dec(t.spacing), dec(s)
        )));
    }
    if band <= 0.0 {
        return Err(refuse(text!(
            "{n} torches {} mm apart reach past the sheet: {height} mm high less {m} mm margins leaves no band for the last torch", t.spacing;
            "{n} tochas a {} mm uma da outra passam da chapa: {} mm de altura menos margens de {} mm não deixam faixa para a última tocha",
            dec(t.spacing), dec(height), dec(m)
        )));
    }
    let mut band_job = job.clone();
    band_job.sheets = match job.sheets {
        Sheets::Rect { width, count, .. } => Sheets::Rect {
            width,
            height: 2.0 * m + band,
            count,
        },
        _ => Sheets::Strip {
            height: 2.0 * m + band,
        },
    };
    let mut too_tall = Vec::new();
    for p in &mut band_job.parts {
        let h = least_height(p, job.settings.tolerance);
        if p.quantity > 0 && h > band + job.settings.tolerance {
            too_tall.push(Unplaced {
                part: p.name.clone(),
                copies: p.quantity,
                reason: text!(
                    "{h:.1} mm tall in every allowed turn: {n} torches {} mm apart on this sheet, parts {s} mm apart, leave {band:.1} mm under each torch",
                    t.spacing;
                    "{:.1} mm de altura em todas as rotações permitidas: {n} tochas a {} mm uma da outra nesta chapa, peças a {} mm uma da outra, deixam {:.1} mm sob cada tocha",
                    dec(h), dec(t.spacing), dec(s), dec(band)
                ),
            });
            p.quantity = 0;
        } else {
            p.quantity = t.per_torch(p.quantity);
        }
    }
    let mut full = if band_job.parts.iter().all(|p| p.quantity == 0) {
        Nest {
            placements: Vec::new(),
            sheets: Vec::new(),
            unplaced: Vec::new(),
            strip_length: None,
            density: 0.0,
            evaluations: 0,
        }
    } else {
        nest(&band_job, clock, progress)?
    };
    // Copies left out under torch 1 are left out under every torch; the
    // parts set aside here replace the engine's "quantity 0" notes.
    full.unplaced
        .retain(|u| !too_tall.iter().any(|t| t.part == u.part));
    for u in &mut full.unplaced {
        u.copies *= n;
    }
    full.unplaced.extend(too_tall);
    let area = |sheet: usize| -> f64 {
        full.placements
            .iter()
            .filter(|p| p.sheet == sheet)
            .map(|p| job.parts[p.part].area())
            .sum::<f64>()
            * n as f64
    };
    let strip = matches!(job.sheets, Sheets::Strip { .. });
    let mut used = 0.0;
    full.sheets = full
        .sheets
        .iter()
        .enumerate()
        .map(|(k, u)| {
            // Paper 001 §6.3 on the whole sheet: parts of every torch over
            // the sheet less its remnant.
            let useful = height
                * if strip {
                    u.used_length
                } else {
                    u.crop_x.unwrap_or(u.width)
                };
            used += height * u.used_length;
            SheetUse {
                height,
                parts: u.parts * n,
                utilisation: if useful > 0.0 { area(k) / useful } else { 0.0 },
                ..u.clone()
            }
        })
        .collect();
    let total: f64 = (0..full.sheets.len()).map(area).sum();
    full.density = if used > 0.0 { total / used } else { 0.0 };
    Ok(TorchNest::of(job, full, *t, band))
}

impl TorchNest {
    /// A nest for the torches `t` (band `band`) with what it makes per
    /// part counted from its placements (as nested or adjusted).
    pub fn of(job: &NestJob, nest: Nest, torches: Torches, band: f64) -> TorchNest {
        let made = job
            .parts
            .iter()
            .enumerate()
            .map(|(i, p)| {
                let placed = nest.placements.iter().filter(|q| q.part == i).count();
                (p.quantity, placed)
            })
            .collect();
        TorchNest {
            nest,
            torches,
            band,
            made,
        }
    }
}

/// Every torch's copies: (torch, placement), torch 0 the programmed one;
/// the others moved by the torch spacing along Y.
pub fn all_copies(tn: &TorchNest) -> Vec<(usize, super::Placement)> {
    (0..tn.torches.count)
        .flat_map(|k| {
            tn.nest.placements.iter().map(move |p| {
                let mut q = *p;
                q.translation.y += tn.torches.offset(k);
                (k, q)
            })
        })
        .collect()
}

/// The nest's JSON ([`super::output::to_json`]) with the setup:
/// `torches: {count, spacing, band, parts[{part, asked, per_torch, made}]}`.
pub fn to_json(job: &NestJob, tn: &TorchNest, seconds: f64, lang: Lang) -> serde_json::Value {
    let mut v = super::output::to_json(job, &tn.nest, seconds, lang);
    v["torches"] = serde_json::json!({
        "count": tn.torches.count,
        "spacing": tn.torches.spacing,
        "band": tn.band,
        "parts": job.parts.iter().zip(&tn.made).map(|(p, &(asked, placed))| serde_json::json!({
            "part": p.name, "asked": asked, "per_torch": placed,
            "made": placed * tn.torches.count})).collect::<Vec<_>>(),
    });
    v
}

/// The nest DXF ([`super::output::to_dxf`]) with the other torches' copies
/// on layer `NULL`, paper 001's inactive layer (§6.5: drawn for the eye,
/// never cut; kerfcam's layer operations ignore `NULL` by name).
pub fn to_dxf(job: &NestJob, tn: &TorchNest) -> String {
    let mut out = super::output::to_dxf(job, &tn.nest);
    let tail = out.rfind("0\nENDSEC\n").unwrap_or(out.len());
    let mut extra = String::new();
    let mut handle = 0xF0000;
    let mut x = 0.0;
    let offsets: Vec<f64> = tn
        .nest
        .sheets
        .iter()
        .map(|s| {
            let o = x;
            x += s.width * (1.0 + super::output::SHEET_GAP);
            o
        })
        .collect();
    for (k, p) in all_copies(tn) {
        if k == 0 {
            continue;
        }
        let dx = offsets.get(p.sheet).copied().unwrap_or(0.0);
        for l in super::output::placed_loops(job, &p) {
            let l: Vec<_> = l
                .iter()
                .map(|s| crate::geom::Segment {
                    a: s.a.add(crate::geom::Point::new(dx, 0.0)),
                    b: s.b.add(crate::geom::Point::new(dx, 0.0)),
                    bulge: s.bulge,
                })
                .collect();
            super::output::polyline(&mut extra, &mut handle, SLAVE_LAYER, &l);
        }
    }
    out.insert_str(tail, &extra);
    out
}

/// Layer of the other torches' copies in the nest DXF.
pub const SLAVE_LAYER: &str = "NULL";
