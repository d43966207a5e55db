//! The overview's own rasteriser (issue 17 item 4): with thousands of
//! contours in sight every mark is a few pixels, and tiny-skia's blitter,
//! which runs its whole pipeline for each span of one or two pixels, spent
//! 1.4 s natively (1.7 s in the page) on a 125k-contour nest. Here the marks
//! are written straight into the pixels:
//!
//! - areas by signed-area accumulation: each edge adds, to the cells it
//!   crosses, the share of the cell's height it covers times the fraction of
//!   the cell left of it (the area idea of font rasterisers, e.g. R. Levien's
//!   font-rs, 2016); a running sum along each row then gives the winding
//!   number, folded even-odd, anti-aliased where edges cross a pixel;
//! - lines 1 px wide by X. Wu's method (1991): two pixels per step of the
//!   major axis, weighted by the distance to the line;
//! - dots as discs, each pixel covered by `r + ½ − distance`.
//!
//! The image is opaque (white under everything), so blending a colour over a
//! pixel is one interpolation per channel, premultiplied or not alike.

use tiny_skia::Pixmap;

use super::pen::Sink;

/// Largest image (pixels) whose area buffer is made: 4 bytes a pixel.
pub const MAX_AREA_PIXELS: usize = 16 << 20;

/// A pixmap drawn into directly.
pub struct Raster<'a> {
    data: &'a mut [u8],
    w: usize,
    h: usize,
}

/// Channels of a colour `0xRRGGBB`.
fn channels(hex: u32) -> [f32; 3] {
    [(hex >> 16) as u8, (hex >> 8) as u8, hex as u8].map(f32::from)
}

