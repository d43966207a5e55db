//! The document tree walked once: each element's map (its transforms and
//! the viewports above it), style and layer; shapes and paths to entities;
//! `<use>` followed to `<symbol>`, nested `<svg>` and plain elements, with
//! cycles, depth and expansion bombs stopped and said; what is not
//! geometry counted for the warnings.

use std::collections::{BTreeMap, HashMap};

use super::document::{self, PX, PX72_MM, PX_MM};
use super::layers::{self, Raw};
use super::path;
use super::shapes::{self, Lengths, Shape};
use super::style::{Sheet, Style};
use super::{curves, transform, MAX_COORD_MM, MAX_DEPTH, MAX_ELEMENTS, MAX_SEGMENTS};
use crate::dxf::{size_text, Drawing, Entity, InsertCopy, Place, ReadOptions};
use crate::geom::{Affine, BBox};
use crate::text;
use crate::warning::{Text, Warning};

const INKSCAPE: &str = "http://www.inkscape.org/namespaces/inkscape";
const XLINK: &str = "http://www.w3.org/1999/xlink";
const SVG: &str = "http://www.w3.org/2000/svg";

/// What an element's children inherit.
#[derive(Clone)]
struct Ctx {
    map: Affine,
    style: Style,
    viewport: (f64, f64),
    layer: Option<String>,
    layer_hidden: bool,
    /// The innermost named group (an index of `Walker::groups`).
    group: Option<u32>,
    depth: usize,
}

/// Things seen that are not cut, for one warning each.
#[derive(Default)]
struct Notes {
    clip: usize,
    mask: usize,
    filter: usize,
    marker: usize,
    stroke_width: bool,
    external: usize,
    missing: usize,
    cycles: usize,
    too_deep: usize,
    too_many: bool,
    empty: usize,
    bad_numbers: usize,
}

struct Walker<'a, 'input> {
    options: &'a ReadOptions,
    px_mm: f64,
    sheet: Sheet,
    ids: HashMap<&'a str, roxmltree::Node<'a, 'input>>,
    /// Byte offsets of the line ends, for an element's line.
    line_ends: Vec<usize>,
    raw: Vec<Raw>,
    counts: BTreeMap<String, usize>,
    skipped: BTreeMap<String, usize>,
    warnings: Vec<Warning>,
    segments: usize,
    elements: usize,
    /// The `<use>` targets being expanded (a target met again is a cycle).
    uses: Vec<roxmltree::NodeId>,
    /// Named groups and Inkscape layers met, as the drawing's copies
    /// ([`Drawing::inserts`]): what names the parts drawn in them.
    groups: Vec<InsertCopy>,
    notes: Notes,
}

