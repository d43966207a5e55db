//! A stable sort for the cold paths, compiled once for all of them (issue
//! 17: the page's wasm). Each `slice::sort_by` with its own closure is a
//! copy of the standard library's stable sort, ~5 KB of wasm apiece: a
//! seventh of the cutting core was twenty such copies. Here the elements'
//! positions are sorted, through one comparison behind a `dyn`, and the
//! elements then moved into place: the same order as `sort_by` (a stable
//! sort's result is unique), a little slower, so the hot sorts (tens of
//! thousands of items in the pipeline's inner stages) keep `sort_by`.

use std::cmp::Ordering;

/// Sorts `v` stably by `cmp`: exactly what `v.sort_by(cmp)` gives.
pub(crate) fn sort_by<T>(v: &mut [T], mut cmp: impl FnMut(&T, &T) -> Ordering) {
    if v.len() < 2 {
        return;
    }
    let mut order: Vec<usize> = (0..v.len()).collect();
    {
        let v = &*v;
        positions(&mut order, &mut |a, b| cmp(&v[a], &v[b]));
    }
    permute(v, &mut order);
}

/// Sorts `v` stably by `key`: exactly what `v.sort_by_key(key)` gives.
pub(crate) fn sort_by_key<T, K: Ord>(v: &mut [T], mut key: impl FnMut(&T) -> K) {
    sort_by(v, |a, b| key(a).cmp(&key(b)))
}

/// The one instance of the standard stable sort behind every [`sort_by`].
#[inline(never)]
fn positions(order: &mut [usize], cmp: &mut dyn FnMut(usize, usize) -> Ordering) {
    order.sort_by(|&a, &b| cmp(a, b));
}

/// Sorts indices ascending: exactly what `v.sort_unstable()` gives (equal
/// indices are alike, so any sort gives the same slice), without a copy of
/// the standard library's unstable sort (issue 17: one instance of it for
/// `usize` was ~5 KB of the page's wasm). The lists are mostly a few ids
/// a query (insertion); long ones go through [`radix`].
pub(crate) fn sort_indices(v: &mut [usize]) {
    if v.len() <= SHORT {
        insertion(v, |a, b| a > b);
        return;
    }
    let mut keys: Vec<u64> = v.iter().map(|&x| x as u64).collect();
    radix(&mut keys);
    for (x, k) in v.iter_mut().zip(keys) {
        *x = k as usize;
    }
}

/// Sorts 64-bit keys ascending (what `v.sort_unstable()` gives), by
/// [`radix`]: the tour's spatial renumbering sorts a key per site.
pub(crate) fn sort_u64(v: &mut [u64]) {
    if v.len() <= SHORT {
        insertion(v, |a, b| a > b);
        return;
    }
    radix(v);
}

/// Sorts numbers by `f64::total_cmp`: exactly what
/// `v.sort_by(f64::total_cmp)` gives (numbers equal under it have the same
/// bits), through [`radix`] on the same order as integers.
pub(crate) fn sort_floats(v: &mut [f64]) {
    if v.len() <= SHORT {
        insertion(v, |a, b| a.total_cmp(b).is_gt());
        return;
    }
    let mut keys: Vec<u64> = v.iter().map(|&x| float_key(x)).collect();
    radix(&mut keys);
    for (x, k) in v.iter_mut().zip(keys) {
        let b = k ^ (1 << 63);
        *x = f64::from_bits(b ^ (((b as i64 >> 63) as u64) >> 1));
    }
}

/// `f64::total_cmp`'s order as unsigned integers: negative numbers'
/// magnitude bits flipped, then the sign bit flipped.
fn float_key(x: f64) -> u64 {
    let b = x.to_bits();
    b ^ (((b as i64 >> 63) as u64) >> 1) ^ (1 << 63)
}

/// Sorts `v` stably by a number, then by `then` among equal numbers:
/// exactly what `v.sort_by(|a, b| key(a).total_cmp(&key(b)).then_with(||
/// then(a, b)))` gives. The numbers go through [`radix_order`] (linear: a
/// million lines or contours compared through [`sort_by`]'s `dyn` was most
/// of the time of their stage), only runs of equal numbers through `then`.
pub(crate) fn sort_by_number_then<T: Copy>(
    v: &mut [T],
    key: impl Fn(&T) -> f64,
    mut then: impl FnMut(&T, &T) -> Ordering,
) {
    if v.len() < 2 {
        return;
    }
    let keys: Vec<u64> = v.iter().map(|x| float_key(key(x))).collect();
    let mut order = radix_order(&keys);
    let mut i = 0;
    while i < order.len() {
        let k = keys[order[i]];
        let n = order[i..].iter().take_while(|&&j| keys[j] == k).count();
        if n > 1 {
            // Positions ascending within the run (the radix sort is
            // stable), and `positions` is too: ties stay in input order.
            let v = &*v;
            positions(&mut order[i..i + n], &mut |a, b| then(&v[a], &v[b]));
        }
        i += n;
    }
    // Gathered, not permuted in place: independent loads, where following
    // the permutation's cycles waits on each one (a million lines).
    let sorted: Vec<T> = order.iter().map(|&k| v[k]).collect();
    v.copy_from_slice(&sorted);
}

