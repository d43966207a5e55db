//! A post-processor as data: everything that differs between controllers,
//! as a serde description (JSON in the page and the CLI), validated once.
//!
//! Paper 001 §7.1 (notes-001 §7.1) asks for "a single table-driven post"
//! configured per control by a standard questionnaire instead of one
//! converter per machine: this is that table. Templates are lines with
//! typed variables (`{feed}`, `{kerf}`, `{pierce_delay}`, …, see [`super::VARS`]);
//! no text from the DXF ever reaches them.

use crate::text;

use serde::{Deserialize, Serialize};

use super::check::{err, PostError};

/// What kind of program the post writes.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Format {
    /// RS274 / ISO 6983 blocks.
    Gcode,
    /// Paper 002's `x;y` rows with `L`/`D` torch codes.
    PointList,
    /// Paper 003's tangential-knife rows `z Δx Δy Δθ`.
    KnifeRelative,
}

/// Program units.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Units {
    /// Millimetres (G21).
    Mm,
    /// Inches (G20).
    Inch,
}

/// How arcs are written.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum ArcMode {
    /// G2/G3 with I/J from the arc start (G91.1, the RS274 default).
    IjIncremental,
    /// G2/G3 with I/J the absolute centre (G90.1).
    IjAbsolute,
    /// G2/G3 with the radius R.
    R,
    /// Straight lines within the chord tolerance (paper 004's chord formula).
    Lines,
}

/// How comments are written.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum CommentStyle {
    /// `(text)`.
    Parens,
    /// `; text`.
    Semicolon,
    /// `$ text`: paper 001's operator messages (annex H).
    Dollar,
    /// No comments.
    None,
}

/// Block numbers.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LineNumbers {
    /// First number.
    pub start: u32,
    /// Increment (paper 001's prompt default: 10).
    pub step: u32,
    /// Digits, zero-padded (0 = as long as needed).
    pub width: u32,
}

/// A tangential knife on a rotary axis (paper 003).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Knife {
    /// The rotary axis word ("A", "B" or "C"), degrees.
    pub axis: String,
    /// A turn larger than this (degrees) lifts the knife, turns, and plunges
    /// again; smaller turns are made while cutting.
    pub lift_angle_deg: f64,
}

