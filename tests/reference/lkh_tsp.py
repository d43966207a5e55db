#!/usr/bin/env python3
"""LKH-3 reference for `cargo bench --bench tsp` (issue 4 §3).

For each instance written by the bench (target/tsp-bench/*.json) this builds
a reference open path from the origin with LKH-3 (the `elkai` package) and
compares kerfcam's tour with it.

What the reference is (and is not):
  1. The points are kerfcam's own chosen entry points (one per contour).
     LKH orders them as a plain TSP: precedence (holes before their part)
     is IGNORED, so this step alone is a relaxation of kerfcam's problem
     for those entry points.
  2. The open path from the origin is exact as a TSP: a dummy node at
     distance 0 from the origin and a big constant M from every other point
     forces the tour origin … last, dummy, origin (length + M).
     Above SMALL nodes the full matrix is too big for elkai; the closed tour
     on EUC_2D coordinates is solved instead and opened by dropping the
     longer edge at the origin (labelled "closed" in the output; that path
     is an upper bound on LKH's open path, so the gap there is optimistic).
  3. The entry points along LKH's order are then re-chosen exactly over all
     candidates (the same layered shortest path kerfcam uses), again
     ignoring precedence.
  4. "LKH fixed": LKH's free order made legal two ways (each outer contour
     deferred to just after its last hole; or the missing holes pulled
     forward to just before their outer), entries re-chosen as in 3, the
     shorter kept: a feasible tour, so an upper bound on the optimum.
Columns: "ratio" = kerfcam / LKH fixed (issue 17's target: <= 1.03); "gap %" after "LKH free" = kerfcam / free - 1 (includes the price
of precedence, which no legal tour avoids); after "LKH fixed" = kerfcam /
fixed - 1 (both legal; negative = kerfcam shorter). On the "-free"
instances (precedence dropped) both compare like with like.

Usage: python3 tests/reference/lkh_tsp.py [target/tsp-bench/*.json]
"""
import glob
import json
import math
import sys
import time

import numpy as np
import elkai  # noqa: F401  (LKH-3; pip install elkai)
from elkai import _elkai

SCALE = 100.0  # LKH works on integers: 0.01 mm
SMALL = 1600   # largest node count solved with an explicit matrix
LARGE = 5000   # above this, LKH gets faster candidate sets (see open_path_closed)


def lkh(problem, runs=1, trials=None, extra=""):
    params = f"RUNS = {runs}\nPROBLEM_FILE = :stdin:\n{extra}"
    if trials:
        params += f"MAX_TRIALS = {trials}\n"
    tour = _elkai.solve_problem(params, problem)
    return [i - 1 for i in tour]


def open_path_explicit(o, pts):
    """Exact open TSP path from o through pts (indices into pts)."""
    allp = np.vstack([o[None, :], pts])
    n = len(allp)
    d = np.rint(np.hypot(*(allp[:, None, :] - allp[None, :, :]).transpose(2, 0, 1)) * SCALE).astype(np.int64)
    big = int(d.max()) * 4 + 1
    m = np.full((n + 1, n + 1), big, dtype=np.int64)
    m[:n, :n] = d
    m[n, 0] = m[0, n] = 0
    m[n, n] = 0
    rows = "\n".join(" ".join(map(str, r)) for r in m.tolist())
    problem = (f"TYPE : TSP\nDIMENSION : {n + 1}\nEDGE_WEIGHT_TYPE : EXPLICIT\n"
               f"EDGE_WEIGHT_FORMAT : FULL_MATRIX\nEDGE_WEIGHT_SECTION\n{rows}\nEOF\n")
    tour = lkh(problem)
    k = tour.index(0)
    tour = tour[k:] + tour[:k]
    if tour[1] == n:  # dummy right after the origin: walk the other way
        tour = [0] + tour[1:][::-1]
    return [i - 1 for i in tour[1:] if i != n]


def open_path_closed(o, pts):
    """Closed EUC_2D tour through o and pts, opened at the origin."""
    allp = np.vstack([o[None, :], pts]) * SCALE
    lines = "\n".join(f"{i + 1} {x:.0f} {y:.0f}" for i, (x, y) in enumerate(allp))
    problem = (f"TYPE : TSP\nDIMENSION : {len(allp)}\nEDGE_WEIGHT_TYPE : EUC_2D\n"
               f"NODE_COORD_SECTION\n{lines}\nEOF\n")
    # Above LARGE nodes LKH's default candidate sets (alpha-nearness from
    # subgradient ascent, quadratic) took 25 min on 15k nodes: POPMUSIC
    # candidates (Taillard & Helsgaun 2019) instead, no ascent.
    extra = ("CANDIDATE_SET_TYPE = POPMUSIC\nINITIAL_PERIOD = 100\n"
             if len(allp) > LARGE else "")
    tour = lkh(problem, trials=200, extra=extra)
    k = tour.index(0)
    tour = tour[k:] + tour[:k]
    fwd, back = tour[1:], tour[1:][::-1]
    # Dropping the longer origin edge = starting towards the shorter one.
    first = lambda seq: np.hypot(*(allp[seq[0]] - allp[0]))
    seq = fwd if first(fwd) <= first(back) else back
    return [i - 1 for i in seq]


