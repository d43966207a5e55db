//! The preview's own rasteriser (issue 17 items 4 and 5): with thousands of
//! contours in sight every mark is a few pixels, and tiny-skia's blitter,
//! which runs its whole pipeline for each span of one or two pixels, spent
//! 1.4 s natively (1.7 s in the page) on a 125k-contour nest; its pipeline
//! of blend modes and shaders, none of them used, was ~70 KB (gzip) of the
//! page's wasm. Here the marks are written straight into the pixels:
//!
//! - areas by signed-area accumulation: each edge adds, to the cells it
//!   crosses, the share of the cell's height it covers times the fraction of
//!   the cell left of it (the area idea of font rasterisers, e.g. R. Levien's
//!   font-rs, 2016); a running sum along each row then gives the winding
//!   number, folded even-odd (areas) or clamped to 1 (strokes, stroke.rs),
//!   anti-aliased where edges cross a pixel; done in bands of rows so a
//!   big image needs no big buffer;
//! - lines 1 px wide by X. Wu's method (1991): two pixels per step of the
//!   major axis, weighted by the distance to the line;
//! - dots as discs, each pixel covered by `r + ½ − distance`.
//!
//! The image is opaque (white under everything), so blending a colour over a
//! pixel is one interpolation per channel, premultiplied or not alike.

use tiny_skia::Pixmap;

/// Most cells in an area buffer (4 bytes each): taller images go in bands.
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

    /// Fills what `shapes` adds to `area` with `hex`, band by band (the
    /// whole image in one band up to [`MAX_AREA_PIXELS`]): even-odd, or
    /// covered wherever a shape is (non-zero, all shapes turning alike).
    pub fn paint(&mut self, area: &mut Area, hex: u32, even_odd: bool, shapes: &dyn Fn(&mut Area)) {
        let rgb = channels(hex);
        let mut top = 0;
        while top < self.h {
            area.top = top as f32;
            area.touched = (usize::MAX, 0, usize::MAX);
            shapes(area);
            // Only the rows and columns the edges reached (a diamond costs
            // its own few pixels, not the image's); left as found: zero.
            let (lo, hi, left) = area.touched;
            for row in lo..hi.min(area.rows) {
                let at = row * area.stride;
                let y = top + row;
                let mut winding = 0.0f32;
                for x in left..self.w.min(area.stride) {
                    winding += std::mem::take(&mut area.cells[at + x]);
                    if y >= self.h {
                        continue;
                    }
                    let w = winding.abs();
                    // Even-odd: 1 inside an odd winding, 0 in an even one,
                    // the fraction between on an edge (w mod 2, without fmodf).
                    let m = w - 2.0 * (w / 2.0).floor();
                    let a = match even_odd {
                        true if m > 1.0 => 2.0 - m,
                        true => m,
                        false => w,
                    };
                    if a > 1.0 / 512.0 {
                        self.blend(x as i64, y as i64, rgb, a);
                    }
                }
                area.cells[at + self.w..at + area.stride].fill(0.0);
            }
            top += area.rows;
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

/// Signed areas of edges, per pixel, for [`Raster::paint`]: a band of
/// `rows` rows from `top`.
pub struct Area {
    cells: Vec<f32>,
    stride: usize,
    rows: usize,
    top: f32,
    w: f32,
    /// Rows `lo..hi` and columns from `left` on that edges reached.
    touched: (usize, usize, usize),
}

impl Area {
    /// An area buffer for a `w`-pixel-wide image, `h` rows or as many as
    /// fit in [`MAX_AREA_PIXELS`].
    pub fn new(w: u32, h: u32) -> Area {
        let stride = w as usize + 2; // an edge at the right border adds to the cell after it
        let rows = (MAX_AREA_PIXELS / stride).clamp(1, (h as usize).max(1));
        Area {
            cells: vec![0.0; stride * rows],
            stride,
            rows,
            top: 0.0,
            w: w as f32,
            touched: (usize::MAX, 0, usize::MAX),
        }
    }

    /// A closed polygon (pixels).
    pub fn polygon(&mut self, points: &[(f32, f32)]) {
        for (i, &a) in points.iter().enumerate() {
            self.edge(a, points[(i + 1) % points.len()]);
        }
    }

    /// Adds the edge from `a` to `b` (pixels). Left of the image an edge
    /// counts on its first column (what is left of the image is left of
    /// every pixel), above and below it nothing is covered.
    pub fn edge(&mut self, a: (f32, f32), b: (f32, f32)) {
        let (a, b) = ((a.0, a.1 - self.top), (b.0, b.1 - self.top));
        let (a, b, dir) = if a.1 <= b.1 {
            (a, b, 1.0)
        } else {
            (b, a, -1.0)
        };
        let (ya, yb) = (a.1.max(0.0), b.1.min(self.rows as f32));
        if ya.partial_cmp(&yb) != Some(std::cmp::Ordering::Less) {
            return; // horizontal, outside, or not a number
        }
        let dxdy = (b.0 - a.0) / (b.1 - a.1);
        let mut x = a.0 + (ya - a.1) * dxdy;
        let last = (yb.ceil() as usize).min(self.rows);
        let t = &mut self.touched;
        *t = (t.0.min(ya.floor() as usize), t.1.max(last), t.2);
        for row in ya.floor() as usize..last {
            let y = row as f32;
            let dy = (y + 1.0).min(yb) - y.max(ya);
            let next = x + dxdy * dy;
            self.span(row, x, next, dy * dir);
            x = next;
        }
    }

    /// One row's part of an edge: from `x` to `next` across height `d` (signed).
    fn span(&mut self, row: usize, x: f32, next: f32, d: f32) {
        let (x0, x1) = if x < next { (x, next) } else { (next, x) };
        let (x0, x1) = (x0.clamp(0.0, self.w), x1.clamp(0.0, self.w));
        let cells = &mut self.cells[row * self.stride..(row + 1) * self.stride];
        let (i0, i1) = (x0.floor() as usize, x1.ceil() as usize);
        self.touched.2 = self.touched.2.min(i0);
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

    fn fill(p: &mut Pixmap, hex: u32, shapes: &dyn Fn(&mut Area)) {
        let mut area = Area::new(p.width(), p.height());
        Raster::new(p).paint(&mut area, hex, true, shapes);
    }

    #[test]
    fn a_square_is_filled_inside_only_and_a_hole_in_it_stays_empty_whatever_its_direction() {
        for hole_reversed in [false, true] {
            let mut p = white(40, 40);
            let mut hole = vec![(15.0, 15.0), (25.0, 15.0), (25.0, 25.0), (15.0, 25.0)];
            if hole_reversed {
                hole.reverse();
            }
            fill(&mut p, 0x102030, &|a| {
                a.polygon(&[(5.0, 5.0), (35.0, 5.0), (35.0, 35.0), (5.0, 35.0)]);
                a.polygon(&hole);
            });
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
        fill(&mut p, 0, &|a| {
            a.polygon(&[(2.0, 2.0), (22.0, 22.0), (2.0, 22.0)])
        });
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
        fill(&mut p, 0, &|a| {
            a.polygon(&[(-50.0, -50.0), (10.0, -50.0), (10.0, 70.0), (-50.0, 70.0)])
        });
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
