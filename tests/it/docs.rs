//! The manual stays true to the repository (issue 40): every relative link
//! in README.md and docs/*.md reaches a file, and a `#heading` link a
//! heading of that Markdown file; every option docs/cli.md names is one
//! `kerfcam --help` or `kerfcam nest --help` names, and every option they
//! name is in docs/cli.md, so an option added without its documentation
//! (or documentation of one that is gone) fails here.
#![cfg(not(target_arch = "wasm32"))]

use std::collections::BTreeSet;
use std::fs;
use std::path::{Path, PathBuf};

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// README.md and every docs/*.md, sorted.
fn manual() -> Vec<PathBuf> {
    let mut files = vec![root().join("README.md")];
    let mut docs: Vec<PathBuf> = fs::read_dir(root().join("docs"))
        .expect("docs/ exists")
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "md"))
        .collect();
    docs.sort();
    files.extend(docs);
    files
}

/// The lines of `md` outside fenced code blocks.
fn prose(md: &str) -> impl Iterator<Item = &str> {
    let mut fenced = false;
    md.lines().filter(move |l| {
        if l.trim_start().starts_with("```") {
            fenced = !fenced;
            return false;
        }
        !fenced
    })
}

/// `line` with its code spans (`` `…` ``) blanked, so a `[a](b)` quoted
/// as code is not taken for a link.
fn without_code(line: &str) -> String {
    let mut out = String::new();
    let mut code = false;
    for c in line.chars() {
        if c == '`' {
            code = !code;
            out.push(' ');
        } else {
            out.push(if code { ' ' } else { c });
        }
    }
    out
}

/// Every link target of `md`: inline `[text](target "title")` (images
/// too) and reference definitions `[label]: target`.
fn links(md: &str) -> Vec<String> {
    let mut out = Vec::new();
    for line in prose(md) {
        let line = without_code(line);
        let t = line.trim_start();
        if t.starts_with('[') {
            if let Some((_, rest)) = t.split_once("]: ") {
                out.push(rest.split_whitespace().next().unwrap_or("").to_string());
                continue;
            }
        }
        let mut rest = line.as_str();
        while let Some(i) = rest.find("](") {
            let after = &rest[i + 2..];
            let Some(end) = after.find(')') else { break };
            let target = after[..end].split_whitespace().next().unwrap_or("");
            out.push(target.trim_matches(['<', '>']).to_string());
            rest = &after[end..];
        }
    }
    out
}

/// GitHub's anchor of a heading: lower case, punctuation dropped (letters,
/// digits, `-` and `_` kept), spaces as `-`.
fn slug(heading: &str) -> String {
    heading
        .trim()
        .to_lowercase()
        .chars()
        .filter_map(|c| match c {
            ' ' => Some('-'),
            c if c.is_alphanumeric() || c == '-' || c == '_' => Some(c),
            _ => None,
        })
        .collect()
}

/// The anchors of `md`'s headings; a repeated one gets `-1`, `-2`… as on GitHub.
fn anchors(md: &str) -> BTreeSet<String> {
    let mut out = BTreeSet::new();
    for line in prose(md) {
        let level = line.chars().take_while(|&c| c == '#').count();
        if (1..=6).contains(&level) && line[level..].starts_with(' ') {
            let base = slug(&line[level..]);
            let mut anchor = base.clone();
            let mut n = 0;
            while out.contains(&anchor) {
                n += 1;
                anchor = format!("{base}-{n}");
            }
            out.insert(anchor);
        }
    }
    out
}

/// What is wrong with the links of the Markdown file `file`: targets that
/// are not there, and anchors no heading of their Markdown file has.
fn broken_links(file: &Path) -> Vec<String> {
    let md = fs::read_to_string(file).unwrap();
    let dir = file.parent().unwrap();
    let mut bad = Vec::new();
    for target in links(&md) {
        if target.is_empty() {
            bad.push("an empty link".to_string());
            continue;
        }
        if target.contains("://") || target.starts_with("mailto:") {
            continue; // not a file of the repository
        }
        let (path, anchor) = match target.split_once('#') {
            Some((p, a)) => (p, Some(a)),
            None => (target.as_str(), None),
        };
        let linked = if path.is_empty() {
            file.to_path_buf()
        } else {
            dir.join(path)
        };
        if !linked.exists() {
            bad.push(format!("{target}: no {}", linked.display()));
            continue;
        }
        if let Some(anchor) = anchor {
            if linked.extension().is_some_and(|e| e == "md") {
                let text = fs::read_to_string(&linked).unwrap();
                if !anchors(&text).contains(anchor) {
                    bad.push(format!(
                        "{target}: no heading #{anchor} in {}",
                        linked.display()
                    ));
                }
            }
        }
    }
    bad
}

