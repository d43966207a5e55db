//! One pass over a file's pairs, ASCII or binary: HEADER, TABLES and
//! BLOCKS kept, ENTITIES streamed through the reader, other sections
//! skipped, and a truncated file read up to its end with a warning.

use super::binary;
use super::pairs::{AsciiPairs, Pair};
use super::reader::Reader;
use super::stream::Stream;
use super::walk::Scratch;
use super::{bad_code_text, place_text, Drawing, DxfError, Place, ReadOptions};
use crate::geom::Affine;
use crate::text;
use crate::warning::Warning;

/// Reads the file once, in the units `options` or the file give (mm when assumed).
pub(super) fn parse_in(bytes: &[u8], options: &ReadOptions) -> Result<Drawing, DxfError> {
    if bytes.iter().all(|b| b.is_ascii_whitespace()) {
        return Err(DxfError::Empty);
    }
    let binary = bytes.starts_with(binary::SENTINEL);
    let run = |stream_entities: bool| {
        if binary {
            read(
                binary::BinaryPairs::new(bytes),
                true,
                options,
                stream_entities,
                |it| it.truncated,
                || Place::Byte(bytes.len()),
            )
        } else {
            read(
                AsciiPairs::new(bytes),
                false,
                options,
                stream_entities,
                |it| it.truncated,
                || Place::Line(count_lines(bytes)),
            )
        }
    };
    // A HEADER, TABLES or BLOCKS section after the entities (no writer seen
    // does this) needs every pair kept: read again that way.
    match run(true) {
        Read::Late => match run(false) {
            Read::Done(r) => *r,
            Read::Late => Err(DxfError::Empty),
        },
        Read::Done(r) => *r,
    }
}

enum Read {
    Done(Box<Result<Drawing, DxfError>>),
    Late,
}

