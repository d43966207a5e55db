//! The crate's modules import one another without cycles
//! (docs/architecture.md, "Keeping the shape"). Every path a source file
//! names (`use crate::a::B`, `super::b::f(…)`, `b::C` through an import)
//! is followed through imports and re-exports to the file that defines
//! the item. Such a reference from
//! file `a` to file `b` makes the module holding `a` depend on the one
//! holding `b`, seen from their nearest common module: its child on `a`'s
//! side depends on its child on `b`'s side (a child with all its
//! submodules is one). The children of every module must form no cycle.
//!
//! A module's own file and its submodules may name each other (children
//! use `super::Point`, a `mod.rs` calls or re-exports `child::f`): the
//! parent's file is its table of contents and its children's shared
//! ground. `#[cfg(test)]` modules are left out: tests reach up to the whole
//! pipeline. Other cfg attributes are ignored, so the wasm-only modules are
//! checked as well. The source is read as tokens (comments and strings
//! dropped); each cycle found is printed with the references that close it.
#![cfg(not(target_arch = "wasm32"))]

use std::collections::{BTreeMap, BTreeSet, HashMap, VecDeque};
use std::fs;
use std::path::{Path, PathBuf};

#[derive(Clone, Debug, PartialEq)]
enum Tok {
    Ident(String),
    Str(String),
    PathSep,
    Punct(char),
}

#[derive(Clone, Debug)]
struct Token {
    tok: Tok,
    line: usize,
}

/// Rust source as identifiers, string literals, `::` and single
/// punctuation; comments, numbers, chars and lifetimes dropped.
fn lex(src: &str) -> Vec<Token> {
    let c: Vec<char> = src.chars().collect();
    let (mut out, mut i, mut line) = (Vec::new(), 0, 1);
    let ident_start = |ch: char| ch == '_' || ch.is_alphabetic();
    let ident_char = |ch: char| ch == '_' || ch.is_alphanumeric();
    while i < c.len() {
        let ch = c[i];
        let at = |k: usize| c.get(i + k).copied().unwrap_or('\0');
        if ch == '\n' {
            line += 1;
            i += 1;
        } else if ch.is_whitespace() {
            i += 1;
        } else if ch == '/' && at(1) == '/' {
            while i < c.len() && c[i] != '\n' {
                i += 1;
            }
        } else if ch == '/' && at(1) == '*' {
            let mut depth = 0;
            while i < c.len() {
                if c[i] == '/' && c.get(i + 1) == Some(&'*') {
                    depth += 1;
                    i += 2;
                } else if c[i] == '*' && c.get(i + 1) == Some(&'/') {
                    depth -= 1;
                    i += 2;
                    if depth == 0 {
                        break;
                    }
                } else {
                    line += usize::from(c[i] == '\n');
                    i += 1;
                }
            }
        } else if ch == '"'
            || ((ch == 'r' || ch == 'b') && (at(1) == '"' || at(1) == '#' || at(1) == 'r'))
        {
            // Strings, byte strings and raw strings (`r#"…"#`).
            let start_line = line;
            let mut j = i;
            if c[j] == 'b' {
                j += 1;
            }
            let raw = c.get(j) == Some(&'r');
            if raw {
                j += 1;
            }
            let mut hashes = 0;
            while c.get(j) == Some(&'#') {
                hashes += 1;
                j += 1;
            }
            if c.get(j) != Some(&'"') {
                // An identifier that starts with r or b.
                let s = i;
                while i < c.len() && ident_char(c[i]) {
                    i += 1;
                }
                out.push(Token {
                    tok: Tok::Ident(c[s..i].iter().collect()),
                    line,
                });
                continue;
            }
            j += 1;
            let body = j;
            loop {
                if j >= c.len() {
                    break;
                }
                if c[j] == '\n' {
                    line += 1;
                }
                if !raw && c[j] == '\\' {
                    j += 2;
                    continue;
                }
                if c[j] == '"' && (0..hashes).all(|k| c.get(j + 1 + k) == Some(&'#')) {
                    break;
                }
                j += 1;
            }
            out.push(Token {
                tok: Tok::Str(c[body..j.min(c.len())].iter().collect()),
                line: start_line,
            });
            i = j + 1 + hashes;
        } else if ch == '\'' {
            // A char literal ('a', '\n', '\u{1F}') or a lifetime ('a).
            if at(1) == '\\' {
                i += 2;
                while i < c.len() && c[i] != '\'' {
                    i += 1;
                }
                i += 1;
            } else if at(2) == '\'' {
                i += 3;
            } else {
                i += 1;
                while i < c.len() && ident_char(c[i]) {
                    i += 1;
                }
            }
        } else if ch.is_ascii_digit() {
            while i < c.len()
                && (ident_char(c[i])
                    || (c[i] == '.' && c.get(i + 1).is_some_and(|d| d.is_ascii_digit())))
            {
                i += 1;
            }
        } else if ident_start(ch) {
            let s = i;
            while i < c.len() && ident_char(c[i]) {
                i += 1;
            }
            out.push(Token {
                tok: Tok::Ident(c[s..i].iter().collect()),
                line,
            });
        } else if ch == ':' && at(1) == ':' {
            out.push(Token {
                tok: Tok::PathSep,
                line,
            });
            i += 2;
        } else {
            out.push(Token {
                tok: Tok::Punct(ch),
                line,
            });
            i += 1;
        }
    }
    out
}

