//! The JSON report of a job (CLI `--json`, the page's summary): what was
//! read, what was skipped, every contour, the invalid vertices, warnings and
//! the plan's totals.

use std::collections::BTreeMap;

use serde::Serialize;

use crate::contour::ContourKind;
use crate::origin::Origin;
use crate::warning::Lang;
use crate::Output;

mod process;
mod sections;

pub use process::{MaterialReport, ProcessReport};
use sections::um;
pub use sections::{
    ArcFitReport, CommonLineReport, ContourReport, EngravingReport, ExtentReport, HealLocation,
    HealingReport, LayerDepthReport, LayerReport, MillSweepReport, OrderReport, PartLossReport,
    PlanReport, SizeReport, TabsReport, ToolReport, VerificationReport, WarningReport,
    MAX_COMMON_LINES,
};

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
    /// The file's format: "dxf" or "svg" (the page's unit switch offers px for an SVG).
    pub format: &'static str,
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
    /// The values the job was cut with (a cut-chart entry's where one
    /// was chosen).
    pub process: ProcessReport,
    /// Other orders' figures, when asked for ([`Report::with_comparison`]).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub comparison: Vec<OrderReport>,
    /// The plan's kerf swept over the parts (issue 20 §9), when asked.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub verification: Option<VerificationReport>,
    /// How many contours the list above leaves out: set only in the page's
    /// report of a big job ([`Report::to_json_listing_at_most`]).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub contours_omitted: Option<usize>,
    /// Cost and time per part, per sheet and for the job, when a cost
    /// model was given ([`Report::with_quote`]).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub quote: Option<crate::quote::Quote>,
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
        // The router's pockets, engravings and holes, moved before the
        // profiles: in the lengths as the program moves them (and in the
        // time: `Output::est_time_s`).
        let mill = out.milled.as_ref().map(|m| m.stats).unwrap_or_default();
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
            format: if out.drawing.svg { "svg" } else { "dxf" },
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
                    layer: c.layer.to_string(),
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
                    self_crossings: h.self_crossings,
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
                    loss: w.loss(),
                    loops: w.loops.clone(),
                })
                .collect(),
            plan: PlanReport {
                order: out.plan.order.name(),
                cut_length: um(st.cut_length + mill.cut_mm + mill.plunge_mm),
                lead_length: um(st.lead_length),
                repeated_length: um(st.repeated_length),
                chains: st.chains,
                spots: st.spots,
                mark_length: um(st.mark_length),
                small_holes: st.small_holes,
                tabs: st.tabs,
                tabs_per_part: tabs_per_part(out),
                est_time_s: (out.est_time_s * 10.0).round() / 10.0,
                rapid_length: um(st.rapid_length + mill.rapid_mm),
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
                arc_fit: out.arc_fit().map(|f| ArcFitReport {
                    lines_before: f.lines_before,
                    arcs_before: f.arcs_before,
                    lines_after: f.lines_after,
                    arcs_after: f.arcs_after,
                    tolerance: f.tolerance,
                }),
                engraving: (out.milled.as_ref()).and_then(|m| m.engraving).map(|e| {
                    EngravingReport {
                        v_angle: e.v_angle_deg,
                        depth: um(e.depth),
                        width: um(e.width),
                    }
                }),
                tools: tool_reports(out),
                layer_depths: (out.milled.iter().flat_map(|m| &m.depths))
                    .map(|d| LayerDepthReport {
                        layers: d.layers.clone(),
                        tool: d.tool,
                        depth: um(d.passes.depth),
                        passes: d.passes.count(),
                        pass_depth: um(d.passes.depth / d.passes.count() as f64),
                        milling: if d.climb { "climb" } else { "conventional" },
                    })
                    .collect(),
            },
            process: ProcessReport::of(&out.process, out.material.as_ref()),
            comparison: Vec::new(),
            verification: out.verification.as_ref().map(|v| VerificationReport {
                overcut_mm2: (v.overcut_mm2 * 1000.0).round() / 1000.0,
                parts_not_freed: v.parts_not_freed,
                max_overcut_mm: um(v.max_overcut_mm),
                parts_held_by_tabs: v.parts_held_by_tabs,
                parts: (v.parts.iter())
                    .map(|l| PartLossReport {
                        part: l.part,
                        overcut_mm2: (l.overcut_mm2 * 1000.0).round() / 1000.0,
                        max_overcut_mm: um(l.max_overcut_mm),
                    })
                    .collect(),
                milling: (out.milled.as_ref())
                    .filter(|m| !m.spans.is_empty())
                    .and_then(|m| m.swept.as_ref())
                    .map(|s| MillSweepReport {
                        gouge_mm2: (s.gouge_mm2 * 1000.0).round() / 1000.0,
                        left_mm2: (s.left_mm2 * 1000.0).round() / 1000.0,
                        unreachable_mm2: (s.unreachable_mm2 * 1000.0).round() / 1000.0,
                    }),
            }),
            contours_omitted: None,
            quote: None,
        }
    }
    /// The same report with the job's quote.
    pub fn with_quote(mut self, quote: crate::quote::Quote) -> Report {
        self.quote = Some(quote);
        self
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

    /// The JSON report with its per-contour list only when it has at most
    /// `max` contours; above, the list is left out and its length given as
    /// `contours_omitted` (the page shows counts: the list of a 125k-contour
    /// nest is 18 MB of JSON to write and read again). The report itself is
    /// the same after the call.
    pub fn to_json_listing_at_most(&mut self, max: usize) -> String {
        let n = self.contours.len();
        if n <= max {
            return self.to_json();
        }
        let contours = std::mem::take(&mut self.contours);
        self.contours_omitted = Some(n);
        let json = self.to_json();
        self.contours = contours;
        self.contours_omitted = None;
        json
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

/// Each tool's share of a router job with several ([`crate::mill::ToolShare`]).
fn tool_reports(out: &Output) -> Vec<ToolReport> {
    let Some(m) = &out.milled else {
        return Vec::new();
    };
    let profiles = out.plan.cuts.iter().any(|c| !c.spot && !c.is_mark());
    (m.tools.iter())
        .map(|s| {
            let t = &s.tool.tool;
            ToolReport {
                number: t.number,
                diameter: t.diameter,
                v_angle: t.v_angle_deg,
                feed: s.tool.feed,
                plunge_feed: t.plunge_feed,
                spindle_rpm: t.spindle_rpm,
                pockets: s.pockets,
                engravings: s.engravings,
                holes: s.holes,
                cut_length: um(s.stats.cut_mm + s.stats.plunge_mm),
                rapid_length: um(s.stats.rapid_mm),
                est_time_s: (s.stats.time_with(&out.process, Some(&s.tool)) * 10.0).round() / 10.0,
                profiles: profiles && t.number == out.process.tool.number,
            }
        })
        .collect()
}
