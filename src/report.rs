//! The JSON report of a job (CLI `--json`, the page's summary): what was
//! read, what was skipped, every contour, the invalid vertices, warnings and
//! the plan's totals.

use std::collections::BTreeMap;

use serde::Serialize;

use crate::contour::ContourKind;
use crate::origin::Origin;
use crate::warning::{Lang, Severity, Text};
use crate::Output;

/// One contour in the report.
#[derive(Clone, Debug, Serialize)]
pub struct ContourReport {
    /// Closed loop?
    pub closed: bool,
    /// "outer", "hole" or "open".
    pub kind: &'static str,
    /// Containment depth.
    pub depth: usize,
    /// Part number (1-based) of closed contours.
    pub part: Option<usize>,
    /// Enclosed area, mm² (absolute; 0 for open).
    pub area: f64,
    /// Length, mm.
    pub length: f64,
    /// "ccw" or "cw" as drawn (None for open).
    pub direction: Option<&'static str>,
    /// `[x0, y0, x1, y1]`, mm.
    pub bbox: [f64; 4],
    /// Layer of its first entity.
    pub layer: String,
    /// Its part, copy and loop (`{part, copy, contour}`; on a nested
    /// sheet the part is the nest's, 1-based), which stay true through
    /// layers and nesting where the index does not.
    pub source: crate::source::ContourRef,
}

/// One warning in the report.
#[derive(Clone, Debug, Serialize)]
pub struct WarningReport {
    /// Stable short name of the kind ("units-assumed"): scripts match this, not the text.
    pub code: &'static str,
    /// The message in the report's language (English unless asked otherwise).
    pub message: String,
    /// The message in every language (`{"en": …, "pt-BR": …}`), so a page
    /// can switch language without running the job again.
    pub messages: Text,
    /// Where, mm (the first place of a group).
    pub at: Option<[f64; 2]>,
    /// "error", "warning" or "info" (repairs and notes).
    pub severity: Severity,
    /// How many identical warnings this one stands for.
    pub count: usize,
    /// The first places of the group, mm.
    pub places: Vec<[f64; 2]>,
}

/// The drawing's overall size.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct SizeReport {
    /// Width, mm.
    pub w: f64,
    /// Height, mm.
    pub h: f64,
}

/// A box in program coordinates.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct ExtentReport {
    /// Lower-left corner, mm.
    pub min: [f64; 2],
    /// Upper-right corner, mm.
    pub max: [f64; 2],
}

/// What the swept kerf takes from the parts.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct VerificationReport {
    /// Part material inside the swept kerf, mm².
    pub overcut_mm2: f64,
    /// Parts the kerf does not cut free all round.
    pub parts_not_freed: usize,
    /// Deepest reach past a drawn edge, mm.
    pub max_overcut_mm: f64,
    /// Parts held only by their tabs (issue 20 §6); absent when none.
    #[serde(skip_serializing_if = "is_zero_count")]
    pub parts_held_by_tabs: usize,
}

/// The tabs left on one part.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct TabsReport {
    /// Part number (1-based).
    pub part: usize,
    /// Tabs left on it.
    pub tabs: usize,
}

/// Plan totals.
#[derive(Clone, Debug, Serialize)]
pub struct PlanReport {
    /// "contour", "chained", "eulerian" or "drawing".
    pub order: &'static str,
    /// Cutting length on contours, mm (each drawn edge once).
    pub cut_length: f64,
    /// Lead-ins, lead-outs and chain links, mm.
    pub lead_length: f64,
    /// Edges travelled again with the tool down, mm.
    pub repeated_length: f64,
    /// Cuts that cut more than one contour on one pierce.
    pub chains: usize,
    /// Spots marked.
    pub spots: usize,
    /// Length marked on the line (scribe, issue 20), mm; absent when none.
    #[serde(skip_serializing_if = "is_zero")]
    pub mark_length: f64,
    /// Small holes cut at the reduced speed; absent when none.
    #[serde(skip_serializing_if = "is_zero_count")]
    pub small_holes: usize,
    /// Tabs left uncut (issue 20 §6; each a torch restart, counted in
    /// `pierces`); absent when none.
    #[serde(skip_serializing_if = "is_zero_count")]
    pub tabs: usize,
    /// The tabs of each part that has some, by part; absent when none.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub tabs_per_part: Vec<TabsReport>,
    /// Estimated machine time, s (feed, rapid speed, pierce delay).
    pub est_time_s: f64,
    /// The contour order's rapid tour between contours (entry points on the
    /// contours, before leads) as the nearest-neighbour construction built
    /// it, mm, and as improved.
    pub tour_nn_length: Option<f64>,
    /// The same tour after 2-opt, Or-opt and entry re-choice, mm.
    pub tour_length: Option<f64>,
    /// Rapid length from the origin, mm.
    pub rapid_length: f64,
    /// Number of pierces.
    pub pierces: usize,
    /// Parts (outer contours).
    pub parts: usize,
    /// Holes.
    pub holes: usize,
    /// Open contours (not cut).
    pub open: usize,
    /// Length of paths cut once for two parts (common-line cutting), mm.
    pub common_line_length: f64,
    /// Those paths in the direction cut, at most [`MAX_COMMON_LINES`].
    pub common_line: Vec<CommonLineReport>,
}