fn ident(t: Option<&Token>) -> Option<&str> {
    match t {
        Some(Token {
            tok: Tok::Ident(s), ..
        }) => Some(s),
        _ => None,
    }
}

fn is(t: Option<&Token>, p: char) -> bool {
    matches!(t, Some(Token { tok: Tok::Punct(q), .. }) if *q == p)
}

fn is_sep(t: Option<&Token>) -> bool {
    matches!(
        t,
        Some(Token {
            tok: Tok::PathSep,
            ..
        })
    )
}

/// The index just past the bracket that closes the one at `open`.
fn closing(toks: &[Token], open: usize) -> usize {
    let (o, c) = match toks[open].tok {
        Tok::Punct('{') => ('{', '}'),
        Tok::Punct('[') => ('[', ']'),
        _ => ('(', ')'),
    };
    let mut depth = 0;
    for (k, t) in toks.iter().enumerate().skip(open) {
        if is(Some(t), o) {
            depth += 1;
        } else if is(Some(t), c) {
            depth -= 1;
            if depth == 0 {
                return k + 1;
            }
        }
    }
    toks.len()
}

/// A path named in a file: where, and its segments as written.
#[derive(Clone, Debug)]
struct Ref {
    line: usize,
    path: Vec<String>,
}

#[derive(Default)]
struct Module {
    name: String,
    file: usize,
    parent: Option<usize>,
    /// Under `#[cfg(test)]`: not part of the structure.
    test: bool,
    children: HashMap<String, usize>,
    items: BTreeSet<String>,
    imports: HashMap<String, Vec<String>>,
    globs: Vec<Vec<String>>,
    refs: Vec<Ref>,
}

#[derive(Clone, Copy, Debug, PartialEq)]
enum Res {
    Module(usize),
    /// An item (function, type, constant, macro…) defined in this file.
    Item(usize),
}

#[derive(Default)]
struct Crate {
    files: Vec<PathBuf>,
    modules: Vec<Module>,
    /// `#[macro_export]` macros: named at the crate root, defined in a file.
    macros: HashMap<String, usize>,
}

impl Crate {
    /// Reads the crate whose root file is `root`, every `mod` file included.
    fn read(root: &Path) -> Crate {
        let mut cr = Crate::default();
        cr.add_file(root, None, "", false);
        cr
    }

    fn add_file(&mut self, path: &Path, parent: Option<usize>, name: &str, test: bool) {
        let src = fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        let file = self.files.len();
        self.files.push(path.to_path_buf());
        let m = self.new_module(file, parent, name, test);
        let dir = path.parent().unwrap().to_path_buf();
        let stem = path.file_stem().unwrap().to_str().unwrap();
        let base = if ["lib", "main", "mod"].contains(&stem) {
            dir.clone()
        } else {
            dir.join(stem)
        };
        let toks = lex(&src);
        self.parse(m, &toks, &dir, &base);
    }

