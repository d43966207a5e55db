//! The process settings' builders: small holes, torch heights, depth
//! passes, the height-control lock, and a cut-chart entry with its
//! controller material number (issue 20). Each checks its numbers and names
//! the field it refuses.

use super::{check, Settings, SettingsError};
use crate::process::{Passes, SmallHole};
use crate::text;

impl Settings {
    /// The same settings with the small-hole rule `rule` (diameter 0 = off;
    /// speed 10..=100 %, as QtPlasmaC clamps it).
    pub fn with_small_hole(mut self, rule: SmallHole) -> Result<Settings, SettingsError> {
        check("small_hole_diameter", rule.diameter, 0.0, 1000.0)?;
        check("small_hole_speed", rule.speed_pct, 10.0, 100.0)?;
        check("small_hole_min", rule.min_diameter, 0.0, 1000.0)?;
        check("small_hole_overcut", rule.overcut, 0.0, 100.0)?;
        self.process.small_hole = rule;
        Ok(self)
    }
    /// The same settings with the torch heights of a Z post, mm (0..=100).
    pub fn with_heights(mut self, pierce: f64, cut: f64) -> Result<Settings, SettingsError> {
        self.process.pierce_height = check("pierce_height", pierce, 0.0, 100.0)?;
        self.process.cut_height = check("cut_height", cut, 0.0, 100.0)?;
        Ok(self)
    }
    /// The same settings cutting `passes.depth` mm of material in passes of
    /// at most `passes.pass_depth` mm (issue 20 §8; both 0 = off, one pass).
    pub fn with_passes(mut self, passes: Passes) -> Result<Settings, SettingsError> {
        check("depth", passes.depth, 0.0, 1000.0)?;
        check("pass_depth", passes.pass_depth, 0.0, 1000.0)?;
        if (passes.depth > 0.0) != (passes.pass_depth > 0.0) {
            return Err(SettingsError {
                field: if passes.depth > 0.0 {
                    "pass_depth"
                } else {
                    "depth"
                },
                reason: text!("depth passes need both the material's depth and the deepest pass";
                              "passes em profundidade precisam da espessura do material e do passe mais fundo"),
            });
        }
        if passes.on() && passes.depth / passes.pass_depth > 1000.0 {
            return Err(SettingsError {
                field: "pass_depth",
                reason: text!("more than 1000 passes"; "mais de 1000 passes"),
            });
        }
        self.process.passes = passes;
        Ok(self)
    }
    /// The same settings milling with `tool` (issue 43; diameter 0 = no
    /// tool). Each number checked, naming its field: a stepover of 0 or
    /// above 100 %, a ramp steeper than 45°, an allowance of half the tool.
    pub fn with_tool(mut self, tool: crate::process::Tool) -> Result<Settings, SettingsError> {
        check_tool(&tool)?;
        self.process.tool = tool;
        Ok(self)
    }
    /// The same settings locking the torch height before sharp corners and
    /// near a contour's end (issue 20 §4; distances 0..=1000 mm, the angle
    /// 1..=179°).
    pub fn with_thc_lock(
        mut self,
        rule: crate::process::ThcLock,
    ) -> Result<Settings, SettingsError> {
        check("thc_corner_angle", rule.corner_angle_deg, 1.0, 179.0)?;
        check("thc_corner_distance", rule.corner_distance, 0.0, 1000.0)?;
        check("thc_end_distance", rule.end_distance, 0.0, 1000.0)?;
        self.process.thc_lock = rule;
        Ok(self)
    }
    /// The same settings cutting with cut-chart entry `e` (the page's cut
    /// chart; what the CLI's `--material` sets): its kerf, feed, pierce
    /// delay, pierce and cut heights, height control and controller
    /// material number, all from [`crate::materials::Entry::process`];
    /// small holes by its rule (1.5 × its thickness) where no diameter is
    /// set here, and at its small-hole speed where it gives one.
    pub fn with_material(mut self, e: &crate::materials::Entry) -> Result<Settings, SettingsError> {
        let p = e.process(self.process.rapid);
        self.process.kerf = check("kerf", p.kerf, 0.0, 100.0)?;
        self.process.feed = check("feed", p.feed, 1e-3, 1e6)?;
        self.process.thc = p.thc;
        let mut rule = self.process.small_hole;
        if rule.diameter == 0.0 {
            rule.diameter = p.small_hole.diameter;
        }
        if e.small_hole_speed.is_some() {
            rule.speed_pct = p.small_hole.speed_pct;
        }
        let s = self
            .with_pierce_delay(p.pierce_delay)?
            .with_heights(p.pierce_height, p.cut_height)?
            .with_small_hole(rule)?;
        match e.number {
            Some(n) => s.with_material_number(n),
            None => Ok(s),
        }
    }
    /// The same settings selecting the controller's material `n` (QtPlasmaC
    /// `M190 Pn`; 0..=1_000_000).
    pub fn with_material_number(mut self, n: u32) -> Result<Settings, SettingsError> {
        check("material_number", n as f64, 0.0, 1e6)?;
        self.process.material = n;
        Ok(self)
    }
}