/// Reads the tree into a drawing (layers assigned, warnings not yet grouped).
pub fn read(doc: &roxmltree::Document, text: &str, options: &ReadOptions) -> Drawing {
    let px_mm = options.units.map_or(PX_MM, |u| u.to_mm);
    let root_node = doc.root_element();
    let root = document::root(root_node, px_mm);
    let mut w = Walker {
        options,
        px_mm,
        sheet: Sheet::of(doc),
        ids: doc
            .descendants()
            .filter_map(|n| n.attribute("id").map(|id| (id, n)))
            .collect(),
        line_ends: text
            .bytes()
            .enumerate()
            .filter(|(_, b)| *b == b'\n')
            .map(|(i, _)| i)
            .collect(),
        raw: Vec::new(),
        counts: BTreeMap::new(),
        skipped: BTreeMap::new(),
        warnings: Vec::new(),
        segments: 0,
        elements: 0,
        uses: Vec::new(),
        groups: Vec::new(),
        notes: Notes::default(),
    };
    let ctx = Ctx {
        map: root.map,
        style: Style::default().child(root_node, &w.sheet),
        viewport: root.viewport,
        layer: None,
        layer_hidden: false,
        group: None,
        depth: 0,
    };
    if let Some(vb) = &root.bad_view_box {
        w.warnings.push(Warning::new(
            "view-box-unusable",
            text!("the viewBox '{vb}' is unusable (not four numbers, or no width or height): ignored, the coordinates are read as px";
                  "o viewBox '{vb}' é inutilizável (não são quatro números, ou largura ou altura zero): ignorado, as coordenadas são lidas em px"),
        ));
    }
    w.children(root_node, &ctx);
    let mut d = Drawing {
        svg: true,
        version: root_node
            .attribute((INKSCAPE, "version"))
            .map(|v| format!("Inkscape {}", v.chars().take(40).collect::<String>())),
        ..Drawing::default()
    };
    let chosen = options.layers.as_deref();
    let (layers, entities, off) = layers::assign(std::mem::take(&mut w.raw), chosen);
    let mut extent = BBox::EMPTY;
    for s in entities.iter().flat_map(|e| &e.segments) {
        extent.union(&s.bbox());
    }
    d.extent = extent;
    d.layers = layers;
    d.entities = entities;
    d.inserts = std::mem::take(&mut w.groups);
    w.finish_notes(&mut d, &off);
    d.counts = std::mem::take(&mut w.counts);
    d.skipped = std::mem::take(&mut w.skipped);
    // Units: the user's choice, else the file's physical size, else px at 96 per inch.
    match options.units {
        Some(u) => {
            d.units = Some(u);
            d.units_source = "override";
            if !root.px_scaled {
                let name = root.units.name;
                w.warnings.insert(0, Warning::new(
                    "units-not-applied",
                    text!("the file gives its size in {name}: the unit chosen ({}) changes only lengths written in px", u.name;
                          "o arquivo dá seu tamanho em {name}: a unidade escolhida ({}) muda só medidas escritas em px", u.name),
                ));
            }
        }
        None => {
            d.units = Some(root.units);
            if root.px_scaled {
                d.units_source = "assumed";
                d.units = Some(PX);
                w.warnings.insert(0, assumed(&root, &d.extent));
            } else {
                d.units_source = "width/height";
            }
        }
    }
    d.warnings = std::mem::take(&mut w.warnings);
    if d.entities.is_empty() {
        d.warnings.push(Warning::new(
            "no-geometry",
            text!("no cuttable geometry in the SVG"; "nenhuma geometria cortável no SVG"),
        ));
    }
    d
}

/// The `units-assumed` warning: the size at 96 and at 72 px per inch.
fn assumed(root: &document::Root, extent: &BBox) -> Warning {
    let (w, h) = if extent.is_empty() {
        root.size_mm.unwrap_or((0.0, 0.0))
    } else {
        (extent.max.x - extent.min.x, extent.max.y - extent.min.y)
    };
    let at96 = size_text(w, h);
    let k = PX72_MM / PX_MM;
    let at72 = size_text(w * k, h * k);
    let why = if root.physical {
        text!("the SVG gives its page size but no viewBox, so its coordinates are px";
              "o SVG dá o tamanho da página mas não um viewBox, então suas coordenadas são px")
    } else {
        text!("the SVG gives no size in physical units (width/height in px or absent)";
              "o SVG não dá tamanho em unidades físicas (width/height em px ou ausentes)")
    };
    Warning::new(
        "units-assumed",
        text!("units assumed: {}; read at 96 px per inch (CSS, Inkscape): {} (at 72 px per inch, Illustrator's, it would be {})", why.en, at96.en, at72.en;
              "unidades supostas: {}; lido a 96 px por polegada (CSS, Inkscape): {} (a 72 px por polegada, do Illustrator, seria {})", why.pt, at96.pt, at72.pt),
    )
}

/// The name a group gives the parts drawn in it (issue 42 §1): its
/// `inkscape:label` (Inkscape's Objects panel, a layer's name), else its
/// `id` unless an editor made it up (`g1234`, `layer1`, `path-3`,
/// `Layer_1-2`: a generator's word and a number tell no part apart).
fn group_name(node: roxmltree::Node) -> Option<String> {
    let named = |s: &str| Some(s.trim()).filter(|s| !s.is_empty()).map(str::to_owned);
    if let Some(label) = node.attribute((INKSCAPE, "label")).and_then(named) {
        return Some(label);
    }
    node.attribute("id").filter(|id| !generated_id(id)).and_then(named)
}