    fn new_module(&mut self, file: usize, parent: Option<usize>, name: &str, test: bool) -> usize {
        let m = self.modules.len();
        let test = test || parent.is_some_and(|p| self.modules[p].test);
        self.modules.push(Module {
            name: name.to_string(),
            file,
            parent,
            test,
            ..Module::default()
        });
        if let Some(p) = parent {
            self.modules[p].children.insert(name.to_string(), m);
        }
        m
    }

    /// Reads one module's tokens: its submodules, items, imports and the
    /// paths it names. `dir` is where `#[path]` is relative to, `base`
    /// where its submodules' files are.
    fn parse(&mut self, m: usize, toks: &[Token], dir: &Path, base: &Path) {
        let (mut i, mut depth) = (0, 0usize);
        let (mut path_attr, mut macro_export, mut cfg_test) = (None::<String>, false, false);
        while i < toks.len() {
            let t = &toks[i];
            // `#[cfg(test)]` holds for the next item only.
            let before_item = matches!(&t.tok, Tok::Ident(k) if ["pub", "crate", "super", "in", "mod"].contains(&k.as_str()))
                || matches!(t.tok, Tok::Punct('#' | '(' | ')'));
            if !before_item {
                cfg_test = false;
            }
            match &t.tok {
                Tok::Punct('#') => {
                    let open = if is(toks.get(i + 1), '!') {
                        i + 2
                    } else {
                        i + 1
                    };
                    let end = closing(toks, open);
                    let attr = &toks[open + 1..end - 1];
                    match (ident(attr.first()), attr.get(2)) {
                        (
                            Some("path"),
                            Some(Token {
                                tok: Tok::Str(p), ..
                            }),
                        ) => path_attr = Some(p.clone()),
                        (Some("macro_export"), _) => macro_export = true,
                        (Some("cfg"), _) => {
                            cfg_test = attr.iter().any(|t| t.tok == Tok::Ident("test".into()))
                                && !attr.iter().any(|t| t.tok == Tok::Ident("not".into()))
                        }
                        _ => {}
                    }
                    i = end;
                    continue;
                }
                Tok::Punct('{') => depth += 1,
                Tok::Punct('}') => depth = depth.saturating_sub(1),
                Tok::Ident(kw) if kw == "mod" && depth == 0 => {
                    let name = ident(toks.get(i + 1)).unwrap().to_string();
                    let test = std::mem::take(&mut cfg_test);
                    if is(toks.get(i + 2), ';') {
                        let file = match path_attr.take() {
                            Some(p) => dir.join(p),
                            None if base.join(format!("{name}.rs")).exists() => {
                                base.join(format!("{name}.rs"))
                            }
                            None => base.join(&name).join("mod.rs"),
                        };
                        self.add_file(&file, Some(m), &name, test);
                        i += 3;
                    } else {
                        let end = closing(toks, i + 2);
                        let inner = self.new_module(self.modules[m].file, Some(m), &name, test);
                        let sub = base.join(&name);
                        self.parse(inner, &toks[i + 3..end - 1], &sub, &sub);
                        i = end;
                    }
                    continue;
                }
                Tok::Ident(kw) if kw == "use" => {
                    let mut entries = Vec::new();
                    i += 1;
                    use_tree(toks, &mut i, Vec::new(), &mut entries);
                    let md = &mut self.modules[m];
                    for (name, path) in entries {
                        md.refs.push(Ref {
                            line: t.line,
                            path: path.clone(),
                        });
                        match name {
                            Some(n) => {
                                md.imports.insert(n, path);
                            }
                            None => md.globs.push(path),
                        }
                    }
                    continue;
                }
                Tok::Ident(kw) if kw == "macro_rules" && is(toks.get(i + 1), '!') => {
                    let name = ident(toks.get(i + 2)).unwrap().to_string();
                    if std::mem::take(&mut macro_export) {
                        self.macros.insert(name.clone(), self.modules[m].file);
                    }
                    self.modules[m].items.insert(name);
                    i += 3;
                    continue;
                }
                Tok::Ident(kw)
                    if depth == 0
                        && [
                            "fn", "struct", "enum", "trait", "type", "const", "static", "union",
                        ]
                        .contains(&kw.as_str()) =>
                {
                    if let Some(name) = ident(toks.get(i + 1)) {
                        self.modules[m].items.insert(name.to_string());
                    }
                    path_attr = None;
                }
                Tok::Ident(first) if !(i > 0 && is_sep(toks.get(i - 1))) => {
                    let mut path = vec![first.clone()];
                    while is_sep(toks.get(i + 1)) {
                        match ident(toks.get(i + 2)) {
                            Some(s) => path.push(s.to_string()),
                            None => break,
                        }
                        i += 2;
                    }
                    if path.len() > 1 {
                        self.modules[m].refs.push(Ref { line: t.line, path });
                    }
                }
                _ => {}
            }
            i += 1;
        }
    }

