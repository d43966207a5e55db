//! What validated settings say, read-only: the fields are private so
//! that every change goes through a checked `with_*` (issue 15 §5).

use super::{MaterialUsed, Settings};
use crate::dxf::ReadOptions;
use crate::gcode::Post;
use crate::geom::Tolerance;
use crate::kerf::Kerf;
use crate::origin::ProgramOrigin;
use crate::plan::PlanOptions;
use crate::process::{LayerOps, Process};
use crate::warning::Lang;

impl Settings {
    /// How the DXF is read.
    pub fn read(&self) -> &ReadOptions {
        &self.read
    }
    /// The one tolerance, mm.
    pub fn tolerance(&self) -> Tolerance {
        self.tolerance
    }
    /// Open ends up to this far apart are joined, mm.
    pub fn gap(&self) -> f64 {
        self.gap
    }
    /// The threads the stages may use.
    pub fn threads(&self) -> crate::par::Threads {
        self.threads
    }
    /// The kerf compensation: the process's width.
    pub fn kerf(&self) -> Kerf {
        Kerf {
            width: self.process.kerf,
            join: self.join,
            threads: self.threads,
        }
    }
    /// The plan options.
    pub fn plan(&self) -> &PlanOptions {
        &self.plan
    }
    /// Decimal places of the plain program (no post).
    pub fn decimals(&self) -> u32 {
        self.decimals
    }
    /// What the program writer reads: the process, program 1, the job's
    /// threads.
    pub fn job(&self) -> crate::gcode::JobInfo {
        crate::gcode::JobInfo {
            threads: self.threads,
            ..crate::gcode::JobInfo::from_process(&self.process)
        }
    }
    /// The post, if any.
    pub fn post(&self) -> Option<&Post> {
        self.post.as_ref()
    }
    /// The language of messages.
    pub fn lang(&self) -> Lang {
        self.lang
    }
    /// Which drawing point is the program's zero.
    pub fn origin(&self) -> ProgramOrigin {
        self.origin
    }
    /// What each layer is for.
    pub fn layer_ops(&self) -> &LayerOps {
        &self.layer_ops
    }
    /// The process: kerf, feed, delay, rapid, heights, rules.
    pub fn process(&self) -> &Process {
        &self.process
    }
    /// The router's other tools and the layers they mill.
    pub fn tools(&self) -> &crate::process::Tools {
        &self.tools
    }
    /// The milling layers given their own depth.
    pub fn layer_depths(&self) -> &crate::process::LayerDepths {
        &self.layer_depths
    }
    /// True when the cut is checked against the parts.
    pub fn verify(&self) -> bool {
        self.verify
    }
    /// The cut-chart entry the process came from, if any.
    pub fn material(&self) -> Option<&MaterialUsed> {
        self.material.as_ref()
    }
}
