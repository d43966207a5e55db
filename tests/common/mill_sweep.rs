//! An independent check of a router program (issue 43 §6), written apart
//! from `kerfcam::mill`: the program's text is read back here (G0–G3,
//! X Y Z I J, modal words), every feed move below the stock's top is
//! sampled every 0.1 mm, and the tool's disc is stamped on a grid of the
//! part, whose cells are classified from the test's own shapes. A disc
//! reaching a cell of material to keep (an island, a wall) is a gouge; a
//! pocket cell a disc of the tool's radius could reach (the pocket opened
//! by the disc, computed here from the shapes' distances) that no disc at
//! full depth covered is material left.

/// What the test knows the part to be: a cell's class.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Cell {
    /// Material to clear at full depth.
    Pocket,
    /// Material to keep.
    Keep,
    /// Outside the stock (a profile's scrap side).
    Outside,
}

/// One sample of the tool's centre on a feed move.
#[derive(Clone, Copy, Debug)]
pub struct Sample {
    pub x: f64,
    pub y: f64,
    pub z: f64,
}

/// The feed moves' samples of a program (absolute coordinates, I/J from
/// the arc's start).
pub fn samples(program: &str, step: f64) -> Vec<Sample> {
    let mut out = Vec::new();
    let (mut x, mut y, mut z) = (0.0_f64, 0.0_f64, 100.0_f64);
    let mut motion = 0;
    for raw in program.lines() {
        let line = raw.split(';').next().unwrap_or("");
        let mut clean = String::new();
        let mut paren = false;
        for c in line.chars() {
            match c {
                '(' => paren = true,
                ')' => paren = false,
                c if !paren => clean.push(c.to_ascii_uppercase()),
                _ => {}
            }
        }
        let mut words: Vec<(char, f64)> = Vec::new();
        let chars: Vec<char> = clean.chars().filter(|c| !c.is_whitespace()).collect();
        let mut i = 0;
        while i < chars.len() {
            let letter = chars[i];
            let mut j = i + 1;
            while j < chars.len()
                && (chars[j].is_ascii_digit() || chars[j] == '.' || chars[j] == '-')
            {
                j += 1;
            }
            let v: f64 = chars[i + 1..j]
                .iter()
                .collect::<String>()
                .parse()
                .unwrap_or(f64::NAN);
            words.push((letter, v));
            i = j.max(i + 1);
        }
        let mut dwell = false;
        for &(l, v) in &words {
            if l == 'G' {
                match v {
                    v if v == 0.0 || v == 1.0 || v == 2.0 || v == 3.0 => motion = v as i32,
                    4.0 => dwell = true,
                    _ => {}
                }
            }
        }
        if dwell {
            continue;
        }
        let get = |c: char| words.iter().find(|w| w.0 == c).map(|w| w.1);
        let (nx, ny, nz) = (
            get('X').unwrap_or(x),
            get('Y').unwrap_or(y),
            get('Z').unwrap_or(z),
        );
        if get('X').is_none() && get('Y').is_none() && get('Z').is_none() {
            continue;
        }
        match motion {
            1 => {
                let len = ((nx - x).powi(2) + (ny - y).powi(2) + (nz - z).powi(2)).sqrt();
                let n = (len / step).ceil().max(1.0) as usize;
                for k in 0..=n {
                    let t = k as f64 / n as f64;
                    out.push(Sample {
                        x: x + (nx - x) * t,
                        y: y + (ny - y) * t,
                        z: z + (nz - z) * t,
                    });
                }
            }
            2 | 3 => {
                let (cx, cy) = (x + get('I').unwrap_or(0.0), y + get('J').unwrap_or(0.0));
                let r = (x - cx).hypot(y - cy);
                let a0 = (y - cy).atan2(x - cx);
                let mut a1 = (ny - cy).atan2(nx - cx);
                let tau = std::f64::consts::TAU;
                if motion == 3 {
                    while a1 <= a0 + 1e-12 {
                        a1 += tau;
                    }
                } else {
                    while a1 >= a0 - 1e-12 {
                        a1 -= tau;
                    }
                }
                let n = ((a1 - a0).abs() * r / step).ceil().max(1.0) as usize;
                for k in 0..=n {
                    let t = k as f64 / n as f64;
                    let a = a0 + (a1 - a0) * t;
                    out.push(Sample {
                        x: cx + r * a.cos(),
                        y: cy + r * a.sin(),
                        z: z + (nz - z) * t,
                    });
                }
            }
            _ => {}
        }
        (x, y, z) = (nx, ny, nz);
    }
    out
}

