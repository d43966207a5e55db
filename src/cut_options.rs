//! The cutting options of the command line, shared by `kerfcam FILE.dxf`
//! and `kerfcam nest … --gcode`: each fills one field of the one
//! [`Spec`] the page fills too (issue 15 §5), and [`Spec::build`] checks
//! them all. Here only the command line's own syntax is parsed (numbers,
//! `X,Y`, `LAYER=OP`, files read); names are checked by the builder.

use anyhow::{bail, Context, Result};
use kerfcam::warning::Lang;
use kerfcam::{Choice, Spec};

fn num(name: &str, v: String) -> Result<f64> {
    v.parse::<f64>()
        .with_context(|| format!("{name}: '{v}' is not a number"))
}

fn whole<T: std::str::FromStr>(name: &str, v: String) -> Result<T> {
    v.parse::<T>()
        .ok()
        .with_context(|| format!("{name}: '{v}' is not a whole number"))
}

/// `--tool N=DIAMETER[,key=value…]`: a tool of the job's list, its keys
/// named as the job's tool's options.
fn tool(opt: &str, v: &str) -> Result<kerfcam::ToolSpec> {
    let mut parts = v.split(',');
    let first = parts.next().unwrap_or("");
    let (n, d) = first
        .split_once('=')
        .with_context(|| format!("{opt}: '{v}' is not N=DIAMETER[,key=value…]"))?;
    let mut t = kerfcam::ToolSpec {
        number: whole(opt, n.trim().into())?,
        diameter: num(opt, d.trim().into())?,
        ..kerfcam::ToolSpec::default()
    };
    for kv in parts {
        let (k, x) = kv
            .split_once('=')
            .with_context(|| format!("{opt}: '{kv}' is not key=value"))?;
        let x = num(&format!("{opt} {}", k.trim()), x.trim().into())?;
        match k.trim() {
            "feed" => t.feed = Some(x),
            "plunge-feed" => t.plunge_feed = Some(x),
            "spindle-rpm" => t.spindle_rpm = Some(x),
            "stepover" => t.stepover = Some(x),
            "v-angle" => t.v_angle = x,
            "allowance" => t.allowance = x,
            "helix-diameter" => t.helix_diameter = x,
            "drill-max" => t.drill_max = x,
            "engrave-width" => t.engrave_width = x,
            "engrave-depth" => t.engrave_depth = x,
            other => bail!("{opt}: '{other}' is not feed, plunge-feed, spindle-rpm, stepover, v-angle, allowance, helix-diameter, drill-max, engrave-width or engrave-depth"),
        }
    }
    Ok(t)
}

/// `LAYER=H[,pass-depth=D][,milling=climb|conventional]`: a milling
/// layer's own depth, its keys the job's options' names.
fn layer_depth(opt: &str, v: &str) -> Result<kerfcam::LayerDepthSpec> {
    let mut parts = v.split(',');
    let first = parts.next().unwrap_or("");
    let (layer, h) = first.rsplit_once('=').with_context(|| {
        format!("{opt}: '{v}' is not LAYER=DEPTH[,pass-depth=D][,milling=climb|conventional]")
    })?;
    let mut d = kerfcam::LayerDepthSpec {
        layer: layer.trim().into(),
        depth: Some(num(opt, h.trim().into())?),
        ..kerfcam::LayerDepthSpec::default()
    };
    for kv in parts {
        let (k, x) = kv
            .split_once('=')
            .with_context(|| format!("{opt}: '{kv}' is not key=value"))?;
        match k.trim() {
            "pass-depth" => {
                d.pass_depth = Some(num(&format!("{opt} pass-depth"), x.trim().into())?)
            }
            "milling" => d.milling = Some(x.trim().into()),
            other => bail!("{opt}: '{other}' is not pass-depth or milling"),
        }
    }
    Ok(d)
}

fn read(name: &str, path: &str) -> Result<String> {
    std::fs::read_to_string(path).with_context(|| format!("{name}: cannot read {path}"))
}