/// An id an editor numbers by itself: a letter or a generator's word
/// (Inkscape's element names and `layer`, Illustrator's `Layer_`,
/// svg-edit's `svg_`, boxes.py's `p-`) then numbers.
fn generated_id(id: &str) -> bool {
    const WORDS: [&str; 18] = [
        "g", "path", "rect", "circle", "ellipse", "line", "polyline", "polygon", "layer", "svg",
        "use", "text", "tspan", "group", "shape", "defs", "image", "symbol",
    ];
    let head = id.trim_end_matches(|c: char| c.is_ascii_digit() || c == '_' || c == '-');
    let tail = &id[head.len()..];
    tail.bytes().any(|b| b.is_ascii_digit())
        && (head.chars().count() == 1 || WORDS.iter().any(|w| w.eq_ignore_ascii_case(head)))
}

/// True for an element of the SVG namespace (or of none: hand-written
/// files and some nesters' output omit xmlns).
fn is_svg(n: roxmltree::Node) -> bool {
    n.is_element() && matches!(n.tag_name().namespace(), None | Some(SVG))
}

/// The element names drawn, as the entity kinds.
fn kind(tag: &str) -> Option<&'static str> {
    Some(match tag {
        "path" => "path",
        "rect" => "rect",
        "circle" => "circle",
        "ellipse" => "ellipse",
        "line" => "line",
        "polyline" => "polyline",
        "polygon" => "polygon",
        _ => return None,
    })
}

impl<'a, 'input> Walker<'a, 'input> {
    fn line(&self, node: roxmltree::Node) -> Place {
        let at = node.range().start;
        Place::Line(self.line_ends.partition_point(|&e| e < at) + 1)
    }

    fn children(&mut self, node: roxmltree::Node<'a, 'input>, ctx: &Ctx) {
        for c in node.children() {
            if is_svg(c) {
                self.element(c, ctx);
            }
        }
    }

    fn count(&mut self, tag: &str) {
        *self.counts.entry(tag.to_owned()).or_default() += 1;
    }

    fn skip(&mut self, tag: &str) {
        self.count(tag);
        *self.skipped.entry(tag.to_owned()).or_default() += 1;
    }

    /// One element with the context of its parent (or of the `<use>` that
    /// instances it).
    fn element(&mut self, node: roxmltree::Node<'a, 'input>, parent: &Ctx) {
        if parent.depth >= MAX_DEPTH {
            self.notes.too_deep += 1;
            return;
        }
        self.elements += 1;
        if self.elements > MAX_ELEMENTS {
            self.notes.too_many = true;
            return;
        }
        let tag = node.tag_name().name();
        let style = parent.style.child(node, &self.sheet);
        let mut ctx = Ctx {
            style,
            depth: parent.depth + 1,
            ..parent.clone()
        };
        if let Some(t) = node.attribute("transform") {
            match transform::parse(t) {
                Ok(m) => ctx.map = ctx.map.then_after(&m),
                Err(t) => {
                    let at = self.line(node);
                    let place = crate::dxf::place_text(at);
                    self.warnings.push(
                        Warning::new(
                            "bad-transform",
                            text!("<{tag}> at {}: transform '{t}' does not parse and was not applied", place.en;
                                  "<{tag}> em {}: transform '{t}' não é legível e não foi aplicado", place.pt),
                        )
                        .of_kind(
                            text!("transform not readable, not applied"; "transform ilegível, não aplicado"),
                            place,
                        ),
                    );
                }
            }
        }
        let st = &ctx.style;
        if !st.display_none {
            self.notes.clip += usize::from(st.clip);
            self.notes.mask += usize::from(st.mask);
            self.notes.filter += usize::from(st.filter);
        }
        match tag {
            "g" | "a" | "switch" => {
                if node.attribute((INKSCAPE, "groupmode")) == Some("layer") {
                    let label = (node.attribute((INKSCAPE, "label")).or(node.attribute("id")))
                        .unwrap_or("layer")
                        .trim();
                    ctx.layer = Some(match &parent.layer {
                        Some(p) => format!("{p}/{label}"),
                        None => label.to_owned(),
                    });
                    ctx.layer_hidden = ctx.style.hidden();
                }
                if let Some(name) = group_name(node) {
                    if let Ok(i) = u32::try_from(self.groups.len()) {
                        self.groups.push(InsertCopy { block: name.into(), parent: ctx.group });
                        ctx.group = Some(i);
                    }
                }
                self.children(node, &ctx);
            }
            "svg" => {
                let (m, vp) = document::nested(node, self.px_mm, parent.viewport, (None, None));
                ctx.map = ctx.map.then_after(&m);
                ctx.viewport = vp;
                self.children(node, &ctx);
            }
            "use" => self.instance(node, ctx),
            "text" | "flowRoot" | "image" | "foreignObject" | "video" => {
                if !ctx.style.display_none {
                    self.skip(if tag == "flowRoot" { "text" } else { tag });
                }
            }
            _ => {
                if let Some(kind) = kind(tag) {
                    self.shape(node, kind, &ctx);
                }
                // defs, symbol, clipPath, mask, marker, pattern, gradients,
                // style, title, metadata …: not drawn where they stand.
            }
        }
    }

