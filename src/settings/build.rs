//! From a [`Spec`] to validated [`Settings`]: names looked up (orders,
//! leads, posts, materials, layer operations), numbers checked by the
//! `Settings` builders, a cut-chart entry's values under what was given.

use super::spec::{Choice, LoopKeySpec, SideChoice, Spec, LEGACY_REACH_MM};
use super::{Settings, SettingsError, DEFAULT_RAPID};
use crate::dxf::Units;
use crate::gcode::{preset, Post, PRESET_NAMES};
use crate::geom::Point;
use crate::kerf::Join;
use crate::kerf::Side;
use crate::materials::{Entry, Library};
use crate::origin::ProgramOrigin;
use crate::plan::choice::{self, LoopKey, Pick, SidePick};
use crate::plan::{ccw_from_name, EulerMode, LeadKind, LeadOptions, Order, PlanOptions, Tabs};
use crate::process::{
    Entry as MillEntry, LayerOps, OffsetFrom, Operation, Passes, PocketStrategy, Process,
    SmallHole, ThcLock, Tool,
};
use crate::source::ContourRef;
use crate::text;
use crate::warning::Lang;

/// `field` holds a name that is none of `known`.
fn unknown(field: &'static str, v: &str, known: &str) -> SettingsError {
    SettingsError {
        field,
        reason: text!("'{v}' is not {known}"; "'{v}' não é {known}"),
    }
}

/// The choices made on the drawing as picks ([`choice`]): an old
/// `[contour, x, y]` with a negative contour is a click on nothing.
fn clicked(choices: &[Choice]) -> Vec<Pick> {
    choices
        .iter()
        .filter_map(|c| match c {
            Choice::Numbered(s) => {
                (s[0] >= 0.0).then(|| Pick::near(Point::new(s[1], s[2]), LEGACY_REACH_MM))
            }
            Choice::Keyed { at, on } => Some(keyed(at, on.as_ref())),
        })
        .collect()
}

/// A pick at `at` on the loop `on` names (the loop nearest within
/// [`choice::REACH_MM`] without a key).
fn keyed(at: &[f64; 2], on: Option<&LoopKeySpec>) -> Pick {
    Pick {
        at: Point::new(at[0], at[1]),
        on: on.map(|k| LoopKey {
            source: ContourRef {
                part: k.part,
                copy: k.copy,
                contour: k.contour,
            },
            area: k.area,
            length: k.length,
            size: k.size,
            layer: k.layer.clone(),
        }),
        reach: choice::REACH_MM,
    }
}

/// The sides chosen on single loops as side picks; an unknown side names
/// the field.
fn sides(given: &[SideChoice]) -> Result<Vec<SidePick>, SettingsError> {
    given
        .iter()
        .map(|c| {
            Ok(SidePick {
                pick: keyed(&c.at, c.on.as_ref()),
                side: Side::from_name(&c.side)
                    .ok_or_else(|| unknown("sides_at", &c.side, "outside, inside or on"))?,
            })
        })
        .collect()
}

impl Spec {
    /// The language of messages (English for an unknown name).
    pub fn lang(&self) -> Lang {
        self.lang
            .as_deref()
            .and_then(Lang::from_name)
            .unwrap_or(Lang::En)
    }

    /// The plan options named here (lengths checked by [`Settings::with_plan`]).
    fn plan_options(&self) -> Result<PlanOptions, SettingsError> {
        let dir = |field, v: &str| ccw_from_name(v).ok_or_else(|| unknown(field, v, "cw or ccw"));
        Ok(PlanOptions {
            origin: Point::new(self.tool_start[0], self.tool_start[1]),
            order: Order::from_name(&self.order).ok_or_else(|| {
                unknown(
                    "order",
                    &self.order,
                    "contour, chained, eulerian or drawing",
                )
            })?,
            euler_mode: EulerMode::from_name(&self.euler_mode)
                .ok_or_else(|| unknown("euler_mode", &self.euler_mode, "repeat or rapid"))?,
            leads: LeadOptions {
                kind: LeadKind::from_name(&self.lead).ok_or_else(|| {
                    unknown(
                        "lead",
                        &self.lead,
                        "perpendicular, tangential, bisector, arc or none",
                    )
                })?,
                outer_length: self.lead_outer,
                hole_length: self.lead_hole,
                overcut: self.overcut,
            },
            max_link: self.max_link,
            outer_ccw: dir("outer_dir", &self.outer_dir)?,
            hole_ccw: dir("hole_dir", &self.hole_dir)?,
            cut_open: self.cut_open,
            controller_comp: self.controller_comp,
            fit_arcs: self.fit_arcs,
            tabs: Tabs {
                count: self.tabs as usize,
                width: self.tab_width,
                holes: self.tab_holes,
            },
            starts: clicked(&self.starts),
            tabs_at: clicked(&self.tabs_at),
            sides_at: sides(&self.sides_at)?,
            ..PlanOptions::DEFAULT
        })
    }

