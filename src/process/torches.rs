//! Several torches on one gantry (issue 18 §7; paper 001 §6.5, notes-001
//! L437–L441, L1263–L1270, L1564–L1566, L2825–L2828).
//!
//! Identical parts are laid out across the sheet's width (Y), one row per
//! torch, the torches a fixed distance apart. The program is single-path:
//! "for the NC everything happens as if only one torch were working"; it
//! drives torch 1 and the others cut the same moves that distance further
//! in Y. So the nest is made for the band under torch 1 and every copy
//! there is implied under the others, and the program says so in a
//! comment. When the torch setup has to be changed by hand, the thesis's
//! program parks the gantry and stops for the operator (`M0`, "PARADA
//! PARA AJUSTES NOS MACARICOS"; its post has a "Y coordinate for torch
//! change", L2320): [`Torches::park`].

use crate::geom::Point;
use crate::settings_error::SettingsError;
use crate::text;
use crate::warning::dec;

/// Most torches on one gantry (the thesis's example has 4).
pub const MAX_TORCHES: usize = 16;

/// The torches cutting one program.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Torches {
    /// How many cut at once (≥ 2; one torch is no setup at all).
    pub count: usize,
    /// Distance between neighbouring torches along Y, mm.
    pub spacing: f64,
    /// Where the gantry parks for the operator to set the torches, in
    /// program coordinates, before the first cut (`M0`); None: no stop.
    pub park: Option<Point>,
}

impl Torches {
    /// A checked setup; `count` 1 is no setup (None).
    pub fn new(
        count: usize,
        spacing: f64,
        park: Option<Point>,
    ) -> Result<Option<Torches>, SettingsError> {
        let bad = |field, reason| Err(SettingsError { field, reason });
        if count == 0 || count > MAX_TORCHES {
            return bad(
                "torches",
                text!("{count} torches: between 1 and {MAX_TORCHES}"; "{count} tochas: entre 1 e {MAX_TORCHES}"),
            );
        }
        if count == 1 {
            return Ok(None);
        }
        if !(spacing.is_finite() && spacing > 0.0 && spacing <= 100_000.0) {
            return bad(
                "torch_spacing",
                text!("{spacing} mm is not a distance between torches (0 to 100000 mm)";
                      "{} mm não é uma distância entre tochas (0 a 100000 mm)", dec(spacing)),
            );
        }
        if let Some(p) = park {
            if !(p.x.is_finite() && p.y.is_finite() && p.x.abs() <= 1e6 && p.y.abs() <= 1e6) {
                return bad(
                    "torch_park",
                    text!("the park position is not a point on the table"; "a posição de estacionamento não é um ponto da mesa"),
                );
            }
        }
        Ok(Some(Torches {
            count,
            spacing,
            park,
        }))
    }
    /// How far torch `k` (0-based; 0 is the programmed one) cuts from
    /// torch 1, mm along Y.
    pub fn offset(&self, k: usize) -> f64 {
        k as f64 * self.spacing
    }
    /// Copies to place under torch 1 so that all torches together make at
    /// least `quantity`: ceil(quantity / count).
    pub fn per_torch(&self, quantity: usize) -> usize {
        quantity.div_ceil(self.count)
    }
    /// The program's comment line naming the setup (a program's numbers:
    /// decimal point in every language).
    pub fn comment(&self) -> String {
        let (n, d) = (self.count, self.spacing);
        let others = if n == 2 {
            format!("torch 2 cuts the same moves {d} mm further in Y")
        } else {
            format!("torches 2 to {n} cut the same moves at {d} mm steps in Y")
        };
        format!("{n} torches {d} mm apart in Y: this program drives torch 1, {others}")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn one_torch_is_no_setup_and_bad_values_are_refused() {
        assert_eq!(Torches::new(1, 0.0, None), Ok(None));
        let t = Torches::new(3, 500.0, None).unwrap().unwrap();
        assert_eq!((t.offset(0), t.offset(2)), (0.0, 1000.0));
        // 10 copies on 3 torches: 4 under torch 1, 12 made.
        assert_eq!(t.per_torch(10), 4);
        assert_eq!(t.per_torch(9), 3);
        for (n, d) in [(0, 500.0), (17, 500.0), (2, 0.0), (2, f64::NAN), (2, -3.0)] {
            assert!(Torches::new(n, d, None).is_err(), "{n} × {d}");
        }
        let far = Some(Point::new(f64::INFINITY, 0.0));
        assert_eq!(Torches::new(2, 500.0, far).unwrap_err().field, "torch_park");
        assert!(t.comment().starts_with("3 torches 500 mm apart"));
    }
}