/// The part on a grid of `cell` mm from `min` to `max`.
pub struct Grid {
    pub cell: f64,
    pub x0: f64,
    pub y0: f64,
    pub nx: usize,
    pub ny: usize,
    pub class: Vec<Cell>,
    /// For pocket cells, the distance from the cell's centre to the
    /// nearest cell that is not pocket (the walls), mm.
    pub wall: Vec<f64>,
}

impl Grid {
    /// Cells classified by `class_of`, walls' distance by `wall_of`.
    pub fn new(
        min: (f64, f64),
        max: (f64, f64),
        cell: f64,
        class_of: impl Fn(f64, f64) -> Cell,
        wall_of: impl Fn(f64, f64) -> f64,
    ) -> Grid {
        let nx = ((max.0 - min.0) / cell).ceil() as usize;
        let ny = ((max.1 - min.1) / cell).ceil() as usize;
        let mut class = Vec::with_capacity(nx * ny);
        let mut wall = Vec::with_capacity(nx * ny);
        for j in 0..ny {
            for i in 0..nx {
                let (x, y) = (
                    min.0 + (i as f64 + 0.5) * cell,
                    min.1 + (j as f64 + 0.5) * cell,
                );
                let c = class_of(x, y);
                class.push(c);
                wall.push(if c == Cell::Pocket {
                    wall_of(x, y)
                } else {
                    0.0
                });
            }
        }
        Grid {
            cell,
            x0: min.0,
            y0: min.1,
            nx,
            ny,
            class,
            wall,
        }
    }
    fn centre(&self, k: usize) -> (f64, f64) {
        let (i, j) = (k % self.nx, k / self.nx);
        (
            self.x0 + (i as f64 + 0.5) * self.cell,
            self.y0 + (j as f64 + 0.5) * self.cell,
        )
    }
    /// Calls `f` with every cell whose centre is within `r` of (x, y).
    fn disc(&self, x: f64, y: f64, r: f64, mut f: impl FnMut(usize)) {
        let i0 = (((x - r - self.x0) / self.cell).floor().max(0.0)) as usize;
        let j0 = (((y - r - self.y0) / self.cell).floor().max(0.0)) as usize;
        let i1 = ((((x + r - self.x0) / self.cell).ceil()) as usize).min(self.nx);
        let j1 = ((((y + r - self.y0) / self.cell).ceil()) as usize).min(self.ny);
        // Row by row, the cells inside form one run: its ends from the
        // chord's half width, then moved onto the exact test (the same
        // cells as testing each one, without testing the run's inside).
        let inside = |i: usize, dy2: f64| {
            let cx = self.x0 + (i as f64 + 0.5) * self.cell;
            (cx - x).powi(2) + dy2 <= r * r
        };
        for j in j0..j1 {
            let cy = self.y0 + (j as f64 + 0.5) * self.cell;
            let dy2 = (cy - y).powi(2);
            if dy2 > r * r || i0 >= i1 {
                continue;
            }
            let half = (r * r - dy2).sqrt();
            let guess = |x: f64| ((x - self.x0) / self.cell - 0.5).round().clamp(i0 as f64, (i1 - 1) as f64) as usize;
            let (mut a, mut b) = (guess(x - half), guess(x + half));
            while a > i0 && inside(a - 1, dy2) {
                a -= 1;
            }
            while a <= b && !inside(a, dy2) {
                a += 1;
            }
            while b + 1 < i1 && inside(b + 1, dy2) {
                b += 1;
            }
            while b >= a && !inside(b, dy2) {
                if b == 0 {
                    break;
                }
                b -= 1;
            }
            if a > b || !inside(a, dy2) {
                continue;
            }
            for i in a..=b {
                f(j * self.nx + i);
            }
        }
    }
}

