//! The program's lines: templates expanded with the job's values, blocks
//! numbered and framed as the post says. Every back end that writes G-code
//! (`emit`, `passes`, `tabs`, `thc`) writes through it.

use crate::plan::CutPlan;

use super::bytes::Bytes;
use super::check::{parse_template, Piece};
use super::number::{self, Grid};
use super::post::{CommentStyle, Post};
use super::{push_sanitised, JobInfo};

/// Lines of a program: templates expanded, blocks numbered and framed.
#[derive(Clone)]
pub(crate) struct Writer<'a> {
    pub(crate) post: &'a Post,
    vars: Vec<(&'static str, String)>,
    /// The plan and job whose stats `{est_time_s}` and `{pierces}` need:
    /// every segment's length (an arc's atan), computed only when a
    /// template asks for one of them (most posts never do).
    stats_of: Option<(&'a CutPlan, JobInfo)>,
    /// A router's milling, cut before the plan: in `{est_time_s}`.
    pub(crate) milling: Option<&'a crate::mill::Toolpath>,
    /// The program, as bytes: only `&str`s and ASCII digits go in, so it is
    /// UTF-8 by construction, checked once at the end instead of per number.
    out: Bytes,
    next_n: Option<u64>,
    feed: String,
    feed_set: bool,
    /// A template was written: it may have changed the modal motion (a
    /// knife's `G1 Z0`), so the next move repeats its motion word.
    templated: bool,
    /// The template line being expanded (kept to reuse its allocation).
    words: String,
    /// A numbered block being put together (reused), and a comment's text.
    block: Bytes,
    scratch: String,
    /// A depth pass is being cut: a knife lifted over a sharp corner goes
    /// back down to the pass's depth.
    pub(crate) pass_depth: bool,
    /// The depth of the pass being written, mm ([`Writer::set_pass_z`]).
    pub(crate) pass_mm: f64,
    /// The machine is in `G91` (an incremental post's motion block set
    /// it): the next template with an axis word is preceded by `G90`.
    pub(crate) g91: bool,
}

impl<'a> Writer<'a> {
    pub(crate) fn new(post: &'a Post, plan: &'a CutPlan, job: &JobInfo) -> Self {
        let grid = Grid::new(post.decimals).with_trailing_zeros(post.trailing_zeros);
        let k = post.unit_scale();
        let feed = grid.fmt_mm(job.process.feed * k);
        let vars = vec![
            ("feed", feed.clone()),
            ("kerf", grid.fmt_mm(job.process.kerf * k)),
            ("pierce_delay", grid.fmt_mm(job.process.pierce_delay)),
            ("pierce_delay_ms", grid.fmt_mm(job.process.pierce_delay * 1000.0)),
            // Filled in by `fill_stats` when first used.
            ("est_time_s", String::new()),
            ("cuts", plan.cuts.len().to_string()),
            ("pierces", String::new()),
            ("program", job.program.to_string()),
            ("rapid_speed", grid.fmt_mm(job.process.rapid * k)),
            (
                "small_hole_feed",
                grid.fmt_mm(job.process.feed * job.process.small_hole.speed_pct / 100.0 * k),
            ),
            ("small_hole_speed", grid.fmt_mm(job.process.small_hole.speed_pct)),
            ("pierce_height", grid.fmt_mm(job.process.pierce_height * k)),
            ("cut_height", grid.fmt_mm(job.process.cut_height * k)),
            ("material", job.process.material.to_string()),
            ("switch_offset", grid.fmt_mm(post.switch_offset * k)),
            ("safe_height", grid.fmt_mm(post.safe_height * k)),
            ("probe_feed", grid.fmt_mm(post.probe_feed * k)),
            ("probe_distance", grid.fmt_mm(post.probe_distance * k)),
            // Set by the emitter before each depth pass.
            ("pass_z", String::new()),
            ("spindle_rpm", grid.fmt_mm(job.process.tool.spindle_rpm)),
            ("tool_number", job.process.tool.number.to_string()),
            ("plunge_feed", grid.fmt_mm(job.process.tool.plunge_feed * k)),
            ("retract_height", grid.fmt_mm(post.retract_height * k)),
        ];
        Writer {
            post,
            vars,
            stats_of: Some((plan, *job)),
            milling: None,
            // About 210 bytes a cut on the generated nests: reserved from
            // an estimate, the program is not copied as it grows.
            out: Bytes::with_capacity(4096 + 256 * plan.cuts.len()),
            next_n: post.line_numbers.map(|n| n.start as u64),
            feed: format!("F{feed}"),
            // A post whose header sets the feed its own way (QtPlasmaC's
            // `F#<_hal[plasmac.cut-feed-rate]>`) never gets our F word.
            feed_set: !post.feed_word,
            templated: false,
            words: String::new(),
            block: Bytes::default(),
            scratch: String::new(),
            pass_depth: false,
            pass_mm: 0.0,
            g91: false,
        }
    }
    /// `{est_time_s}` and `{pierces}` from the plan's stats, once.
    fn fill_stats(&mut self) {
        let Some((plan, job)) = self.stats_of.take() else {
            return;
        };
        let post = self.post;
        let grid = Grid::new(post.decimals).with_trailing_zeros(post.trailing_zeros);
        let st = plan.stats();
        for (name, val) in &mut self.vars {
            match *name {
                "est_time_s" => {
                    let t = super::router_time::job_time_s(plan, self.milling, Some(post), &job);
                    *val = grid.fmt_mm(t);
                }
                "pierces" => *val = st.pierces.to_string(),
                _ => {}
            }
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
                    if v == "plunge_feed" && self.post.feed_word {
                        // The plunge's F is modal: the next cut says its own.
                        self.feed_set = false;
                    }
                    if v == "est_time_s" || v == "pierces" {
                        self.fill_stats();
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
        self.pass_mm = z_mm;
        let grid = Grid::new(self.post.decimals).with_trailing_zeros(self.post.trailing_zeros);
        let v = grid.fmt_mm(z_mm * self.post.unit_scale());
        if let Some(slot) = self.vars.iter_mut().find(|(n, _)| *n == "pass_z") {
            slot.1 = v;
        }
    }
    /// A comment naming a router's tool after `what`: `what: T2 3.175 mm`,
    /// a V-bit's angle after (`, V 90deg`).
    pub(crate) fn tool_comment(&mut self, what: &str, t: &crate::process::Tool) {
        let grid = Grid::new(self.post.decimals);
        let v = if t.v_angle_deg > 0.0 {
            format!(", V {}deg", grid.fmt_mm(t.v_angle_deg))
        } else {
            String::new()
        };
        let text = format!("{what}: T{} {} mm{v}", t.number, grid.fmt_mm(t.diameter));
        self.comment(&text);
    }
    /// The template values of `tc` from now on (issue 43 §1: a tool
    /// change): its `{tool_number}`, `{spindle_rpm}` and `{plunge_feed}`.
    pub(crate) fn set_tool(&mut self, tc: &crate::process::MillTool) {
        let grid = Grid::new(self.post.decimals).with_trailing_zeros(self.post.trailing_zeros);
        let k = self.post.unit_scale();
        let t = &tc.tool;
        for (name, v) in [
            ("spindle_rpm", grid.fmt_mm(t.spindle_rpm)),
            ("tool_number", t.number.to_string()),
            ("plunge_feed", grid.fmt_mm(t.plunge_feed * k)),
        ] {
            if let Some(slot) = self.vars.iter_mut().find(|(n, _)| *n == name) {
                slot.1 = v;
            }
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
        self.out.extend_from_slice(line.as_bytes());
        self.out.push(b'\n');
    }
    pub(crate) fn raws(&mut self, lines: &[String]) {
        for l in lines {
            let s = self.expand(l);
            self.raw(&s);
        }
    }
    fn framed(&mut self, text: &[u8]) {
        let numbered = !self
            .post
            .unnumbered
            .iter()
            .any(|u| !u.is_empty() && text.starts_with(u.as_bytes()));
        self.out
            .extend_from_slice(self.post.block_prefix.as_bytes());
        if let (true, Some(n), Some(ln)) = (numbered, self.next_n, self.post.line_numbers) {
            // `N` and the number zero-padded to the width (as `{:0w$}`).
            self.out.push(b'N');
            let digits = n.checked_ilog10().map_or(1, |l| l as usize + 1);
            for _ in digits..ln.width as usize {
                self.out.push(b'0');
            }
            number::push_u64_bytes(&mut self.out, n);
            self.out
                .extend_from_slice(self.post.word_separator.as_bytes());
            self.next_n = Some(n + ln.step as u64);
        }
        self.out.extend_from_slice(text);
        self.out
            .extend_from_slice(self.post.block_suffix.as_bytes());
        self.out.push(b'\n');
    }
    /// One block of words.
    pub(crate) fn block(&mut self, words: &[String]) {
        let text = words.join(&self.post.word_separator);
        self.framed(text.as_bytes());
    }
    /// A block put together word by word: `word` adds one word (letters,
    /// then a grid number when given). Without line numbers (no block to
    /// look at before it is framed) the words go straight into the program;
    /// numbered, through a reused buffer.
    pub(crate) fn block_of(&mut self, build: impl FnOnce(&mut Words)) {
        let sep = &self.post.word_separator;
        if self.post.line_numbers.is_none() {
            self.out
                .extend_from_slice(self.post.block_prefix.as_bytes());
            let mut words = Words {
                text: &mut self.out,
                sep,
                any: false,
            };
            build(&mut words);
            self.out
                .extend_from_slice(self.post.block_suffix.as_bytes());
            self.out.push(b'\n');
            return;
        }
        let mut buf = std::mem::take(&mut self.block);
        buf.clear();
        build(&mut Words {
            text: &mut buf,
            sep,
            any: false,
        });
        self.framed(buf.as_slice());
        self.block = buf;
    }
    /// Template blocks.
    pub(crate) fn templates(&mut self, lines: &[String]) {
        let mut s = std::mem::take(&mut self.words);
        for l in lines {
            s.clear();
            self.expand_into(l, &mut s);
            if !s.trim().is_empty() {
                if self.g91 && has_axis_word(&s) {
                    // A template's heights are absolute (`G0 Z{safe_height}`).
                    self.g91 = false;
                    self.framed(b"G90");
                }
                self.framed(s.as_bytes());
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
        if is_sanitised(text) {
            // Our own words and numbers (a cut's comment): as they are.
            for part in [open, text, close, "\n"] {
                self.out.extend_from_slice(part.as_bytes());
            }
            return;
        }
        let mut s = std::mem::take(&mut self.scratch);
        s.clear();
        push_sanitised(&mut s, text);
        for part in [open, s.as_str(), close, "\n"] {
            self.out.extend_from_slice(part.as_bytes());
        }
        self.scratch = s;
    }
    /// The comment naming a cut (`cut 3 part 1 hole contour 7`; `-` for
    /// no part or contour), written straight into the program as
    /// [`Writer::comment`] writes it: our own words (`what` is one of the
    /// emitter's kinds) and numbers, at most ~90 bytes of letters, digits,
    /// blanks and '-', none at either end, which sanitising leaves as they
    /// are (one a cut: no text put together first, no scan of it).
    pub(crate) fn cut_comment(
        &mut self,
        cut: u64,
        part: Option<u64>,
        what: &str,
        contour: Option<u64>,
    ) {
        let (open, close) = match self.post.comments {
            CommentStyle::Parens => ("(", ")"),
            CommentStyle::Semicolon => ("; ", ""),
            CommentStyle::Dollar => ("$ ", ""),
            CommentStyle::None => return,
        };
        let out = &mut self.out;
        let number_or_dash = |out: &mut Bytes, n: Option<u64>| match n {
            Some(n) => number::push_u64_bytes(out, n),
            None => out.push(b'-'),
        };
        out.extend_from_slice(open.as_bytes());
        out.extend_from_slice(b"cut ");
        number::push_u64_bytes(out, cut);
        out.extend_from_slice(b" part ");
        number_or_dash(out, part);
        out.push(b' ');
        out.extend_from_slice(what.as_bytes());
        out.extend_from_slice(b" contour ");
        number_or_dash(out, contour);
        out.extend_from_slice(close.as_bytes());
        out.push(b'\n');
    }
    /// True when blocks written next by `self` and by `o` are the same:
    /// the same block number, modal feed, motion reset and pass depth
    /// (`{est_time_s}` and `{pierces}` are the plan's, filled in or not).
    pub(crate) fn same_course(&self, o: &Writer) -> bool {
        let pass_z = |w: &Writer| {
            w.vars
                .iter()
                .find(|(n, _)| *n == "pass_z")
                .map(|v| v.1.clone())
        };
        (
            self.next_n,
            self.feed_set,
            self.templated,
            self.pass_depth,
            self.g91,
        ) == (o.next_n, o.feed_set, o.templated, o.pass_depth, o.g91)
            && pass_z(self) == pass_z(o)
    }
    /// The program so far, taken out (the writer goes on with an empty
    /// one of `capacity` bytes).
    pub(crate) fn take_program(&mut self, capacity: usize) -> Vec<u8> {
        std::mem::replace(&mut self.out, Bytes::with_capacity(capacity)).into_vec()
    }
    /// The program so far is `out` (taken from a writer this one copied).
    pub(crate) fn set_program(&mut self, out: Vec<u8>) {
        self.out = Bytes::from_vec(out);
    }
    pub(crate) fn finish(self) -> String {
        // Always UTF-8 (see `out`); lossy rather than a panic all the same.
        String::from_utf8(self.out.into_vec())
            .unwrap_or_else(|e| String::from_utf8_lossy(e.as_bytes()).into_owned())
    }
}

/// True when a template line may move an axis (a letter of one: a
/// comment's letters may say so too, and cost a `G90` block only).
fn has_axis_word(line: &str) -> bool {
    line.bytes().any(|c| b"XYZABCUVWxyzabcuvw".contains(&c))
}

/// True when [`push_sanitised`] would write `text` unchanged: at most 120
/// bytes of printable ASCII without a delimiter, no blank at either end.
fn is_sanitised(text: &str) -> bool {
    let b = text.as_bytes();
    b.len() <= 120
        && b.first() != Some(&b' ')
        && b.last() != Some(&b' ')
        && b.iter().all(|&c| {
            matches!(c, b' '..=b'~') && !matches!(c, b'(' | b')' | b';' | b'%' | b'$' | b'#')
        })
}

/// The words of one block, separated by the post's separator.
pub(crate) struct Words<'s> {
    text: &'s mut Bytes,
    sep: &'s str,
    any: bool,
}

impl Words<'_> {
    /// A word of text (`G1`, `F2000`).
    pub(crate) fn text(&mut self, w: &str) {
        self.start();
        self.text.extend_from_slice(w.as_bytes());
    }
    /// A letter and a number on the grid (`X12.5`).
    pub(crate) fn num(&mut self, letter: &str, grid: &number::Grid, v: i64) {
        self.start();
        self.text.extend_from_slice(letter.as_bytes());
        grid.push_bytes(self.text, v);
    }
    fn start(&mut self) {
        if self.any {
            self.text.extend_from_slice(self.sep.as_bytes());
        }
        self.any = true;
    }
}

#[cfg(test)]
#[path = "writer_tests.rs"]
mod tests;