/// Lists up to this long are sorted by insertion.
const SHORT: usize = 32;

/// Straight insertion: `gt(a, b)` is "a goes after b".
fn insertion<T: Copy>(v: &mut [T], gt: impl Fn(&T, &T) -> bool) {
    for i in 1..v.len() {
        let x = v[i];
        let mut j = i;
        while j > 0 && gt(&v[j - 1], &x) {
            v[j] = v[j - 1];
            j -= 1;
        }
        v[j] = x;
    }
}

/// Least-significant-digit radix sort, a byte a pass, only as many passes
/// as the largest key has bytes and none for a byte all keys share (the
/// counts stay small enough to clear for lists of a few dozen): linear, and
/// one copy for all the integer and float sorts above.
fn radix(v: &mut [u64]) {
    let max = v.iter().copied().max().unwrap_or(0);
    let sorted = radix_by(v.to_vec(), max, |x| x);
    v.copy_from_slice(&sorted);
}

/// The LSD radix passes of [`radix`] and [`radix_order`]: `from` in
/// ascending order of `key` (stable), `max` the largest key.
#[inline(never)]
fn radix_by<T: Copy + Default>(mut from: Vec<T>, max: u64, key: impl Fn(T) -> u64) -> Vec<T> {
    let mut to = vec![T::default(); from.len()];
    let mut shift = 0;
    while shift < u64::BITS && (shift == 0 || max >> shift != 0) {
        let mut count = [0usize; 256];
        for &x in &from {
            count[((key(x) >> shift) & 0xff) as usize] += 1;
        }
        if count.contains(&from.len()) {
            shift += 8;
            continue;
        }
        let mut at = 0;
        for c in count.iter_mut() {
            (*c, at) = (at, at + *c);
        }
        for &x in &from {
            let d = ((key(x) >> shift) & 0xff) as usize;
            to[count[d]] = x;
            count[d] += 1;
        }
        std::mem::swap(&mut from, &mut to);
        shift += 8;
    }
    from
}

/// Sorts a heat map's cells row by row, by `(j, i)`: what
/// `v.sort_unstable_by_key(|&((i, j), _)| (j, i))` gives for distinct
/// cells (the verification's cells and the page's heat squares, each from
/// a map by cell), without a copy of the standard sort for them. Cells
/// whose indices fit in 32 bits (any drawing at any cell size the callers
/// use) are radix-sorted on one 64-bit key; others go through [`sort_by`].
pub(crate) fn sort_cells(v: &mut [((i64, i64), f64)]) {
    let small = |x: i64| i32::try_from(x).is_ok();
    if v.len() <= 1 {
        return;
    }
    if !v.iter().all(|&((i, j), _)| small(i) && small(j)) {
        sort_by_key(v, |&((i, j), _)| (j, i));
        return;
    }
    // Offset by 2^31 so that the order of the unsigned halves is that of
    // the signed indices.
    let half = |x: i64| (x + (1 << 31)) as u64;
    let keys: Vec<u64> = v
        .iter()
        .map(|&((i, j), _)| half(j) << 32 | half(i))
        .collect();
    let mut order = radix_order(&keys);
    permute(v, &mut order);
}

/// The positions of `keys` in ascending order (stable): the same LSD radix
/// sort as [`radix`], carrying each key's position.
pub(crate) fn radix_order(keys: &[u64]) -> Vec<usize> {
    let max = keys.iter().copied().max().unwrap_or(0);
    // Each key moved with its position: looked up by position, a pass's
    // reads went all over a million keys.
    let pairs: Vec<(u64, usize)> = keys.iter().copied().zip(0..).collect();
    let sorted = radix_by(pairs, max, |(key, _)| key);
    sorted.into_iter().map(|(_, k)| k).collect()
}

