//! The built-in posts, as JSON files beside this one (the same format a
//! user saves and loads), embedded at build time.

use super::post::Post;

/// CLI names of the presets, in the order `--list-posts` shows them.
pub const PRESET_NAMES: [&str; 15] = [
    "linuxcnc-plasma",
    "linuxcnc",
    "grbl-laser",
    "grbl-plasma",
    "mach3-plasma",
    "iso6983",
    "annex-h",
    "point-list",
    "knife-relative",
    "knife-gcode",
    "qtplasmac",
    "linuxcnc-z",
    "grbl-router",
    "linuxcnc-router",
    "mach3-router",
];

fn json(name: &str) -> Option<&'static str> {
    Some(match name {
        "linuxcnc-plasma" => include_str!("presets/linuxcnc-plasma.json"),
        "linuxcnc" => include_str!("presets/linuxcnc.json"),
        "grbl-laser" => include_str!("presets/grbl-laser.json"),
        "grbl-plasma" => include_str!("presets/grbl-plasma.json"),
        "mach3-plasma" => include_str!("presets/mach3-plasma.json"),
        "iso6983" => include_str!("presets/iso6983.json"),
        "annex-h" => include_str!("presets/annex-h.json"),
        "point-list" => include_str!("presets/point-list.json"),
        "knife-relative" => include_str!("presets/knife-relative.json"),
        "knife-gcode" => include_str!("presets/knife-gcode.json"),
        "qtplasmac" => include_str!("presets/qtplasmac.json"),
        "linuxcnc-z" => include_str!("presets/linuxcnc-z.json"),
        "grbl-router" => include_str!("presets/grbl-router.json"),
        "linuxcnc-router" => include_str!("presets/linuxcnc-router.json"),
        "mach3-router" => include_str!("presets/mach3-router.json"),
        _ => return None,
    })
}

/// The preset called `name` (None for an unknown name).
pub fn preset(name: &str) -> Option<Post> {
    // Every preset parses and validates (tested below).
    Post::from_json(json(name)?).ok()
}

/// Every preset, as one JSON object by name (the page's post menu): the
/// text `serde_json::Value::Object` of a `serde_json::Map` writes (names
/// in byte order, each post as `serde_json::to_value` makes it), put
/// together here so that the cutting core's wasm needs no map of values
/// and its sort (issue 17).
pub fn presets_json() -> String {
    let mut names = PRESET_NAMES;
    crate::sort::sort_by(&mut names, |a, b| a.cmp(b));
    let mut out = String::from("{");
    for n in names {
        let Some(post) = preset(n).and_then(|p| serde_json::to_value(p).ok()) else {
            continue;
        };
        if out.len() > 1 {
            out.push(',');
        }
        out.push_str(&serde_json::Value::from(n).to_string());
        out.push(':');
        out.push_str(&post.to_string());
    }
    out.push('}');
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn presets_json_as_the_map_wrote_it() {
        let map: serde_json::Map<String, serde_json::Value> = PRESET_NAMES
            .iter()
            .filter_map(|n| Some((n.to_string(), serde_json::to_value(preset(n)?).ok()?)))
            .collect();
        assert_eq!(presets_json(), serde_json::Value::Object(map).to_string());
    }

    #[test]
    fn every_preset_parses_and_validates() {
        for n in PRESET_NAMES {
            let text = json(n).unwrap();
            if let Err(e) = Post::from_json(text) {
                panic!("preset {n}: {e}");
            }
        }
        assert!(preset("nope").is_none());
    }

    #[test]
    fn the_linuxcnc_preset_is_the_first_pipeline_program() {
        let p = preset("linuxcnc").unwrap();
        assert_eq!(
            p,
            Post {
                name: "LinuxCNC".into(),
                // The Z words of depth passes (issue 20 §8), as emit's.
                pass_z: vec!["G1 Z{pass_z}".into()],
                pass_retract: vec!["G0 Z{safe_height}".into()],
                ..Post::default()
            }
        );
        // A post survives export and import.
        assert_eq!(Post::from_json(&p.to_json()).unwrap(), p);
    }
}