/// Common-line pieces listed one by one in the report; the length counts all.
pub const MAX_COMMON_LINES: usize = 1000;

/// A path two parts share, cut once: which way, and which part is on the
/// right of the cut (the square side of a clockwise-swirl plasma arc).
#[derive(Clone, Debug, Serialize)]
pub struct CommonLineReport {
    /// The two parts (1-based; 0 for none).
    pub parts: [usize; 2],
    /// The part on the right of the cut direction (0: not found).
    pub right: usize,
    /// Where the cut entered the piece, mm.
    pub from: [f64; 2],
    /// Where it left it, mm.
    pub to: [f64; 2],
    /// Length, mm.
    pub length: f64,
}

/// One layer in the report.
#[derive(Clone, Debug, Serialize)]
pub struct LayerReport {
    /// Name (text from the file: escape it wherever it is shown).
    pub name: String,
    /// AutoCAD colour index.
    pub color: i16,
    /// On and thawed in the file.
    pub visible: bool,
    /// Cut in this job.
    pub selected: bool,
    /// Geometry entities on it.
    pub entities: usize,
}

/// What healing changed.
#[derive(Clone, Debug, Serialize)]
pub struct HealingReport {
    /// Copies dropped.
    pub duplicates: usize,
    /// Overlaps merged.
    pub overlaps: usize,
    /// Gaps closed.
    pub gaps_closed: usize,
    /// Zero-length entities and segments dropped.
    pub zero_length: usize,
    /// Each fix: `{"kind": "duplicate"|"overlap"|"gap"|"zero_length", "at": [x, y]}`.
    pub locations: Vec<HealLocation>,
}

/// One healing fix.
#[derive(Clone, Debug, Serialize)]
pub struct HealLocation {
    /// What was done.
    pub kind: &'static str,
    /// Where, mm.
    pub at: [f64; 2],
}

/// The whole report.
#[derive(Clone, Debug, Serialize)]
pub struct Report {
    /// Drawing unit name.
    pub units: &'static str,
    /// Where the unit came from: "$INSUNITS", "assumed" or "override".
    pub units_source: &'static str,
    /// True when the file does not state its units and the user did not
    /// choose: the `units-assumed` warning says what was assumed and why.
    pub units_assumed: bool,
    /// The drawing's overall size (selected layers), mm; absent when nothing was read.
    pub size: Option<SizeReport>,
    /// Its box in program coordinates, mm.
    pub extent: Option<ExtentReport>,
    /// Which drawing point is the program's zero.
    pub origin: Origin,
    /// `$ACADVER` of the file.
    pub version: Option<String>,
    /// Binary DXF?
    pub binary: bool,
    /// Layers with their entity counts.
    pub layers: Vec<LayerReport>,
    /// POINT entities (spots to mark), mm.
    pub spots: Vec<[f64; 2]>,
    /// Entities seen, by type.
    pub entities: BTreeMap<String, usize>,
    /// Entities not used, by type.
    pub skipped: BTreeMap<String, usize>,
    /// Every contour.
    pub contours: Vec<ContourReport>,
    /// What healing changed (duplicates, overlaps, gaps, zero-length pieces).
    pub healing: HealingReport,
    /// Paper 000's invalid vertices, mm.
    pub invalid_vertices: Vec<[f64; 2]>,
    /// Warnings of all stages.
    pub warnings: Vec<WarningReport>,
    /// Plan totals.
    pub plan: PlanReport,
    /// Other orders' figures, when asked for ([`Report::with_comparison`]).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub comparison: Vec<OrderReport>,
    /// The plan's kerf swept over the parts (issue 20 §9), when asked.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub verification: Option<VerificationReport>,
}