/// Puts the element at `order[k]` at position `k`, for every `k` (`order`
/// is a permutation), following its cycles with swaps; `order` is spent.
fn permute<T>(v: &mut [T], order: &mut [usize]) {
    for i in 0..v.len() {
        let mut j = i;
        loop {
            let k = order[j];
            order[j] = j; // done
            if k == i || k == j {
                break;
            }
            v.swap(j, k);
            j = k;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Small deterministic generator for the cases.
    fn numbers(seed: u64, n: usize, range: u64) -> Vec<u64> {
        let mut x = seed | 1;
        (0..n)
            .map(|_| {
                x = crate::test_rng::Xorshift(x).next();
                x % range
            })
            .collect()
    }

    #[test]
    fn same_order_as_the_standard_stable_sort() {
        for (seed, n, range) in [
            (1, 0, 5),
            (2, 1, 5),
            (3, 2, 2),
            (4, 50, 3),
            (5, 1000, 40),
            (6, 777, 1_000_000),
        ] {
            // (key, original position): ties must keep their order.
            let items: Vec<(u64, usize)> = numbers(seed, n, range).into_iter().zip(0..).collect();
            let mut ours = items.clone();
            sort_by(&mut ours, |a, b| a.0.cmp(&b.0));
            let mut std = items.clone();
            std.sort_by_key(|a| a.0);
            assert_eq!(ours, std, "seed {seed}");
            let mut by_key = items.clone();
            sort_by_key(&mut by_key, |a| std::cmp::Reverse(a.0));
            std.sort_by_key(|a| std::cmp::Reverse(a.0));
            assert_eq!(by_key, std, "seed {seed} by key");
        }
    }

    #[test]
    fn by_number_then_as_the_standard_stable_sort() {
        for (seed, n, range) in [(1, 0, 5), (2, 1, 5), (3, 2, 2), (4, 60, 3), (5, 3000, 50)] {
            // Numbers with many ties (and both zeros, a NaN, infinities),
            // a second key with ties, and the position to see stability.
            let xs = numbers(seed, n, range);
            let ys = numbers(seed + 100, n, 4);
            let items: Vec<(f64, u64, usize)> = xs
                .iter()
                .zip(&ys)
                .enumerate()
                .map(|(k, (&x, &y))| {
                    let x = match x {
                        0 => -0.0,
                        1 => f64::NAN,
                        2 => f64::NEG_INFINITY,
                        x => x as f64 - 20.5,
                    };
                    (x, y, k)
                })
                .collect();
            let mut ours = items.clone();
            sort_by_number_then(&mut ours, |a| a.0, |a, b| a.1.cmp(&b.1));
            let mut std = items.clone();
            std.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));
            let bits = |v: &[(f64, u64, usize)]| -> Vec<(u64, u64, usize)> {
                v.iter().map(|&(x, y, k)| (x.to_bits(), y, k)).collect()
            };
            assert_eq!(bits(&ours), bits(&std), "seed {seed}");
        }
    }

    #[test]
    fn indices_as_the_standard_sort() {
        for (seed, n, range) in [
            (1, 0, 5),
            (2, 1, 5),
            (3, 31, 7),
            (4, 33, 3),
            (5, 1000, 40),
            (6, 5000, 1 << 40),
            (7, 300, u64::MAX),
        ] {
            let mut ours: Vec<usize> = numbers(seed, n, range)
                .iter()
                .map(|&x| x as usize)
                .collect();
            let mut std = ours.clone();
            std.sort_unstable();
            sort_indices(&mut ours);
            assert_eq!(ours, std, "seed {seed}");
        }
        let mut top = vec![usize::MAX, 0, usize::MAX - 1, 1 << (usize::BITS - 1), 5];
        top.extend(0..40);
        let mut std = top.clone();
        std.sort_unstable();
        sort_indices(&mut top);
        assert_eq!(top, std);
    }

    #[test]
    fn floats_as_the_standard_sort() {
        let special = [
            -0.0,
            0.0,
            f64::NAN,
            -f64::NAN,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::MIN_POSITIVE,
            -f64::MIN_POSITIVE,
            5e-324,
            -5e-324,
            f64::MAX,
            f64::MIN,
        ];
        for (seed, n) in [(1, 0), (2, 1), (3, 20), (4, 33), (5, 2000)] {
            let mut v: Vec<f64> = numbers(seed, n, 1 << 20)
                .iter()
                .map(|&x| (x as f64 - 5e5) / 7.0)
                .collect();
            v.extend(special);
            v.extend(special);
            let mut std = v.clone();
            std.sort_by(f64::total_cmp);
            sort_floats(&mut v);
            let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
            assert_eq!(bits(&v), bits(&std), "seed {seed}");
        }
    }

    #[test]
    fn cells_as_the_standard_sort() {
        for (seed, n, range, far) in [
            (1, 0, 5, false),
            (2, 1, 5, false),
            (3, 500, 60, false),
            (4, 3000, 1 << 33, false),
            (5, 200, 40, true),
        ] {
            // Distinct cells, as the callers' maps give them.
            let mut seen = std::collections::HashSet::new();
            let xs = numbers(seed, 2 * n, range);
            let mut v: Vec<((i64, i64), f64)> = xs
                .chunks(2)
                .map(|c| {
                    let (i, j) = (
                        c[0] as i64 - range as i64 / 2,
                        c[1] as i64 - range as i64 / 2,
                    );
                    ((i, j), (i * 3 + j) as f64)
                })
                .filter(|(k, _)| seen.insert(*k))
                .collect();
            if far {
                v.push(((i64::MIN, 3), 1.0));
                v.push(((5, i64::MAX), 2.0));
            }
            let mut std = v.clone();
            std.sort_unstable_by_key(|&((i, j), _)| (j, i));
            sort_cells(&mut v);
            assert_eq!(v, std, "seed {seed}");
        }
    }

    #[test]
    fn moves_owned_values_without_losing_any() {
        let mut v: Vec<String> = ["d", "b", "a", "c", "b"]
            .iter()
            .map(|s| s.to_string())
            .collect();
        sort_by(&mut v, |a, b| a.cmp(b));
        assert_eq!(v, ["a", "b", "b", "c", "d"]);
    }
}