def best_entries(o, cands):
    """Shortest open path choosing one point of each layer, in order."""
    prev = np.asarray([o])
    cost = np.zeros(1)
    for c in cands:
        c = np.asarray(c)
        dd = np.hypot(*(prev[:, None, :] - c[None, :, :]).transpose(2, 0, 1))
        cost = (cost[:, None] + dd).min(axis=0)
        prev = c
    return float(cost.min())


def repairs(order, sites, visits):
    """Two precedence-respecting versions of a free order (indices into
    visits): parents deferred to just after their last descendant, and
    missing descendants pulled forward to just before their parent."""
    site_of = [visits[i][0] for i in order]
    idx = {s: i for i, (s, _) in enumerate(visits)}
    kids = {}
    for i, (s, _) in enumerate(visits):
        p = sites[s]["parent"]
        while p is not None and p not in idx:  # skip unvisited ancestors
            p = sites[p]["parent"]
        if p is not None:
            kids.setdefault(p, []).append(s)
    # Deferred parents.
    waiting = {s: len(kids.get(s, [])) for s in site_of}
    parent_of = {k: p for p, ks in kids.items() for k in ks}
    out, held = [], set()
    def emit(s):
        stack = [s]
        while stack:
            x = stack.pop()
            out.append(x)
            p = parent_of.get(x)
            if p is not None:
                waiting[p] -= 1
                if waiting[p] == 0 and p in held:
                    held.discard(p)
                    stack.append(p)
    for s in site_of:
        if waiting[s] == 0:
            emit(s)
        else:
            held.add(s)
    deferred = [idx[s] for s in out]
    # Pulled-forward descendants (post-order of the subtree, in free order).
    rank = {s: r for r, s in enumerate(site_of)}
    seen, out = set(), []
    for s in site_of:
        if s in seen:
            continue
        post, stack = [], [(s, False)]
        while stack:
            x, expanded = stack.pop()
            if x in seen:
                continue
            if expanded:
                seen.add(x)
                post.append(x)
                continue
            stack.append((x, True))
            for k in sorted(kids.get(x, []), key=lambda k: -rank[k]):
                if k not in seen:
                    stack.append((k, False))
        out.extend(post)
    pulled = [idx[s] for s in out]
    return deferred, pulled


def path_len(o, pts):
    allp = np.vstack([o[None, :], pts])
    return float(np.hypot(*np.diff(allp, axis=0).T).sum())


def main(files):
    print(f"{'instance':<18} {'sites':>6} {'NN':>9} {'kerfcam':>9} {'LKH free':>9} "
          f"{'gap %':>6} {'LKH fixed':>9} {'gap %':>6} {'ratio':>6} {'LKH s':>6} kind")
    for f in files:
        inst = json.load(open(f))
        o = np.asarray(inst["origin"], dtype=float)
        sites = inst["sites"]
        visits = inst["visits"]
        pts = np.asarray([sites[s]["candidates"][c] for s, c in visits], dtype=float)
        t = time.time()
        if len(pts) + 2 <= SMALL:
            order, kind = open_path_explicit(o, pts), "open"
        else:
            order, kind = open_path_closed(o, pts), "closed"
        secs = time.time() - t
        def ref(order):
            fixed = path_len(o, pts[order])
            dp = best_entries(o, [sites[visits[i][0]]["candidates"] for i in order])
            return min(fixed, dp)
        free = ref(order)
        fixed = min(ref(r) for r in repairs(order, sites, visits))
        name = f.split("/")[-1].removesuffix(".json")
        ours = inst["length"]
        print(f"{name:<18} {len(pts):>6} {inst['nn_length']:>9.0f} {ours:>9.0f} {free:>9.0f} "
              f"{100 * (ours / free - 1):>6.2f} {fixed:>9.0f} {100 * (ours / fixed - 1):>6.2f} "
              f"{secs:>6.1f} {kind}", flush=True)


if __name__ == "__main__":
    main(sys.argv[1:] or sorted(glob.glob("target/tsp-bench/*.json"),
                                key=lambda p: (len(p), p)))
