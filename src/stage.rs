//! The pipeline's stages, for progress reports.

/// A pipeline stage, for progress reports (the page's progress bar).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Stage {
    /// DXF bytes → Drawing.
    Reading,
    /// Drawing → Contours (healing, chaining, containment depth).
    Chaining,
    /// Contours → kerf paths.
    Offset,
    /// Kerf paths → CutPlan.
    Planning,
    /// CutPlan → program text.
    GCode,
}

impl Stage {
    /// Every stage, in pipeline order.
    pub const ALL: [Stage; 5] = [
        Stage::Reading,
        Stage::Chaining,
        Stage::Offset,
        Stage::Planning,
        Stage::GCode,
    ];

    /// Stable name: "reading", "chaining", "offset", "planning", "gcode".
    pub fn name(self) -> &'static str {
        match self {
            Stage::Reading => "reading",
            Stage::Chaining => "chaining",
            Stage::Offset => "offset",
            Stage::Planning => "planning",
            Stage::GCode => "gcode",
        }
    }
}

/// What one finished stage made: `stage` and a count of what it produced
/// (entities read, contours, kerf paths, pierces, program bytes), so a
/// progress display can show results as they come.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct StageDone {
    /// The stage that finished.
    pub stage: Stage,
    /// Entities, contours, kerf paths, pierces or program bytes.
    pub count: usize,
}