    /// The router's tool as given (names checked here, numbers by
    /// [`Settings::with_tool`]).
    fn tool(&self) -> Result<Tool, SettingsError> {
        let pocket = PocketStrategy::from_name(&self.pocket)
            .ok_or_else(|| unknown("pocket", &self.pocket, "zigzag or offset"))?;
        let offset_from = OffsetFrom::from_name(&self.pocket_from)
            .ok_or_else(|| unknown("pocket_from", &self.pocket_from, "centre or walls"))?;
        let entry = MillEntry::from_name(&self.entry)
            .ok_or_else(|| unknown("entry", &self.entry, "plunge, ramp or helix"))?;
        let climb = match self.milling.as_str() {
            "climb" => true,
            "conventional" => false,
            other => return Err(unknown("milling", other, "climb or conventional")),
        };
        Ok(Tool {
            diameter: self.tool_diameter.unwrap_or(0.0),
            stepover_pct: self.stepover,
            plunge_feed: self.plunge_feed,
            spindle_rpm: self.spindle_rpm,
            climb,
            pocket,
            offset_from,
            angle_deg: self.pocket_angle,
            entry,
            ramp_angle_deg: self.ramp_angle,
            helix_diameter: self.helix_diameter,
            allowance: self.allowance,
            peck: self.peck,
            drill_max: self.drill_max,
            v_angle_deg: self.v_angle,
            engrave_width: self.engrave_width,
            engrave_depth: self.engrave_depth,
            lead_radius: self.lead_radius,
            tab_height: self.tab_height,
            number: self.tool_number,
        })
    }

    /// The listed tools as given (numbers checked by
    /// [`Settings::with_tools`]): the job's tool's choices, their own
    /// sizes and speeds.
    fn tools(&self, job: &Tool, feed: f64) -> crate::process::Tools {
        let others = (self.tools.iter())
            .map(|t| crate::process::MillTool {
                tool: Tool {
                    number: t.number,
                    diameter: t.diameter,
                    stepover_pct: t.stepover.unwrap_or(job.stepover_pct),
                    plunge_feed: t.plunge_feed.unwrap_or(job.plunge_feed),
                    spindle_rpm: t.spindle_rpm.unwrap_or(job.spindle_rpm),
                    v_angle_deg: t.v_angle,
                    allowance: t.allowance,
                    helix_diameter: t.helix_diameter,
                    drill_max: t.drill_max,
                    engrave_width: t.engrave_width,
                    engrave_depth: t.engrave_depth,
                    ..*job
                },
                feed: t.feed.unwrap_or(feed),
            })
            .collect();
        crate::process::Tools {
            others,
            layers: self.layer_tools.clone(),
        }
    }

    /// The milling layers' own depths as given (names checked here,
    /// numbers by [`Settings::with_layer_depths`]); a pass depth or a
    /// direction not given is the job's.
    fn layer_depths(&self, s: &Settings) -> Result<crate::process::LayerDepths, SettingsError> {
        let given = (self.layer_depths.iter())
            .map(|d| {
                let climb = match d.milling.as_deref() {
                    None => s.process.tool.climb,
                    Some("climb") => true,
                    Some("conventional") => false,
                    Some(other) => {
                        let layer = &d.layer;
                        return Err(SettingsError {
                            field: "layer_depths",
                            reason: text!("layer '{layer}': milling '{other}' is not climb or conventional";
                                          "camada '{layer}': fresamento '{other}' não é climb nem conventional"),
                        });
                    }
                };
                Ok(crate::process::LayerDepth {
                    layer: d.layer.trim().into(),
                    passes: Passes {
                        depth: d.depth.unwrap_or(s.process.passes.depth),
                        pass_depth: d.pass_depth.unwrap_or(s.process.passes.pass_depth),
                    },
                    climb,
                })
            })
            .collect::<Result<_, _>>()?;
        Ok(crate::process::LayerDepths { given })
    }

