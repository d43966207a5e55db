//! A G-code reader: program text → the moves a machine would make, so the
//! page can draw any program (ours or another's) and tests can prove that
//! what is downloaded retraces the plan (paper 001 §8, paper 004: simulate
//! and verify the program, not the intention).
//!
//! Understood: G0/G1/G2/G3 (modal), I/J incremental (G91.1, the default) or
//! absolute (G90.1), R arcs, G20/G21, G90/G91, G4, N words, `( )` and `;`
//! comments, M3/M4 (torch on) and M5 (off), annex H's `: …$` framing and `$`
//! lines. Other words are skipped with a warning; no text makes it panic.

use serde::Serialize;

use crate::geom::{arc_pieces, Point, Segment};
use crate::text;
use crate::warning::Text;

/// One move, in mm.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum BackplotMove {
    /// G0.
    Rapid {
        /// Start.
        from: Point,
        /// End.
        to: Point,
    },
    /// G1.
    Line {
        /// Start.
        from: Point,
        /// End.
        to: Point,
        /// Torch on (M3/M4 given, no M5 since).
        torch: bool,
    },
    /// G2 or G3.
    Arc {
        /// Start.
        from: Point,
        /// End.
        to: Point,
        /// Centre.
        center: Point,
        /// G3.
        ccw: bool,
        /// Torch on.
        torch: bool,
    },
}

impl BackplotMove {
    /// Torch state: None for a rapid, else whether the torch is on.
    pub fn torch(&self) -> Option<bool> {
        match *self {
            BackplotMove::Rapid { .. } => None,
            BackplotMove::Line { torch, .. } | BackplotMove::Arc { torch, .. } => Some(torch),
        }
    }

    /// The move as segments (arcs of at most 180°; an arc whose ends
    /// coincide is a full circle, as RS274 reads it).
    pub fn segments(&self) -> Vec<Segment> {
        match *self {
            BackplotMove::Rapid { from, to } | BackplotMove::Line { from, to, .. } => {
                vec![Segment::line(from, to)]
            }
            BackplotMove::Arc {
                from,
                to,
                center,
                ccw,
                ..
            } => {
                let a0 = (from.y - center.y).atan2(from.x - center.x);
                let a1 = (to.y - center.y).atan2(to.x - center.x);
                let tau = std::f64::consts::TAU;
                let mut sweep = if ccw {
                    (a1 - a0).rem_euclid(tau)
                } else {
                    -(a0 - a1).rem_euclid(tau)
                };
                if sweep.abs() < 1e-9 {
                    sweep = if ccw { tau } else { -tau };
                }
                arc_pieces(center, from.dist(center), a0, sweep)
            }
        }
    }
}

/// Something the reader skipped, with its 1-based line.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct BackplotWarning {
    /// Line number in the text.
    pub line: usize,
    /// Stable short name of the kind ("word-skipped"), for scripts.
    pub code: &'static str,
    /// What was not understood, in English.
    pub message: String,
    /// The same in every language (`{"en": …, "pt-BR": …}`).
    pub messages: Text,
}

impl BackplotWarning {
    fn new(line: usize, code: &'static str, text: Text) -> Self {
        BackplotWarning {
            line,
            code,
            message: text.en.clone(),
            messages: text,
        }
    }
}

/// What the reader made of a program.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct Backplot {
    /// Moves in program order.
    pub moves: Vec<BackplotMove>,
    /// Skipped words (at most [`MAX_WARNINGS`]).
    pub warnings: Vec<BackplotWarning>,
}

/// Warnings kept; more are counted in the last one.
pub const MAX_WARNINGS: usize = 100;

struct Machine {
    pos: Point,
    motion: u8,
    inch: bool,
    incremental: bool,
    ij_absolute: bool,
    torch: bool,
}

/// Words of one block: (letter, value); an unreadable piece is an Err.
fn words(text: &str) -> Vec<Result<(char, f64), Text>> {
    let b = text.as_bytes();
    let mut out = Vec::new();
    let mut i = 0;
    while i < b.len() {
        let c = b[i] as char;
        if c.is_ascii_whitespace() {
            i += 1;
            continue;
        }
        if !(c.is_ascii_alphabetic() || c == '$') {
            let c = c.escape_debug();
            out.push(Err(text!("'{c}' is not a word"; "'{c}' não é uma palavra")));
            i += 1;
            continue;
        }
        let letter = c.to_ascii_uppercase();
        let mut j = i + 1;
        while j < b.len() && b[j] == b' ' {
            j += 1;
        }
        let start = j;
        if j < b.len() && (b[j] == b'-' || b[j] == b'+') {
            j += 1;
        }
        let digits = j;
        while j < b.len() && (b[j].is_ascii_digit() || b[j] == b'.') {
            j += 1;
        }
        let num = text.get(start..j).unwrap_or("");
        match num.parse::<f64>() {
            Ok(v) if j > digits && v.is_finite() => out.push(Ok((letter, v))),
            _ => {
                // Skip the rest of an unreadable word (CYC10PRAQUECIMENTO…).
                while j < b.len() && b[j].is_ascii_alphanumeric() {
                    j += 1;
                }
                let w = text.get(i..j.max(i + 1)).unwrap_or("?");
                out.push(Err(text!("'{w}' is not a word"; "'{w}' não é uma palavra")));
            }
        }
        i = j.max(i + 1);
    }
    out
}