/// A post-processor.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct Post {
    /// Shown in the program's first comment.
    pub name: String,
    /// What kind of program.
    pub format: Format,
    /// G21 or G20 coordinates (the header writes the word).
    pub units: Units,
    /// Decimal places of coordinates (1..=6).
    pub decimals: u32,
    /// Keep trailing zeros (`10.0`) instead of stripping them (`10`).
    pub trailing_zeros: bool,
    /// Arc output.
    pub arcs: ArcMode,
    /// Largest distance between an arc and the lines replacing it, mm.
    pub chord: f64,
    /// Arcs split in pieces of this length (paper 002's resolution:
    /// n = floor(arc length / resolution)), mm; 0 = use `chord`.
    pub segment_length: f64,
    /// Largest sweep of one arc block, degrees (0 < · ≤ 180).
    pub max_arc_sweep_deg: f64,
    /// Block numbers, if any.
    pub line_numbers: Option<LineNumbers>,
    /// Template lines starting with one of these words get no block number
    /// (paper 001's `CYC10…` cycle lines).
    pub unnumbered: Vec<String>,
    /// Written before every block (annex H: ": ").
    pub block_prefix: String,
    /// Written after every block (annex H: "$").
    pub block_suffix: String,
    /// Between the words of a block (" ", or "" as annex H writes).
    pub word_separator: String,
    /// Comment style.
    pub comments: CommentStyle,
    /// Repeat no motion word or unchanged coordinate (modal suppression).
    pub modal: bool,
    /// Raw lines before everything (`%`, `#`): no number, prefix or suffix.
    pub program_start: Vec<String>,
    /// Header blocks (templates).
    pub header: Vec<String>,
    /// Footer blocks (templates); must end the program (M2 or M30).
    pub footer: Vec<String>,
    /// Raw lines after everything.
    pub program_end: Vec<String>,
    /// Rapid motion word ("G0"; "G1" where the control has no rapid, annex H).
    pub rapid: String,
    /// Linear feed word.
    pub line: String,
    /// Clockwise arc word.
    pub cw: String,
    /// Counter-clockwise arc word.
    pub ccw: String,
    /// Before each pierce: initial height sensing (templates).
    pub probe: Vec<String>,
    /// Torch on (templates).
    pub torch_on: Vec<String>,
    /// After torch on, only when the pierce delay is not 0 (templates).
    pub dwell: Vec<String>,
    /// After the pierce (and its delay), every cut (templates): a Z post
    /// goes down to the cut height here.
    pub after_pierce: Vec<String>,
    /// After the pierce: torch-height control on (templates; not in small
    /// holes, where the height stays locked).
    pub thc_on: Vec<String>,
    /// Before torch off: torch-height control off (templates).
    pub thc_off: Vec<String>,
    /// Torch off (templates).
    pub torch_off: Vec<String>,
    /// A spot (DXF POINT) (templates); empty = torch on, dwell, torch off.
    pub spot: Vec<String>,
    /// Marking tool on, for paths marked on the line (templates); empty =
    /// `torch_on` (QtPlasmaC's scribe: `M3 $1 S1`).
    pub mark_on: Vec<String>,
    /// Marking tool off (templates); empty = `torch_off`.
    pub mark_off: Vec<String>,
    /// Lock the torch height, synchronised with motion (templates): in
    /// small holes and over the overcut at a contour's end (QtPlasmaC
    /// `M62 P2`).
    pub thc_lock: Vec<String>,
    /// Release the lock, after the torch is off (templates; QtPlasmaC `M63 P2`).
    pub thc_unlock: Vec<String>,
    /// Slow down for a small hole (templates; `F{small_hole_feed}`, or
    /// QtPlasmaC's `M67 E3 Q{small_hole_speed}`).
    pub small_hole_on: Vec<String>,
    /// Back to the cutting speed after a small hole (templates).
    pub small_hole_off: Vec<String>,
    /// Controller compensation on, tool left of the path, before the
    /// lead-in line (templates; LinuxCNC `G41.1 D{kerf}`).
    pub comp_left: Vec<String>,
    /// The same, tool right of the path (`G42.1 D{kerf}`).
    pub comp_right: Vec<String>,
    /// Compensation off after the contour (`G40`).
    pub comp_off: Vec<String>,
    /// Over a tab (issue 20 §6): the torch off while the motion goes on,
    /// synchronised (templates). Empty = off as at a cut's end, a rapid
    /// over the tab and a new pierce after it ([`super::tabs`]).
    pub tab_off: Vec<String>,
    /// After a tab: the torch on again (templates; with `tab_off`).
    pub tab_on: Vec<String>,
    /// Depth passes (issue 20 §8): down to the pass's depth at the start
    /// of each pass (templates; `G1 Z{pass_z}`: no F word, so a small hole
    /// keeps its own feed). Empty = the post has no Z word and refuses a
    /// multi-pass job.
    pub pass_z: Vec<String>,
    /// Depth passes: up out of the cut after the last pass, before the
    /// tool goes off (templates; `G0 Z{safe_height}`).
    pub pass_retract: Vec<String>,
    /// Routers: the change to the next tool of a job with several
    /// (templates, with the new tool's `{tool_number}`, `{spindle_rpm}`,
    /// `{plunge_feed}`; `pass_retract` follows). Empty: one tool per
    /// program, a job with more refused.
    pub tool_change: Vec<String>,
    /// Write the F word on the first feed move when no template set the
    /// feed (false where the header sets it, as QtPlasmaC's material feed).
    pub feed_word: bool,
    /// Z posts: how far the torch travels after touching the plate before
    /// its float switch trips, mm (`{switch_offset}`).
    pub switch_offset: f64,
    /// Z posts: the height of rapids, mm (`{safe_height}`).
    pub safe_height: f64,
    /// Routers: the height of moves between places within a job, above
    /// the stock's top, mm (`{retract_height}`; below `safe_height`).
    pub retract_height: f64,
    /// Z posts: the probing speed, mm/min (`{probe_feed}`).
    pub probe_feed: f64,
    /// Z posts: the longest probing move, mm (`{probe_distance}`).
    pub probe_distance: f64,
    /// Rapid traverse speed of the machine, mm/min (time estimate).
    pub rapid_speed: f64,
    /// A tangential knife's rotary axis (G-code format only).
    pub knife: Option<Knife>,
    /// Motion blocks in incremental coordinates (`G91`, paper 004 L361):
    /// each X and Y the rounded target less the rounded position before,
    /// so the sum of the increments is the `G90` program's end to the
    /// last decimal, however many moves. Templates stay absolute (their Z
    /// heights are): a `G90` block is written before one with an axis
    /// word, `G91` again on the next move. G-code posts without a knife.
    pub incremental: bool,
}

