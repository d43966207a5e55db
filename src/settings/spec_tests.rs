//! `Spec::build`: the page's wire names, bad names, materials, the post's rapid.

use super::*;
use crate::gcode::preset;
use crate::geom::Point;
use crate::kerf::Join;
use crate::materials::Library;
use crate::origin::ProgramOrigin;
use crate::plan::LeadKind;
use crate::plan::Order;
use crate::settings::{Settings, DEFAULT_RAPID};
use crate::warning::Lang;

#[test]
fn the_default_spec_is_the_everyday_settings() {
    let s = Spec::default().build().unwrap();
    let plain = Settings::new(1.5, 0.001, 2000.0).unwrap();
    assert_eq!(s.kerf(), plain.kerf());
    assert_eq!(s.process(), plain.process());
    assert_eq!(s.decimals(), plain.decimals());
    assert_eq!(s.process.rapid, DEFAULT_RAPID);
    assert_eq!(s.plan().order, Order::Contour);
    assert!(s.material().is_none());
}

#[test]
fn the_page_wire_names_fill_the_spec() {
    // What www/job.js sends, by name (serde_json stands for the page).
    let spec: Spec = serde_json::from_str(
        r#"{"kerf": 2, "feed": 1500, "order": "chained", "lead": "arc",
            "starts": [[3, 10, 20], [-1, 0, 0]], "origin": "point",
            "origin_point": [5, 6], "layer_ops": [["ETCH", "mark"]],
            "decimals": 4, "join": "miter", "lang": "pt-BR"}"#,
    )
    .unwrap();
    let s = spec.build().unwrap();
    assert_eq!(s.kerf().width, 2.0);
    assert_eq!(s.kerf().join, Join::Miter);
    assert_eq!(s.process().feed, 1500.0);
    assert_eq!(s.plan().order, Order::Chained);
    assert_eq!(s.plan().leads.kind, LeadKind::Arc);
    // The click on nothing (-1) is dropped; the contour number is not
    // trusted: the point takes the loop nearest it.
    assert_eq!(
        s.plan().starts,
        vec![crate::plan::choice::Pick::near(
            Point::new(10.0, 20.0),
            super::LEGACY_REACH_MM
        )]
    );
    assert_eq!(s.origin(), ProgramOrigin::Point(Point::new(5.0, 6.0)));
    assert_eq!(s.decimals(), 4);
    assert_eq!(s.lang(), Lang::PtBr);
}

#[test]
fn every_bad_name_names_its_field() {
    let bad = |edit: fn(&mut Spec)| {
        let mut s = Spec::default();
        edit(&mut s);
        s.build().unwrap_err().field
    };
    assert_eq!(bad(|s| s.order = "spiral".into()), "order");
    assert_eq!(bad(|s| s.euler_mode = "x".into()), "euler_mode");
    assert_eq!(bad(|s| s.lead = "loop".into()), "lead");
    assert_eq!(bad(|s| s.outer_dir = "up".into()), "outer_dir");
    assert_eq!(bad(|s| s.join = "bevel".into()), "join");
    assert_eq!(bad(|s| s.post = Some("fanuc-9000".into())), "post");
    assert_eq!(bad(|s| s.post_json = Some("{".into())), "post");
    assert_eq!(bad(|s| s.units = Some("furlong".into())), "units");
    assert_eq!(bad(|s| s.origin = "middle".into()), "origin");
    assert_eq!(
        bad(|s| s.layer_ops = vec![["A".into(), "weld".into()]]),
        "layer_ops"
    );
    assert_eq!(bad(|s| s.decimals = 9), "decimals");
    assert_eq!(bad(|s| s.kerf = Some(-1.0)), "kerf");
    assert_eq!(
        bad(|s| s.material_name = Some("unobtainium".into())),
        "material"
    );
    // A broken chart is said even when no entry is chosen from it.
    assert_eq!(
        bad(|s| s.materials = Some("{\"entries\": 3}".into())),
        "materials"
    );
}

#[test]
fn a_material_fills_what_is_not_given_and_given_values_win() {
    let lib = Library::starter();
    let e = &lib.entries[0];
    let chosen = Spec {
        material_name: Some(e.name.clone()),
        ..Spec::default()
    };
    let s = chosen.build().unwrap();
    assert_eq!(s.kerf().width, e.kerf);
    assert_eq!(s.process().feed, e.feed);
    assert_eq!(s.process().pierce_delay, e.pierce_delay);
    assert_eq!(
        s.material().map(|m| (m.name.as_str(), m.example)),
        Some((e.name.as_str(), e.example))
    );
    let typed = Spec {
        kerf: Some(0.5),
        feed: Some(999.0),
        ..chosen
    }
    .build()
    .unwrap();
    assert_eq!(typed.kerf().width, 0.5);
    assert_eq!(typed.process().feed, 999.0);
    assert_eq!(typed.process().pierce_delay, e.pierce_delay);
}

#[test]
fn the_post_gives_the_rapid_unless_one_is_given() {
    let post = preset("qtplasmac").unwrap();
    let s = Spec {
        post: Some("qtplasmac".into()),
        ..Spec::default()
    };
    assert_eq!(s.clone().build().unwrap().process.rapid, post.rapid_speed);
    let given = Spec {
        rapid: Some(1234.0),
        ..s
    };
    assert_eq!(given.build().unwrap().process.rapid, 1234.0);
}

#[test]
fn the_pages_chosen_entry_wins_over_the_fields() {
    let lib = Library::starter();
    let mut e = lib.entries[0].clone();
    e.number = Some(4);
    let spec = Spec {
        // The page sends the fields too (shown locked with the entry's values).
        kerf: Some(9.0),
        material: Some(serde_json::to_string(&e).unwrap()),
        ..Spec::default()
    };
    let s = spec.build().unwrap();
    assert_eq!(s.kerf().width, e.kerf);
    assert_eq!(s.process().feed, e.feed);
    assert_eq!(s.process().material, 4);
    assert_eq!(s.material().map(|m| m.name.as_str()), Some(e.name.as_str()));
    // A broken entry names the field.
    let bad = Spec {
        material: Some("{".into()),
        ..Spec::default()
    };
    assert_eq!(bad.build().unwrap_err().field, "material");
}
