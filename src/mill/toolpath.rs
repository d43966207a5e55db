//! The router's program before any dialect: moves in X, Y and Z, each
//! knowing whether it goes down into material (the plunge feed) or cuts
//! across (the feed). What `gcode::router` writes, and what the report
//! counts.

use crate::geom::{Point, Segment};

/// One move of the tool.
#[derive(Clone, Debug, PartialEq)]
pub enum MillMove {
    /// Rapid in X and Y at the current height.
    Rapid(Point),
    /// Rapid to a height (up, or down to just above cleared material).
    RapidZ(f64),
    /// Straight down (or up) at the plunge feed.
    Plunge(f64),
    /// Along `seg` (a line or an arc in X and Y) while Z goes linearly to
    /// `z`: flat at the cutting feed, descending (a ramp, a helix) at the
    /// plunge feed.
    Cut {
        /// The path in X and Y.
        seg: Segment,
        /// Height at the end.
        z: f64,
    },
    /// A comment in the program (our own words and numbers only).
    Note(String),
    /// The moves after it are cut with this tool (issue 43 §1): the
    /// spindle stopped, the tool changed, the spindle started again, the
    /// tool back at the retract height where the one before left it. The
    /// first of a job is its header's tool, changed to before any move.
    ToolChange(crate::process::MillTool),
}

/// The moves of a milling job and what they add up to.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Toolpath {
    /// Where the tool is before the first move (the program's origin, at
    /// the retract height): what the first rapid is measured and drawn from.
    pub start: Point,
    /// The moves, in order, from the retract height at `start`.
    pub moves: Vec<MillMove>,
    /// Times the tool came up inside a pocket's depth to reach the next
    /// pass (an island or a wall in the way).
    pub lifts: usize,
}

/// Builds a [`Toolpath`], tracking where the tool is.
#[derive(Clone, Debug)]
pub(crate) struct Builder {
    pub(crate) path: Toolpath,
    pub(crate) at: Point,
    pub(crate) z: f64,
    /// Height the tool moves at between places, above the stock.
    pub(crate) retract: f64,
}

impl Builder {
    pub(crate) fn new(at: Point, retract: f64) -> Builder {
        Builder {
            path: Toolpath {
                start: at,
                ..Toolpath::default()
            },
            at,
            z: retract,
            retract,
        }
    }
    pub(crate) fn note(&mut self, text: String) {
        self.path.moves.push(MillMove::Note(text));
    }
    /// Up to the retract height (if below it).
    pub(crate) fn up(&mut self) {
        if self.z < self.retract {
            self.path.moves.push(MillMove::RapidZ(self.retract));
            self.z = self.retract;
        }
    }
    /// Up, across to `p`, and down at rapid to `z` (above material).
    pub(crate) fn travel(&mut self, p: Point, z: f64) {
        self.up();
        if p.dist(self.at) > 0.0 {
            self.path.moves.push(MillMove::Rapid(p));
            self.at = p;
        }
        if z < self.z {
            self.path.moves.push(MillMove::RapidZ(z));
            self.z = z;
        }
    }
    /// Straight down to `z` at the plunge feed.
    pub(crate) fn plunge(&mut self, z: f64) {
        if z != self.z {
            self.path.moves.push(MillMove::Plunge(z));
            self.z = z;
        }
    }
    /// Along `seg` (from where the tool is) to height `z`.
    pub(crate) fn cut(&mut self, seg: Segment, z: f64) {
        if seg.a.dist(seg.b) == 0.0 && z == self.z {
            return;
        }
        self.at = seg.b;
        self.z = z;
        self.path.moves.push(MillMove::Cut { seg, z });
    }
    /// A straight cut to `p` at the current height.
    pub(crate) fn line_to(&mut self, p: Point) {
        let z = self.z;
        self.cut(Segment::line(self.at, p), z);
    }
}

/// Lengths and counts of a toolpath.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct MillStats {
    /// Cutting moves at the feed, mm.
    pub cut_mm: f64,
    /// Moves into material at the plunge feed (plunges, ramps, helices), mm.
    pub plunge_mm: f64,
    /// Rapid moves, X/Y and Z, mm.
    pub rapid_mm: f64,
    /// Moves (not counting notes).
    pub moves: usize,
}