/// One pass over the pairs. HEADER, TABLES and BLOCKS are kept as pairs
/// (`pre`); other sections are skipped; ENTITIES streams through the reader
/// (or, when `stream_entities` is false, is kept and walked at the end).
fn read<'a, I>(
    it: I,
    binary: bool,
    options: &ReadOptions,
    stream_entities: bool,
    truncated: impl Fn(&I) -> bool,
    end: impl Fn() -> Place,
) -> Read
where
    I: super::pairs::Source<'a>,
{
    let mut s = Stream::new(it);
    let mut r = Reader::new(binary, options);
    let mut pre: Vec<Pair<'a>> = Vec::new();
    let mut sc = Scratch::default();
    let (mut tables, mut blocks, mut ents) = (None, None, None);
    let (mut prepared, mut saw_section, mut saw_eof) = (false, false, false);
    while let Some(p) = s.next_pair() {
        if p.code != 0 {
            continue;
        }
        if p.is("EOF") {
            saw_eof = true;
            break;
        }
        if !p.is("SECTION") {
            if saw_section {
                continue;
            }
            // Entities before any SECTION: a file of bare entities.
            s.push_back(p);
            if !prepared {
                r.prepare(&pre, tables, blocks);
                prepared = true;
            }
            if stream_entities {
                r.stream_entities(&pre, &mut s, &mut sc);
            } else {
                let from = pre.len();
                keep_section(&mut s, &mut pre, true);
                ents = Some((from, pre.len()));
            }
            continue;
        }
        saw_section = true;
        let name = match s.peek() {
            Some(n) if n.code == 2 => {
                s.next_pair();
                n.trimmed()
            }
            _ => b"",
        };
        match name {
            b"HEADER" | b"TABLES" | b"BLOCKS" => {
                if prepared {
                    if stream_entities {
                        return Read::Late;
                    }
                    let section = String::from_utf8_lossy(name);
                    r.d.warnings.push(Warning::new(
                        "late-section",
                        text!("a {section} section after the entities was ignored";
                              "uma seção {section} depois das entidades foi ignorada"),
                    ));
                    skip_section(&mut s);
                    continue;
                }
                let from = pre.len();
                keep_section(&mut s, &mut pre, false);
                let range = Some((from, pre.len()));
                match name {
                    b"HEADER" => r.read_header(&pre, from, pre.len()),
                    b"TABLES" => tables = range,
                    _ => blocks = range,
                }
            }
            b"ENTITIES" if stream_entities => {
                if !prepared {
                    r.prepare(&pre, tables, blocks);
                    prepared = true;
                }
                r.stream_entities_par(&pre, &mut s, &mut sc);
            }
            b"ENTITIES" => {
                let from = pre.len();
                keep_section(&mut s, &mut pre, false);
                ents = Some((from, pre.len()));
            }
            _ => skip_section(&mut s),
        }
    }
    if !prepared {
        r.prepare(&pre, tables, blocks);
    }
    if let Some((f, t)) = ents {
        let m = Affine::scale(r.scale);
        r.walk(&pre, f, t, &m, None, true, &mut Vec::new());
    }
    drop(sc);
    let cut_short = truncated(s.inner());
    let bad = s.bad.take();
    if let Some(e) = &bad {
        if !s.any {
            return Read::Done(Box::new(Err(DxfError::NotDxf(e.clone()))));
        }
    }
    let mut d = r.finish();
    if let Some(e) = bad {
        if d.entities.is_empty() && d.counts.is_empty() {
            return Read::Done(Box::new(Err(DxfError::Malformed(e))));
        }
        let e = bad_code_text(&e);
        d.warnings.push(Warning::new(
            "read-stopped",
            text!("reading stopped at {}; the rest of the file was ignored", e.en;
                  "a leitura parou em {}; o restante do arquivo foi ignorado", e.pt),
        ));
    } else if cut_short || !saw_eof {
        // A file cut off in transfer (a partial download, a full disk) still
        // reads as a valid drawing of its first parts: say so loudly.
        let at = place_text(end());
        let why = if cut_short {
            text!("it ends in the middle of a group"; "ele termina no meio de um grupo")
        } else {
            text!("it has no EOF marker"; "ele não tem a marca EOF")
        };
        d.warnings.push(Warning::new(
            "file-truncated",
            text!("the file looks truncated: {}; it was read up to its end at {}, and parts after that point are missing", why.en, at.en;
                  "o arquivo parece truncado: {}; foi lido até o fim, em {}, e as peças depois desse ponto faltam", why.pt, at.pt),
        ));
    }
    Read::Done(Box::new(Ok(d)))
}

/// Lines in a text file (the last one counts without its line end).
fn count_lines(bytes: &[u8]) -> usize {
    let n = bytes.iter().filter(|&&b| b == b'\n').count();
    n + usize::from(!bytes.ends_with(b"\n"))
}

/// Appends a section's pairs to `pre`, up to its ENDSEC (consumed) or EOF
/// (left); bare entities (`bare`) also end at a SECTION (left).
fn keep_section<'a, I>(s: &mut Stream<'a, I>, pre: &mut Vec<Pair<'a>>, bare: bool)
where
    I: super::pairs::Source<'a>,
{
    while let Some(p) = s.next_pair() {
        if p.code == 0 && (p.is("ENDSEC") || p.is("EOF") || (bare && p.is("SECTION"))) {
            if !p.is("ENDSEC") {
                s.push_back(p);
            }
            return;
        }
        pre.push(p);
    }
}

/// Reads past a section not needed (CLASSES, OBJECTS, THUMBNAILIMAGE, …).
fn skip_section<'a, I>(s: &mut Stream<'a, I>)
where
    I: super::pairs::Source<'a>,
{
    while let Some(p) = s.next_pair() {
        if p.code == 0 && (p.is("ENDSEC") || p.is("EOF")) {
            if p.is("EOF") {
                s.push_back(p);
            }
            return;
        }
    }
}
