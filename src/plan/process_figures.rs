//! What the plan stage makes of the process's figures: the verification
//! said as a warning. Here, not in
//! `process`, so that `process` (read by the plan) does not read the plan
//! back (issue 15 §6).

use super::Verification;
use crate::text;
use crate::warning::{dec, Warning};

impl Verification {
    /// What the verification found, as one warning (None when the cut is clean).
    pub fn warning(&self) -> Option<Warning> {
        let v = self;
        let (area, depth, n) = (v.overcut_mm2, v.max_overcut_mm, v.parts_not_freed);
        let mut w = if area > 0.0 || depth > 0.0 {
            let cell = (v.cell * 1000.0).round() / 1000.0;
            let parts = v.parts.len();
            Warning::new(
                "verify-overcut",
                text!("the swept kerf takes {area:.2} mm² of part material from {parts} part(s), up to {depth:.3} mm past a drawn edge{}{}",
                      if n > 0 { format!("; {n} part(s) not cut free (part {} first)", v.first_not_freed.unwrap_or(0)) } else { String::new() },
                      if v.area_coarsened { format!(" (at most: every {cell} mm cell the kerf reaches counted, too much overcut to count finer)") } else { String::new() };
                      "a sangria varrida remove {} mm² de material de {parts} peça(s), até {} mm além de uma aresta desenhada{}{}",
                      dec(area), dec(depth),
                      if n > 0 { format!("; {n} peça(s) não soltas (a peça {} primeiro)", v.first_not_freed.unwrap_or(0)) } else { String::new() },
                      if v.area_coarsened { format!(" (no máximo: contada cada célula de {} mm que a sangria alcança, sobrecorte demais para contar mais fino)", dec(cell)) } else { String::new() }),
            )
        } else if n > 0 {
            let first = v.first_not_freed.unwrap_or(0);
            Warning::new(
                "verify-not-freed",
                text!("{n} part(s) not cut free all round (part {first} first): the kerf does not reach every point of their outline";
                      "{n} peça(s) não soltas por completo (a peça {first} primeiro): a sangria não alcança todo o contorno"),
            )
        } else {
            return None;
        };
        if let Some(p) = v.deepest_at {
            w.at = Some(p);
        }
        Some(w)
    }
}
