//! The turns a part may take ([`Rotations`]), by the names the CLI and the
//! page give them.

/// Steps used for free (continuous) rotation: 15°. The placer tries
/// discrete turns only; finer ones cost time linearly.
pub const FREE_STEPS: u32 = 24;

/// Turns a part may take.
#[derive(Clone, Debug, PartialEq)]
pub enum Rotations {
    /// As drawn.
    None,
    /// 0° and 180°.
    Half,
    /// Steps of 90°.
    Quarter,
    /// N equal steps of 360°/N.
    Steps(u32),
    /// Any angle (tried in [`FREE_STEPS`] steps).
    Free,
    /// These angles, degrees.
    List(Vec<f64>),
}

impl Rotations {
    /// From the CLI's and the page's names: none, 180, 90, free, or a
    /// number of equal steps 1..=360.
    pub fn from_name(name: &str) -> Option<Rotations> {
        Some(match name {
            "none" | "0" => Rotations::None,
            "180" => Rotations::Half,
            "90" => Rotations::Quarter,
            "free" => Rotations::Free,
            n => match n.parse::<u32>() {
                Ok(k) if (1..=360).contains(&k) => Rotations::Steps(k),
                _ => return None,
            },
        })
    }

    /// The angles tried, degrees.
    pub fn angles(&self) -> Vec<f64> {
        let steps = |n: u32| {
            (0..n.max(1))
                .map(|k| 360.0 * k as f64 / n.max(1) as f64)
                .collect()
        };
        match self {
            Rotations::None => vec![0.0],
            Rotations::Half => vec![0.0, 180.0],
            Rotations::Quarter => steps(4),
            Rotations::Steps(n) => steps(*n),
            Rotations::Free => steps(FREE_STEPS),
            Rotations::List(v) if v.is_empty() => vec![0.0],
            Rotations::List(v) => v.clone(),
        }
    }
}
