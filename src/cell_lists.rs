//! Items filed by the cells of a uniform grid, all lists in one array
//! (compressed rows): cell `c` holds `items[start[c]..start[c + 1]]`.
//!
//! Built in two passes over the same filings, one to count each cell's
//! items and one to place them, so there is no vector per cell: on a
//! sheet of 100k contours a map of vectors was most of an index's time and
//! memory (issue 17). The lead clearance index, the part-material test and
//! the parts-freed check file their items this way.

/// The lists of a grid's cells.
#[derive(Default)]
pub(crate) struct CellLists {
    start: Vec<u32>,
    items: Vec<u32>,
}

/// What a filing pass does with each (cell, item): counts it, then places it.
pub(crate) struct Filing {
    counting: bool,
    start: Vec<u32>,
    fill: Vec<u32>,
    items: Vec<u32>,
}

impl Filing {
    /// Files `item` under `cell` (< the grid's cell count).
    #[inline]
    pub(crate) fn push(&mut self, cell: usize, item: u32) {
        if self.counting {
            self.start[cell + 1] += 1;
        } else {
            let f = &mut self.fill[cell];
            self.items[*f as usize] = item;
            *f += 1;
        }
    }
}

impl CellLists {
    /// The lists of `cells` cells, filled by `file`, which is called twice
    /// and must file the same items under the same cells both times; an
    /// item filed twice under a cell is listed twice.
    pub(crate) fn build(cells: usize, mut file: impl FnMut(&mut Filing)) -> CellLists {
        let mut f = Filing {
            counting: true,
            start: vec![0; cells + 1],
            fill: Vec::new(),
            items: Vec::new(),
        };
        file(&mut f);
        for c in 1..f.start.len() {
            f.start[c] += f.start[c - 1];
        }
        f.counting = false;
        f.fill = f.start[..cells].to_vec();
        f.items = vec![0; f.start[cells] as usize];
        file(&mut f);
        debug_assert!(f.fill.iter().zip(&f.start[1..]).all(|(a, b)| a == b));
        CellLists {
            start: f.start,
            items: f.items,
        }
    }

    /// The items of cell `c`; none for a cell past the grid.
    #[inline]
    pub(crate) fn get(&self, c: usize) -> &[u32] {
        match (self.start.get(c), self.start.get(c + 1)) {
            (Some(&a), Some(&b)) => &self.items[a as usize..b as usize],
            _ => &[],
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_cell_lists_its_items_in_filing_order() {
        // Items 0..5 under cells i % 3 and (i + 1) % 3, cell 3 left empty.
        let lists = CellLists::build(4, |f| {
            for i in 0..5u32 {
                f.push(i as usize % 3, i);
                f.push((i as usize + 1) % 3, i);
            }
        });
        assert_eq!(lists.get(0), &[0, 2, 3]);
        assert_eq!(lists.get(1), &[0, 1, 3, 4]);
        assert_eq!(lists.get(2), &[1, 2, 4]);
        assert_eq!(lists.get(3), &[] as &[u32]);
        assert_eq!(lists.get(4), &[] as &[u32]);
        assert_eq!(CellLists::build(0, |_| {}).get(0), &[] as &[u32]);
    }
}
