//! What the back ends draw and point into (issue 15 §2): the contours as
//! drawn, the plan cut over them, and the few marks that belong to
//! neither (DXF POINTs, kerf vertices the offset had to drop). A drawing's
//! [`crate::Output`] gives one ([`crate::Output::scene`]), and so does a
//! nested sheet's, made from the sheet's own contours and plan: the
//! preview and the inspector never need to know which it was.

use crate::contour::Contours;
use crate::geom::{Point, Segment};
use crate::mill::Toolpath;
use crate::plan::{CutPlan, FileOrder};

/// A job as drawn: borrowed from the stages' outputs, never copied.
#[derive(Clone, Copy, Debug)]
pub struct Scene<'a> {
    /// The drawn entities (their DXF types, for the inspector) and POINTs.
    pub file: FileOrder<'a>,
    /// The contours as drawn, with what healing changed and where.
    pub contours: &'a Contours,
    /// Where the kerf offset dropped a vertex ([`crate::kerf::KerfPaths`]).
    pub invalid_vertices: &'a [Point],
    /// The ordered cuts.
    pub plan: &'a CutPlan,
    /// A router's pockets, engravings and holes, cut before the plan's
    /// profiles: the very moves the router post writes.
    pub milling: Option<Milling<'a>>,
    /// The program's rapids in X and Y when known
    /// ([`crate::animation::rapids`]: a router profile's lift and rapid
    /// between depth passes too), for the preview to draw them as Play
    /// and the plan SVG do; none: the plan's, one per cut, and the
    /// milling's.
    pub rapids: Option<&'a [Segment]>,
}

/// The milling toolpath of a job and the tool that cuts it.
#[derive(Clone, Copy, Debug)]
pub struct Milling<'a> {
    /// The moves (`gcode::emit_router` writes the same).
    pub toolpath: &'a Toolpath,
    /// The tool's cutting diameter, mm: the width each cut clears.
    pub tool_diameter: f64,
    /// A V-bit's included angle, degrees (0: a flat end mill): a cut at
    /// depth d clears 2·d·tan(angle/2), at most the diameter.
    pub v_angle_deg: f64,
    /// The pockets' and drilled shapes' outlines as drawn.
    pub drawn: &'a [Vec<Segment>],
}

impl crate::Output {
    /// The job as the preview and the inspector see it.
    pub fn scene(&self) -> Scene<'_> {
        Scene {
            file: FileOrder::of(&self.drawing),
            contours: &self.contours,
            invalid_vertices: &self.kerf.invalid_vertices,
            plan: &self.plan,
            milling: self.milled.as_ref().map(|m| Milling {
                toolpath: &m.toolpath,
                tool_diameter: self.process.tool.diameter,
                v_angle_deg: self.process.tool.v_angle_deg,
                drawn: &m.drawn,
            }),
            rapids: None,
        }
    }
}
