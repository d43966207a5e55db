//! A single-stroke font of our own: every glyph a few polylines on a grid
//! 4 units wide and 6 high (baseline at 0, capitals 6 high), drawn for a
//! scribe or an etching pass — one line per stroke, no outline to fill.
//! Digits, A–Z, space and `# - _ . / ?`; lowercase is drawn as uppercase,
//! a few accented letters as their base letter, anything else as `?`.

use crate::geom::Point;

/// Grid units from one glyph's left edge to the next one's (4 of glyph,
/// 2 of gap).
pub const ADVANCE: f64 = 6.0;
/// Glyph width in grid units.
pub const WIDTH: f64 = 4.0;
/// Capital height in grid units.
pub const HEIGHT: f64 = 6.0;

/// The strokes of `c` in grid units: polylines separated by `|`, points
/// `x,y` separated by spaces. None for a character the font lacks.
fn strokes(c: char) -> Option<&'static str> {
    Some(match c {
        ' ' => "",
        '0' => "0,1 1,0 3,0 4,1 4,5 3,6 1,6 0,5 0,1|0,1 4,5",
        '1' => "1,5 2,6 2,0|1,0 3,0",
        '2' => "0,5 1,6 3,6 4,5 4,4 0,0 4,0",
        '3' => "0,5 1,6 3,6 4,5 4,4 3,3 1,3|3,3 4,2 4,1 3,0 1,0 0,1",
        '4' => "3,0 3,6 0,2 4,2",
        '5' => "4,6 0,6 0,3 3,3 4,2 4,1 3,0 0,0",
        '6' => "4,5 3,6 1,6 0,5 0,1 1,0 3,0 4,1 4,2 3,3 0,3",
        '7' => "0,6 4,6 1,0",
        '8' => "1,3 0,4 0,5 1,6 3,6 4,5 4,4 3,3 1,3 0,2 0,1 1,0 3,0 4,1 4,2 3,3",
        '9' => "0,1 1,0 3,0 4,1 4,5 3,6 1,6 0,5 0,4 1,3 4,3",
        'A' => "0,0 0,4 2,6 4,4 4,0|0,3 4,3",
        'B' => "0,0 0,6 3,6 4,5 4,4 3,3 0,3|3,3 4,2 4,1 3,0 0,0",
        'C' => "4,5 3,6 1,6 0,5 0,1 1,0 3,0 4,1",
        'D' => "0,0 0,6 2,6 4,4 4,2 2,0 0,0",
        'E' => "4,0 0,0 0,6 4,6|0,3 3,3",
        'F' => "0,0 0,6 4,6|0,3 3,3",
        'G' => "4,5 3,6 1,6 0,5 0,1 1,0 3,0 4,1 4,3 2,3",
        'H' => "0,0 0,6|4,0 4,6|0,3 4,3",
        'I' => "1,0 3,0|2,0 2,6|1,6 3,6",
        'J' => "0,1 1,0 2,0 3,1 3,6|2,6 4,6",
        'K' => "0,0 0,6|4,6 0,2|1,3 4,0",
        'L' => "0,6 0,0 4,0",
        'M' => "0,0 0,6 2,3 4,6 4,0",
        'N' => "0,0 0,6 4,0 4,6",
        'O' => "0,1 1,0 3,0 4,1 4,5 3,6 1,6 0,5 0,1",
        'P' => "0,0 0,6 3,6 4,5 4,4 3,3 0,3",
        'Q' => "0,1 1,0 3,0 4,1 4,5 3,6 1,6 0,5 0,1|2,2 4,0",
        'R' => "0,0 0,6 3,6 4,5 4,4 3,3 0,3|2,3 4,0",
        'S' => "4,5 3,6 1,6 0,5 0,4 1,3 3,3 4,2 4,1 3,0 1,0 0,1",
        'T' => "0,6 4,6|2,6 2,0",
        'U' => "0,6 0,1 1,0 3,0 4,1 4,6",
        'V' => "0,6 2,0 4,6",
        'W' => "0,6 1,0 2,3 3,0 4,6",
        'X' => "0,0 4,6|0,6 4,0",
        'Y' => "0,6 2,3 4,6|2,3 2,0",
        'Z' => "0,6 4,6 0,0 4,0",
        '#' => "1,0 2,6|2,0 3,6|0,2 4,2|0,4 4,4",
        '-' => "1,3 3,3",
        '_' => "0,0 4,0",
        '.' => "2,0 2,1",
        '/' => "0,0 4,6",
        '?' => "0,5 1,6 3,6 4,5 4,4 2,3 2,2|2,0 2,1",
        _ => return None,
    })
}

