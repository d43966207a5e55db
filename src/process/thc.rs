//! Torch-height lock at sharp corners and near a contour's end (issue 20
//! item 4). A height control follows the arc voltage; where the torch
//! slows down for a corner the voltage rises and the control dives the
//! torch into the plate, and near the end of a contour the kerf meets its
//! own start (or the part drops) and the voltage jumps. QtPlasmaC's
//! documentation and the torch makers lock the height there; the post's
//! `thc_lock`/`thc_unlock` templates (QtPlasmaC `M62 P2`/`M63 P2`,
//! synchronised with motion) say how ([`crate::gcode`]'s `thc.rs` writes them).

/// Where the height is locked within a cut. Lengths mm, angle degrees.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ThcLock {
    /// Corners whose included angle is below this are sharp (180 = a
    /// straight run, 90 = a square corner).
    pub corner_angle_deg: f64,
    /// Locked from this far before a sharp corner to this far after it
    /// (0 = no corner locks).
    pub corner_distance: f64,
    /// Locked this far before the contour's end, to the torch going off
    /// (0 = from the lead-out only).
    pub end_distance: f64,
}

impl ThcLock {
    /// No locks but the small holes' and the lead-out's.
    pub const OFF: ThcLock = ThcLock {
        corner_angle_deg: 120.0,
        corner_distance: 0.0,
        end_distance: 0.0,
    };
    /// True when corner or end locks are asked for.
    pub fn on(&self) -> bool {
        self.corner_distance > 0.0 || self.end_distance > 0.0
    }
}