/// One order's figures in a comparison.
#[derive(Clone, Debug, Serialize)]
pub struct OrderReport {
    /// The order's name.
    pub order: &'static str,
    /// Cutting length on contours, mm.
    pub cut_length: f64,
    /// Leads and links, mm.
    pub lead_length: f64,
    /// Repeated length, mm.
    pub repeated_length: f64,
    /// Rapid length, mm.
    pub rapid_length: f64,
    /// Pierces.
    pub pierces: usize,
    /// Chains.
    pub chains: usize,
    /// Estimated time, s.
    pub est_time_s: f64,
    /// True when some torch-on move cuts into a part (issue 14).
    pub cuts_into_parts: bool,
    /// Length of torch-on travel whose kerf reaches into a part, mm.
    pub into_parts_length: f64,
    /// Deepest reach of the kerf into a part, mm.
    pub into_parts_depth: f64,
}

impl From<&crate::OrderSummary> for OrderReport {
    fn from(o: &crate::OrderSummary) -> Self {
        OrderReport {
            order: o.order.name(),
            cut_length: um(o.stats.cut_length),
            lead_length: um(o.stats.lead_length),
            repeated_length: um(o.stats.repeated_length),
            rapid_length: um(o.stats.rapid_length),
            pierces: o.stats.pierces,
            chains: o.stats.chains,
            est_time_s: (o.est_time_s * 10.0).round() / 10.0,
            cuts_into_parts: o.intrusion.cuts_parts(),
            into_parts_length: um(o.intrusion.length),
            into_parts_depth: um(o.intrusion.depth),
        }
    }
}

/// Rounds to a micrometre, so reports do not carry float noise.
fn um(v: f64) -> f64 {
    // `+ 0.0` turns -0 into 0.
    (v * 1000.0).round() / 1000.0 + 0.0
}

impl Report {
    /// The report of a job, messages in English.
    pub fn new(out: &Output) -> Report {
        Report::in_lang(out, Lang::En)
    }