    /// A `<use>`: its x/y after its transform, then the target, drawn as
    /// if it were the use's child.
    fn instance(&mut self, node: roxmltree::Node<'a, 'input>, mut ctx: Ctx) {
        self.count("use");
        let href = node
            .attribute((XLINK, "href"))
            .or(node.attribute("href"))
            .unwrap_or("")
            .trim();
        let Some(id) = href.strip_prefix('#') else {
            // A reference to another file or a URL: never fetched.
            self.notes.external += usize::from(!href.is_empty());
            return;
        };
        let Some(&target) = self.ids.get(id) else {
            self.notes.missing += 1;
            return;
        };
        if self.uses.contains(&target.id()) || node.ancestors().any(|a| a == target) {
            self.notes.cycles += 1;
            return;
        }
        let l = Lengths {
            viewport: ctx.viewport,
            px_mm: self.px_mm,
        };
        let x = document::attr_length(node, "x", l.px_mm, l.viewport.0).unwrap_or(0.0);
        let y = document::attr_length(node, "y", l.px_mm, l.viewport.1).unwrap_or(0.0);
        ctx.map = ctx.map.then_after(&Affine::translate(x, y));
        self.uses.push(target.id());
        let tag = target.tag_name().name();
        if is_svg(target) && (tag == "symbol" || tag == "svg") {
            // The use's width and height size the symbol's viewport.
            let w = document::attr_length(node, "width", l.px_mm, l.viewport.0);
            let h = document::attr_length(node, "height", l.px_mm, l.viewport.1);
            self.elements += 1;
            ctx.style = ctx.style.child(target, &self.sheet);
            if let Some(t) = target
                .attribute("transform")
                .and_then(|t| transform::parse(t).ok())
            {
                ctx.map = ctx.map.then_after(&t);
            }
            let (m, vp) = document::nested(target, self.px_mm, ctx.viewport, (w, h));
            // A symbol's own x/y are not SVG 1.1; nested() reads them as SVG 2 does.
            ctx.map = ctx.map.then_after(&m);
            ctx.viewport = vp;
            ctx.depth += 1;
            self.children(target, &ctx);
        } else if is_svg(target) {
            self.element(target, &ctx);
        }
        self.uses.pop();
    }