    fn lookup(&self, m: usize, name: &str, depth: usize) -> Option<Res> {
        let md = &self.modules[m];
        if let Some(&c) = md.children.get(name) {
            return Some(Res::Module(c));
        }
        if md.items.contains(name) {
            return Some(Res::Item(md.file));
        }
        if let Some(p) = md.imports.get(name) {
            if let Some(r) = self.resolve(m, p, depth + 1) {
                return Some(r);
            }
        }
        for g in &md.globs {
            if let Some(Res::Module(gm)) = self.resolve(m, g, depth + 1) {
                if let Some(r) = self.lookup(gm, name, depth + 1) {
                    return Some(r);
                }
            }
        }
        if md.parent.is_none() {
            return self.macros.get(name).map(|&f| Res::Item(f));
        }
        None
    }

    /// Where `path`, named in module `m`, leads: a module or the file that
    /// defines the item; `None` outside the crate (std, dependencies) or
    /// for names that are not paths to items (`Self::new`, `T::default`).
    fn resolve(&self, m: usize, path: &[String], depth: usize) -> Option<Res> {
        if depth > 40 {
            return None;
        }
        let step = |at: usize, seg: &str| match seg {
            "crate" => Some(Res::Module(0)),
            "self" => Some(Res::Module(at)),
            "super" => self.modules[at].parent.map(Res::Module),
            _ => self.lookup(at, seg, depth),
        };
        let mut cur = step(m, &path[0])?;
        for seg in &path[1..] {
            cur = match cur {
                Res::Module(c) => step(c, seg)?,
                Res::Item(_) => break,
            };
        }
        Some(cur)
    }

    /// File → file it names an item of, with the first reference that does.
    fn edges(&self) -> BTreeMap<usize, BTreeMap<usize, Ref>> {
        let mut edges: BTreeMap<usize, BTreeMap<usize, Ref>> = BTreeMap::new();
        for (m, md) in self.modules.iter().enumerate().filter(|(_, md)| !md.test) {
            for r in &md.refs {
                if let Some(Res::Item(f)) = self.resolve(m, &r.path, 0) {
                    if f != md.file {
                        edges
                            .entry(md.file)
                            .or_default()
                            .entry(f)
                            .or_insert_with(|| r.clone());
                    }
                }
            }
        }
        edges
    }
}

/// Reads one use tree from `toks[*i]` on, `prefix` before it: each name it
/// brings in with its full path, `None` for globs. Leaves `i` past the `;`.
fn use_tree(
    toks: &[Token],
    i: &mut usize,
    mut prefix: Vec<String>,
    out: &mut Vec<(Option<String>, Vec<String>)>,
) {
    loop {
        let t = toks.get(*i);
        if is_sep(t) {
            *i += 1;
        } else if is(t, '*') {
            *i += 1;
            out.push((None, prefix));
            break;
        } else if is(t, '{') {
            *i += 1;
            while !is(toks.get(*i), '}') {
                use_tree(toks, i, prefix.clone(), out);
                if is(toks.get(*i), ',') {
                    *i += 1;
                }
            }
            *i += 1;
            break;
        } else if let Some(seg) = ident(t) {
            prefix.push(seg.to_string());
            *i += 1;
            if is_sep(toks.get(*i)) {
                continue;
            }
            let name = if ident(toks.get(*i)) == Some("as") {
                *i += 2;
                ident(toks.get(*i - 1)).unwrap().to_string()
            } else if seg == "self" {
                prefix.pop();
                prefix.last().cloned().unwrap_or_default()
            } else {
                seg.to_string()
            };
            out.push((Some(name), prefix));
            break;
        } else {
            break;
        }
    }
    if is(toks.get(*i), ';') {
        *i += 1;
    }
}

