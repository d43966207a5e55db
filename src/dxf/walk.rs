//! Entities → segments: the ENTITIES section streamed one entity at a time,
//! each entity's OCS applied and its kind read ([`super::insert`] places
//! them and walks the block definitions of an INSERT) (DXF reference, ENTITIES section; "Object
//! Coordinate Systems").

use super::pairs::Pair;
use super::place_text;
use super::reader::{entity_end, Reader};
use super::stream::Stream;
use super::{curves, ellipse, entities, Entity};
use super::{MAX_COORD_MM, MAX_TYPE_LEN};
use crate::geom::Affine;
use crate::text;
use crate::warning::Warning;

/// Reusable buffers for streaming: one entity's pairs and its children's ranges.
#[derive(Default)]
pub struct Scratch<'a> {
    buf: Vec<Pair<'a>>,
    kids: Vec<(usize, usize)>,
    stack: Vec<&'a [u8]>,
    lw: entities::LwVertices,
}

/// Children after a POLYLINE (VERTEX) or an INSERT (ATTRIB), closed by SEQEND.
fn child_of(head: &Pair) -> Option<&'static str> {
    match head.trimmed() {
        b"POLYLINE" => Some("VERTEX"),
        b"INSERT" => Some("ATTRIB"),
        _ => None,
    }
}