    /// A shape or path: one entity per subpath.
    fn shape(&mut self, node: roxmltree::Node<'a, 'input>, kind: &'static str, ctx: &Ctx) {
        self.count(kind);
        let place = self.line(node);
        let subpaths = if kind == "path" {
            let (sps, err) = path::parse(node.attribute("d").unwrap_or(""));
            if let Some(e) = err {
                let at = crate::dxf::place_text(place);
                self.warnings.push(
                    Warning::new(
                        "path-error",
                        text!("<path> at {}: bad path data ({e}): read up to the error", at.en;
                              "<path> em {}: dados de caminho inválidos ({e}): lido até o erro", at.pt),
                    )
                    .of_kind(text!("bad path data, read up to the error"; "dados de caminho inválidos, lidos até o erro"), at),
                );
            }
            if sps.is_empty() {
                self.notes.empty += 1;
            }
            sps
        } else {
            let l = Lengths {
                viewport: ctx.viewport,
                px_mm: self.px_mm,
            };
            match shapes::shape(node, kind, &l) {
                Shape::Paths(p) => p,
                Shape::Empty => {
                    self.notes.empty += 1;
                    return;
                }
            }
        };
        let st = &ctx.style;
        self.notes.marker += usize::from(st.marker && !st.display_none);
        self.notes.stroke_width |= st.stroke_width && st.stroke != super::style::Paint::None;
        for sp in &subpaths {
            let room = MAX_SEGMENTS.saturating_sub(self.segments);
            let mut segs = Vec::new();
            curves::segments(sp, &ctx.map, self.options.chord, room, &mut segs);
            if segs.is_empty() {
                continue;
            }
            let ok = segs.iter().all(|s| {
                s.is_finite()
                    && s.a
                        .x
                        .abs()
                        .max(s.a.y.abs())
                        .max(s.b.x.abs())
                        .max(s.b.y.abs())
                        <= MAX_COORD_MM
            });
            if !ok {
                self.notes.bad_numbers += 1;
                continue;
            }
            self.segments += segs.len();
            let closed = sp.closed && segs.len() >= 2 && segs[0].a == segs[segs.len() - 1].b;
            self.raw.push(Raw {
                entity: Entity {
                    kind,
                    layer: 0,
                    place,
                    segments: segs,
                    closed,
                    source: None,
                    insert: ctx.group,
                },
                label: ctx.layer.clone(),
                color: st.color(),
                hidden: st.hidden(),
                layer_hidden: ctx.layer_hidden,
            });
        }
    }