#[test]
fn every_relative_link_reaches_its_file_and_heading() {
    let files = manual();
    assert!(files.len() > 2, "README.md and docs/*.md: {files:?}");
    let mut bad = Vec::new();
    let mut checked = 0;
    for f in &files {
        checked += links(&fs::read_to_string(f).unwrap()).len();
        for b in broken_links(f) {
            bad.push(format!(
                "{}: {b}",
                f.strip_prefix(root()).unwrap().display()
            ));
        }
    }
    assert!(
        checked > 10,
        "only {checked} links found: is the reader right?"
    );
    assert!(bad.is_empty(), "broken links:\n{}", bad.join("\n"));
}

#[test]
fn a_broken_link_and_a_missing_heading_are_found() {
    let dir = std::env::temp_dir().join(format!("kerfcam-docs-{}", std::process::id()));
    fs::create_dir_all(&dir).unwrap();
    let other = dir.join("other.md");
    fs::write(&other, "# Other page\n\n## The units, one rule\n").unwrap();
    let page = dir.join("page.md");
    fs::write(
        &page,
        "# Page\n\nSee [it](other.md#the-units-one-rule), [top](#page), \
         ![pic](other.md \"a title\"), `[code](nowhere.md)`, [web](https://example.org/x).\n\
         ```sh\n[fenced](nowhere.md)\n```\n\
         Bad: [gone](gone.md) and [heading](other.md#no-such-heading) and [here](#nope).\n\
         [ref]: gone-too.md\n",
    )
    .unwrap();
    let bad = broken_links(&page);
    fs::remove_dir_all(&dir).unwrap();
    assert_eq!(bad.len(), 4, "{bad:#?}");
    for b in ["gone.md", "#no-such-heading", "#nope", "gone-too.md"] {
        assert!(
            bad.iter().any(|x| x.contains(b)),
            "{b} not found in {bad:#?}"
        );
    }
}

#[test]
fn anchors_are_githubs() {
    let a = anchors("# kerfcam\n## The page, in ten lines\n## `--json`: the report\n## The page, in ten lines\n");
    let want: BTreeSet<String> = [
        "kerfcam",
        "the-page-in-ten-lines",
        "--json-the-report",
        "the-page-in-ten-lines-1",
    ]
    .map(String::from)
    .into();
    assert_eq!(a, want);
}

/// Every `-x` and `--word` option `text` names (the rule of src/cli.rs's
/// `options_in`: the name starts with a letter).
fn options(text: &str) -> BTreeSet<String> {
    text.split(|c: char| !(c.is_ascii_alphanumeric() || c == '-'))
        .filter(|w| {
            let name = w.trim_start_matches('-');
            let dashes = w.len() - name.len();
            ((dashes == 2 && name.len() > 1) || (dashes == 1 && name.len() == 1))
                && name.starts_with(|c: char| c.is_ascii_alphabetic())
        })
        .map(String::from)
        .collect()
}

fn help(args: &[&str]) -> String {
    let o = std::process::Command::new(env!("CARGO_BIN_EXE_kerfcam"))
        .args(args)
        .output()
        .expect("kerfcam runs");
    assert!(o.status.success(), "kerfcam {args:?}: {o:?}");
    String::from_utf8(o.stdout).unwrap()
}

/// What the manual names and the help does not, and the reverse.
fn differences(manual: &BTreeSet<String>, help: &BTreeSet<String>) -> Vec<String> {
    let mut out: Vec<String> = manual
        .difference(help)
        .map(|o| format!("{o}: in docs/cli.md, in no --help (gone, or a typo?)"))
        .collect();
    out.extend(
        help.difference(manual)
            .map(|o| format!("{o}: in --help, not in docs/cli.md (document it)")),
    );
    out
}

#[test]
fn docs_cli_names_every_option_of_the_help_and_no_other() {
    let mut from_help = options(&help(&["--help"]));
    let nest = options(&help(&["nest", "--help"]));
    assert!(
        from_help.contains("--kerf") && nest.contains("--sheet"),
        "{from_help:?} {nest:?}"
    );
    from_help.extend(nest);
    let doc = options(&fs::read_to_string(root().join("docs/cli.md")).unwrap());
    let diff = differences(&doc, &from_help);
    assert!(
        diff.is_empty(),
        "docs/cli.md and the help differ:\n{}",
        diff.join("\n")
    );
}

#[test]
fn an_undocumented_option_is_found() {
    let help = options("  --kerf MM   kerf\n  -o, --output FILE\n  --tab-at X,Y  a tab\n");
    let doc = options("`--kerf` and `-o`/`--output` (lower-left, G-code, ---, -1, x-y)");
    assert_eq!(
        differences(&doc, &help),
        ["--tab-at: in --help, not in docs/cli.md (document it)"]
    );
    let doc = options("`--kerf`, `--output`, `-o`, `--tab-at`, `--kref`");
    assert_eq!(
        differences(&doc, &help),
        ["--kref: in docs/cli.md, in no --help (gone, or a typo?)"]
    );
}