impl MillStats {
    /// Machine time, s: cutting moves at the job's feed, moves into
    /// material at the tool's plunge feed, rapids at the rapid speed — the
    /// feeds the router post writes (src/gcode/router.rs).
    pub fn time_s(&self, p: &crate::process::Process) -> f64 {
        60.0 * (self.cut_mm / p.feed.max(1e-9)
            + self.plunge_mm / p.tool.plunge_feed.max(1e-9)
            + self.rapid_mm / p.rapid.max(1e-9))
    }
    /// Both counts added: one tool's work at two depths.
    pub fn plus(&self, o: &MillStats) -> MillStats {
        MillStats {
            cut_mm: self.cut_mm + o.cut_mm,
            plunge_mm: self.plunge_mm + o.plunge_mm,
            rapid_mm: self.rapid_mm + o.rapid_mm,
            moves: self.moves + o.moves,
        }
    }
    /// [`MillStats::time_s`] with `tool` (None: the job's own) at its feeds.
    pub fn time_with(
        &self,
        p: &crate::process::Process,
        tool: Option<&crate::process::MillTool>,
    ) -> f64 {
        match tool {
            Some(t) => self.time_s(&crate::process::Process {
                feed: t.feed,
                tool: t.tool,
                ..*p
            }),
            None => self.time_s(p),
        }
    }
}

impl Toolpath {
    /// Where the tool is after the last move, in X and Y (`start` when
    /// there is none): where the profiles after it are reached from.
    pub fn end(&self) -> Point {
        let mut at = self.start;
        for m in &self.moves {
            match m {
                MillMove::Rapid(p) => at = *p,
                MillMove::Cut { seg, .. } => at = seg.b,
                _ => {}
            }
        }
        at
    }
    /// Lengths and counts, from the safe height `start_z` at `from`.
    pub fn stats(&self, from: Point, start_z: f64) -> MillStats {
        stats_of(&self.moves, from, start_z).0
    }
    /// The moves in runs of one tool ([`MillMove::ToolChange`]), each with
    /// its tool (None before the first change: the job's) and its lengths,
    /// from `start_z` at `start`: each tool's time at its own feeds.
    pub fn by_tool(&self, start_z: f64) -> Vec<(Option<crate::process::MillTool>, MillStats)> {
        let mut runs = Vec::new();
        let (mut tool, mut from) = (None, 0);
        for (i, m) in self.moves.iter().enumerate() {
            if let MillMove::ToolChange(t) = m {
                if i > from || tool.is_some() {
                    runs.push((tool, from..i));
                }
                (tool, from) = (Some(*t), i + 1);
            }
        }
        runs.push((tool, from..self.moves.len()));
        let (mut at, mut z) = (self.start, start_z);
        (runs.into_iter())
            .map(|(t, r)| {
                let (st, a, h) = stats_of(&self.moves[r], at, z);
                (at, z) = (a, h);
                (t, st)
            })
            .collect()
    }
}

/// The lengths of `moves` from `start_z` at `from`; where they end and at
/// what height.
fn stats_of(moves: &[MillMove], from: Point, start_z: f64) -> (MillStats, Point, f64) {
    let mut st = MillStats::default();
    let (mut at, mut z) = (from, start_z);
    for m in moves {
        match m {
            MillMove::Rapid(p) => {
                st.rapid_mm += p.dist(at);
                at = *p;
            }
            MillMove::RapidZ(h) => {
                st.rapid_mm += (h - z).abs();
                z = *h;
            }
            MillMove::Plunge(h) => {
                st.plunge_mm += (h - z).abs();
                z = *h;
            }
            MillMove::Cut { seg, z: h } => {
                let l = seg.length();
                if *h != z {
                    st.plunge_mm += l.hypot(h - z);
                } else {
                    st.cut_mm += l;
                }
                at = seg.b;
                z = *h;
            }
            MillMove::Note(_) | MillMove::ToolChange(_) => continue,
        }
        st.moves += 1;
    }
    (st, at, z)
}