    /// The post named here: a user's JSON, a preset, or none.
    fn post(&self) -> Result<Option<Post>, SettingsError> {
        let bad = |reason| SettingsError {
            field: "post",
            reason,
        };
        let post = if let Some(json) = self.post_json.as_deref().filter(|j| !j.is_empty()) {
            Post::from_json(json).map(Some).map_err(|e| bad(e.text()))?
        } else {
            match self.post.as_deref().filter(|n| !n.is_empty()) {
                None => None,
                Some(name) => Some(preset(name).ok_or_else(|| {
                    let known = PRESET_NAMES.join(", ");
                    bad(text!("no preset '{name}' (the presets: {known})";
                              "não existe o modelo '{name}' (os modelos: {known})"))
                })?),
            }
        };
        if !self.incremental {
            return Ok(post);
        }
        // G91 asked of any post (issue 43 §5): the plain one's when none.
        let mut post = post.unwrap_or_else(|| crate::gcode::plain_post(self.decimals));
        post.incremental = true;
        post.validate().map_err(|e| SettingsError {
            field: "incremental",
            reason: e.text(),
        })?;
        Ok(Some(post))
    }

    /// The validated settings. The first bad value names its field; a
    /// material not in the chart names the chart's fault.
    pub fn build(&self) -> Result<Settings, SettingsError> {
        let lang = self.lang();
        let material = |field, e: crate::materials::MaterialError| SettingsError {
            field,
            reason: e.text(),
        };
        // A chart given is read even when no entry is chosen: a broken
        // chart is said now, not when an entry is first picked.
        let lib = match &self.materials {
            Some(text) => Some(Library::from_text(text).map_err(|e| material("materials", e))?),
            None => None,
        };
        let entry = match &self.material_name {
            None => None,
            Some(name) => {
                let lib = lib.unwrap_or_else(Library::starter);
                Some(lib.find(name).map_err(|e| material("material", e))?.clone())
            }
        };
        // The entry's process fills what is not given (the CLI's rule:
        // options typed win over the chart).
        let chart = entry.as_ref().map(|e| e.process(DEFAULT_RAPID));
        let pick = |given: Option<f64>, from: fn(&Process) -> f64, default: f64| {
            given.unwrap_or_else(|| chart.as_ref().map_or(default, from))
        };
        let d = Process::DEFAULT;
        // A router's profile: the tool's width is the kerf, unless one is given.
        let kerf = match (self.kerf, self.tool_diameter) {
            (None, Some(t)) => t,
            _ => pick(self.kerf, |p| p.kerf, d.kerf),
        };
        let feed = pick(self.feed, |p| p.feed, d.feed);
        let post = self.post()?;
        let mut s = Settings::new(kerf, self.tolerance, feed)?.with_lang(lang);
        s = s
            .with_join(match self.join.as_str() {
                "round" => Join::Round,
                "miter" | "mitre" => Join::Miter,
                other => return Err(unknown("join", other, "round or miter")),
            })
            .with_decimals(self.decimals)?
            .with_pierce_delay(pick(self.pierce_delay, |p| p.pierce_delay, d.pierce_delay))?;
        let rapid = self
            .rapid
            .or(post.as_ref().map(|p| p.rapid_speed))
            .unwrap_or(DEFAULT_RAPID);
        s = s.with_rapid(rapid)?.with_plan(self.plan_options()?)?;
        if let Some(p) = post {
            s = s.with_post(p)?;
        }
        let origin = match (self.origin.as_str(), self.origin_point) {
            ("point", Some([x, y])) => ProgramOrigin::Point(Point::new(x, y)),
            (name, _) => ProgramOrigin::from_name(name).ok_or_else(|| {
                unknown("origin", name, "auto, drawing, lower-left, point or X,Y")
            })?,
        };
        let mut ops = LayerOps::new();
        ops.by_name = self.layer_ops_by_name;
        for [layer, op] in &self.layer_ops {
            let op = Operation::from_name(op).ok_or_else(|| SettingsError {
                field: "layer_ops",
                reason: text!("layer '{layer}': '{op}' is not cut, mark, spot, ignore, pocket, profile, engrave or drill";
                              "camada '{layer}': '{op}' não é cut, mark, spot, ignore, pocket, profile, engrave ou drill"),
            })?;
            ops.given.push((layer.clone(), op));
        }
        let depth = match (self.depth, &entry) {
            (Some(d), _) => d,
            (None, Some(e)) if self.pass_depth > 0.0 => e.thickness,
            (None, _) => 0.0,
        };
        s = s
            .with_origin(origin)?
            .with_layer_ops(ops)
            .with_verify(self.verify)
            .with_repair(self.repair_self_crossing)
            .with_small_hole(SmallHole {
                diameter: pick(
                    self.small_hole_diameter,
                    |p| p.small_hole.diameter,
                    d.small_hole.diameter,
                ),
                speed_pct: pick(
                    self.small_hole_speed,
                    |p| p.small_hole.speed_pct,
                    SmallHole::OFF.speed_pct,
                ),
                min_diameter: self.small_hole_min,
                ..SmallHole::OFF
            })?
            .with_heights(
                pick(self.pierce_height, |p| p.pierce_height, d.pierce_height),
                pick(self.cut_height, |p| p.cut_height, d.cut_height),
            )?
            .with_material_number(
                self.material_number
                    .or(entry.as_ref().and_then(|e| e.number))
                    .unwrap_or(0),
            )?
            .with_passes(Passes {
                depth,
                pass_depth: self.pass_depth,
            })?
            .with_thc_lock(ThcLock {
                corner_angle_deg: self.thc_corner_angle,
                corner_distance: self.thc_corner_distance,
                end_distance: self.thc_end_distance,
            })?;
        s = s.with_tool(self.tool()?)?;
        let tools = self.tools(&s.process.tool, s.process.feed);
        s = s.with_tools(tools)?;
        let depths = self.layer_depths(&s)?;
        s = s.with_layer_depths(depths)?;
        passes_on_grid(&s)?;
        if let Some(name) = self.units.as_deref().filter(|n| !n.is_empty()) {
            let u = Units::from_name(name).ok_or_else(|| SettingsError {
                field: "units",
                reason: text!("unknown unit '{name}'"; "unidade '{name}' desconhecida"),
            })?;
            s = s.with_units(u);
        }
        if let Some(g) = self.gap {
            s = s.with_gap(g)?;
        }
        if let Some(l) = &self.layers {
            s = s.with_layers(l.clone());
        }
        let entry = match self.material.as_deref().filter(|j| !j.is_empty()) {
            // The page's chosen entry: its values are the job's.
            Some(json) => {
                let e = Entry::from_json(json).map_err(|e| material("material", e))?;
                s = s.with_material(&e)?;
                Some(e)
            }
            None => entry,
        };
        s.material = entry.map(|e| super::MaterialUsed {
            name: e.name,
            example: e.example,
        });
        Ok(s)
    }
}