/// Applies the cutting option `opt` to `spec`, taking its value from
/// `value` when it has one. Ok(false): `opt` is not a cutting option.
pub fn apply(
    spec: &mut Spec,
    opt: &str,
    value: &mut dyn FnMut(&str) -> Result<String>,
) -> Result<bool> {
    let s = spec;
    match opt {
        "--kerf" => s.kerf = Some(num(opt, value(opt)?)?),
        "--tolerance" => s.tolerance = num(opt, value(opt)?)?,
        "--feed" => s.feed = Some(num(opt, value(opt)?)?),
        "--pierce-delay" => s.pierce_delay = Some(num(opt, value(opt)?)?),
        "--rapid" => s.rapid = Some(num(opt, value(opt)?)?),
        "--decimals" => s.decimals = whole(opt, value(opt)?)?,
        "--join" => s.join = value(opt)?,
        "--material" => s.material_name = Some(value(opt)?),
        "--materials" => s.materials = Some(read(opt, &value(opt)?)?),
        "--units" => s.units = Some(value(opt)?),
        "--gap" => s.gap = Some(num(opt, value(opt)?)?),
        "--layers" => {
            s.layers = Some(
                value(opt)?
                    .split(',')
                    .map(|l| l.trim().to_string())
                    .collect(),
            )
        }
        "--order" => s.order = value(opt)?,
        "--euler-mode" => s.euler_mode = value(opt)?,
        "--lead" => s.lead = value(opt)?,
        "--lead-outer" => s.lead_outer = num(opt, value(opt)?)?,
        "--lead-hole" => s.lead_hole = num(opt, value(opt)?)?,
        "--overcut" => s.overcut = num(opt, value(opt)?)?,
        "--max-link" => s.max_link = num(opt, value(opt)?)?,
        "--outer-dir" => s.outer_dir = value(opt)?,
        "--hole-dir" => s.hole_dir = value(opt)?,
        "--origin" => {
            let v = value(opt)?;
            let (x, y) = v
                .split_once(',')
                .with_context(|| format!("--origin: '{v}' is not X,Y"))?;
            s.tool_start = [num(opt, x.trim().into())?, num(opt, y.trim().into())?];
        }
        "--start" | "--tab-at" => {
            let v = value(opt)?;
            let (x, y) = v
                .split_once(',')
                .with_context(|| format!("{opt}: '{v}' is not X,Y"))?;
            let at = [num(opt, x.trim().into())?, num(opt, y.trim().into())?];
            let choice = Choice::Keyed { at, on: None };
            match opt {
                "--start" => s.starts.push(choice),
                _ => s.tabs_at.push(choice),
            }
        }
        "--side-at" => {
            // X,Y=SIDE: the profile through X,Y cut outside, inside or on.
            let v = value(opt)?;
            let (xy, side) = v
                .rsplit_once('=')
                .with_context(|| format!("{opt}: '{v}' is not X,Y=outside, inside or on"))?;
            let (x, y) = xy
                .split_once(',')
                .with_context(|| format!("{opt}: '{v}' is not X,Y=outside, inside or on"))?;
            let at = [num(opt, x.trim().into())?, num(opt, y.trim().into())?];
            s.sides_at.push(kerfcam::SideChoice {
                at,
                on: None,
                side: side.trim().into(),
            });
        }
        "--program-origin" => s.origin = value(opt)?,
        "--cut-open" => s.cut_open = true,
        "--controller-comp" => s.controller_comp = true,
        "--fit-arcs" => s.fit_arcs = true,
        "--incremental" => s.incremental = true,
        "--layer-op" => {
            let v = value(opt)?;
            let (layer, op) = v.rsplit_once('=').with_context(|| {
                format!("--layer-op: '{v}' is not LAYER=cut, mark, spot, ignore, pocket, profile, engrave or drill")
            })?;
            s.layer_ops.push([layer.trim().into(), op.trim().into()]);
        }
        "--no-layer-names" => s.layer_ops_by_name = false,
        "--small-hole" => s.small_hole_diameter = Some(num(opt, value(opt)?)?),
        "--small-hole-speed" => s.small_hole_speed = Some(num(opt, value(opt)?)?),
        "--small-hole-min" => s.small_hole_min = num(opt, value(opt)?)?,
        "--pierce-height" => s.pierce_height = Some(num(opt, value(opt)?)?),
        "--cut-height" => s.cut_height = Some(num(opt, value(opt)?)?),
        "--material-number" => s.material_number = Some(whole(opt, value(opt)?)?),
        "--depth" => s.depth = Some(num(opt, value(opt)?)?),
        "--pass-depth" => s.pass_depth = num(opt, value(opt)?)?,
        "--thc-corner" => s.thc_corner_distance = num(opt, value(opt)?)?,
        "--thc-corner-angle" => s.thc_corner_angle = num(opt, value(opt)?)?,
        "--thc-end" => s.thc_end_distance = num(opt, value(opt)?)?,
        "--tabs" => s.tabs = whole(opt, value(opt)?)?,
        "--tab-width" => s.tab_width = num(opt, value(opt)?)?,
        "--tab-holes" => s.tab_holes = true,
        "--tool-diameter" => s.tool_diameter = Some(num(opt, value(opt)?)?),
        "--stepover" => s.stepover = num(opt, value(opt)?)?,
        "--plunge-feed" => s.plunge_feed = num(opt, value(opt)?)?,
        "--spindle-rpm" => s.spindle_rpm = num(opt, value(opt)?)?,
        "--tool-number" => s.tool_number = whole(opt, value(opt)?)?,
        "--tool" => s.tools.push(tool(opt, &value(opt)?)?),
        "--layer-tool" => {
            let v = value(opt)?;
            let (layer, n) = v
                .rsplit_once('=')
                .with_context(|| format!("{opt}: '{v}' is not LAYER=N (a tool's number)"))?;
            s.layer_tools
                .push((layer.trim().into(), whole(opt, n.trim().into())?));
        }
        "--layer-depth" => s.layer_depths.push(layer_depth(opt, &value(opt)?)?),
        "--conventional" => s.milling = "conventional".into(),
        "--pocket" => s.pocket = value(opt)?,
        "--pocket-angle" => s.pocket_angle = num(opt, value(opt)?)?,
        "--pocket-from" => s.pocket_from = value(opt)?,
        "--entry" => s.entry = value(opt)?,
        "--ramp-angle" => s.ramp_angle = num(opt, value(opt)?)?,
        "--helix-diameter" => s.helix_diameter = num(opt, value(opt)?)?,
        "--allowance" => s.allowance = num(opt, value(opt)?)?,
        "--peck" => s.peck = num(opt, value(opt)?)?,
        "--drill-max" => s.drill_max = num(opt, value(opt)?)?,
        "--v-angle" => s.v_angle = num(opt, value(opt)?)?,
        "--engrave-width" => s.engrave_width = num(opt, value(opt)?)?,
        "--engrave-depth" => s.engrave_depth = num(opt, value(opt)?)?,
        "--lead-radius" => s.lead_radius = num(opt, value(opt)?)?,
        "--tab-height" => s.tab_height = num(opt, value(opt)?)?,
        "--verify" => s.verify = true,
        "--no-repair" => s.repair_self_crossing = false,
        "--post" => {
            let v = value(opt)?;
            if v.ends_with(".json") {
                s.post_json = Some(read(opt, &v)?);
            } else {
                // A preset's name: the builder lists them when it is none.
                s.post = Some(v);
            }
        }
        "--lang" => {
            let v = value(opt)?;
            if Lang::from_name(&v).is_none() {
                bail!("--lang: '{v}' is not en or pt-BR");
            }
            s.lang = Some(v);
        }
        _ => return Ok(false),
    }
    Ok(true)
}

