//! Stage 5: [`CutPlan`] → program text, as a [`Post`] says.
//!
//! # Output contract
//! - A post is data ([`Post`], JSON): units, decimals, arc mode, block
//!   numbers and framing, comments, modal suppression, header/footer and
//!   torch templates with typed variables. Ten presets ([`PRESET_NAMES`]):
//!   LinuxCNC (plain and QtPlasmaC), GRBL (laser, plasma), Mach3/4 plasma,
//!   ISO 6983, paper 001's annex H dialect, paper 002's point list, paper
//!   003's knife rows and a tangential-knife G-code.
//! - [`emit`] keeps the first pipeline's LinuxCNC program (the `linuxcnc`
//!   preset); [`emit_post`] writes any post; [`est_time_s`] is the time on the
//!   post's machine; [`backplot`] re-reads a program into moves.
//! - Every coordinate is rounded to a fixed grid of `decimals` places, and
//!   the machine position is tracked on that grid, so what the program says
//!   is where the machine is; arc centres are grid points whose distances to
//!   both rounded ends agree within one grid step (see `emit.rs`).
//! - Comments carry only our own words and numbers, sanitised ([`sanitise`]);
//!   numbers never print as `-0`, `NaN`, an exponent or with a comma.

mod backplot;
mod check;
mod emit;
mod flatten;
mod knife;
mod number;
mod passes;
mod point_list;
mod post;
mod presets;
mod tabs;
mod thc;

pub use backplot::{backplot, Backplot, BackplotMove, BackplotWarning};
pub use check::PostError;
pub use check::VARS;
pub use post::{ArcMode, CommentStyle, Format, Knife, LineNumbers, Post, Units};
pub use presets::{preset, PRESET_NAMES};

use crate::plan::{CutPlan, Timing};
use check::{parse_template, Piece};
use number::Grid;

/// Program settings (the LinuxCNC program of the first pipeline).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GcodeOptions {
    /// Cutting feed, mm/min.
    pub feed: f64,
    /// Decimal places of every coordinate (1..=6).
    pub decimals: u32,
    /// Dwell after torch on, seconds (0 = none).
    pub pierce_delay: f64,
    /// Kerf width, for the header comment.
    pub kerf: f64,
}

impl GcodeOptions {
    /// 2000 mm/min, 3 decimals, no pierce delay.
    pub const DEFAULT: GcodeOptions = GcodeOptions {
        feed: 2000.0,
        decimals: 3,
        pierce_delay: 0.0,
        kerf: 0.0,
    };
}

/// The job's typed values that templates may use (never DXF text).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct JobInfo {
    /// Cutting feed, mm/min.
    pub feed: f64,
    /// Kerf width, mm.
    pub kerf: f64,
    /// Dwell after torch on, seconds.
    pub pierce_delay: f64,
    /// Program number (annex H's `%52100`).
    pub program: u32,
    /// Torch height while piercing, mm (Z posts).
    pub pierce_height: f64,
    /// Torch height while cutting, mm (Z posts).
    pub cut_height: f64,
    /// Speed in small holes, % of `feed`.
    pub small_hole_speed: f64,
    /// The controller's material number (QtPlasmaC `M190 Pn`).
    pub material: u32,
    /// Depth passes (off: one pass, no Z word).
    pub passes: crate::process::Passes,
    /// Several torches on the gantry: named in a comment, and a park and
    /// operator stop before the first cut when asked.
    pub torches: Option<crate::process::Torches>,
    /// Height locks before sharp corners and a contour's end.
    pub thc_lock: crate::process::ThcLock,
}

