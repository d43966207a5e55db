//! The router's tool list's builder (issue 43 §1): each listed tool's
//! numbers in range, numbers that name one tool each, and layers given a
//! tool the job has.

use super::{check, process::check_tool, Settings, SettingsError};
use crate::process::{LayerDepths, Tools};
use crate::text;
use crate::warning::dec;

impl Settings {
    /// The same settings with the job's other tools and the layers they
    /// mill ([`Tools`]). Refused, naming `tools` or `layer_tools`: a list
    /// without the job's own tool, a number out of range or given twice
    /// (the job's own included), a listed tool's value out of its range
    /// (said with its number), a layer given a tool the job does not have.
    pub fn with_tools(mut self, tools: Tools) -> Result<Settings, SettingsError> {
        let job = self.process.tool;
        let err = |field, reason| SettingsError { field, reason };
        if !tools.is_empty() && !job.on() {
            return Err(err(
                "tools",
                text!("a tool list needs the job's own tool (--tool-diameter), which also cuts the profiles";
                      "uma lista de ferramentas precisa da ferramenta do trabalho (--tool-diameter), que também corta os perfis"),
            ));
        }
        let mut seen = vec![job.number];
        for t in &tools.others {
            let n = t.tool.number;
            let named = |e: SettingsError| {
                let (f, en, pt) = (e.field, e.reason.en, e.reason.pt);
                err(
                    "tools",
                    text!("tool {n}: {f}: {en}"; "ferramenta {n}: {f}: {pt}"),
                )
            };
            check("tool_number", f64::from(n), 1.0, 99_999.0).map_err(named)?;
            if seen.contains(&n) {
                return Err(err(
                    "tools",
                    text!("tool {n} is given twice (the job's own tool is {}): one number, one tool", job.number;
                          "a ferramenta {n} aparece duas vezes (a do trabalho é a {}): um número, uma ferramenta", job.number),
                ));
            }
            seen.push(n);
            if !t.tool.on() {
                return Err(err(
                    "tools",
                    text!("tool {n}: its diameter is needed (N=DIAMETER)"; "ferramenta {n}: falta o diâmetro (N=DIÂMETRO)"),
                ));
            }
            check_tool(&t.tool).map_err(named)?;
            check("feed", t.feed, 1e-3, 1e6).map_err(named)?;
        }
        for (layer, n) in &tools.layers {
            if !seen.contains(n) {
                let known = (seen.iter().map(u32::to_string))
                    .collect::<Vec<_>>()
                    .join(", ");
                return Err(err(
                    "layer_tools",
                    text!("layer '{layer}': the job has no tool {n} (its tools: {known})";
                          "camada '{layer}': o trabalho não tem a ferramenta {n} (as suas: {known})"),
                ));
            }
        }
        self.tools = tools;
        Ok(self)
    }
}

impl Settings {
    /// The same settings with milling layers at their own depth
    /// ([`LayerDepths`]). Refused, naming `layer_depths` and the layer:
    /// a depth or pass depth out of 0 < x ≤ 1000 mm, a layer depth with
    /// no job depth to default the others to, a layer deeper than the
    /// job's depth (the material's thickness, what the profiles cut
    /// through): the tool would mill the machine's bed.
    pub fn with_layer_depths(mut self, depths: LayerDepths) -> Result<Settings, SettingsError> {
        let job = self.process.passes;
        for d in &depths.given {
            let layer = &d.layer;
            let named = |e: SettingsError| {
                let (f, en, pt) = (e.field, e.reason.en, e.reason.pt);
                SettingsError {
                    field: "layer_depths",
                    reason: text!("layer '{layer}': {f}: {en}"; "camada '{layer}': {f}: {pt}"),
                }
            };
            if !job.on() {
                return Err(SettingsError {
                    field: "layer_depths",
                    reason: text!("layer '{layer}': a layer's own depth needs the job's (--depth and --pass-depth), which the other layers and the profiles are cut to";
                                  "camada '{layer}': a profundidade de uma camada precisa da do trabalho (--depth e --pass-depth), a das outras camadas e dos perfis"),
                });
            }
            for (f, v) in [
                ("depth", d.passes.depth),
                ("pass_depth", d.passes.pass_depth),
            ] {
                if !(v > 0.0 && v <= 1000.0) {
                    let vd = dec(v);
                    return Err(named(SettingsError {
                        field: f,
                        reason: text!("{v} mm is not above 0 and at most 1000"; "{vd} mm não é mais que 0 e no máximo 1000"),
                    }));
                }
            }
            if d.passes.depth > job.depth * (1.0 + 1e-9) {
                let (h, t) = (d.passes.depth, job.depth);
                let (hd, td) = (dec(h), dec(t));
                return Err(SettingsError {
                    field: "layer_depths",
                    reason: text!("layer '{layer}': {h} mm is deeper than the job's {t} mm (the material's thickness): the tool would mill the bed below it";
                                  "camada '{layer}': {hd} mm é mais fundo que os {td} mm do trabalho (a espessura do material): a ferramenta fresaria a mesa abaixo dele"),
                });
            }
        }
        self.layer_depths = depths;
        Ok(self)
    }
}