    /// The report of a job, messages in `lang`.
    pub fn in_lang(out: &Output, lang: Lang) -> Report {
        let cs = &out.contours.contours;
        let count = |k: ContourKind| cs.iter().filter(|c| c.kind == k).count();
        let st = out.plan.stats();
        let bb = out.drawing.extent;
        Report {
            units: out.drawing.units.map_or("mm", |u| u.name),
            units_source: out.drawing.units_source,
            units_assumed: out.drawing.units_source == "assumed",
            size: (!bb.is_empty()).then(|| SizeReport {
                w: um(bb.max.x - bb.min.x),
                h: um(bb.max.y - bb.min.y),
            }),
            extent: (!bb.is_empty()).then(|| ExtentReport {
                min: bb.min.xy().map(um),
                max: bb.max.xy().map(um),
            }),
            origin: Origin {
                at: out.origin.at.map(um),
                ..out.origin
            },
            version: out.drawing.version.clone(),
            binary: out.drawing.binary,
            layers: out
                .drawing
                .layers
                .iter()
                .map(|l| LayerReport {
                    name: l.name.clone(),
                    color: l.color,
                    visible: l.visible,
                    selected: l.selected,
                    entities: l.entities,
                })
                .collect(),
            spots: out
                .drawing
                .spots
                .iter()
                .map(|s| s.at.xy().map(um))
                .collect(),
            entities: out.drawing.counts.clone(),
            skipped: out.drawing.skipped.clone(),
            contours: cs
                .iter()
                .map(|c| ContourReport {
                    closed: c.is_closed(),
                    kind: c.kind.name(),
                    depth: c.depth,
                    part: c.part,
                    area: um(c.area.abs()),
                    length: um(c.length),
                    direction: c
                        .is_closed()
                        .then_some(if c.area > 0.0 { "ccw" } else { "cw" }),
                    bbox: c.bbox.to_array().map(um),
                    layer: c.layer.clone(),
                    source: c.source,
                })
                .collect(),
            healing: {
                let h = &out.contours.healing;
                HealingReport {
                    duplicates: h.duplicates,
                    overlaps: h.overlaps,
                    gaps_closed: h.gaps_closed,
                    zero_length: h.zero_length,
                    locations: h
                        .locations
                        .iter()
                        .map(|(k, p)| HealLocation {
                            kind: k.name(),
                            at: p.xy().map(um),
                        })
                        .collect(),
                }
            },
            invalid_vertices: out
                .kerf
                .invalid_vertices
                .iter()
                .map(|p| p.xy().map(um))
                .collect(),
            warnings: out
                .warnings()
                .map(|w| WarningReport {
                    code: w.code,
                    message: w.message_in(lang).to_owned(),
                    messages: w.text.clone(),
                    at: w.at.map(|p| p.xy().map(um)),
                    severity: w.severity(),
                    count: w.count,
                    places: w.places.iter().map(|p| p.xy().map(um)).collect(),
                })
                .collect(),
            plan: PlanReport {
                order: out.plan.order.name(),
                cut_length: um(st.cut_length),
                lead_length: um(st.lead_length),
                repeated_length: um(st.repeated_length),
                chains: st.chains,
                spots: st.spots,
                mark_length: um(st.mark_length),
                small_holes: st.small_holes,
                tabs: st.tabs,
                tabs_per_part: tabs_per_part(out),
                est_time_s: (st.est_time_s(&out.timing) * 10.0).round() / 10.0,
                rapid_length: um(st.rapid_length),
                tour_nn_length: out.plan.tour.map(|t| um(t.nearest_neighbour)),
                tour_length: out.plan.tour.map(|t| um(t.improved)),
                pierces: st.pierces,
                parts: count(ContourKind::Outer),
                holes: count(ContourKind::Hole),
                open: count(ContourKind::Open),
                common_line_length: um(out
                    .plan
                    .common_line
                    .iter()
                    .map(|c| c.segment.length())
                    .sum()),
                common_line: out
                    .plan
                    .common_line
                    .iter()
                    .take(MAX_COMMON_LINES)
                    .map(|c| CommonLineReport {
                        parts: [c.parts.0.unwrap_or(0), c.parts.1.unwrap_or(0)],
                        right: c.right.unwrap_or(0),
                        from: c.segment.a.xy().map(um),
                        to: c.segment.b.xy().map(um),
                        length: um(c.segment.length()),
                    })
                    .collect(),
            },
            comparison: Vec::new(),
            verification: out.verification.as_ref().map(|v| VerificationReport {
                overcut_mm2: (v.overcut_mm2 * 1000.0).round() / 1000.0,
                parts_not_freed: v.parts_not_freed,
                max_overcut_mm: um(v.max_overcut_mm),
                parts_held_by_tabs: v.parts_held_by_tabs,
            }),
        }
    }
    /// The same report with other orders' figures.
    pub fn with_comparison(mut self, orders: &[crate::OrderSummary]) -> Report {
        self.comparison = orders.iter().map(OrderReport::from).collect();
        self
    }
    /// As JSON text.
    pub fn to_json(&self) -> String {
        serde_json::to_string(self).unwrap_or_else(|e| format!("{{\"error\":\"{e}\"}}"))
    }
}

/// Tabs by part, in part order.
fn tabs_per_part(out: &Output) -> Vec<TabsReport> {
    let mut by: std::collections::BTreeMap<usize, usize> = Default::default();
    for s in out.plan.cuts.iter().flat_map(|c| &c.steps) {
        if s.role == crate::plan::Role::Tab {
            let part = s
                .contour
                .and_then(|k| out.contours.contours.get(k))
                .and_then(|c| c.part)
                .unwrap_or(0);
            *by.entry(part).or_default() += 1;
        }
    }
    by.into_iter()
        .map(|(part, tabs)| TabsReport { part, tabs })
        .collect()
}

fn is_zero(v: &f64) -> bool {
    *v == 0.0
}

fn is_zero_count(v: &usize) -> bool {
    *v == 0
}
