//! The document's size and units: lengths in CSS units, `viewBox` with
//! `preserveAspectRatio`, and the root viewport in millimetres (SVG 1.1
//! §7.7–7.10, CSS Values 3 §5.2: 1 in = 2.54 cm = 25.4 mm = 72 pt = 6 pc =
//! 96 px).

use std::str::FromStr;

use svgtypes::{Align, AspectRatio, Length, LengthUnit, ViewBox};

use crate::dxf::Units;
use crate::geom::Affine;

/// Millimetres per CSS px (96 per inch).
pub const PX_MM: f64 = Units::PX.to_mm;
/// Millimetres per px at Illustrator's legacy 72 per inch.
pub const PX72_MM: f64 = Units::PX72.to_mm;
/// CSS's initial font size, px: an `em` where no font size is known.
const EM_PX: f64 = 16.0;

/// The px units, as the page's unit switch names them.
pub const PX: Units = Units::PX;
pub const PX72: Units = Units::PX72;

/// Millimetres per unit of a physical length unit; None for px, unitless,
/// relative units.
pub fn physical_mm(unit: LengthUnit) -> Option<(f64, &'static str)> {
    match unit {
        LengthUnit::Mm => Some((1.0, "mm")),
        LengthUnit::Cm => Some((10.0, "cm")),
        LengthUnit::In => Some((25.4, "in")),
        LengthUnit::Pt => Some((25.4 / 72.0, "pt")),
        LengthUnit::Pc => Some((25.4 / 6.0, "pc")),
        _ => None,
    }
}

/// A length in user units (px) where one px is `px_mm` millimetres;
/// percentages of `of` (the viewport's width, height or normalised
/// diagonal). None for a length that is not a finite number.
pub fn user_length(l: Length, px_mm: f64, of: f64) -> Option<f64> {
    let v = match l.unit {
        LengthUnit::None | LengthUnit::Px => l.number,
        LengthUnit::Em => l.number * EM_PX,
        LengthUnit::Ex => l.number * EM_PX / 2.0,
        LengthUnit::Percent => l.number / 100.0 * of,
        u => l.number * physical_mm(u).map_or(1.0, |(k, _)| k) / px_mm,
    };
    v.is_finite().then_some(v)
}

/// An attribute as a length in user units (see [`user_length`]).
pub fn attr_length(node: roxmltree::Node, name: &str, px_mm: f64, of: f64) -> Option<f64> {
    let l = Length::from_str(node.attribute(name)?.trim()).ok()?;
    user_length(l, px_mm, of)
}

/// A usable `viewBox`: None when absent; Err when present but unusable
/// (not four numbers, or a zero or negative width or height).
pub fn view_box(node: roxmltree::Node) -> Result<Option<ViewBox>, String> {
    let Some(v) = node.attribute("viewBox") else {
        return Ok(None);
    };
    match ViewBox::from_str(v) {
        Ok(vb)
            if [vb.x, vb.y, vb.w, vb.h].iter().all(|x| x.is_finite())
                && vb.w > 0.0
                && vb.h > 0.0 =>
        {
            Ok(Some(vb))
        }
        _ => Err(v.chars().take(60).collect()),
    }
}

/// `preserveAspectRatio` (default xMidYMid meet).
pub fn aspect(node: roxmltree::Node) -> AspectRatio {
    node.attribute("preserveAspectRatio")
        .and_then(|v| AspectRatio::from_str(v).ok())
        .unwrap_or_default()
}

/// The map from a viewBox to the viewport (x, y, w, h) (SVG 1.1 §7.8,
/// "viewBox" and "preserveAspectRatio"): scale each axis by the viewport
/// over the box, or both by the smaller (meet) or larger (slice) of the
/// two and align.
pub fn view_box_map(vb: &ViewBox, (x, y, w, h): (f64, f64, f64, f64), par: AspectRatio) -> Affine {
    let (sx, sy) = (w / vb.w, h / vb.h);
    if par.align == Align::None {
        return Affine::translate(x - vb.x * sx, y - vb.y * sy)
            .then_after(&Affine::scale_xy(sx, sy));
    }
    let s = if par.slice { sx.max(sy) } else { sx.min(sy) };
    let (fx, fy) = match par.align {
        Align::XMinYMin => (0.0, 0.0),
        Align::XMidYMin => (0.5, 0.0),
        Align::XMaxYMin => (1.0, 0.0),
        Align::XMinYMid => (0.0, 0.5),
        Align::XMinYMax => (0.0, 1.0),
        Align::XMidYMax => (0.5, 1.0),
        Align::XMaxYMax => (1.0, 1.0),
        Align::XMaxYMid => (1.0, 0.5),
        Align::XMidYMid | Align::None => (0.5, 0.5),
    };
    let tx = x - vb.x * s + (w - vb.w * s) * fx;
    let ty = y - vb.y * s + (h - vb.h * s) * fy;
    Affine::translate(tx, ty).then_after(&Affine::scale(s))
}

