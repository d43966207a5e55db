//! The integration tests, one binary (issue 40): each file a module here, so
//! cargo builds and links one test executable instead of one per file. A new
//! test file goes in tests/it/NAME.rs with a `mod NAME;` line below (keep the
//! list sorted), and uses the shared helpers with `use crate::common;`
//! instead of `mod common;`. Run one file's tests with
//! `cargo test --test it NAME::`.

#[path = "../common/mod.rs"]
mod common;

mod arcfit;
mod backplot;
mod choices;
mod cli;
mod common_line;
mod corpus;
mod docs;
mod eulerian;
mod fixtures;
mod gcode_threads;
mod golden;
mod i18n;
mod kerf_props;
mod labels;
mod materials;
mod milling;
mod milling_depths;
mod milling_leads;
mod milling_offset;
mod milling_play;
mod milling_preview;
mod milling_sides;
mod milling_tabs;
mod milling_tools;
mod module_cycles;
mod multipass;
mod nest;
mod nest_budget;
mod nest_corpus;
mod nest_cost;
mod nest_holes;
mod nest_part_in_hole;
mod part_names;
mod plan_svg;
mod plan_threads;
mod planning;
mod posts;
mod process;
mod quote;
mod reader_reference;
mod robustness;
mod self_crossing;
mod shared_edges;
mod svg;
mod tabs;
mod thc;
mod threads;
mod torches;
mod trust;
mod verify;