impl<'a> Raster<'a> {
    pub fn new(pixmap: &'a mut Pixmap) -> Raster<'a> {
        let (w, h) = (pixmap.width() as usize, pixmap.height() as usize);
        Raster {
            data: pixmap.data_mut(),
            w,
            h,
        }
    }

    /// Blends `rgb` over pixel `(x, y)` with coverage `a` (0..=1).
    #[inline]
    fn blend(&mut self, x: i64, y: i64, rgb: [f32; 3], a: f32) {
        if x < 0 || y < 0 || x as usize >= self.w || y as usize >= self.h || a <= 0.0 {
            return;
        }
        let i = 4 * (y as usize * self.w + x as usize);
        let a = a.min(1.0);
        for (d, c) in self.data[i..i + 3].iter_mut().zip(rgb) {
            let v = f32::from(*d);
            *d = (v + (c - v) * a + 0.5) as u8;
        }
    }

    /// Fills the winding of `area` even-odd with `hex`.
    pub fn fill(&mut self, area: &Area, hex: u32) {
        let rgb = channels(hex);
        for y in 0..self.h {
            let row = &area.cells[y * area.stride..(y + 1) * area.stride];
            let mut winding = 0.0f32;
            for (x, cell) in row.iter().take(self.w).enumerate() {
                winding += cell;
                // Even-odd: 1 inside an odd winding, 0 in an even one,
                // the fraction between on an edge.
                let w = winding.abs();
                let m = w - 2.0 * (w / 2.0).floor(); // w mod 2, without libm's fmodf
                let a = if m > 1.0 { 2.0 - m } else { m };
                if a > 1.0 / 512.0 {
                    self.blend(x as i64, y as i64, rgb, a);
                }
            }
        }
    }

    /// A line 1 px wide from `a` to `b` (pixels), anti-aliased.
    pub fn line(&mut self, a: (f32, f32), b: (f32, f32), hex: u32) {
        let Some(((x0, y0), (x1, y1))) = clip(a, b, self.w as f32, self.h as f32) else {
            return;
        };
        let rgb = channels(hex);
        let steep = (y1 - y0).abs() > (x1 - x0).abs();
        // Along the major axis `u`, across it `v`.
        let (u0, v0, u1, v1) = if steep {
            (y0, x0, y1, x1)
        } else {
            (x0, y0, x1, y1)
        };
        let (u0, v0, u1, v1) = if u0 > u1 {
            (u1, v1, u0, v0)
        } else {
            (u0, v0, u1, v1)
        };
        let slope = if u1 - u0 > 1e-6 {
            (v1 - v0) / (u1 - u0)
        } else {
            0.0
        };
        // Pixel centres are at +0.5: step over the centres the line spans.
        let first = u0.floor() as i64;
        let last = (u1 - 1e-3).floor().max(u0.floor()) as i64;
        for u in first..=last {
            let v = v0 + slope * (u as f32 + 0.5 - u0) - 0.5;
            let vf = v.floor();
            let frac = v - vf;
            let vi = vf as i64;
            for (vv, a) in [(vi, 1.0 - frac), (vi + 1, frac)] {
                if steep {
                    self.blend(vv, u, rgb, a);
                } else {
                    self.blend(u, vv, rgb, a);
                }
            }
        }
    }

    /// Discs of radius `r` (pixels) at `centres`.
    pub fn discs(&mut self, centres: &[(f32, f32)], r: f32, hex: u32) {
        let rgb = channels(hex);
        let reach = (r + 1.0).ceil() as i64;
        for &(cx, cy) in centres {
            if !(cx.is_finite() && cy.is_finite()) {
                continue;
            }
            let (px, py) = (cx.floor() as i64, cy.floor() as i64);
            for y in py - reach..=py + reach {
                for x in px - reach..=px + reach {
                    let (dx, dy) = (x as f32 + 0.5 - cx, y as f32 + 0.5 - cy);
                    let d = (dx * dx + dy * dy).sqrt();
                    self.blend(x, y, rgb, (r + 0.5 - d).clamp(0.0, 1.0));
                }
            }
        }
    }
}

/// The segment `a`–`b` cut to the image grown by 2 px (Liang–Barsky), or
/// None when it misses it: a far line costs nothing.
fn clip(a: (f32, f32), b: (f32, f32), w: f32, h: f32) -> Option<((f32, f32), (f32, f32))> {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let (mut t0, mut t1) = (0.0f32, 1.0f32);
    for (p, q) in [
        (-dx, a.0 + 2.0),
        (dx, w + 2.0 - a.0),
        (-dy, a.1 + 2.0),
        (dy, h + 2.0 - a.1),
    ] {
        if p == 0.0 {
            if q < 0.0 {
                return None;
            }
        } else {
            let t = q / p;
            if p < 0.0 {
                t0 = t0.max(t);
            } else {
                t1 = t1.min(t);
            }
        }
    }
    (t0 <= t1).then_some((
        (a.0 + t0 * dx, a.1 + t0 * dy),
        (a.0 + t1 * dx, a.1 + t1 * dy),
    ))
}

/// Flattened outlines (pixels), kept for the raster: polyline `i` is
/// `points[starts[i]..starts[i + 1]]`.
#[derive(Default)]
pub struct Polylines {
    points: Vec<(f32, f32)>,
    starts: Vec<usize>,
}

impl Polylines {
    fn each(&self) -> impl Iterator<Item = &[(f32, f32)]> {
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
}

impl Sink for Polylines {
    fn move_to(&mut self, x: f32, y: f32) {
        self.starts.push(self.points.len());
        self.points.push((x, y));
    }
    fn line_to(&mut self, x: f32, y: f32) {
        if self.starts.is_empty() {
            self.starts.push(0);
        }
        self.points.push((x, y));
    }
    fn close(&mut self) {
        if let Some(&first) = self.starts.last().and_then(|&i| self.points.get(i)) {
            self.points.push(first);
        }
    }
}

impl Raster<'_> {
    /// The polylines' lines in `hex`, 1 px wide.
    pub fn polylines(&mut self, lines: &Polylines, hex: u32) {
        for pl in lines.each() {
            for w in pl.windows(2) {
                self.line(w[0], w[1], hex);
            }
        }
    }
}

/// Signed areas of edges, per pixel, for [`Raster::fill`].
pub struct Area {
    cells: Vec<f32>,
    stride: usize,
    w: f32,
    h: f32,
}

impl Area {
    /// An empty area buffer for a `w × h` image; None above [`MAX_AREA_PIXELS`].
    pub fn new(w: u32, h: u32) -> Option<Area> {
        let stride = w as usize + 2; // an edge at the right border adds to the cell after it
        let n = stride.checked_mul(h as usize)?;
        (n <= MAX_AREA_PIXELS).then(|| Area {
            cells: vec![0.0; n],
            stride,
            w: w as f32,
            h: h as f32,
        })
    }