/// The root `<svg>` read: how its user units map to the drawing.
#[derive(Clone, Debug)]
pub struct Root {
    /// User units → mm, Y up, the viewport's bottom edge at y = 0.
    pub map: Affine,
    /// The viewport in user units (for percentages).
    pub viewport: (f64, f64),
    /// The viewport in mm, where the file gives one.
    pub size_mm: Option<(f64, f64)>,
    /// The unit the size is given in (its name and mm), px when none.
    pub units: Units,
    /// True when the file states a physical size (mm, cm, in, pt, pc).
    pub physical: bool,
    /// True when the scale rests on the px length (no physical size, or no
    /// viewBox to map the user units into it).
    pub px_scaled: bool,
    /// A `viewBox` present but unusable (its text).
    pub bad_view_box: Option<String>,
}

/// One of `width`/`height`: mm and whether physical; None when absent,
/// a percentage, not a length or not positive.
fn side(node: roxmltree::Node, name: &str, px_mm: f64) -> Option<(f64, bool, &'static str)> {
    let l = Length::from_str(node.attribute(name)?.trim()).ok()?;
    if !(l.number.is_finite() && l.number > 0.0) || l.unit == LengthUnit::Percent {
        return None;
    }
    Some(match physical_mm(l.unit) {
        Some((k, name)) => (l.number * k, true, name),
        None => (user_length(l, px_mm, 0.0)? * px_mm, false, "px"),
    })
}

/// Reads the root's size, viewBox and aspect; `px_mm` is one px in mm.
pub fn root(node: roxmltree::Node, px_mm: f64) -> Root {
    let (w, h) = (side(node, "width", px_mm), side(node, "height", px_mm));
    let (vb, bad_view_box) = match view_box(node) {
        Ok(vb) => (vb, None),
        Err(t) => (None, Some(t)),
    };
    let physical = w.is_some_and(|s| s.1) || h.is_some_and(|s| s.1);
    let unit_name = w.filter(|s| s.1).or(h.filter(|s| s.1)).map(|s| s.2);
    // Sides not given follow the viewBox's aspect, or its size as px.
    let (wmm, hmm) = match (w, h, vb) {
        (Some(w), Some(h), _) => (Some(w.0), Some(h.0)),
        (Some(w), None, Some(vb)) => (Some(w.0), Some(w.0 * vb.h / vb.w)),
        (None, Some(h), Some(vb)) => (Some(h.0 * vb.w / vb.h), Some(h.0)),
        (None, None, Some(vb)) => (Some(vb.w * px_mm), Some(vb.h * px_mm)),
        (w, h, None) => (w.map(|s| s.0), h.map(|s| s.0)),
    };
    let (to_user, viewport) = match vb {
        Some(vb) => {
            let (wm, hm) = (wmm.unwrap_or(vb.w * px_mm), hmm.unwrap_or(vb.h * px_mm));
            (
                view_box_map(&vb, (0.0, 0.0, wm, hm), aspect(node)),
                (vb.w, vb.h),
            )
        }
        None => (
            Affine::scale(px_mm),
            (
                wmm.map_or(100.0, |w| w / px_mm),
                hmm.map_or(100.0, |h| h / px_mm),
            ),
        ),
    };
    // SVG's y runs down from the top edge: y_up = height − y.
    let flip = Affine::translate(0.0, hmm.unwrap_or(0.0)).then_after(&Affine::scale_xy(1.0, -1.0));
    let units = match unit_name {
        Some(name) => Units {
            name,
            to_mm: physical_mm(unit_of(name)).map_or(1.0, |(k, _)| k),
        },
        None if px_mm == PX72_MM => PX72,
        None if px_mm == PX_MM => PX,
        None => Units {
            name: "px",
            to_mm: px_mm,
        },
    };
    Root {
        map: flip.then_after(&to_user),
        viewport,
        size_mm: wmm.zip(hmm),
        units,
        physical,
        px_scaled: !physical || vb.is_none(),
        bad_view_box,
    }
}

fn unit_of(name: &str) -> LengthUnit {
    match name {
        "mm" => LengthUnit::Mm,
        "cm" => LengthUnit::Cm,
        "in" => LengthUnit::In,
        "pt" => LengthUnit::Pt,
        "pc" => LengthUnit::Pc,
        _ => LengthUnit::Px,
    }
}