/// Depth passes finer than the program writes heights (the post's
/// decimals) would round to the same heights or to none at all (a depth
/// below the grid is Z0: nothing cut): refused, naming the depth when it
/// is itself below the grid, else the deepest pass (issue 43 §7).
fn passes_on_grid(s: &Settings) -> Result<(), SettingsError> {
    let Some(post) = s.post() else {
        return Ok(());
    };
    on_grid(post, s.process.passes, None)?;
    for d in &s.layer_depths.given {
        on_grid(post, d.passes, Some(&d.layer))?;
    }
    Ok(())
}

/// [`passes_on_grid`] for the job's passes (`layer` None) or a layer's,
/// the layer named in what is refused.
fn on_grid(post: &Post, passes: Passes, layer: Option<&str>) -> Result<(), SettingsError> {
    if !passes.on() {
        return Ok(());
    }
    let grid = 10f64.powi(-(post.decimals.min(9) as i32));
    let each = passes.depth / passes.count() as f64;
    let (n, dp) = (passes.count(), post.decimals);
    let (g, gd) = (grid, crate::warning::dec(grid));
    let named = |field: &'static str, e: crate::warning::Text| match layer {
        None => SettingsError { field, reason: e },
        Some(l) => {
            let (en, pt) = (e.en, e.pt);
            SettingsError {
                field: "layer_depths",
                reason: text!("layer '{l}': {en}"; "camada '{l}': {pt}"),
            }
        }
    };
    if passes.depth < grid * (1.0 - 1e-9) {
        let h = passes.depth;
        let hd = crate::warning::dec(h);
        return Err(named(
            "depth",
            text!("{h} mm is below the {g} mm the program writes heights to (the post's {dp} decimals): it would cut at Z0";
                  "{hd} mm é menos que os {gd} mm com que o programa escreve as alturas ({dp} casas decimais do pós-processador): cortaria em Z0"),
        ));
    }
    if each < grid * (1.0 - 1e-9) {
        let ed = crate::warning::dec(each);
        return Err(named(
            "pass_depth",
            text!("{n} passes of {each} mm are finer than the {g} mm the program writes heights to (the post's {dp} decimals): passes would round to the same height (a deeper pass cuts as asked)";
                  "{n} passes de {ed} mm são mais finos que os {gd} mm com que o programa escreve as alturas ({dp} casas decimais do pós-processador): passes arredondariam para a mesma altura (um passe mais fundo corta como pedido)"),
        ));
    }
    Ok(())
}