impl<'a, 'o> Reader<'a, 'o> {
    /// Reads entities from the stream until ENDSEC (consumed), EOF or a
    /// SECTION (left in the stream) or the end. `pre` holds the blocks.
    /// True when one of those three ended it (not the end of the input).
    pub fn stream_entities<I>(
        &mut self,
        pre: &[Pair<'a>],
        s: &mut Stream<'a, I>,
        sc: &mut Scratch<'a>,
    ) -> bool
    where
        I: super::pairs::Source<'a>,
    {
        let m = Affine::scale(self.scale);
        while let Some(head) = s.next_pair() {
            if head.code != 0 {
                continue;
            }
            let name = head.trimmed();
            if name == b"ENDSEC" {
                return true;
            }
            if name == b"EOF" || name == b"SECTION" {
                s.push_back(head);
                return true;
            }
            sc.buf.clear();
            sc.kids.clear();
            sc.buf.push(head);
            let lw = name == b"LWPOLYLINE";
            if lw {
                // Vertices go straight to the vertex list: a polyline of
                // millions of vertices is not kept as pairs. One over the
                // budget is enough to know it is too big.
                sc.lw.clear();
                while let Some(p) = s.peek().filter(|p| p.code != 0) {
                    s.next_pair();
                    if !sc.lw.feed(&p, self.budget.saturating_add(1)) {
                        sc.buf.push(p);
                    }
                }
            } else {
                s.take_body(&mut sc.buf);
            }
            let body = (1, sc.buf.len());
            if let Some(child) = child_of(&head) {
                while let Some(p) = s.peek().filter(|p| p.code == 0 && p.is(child)) {
                    sc.buf.push(p);
                    s.next_pair();
                    let from = sc.buf.len();
                    s.take_body(&mut sc.buf);
                    sc.kids.push((from, sc.buf.len()));
                }
                if s.peek().is_some_and(|p| p.code == 0 && p.is("SEQEND"))
                    && (child == "VERTEX" || !sc.kids.is_empty())
                {
                    s.next_pair();
                    let mark = sc.buf.len();
                    s.take_body(&mut sc.buf);
                    sc.buf.truncate(mark);
                }
            }
            if self.budget > 0 {
                let (buf, kids) = (&sc.buf, &sc.kids);
                let lw = lw.then_some(&sc.lw);
                self.entity(pre, buf, body, kids, lw, &m, None, true, &mut sc.stack);
            }
        }
        false
    }

    /// Reads the entities in `raw[from..to]` through the map `m`. `inherit` is the
    /// layer of the INSERT that placed them (for entities on layer "0").
    #[allow(clippy::too_many_arguments)]
    pub fn walk(
        &mut self,
        raw: &[Pair<'a>],
        from: usize,
        to: usize,
        m: &Affine,
        inherit: Option<u32>,
        top: bool,
        stack: &mut Vec<&'a [u8]>,
    ) {
        let mut i = from;
        let mut kids: Vec<(usize, usize)> = Vec::new();
        while i < to && self.budget > 0 {
            if raw[i].code != 0 {
                i += 1;
                continue;
            }
            let head = raw[i];
            let body = (i + 1, entity_end(raw, i, to));
            i = body.1;
            kids.clear();
            if let Some(child) = child_of(&head) {
                while i < to && raw[i].code == 0 && raw[i].is(child) {
                    let end = entity_end(raw, i, to);
                    kids.push((i + 1, end));
                    i = end;
                }
                if i < to
                    && raw[i].code == 0
                    && raw[i].is("SEQEND")
                    && (child == "VERTEX" || !kids.is_empty())
                {
                    i = entity_end(raw, i, to);
                }
            }
            // The head sits just before its body.
            self.entity(raw, raw, body, &kids, None, m, inherit, top, stack);
        }
    }

    /// One entity: `src[body.0 - 1]` is its `0 TYPE` pair, `src[body.0..body.1]`
    /// its pairs, `kids` the pair ranges of its VERTEX/ATTRIB children in `src`;
    /// `lw` the vertices of a streamed LWPOLYLINE (then not in its pairs).
    #[allow(clippy::too_many_arguments)]
    fn entity(
        &mut self,
        pre: &[Pair<'a>],
        src: &[Pair<'a>],
        body: (usize, usize),
        kids: &[(usize, usize)],
        lw: Option<&entities::LwVertices>,
        m: &Affine,
        inherit: Option<u32>,
        top: bool,
        stack: &mut Vec<&'a [u8]>,
    ) {
        let Some(&head) = body.0.checked_sub(1).and_then(|h| src.get(h)) else {
            return;
        };
        let body = src.get(body.0..body.1).unwrap_or(&[]);
        let name = head.trimmed();
        if matches!(name, b"ENDSEC" | b"EOF" | b"SEQEND" | b"ENDBLK") {
            return;
        }
        // Type names stay borrowed bytes until `finish`: no allocation per entity.
        let kind: &'a [u8] = &name[..name.len().min(MAX_TYPE_LEN)];
        // Paper space (group 67 = 1) is layout, not model: counted in a warning only.
        if body.iter().any(|p| p.code == 67 && p.int() == Some(1)) {
            self.paper_space += 1;
            return;
        }
        if top {
            self.count(kind);
        }
        let layer = match body.iter().find(|p| p.code == 8).map(|p| p.trimmed()) {
            Some(b"0") | None if inherit.is_some() => inherit.unwrap_or(0),
            Some(name) => self.layer_id(name),
            None => self.layer_id(b"0"),
        };
        let place = self.place(head.at);
        // Only curves need it (a square root per entity otherwise).
        let chord = || self.options.chord / m.mean_scale().max(1e-300);
        let built = match name {
            b"LINE" => Some(("LINE", entities::line(body))),
            b"ARC" => Some(("ARC", entities::arc(body))),
            b"CIRCLE" => Some(("CIRCLE", entities::circle(body))),
            b"LWPOLYLINE" => Some((
                "LWPOLYLINE",
                match lw {
                    Some(lw) => entities::lwpolyline_from(body, lw),
                    None => entities::lwpolyline(body),
                },
            )),
            b"POLYLINE" => {
                let vs: Vec<&[Pair]> = kids.iter().filter_map(|&(a, b)| src.get(a..b)).collect();
                let r = entities::polyline(body, &vs).map(|(segs, closed, z)| {
                    if let Some((lo, hi)) = z.filter(|(lo, hi)| hi - lo > 1e-6) {
                        let f = self.not_flat.get_or_insert((0, lo, hi, place));
                        *f = (f.0 + 1, f.1.min(lo), f.2.max(hi), f.3);
                    }
                    (segs, closed)
                });
                Some(("POLYLINE", r))
            }
            b"SPLINE" => Some((
                "SPLINE",
                curves::spline(body, chord()).map(|(segs, closed, note)| {
                    if let Some(n) = note {
                        let at = place_text(place);
                        self.d.warnings.push(Warning::new(
                            "spline-note",
                            text!("SPLINE at {}: {}", at.en, n.en; "SPLINE em {}: {}", at.pt, n.pt),
                        ));
                    }
                    (segs, closed)
                }),
            )),
            b"ELLIPSE" => Some(("ELLIPSE", ellipse::ellipse(body, chord()))),
            b"POINT" => {
                if let Ok(p) = entities::point(body, 10) {
                    let at = m.apply(p);
                    if at.is_finite() && at.x.abs() <= MAX_COORD_MM && at.y.abs() <= MAX_COORD_MM {
                        self.add_spot(at, layer);
                    }
                }
                return;
            }
            b"INSERT" => {
                self.insert(pre, body, m, layer, place, stack);
                return;
            }
            _ => None,
        };
        let Some((kind_name, result)) = built else {
            if top {
                *self.skipped.entry(kind).or_default() += 1;
            } else {
                *self.in_blocks_skipped.entry(kind).or_default() += 1;
            }
            return;
        };
        // Entities drawn in their own OCS; LINE, SPLINE, ELLIPSE and 3-D polylines are in world coordinates.
        // Flags matter only to POLYLINE (3-D ones are in world coordinates).
        let flags = || entities::int(body, 70).unwrap_or(0);
        let (ocs, tilted) = match kind_name {
            "ARC" | "CIRCLE" => entities::ocs(body, 30),
            "LWPOLYLINE" => entities::ocs(body, 38),
            "POLYLINE" if flags() & 8 == 0 => entities::ocs(body, 30),
            // In world coordinates, but projected when tilted: counted for the warning.
            "ELLIPSE" => (Affine::IDENTITY, entities::ocs(body, 30).1),
            _ => (Affine::IDENTITY, false),
        };
        if tilted {
            self.tilted += 1;
        }
        let m = &m.then_after(&ocs);
        match result.and_then(|(segs, closed)| self.place_segments(segs, m).map(|s| (s, closed))) {
            Ok((segments, closed)) => {
                if segments.is_empty() {
                    return;
                }
                self.add_entity(Entity {
                    kind: kind_name,
                    layer,
                    place,
                    segments,
                    closed,
                    source: None,
                    insert: self.insert,
                });
            }
            Err(reason) => {
                if top {
                    *self.skipped.entry(kind).or_default() += 1;
                }
                let at = entities::point(body, 10)
                    .ok()
                    .map(|p| m.apply(p))
                    .filter(|p| p.is_finite());
                let p = place_text(place);
                let kind = text!("{kind_name} skipped: {}", reason.en;
                                 "{kind_name} ignorada: {}", reason.pt);
                self.d.warnings.push(
                    Warning::maybe_at(
                        "entity-skipped",
                        text!("{kind_name} at {} skipped: {}", p.en, reason.en;
                              "{kind_name} em {} ignorada: {}", p.pt, reason.pt),
                        at,
                    )
                    .of_kind(kind, p),
                );
            }
        }
    }
}
