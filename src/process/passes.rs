//! Multi-pass depth (issue 20 §8; paper 004, notes-004 §5.1 item 6, thesis
//! L999–L1003): material of thickness H cut by a tool that takes at most
//! d_max per pass is cut in n = ceil(H / d_max) passes of equal depth
//! d = H / n, at Z = -d, -2d, … -H. For knife, router and thick laser or
//! waterjet cuts; off (one pass, no Z word) unless both are given.

/// The job's depth: material thickness and the deepest pass, mm.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Passes {
    /// Material thickness H, mm; 0 = off.
    pub depth: f64,
    /// Deepest pass d_max, mm; 0 = off.
    pub pass_depth: f64,
}

impl Passes {
    /// Off: every contour cut once, as before, with no Z word.
    pub const OFF: Passes = Passes {
        depth: 0.0,
        pass_depth: 0.0,
    };
    /// True when the job is cut in depth passes (both values given).
    pub fn on(&self) -> bool {
        self.depth > 0.0 && self.pass_depth > 0.0
    }
    /// n = ceil(H / d_max) (1 when off). A hair of rounding (10 mm in
    /// 2.5 mm passes computed as 4.000000001) does not add a pass.
    pub fn count(&self) -> usize {
        if !self.on() {
            return 1;
        }
        ((self.depth / self.pass_depth) - 1e-9)
            .ceil()
            .clamp(1.0, 1000.0) as usize
    }
    /// Z of pass `k` (1-based): -k·H/n, the last exactly -H.
    pub fn z(&self, k: usize) -> f64 {
        let n = self.count();
        if k >= n {
            -self.depth
        } else {
            -self.depth * k as f64 / n as f64
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn passes_follow_paper_004() {
        // The thesis's Case 3: H = 64.8, d_max = 15 → 5 planes of 12.96.
        let p = Passes {
            depth: 64.8,
            pass_depth: 15.0,
        };
        assert_eq!(p.count(), 5);
        assert!((p.z(1) + 12.96).abs() < 1e-9);
        assert_eq!(p.z(5), -64.8);
        let q = Passes {
            depth: 10.0,
            pass_depth: 4.0,
        };
        assert_eq!(q.count(), 3);
        assert!((q.z(2) + 20.0 / 3.0).abs() < 1e-12);
        let exact = Passes {
            depth: 10.0,
            pass_depth: 2.5,
        };
        assert_eq!(exact.count(), 4);
        assert_eq!(Passes::OFF.count(), 1);
        assert!(!Passes {
            depth: 5.0,
            pass_depth: 0.0
        }
        .on());
    }
}