type Graph<E> = BTreeMap<usize, BTreeMap<usize, E>>;

/// Strongly connected components of more than one node (Tarjan); nodes
/// are below `n`.
fn components<E>(n: usize, edges: &Graph<E>) -> Vec<Vec<usize>> {
    struct T<'a, E> {
        edges: &'a Graph<E>,
        index: Vec<Option<usize>>,
        low: Vec<usize>,
        on: Vec<bool>,
        stack: Vec<usize>,
        next: usize,
        out: Vec<Vec<usize>>,
    }
    fn visit<E>(t: &mut T<E>, v: usize) {
        t.index[v] = Some(t.next);
        t.low[v] = t.next;
        t.next += 1;
        t.stack.push(v);
        t.on[v] = true;
        let succ: Vec<usize> = t
            .edges
            .get(&v)
            .map(|e| e.keys().copied().collect())
            .unwrap_or_default();
        for w in succ {
            match t.index[w] {
                None => {
                    visit(t, w);
                    t.low[v] = t.low[v].min(t.low[w]);
                }
                Some(iw) if t.on[w] => t.low[v] = t.low[v].min(iw),
                _ => {}
            }
        }
        if Some(t.low[v]) == t.index[v] {
            let mut comp = Vec::new();
            while let Some(w) = t.stack.pop() {
                t.on[w] = false;
                comp.push(w);
                if w == v {
                    break;
                }
            }
            if comp.len() > 1 {
                comp.sort();
                t.out.push(comp);
            }
        }
    }
    let mut t = T {
        edges,
        index: vec![None; n],
        low: vec![0; n],
        on: vec![false; n],
        stack: Vec::new(),
        next: 0,
        out: Vec::new(),
    };
    for v in 0..n {
        if t.index[v].is_none() && edges.contains_key(&v) {
            visit(&mut t, v);
        }
    }
    t.out
}

/// The shortest circuit from `from` back to it inside `comp`, as edges.
fn circuit<E>(from: usize, comp: &[usize], edges: &Graph<E>) -> Vec<(usize, usize)> {
    let mut prev: HashMap<usize, usize> = HashMap::new();
    let mut queue = VecDeque::from([from]);
    while let Some(v) = queue.pop_front() {
        for &w in edges.get(&v).map(|e| e.keys()).into_iter().flatten() {
            if !comp.contains(&w) || prev.contains_key(&w) {
                continue;
            }
            prev.insert(w, v);
            if w == from {
                let mut chain = vec![(v, w)];
                let mut at = v;
                while at != from {
                    let p = prev[&at];
                    chain.push((p, at));
                    at = p;
                }
                chain.reverse();
                return chain;
            }
            queue.push_back(w);
        }
    }
    Vec::new()
}