impl JobInfo {
    /// The values of the first pipeline's settings; program number 1, the
    /// default process's heights.
    pub fn from_options(o: &GcodeOptions) -> JobInfo {
        let p = crate::process::Process::DEFAULT;
        JobInfo {
            feed: o.feed,
            kerf: o.kerf,
            pierce_delay: o.pierce_delay,
            program: 1,
            pierce_height: p.pierce_height,
            cut_height: p.cut_height,
            small_hole_speed: p.small_hole.speed_pct,
            material: p.material,
            passes: p.passes,
            torches: p.torches,
            thc_lock: p.thc_lock,
        }
    }
    /// What a post may write of `p`; program number 1.
    pub fn from_process(p: &crate::process::Process) -> JobInfo {
        JobInfo {
            feed: p.feed,
            kerf: p.kerf,
            pierce_delay: p.pierce_delay,
            program: 1,
            pierce_height: p.pierce_height,
            cut_height: p.cut_height,
            small_hole_speed: p.small_hole.speed_pct,
            material: p.material,
            passes: p.passes,
            torches: p.torches,
            thc_lock: p.thc_lock,
        }
    }
}

/// Text safe inside `( )`: no parentheses, no `;`, no line breaks or other
/// control characters, ASCII only (some controllers choke on anything else).
pub fn comment(text: &str) -> String {
    format!("({})", sanitise(text))
}

/// Printable ASCII without any comment or block delimiter of our dialects
/// (`( ) ; % $ #`), one line, at most 120 characters: a layer named
/// `A)\nM30\n(` cannot end a comment and start a block.
pub fn sanitise(text: &str) -> String {
    let mut s = String::with_capacity(text.len().min(120));
    push_sanitised(&mut s, text);
    s
}

/// [`sanitise`] appended to `out` (a program writes one a cut).
fn push_sanitised(out: &mut String, text: &str) {
    let start = out.len();
    let mut leading = true;
    for c in text.chars().take(120) {
        let c = match c {
            '(' | ')' | ';' | '%' | '$' | '#' => ' ',
            c if c.is_ascii_graphic() || c == ' ' => c,
            _ => '?',
        };
        // Trimmed: every character left is ASCII, the only blank a space.
        if leading && c == ' ' {
            continue;
        }
        leading = false;
        out.push(c);
    }
    let end = out[start..].trim_end_matches(' ').len();
    out.truncate(start + end);
}

/// A comment in the post's style (None when the post writes none).
pub fn comment_as(style: CommentStyle, text: &str) -> Option<String> {
    match style {
        CommentStyle::Parens => Some(comment(text)),
        CommentStyle::Semicolon => Some(format!("; {}", sanitise(text))),
        CommentStyle::Dollar => Some(format!("$ {}", sanitise(text))),
        CommentStyle::None => None,
    }
}

/// Writes the LinuxCNC program of the first pipeline (the `linuxcnc` preset).
pub fn emit(plan: &CutPlan, options: &GcodeOptions) -> String {
    let post = Post {
        name: "LinuxCNC".into(),
        decimals: options.decimals.clamp(1, 6),
        ..Post::default()
    };
    emit::gcode(plan, &post, &JobInfo::from_options(options))
}

/// Writes the LinuxCNC program of the first pipeline with the job's process
/// values (small-hole speed, heights) from `job`.
pub fn emit_job(plan: &CutPlan, options: &GcodeOptions, job: &JobInfo) -> String {
    // With the `linuxcnc` preset's Z words for depth passes (unused when
    // the job has none).
    let post = Post {
        name: "LinuxCNC".into(),
        decimals: options.decimals.clamp(1, 6),
        pass_z: vec!["G1 Z{pass_z}".into()],
        pass_retract: vec!["G0 Z{safe_height}".into()],
        ..Post::default()
    };
    emit::gcode(plan, &post, job)
}

