//! The defaults of every number a job is given, as the page's form shows
//! them: [`Spec::default`] with what it leaves to the process (kerf,
//! feed, delay, rapid, heights, small holes) filled from
//! [`Process::DEFAULT`], and the nest's. The page takes its form's initial
//! values from here, so a default is written once, in Rust.

use serde_json::{json, Value};

use crate::nest::{NestSettings, SPACING_OVER_KERF};
use crate::process::Process;
use crate::settings::{Spec, DEFAULT_RAPID};

/// The Router tool panel's starting diameter, mm.
pub const PAGE_TOOL_DIAMETER: f64 = 6.0;

/// The defaults by the settings' wire names (numbers only; the choices'
/// defaults are the form's selected options), the nest's under `nest`.
pub fn page_defaults() -> Value {
    let s = Spec::default();
    let p = Process::DEFAULT;
    let n = NestSettings::for_kerf(p.kerf);
    let mut d = json!({
        "kerf": s.kerf.unwrap_or(p.kerf),
        "tolerance": s.tolerance,
        "feed": s.feed.unwrap_or(p.feed),
        "rapid": s.rapid.unwrap_or(DEFAULT_RAPID),
        "pierce_delay": s.pierce_delay.unwrap_or(p.pierce_delay),
        "lead_outer": s.lead_outer,
        "lead_hole": s.lead_hole,
        "overcut": s.overcut,
        "max_link": s.max_link,
        "small_hole_diameter": s.small_hole_diameter.unwrap_or(p.small_hole.diameter),
        "small_hole_speed": s.small_hole_speed.unwrap_or(p.small_hole.speed_pct),
        "small_hole_min": s.small_hole_min,
        "pierce_height": s.pierce_height.unwrap_or(p.pierce_height),
        "cut_height": s.cut_height.unwrap_or(p.cut_height),
        "tabs": s.tabs,
        "tab_width": s.tab_width,
        "thc_corner_distance": s.thc_corner_distance,
        "thc_corner_angle": s.thc_corner_angle,
        "thc_end_distance": s.thc_end_distance,
        "depth": s.depth.unwrap_or(p.passes.depth),
        "pass_depth": s.pass_depth,
        // The router's tool (issue 43): the Spec's, but the diameter, which
        // the Spec leaves unset (no tool): the form starts from a 6 mm end
        // mill, a common router bit, shown in its field.
        "tool_diameter": s.tool_diameter.unwrap_or(PAGE_TOOL_DIAMETER),
        "stepover": s.stepover,
        "plunge_feed": s.plunge_feed,
        "spindle_rpm": s.spindle_rpm,
        "pocket_angle": s.pocket_angle,
        "ramp_angle": s.ramp_angle,
        "helix_diameter": s.helix_diameter,
        "allowance": s.allowance,
        "peck": s.peck,
        "drill_max": s.drill_max,
        "v_angle": s.v_angle,
        "engrave_width": s.engrave_width,
        "engrave_depth": s.engrave_depth,
        "lead_radius": s.lead_radius,
        "tab_height": s.tab_height,
        "nest": {
            "spacing_over_kerf": SPACING_OVER_KERF,
            "margin": n.margin,
            "tolerance": n.tolerance,
            "time_s": n.time_s,
        },
    });
    // Past json!'s recursion limit in the one literal.
    d["tool_number"] = json!(s.tool_number);
    d
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_page_defaults_are_the_engine_defaults() {
        let d = page_defaults();
        let built = Spec::default().build().unwrap();
        let p = built.process();
        assert_eq!(d["kerf"], p.kerf);
        assert_eq!(d["feed"], p.feed);
        assert_eq!(d["rapid"], p.rapid);
        assert_eq!(d["pierce_delay"], p.pierce_delay);
        assert_eq!(d["pierce_height"], p.pierce_height);
        assert_eq!(d["small_hole_speed"], p.small_hole.speed_pct);
        assert_eq!(d["tolerance"], built.tolerance().mm());
        assert_eq!(d["nest"]["spacing_over_kerf"], 1.0);
        // Every field the page has: a number.
        for key in [
            "lead_outer",
            "lead_hole",
            "overcut",
            "max_link",
            "tab_width",
            "thc_corner_angle",
            "tool_diameter",
            "stepover",
            "plunge_feed",
            "spindle_rpm",
            "tool_number",
            "ramp_angle",
        ] {
            assert!(d[key].is_number(), "{key}");
        }
    }
}