/// What the sweep found.
#[derive(Debug)]
pub struct Sweep {
    /// Area of keep cells a disc below the top reached, mm².
    pub gouge_mm2: f64,
    /// One such cell's centre.
    pub gouge_at: Option<(f64, f64)>,
    /// Pocket area the tool can reach, mm².
    pub reachable_mm2: f64,
    /// Of it, cleared at full depth, mm².
    pub cleared_mm2: f64,
    /// Pocket area as drawn, mm².
    pub pocket_mm2: f64,
}

/// Sweeps a disc of `r` (the gouge test with `r − slack`) over `samples`:
/// below Z 0 for gouges, at `full` depth (within 1 µm) for clearing.
pub fn sweep(g: &Grid, samples: &[Sample], r: f64, full: f64, slack: f64) -> Sweep {
    let area = g.cell * g.cell;
    let mut cleared = vec![false; g.class.len()];
    let mut gouge = 0usize;
    let mut gouge_at = None;
    let mut hit = vec![false; g.class.len()];
    for s in samples {
        if s.z >= 0.0 {
            continue;
        }
        let mut gouges = |k: usize| {
            if g.class[k] == Cell::Keep && !hit[k] {
                hit[k] = true;
                gouge += 1;
                gouge_at.get_or_insert(g.centre(k));
            }
        };
        if s.z <= full + 1e-3 {
            // One pass for both discs: the cleared one of `r`, and in it
            // the gouge test's of `r − slack`.
            let inner = (r - slack).max(0.0).powi(2);
            g.disc(s.x, s.y, r, |k| {
                cleared[k] = true;
                if g.class[k] == Cell::Keep {
                    let (cx, cy) = g.centre(k);
                    if (cx - s.x).powi(2) + (cy - s.y).powi(2) <= inner {
                        gouges(k);
                    }
                }
            });
        } else {
            g.disc(s.x, s.y, r - slack, &mut gouges);
        }
    }
    // Reachable: pocket cells within r of a cell whose disc fits (wall
    // distance ≥ r); stamped from the fitting cells near the walls only
    // (a point a disc inside reaches is also reached from that band).
    let mut reach = vec![false; g.class.len()];
    for k in 0..g.class.len() {
        if g.class[k] != Cell::Pocket || g.wall[k] < r {
            continue;
        }
        reach[k] = true;
        if g.wall[k] < r + 2.0 * g.cell {
            let (x, y) = g.centre(k);
            g.disc(x, y, r, |q| {
                if g.class[q] == Cell::Pocket {
                    reach[q] = true;
                }
            });
        }
    }
    let pocket = g.class.iter().filter(|c| **c == Cell::Pocket).count();
    let reachable = reach.iter().filter(|r| **r).count();
    let both = (0..g.class.len())
        .filter(|&k| reach[k] && cleared[k])
        .count();
    Sweep {
        gouge_mm2: gouge as f64 * area,
        gouge_at,
        reachable_mm2: reachable as f64 * area,
        cleared_mm2: both as f64 * area,
        pocket_mm2: pocket as f64 * area,
    }
}

/// A disc's cells by runs are the cells whose centre is within `r`, each
/// tested: random discs on a small grid, over its edges too.
#[test]
fn a_disc_by_runs_is_every_cell_within_its_radius() {
    let g = Grid::new((-3.0, -2.0), (7.0, 5.0), 0.25, |_, _| Cell::Pocket, |_, _| 1.0);
    let mut seed = 0x2545_f491_4f6c_dd1du64;
    let mut next = || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        (seed >> 11) as f64 / (1u64 << 53) as f64
    };
    for _ in 0..2000 {
        let (x, y, r) = (-5.0 + 14.0 * next(), -4.0 + 11.0 * next(), 3.0 * next());
        let mut runs = Vec::new();
        g.disc(x, y, r, |k| runs.push(k));
        let each: Vec<usize> = (0..g.nx * g.ny)
            .filter(|&k| {
                let (cx, cy) = g.centre(k);
                (cx - x).powi(2) + (cy - y).powi(2) <= r * r
            })
            .collect();
        assert_eq!(runs, each, "disc at ({x}, {y}) of {r}");
    }
}
