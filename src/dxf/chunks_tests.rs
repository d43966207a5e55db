//! The drawing read on several threads, its ENTITIES cut into small chunks,
//! is the one read on one thread: every file of ../shared and generated ones.

use std::path::{Path, PathBuf};

use super::*;
use crate::dxf::{parse, ReadOptions};
use crate::par::Threads;

/// The drawing read on `threads`, as its Debug text (`pretty`: a field a
/// line, to say where two differ; else on one line, several times
/// shorter to make and compare for the corpus's megabyte files).
fn read(bytes: &[u8], threads: usize, pretty: bool) -> String {
    let o = ReadOptions {
        threads: Threads::new(threads),
        ..ReadOptions::DEFAULT
    };
    let d = parse(bytes, &o);
    if pretty {
        format!("{d:#?}")
    } else {
        format!("{d:?}")
    }
}

/// One thread's drawing (`one`, its Debug text on one line) against 2, 3
/// and 8 threads' with chunks of about `chunk` bytes; the most chunks
/// joined in one read.
fn same(name: &str, bytes: &[u8], one: &str, chunk: usize) -> usize {
    set_chunk_bytes(chunk);
    let mut joined = 0;
    for t in [2, 3, 8] {
        JOINED.with(|j| j.set(0));
        let many = read(bytes, t, false);
        joined = joined.max(JOINED.with(|j| j.get()));
        if one != many {
            let (one, many) = (read(bytes, 1, true), read(bytes, t, true));
            if let Ok(dir) = std::env::var("CHUNKS_DUMP") {
                let _ = std::fs::write(format!("{dir}/one.txt"), &one);
                let _ = std::fs::write(format!("{dir}/many.txt"), &many);
            }
            let at = one.lines().zip(many.lines()).position(|(a, b)| a != b);
            let line = |s: &str| at.and_then(|k| s.lines().nth(k)).unwrap_or("").to_owned();
            panic!(
                "{name}, {t} threads, chunks of {chunk} B: differs at Debug line {at:?}: {} vs {}",
                line(&one),
                line(&many)
            );
        }
    }
    set_chunk_bytes(MIN_CHUNK_BYTES);
    joined
}

fn dxf_files(dir: &Path, out: &mut Vec<PathBuf>) {
    let Ok(rd) = std::fs::read_dir(dir) else {
        return;
    };
    for e in rd.flatten() {
        let p = e.path();
        if p.is_dir() {
            dxf_files(&p, out);
        } else if p.extension().is_some_and(|x| x.eq_ignore_ascii_case("dxf")) {
            out.push(p);
        }
    }
}

#[test]
fn shared_corpus_and_fixtures_read_the_same_on_any_threads() {
    let shared = Path::new(env!("CARGO_MANIFEST_DIR")).join("../shared");
    let mut files = Vec::new();
    dxf_files(&shared.join("corpus"), &mut files);
    dxf_files(&shared.join("fixtures"), &mut files);
    files.sort();
    assert!(
        files.len() >= 50,
        "../shared not found: {} files",
        files.len()
    );
    let mut cut = 0;
    for f in &files {
        let bytes = std::fs::read(f).unwrap();
        let name = f.display().to_string();
        // Chunks of a few entities, and of about a kilobyte.
        let one = read(&bytes, 1, false);
        let n = same(&name, &bytes, &one, 64).max(same(&name, &bytes, &one, 4096));
        cut += usize::from(n > 1);
    }
    // Binary files and files of one entity are not cut; most others are.
    assert!(
        cut * 10 >= files.len() * 7,
        "{cut} of {} files cut",
        files.len()
    );
}

/// A generated sheet: parts on layers met for the first time anywhere in
/// it (and in two spellings), circles, polylines with VERTEX children,
/// points, INSERTs of a block, a tilted arc, paper-space and unknown
/// entities; places (lines) differ from entity to entity, so chunks
/// joined out of order, or places or layers not moved, show.
fn sheet(parts: usize, tail: &str) -> Vec<u8> {
    let mut s = String::from(
        "0\nSECTION\n2\nHEADER\n9\n$INSUNITS\n70\n4\n0\nENDSEC\n\
         0\nSECTION\n2\nTABLES\n0\nTABLE\n2\nLAYER\n0\nLAYER\n2\nCut\n62\n1\n70\n0\n\
         0\nLAYER\n2\nOff\n62\n-3\n70\n0\n0\nENDTAB\n0\nENDSEC\n\
         0\nSECTION\n2\nBLOCKS\n0\nBLOCK\n2\nHOLE\n10\n0\n20\n0\n\
         0\nCIRCLE\n8\n0\n10\n0\n20\n0\n40\n2\n0\nENDBLK\n0\nENDSEC\n\
         0\nSECTION\n2\nENTITIES\n",
    );
    for i in 0..parts {
        let (x, y) = ((i % 40) as f64 * 60.0, (i / 40) as f64 * 60.0 - 0.0);
        let layer = match i % 7 {
            0 => "Cut".to_owned(),
            1 => "Off".to_owned(),
            2 => format!("L{}", i / 50),
            3 => format!("l{}", i / 50),
            _ => "Cut".to_owned(),
        };
        s += &format!(
            "0\nLWPOLYLINE\n8\n{layer}\n90\n4\n70\n1\n10\n{x}\n20\n{y}\n10\n{}\n20\n{y}\n42\n0.3\n10\n{}\n20\n{}\n10\n{x}\n20\n{}\n",
            x + 50.0,
            x + 50.0,
            y + 40.0,
            y + 40.0
        );
        s += &format!(
            "0\nCIRCLE\n8\n{layer}\n10\n{}\n20\n{}\n40\n{}\n",
            x + 25.0,
            y + 20.0,
            1.0 + i as f64 * 1e-3
        );
        if i % 5 == 0 {
            s += &format!(
                "0\nPOLYLINE\n8\nCut\n66\n1\n70\n1\n0\nVERTEX\n8\nCut\n10\n{x}\n20\n{y}\n0\nVERTEX\n8\nCut\n10\n{}\n20\n{y}\n42\n1\n0\nVERTEX\n8\nCut\n10\n{}\n20\n{}\n0\nSEQEND\n8\nCut\n",
                x + 10.0,
                x + 10.0,
                y + 5.0
            );
        }
        if i % 9 == 0 {
            s += &format!("0\nPOINT\n8\n{layer}\n10\n{}\n20\n{}\n", x + 1.0, y + 1.0);
            s += &format!(
                "0\nINSERT\n8\n{layer}\n2\nHOLE\n10\n{}\n20\n{}\n",
                x + 40.0,
                y + 30.0
            );
        }
        if i % 31 == 0 {
            s += &format!("0\nARC\n8\nCut\n10\n{x}\n20\n{y}\n40\n3\n50\n0\n51\n90\n210\n0.1\n220\n0\n230\n0.99\n");
            s += "0\nHATCH\n8\nCut\n0\nTEXT\n8\nCut\n67\n1\n1\n0\n";
        }
    }
    s += tail;
    s.into_bytes()
}