/// `tool`'s numbers in their ranges, naming the field of the first that
/// is not ([`Settings::with_tool`]; a listed tool's too).
pub(super) fn check_tool(tool: &crate::process::Tool) -> Result<(), SettingsError> {
    check("tool_diameter", tool.diameter, 0.0, 200.0)?;
    if tool.on() {
        check("stepover", tool.stepover_pct, 1.0, 100.0)?;
        check("plunge_feed", tool.plunge_feed, 1e-3, 1e6)?;
        check("spindle_rpm", tool.spindle_rpm, 0.0, 1e6)?;
        check("pocket_angle", tool.angle_deg, -360.0, 360.0)?;
        check("ramp_angle", tool.ramp_angle_deg, 0.1, 45.0)?;
        check("helix_diameter", tool.helix_diameter, 0.0, tool.diameter)?;
        check("allowance", tool.allowance, 0.0, tool.diameter / 2.0)?;
        check("peck", tool.peck, 0.0, 1000.0)?;
        check("drill_max", tool.drill_max, 0.0, 1000.0)?;
        if tool.v_angle_deg != 0.0 {
            // A V-bit's angle in (0°, 180°): a flat or a spike cuts no width.
            check("v_angle", tool.v_angle_deg, 1.0, 179.0)?;
        }
        check("engrave_width", tool.engrave_width, 0.0, tool.diameter)?;
        check("engrave_depth", tool.engrave_depth, 0.0, 1000.0)?;
        check("lead_radius", tool.lead_radius, 0.0, 200.0)?;
        check("tab_height", tool.tab_height, 0.0, 1000.0)?;
        check("tool_number", f64::from(tool.number), 1.0, 99_999.0)?;
        if tool.engrave_width > 0.0 && tool.v_angle_deg == 0.0 {
            return Err(SettingsError {
                field: "engrave_width",
                reason: text!("an engraving's width sets its depth only with a V-bit: give the tool's V angle (--v-angle DEG), or leave the width at 0 and give the depth";
                              "a largura da gravação só define a profundidade com uma fresa em V: informe o ângulo do V (--v-angle GRAUS), ou deixe a largura em 0 e informe a profundidade"),
            });
        }
        if tool.engrave_depth > 0.0 && tool.v_angle_deg == 0.0 {
            return Err(SettingsError {
                field: "engrave_depth",
                reason: text!("an engraving's own depth is a V-bit's: give the tool's V angle (--v-angle DEG), or leave it at 0 and give the job's depth";
                              "a profundidade própria da gravação é de uma fresa em V: informe o ângulo do V (--v-angle GRAUS), ou deixe-a em 0 e informe a profundidade do trabalho"),
            });
        }
        if tool.engrave_depth > 0.0 && tool.engrave_width > 0.0 {
            return Err(SettingsError {
                field: "engrave_depth",
                reason: text!("a V engraving's depth and width follow from each other: give one of them (the other 0)";
                              "a profundidade e a largura de uma gravação em V decorrem uma da outra: informe só uma (a outra 0)"),
            });
        }
    }
    Ok(())
}
