//! Labels on nested parts (issue 42 §2): each placed copy gets its ID —
//! the part's name and copy number (`BRACKET#3`) or a short code (`A3`:
//! a letter per part, the copy number) — written in our single-stroke
//! font ([`font`]) inside the part.
//!
//! # Contract
//! - A label lies in its part's material: inside the outline, outside
//!   every hole, at least [`LabelOptions::margin`] from each, the height
//!   as large as fits between `height_min` and `height_max` ([`fit`]).
//!   [`check::clearance`] checks this without the placer's code.
//! - It is placed in the part's own coordinates, upright or across, and
//!   moves with the copy (turned, mirrored, moved); it always reads from
//!   left to right or from bottom to top on the sheet (turned a half turn
//!   when the copy's turn would put it upside down), never mirrored.
//! - A copy with no room for the smallest label gets none, and the
//!   labels' warning names its part: nothing is shrunk below the minimum.
//! - The text is data: strokes only (the DXF, the program); the SVG and
//!   the page escape it.

pub mod check;
pub mod fit;
pub mod font;
pub mod output;

use crate::geom::{Affine, Point};
use crate::nest::{Nest, NestJob, Placement};
use crate::text;
use crate::warning::Warning;

/// Layer of the labels in the nest DXF (a layer name that reads as a
/// marking layer when the file is cut again).
pub const LABEL_LAYER: &str = "LABELS";

/// What a label says.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Naming {
    /// The part's name and the copy number: `BRACKET#3`.
    Name,
    /// A letter (or letters) per part in the job's order, then the copy
    /// number: `A3`, `B12`, …, `AA1`.
    Code,
}

impl Naming {
    /// The naming called `name` (`name`, `code`).
    pub fn from_name(name: &str) -> Option<Naming> {
        match name {
            "name" => Some(Naming::Name),
            "code" => Some(Naming::Code),
            _ => None,
        }
    }
}

/// How labels are sized and placed.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LabelOptions {
    /// Largest text height, mm (default 10).
    pub height_max: f64,
    /// Smallest text height, mm: a copy with no room for it gets no label
    /// (default 3).
    pub height_min: f64,
    /// Least distance from the strokes to the outline and to every hole,
    /// mm (default 2).
    pub margin: f64,
    /// What the label says (default the part's name and copy).
    pub naming: Naming,
}

impl LabelOptions {
    /// 3–10 mm high, 2 mm clear, named after the part.
    pub const DEFAULT: LabelOptions = LabelOptions {
        height_max: 10.0,
        height_min: 3.0,
        margin: 2.0,
        naming: Naming::Name,
    };

    /// The field and the reason when a value is out of range.
    pub fn check(&self) -> Result<(), (&'static str, crate::warning::Text)> {
        let LabelOptions {
            height_max: max,
            height_min: min,
            margin,
            ..
        } = *self;
        if !(min.is_finite() && min > 0.0) {
            return Err(("label_height_min", text!("{min} is not a height > 0"; "{min} não é uma altura > 0")));
        }
        if !(max.is_finite() && max >= min) {
            return Err(("label_height_max", text!("{max} is not a height ≥ the smallest, {min}"; "{max} não é uma altura ≥ a menor, {min}")));
        }
        if !(margin.is_finite() && margin >= 0.0) {
            return Err(("label_margin", text!("{margin} is not a distance ≥ 0"; "{margin} não é uma distância ≥ 0")));
        }
        Ok(())
    }
}

impl Default for LabelOptions {
    fn default() -> Self {
        LabelOptions::DEFAULT
    }
}

/// One copy's label, in sheet coordinates.
#[derive(Clone, Debug, PartialEq)]
pub struct Label {
    /// Index into the job's parts.
    pub part: usize,
    /// Which copy (0-based; the label says copy + 1).
    pub copy: usize,
    /// Which sheet.
    pub sheet: usize,
    /// What it says, as given (the strokes draw [`font::drawn`] letters).
    pub text: String,
    /// Text height, mm.
    pub height: f64,
    /// Centre of its box.
    pub centre: Point,
    /// Reading direction, degrees counter-clockwise from +x, in (−90, 90].
    pub angle: f64,
    /// The strokes (polylines), sheet coordinates.
    pub strokes: Vec<Vec<Point>>,
}

/// Every placed copy's label, and the copies left without one.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Labels {
    /// The labels, in the nest's placement order.
    pub labels: Vec<Label>,
    /// (part, copy) of each copy with no room for a label.
    pub left_out: Vec<(usize, usize)>,
    /// The note naming the parts left without a label (none when every
    /// copy has one).
    pub warnings: Vec<Warning>,
}

