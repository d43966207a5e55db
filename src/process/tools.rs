//! A router job's tool list (issue 43 §1: each operation with its tool):
//! the job's own tool ([`super::Process::tool`], cutting at
//! [`super::Process::feed`]) and the others, each milling layer given
//! one of them by number. Profiles are cut with the job's tool (its
//! diameter is the kerf the profiles are offset by), so the job's tool
//! works last: every pocket, engraving and hole — whatever its tool — is
//! machined before a profile frees a part.
//!
//! A tool of the list takes the job's tool's pocketing choices (strategy,
//! entry, allowance…) and has its own number, diameter, V angle, stepover,
//! feeds and spindle speed: what a shop's tool table holds.

use super::Tool;

/// A tool and its cutting feed, mm/min.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MillTool {
    /// The end mill, its number, speeds and pocketing choices.
    pub tool: Tool,
    /// Feed of moves across material, mm/min.
    pub feed: f64,
}

/// The job's tools beside its own, and the milling layers they take.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Tools {
    /// The other tools, in the order they work (before the job's tool).
    pub others: Vec<MillTool>,
    /// Layer name (compared without case) and the number of its tool.
    pub layers: Vec<(String, u32)>,
}

impl Tools {
    /// True when every layer is the job's tool's.
    pub fn is_empty(&self) -> bool {
        self.others.is_empty() && self.layers.is_empty()
    }
    /// The number of the tool given to `layer`, if one is (the last given
    /// wins, as `--layer-op`).
    pub fn number_of(&self, layer: &str) -> Option<u32> {
        let want = crate::case::lower(layer.trim());
        (self.layers.iter().rev())
            .find(|(l, _)| crate::case::lower(l.trim()) == want)
            .map(|(_, n)| *n)
    }
    /// The listed tool numbered `n`.
    pub fn get(&self, n: u32) -> Option<&MillTool> {
        self.others.iter().find(|t| t.tool.number == n)
    }
}
