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
                x ^= x << 13;
                x ^= x >> 7;
                x ^= x << 17;
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
    fn moves_owned_values_without_losing_any() {
        let mut v: Vec<String> = ["d", "b", "a", "c", "b"]
            .iter()
            .map(|s| s.to_string())
            .collect();
        sort_by(&mut v, |a, b| a.cmp(b));
        assert_eq!(v, ["a", "b", "b", "c", "d"]);
    }
}