/// The import cycles of the crate whose root file is `root`, one message
/// each.
///
/// Each reference from file `a` to an item of file `b` is an edge between
/// the two sibling modules that hold them: the children of their nearest
/// common module (a child with all its submodules counts as one). Each
/// module's children must form no cycle. A reference between a module and
/// one of its own submodules (`super::Point`, `child::f`) joins no siblings:
/// a module's own file is where its children's shared ground and its table
/// of contents live.
fn report(root: &Path) -> Vec<String> {
    let src = root.parent().unwrap();
    let cr = Crate::read(root);
    let file = |f: usize| cr.files[f].strip_prefix(src).unwrap().display().to_string();
    let up = |m: usize| {
        let mut chain = vec![m];
        while let Some(p) = cr.modules[*chain.last().unwrap()].parent {
            chain.push(p);
        }
        chain.reverse();
        chain
    };
    let module_of: HashMap<usize, usize> = (0..cr.modules.len())
        .rev()
        .map(|m| (cr.modules[m].file, m))
        .collect();
    let mut levels: BTreeMap<usize, Graph<(usize, usize, Ref)>> = BTreeMap::new();
    for (a, targets) in cr.edges() {
        for (b, r) in targets {
            let (ua, ub) = (up(module_of[&a]), up(module_of[&b]));
            let k = ua.iter().zip(&ub).take_while(|(x, y)| x == y).count();
            if k < ua.len() && k < ub.len() {
                levels
                    .entry(ua[k - 1])
                    .or_default()
                    .entry(ua[k])
                    .or_default()
                    .entry(ub[k])
                    .or_insert((a, b, r));
            }
        }
    }
    let name = |m: usize| {
        let path: Vec<&str> = up(m)[1..]
            .iter()
            .map(|&x| cr.modules[x].name.as_str())
            .collect();
        if path.is_empty() {
            "crate".to_string()
        } else {
            path.join("::")
        }
    };
    let mut found = Vec::new();
    for (parent, graph) in &levels {
        for comp in components(cr.modules.len(), graph) {
            let members: Vec<&str> = comp.iter().map(|&m| cr.modules[m].name.as_str()).collect();
            let mut s = format!("cycle in {} among {}:", name(*parent), members.join(", "));
            for (x, y) in circuit(comp[0], &comp, graph) {
                let (a, b, r) = &graph[&x][&y];
                s += &format!(
                    "\n  {} -> {}: {}:{} names `{}` (defined in {})",
                    cr.modules[x].name,
                    cr.modules[y].name,
                    file(*a),
                    r.line,
                    r.path.join("::"),
                    file(*b)
                );
            }
            found.push(s);
        }
    }
    found
}

#[test]
fn modules_import_one_another_without_cycles() {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut found = Vec::new();
    for root in ["lib.rs", "main.rs"] {
        found.extend(report(&src.join(root)));
    }
    assert!(
        found.is_empty(),
        "{} import cycle(s) between source files:\n{}",
        found.len(),
        found.join("\n")
    );
}

#[test]
fn a_planted_cycle_is_found() {
    let dir = std::env::temp_dir().join(format!("kerfcam-cycles-{}", std::process::id()));
    fs::create_dir_all(dir.join("b")).unwrap();
    let write = |p: &str, s: &str| fs::write(dir.join(p), s).unwrap();
    write("lib.rs", "mod a;\nmod b;\nmod c;\nmod e;\nmod f;\n");
    // a → b (its child inner, through b's re-export) → c → a.
    write(
        "a.rs",
        "use crate::b::Thing;\npub fn f() -> Thing { Thing }\n",
    );
    // b and its child name each other: no cycle.
    write(
        "b/mod.rs",
        "mod inner;\npub use inner::Thing;\npub fn shared() { inner::g() }\n",
    );
    write(
        "b/inner.rs",
        "pub struct Thing;\npub fn g() { super::shared(); crate::c::h() }\n",
    );
    // A comment and a string naming `crate::b` are not references.
    write(
        "c.rs",
        "// crate::b::Thing\npub fn h() { let _ = \"crate::b\"; super::a::f(); }\n",
    );
    // e → f, and f's tests use e: no cycle.
    write("e.rs", "pub fn x() { crate::f::y() }\n");
    write(
        "f.rs",
        "pub fn y() {}\n#[cfg(test)]\nmod tests {\n    use crate::e::x;\n}\n",
    );
    let found = report(&dir.join("lib.rs"));
    fs::remove_dir_all(&dir).unwrap();
    assert_eq!(
        found,
        ["cycle in crate among a, b, c:\n  \
          a -> b: a.rs:1 names `crate::b::Thing` (defined in b/inner.rs)\n  \
          b -> c: b/inner.rs:2 names `crate::c::h` (defined in c.rs)\n  \
          c -> a: c.rs:2 names `super::a::f` (defined in a.rs)"]
    );
}
