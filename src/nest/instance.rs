//! ESICUP strip-packing instances in the JSON of jagua-rs and sparrow:
//! `{name, items[{id, demand, allowed_orientations, shape{type, data}}],
//! strip_height}` (the format of `../shared/nesting/`). Shapes:
//! `simple_polygon` (a point list), `polygon` ({outer, inner}) and
//! `rectangle` ({x_min, y_min, width, height}). Units are the instance's own.

use serde_json::Value;

use super::{NestError, NestJob, NestSettings, Part, Rotations, Sheets, MAX_QUANTITY};
use crate::geom::{Point, Segment};

/// An instance read: its name and the job (strip mode, no mirror).
#[derive(Clone, Debug)]
pub struct Instance {
    /// `name`.
    pub name: String,
    /// The job; its settings are `settings` as given, spacing and margin 0.
    pub job: NestJob,
}

fn bad<T>(why: impl Into<String>) -> Result<T, NestError> {
    Err(NestError::Instance(why.into()))
}

fn ring(v: &Value, what: &str) -> Result<Vec<Segment>, NestError> {
    let Some(pts) = v.as_array() else {
        return bad(format!("{what}: not a list of points"));
    };
    let mut p: Vec<Point> = Vec::with_capacity(pts.len());
    for q in pts {
        let xy = q
            .as_array()
            .and_then(|a| Some((a.first()?.as_f64()?, a.get(1)?.as_f64()?)));
        match xy {
            Some((x, y)) if x.is_finite() && y.is_finite() => p.push(Point::new(x, y)),
            _ => return bad(format!("{what}: a point is not [x, y]")),
        }
    }
    if p.len() > 1 && p.first() == p.last() {
        p.pop();
    }
    p.dedup();
    if p.len() < 3 {
        return bad(format!("{what}: fewer than 3 points"));
    }
    let n = p.len();
    Ok((0..n)
        .map(|i| Segment::line(p[i], p[(i + 1) % n]))
        .collect())
}

/// Reads an instance; `settings` gives the tolerance, time and seed.
pub fn read(json: &str, settings: NestSettings) -> Result<Instance, NestError> {
    let v: Value =
        serde_json::from_str(json).map_err(|e| NestError::Instance(format!("not JSON ({e})")))?;
    let name = v
        .get("name")
        .and_then(Value::as_str)
        .unwrap_or("instance")
        .to_owned();
    let Some(height) = v.get("strip_height").and_then(Value::as_f64) else {
        return bad("no strip_height");
    };
    let Some(items) = v.get("items").and_then(Value::as_array) else {
        return bad("no items list");
    };
    let mut parts = Vec::new();
    for (k, it) in items.iter().enumerate() {
        let id = it.get("id").map_or(k.to_string(), |i| i.to_string());
        let what = format!("item {id}");
        let demand = match it.get("demand").and_then(Value::as_u64) {
            Some(d) if d as usize <= MAX_QUANTITY => d as usize,
            Some(d) => {
                return Err(NestError::TooMany {
                    part: id,
                    quantity: d as usize,
                })
            }
            None => return bad(format!("{what}: no demand")),
        };
        let rotations = match it.get("allowed_orientations") {
            None | Some(Value::Null) => Rotations::None,
            Some(a) => match a.as_array() {
                Some(a) => Rotations::List(a.iter().filter_map(Value::as_f64).collect()),
                None => return bad(format!("{what}: allowed_orientations is not a list")),
            },
        };
        let Some(shape) = it.get("shape") else {
            return bad(format!("{what}: no shape"));
        };
        let data = shape.get("data").unwrap_or(&Value::Null);
        let (outer, holes) = match shape.get("type").and_then(Value::as_str) {
            Some("simple_polygon") => (ring(data, &what)?, Vec::new()),
            Some("polygon") => {
                let holes = match data.get("inner").and_then(Value::as_array) {
                    Some(h) => h.iter().map(|r| ring(r, &what)).collect::<Result<_, _>>()?,
                    None => Vec::new(),
                };
                (
                    ring(data.get("outer").unwrap_or(&Value::Null), &what)?,
                    holes,
                )
            }
            Some("rectangle") => {
                let f = |k: &str| data.get(k).and_then(Value::as_f64);
                let (Some(x), Some(y), Some(w), Some(h)) =
                    (f("x_min"), f("y_min"), f("width"), f("height"))
                else {
                    return bad(format!(
                        "{what}: rectangle needs x_min, y_min, width, height"
                    ));
                };
                let r = serde_json::json!([[x, y], [x + w, y], [x + w, y + h], [x, y + h]]);
                (ring(&r, &what)?, Vec::new())
            }
            other => return bad(format!("{what}: shape type {other:?} is not read")),
        };
        parts.push(Part {
            name: format!("item_{id}"),
            outer,
            holes,
            quantity: demand,
            rotations,
            mirror: false,
        });
    }
    if parts.is_empty() {
        return bad("no items");
    }
    let settings = NestSettings {
        spacing: 0.0,
        margin: 0.0,
        ..settings
    };
    Ok(Instance {
        name,
        job: NestJob {
            parts,
            sheets: Sheets::Strip { height },
            settings,
        },
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reads_polygons_rectangles_and_orientations() {
        let j = r#"{"name":"t","strip_height":10,"items":[
            {"id":0,"demand":2,"allowed_orientations":[0,180],"shape":{"type":"simple_polygon","data":[[0,0],[2,0],[0,2],[0,0]]}},
            {"id":1,"demand":1,"shape":{"type":"rectangle","data":{"x_min":0,"y_min":0,"width":3,"height":1}}}]}"#;
        let i = read(j, NestSettings::default()).unwrap();
        assert_eq!(i.job.parts.len(), 2);
        assert_eq!(i.job.parts[0].quantity, 2);
        assert_eq!(i.job.parts[0].rotations.angles(), [0.0, 180.0]);
        assert!((i.job.parts[1].area() - 3.0).abs() < 1e-12);
        assert_eq!(i.job.sheets, Sheets::Strip { height: 10.0 });
    }

    #[test]
    fn what_is_not_an_instance_is_said() {
        for bad in [
            "",
            "[]",
            "{\"items\":[]}",
            "{\"strip_height\":5,\"items\":[{\"demand\":1}]}",
            "{\"strip_height\":5,\"items\":[{\"demand\":1,\"shape\":{\"type\":\"circle\"}}]}",
        ] {
            assert!(
                matches!(
                    read(bad, NestSettings::default()),
                    Err(NestError::Instance(_))
                ),
                "{bad}"
            );
        }
        let big = r#"{"strip_height":5,"items":[{"demand":20000,"shape":{"type":"simple_polygon","data":[[0,0],[1,0],[0,1]]}}]}"#;
        assert!(matches!(
            read(big, NestSettings::default()),
            Err(NestError::TooMany { .. })
        ));
    }
}
