//! kerfcam: DXF drawings to cutting programs for 2-D thermal and knife
//! cutting, natively and in WebAssembly.
//!
//! The pipeline, one module per stage, each with one input and one output:
//!
//! ```text
//! &[u8] ─dxf::parse→ Drawing ─contour::extract→ Contours ─kerf::offset→ KerfPaths
//!       ─plan::plan→ CutPlan ─┬─gcode::emit→ String
//!                             ├─preview::render→ Pixmap   (of a scene::Scene:
//!                             │                            contours + plan)
//!                             └─report::Report::new→ JSON
//! ```
//!
//! ```
//! let dxf = b"0\nSECTION\n2\nENTITIES\n0\nCIRCLE\n10\n50\n20\n50\n40\n10\n0\nENDSEC\n0\nEOF\n";
//! let settings = kerfcam::Settings::new(1.5, 0.001, 2000.0)?;
//! let out = kerfcam::run(dxf, &settings)?;
//! assert_eq!(out.plan.pierces(), 1);
//! assert!(out.gcode.contains("G21"));
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

pub mod animation;
mod case;
mod cell_lists;
mod compare;
pub mod contour;
mod defaults;
pub mod dxf;
mod error;
mod fx;
pub mod gcode;
pub mod geom;
pub mod input;
pub mod inspect;
pub mod kerf;
pub mod label;
pub mod losses;
pub mod materials;
pub mod mill;
pub mod nest;
pub mod nest_cut;
pub mod origin;
mod output;
pub mod par;
mod pipeline;
pub mod plan;
pub mod preview;
pub mod process;
pub mod quote;
pub mod report;
pub mod scene;
mod settings;
mod settings_error;
mod sort;
pub mod source;
mod stage;
pub mod svg;
#[cfg(test)]
mod test_dxf;
#[cfg(test)]
mod test_rng;
pub mod warning;
#[cfg(target_arch = "wasm32")]
pub mod wasm;
#[cfg(target_arch = "wasm32")]
mod wasm_text;

pub use compare::{compare_orders, OrderSummary};
pub use defaults::page_defaults;
pub use error::Error;
pub use output::Output;
pub use pipeline::{cut_drawing, run, run_watched, run_with_progress};
pub use settings::{
    Choice, LayerDepthSpec, LoopKeySpec, MaterialUsed, Settings, SettingsError, SideChoice, Spec,
    ToolSpec, DEFAULT_RAPID,
};
pub use stage::{Stage, StageDone};