/// Writes the plan as `post` says; an invalid post names its field.
pub fn emit_post(plan: &CutPlan, post: &Post, job: &JobInfo) -> Result<String, PostError> {
    post.validate()?;
    for (field, v, max) in [
        ("job.feed", job.feed, 1e6),
        ("job.kerf", job.kerf, 100.0),
        ("job.pierce_delay", job.pierce_delay, 60.0),
        ("job.pierce_height", job.pierce_height, 100.0),
        ("job.cut_height", job.cut_height, 100.0),
        ("job.small_hole_speed", job.small_hole_speed, 100.0),
        ("job.depth", job.passes.depth, 1000.0),
        ("job.pass_depth", job.passes.pass_depth, 1000.0),
    ] {
        if !(v.is_finite() && (0.0..=max).contains(&v)) {
            return Err(PostError {
                field: field.into(),
                reason: crate::text!("{v} is not between 0 and {max}"; "{} não está entre 0 e {}", crate::warning::dec(v), crate::warning::dec(max)),
            });
        }
    }
    if job.passes.on() && (post.format != Format::Gcode || post.pass_z.is_empty()) {
        // A post that cannot move Z would cut every pass at the same depth,
        // n times over the same line: refused, not written.
        let name = &post.name;
        return Err(PostError {
            field: "pass_z".into(),
            reason: crate::text!("post '{name}' has no Z word for depth passes (a G-code post with a 'pass_z' template, e.g. 'G1 Z{{pass_z}}'): multi-pass refused";
                                 "o pós-processador '{name}' não tem palavra Z para passes em profundidade (um pós de G-code com o modelo 'pass_z', p. ex. 'G1 Z{{pass_z}}'): multipasse recusado"),
        });
    }
    if job.torches.is_some() && post.format != Format::Gcode {
        // Without comments or a program stop, the operator would not learn
        // from the program that the other torches cut too.
        let name = &post.name;
        return Err(PostError {
            field: "torches".into(),
            reason: crate::text!("post '{name}' is not G-code: it cannot name the torch setup or stop for it; several torches refused";
                                 "o pós-processador '{name}' não é G-code: não pode nomear a montagem das tochas nem parar para ela; várias tochas recusadas"),
        });
    }
    let tabs = plan
        .cuts
        .iter()
        .any(|c| c.steps.iter().any(|s| s.role == crate::plan::Role::Tab));
    if tabs && post.format != Format::Gcode {
        // Paper 002's and 003's row formats have no torch switch within a
        // path: a tab would be cut through. Refused, not written wrong.
        let name = &post.name;
        return Err(PostError {
            field: "format".into(),
            reason: crate::text!("post '{name}' cannot leave tabs (its rows cut a path without stopping): tabs refused";
                                 "o pós-processador '{name}' não deixa pontes (suas linhas cortam um caminho sem parar): pontes recusadas"),
        });
    }
    Ok(match post.format {
        Format::Gcode => emit::gcode(plan, post, job),
        Format::PointList => point_list::write(plan, post),
        Format::KnifeRelative => knife::write(plan, post),
    })
}

/// Estimated machine time of the plan on this post's machine, s: feed moves
/// at the job's feed, rapids at the post's rapid speed, a dwell per pierce.
pub fn est_time_s(plan: &CutPlan, post: &Post, job: &JobInfo) -> f64 {
    plan.est_time_s(&Timing {
        feed: job.feed,
        rapid: post.rapid_speed,
        pierce_delay: job.pierce_delay,
        passes: job.passes.count(),
        small_hole_speed: job.small_hole_speed,
    })
}

/// Lines of a program: templates expanded, blocks numbered and framed.
pub(crate) struct Writer<'a> {
    pub(crate) post: &'a Post,
    vars: Vec<(&'static str, String)>,
    out: String,
    next_n: Option<u64>,
    feed: String,
    feed_set: bool,
    /// A template was written: it may have changed the modal motion (a
    /// knife's `G1 Z0`), so the next move repeats its motion word.
    templated: bool,
    /// The block being put together (kept to reuse its allocation).
    words: String,
    /// A depth pass is being cut: a knife lifted over a sharp corner goes
    /// back down to the pass's depth.
    pub(crate) pass_depth: bool,
}

