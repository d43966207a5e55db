//! Tests of `gcode::number`.

use super::*;

/// The text `Grid::push` must write, by `format!` (independent of it).
fn reference(v: i64, decimals: u32, zeros: bool) -> String {
    let unit = 10u64.pow(decimals);
    let a = v.unsigned_abs();
    let sign = if v < 0 { "-" } else { "" };
    let frac = format!("{:0w$}", a % unit, w = decimals as usize);
    let frac = if zeros {
        frac.as_str()
    } else {
        frac.trim_end_matches('0')
    };
    if frac.is_empty() {
        format!("{sign}{}", a / unit)
    } else {
        format!("{sign}{}.{frac}", a / unit)
    }
}

#[test]
fn push_writes_what_format_writes() {
    let mut x: u64 = 0x2545_F491_4F6C_DD1D;
    for d in 1..=6 {
        for zeros in [false, true] {
            let g = Grid::new(d).with_trailing_zeros(zeros);
            for k in 0..4000 {
                x = crate::test_rng::Xorshift(x).next();
                // Every magnitude, small ones often, and the extremes.
                let v = match k {
                    0 => i64::MIN,
                    1 => i64::MAX,
                    2 => 0,
                    _ => (x as i64) >> (x % 64),
                };
                let want = reference(v, d, zeros);
                assert_eq!(g.fmt(v), want, "{v} at {d} decimals");
                // The bytes path: after other text, and followed by more.
                let mut b = Bytes::from_vec(b"X".to_vec());
                g.push_bytes(&mut b, v);
                b.push(b' ');
                assert_eq!(b.into_vec(), format!("X{want} ").into_bytes());
            }
        }
    }
    let mut n = Bytes::default();
    push_u64_bytes(&mut n, 0);
    push_u64_bytes(&mut n, u64::MAX);
    assert_eq!(n.into_vec(), format!("0{}", u64::MAX).into_bytes());
}

#[test]
fn round_i64_is_round_as_i64() {
    let mut x: u64 = 0x9E37_79B9_7F4A_7C15;
    let mut edge = vec![
        0.0,
        -0.0,
        0.5,
        -0.5,
        1.5,
        -2.5,
        0.49999999999999994,
        -0.49999999999999994,
        4503599627370495.5,
        -4503599627370495.5,
        9007199254740993.0,
        9.223372036854775e18,
        -9.223372036854775e18,
        9.3e18,
        -9.3e18,
        1e300,
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::NAN,
        f64::MIN_POSITIVE,
    ];
    for _ in 0..200_000 {
        x = crate::test_rng::Xorshift(x).next();
        // Halves and near-halves at every magnitude, and raw bit patterns.
        let m = ((x >> 11) as f64 / (1u64 << 53) as f64 - 0.5) * 10f64.powi((x % 22) as i32);
        edge.push(m);
        edge.push((m * 2.0).round() / 2.0);
        edge.push(f64::from_bits(x));
    }
    for v in edge {
        assert_eq!(round_i64(v), v.round() as i64, "{v:e}");
    }
}

/// The centre search without the pruning: every one of the 49 points.
fn full_scan(start: (i64, i64), end: (i64, i64), c0: (i64, i64)) -> Option<(i64, i64)> {
    let mut best: Option<(f64, f64, (i64, i64))> = None;
    for dx in -CENTRE_SEARCH..=CENTRE_SEARCH {
        for dy in -CENTRE_SEARCH..=CENTRE_SEARCH {
            let q = (c0.0 + dx, c0.1 + dy);
            let r = |p: (i64, i64)| {
                (((p.0 - q.0) as f64).powi(2) + ((p.1 - q.1) as f64).powi(2)).sqrt()
            };
            let diff = (r(start) - r(end)).abs();
            let moved = ((dx * dx + dy * dy) as f64).sqrt();
            if best.is_none_or(|(bd, bm, _)| diff < bd - 1e-9 || (diff <= bd + 1e-9 && moved < bm))
            {
                best = Some((diff, moved, q));
            }
        }
    }
    let (diff, _, q) = best?;
    (diff <= 1.0 && q != start).then_some((q.0 - start.0, q.1 - start.1))
}

