//! Outlines flattened to pixels, and what the raster makes of them
//! (issue 17 item 5: the preview's own raster in place of tiny-skia, whose
//! pipeline of blend modes and shaders cost ~60 KiB of the page's wasm):
//! dashes cut along each outline, and a stroke of width `w` drawn as the
//! union of a `w`-wide band along each piece and a disc at each vertex
//! (round caps and joins), every shape turning the same way so that their
//! windings add up instead of cancelling.

use super::raster::Area;

/// Flattened outlines (pixels): polyline `i` is
/// `points[starts[i]..starts[i + 1]]`.
#[derive(Default)]
pub struct Polylines {
    points: Vec<(f32, f32)>,
    starts: Vec<usize>,
}

impl Polylines {
    pub fn move_to(&mut self, x: f32, y: f32) {
        self.starts.push(self.points.len());
        self.points.push((x, y));
    }

    pub fn line_to(&mut self, x: f32, y: f32) {
        if self.starts.is_empty() {
            self.starts.push(0);
        }
        self.points.push((x, y));
    }

    /// Closes the last polyline (back to its first point).
    pub fn close(&mut self) {
        if let Some(&first) = self.starts.last().and_then(|&i| self.points.get(i)) {
            self.points.push(first);
        }
    }

    pub fn each(&self) -> impl Iterator<Item = &[(f32, f32)]> {
        let ends = self
            .starts
            .iter()
            .skip(1)
            .copied()
            .chain([self.points.len()]);
        self.starts
            .iter()
            .zip(ends)
            .map(|(&a, b)| &self.points[a..b])
    }

    /// The dashes of every polyline: `on` pixels drawn, `off` skipped,
    /// starting afresh on each polyline.
    pub fn dashed(&self, on: f32, off: f32) -> Polylines {
        let mut out = Polylines::default();
        for pl in self.each() {
            let (mut drawing, mut left) = (true, on);
            if let Some(&(x, y)) = pl.first() {
                out.move_to(x, y);
            }
            for w in pl.windows(2) {
                let (a, b) = (w[0], w[1]);
                let len = (b.0 - a.0).hypot(b.1 - a.1);
                let mut done = 0.0;
                while len - done > left {
                    done += left;
                    let t = done / len;
                    let (x, y) = (a.0 + (b.0 - a.0) * t, a.1 + (b.1 - a.1) * t);
                    if drawing {
                        out.line_to(x, y);
                    } else {
                        out.move_to(x, y);
                    }
                    drawing = !drawing;
                    left = if drawing { on } else { off };
                }
                left -= len - done;
                if drawing {
                    out.line_to(b.0, b.1);
                }
            }
        }
        out
    }
}

/// Adds the polylines stroked `width` pixels wide, round caps and joins,
/// to `area` (to be painted non-zero).
pub fn stroke(area: &mut Area, lines: &Polylines, width: f32) {
    let r = width / 2.0;
    // A disc's sides: within a twentieth of a pixel of the circle.
    let n = ((std::f32::consts::PI / (1.0 - 0.05 / r.max(0.1)).max(0.0).acos()).ceil() as usize)
        .clamp(6, 48);
    let disc: Vec<(f32, f32)> = (0..n)
        .map(|k| {
            // Clockwise in pixels (y down), as the bands below turn.
            let t = -(k as f32) * std::f32::consts::TAU / n as f32;
            (r * t.cos(), r * t.sin())
        })
        .collect();
    let mut at = Vec::with_capacity(n);
    for pl in lines.each().filter(|pl| pl.len() > 1) {
        for (i, &(x, y)) in pl.iter().enumerate() {
            at.clear();
            at.extend(disc.iter().map(|(dx, dy)| (x + dx, y + dy)));
            area.polygon(&at);
            let Some(&(bx, by)) = pl.get(i + 1) else {
                continue;
            };
            let len = (bx - x).hypot(by - y);
            if len > 1e-6 {
                let (nx, ny) = (-(by - y) / len * r, (bx - x) / len * r);
                area.polygon(&[
                    (x + nx, y + ny),
                    (bx + nx, by + ny),
                    (bx - nx, by - ny),
                    (x - nx, y - ny),
                ]);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::preview::raster::Raster;
    use tiny_skia::{Color, Pixmap};

    fn ink(lines: &Polylines, width: f32) -> (Pixmap, f32) {
        let mut p = Pixmap::new(60, 40).unwrap();
        p.fill(Color::WHITE);
        let mut area = Area::new(60, 40);
        Raster::new(&mut p).paint(&mut area, 0, false, &|a| stroke(a, lines, width));
        let ink = p
            .pixels()
            .iter()
            .map(|c| 1.0 - c.red() as f32 / 255.0)
            .sum();
        (p, ink)
    }

    #[test]
    fn a_stroke_covers_its_band_and_round_caps_once_even_where_pieces_overlap() {
        let mut l = Polylines::default();
        l.move_to(10.0, 20.0);
        l.line_to(30.0, 20.0);
        l.line_to(50.0, 20.0); // a join on a straight line: no double ink
        let (p, ink) = ink(&l, 4.0);
        let want = 40.0 * 4.0 + std::f32::consts::PI * 4.0;
        assert!((ink - want).abs() < 3.0, "{ink} for {want}");
        assert_eq!(p.pixel(30, 19).unwrap().red(), 0);
        assert_eq!(p.pixel(30, 23).unwrap().red(), 255);
    }

    #[test]
    fn dashes_draw_their_share_of_each_polyline() {
        let mut l = Polylines::default();
        l.move_to(0.0, 0.0);
        l.line_to(10.0, 0.0);
        l.line_to(10.0, 10.0); // the dash turns the corner
        let d = l.dashed(6.0, 4.0);
        let pieces: Vec<Vec<(f32, f32)>> = d.each().map(|p| p.to_vec()).collect();
        // On 0–6, off 6–10, on 10–16 (round the corner), off 16–20.
        assert_eq!(
            pieces,
            [vec![(0.0, 0.0), (6.0, 0.0)], vec![(10.0, 0.0), (10.0, 6.0)]]
        );
    }
}