/// The block text without comments and framing (None: nothing to read).
fn strip(line: &str) -> Option<String> {
    let mut t = line.trim();
    if t.starts_with('$') || t.starts_with('#') || t.starts_with('%') || t.is_empty() {
        return None;
    }
    if let Some(r) = t.strip_prefix(':') {
        t = r.trim_start();
    }
    if let Some(r) = t.strip_suffix('$') {
        t = r;
    }
    // Block delete, and annex H's program number `: %52100$`.
    if t.starts_with('/') || t.starts_with('%') {
        return None;
    }
    let mut s = String::with_capacity(t.len());
    let mut depth = 0usize;
    for c in t.chars() {
        match c {
            '(' => depth += 1,
            ')' => depth = depth.saturating_sub(1),
            ';' if depth == 0 => break,
            c if depth == 0 => s.push(c),
            _ => {}
        }
    }
    Some(s)
}

/// Reads a program.
pub fn backplot(text: &str) -> Backplot {
    let mut bp = Backplot::default();
    let mut dropped = 0usize;
    let mut m = Machine {
        pos: Point::new(0.0, 0.0),
        motion: 0,
        inch: false,
        incremental: false,
        ij_absolute: false,
        torch: false,
    };
    let mut warn = |bp: &mut Backplot, line: usize, code: &'static str, message: Text| {
        if bp.warnings.len() < MAX_WARNINGS {
            bp.warnings.push(BackplotWarning::new(line, code, message));
        } else {
            dropped += 1;
        }
    };
    for (n, raw) in text.lines().enumerate() {
        let line = n + 1;
        let Some(block) = strip(raw) else { continue };
        let mut motion_word = false;
        let (mut x, mut y, mut i, mut j, mut r) = (None, None, None, None, None);
        let mut dwell = false;
        for w in words(&block) {
            let (letter, v) = match w {
                Ok(w) => w,
                Err(e) => {
                    warn(&mut bp, line, "not-a-word", e);
                    continue;
                }
            };
            match letter {
                'G' => {
                    let code = (v * 10.0).round() as i64;
                    match code {
                        0 | 10 | 20 | 30 => {
                            m.motion = (code / 10) as u8;
                            motion_word = true;
                        }
                        40 => dwell = true,
                        200 => m.inch = true,
                        210 => m.inch = false,
                        900 => m.incremental = false,
                        910 => m.incremental = true,
                        901 => m.ij_absolute = true,
                        911 => m.ij_absolute = false,
                        // Plane, compensation off, modes that do not move.
                        170 | 400 | 490 | 540 | 640 | 800 | 921 | 940 | 970 => {}
                        _ => warn(
                            &mut bp,
                            line,
                            "g-skipped",
                            text!("G{v} skipped"; "G{v} ignorado"),
                        ),
                    }
                }
                'M' => match v.round() as i64 {
                    3 | 4 | 7 => m.torch = true,
                    5 | 8 => m.torch = false,
                    _ => {}
                },
                'X' => x = Some(v),
                'Y' => y = Some(v),
                'I' => i = Some(v),
                'J' => j = Some(v),
                'R' => r = Some(v),
                // Block numbers, feed, power, dwell time, other axes, spindle select.
                'N' | 'F' | 'S' | 'P' | 'Z' | 'A' | 'B' | 'C' | 'Q' | '$' => {}
                c => warn(
                    &mut bp,
                    line,
                    "word-skipped",
                    text!("word {c} skipped"; "palavra {c} ignorada"),
                ),
            }
        }
        if dwell || (x.is_none() && y.is_none() && !motion_word) {
            continue;
        }
        if x.is_none() && y.is_none() && i.is_none() && j.is_none() {
            continue;
        }
        let k = if m.inch { 25.4 } else { 1.0 };
        let to = if m.incremental {
            Point::new(
                m.pos.x + x.unwrap_or(0.0) * k,
                m.pos.y + y.unwrap_or(0.0) * k,
            )
        } else {
            Point::new(x.map_or(m.pos.x, |v| v * k), y.map_or(m.pos.y, |v| v * k))
        };
        let from = m.pos;
        let mv = match m.motion {
            0 => BackplotMove::Rapid { from, to },
            1 => BackplotMove::Line {
                from,
                to,
                torch: m.torch,
            },
            _ => {
                let ccw = m.motion == 3;
                let center = if let Some(r) = r {
                    match r_centre(from, to, r * k, ccw) {
                        Some(c) => c,
                        None => {
                            warn(
                                &mut bp,
                                line,
                                "r-arc-unreachable",
                                text!("R arc cannot reach its end";
                                      "o arco R não alcança seu ponto final"),
                            );
                            m.pos = to;
                            continue;
                        }
                    }
                } else if m.ij_absolute {
                    Point::new(i.unwrap_or(from.x / k) * k, j.unwrap_or(from.y / k) * k)
                } else {
                    Point::new(from.x + i.unwrap_or(0.0) * k, from.y + j.unwrap_or(0.0) * k)
                };
                BackplotMove::Arc {
                    from,
                    to,
                    center,
                    ccw,
                    torch: m.torch,
                }
            }
        };
        m.pos = to;
        bp.moves.push(mv);
    }
    if dropped > 0 {
        bp.warnings.push(BackplotWarning::new(
            0,
            "more-warnings",
            text!("{dropped} more warnings"; "mais {dropped} avisos"),
        ));
    }
    bp
}

/// Centre of an R arc (negative R: the longer way, RS274).
fn r_centre(a: Point, b: Point, r: f64, ccw: bool) -> Option<Point> {
    let d = a.dist(b);
    if d == 0.0 || r.abs() * 2.0 < d * (1.0 - 1e-6) {
        return None;
    }
    let h = (r * r - d * d / 4.0).max(0.0).sqrt();
    let mid = a.add(b).scale(0.5);
    let n = b.sub(a).perp().scale(1.0 / d);
    // Centre on the left of a→b for a short CCW arc.
    let left = ccw == (r > 0.0);
    Some(mid.add(n.scale(if left { h } else { -h })))
}

#[cfg(test)]
#[path = "backplot_tests.rs"]
mod tests;