    /// The warnings for what was seen and not cut.
    fn finish_notes(&mut self, d: &mut Drawing, off: &BTreeMap<u32, usize>) {
        let n = &self.notes;
        let mut say = |code: &'static str, t: Text| self.warnings.push(Warning::new(code, t));
        let sk = |k: &str| self.skipped.get(k).copied().unwrap_or(0);
        let (text_n, image_n, fo_n) = (sk("text"), sk("image"), sk("foreignObject") + sk("video"));
        if text_n > 0 {
            say(
                "text-not-cut",
                text!(
                "{text_n} text element(s) not cut: convert text to paths (Inkscape: Path → Object to Path; Illustrator: Type → Create Outlines)";
                "{text_n} texto(s) não cortado(s): converta o texto em caminhos (Inkscape: Caminho → Objeto para caminho; Illustrator: Tipo → Criar contornos)"),
            );
        }
        if image_n > 0 {
            say(
                "image-not-cut",
                text!(
                "{image_n} image(s) not cut: a picture has no outline to cut (Inkscape: Path → Trace Bitmap)";
                "{image_n} imagem(ns) não cortada(s): uma imagem não tem contorno a cortar (Inkscape: Caminho → Vetorizar bitmap)"),
            );
        }
        if fo_n > 0 {
            say(
                "foreign-not-cut",
                text!("{fo_n} embedded object(s) (foreignObject, video) not cut";
                                         "{fo_n} objeto(s) embutido(s) (foreignObject, video) não cortado(s)"),
            );
        }
        if n.clip + n.mask > 0 {
            let k = n.clip + n.mask;
            say(
                "clip-ignored",
                text!(
                "{k} clip path(s) or mask(s) not applied: what they hide is cut too (Inkscape: Path → Intersection makes the clipped shape)";
                "{k} recorte(s) ou máscara(s) não aplicado(s): o que escondem também é cortado (Inkscape: Caminho → Interseção faz a forma recortada)"),
            );
        }
        if n.filter > 0 {
            let k = n.filter;
            say(
                "filter-ignored",
                text!("{k} filter(s) ignored (blur, shadow …): the shapes are cut as drawn";
                                        "{k} filtro(s) ignorado(s) (desfoque, sombra …): as formas são cortadas como desenhadas"),
            );
        }
        if n.marker > 0 {
            let k = n.marker;
            say(
                "markers-not-cut",
                text!(
                "{k} element(s) with markers (arrow heads …): the markers are not cut (Inkscape: Path → Stroke to Path draws them)";
                "{k} elemento(s) com marcadores (pontas de seta …): os marcadores não são cortados (Inkscape: Caminho → Contorno em caminho os desenha)"),
            );
        }
        if n.stroke_width {
            say(
                "stroke-width-ignored",
                text!(
                "stroke widths are ignored: the centre line of each shape is cut (the kerf is set in the process)";
                "larguras de traço são ignoradas: corta-se a linha central de cada forma (o kerf é definido no processo)"),
            );
        }
        if n.external > 0 {
            let k = n.external;
            say(
                "external-reference",
                text!(
                "{k} reference(s) to another file or a URL not followed (never fetched): embed what they show";
                "{k} referência(s) a outro arquivo ou URL não seguida(s) (nunca buscadas): incorpore o que mostram"),
            );
        }
        if n.missing > 0 {
            let k = n.missing;
            say(
                "use-missing",
                text!("{k} <use> of an id the file does not have: nothing drawn for them";
                                     "{k} <use> de um id que o arquivo não tem: nada desenhado para eles"),
            );
        }
        if n.cycles > 0 {
            let k = n.cycles;
            say(
                "use-cycle",
                text!("{k} <use> that refer back to themselves (a cycle): not expanded";
                                   "{k} <use> que se referem a si mesmos (um ciclo): não expandidos"),
            );
        }
        if n.too_deep > 0 {
            let k = n.too_deep;
            say(
                "too-deep",
                text!("{k} element(s) nested deeper than {MAX_DEPTH} levels not read";
                                  "{k} elemento(s) aninhado(s) a mais de {MAX_DEPTH} níveis não lido(s)"),
            );
        }
        if n.too_many {
            say(
                "too-many-elements",
                text!(
                "the SVG expands to more than {MAX_ELEMENTS} elements (counting <use> copies): the rest was not read";
                "o SVG se expande em mais de {MAX_ELEMENTS} elementos (contando cópias de <use>): o restante não foi lido"),
            );
        }
        if self.segments >= MAX_SEGMENTS {
            say(
                "too-many-segments",
                text!(
                "the drawing expands to more than {MAX_SEGMENTS} segments: the rest was not read";
                "o desenho se expande em mais de {MAX_SEGMENTS} segmentos: o restante não foi lido"),
            );
        }
        if n.empty > 0 {
            let k = n.empty;
            say(
                "empty-shape",
                text!("{k} shape(s) of zero size or with no path data: nothing to cut";
                                     "{k} forma(s) de tamanho zero ou sem dados de caminho: nada a cortar"),
            );
        }
        if n.bad_numbers > 0 {
            let k = n.bad_numbers;
            say(
                "bad-number",
                text!("{k} shape(s) with coordinates beyond {MAX_COORD_MM:e} mm or not numbers: not read";
                                    "{k} forma(s) com coordenadas além de {MAX_COORD_MM:e} mm ou não numéricas: não lida(s)"),
            );
        }
        if !off.is_empty() {
            let list: Vec<String> = off
                .iter()
                .map(|(&l, k)| format!("'{}' ×{k}", d.layers[l as usize].name))
                .collect();
            let list = list.join(", ");
            say(
                "layers-not-selected",
                text!("shapes on layers not selected for cutting (hidden in the file or not chosen): {list}";
                                             "formas em camadas não selecionadas para corte (ocultas no arquivo ou não escolhidas): {list}"),
            );
        }
    }
}