#[test]
fn generated_sheets_read_the_same_on_any_threads() {
    let end = "0\nENDSEC\n0\nEOF\n";
    let cases: [(&str, Vec<u8>); 5] = [
        ("sheet", sheet(400, end)),
        // More after the entities: an OBJECTS section the chunks run into.
        (
            "objects",
            sheet(
                300,
                &format!(
                    "0\nENDSEC\n0\nSECTION\n2\nOBJECTS\n{}0\nENDSEC\n0\nEOF\n",
                    "0\nDICTIONARY\n5\nC\n".repeat(800)
                ),
            ),
        ),
        // Truncated: no ENDSEC, no EOF; and in the middle of a pair.
        ("no end", sheet(300, "")),
        ("cut short", sheet(300, "0\nLINE\n10\n")),
        // A bad group code in the middle, after which nothing is read.
        (
            "bad code",
            [sheet(150, "0\nLINE\nNOT A CODE\n1\n"), sheet(150, end)].concat(),
        ),
    ];
    for (name, bytes) in &cases {
        for chunk in [100, 700, 5000] {
            let n = same(name, bytes, &read(bytes, 1, false), chunk);
            assert!(n > 1, "{name}: not cut");
        }
    }
}

#[test]
fn warnings_after_the_first_chunk_keep_their_lines() {
    // A SPLINE that reads with a note, an undefined block: warnings with
    // line numbers, near the end of the entities.
    let tail = "0\nINSERT\n8\nCut\n2\nNOPE\n10\n0\n20\n0\n\
                0\nLWPOLYLINE\n8\nCut\n90\n1\n10\n0\n20\n0\n0\nENDSEC\n0\nEOF\n";
    let bytes = sheet(300, tail);
    let text = read(&bytes, 1, false);
    assert!(text.contains("block-undefined") && text.contains("entity-skipped"));
    assert!(same("warnings", &bytes, &text, 300) > 1);
}

#[test]
fn cuts_fall_on_entity_starts_only() {
    let b = b"0\nLINE\n8\n0\n10\n0\n0\nVERTEX\n0\nSEQEND\n0\n3DFACE\n";
    // The line "0" after 8 is a value (followed by a code): not a cut;
    // VERTEX and SEQEND belong to the entity before.
    assert_eq!(entity_start(b, 0, b.len()), Some(b.len() - 9));
    assert_eq!(entity_start(b, b.len() - 9, b.len()), None);
    let crlf = b"0\r\nLINE\r\n 0\r\nCIRCLE\r\n";
    assert_eq!(entity_start(crlf, 0, crlf.len()), Some(9));
}

#[test]
fn the_segment_budget_runs_out_where_it_does_on_one_thread() {
    // Budgets that run out in the first chunk, in a later one, at a chunk's
    // end, inside a polyline, and not at all.
    let bytes = sheet(300, "0\nENDSEC\n0\nEOF\n");
    let all = {
        let d = parse(&bytes, &ReadOptions::DEFAULT).unwrap();
        d.entities.iter().map(|e| e.segments.len()).sum::<usize>()
    };
    for budget in [3, 50, 500, 1001, all / 2, all - 5, all, all + 1, all + 100] {
        crate::dxf::reader::TEST_BUDGET.with(|b| b.set(budget));
        same(&format!("budget {budget}"), &bytes, &read(&bytes, 1, false), 300);
    }
    crate::dxf::reader::TEST_BUDGET.with(|b| b.set(crate::dxf::MAX_SEGMENTS));
}

#[test]
fn in_order_hands_results_in_index_order_and_stops_when_asked() {
    for t in 1..=4 {
        for n in [1, 2, 7, 40] {
            let mut got = Vec::new();
            in_order(
                n,
                Threads::new(t),
                |i| i * 10,
                |i, r| {
                    got.push((i, r));
                    true
                },
            );
            assert_eq!(
                got,
                (0..n).map(|i| (i, i * 10)).collect::<Vec<_>>(),
                "t {t} n {n}"
            );
            let mut got = Vec::new();
            in_order(
                n,
                Threads::new(t),
                |i| i,
                |i, _| {
                    got.push(i);
                    i < n / 2
                },
            );
            assert_eq!(got, (0..=n / 2).collect::<Vec<_>>(), "t {t} n {n}");
        }
    }
}
