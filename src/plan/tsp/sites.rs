//! The sites of a tour stored flat ([`Sites`]): what the planner hands the
//! tour on a big sheet without a vector of candidates per contour (137k
//! vectors built, copied into the instance and dropped on the 25 MB nest).

use super::Site;
use crate::geom::Point;

/// Sites stored flat: site `i`'s candidates are
/// `points[first[i]..first[i + 1]]`, its parent `parents[i]` (the same
/// meaning as [`Site`]'s fields).
#[derive(Clone, Debug, Default)]
pub struct Sites {
    points: Vec<Point>,
    first: Vec<usize>,
    parents: Vec<Option<usize>>,
}

impl Sites {
    /// No sites, with room for `sites` of `points` candidates in all.
    pub fn with_capacity(sites: usize, points: usize) -> Sites {
        let mut first = Vec::with_capacity(sites + 1);
        first.push(0);
        Sites {
            points: Vec::with_capacity(points),
            first,
            parents: Vec::with_capacity(sites),
        }
    }

    /// Adds a site (numbered in the order added).
    pub fn push(&mut self, candidates: impl IntoIterator<Item = Point>, parent: Option<usize>) {
        self.points.extend(candidates);
        self.first.push(self.points.len());
        self.parents.push(parent);
    }

    /// The same sites as `sites` (the entry of [`super::order`], which the
    /// benches and tests call; the planner builds its sites flat).
    #[allow(dead_code)]
    pub fn of(sites: &[Site]) -> Sites {
        let total = sites.iter().map(|s| s.candidates.len()).sum();
        let mut flat = Sites::with_capacity(sites.len(), total);
        for s in sites {
            flat.push(s.candidates.iter().copied(), s.parent);
        }
        flat
    }

    /// How many sites.
    pub fn count(&self) -> usize {
        self.parents.len()
    }

    /// Site `i`'s candidates.
    pub fn candidates(&self, i: usize) -> &[Point] {
        &self.points[self.first[i]..self.first[i + 1]]
    }

    /// Site `i`'s parent.
    pub fn parent(&self, i: usize) -> Option<usize> {
        self.parents[i]
    }
}