    /// Adds the edge from `a` to `b` (pixels). Left of the image an edge
    /// counts on its first column (what is left of the image is left of
    /// every pixel), above and below it nothing is covered.
    pub fn edge(&mut self, a: (f32, f32), b: (f32, f32)) {
        let (a, b, dir) = if a.1 <= b.1 {
            (a, b, 1.0)
        } else {
            (b, a, -1.0)
        };
        let (ya, yb) = (a.1.max(0.0), b.1.min(self.h));
        if ya.partial_cmp(&yb) != Some(std::cmp::Ordering::Less) {
            return; // horizontal, outside, or not a number
        }
        let dxdy = (b.0 - a.0) / (b.1 - a.1);
        let mut x = a.0 + (ya - a.1) * dxdy;
        let last = (yb.ceil() as usize).min(self.h as usize);
        for row in ya.floor() as usize..last {
            let y = row as f32;
            let dy = (y + 1.0).min(yb) - y.max(ya);
            let next = x + dxdy * dy;
            self.span(row, x, next, dy * dir);
            x = next;
        }
    }

    /// Adds the polylines as closed outlines.
    pub fn polylines(&mut self, lines: &Polylines) {
        for pl in lines.each() {
            for (i, &a) in pl.iter().enumerate() {
                self.edge(a, pl[(i + 1) % pl.len()]);
            }
        }
    }