/// The command-line option that sets a [`Spec`] field the builder names
/// in an error (its wire name): the CLI's messages name what was typed.
pub fn option_of(field: &str) -> String {
    let named = match field {
        "layer_ops" => "layer-op",
        "small_hole_diameter" => "small-hole",
        "small_hole_min" => "small-hole-min",
        "origin" | "program_origin_x" | "program_origin_y" => "program-origin",
        "origin_x" | "origin_y" => "origin",
        "thc_corner_distance" => "thc-corner",
        "thc_end_distance" => "thc-end",
        "milling" => "conventional",
        "tools" => "tool",
        "layer_tools" => "layer-tool",
        "layer_depths" => "layer-depth",
        other => return format!("--{}", other.replace('_', "-")),
    };
    format!("--{named}")
}

/// A builder's error as the command line says it: the option, then why,
/// in `lang`.
pub fn settings_error(e: &kerfcam::SettingsError, lang: Lang) -> anyhow::Error {
    anyhow::anyhow!("{}: {}", option_of(e.field), e.reason.get(lang))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn builder_errors_name_the_option_typed() {
        let mut spec = Spec::default();
        let mut args = ["DIM=mill".to_string()].into_iter();
        let mut value = |_: &str| Ok(args.next().unwrap());
        assert!(apply(&mut spec, "--layer-op", &mut value).unwrap());
        let e = spec.build().unwrap_err();
        let msg = settings_error(&e, Lang::En).to_string();
        assert!(msg.starts_with("--layer-op: layer 'DIM'"), "{msg}");
        assert_eq!(option_of("lead_outer"), "--lead-outer");
        assert_eq!(option_of("small_hole_diameter"), "--small-hole");
    }

    #[test]
    fn a_layer_depth_reads_its_keys_and_names_what_is_not_one() {
        let d = layer_depth(
            "--layer-depth",
            "LETTERS=3,pass-depth=1.5,milling=conventional",
        )
        .unwrap();
        assert_eq!(
            (d.layer.as_str(), d.depth, d.pass_depth),
            ("LETTERS", Some(3.0), Some(1.5))
        );
        assert_eq!(d.milling.as_deref(), Some("conventional"));
        let d = layer_depth("--layer-depth", "A=B=0.5").unwrap();
        assert_eq!(
            (d.layer.as_str(), d.depth, d.pass_depth),
            ("A=B", Some(0.5), None)
        );
        let e = layer_depth("--layer-depth", "LETTERS=3,pass=1")
            .unwrap_err()
            .to_string();
        assert!(e.contains("'pass' is not pass-depth or milling"), "{e}");
        assert!(layer_depth("--layer-depth", "LETTERS").is_err());
        assert_eq!(option_of("layer_depths"), "--layer-depth");
    }
}