impl Default for Post {
    /// Plain LinuxCNC.
    fn default() -> Self {
        Post {
            name: "custom".into(),
            format: Format::Gcode,
            units: Units::Mm,
            decimals: 3,
            trailing_zeros: false,
            arcs: ArcMode::IjIncremental,
            chord: 0.01,
            segment_length: 0.0,
            max_arc_sweep_deg: 180.0,
            line_numbers: None,
            unnumbered: Vec::new(),
            block_prefix: String::new(),
            block_suffix: String::new(),
            word_separator: " ".into(),
            comments: CommentStyle::Parens,
            modal: false,
            program_start: vec!["%".into()],
            header: vec!["G21 G90 G17 G40 G91.1".into(), "F{feed}".into()],
            footer: vec!["M2".into()],
            program_end: vec!["%".into()],
            rapid: "G0".into(),
            line: "G1".into(),
            cw: "G2".into(),
            ccw: "G3".into(),
            probe: Vec::new(),
            torch_on: vec!["M3 S1".into()],
            dwell: vec!["G4 P{pierce_delay}".into()],
            after_pierce: Vec::new(),
            thc_on: Vec::new(),
            thc_off: Vec::new(),
            torch_off: vec!["M5".into()],
            spot: Vec::new(),
            mark_on: Vec::new(),
            mark_off: Vec::new(),
            thc_lock: Vec::new(),
            thc_unlock: Vec::new(),
            small_hole_on: vec!["F{small_hole_feed}".into()],
            small_hole_off: vec!["F{feed}".into()],
            comp_left: vec!["G41.1 D{kerf}".into()],
            comp_right: vec!["G42.1 D{kerf}".into()],
            comp_off: vec!["G40".into()],
            tab_off: Vec::new(),
            tab_on: Vec::new(),
            pass_z: Vec::new(),
            pass_retract: Vec::new(),
            tool_change: Vec::new(),
            feed_word: true,
            switch_offset: 0.0,
            safe_height: 10.0,
            retract_height: 2.0,
            probe_feed: 300.0,
            probe_distance: 50.0,
            rapid_speed: crate::DEFAULT_RAPID,
            knife: None,
            incremental: false,
        }
    }
}

impl Post {
    /// mm → the program's units.
    pub fn unit_scale(&self) -> f64 {
        match self.units {
            Units::Mm => 1.0,
            Units::Inch => 1.0 / 25.4,
        }
    }
    /// A post from JSON, validated; missing fields take plain LinuxCNC's values.
    pub fn from_json(text: &str) -> Result<Post, PostError> {
        let post: Post = serde_json::from_str(text).map_err(|e| {
            // serde names unknown fields and wrong types in its message.
            err("json", text!("{e}"; "JSON inválido: {e}"))
        })?;
        post.validate()?;
        Ok(post)
    }

    /// The post as pretty JSON (for export and editing).
    pub fn to_json(&self) -> String {
        serde_json::to_string_pretty(self).unwrap_or_default()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn invalid_posts_name_the_field() {
        let mut p = Post {
            decimals: 9,
            ..Post::default()
        };
        assert_eq!(p.validate().unwrap_err().field, "decimals");
        p.decimals = 3;
        p.footer = vec!["M5".into()];
        assert_eq!(p.validate().unwrap_err().field, "footer");
        p.footer = vec!["M30".into()];
        p.header.push("G0 X0\nM3".into());
        assert_eq!(p.validate().unwrap_err().field, "header[2]");
        let e = Post::from_json(r#"{"decimals": 3, "colour": 1}"#).unwrap_err();
        assert_eq!(e.field, "json");
        assert!(e.reason.en.contains("colour"));
        let e = Post::from_json(r#"{"max_arc_sweep_deg": 270}"#).unwrap_err();
        assert_eq!(e.field, "max_arc_sweep_deg");
    }
}