#[test]
fn pruned_centre_search_picks_what_the_full_scan_picks() {
    let mut f = crate::test_rng::unit(77);
    for d in [1, 3, 4, 6] {
        let g = Grid::new(d);
        for _ in 0..3000 {
            // Arcs of every size and sweep, centres on and off the grid,
            // some axis-aligned (ties along a grid line).
            let r = 10f64.powf(f() * 6.0 - 2.0);
            let c = Point::new((f() - 0.5) * 2000.0, (f() - 0.5) * 2000.0);
            // A third on round numbers: the centre and radius on the grid
            // (the nearest point's radii agree: the search's shortcut).
            let (r, c) = if f() < 0.33 {
                let on = |v: f64| (v * g.scale()).round() / g.scale();
                (on(r).max(g.step()), Point::new(on(c.x), on(c.y)))
            } else {
                (r, c)
            };
            let (a0, sweep) = if f() < 0.3 {
                (
                    (f() * 4.0).floor() * std::f64::consts::FRAC_PI_2,
                    std::f64::consts::PI * (1.0 + (f() * 2.0).floor()) / 2.0,
                )
            } else {
                (
                    f() * std::f64::consts::TAU,
                    (f() - 0.5) * 2.0 * std::f64::consts::PI,
                )
            };
            let at = |t: f64| g.snap(Point::new(c.x + r * t.cos(), c.y + r * t.sin()));
            let (s, e) = (at(a0), at(a0 + sweep));
            assert_eq!(
                g.arc_center(s, e, c),
                full_scan(s, e, g.snap(c)),
                "r {r} at {d} decimals"
            );
        }
    }
}

#[test]
fn formats_without_noise() {
    let g = Grid::new(3);
    assert_eq!(g.fmt(0), "0");
    assert_eq!(g.fmt(-1), "-0.001");
    assert_eq!(g.fmt(12_500), "12.5");
    assert_eq!(g.fmt(-40_000), "-40");
    assert_eq!(g.fmt_mm(-0.0001), "0");
    let z = Grid::new(1).with_trailing_zeros(true);
    assert_eq!(z.fmt(100), "10.0");
    assert_eq!(z.fmt(0), "0.0");
    assert_eq!(z.fmt(-5), "-0.5");
    assert_eq!(g.fmt(i64::MIN + 1), "-9223372036854775.807");
    assert_eq!(Grid::new(6).fmt(1_000_001), "1.000001");
    assert_eq!(Grid::new(6).fmt(1_100_000), "1.1");
    assert_eq!(
        Grid::new(6).with_trailing_zeros(true).fmt(1_100_000),
        "1.100000"
    );
}

#[test]
fn no_number_prints_as_minus_zero_nan_exponent_or_comma() {
    // A deterministic sweep over awkward values (property test).
    let mut x: u64 = 0x9E37_79B9_7F4A_7C15;
    for d in 1..=6 {
        let g = Grid::new(d);
        for _ in 0..2000 {
            x = crate::test_rng::Xorshift(x).next();
            let mag = 10f64.powi((x % 20) as i32 - 10);
            let v = ((x >> 11) as f64 / (1u64 << 53) as f64 - 0.5) * mag;
            for s in [
                g.fmt_mm(v),
                g.fmt_mm(-v),
                g.fmt_mm(f64::NAN),
                g.fmt_mm(1e300),
            ] {
                assert!(s.parse::<f64>().is_ok(), "{s}");
                assert!(!s.contains(['e', 'E', ',', 'N', 'i']), "{s}");
                assert!(s
                    .chars()
                    .all(|c| c.is_ascii_digit() || c == '-' || c == '.'));
                if let Some(rest) = s.strip_prefix('-') {
                    assert!(rest.chars().any(|c| ('1'..='9').contains(&c)), "{s}");
                }
            }
        }
    }
}

#[test]
fn arc_centre_keeps_both_radii_within_a_step() {
    let g = Grid::new(3);
    // Quarter circle r = 7.0711 from an awkward angle.
    let c = Point::new(1.23456, -2.34567);
    let r = 7.07107;
    let a = Point::new(c.x + r * 0.3f64.cos(), c.y + r * 0.3f64.sin());
    let b = Point::new(c.x + r * 1.9f64.cos(), c.y + r * 1.9f64.sin());
    let (s, e) = (g.snap(a), g.snap(b));
    let (i, j) = g.arc_center(s, e, c).unwrap();
    let q = (s.0 + i, s.1 + j);
    let rs = (((s.0 - q.0) as f64).powi(2) + ((s.1 - q.1) as f64).powi(2)).sqrt();
    let re = (((e.0 - q.0) as f64).powi(2) + ((e.1 - q.1) as f64).powi(2)).sqrt();
    assert!((rs - re).abs() <= 1.0);
}