    /// One row's part of an edge: from `x` to `next` across height `d` (signed).
    fn span(&mut self, row: usize, x: f32, next: f32, d: f32) {
        let (x0, x1) = if x < next { (x, next) } else { (next, x) };
        let (x0, x1) = (x0.clamp(0.0, self.w), x1.clamp(0.0, self.w));
        let cells = &mut self.cells[row * self.stride..(row + 1) * self.stride];
        let (i0, i1) = (x0.floor() as usize, x1.ceil() as usize);
        if i1 <= i0 + 1 {
            // Within one cell: the part right of the edge's mean x is covered.
            let mid = (x0 + x1) / 2.0 - i0 as f32;
            cells[i0] += d * (1.0 - mid);
            cells[i0 + 1] += d * mid;
            return;
        }
        // Across cells: the covered area grows as a ramp from x0 to x1.
        let s = 1.0 / (x1 - x0);
        let f0 = x0 - i0 as f32;
        let first = 0.5 * s * (1.0 - f0) * (1.0 - f0);
        let f1 = x1 - (i1 - 1) as f32;
        let end = 0.5 * s * f1 * f1;
        cells[i0] += d * first;
        if i1 == i0 + 2 {
            cells[i0 + 1] += d * (1.0 - first - end);
        } else {
            let second = s * (1.5 - f0);
            cells[i0 + 1] += d * (second - first);
            for c in &mut cells[i0 + 2..i1 - 1] {
                *c += d * s;
            }
            let before_end = second + (i1 - i0 - 3) as f32 * s;
            cells[i1 - 1] += d * (1.0 - before_end - end);
        }
        cells[i1] += d * end;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use tiny_skia::Color;

    fn white(w: u32, h: u32) -> Pixmap {
        let mut p = Pixmap::new(w, h).unwrap();
        p.fill(Color::WHITE);
        p
    }

    fn px(p: &Pixmap, x: u32, y: u32) -> [u8; 3] {
        let c = p.pixel(x, y).unwrap();
        [c.red(), c.green(), c.blue()]
    }

    fn polygon(area: &mut Area, pts: &[(f32, f32)]) {
        for i in 0..pts.len() {
            area.edge(pts[i], pts[(i + 1) % pts.len()]);
        }
    }

    #[test]
    fn a_square_is_filled_inside_only_and_a_hole_in_it_stays_empty_whatever_its_direction() {
        for hole_reversed in [false, true] {
            let mut p = white(40, 40);
            let mut area = Area::new(40, 40).unwrap();
            polygon(
                &mut area,
                &[(5.0, 5.0), (35.0, 5.0), (35.0, 35.0), (5.0, 35.0)],
            );
            let mut hole = vec![(15.0, 15.0), (25.0, 15.0), (25.0, 25.0), (15.0, 25.0)];
            if hole_reversed {
                hole.reverse();
            }
            polygon(&mut area, &hole);
            Raster::new(&mut p).fill(&area, 0x102030);
            assert_eq!(px(&p, 10, 10), [0x10, 0x20, 0x30]);
            assert_eq!(px(&p, 34, 34), [0x10, 0x20, 0x30]);
            assert_eq!(px(&p, 20, 20), [255; 3], "the hole");
            assert_eq!(px(&p, 2, 20), [255; 3]);
            assert_eq!(px(&p, 37, 20), [255; 3]);
            // Every pixel's coverage is the share of it inside: 30² − 10² pixels in all.
            let ink: f32 = p
                .pixels()
                .iter()
                .map(|c| (255.0 - c.red() as f32) / (255.0 - 16.0))
                .sum();
            assert!((ink - 800.0).abs() < 1.0, "{ink}");
        }
    }

    #[test]
    fn a_slanted_edge_covers_half_of_the_pixels_it_halves() {
        // A triangle under the diagonal of a 20 px square: 200 px² of coverage.
        let mut p = white(30, 30);
        let mut area = Area::new(30, 30).unwrap();
        polygon(&mut area, &[(2.0, 2.0), (22.0, 22.0), (2.0, 22.0)]);
        Raster::new(&mut p).fill(&area, 0x000000);
        let ink: f32 = p
            .pixels()
            .iter()
            .map(|c| 1.0 - c.red() as f32 / 255.0)
            .sum();
        assert!((ink - 200.0).abs() < 1.0, "{ink}");
        // A pixel the diagonal cuts through its corners is half covered.
        let half = p.pixel(10, 10).unwrap().red();
        assert!((120..=135).contains(&half), "{half}");
    }

    #[test]
    fn shapes_beyond_the_image_fill_what_they_cover_of_it() {
        let mut p = white(20, 20);
        let mut area = Area::new(20, 20).unwrap();
        polygon(
            &mut area,
            &[(-50.0, -50.0), (10.0, -50.0), (10.0, 70.0), (-50.0, 70.0)],
        );
        Raster::new(&mut p).fill(&area, 0);
        assert_eq!(px(&p, 0, 0), [0; 3]);
        assert_eq!(px(&p, 9, 19), [0; 3]);
        assert_eq!(px(&p, 10, 5), [255; 3]);
    }

    #[test]
    fn a_line_inks_about_one_pixel_per_pixel_of_length_and_nothing_off_it() {
        let mut p = white(50, 50);
        let mut r = Raster::new(&mut p);
        r.line((5.0, 10.5), (45.0, 30.5), 0);
        r.line((-1e6, 40.5), (1e6, 40.5), 0); // clipped, not walked
        let ink: f32 = p
            .pixels()
            .iter()
            .map(|c| 1.0 - c.red() as f32 / 255.0)
            .sum();
        // One pixel's worth per column crossed: 40 for the slanted line, 50 for the clipped one.
        assert!((ink - 90.0).abs() < 2.0, "{ink}");
        assert_eq!(px(&p, 25, 40), [0; 3]);
        assert_eq!(px(&p, 25, 5), [255; 3]);
    }

    #[test]
    fn a_disc_covers_about_pi_r_squared() {
        let mut p = white(20, 20);
        Raster::new(&mut p).discs(&[(10.0, 10.0)], 3.0, 0);
        let ink: f32 = p
            .pixels()
            .iter()
            .map(|c| 1.0 - c.red() as f32 / 255.0)
            .sum();
        assert!((ink - std::f32::consts::PI * 9.0).abs() < 2.0, "{ink}");
        assert_eq!(px(&p, 10, 10), [0; 3]);
    }
}
