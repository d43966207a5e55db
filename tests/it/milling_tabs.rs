//! A router's tabs leave a bridge at the bottom (issue 43 §3): with a tab
//! height H_t, the passes deeper than depth − H_t go up to depth − H_t
//! over each tab and cut across it there; the passes above cut through.
//! Read back from the program's text alone (`common::program_xy`).
#![cfg(not(target_arch = "wasm32"))]

use crate::common;

use common::program_xy::read;
use kerfcam::plan::Role;
use kerfcam::Spec;

fn plate() -> Vec<u8> {
    let mut e = "0\nLWPOLYLINE\n8\nPROFILE\n90\n4\n70\n1\n".to_string();
    for (x, y) in [(0.0, 0.0), (100.0, 0.0), (100.0, 60.0), (0.0, 60.0)] {
        e += &format!("10\n{x}\n20\n{y}\n");
    }
    format!("0\nSECTION\n2\nHEADER\n9\n$INSUNITS\n70\n4\n0\nENDSEC\n0\nSECTION\n2\nENTITIES\n{e}0\nENDSEC\n0\nEOF\n").into_bytes()
}

fn spec(tab_height: f64) -> Spec {
    Spec {
        tool_diameter: Some(6.0),
        depth: Some(6.0),
        pass_depth: 2.0,
        post: Some("grbl-router".into()),
        layer_ops: vec![["PROFILE".into(), "profile".into()]],
        tabs: 2,
        tab_width: 8.0,
        tab_height,
        ..Spec::default()
    }
}

#[test]
fn a_router_tab_with_a_height_is_a_bridge_at_the_bottom_the_passes_above_cut_through() {
    for (h, post) in [(3.0, "grbl-router"), (1.0, "linuxcnc-router"), (0.0, "grbl-router")] {
        let mut s = spec(h);
        s.post = Some(post.into());
        s.incremental = post == "linuxcnc-router";
        let settings = s.build().unwrap();
        let out = kerfcam::run(&plate(), &settings).unwrap();
        let errors = common::rs274_errors(&out.gcode, &format!("milling-tab-height-{h}"));
        assert!(errors.is_empty(), "{h}: {errors:?}");
        let moves = read(&out.gcode, 15.0);
        // Where the tabs are (the plan's), and a point of the contour
        // away from them.
        let tabs: Vec<(f64, f64)> = (out.plan.cuts.iter().flat_map(|c| &c.steps))
            .filter(|s| s.role == Role::Tab)
            .map(|s| {
                let m = s.segment.point_at(0.5);
                (m.x, m.y)
            })
            .collect();
        assert_eq!(tabs.len(), 2, "{h}");
        // The lowest a feed move goes over a point, and the depths of the
        // feed moves over it.
        let over = |p: (f64, f64)| {
            let mut zs: Vec<f64> = (moves.iter())
                .filter(|m| !m.rapid && m.z.0 == m.z.1 && m.z.0 < 0.0 && m.dist(p) < 1e-3)
                .map(|m| m.z.0)
                .collect();
            zs.sort_by(f64::total_cmp);
            zs.dedup();
            zs
        };
        let off_tab = over((-3.0, 30.0));
        assert_eq!(off_tab, [-6.0, -4.0, -2.0], "{h}: the contour away from the tabs");
        for t in &tabs {
            let zs = over(*t);
            eprintln!("tab height {h} ({post}): feed moves over the tab at {t:?} at Z {zs:?}");
            let want: &[f64] = match h {
                // Pass 1 (Z -2) cuts through; passes 2 and 3 cross at -3.
                3.0 => &[-3.0, -2.0],
                // Passes 1 and 2 cut through; pass 3 crosses at -5.
                1.0 => &[-5.0, -4.0, -2.0],
                // No height: the tool lifts out over the tab on every pass.
                _ => &[],
            };
            assert_eq!(zs, want, "{h}: over the tab at {t:?}");
        }
    }
}