impl<'a> Writer<'a> {
    pub(crate) fn new(post: &'a Post, plan: &CutPlan, job: &JobInfo) -> Self {
        let grid = Grid::new(post.decimals).with_trailing_zeros(post.trailing_zeros);
        let k = emit::unit_scale(post);
        let st = plan.stats();
        let feed = grid.fmt_mm(job.feed * k);
        let vars = vec![
            ("feed", feed.clone()),
            ("kerf", grid.fmt_mm(job.kerf * k)),
            ("pierce_delay", grid.fmt_mm(job.pierce_delay)),
            ("pierce_delay_ms", grid.fmt_mm(job.pierce_delay * 1000.0)),
            ("est_time_s", grid.fmt_mm(est_time_s(plan, post, job))),
            ("cuts", plan.cuts.len().to_string()),
            ("pierces", st.pierces.to_string()),
            ("program", job.program.to_string()),
            ("rapid_speed", grid.fmt_mm(post.rapid_speed * k)),
            (
                "small_hole_feed",
                grid.fmt_mm(job.feed * job.small_hole_speed / 100.0 * k),
            ),
            ("small_hole_speed", grid.fmt_mm(job.small_hole_speed)),
            ("pierce_height", grid.fmt_mm(job.pierce_height * k)),
            ("cut_height", grid.fmt_mm(job.cut_height * k)),
            ("material", job.material.to_string()),
            ("switch_offset", grid.fmt_mm(post.switch_offset * k)),
            ("safe_height", grid.fmt_mm(post.safe_height * k)),
            ("probe_feed", grid.fmt_mm(post.probe_feed * k)),
            ("probe_distance", grid.fmt_mm(post.probe_distance * k)),
            // Set by the emitter before each depth pass.
            ("pass_z", String::new()),
        ];
        Writer {
            post,
            vars,
            out: String::with_capacity(4096),
            next_n: post.line_numbers.map(|n| n.start as u64),
            feed: format!("F{feed}"),
            // A post whose header sets the feed its own way (QtPlasmaC's
            // `F#<_hal[plasmac.cut-feed-rate]>`) never gets our F word.
            feed_set: !post.feed_word,
            templated: false,
            words: String::new(),
            pass_depth: false,
        }
    }
    fn expand(&mut self, t: &str) -> String {
        let mut s = String::new();
        self.expand_into(t, &mut s);
        s
    }
    /// A template with its variables filled in, appended to `s`.
    fn expand_into(&mut self, t: &str, s: &mut String) {
        if !t.contains('{') {
            // No variable (most templates: `M3 S1`, `M5`): no parsing.
            s.push_str(t);
            return;
        }
        // Templates were validated; an error here writes the line unexpanded.
        let Ok(pieces) = parse_template(t, "") else {
            s.push_str(t);
            return;
        };
        for p in pieces {
            match p {
                Piece::Text(x) => s.push_str(x),
                Piece::Var(v) => {
                    if v == "feed" || v == "small_hole_feed" {
                        self.feed_set = true;
                    }
                    if let Some((_, val)) = self.vars.iter().find(|(n, _)| *n == v) {
                        s.push_str(val);
                    }
                }
            }
        }
    }
    /// The depth of the next pass, mm (the `{pass_z}` variable).
    pub(crate) fn set_pass_z(&mut self, z_mm: f64) {
        let grid = Grid::new(self.post.decimals).with_trailing_zeros(self.post.trailing_zeros);
        let v = grid.fmt_mm(z_mm * emit::unit_scale(self.post));
        if let Some(slot) = self.vars.iter_mut().find(|(n, _)| *n == "pass_z") {
            slot.1 = v;
        }
    }
    /// The next feed block writes the F word again (a template moved Z at
    /// its own feed: a probe).
    pub(crate) fn reset_feed(&mut self) {
        if self.post.feed_word {
            self.feed_set = false;
        }
    }
    /// F word for a feed block, if the modal feed is not set yet.
    pub(crate) fn feed_word(&mut self) -> Option<String> {
        (!std::mem::replace(&mut self.feed_set, true)).then(|| self.feed.clone())
    }
    pub(crate) fn raw(&mut self, line: &str) {
        self.out.push_str(line);
        self.out.push('\n');
    }
    pub(crate) fn raws(&mut self, lines: &[String]) {
        for l in lines {
            let s = self.expand(l);
            self.raw(&s);
        }
    }
    fn framed(&mut self, text: &str) {
        let numbered = !self
            .post
            .unnumbered
            .iter()
            .any(|u| !u.is_empty() && text.starts_with(u.as_str()));
        self.out.push_str(&self.post.block_prefix);
        if let (true, Some(n), Some(ln)) = (numbered, self.next_n, self.post.line_numbers) {
            // `N` and the number zero-padded to the width (as `{:0w$}`).
            self.out.push('N');
            let digits = n.checked_ilog10().map_or(1, |l| l as usize + 1);
            for _ in digits..ln.width as usize {
                self.out.push('0');
            }
            number::push_u64(&mut self.out, n);
            self.out.push_str(&self.post.word_separator);
            self.next_n = Some(n + ln.step as u64);
        }
        self.out.push_str(text);
        self.out.push_str(&self.post.block_suffix);
        self.out.push('\n');
    }
    /// One block of words.
    pub(crate) fn block(&mut self, words: &[String]) {
        let text = words.join(&self.post.word_separator);
        self.framed(&text);
    }
    /// A block put together word by word in a reused buffer: `word` adds
    /// one word (letters, then a grid number when given).
    pub(crate) fn block_of(&mut self, build: impl FnOnce(&mut Words)) {
        let mut buf = std::mem::take(&mut self.words);
        buf.clear();
        let mut words = Words {
            text: buf,
            sep: &self.post.word_separator,
            any: false,
        };
        build(&mut words);
        let text = words.text;
        self.framed(&text);
        self.words = text;
    }
    /// Template blocks.
    pub(crate) fn templates(&mut self, lines: &[String]) {
        let mut s = std::mem::take(&mut self.words);
        for l in lines {
            s.clear();
            self.expand_into(l, &mut s);
            if !s.trim().is_empty() {
                self.framed(&s);
                self.templated = true;
            }
        }
        self.words = s;
    }
    /// True once after any template block.
    pub(crate) fn take_templated(&mut self) -> bool {
        std::mem::replace(&mut self.templated, false)
    }
    /// A comment line in the post's style (as [`comment_as`]), written
    /// straight into the program.
    pub(crate) fn comment(&mut self, text: &str) {
        let (open, close) = match self.post.comments {
            CommentStyle::Parens => ("(", ")"),
            CommentStyle::Semicolon => ("; ", ""),
            CommentStyle::Dollar => ("$ ", ""),
            CommentStyle::None => return,
        };
        self.out.push_str(open);
        push_sanitised(&mut self.out, text);
        self.out.push_str(close);
        self.out.push('\n');
    }
    pub(crate) fn finish(self) -> String {
        self.out
    }
}

