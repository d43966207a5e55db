//! The router's milling within the pipeline (issue 43): the layers given
//! pocket, engrave or drill, by tool and by depth ([`crate::mill`] plans
//! each), refused by name when a tool, a depth or a layer's choice cannot
//! apply.

use crate::{dxf, geom, process, text, Error, Settings, SettingsError};

/// The milling of the layers given pocket, engrave or drill: refused,
/// naming the setting, without a tool or a depth.
pub(super) fn mill_layers(
    g: &process::layers::MillGeometry,
    settings: &Settings,
    from: geom::Point,
) -> Result<crate::mill::Milled, Error> {
    milling_needs(settings)?;
    let p = &settings.process;
    let retract = settings.post.as_ref().map_or(2.0, |p| p.retract_height);
    let heights = crate::mill::Heights {
        retract,
        tolerance: settings.tolerance.mm(),
    };
    let mut m = crate::mill::plan(g, &p.tool, p.passes, heights, from);
    if settings.plan.fit_arcs {
        m.fit_arcs(heights.tolerance, retract);
    }
    if settings.verify {
        m.verify(p.tool.radius(), p.passes.depth, retract, heights.tolerance);
    }
    Ok(m)
}

/// The milling of a job with a tool list (issue 43 §1): each milling
/// layer's geometry with its tool, the listed tools first in their order,
/// the job's own last (it cuts the profiles after its milling, when the
/// job has `profiles`): every pocket, engraving and hole is machined
/// before a profile frees a part. Only the job's tool used: the
/// one-tool milling. A tool given to a layer that is not milled is
/// refused, naming the layer; a listed tool no layer uses is said.
pub(super) fn mill_by_tool(
    drawing: &dxf::Drawing,
    g: &process::layers::MillGeometry,
    settings: &Settings,
    profiles: bool,
) -> Result<crate::mill::Milled, Error> {
    use process::Operation;
    milling_needs(settings)?;
    let (p, tools, ops) = (&settings.process, &settings.tools, &settings.layer_ops);
    let job = process::MillTool {
        tool: p.tool,
        feed: p.feed,
    };
    for l in &drawing.layers {
        let (Some(n), op) = (tools.number_of(&l.name), ops.op(&l.name)) else {
            continue;
        };
        if op.is_milling() || (n == job.tool.number && op == Operation::Profile) {
            continue;
        }
        let (layer, opn) = (&l.name, op.name());
        return Err(Error::Settings(SettingsError {
            field: "layer_tools",
            reason: if op == Operation::Profile || op == Operation::Cut {
                text!("layer '{layer}' is cut as a profile, by the job's own tool (its diameter is the profiles' kerf): tool {n} cannot cut it (give the layer tool {}, or make tool {n} the job's)", job.tool.number;
                      "a camada '{layer}' é cortada como perfil, pela ferramenta do trabalho (o diâmetro dela é a sangria dos perfis): a ferramenta {n} não pode cortá-la (dê à camada a ferramenta {}, ou faça da {n} a do trabalho)", job.tool.number)
            } else {
                text!("layer '{layer}' is {opn}, not milled: a tool applies to pocket, engrave and drill layers";
                      "a camada '{layer}' é {opn}, não fresada: uma ferramenta vale para camadas de bolsão, gravação e furação")
            },
        }));
    }
    let depths = &settings.layer_depths;
    for l in &drawing.layers {
        let (Some(d), op) = (depths.of(&l.name), ops.op(&l.name)) else {
            continue;
        };
        if op.is_milling() {
            continue;
        }
        let (layer, opn, h) = (&l.name, op.name(), d.passes.depth);
        let hd = crate::warning::dec(h);
        return Err(Error::Settings(SettingsError {
            field: "layer_depths",
            reason: if op == Operation::Profile || op == Operation::Cut {
                text!("layer '{layer}' is cut as a profile, at the job's depth (--depth, what frees the parts): its own {h} mm cannot apply (a profile layer takes the job's depth; give the milling layers theirs)";
                      "a camada '{layer}' é cortada como perfil, na profundidade do trabalho (--depth, a que solta as peças): os seus {hd} mm não se aplicam (uma camada de perfil usa a profundidade do trabalho; dê às camadas fresadas as delas)")
            } else {
                text!("layer '{layer}' is {opn}, not milled: a depth applies to pocket, engrave and drill layers";
                      "a camada '{layer}' é {opn}, não fresada: uma profundidade vale para camadas de bolsão, gravação e furação")
            },
        }));
    }
    let tol = settings.tolerance;
    let mut works = Vec::new();
    let mut unused = Vec::new();
    let cut_of = |layer: &str| depths.cut_of(layer, p.passes, p.tool.climb);
    for t in tools.others.iter().chain(std::iter::once(&job)) {
        let n = t.tool.number;
        let mine = |l: &str| tools.number_of(l).unwrap_or(job.tool.number) == n;
        // The tool's layers by depth and direction, the job's first, then
        // as their layers come in the drawing: one milling each.
        let mut cuts = vec![(p.passes, p.tool.climb)];
        for l in &drawing.layers {
            let c = cut_of(&l.name);
            if ops.op(&l.name).is_milling() && mine(&l.name) && !cuts.contains(&c) {
                cuts.push(c);
            }
        }
        let before = works.len();
        for (passes, climb) in cuts {
            let mut own = ops.clone();
            for l in &drawing.layers {
                if ops.op(&l.name).is_milling()
                    && !(mine(&l.name) && cut_of(&l.name) == (passes, climb))
                {
                    own.given.push((l.name.clone(), Operation::Ignore));
                }
            }
            let geometry = process::layers::split(drawing, &own, tol, settings.gap)
                .map(|l| l.milling)
                .unwrap_or_default();
            if !geometry.is_empty() {
                let mut t = *t;
                t.tool.climb = climb;
                let layers = (drawing.layers.iter())
                    .filter(|l| {
                        ops.op(&l.name).is_milling()
                            && mine(&l.name)
                            && cut_of(&l.name) == (passes, climb)
                    })
                    .map(|l| l.name.clone())
                    .collect();
                works.push(crate::mill::Work {
                    tool: t,
                    geometry,
                    passes,
                    layers,
                });
            }
        }
        let last = n == job.tool.number;
        if last && profiles && works.len() == before && !works.is_empty() {
            works.push(crate::mill::Work {
                tool: *t,
                geometry: Default::default(),
                passes: p.passes,
                layers: Vec::new(),
            });
        } else if !last && works.len() == before {
            unused.push(n);
        }
    }
    let mut m = match works.as_slice() {
        [w] if w.tool.tool.number == job.tool.number
            && w.passes == p.passes
            && w.tool.tool.climb == p.tool.climb =>
        {
            mill_layers(g, settings, settings.plan.origin)?
        }
        _ => {
            let heights = crate::mill::Heights {
                retract: settings.post.as_ref().map_or(2.0, |p| p.retract_height),
                tolerance: tol.mm(),
            };
            let finish = crate::mill::Finish {
                fit_arcs: settings.plan.fit_arcs,
                verify: settings.verify,
            };
            crate::mill::plan_tools(
                &works,
                job.tool.number,
                heights,
                settings.plan.origin,
                finish,
            )
        }
    };
    if depths.is_empty() {
        m.depths.clear();
    }
    if let Some(&first) = unused.first() {
        let list = (unused.iter().map(u32::to_string))
            .collect::<Vec<_>>()
            .join(", ");
        m.warnings.push(crate::warning::Warning::new(
            "tool-unused",
            text!("tool(s) {list} of the tool list mill no layer: not in the program (give a layer one with --layer-tool LAYER={first})";
                  "ferramenta(s) {list} da lista não fresam nenhuma camada: fora do programa (dê uma a uma camada com --layer-tool CAMADA={first})"),
        ));
    }
    Ok(m)
}

/// Refused, naming the setting, without a tool or a depth.
fn milling_needs(settings: &Settings) -> Result<(), Error> {
    let p = &settings.process;
    if !p.tool.on() {
        return Err(Error::Settings(SettingsError {
            field: "tool_diameter",
            reason: text!("layers to pocket, engrave or drill need the tool's diameter";
                          "camadas de bolsão, gravação ou furação precisam do diâmetro da ferramenta"),
        }));
    }
    if !p.passes.on() {
        return Err(Error::Settings(SettingsError {
            field: "depth",
            reason: text!("layers to pocket, engrave or drill need the depth and the deepest pass";
                          "camadas de bolsão, gravação ou furação precisam da profundidade e do passe mais fundo"),
        }));
    }
    Ok(())
}