/// A short code for part `i`: A … Z, AA, AB, … (bijective base 26).
pub fn code(mut i: usize) -> String {
    let mut s = Vec::new();
    loop {
        s.push(b'A' + (i % 26) as u8);
        if i < 26 {
            break;
        }
        i = i / 26 - 1;
    }
    s.reverse();
    String::from_utf8(s).unwrap_or_default()
}

/// The text of copy `p`'s label.
pub fn text_of(job: &NestJob, p: &Placement, naming: Naming) -> String {
    let n = p.copy + 1;
    match naming {
        Naming::Name => format!("{}#{n}", job.parts[p.part].name),
        Naming::Code => format!("{}{n}", code(p.part)),
    }
}

/// The map from the label's own frame (text laid out from the origin
/// along +x, [`font::layout`]) to the sheet, for a box `w` × `h` at `fit`
/// on copy `p`: it reads left to right or bottom to top, unmirrored.
fn label_map(p: &Placement, fit: &fit::Fit, w: f64, h: f64) -> (Affine, f64) {
    let copy = p.affine();
    // The copy's mirror undone in the label's frame, about its centre line.
    let unmirror = if p.mirror {
        Affine::translate(w, 0.0).then_after(&Affine::scale_xy(-1.0, 1.0))
    } else {
        Affine::IDENTITY
    };
    let to_centre = Affine::translate(-w / 2.0, -h / 2.0).then_after(&unmirror);
    let base = if fit.across { 90.0 } else { 0.0 };
    let mut best = None;
    for turn in [base, base + 180.0] {
        let m = copy.then_after(
            &Affine::translate(fit.centre.x, fit.centre.y)
                .then_after(&Affine::rotate_deg(turn).then_after(&to_centre)),
        );
        let d = m.apply(Point::new(1.0, 0.0)).sub(m.apply(Point::new(0.0, 0.0)));
        let angle = d.y.atan2(d.x).to_degrees();
        // Left to right, or bottom to top when it stands vertical.
        if angle > -90.0 + 1e-6 && angle <= 90.0 + 1e-6 || best.is_none() {
            best = Some((m, angle));
        }
    }
    best.unwrap_or((copy, 0.0))
}

/// Labels for every placed copy of `nest`: placed in each part once per
/// text length, the outlines flattened within `chord` mm.
pub fn label_nest(job: &NestJob, nest: &Nest, options: &LabelOptions, chord: f64) -> Labels {
    let mut out = Labels::default();
    if options.check().is_err() {
        return out;
    }
    let chord = if chord.is_finite() && chord > 0.0 { chord } else { 0.05 };
    let mut regions: Vec<Option<fit::Region>> = vec![None; job.parts.len()];
    let mut fits: std::collections::HashMap<(usize, usize), Option<fit::Fit>> =
        std::collections::HashMap::new();
    for p in &nest.placements {
        let Some(part) = job.parts.get(p.part) else { continue };
        let text = text_of(job, p, options.naming);
        let chars = text.chars().count();
        let ratio = font::width(&text, 1.0);
        let fit = *fits.entry((p.part, chars)).or_insert_with(|| {
            let region = regions[p.part]
                .get_or_insert_with(|| fit::Region::new(&part.outer, &part.holes, chord));
            region.fit(
                ratio,
                options.height_min,
                options.height_max,
                options.margin + chord,
            )
        });
        let Some(fit) = fit else {
            out.left_out.push((p.part, p.copy));
            continue;
        };
        let (w, h) = (font::width(&text, fit.height), fit.height);
        let (m, angle) = label_map(p, &fit, w, h);
        let strokes = font::layout(&text, h)
            .into_iter()
            .map(|s| s.into_iter().map(|q| m.apply(q)).collect())
            .collect();
        out.labels.push(Label {
            part: p.part,
            copy: p.copy,
            sheet: p.sheet,
            text,
            height: h,
            centre: m.apply(Point::new(w / 2.0, h / 2.0)),
            angle,
            strokes,
        });
    }
    if !out.left_out.is_empty() {
        let n = out.left_out.len();
        let mut names: Vec<&str> = Vec::new();
        for &(part, _) in &out.left_out {
            let name = job.parts[part].name.as_str();
            if !names.contains(&name) {
                names.push(name);
            }
        }
        let names = names.join(", ");
        let min = options.height_min;
        let margin = options.margin;
        out.warnings.push(Warning::new(
            "label-no-room",
            text!("{n} cop(y/ies) left without a label: no room for a label {min} mm high, {margin} mm clear of edges and holes, in {names}";
                  "{n} cópia(s) sem etiqueta: não há espaço para uma etiqueta de {min} mm de altura, a {margin} mm das bordas e furos, em {names}"),
        ));
    }
    out
}

#[cfg(test)]
mod tests;