/// The words of one block, separated by the post's separator.
pub(crate) struct Words<'s> {
    text: String,
    sep: &'s str,
    any: bool,
}

impl Words<'_> {
    /// A word of text (`G1`, `F2000`).
    pub(crate) fn text(&mut self, w: &str) {
        self.start();
        self.text.push_str(w);
    }
    /// A letter and a number on the grid (`X12.5`).
    pub(crate) fn num(&mut self, letter: &str, grid: &number::Grid, v: i64) {
        self.start();
        self.text.push_str(letter);
        grid.push(&mut self.text, v);
    }
    fn start(&mut self) {
        if self.any {
            self.text.push_str(self.sep);
        }
        self.any = true;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn comments_cannot_break_out_or_inject_blocks() {
        let c = comment("layer (x)\nG0 X0; M3");
        assert_eq!(c, "(layer  x ?G0 X0  M3)");
        assert_eq!(c.matches('(').count(), 1);
        assert_eq!(c.matches(')').count(), 1);
        assert!(!c.contains('\n') && !c.contains(';'));
        let evil = "A)\nM30\n(";
        for style in [
            CommentStyle::Parens,
            CommentStyle::Semicolon,
            CommentStyle::Dollar,
        ] {
            let c = comment_as(style, evil).unwrap();
            assert!(!c.contains('\n') && !c.contains(')') || style == CommentStyle::Parens);
            assert_eq!(c.lines().count(), 1);
        }
        assert_eq!(comment_as(CommentStyle::None, evil), None);
    }
}