/// The character drawn for `c`: upper case, accents dropped from common
/// Latin letters, `?` for what the font lacks.
pub fn drawn(c: char) -> char {
    let up = c.to_uppercase().next().unwrap_or(c);
    let base = match up {
        'À' | 'Á' | 'Â' | 'Ã' | 'Ä' | 'Å' => 'A',
        'Ç' => 'C',
        'È' | 'É' | 'Ê' | 'Ë' => 'E',
        'Ì' | 'Í' | 'Î' | 'Ï' => 'I',
        'Ñ' => 'N',
        'Ò' | 'Ó' | 'Ô' | 'Õ' | 'Ö' | 'Ø' => 'O',
        'Ù' | 'Ú' | 'Û' | 'Ü' => 'U',
        'Ý' => 'Y',
        c => c,
    };
    if strokes(base).is_some() {
        base
    } else {
        '?'
    }
}

/// Width of `text` set `height` mm high, mm (its first glyph's left edge
/// to its last glyph's right edge).
pub fn width(text: &str, height: f64) -> f64 {
    let n = text.chars().count();
    if n == 0 {
        return 0.0;
    }
    (n as f64 * ADVANCE - (ADVANCE - WIDTH)) * height / HEIGHT
}

/// `text` laid out `height` mm high as polylines, its box's lower-left
/// corner at the origin, reading along +x.
pub fn layout(text: &str, height: f64) -> Vec<Vec<Point>> {
    let unit = height / HEIGHT;
    let mut out = Vec::new();
    for (i, c) in text.chars().enumerate() {
        let x0 = i as f64 * ADVANCE;
        let Some(s) = strokes(drawn(c)) else { continue };
        for stroke in s.split('|').filter(|s| !s.is_empty()) {
            let line: Vec<Point> = stroke
                .split(' ')
                .filter_map(|xy| {
                    let (x, y) = xy.split_once(',')?;
                    Some(Point::new(
                        (x0 + x.parse::<f64>().ok()?) * unit,
                        y.parse::<f64>().ok()? * unit,
                    ))
                })
                .collect();
            out.push(line);
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_glyph_stays_on_its_grid_and_every_stroke_is_a_line() {
        let all = "0123456789ABCDEFGHIJKLMNOPQRSTUVWXYZ#-_./?";
        for c in all.chars() {
            let s = strokes(c).unwrap();
            for stroke in s.split('|') {
                let pts: Vec<(f64, f64)> = stroke
                    .split(' ')
                    .map(|xy| {
                        let (x, y) = xy.split_once(',').unwrap();
                        (x.parse().unwrap(), y.parse().unwrap())
                    })
                    .collect();
                assert!(pts.len() >= 2, "{c}: a stroke of one point");
                for (x, y) in pts {
                    assert!((0.0..=WIDTH).contains(&x) && (0.0..=HEIGHT).contains(&y), "{c}");
                }
            }
        }
    }

    #[test]
    fn text_is_laid_out_in_its_box_and_unknown_letters_become_question_marks() {
        let strokes = layout("ab#12", 12.0);
        let w = width("ab#12", 12.0);
        assert!((w - (5.0 * 6.0 - 2.0) * 2.0).abs() < 1e-12);
        for p in strokes.iter().flatten() {
            assert!(p.x >= 0.0 && p.x <= w + 1e-12 && p.y >= 0.0 && p.y <= 12.0 + 1e-12);
        }
        assert_eq!(layout("a", 6.0), layout("A", 6.0));
        assert_eq!(drawn('é'), 'E');
        assert_eq!(drawn('€'), '?');
        assert!(layout(" ", 6.0).is_empty());
    }
}
