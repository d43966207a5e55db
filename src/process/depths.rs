//! A milling layer's own depth (issue 43 §1: each operation has its depth,
//! pass depth and climb or conventional): a sign's lettering pocketed
//! 3 mm deep in the program that profiles its outline through the board.
//! A layer not given one is milled at the job's [`super::Process::passes`]
//! and direction ([`super::Tool::climb`]).

use super::Passes;

/// A layer's depth, its passes and its direction.
#[derive(Clone, Debug, PartialEq)]
pub struct LayerDepth {
    /// Layer name (compared without case).
    pub layer: String,
    /// Its depth H and deepest pass d_max (n = ceil(H / d_max)).
    pub passes: Passes,
    /// Climb (true) or conventional (false) finishing passes.
    pub climb: bool,
}

/// The layers given their own depth; the last given for a layer wins,
/// as `--layer-op`.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct LayerDepths {
    /// In the order given.
    pub given: Vec<LayerDepth>,
}

impl LayerDepths {
    /// True when every layer is milled at the job's depth.
    pub fn is_empty(&self) -> bool {
        self.given.is_empty()
    }
    /// The depth given to `layer`, if one is.
    pub fn of(&self, layer: &str) -> Option<&LayerDepth> {
        let want = crate::case::lower(layer.trim());
        (self.given.iter().rev()).find(|d| crate::case::lower(d.layer.trim()) == want)
    }
    /// `layer`'s passes and direction: its own, else the job's.
    pub fn cut_of(&self, layer: &str, job: Passes, climb: bool) -> (Passes, bool) {
        self.of(layer).map_or((job, climb), |d| (d.passes, d.climb))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_layers_depth_is_found_without_case_the_last_given_winning() {
        let job = Passes {
            depth: 18.0,
            pass_depth: 6.0,
        };
        let given = |h: f64| LayerDepth {
            layer: "Letters".into(),
            passes: Passes {
                depth: h,
                pass_depth: 1.5,
            },
            climb: false,
        };
        let d = LayerDepths {
            given: vec![given(2.0), given(3.0)],
        };
        let (p, climb) = d.cut_of(" LETTERS ", job, true);
        assert_eq!((p.depth, p.count(), climb), (3.0, 2, false));
        assert_eq!(d.cut_of("OUTLINE", job, true), (job, true));
    }
}