/// A nested `<svg>`'s or a `<symbol>`'s viewport in its parent's user
/// units (x, y, width, height; a missing size is 100 %), and the map from
/// its own user units to its parent's, with its viewport size in its own
/// user units.
pub fn nested(
    node: roxmltree::Node,
    px_mm: f64,
    parent: (f64, f64),
    size: (Option<f64>, Option<f64>),
) -> (Affine, (f64, f64)) {
    let x = attr_length(node, "x", px_mm, parent.0).unwrap_or(0.0);
    let y = attr_length(node, "y", px_mm, parent.1).unwrap_or(0.0);
    let w = size
        .0
        .or_else(|| attr_length(node, "width", px_mm, parent.0))
        .unwrap_or(parent.0);
    let h = size
        .1
        .or_else(|| attr_length(node, "height", px_mm, parent.1))
        .unwrap_or(parent.1);
    match view_box(node) {
        Ok(Some(vb)) if w > 0.0 && h > 0.0 => {
            (view_box_map(&vb, (x, y, w, h), aspect(node)), (vb.w, vb.h))
        }
        _ => (Affine::translate(x, y), (w, h)),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::Point;

    fn root_of(svg: &str, px_mm: f64) -> Root {
        let doc = roxmltree::Document::parse(svg).unwrap();
        root(doc.root_element(), px_mm)
    }

    fn close(a: Point, b: Point) {
        assert!(a.dist(b) < 1e-9, "{a:?} != {b:?}");
    }

    #[test]
    fn a_mm_page_with_a_view_box_maps_user_units_to_mm_y_up() {
        // 100 × 50 mm page, 200 × 100 units: 0.5 mm per unit, y down → up.
        let r = root_of(
            r#"<svg width="100mm" height="50mm" viewBox="0 0 200 100"/>"#,
            PX_MM,
        );
        assert!(r.physical && !r.px_scaled);
        assert_eq!(r.units.name, "mm");
        close(r.map.apply(Point::new(0.0, 0.0)), Point::new(0.0, 50.0));
        close(
            r.map.apply(Point::new(200.0, 100.0)),
            Point::new(100.0, 0.0),
        );
        close(r.map.apply(Point::new(20.0, 10.0)), Point::new(10.0, 45.0));
    }

    #[test]
    fn inches_points_and_picas_are_physical() {
        for (w, mm) in [("2in", 50.8), ("72pt", 25.4), ("6pc", 25.4), ("3cm", 30.0)] {
            let r = root_of(
                &format!(r#"<svg width="{w}" height="{w}" viewBox="0 0 10 10"/>"#),
                PX_MM,
            );
            let (sw, _) = r.size_mm.unwrap();
            assert!((sw - mm).abs() < 1e-9, "{w}: {sw}");
            close(r.map.apply(Point::new(10.0, 0.0)), Point::new(mm, mm));
        }
    }

    #[test]
    fn px_or_no_size_is_read_at_the_px_length() {
        let r = root_of(r#"<svg width="960" height="96px"/>"#, PX_MM);
        assert!(!r.physical && r.px_scaled);
        let (w, h) = r.size_mm.unwrap();
        assert!((w - 254.0).abs() < 1e-9 && (h - 25.4).abs() < 1e-9);
        let r = root_of(r#"<svg viewBox="0 0 72 72"/>"#, PX72_MM);
        assert_eq!(r.units.name, "px72");
        close(r.map.apply(Point::new(72.0, 0.0)), Point::new(25.4, 25.4));
    }

    #[test]
    fn preserve_aspect_ratio_centres_or_stretches() {
        // 200 × 100 px viewport, 200 × 200 box: meet scales by 0.5 and
        // centres x (50 px in); none stretches y only.
        let m = view_box_map(
            &ViewBox::new(0.0, 0.0, 200.0, 200.0),
            (0.0, 0.0, 200.0, 100.0),
            AspectRatio::default(),
        );
        close(m.apply(Point::new(0.0, 0.0)), Point::new(50.0, 0.0));
        close(m.apply(Point::new(200.0, 200.0)), Point::new(150.0, 100.0));
        let none = AspectRatio::from_str("none").unwrap();
        let m = view_box_map(
            &ViewBox::new(0.0, 0.0, 200.0, 200.0),
            (0.0, 0.0, 200.0, 100.0),
            none,
        );
        close(m.apply(Point::new(200.0, 200.0)), Point::new(200.0, 100.0));
        let slice = AspectRatio::from_str("xMinYMin slice").unwrap();
        let m = view_box_map(
            &ViewBox::new(-100.0, -50.0, 200.0, 200.0),
            (0.0, 0.0, 200.0, 100.0),
            slice,
        );
        close(m.apply(Point::new(-100.0, -50.0)), Point::new(0.0, 0.0));
        close(m.apply(Point::new(0.0, 0.0)), Point::new(100.0, 50.0));
    }

    #[test]
    fn a_zero_view_box_is_refused_and_said() {
        let r = root_of(
            r#"<svg width="10mm" height="10mm" viewBox="0 0 0 10"/>"#,
            PX_MM,
        );
        assert_eq!(r.bad_view_box.as_deref(), Some("0 0 0 10"));
        assert!(r.px_scaled);
    }

    #[test]
    fn lengths_convert_through_the_px() {
        let mm = |s: &str| user_length(Length::from_str(s).unwrap(), PX_MM, 200.0).unwrap();
        assert!((mm("25.4mm") - 96.0).abs() < 1e-9);
        assert!((mm("1in") - 96.0).abs() < 1e-9);
        assert!((mm("50%") - 100.0).abs() < 1e-9);
        assert!((mm("3") - 3.0).abs() < 1e-12);
    }
}
