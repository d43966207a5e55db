#!/usr/bin/env bash
# Speed at sheet scale (issue 17): every stage on generated nests from ~1k to
# ~140k contours (time per contour: flat means linear), and the whole
# pipeline beside ezdxf merely *reading* the biggest one, in one run.
#
#   bash scripts/bench-sheet.sh [ROUNDS]
#
# Makes a venv with ezdxf under target/bench-venv (pip, once), nests under
# target/bench-sheet/ (benches/reader.rs --write-nest). A benchmark, not a
# test: it asserts nothing. Budgets: what each stage may take of the issue's
# ~0.45 s for the whole 25 MB nest.
#
# Issue 17, session 21 (2026-11-28 evening, the same machine, slower this
# evening: ezdxf reads the file in 11.7-12.0 s against 8.6-10.0 s in the
# afternoon). The tour's entry re-choices on the threads (14d1c86: the
# polish's stretches at once, a big sheet's whole re-choice in blocks of
# 8,192 sites) and the containment grid on the threads (ce1b377); every
# program byte-identical. This script twice:
#   22:43  1 thread 705 ms 16.6x, 2 threads 451 ms 26.0x (ezdxf 11,715 ms);
#          2 threads: parse 44/100, contours 110/80, kerf 17/50, plan
#          226/150, G-code 54/70 ms
#   23:13  1 thread 783 ms 15.3x, 2 threads 482 ms 24.9x (ezdxf 11,993 ms);
#          2 threads: parse 42/100, contours 111/80, kerf 17/50, plan
#          255/150, G-code 57/70 ms
#   23:59  after the two-hole nest's shortcut (71ec8cb), the script now
#          also timing the nest issue 17 was measured on (20,000 plates
#          with a round and a rectangular hole, benches/pipeline.rs
#          --write-nest; 60k contours, 8.4 MB): 25 MB nest 1 thread
#          765 ms 16.9x, 2 threads 498 ms 26.0x (ezdxf 12,928 ms; plan
#          267/150, contours 113/80); the 20,000-part nest 1 thread 293
#          ms 22.3x, 2 threads 202 ms 32.4x (ezdxf 6,527 ms; 2 threads:
#          parse 19, contours 46, kerf 13, plan 101, G-code 23 ms).
# Per contour, 2 threads, 22k -> 61k -> 137k contours: plan 1.6, 1.6, 1.6
# (22:43) and 1.6, 1.6, 1.9 us (23:13): flat now where it rose 1.2 ->
# 1.6 (a re-choice's block of layers stays in cache).
# Before (a8180b3) against after (ce1b377), the 25 MB nest, --rounds 3,
# 8 alternating pairs at 23:17 (the machine slow), median pair ratios:
#   2 threads: plan 282.0 -> 265.3 ms (0.948), contours 116.2 -> 111.8
#   (0.972), total 517.5 -> 502.2 (0.967); 1 thread: plan 477.6 ->
#   450.4 (0.947), contours 142.8 -> 130.9 (0.908), total 0.975.
# Earlier, quieter: plan 242.1 -> 223.2 ms (10 pairs, 0.915) for the
# re-choices, contours 108.6 -> 104.0 (10 pairs, 0.955) for the grid.
# Where the time goes now (probes, 2 threads): plan: sites ~6, instance
# 30 + its grids 10-15 (the clearance index ~45 beside), the start with
# the lists beside ~45, entries 15-18 (the baseline beside), free search
# 20-25, repair 5-7, polish 31-39 (entries 9-10, search 17), cuts 56.
# contours: prepare 19-20 (ranges 12, joining them 5.5), end grid 13,
# walk 22-27 (strips 7.5, writing the chains 9-11 on one thread), split
# 2.7, duplicate loops 7 (hashes 3.3, their sort 3.2), contours made 8,
# classify 18-20 (grid ~8, search 9-11), numbering 2.5.
# Tried and dropped (see benches/tsp.rs, eleventh pass): mimalloc as the
# allocator (erratic fresh-process times), the lists and baseline handed
# over from one thread, the chains written on the strips' threads, the
# copies' hashes on the threads.
#
# Issue 17, session 20 (2026-11-28, a new machine of the same kind: 2-core
# Intel Xeon; ezdxf reads faster here, 8.6-10.0 s). This script twice, at
# df4205b (the short tour's neighbour lists by site centre):
#   17:58  1 thread 754 ms 13.3x, 2 threads 471 ms 21.3x (ezdxf 10,012 ms);
#          2 threads: parse 42/100, contours 114/80, kerf 16/50, plan
#          245/150, G-code 55/70 ms
#   18:52  1 thread 647 ms 13.3x, 2 threads 430 ms 20.1x (ezdxf 8,633 ms);
#          2 threads: parse 34/100, contours 104/80, kerf 14/50, plan
#          224/150, G-code 52/70 ms
#   19:30  after the end grid on the threads, the 32-bit copies' hashes
#          and the containment order sorted beside (4890198..): 1 thread
#          685 ms 12.9x, 2 threads 446 ms 19.9x (ezdxf 8,870 ms); 2
#          threads: parse 36/100, contours 99/80, kerf 15/50, plan 246/150
#          (a noisy minute: 220-250 in the pairs), G-code 50/70 ms. The
#          contours stage in alternating pairs: 97.3 -> 91.4 (grid),
#          108.8 -> 103.9 (hashes), 104.1 -> 97.8 ms (order), ~0.88 of
#          df4205b's in all, the same programs.
# Per contour, 2 threads, 22k -> 61k -> 137k contours: parse 0.3, 0.3,
# 0.2; contours 0.6, 0.7, 0.8; kerf 0.1; plan 1.2, 1.4, 1.6; G-code 0.3,
# 0.4, 0.4 us (the plan's rise is the tour's arrays leaving the caches).
# Over their share still: the contours (~105-115 / 80) and the plan
# (~225-245 / 150). Where their time goes, 2 threads, the third round
# of a process (probes, not kept):
#   plan: sites 12; tour instance 55 (one thread; the clearance index
#   ~45 on the other); nearest-neighbour start with the lists beside it
#   56-60; entry re-choice 26; free local search 22; repair 5; polish
#   42; the cuts 62 (both threads: the lead-in's clearance checks are
#   more than half of a cut).
#   contours: prepare 17 (ranges 10, joining them 5, closed copies 2);
#   the chainer's end grid 19-20 (one thread: box 4.5, count 8, place
#   8); the walk 17-19; duplicate loops 7; contours made 4.5; classify
#   25 (sort by area 7, box grid 9, the search 8); numbering 2.
# Tried and dropped (no gain measured, the programs byte-identical):
#   the tour's instance on two threads (Hilbert keys on ranges, the two
#   constructions' grids made at once beside the relaxed copy): plan
#   221.1 -> 219.4 ms, 10 alternating pairs, ratios 0.96-1.07; the box
#   grid of the containment search reading each box once in area order:
#   contours 102.2 -> 104.3 ms, 8 pairs, median ratio 1.03.
#
# Issue 17, session 18 (2026-11-25, the same machine): the cut check on a
# clean plan (--verify, contour order), whole CLI runs, wall s / peak
# memory, before (dba7398) -> after, the same verification (the JSON's
# verification and warnings of 196 runs over every corpus and fixture
# drawing, contour and drawing orders, kerf 0, 2 tabs, identical):
#   4 MB nest (22k contours): 8.06 s / 362 MB -> 2.8 s / 60 MB one
#       thread, 1.6 s / 71 MB two threads
#   11 MB nest (61k): 27.8 s / 1.37 GB -> 4.2 s / 191 MB (two threads)
#   25 MB nest (137k): 9.3 s / 376 MB (two threads)
#   (src/plan/verify/moves.rs: the moves in one flat grid; freed.rs: one
#   set of buffers, each row's inside as runs, the parts on the threads;
#   overcut.rs: each move's nearby drawn segments gathered once.)
# --order eulerian, idle machine, wall s / peak memory, before (dba7398)
# -> after, programs byte-identical (cmp; 147 eulerian runs over every
# corpus and fixture drawing, kerf 1.5 and 3, modes repeat and rapid,
# the same programs and JSON reports):
#   4 MB nest: 1.01 s / 156 MB -> 0.45 s / 94 MB
#   11 MB nest: 3.39, 3.54 s / 533 MB -> 1.38, 1.34 s / 276 MB
#   25 MB nest: 8.46 s / 1.07 GB -> 3.24 s / 562 MB
#   (src/plan/euler/spacing.rs: the parts' segments in one flat grid, each
#   box made once; graph.rs: the vertex grids' cells as chains, the edges
#   between two vertices as a chain, a vertex's edges as one CellLists.)
#
# Issue 17, session 17 (2026-11-25, the same machine): the other orders
# and the cut check at sheet scale, whole CLI runs (wall s, peak memory),
# before -> after; programs byte-identical wherever the plan is the same:
#   --cut-open, 20,000 open lines (nearest next by a scan, quadratic):
#       5.12 s -> 0.05 s (src/plan/nearest.rs; 10,000 marks 1.58 -> 0.07)
#   --order eulerian, 4 MB nest (22k contours): 5.09 -> 1.1 s; 11 MB (61k):
#       40.3 -> 3.3 s; 25 MB (137k): 9.1 s (src/plan/euler/next.rs, the
#       spacing check once a segment)
#   --order drawing --verify (cut on the lines), 0.2 MB nest: 22.7 s /
#       820 MB -> 1.5 s / 108 MB; 1 MB nest: 129 s / 3.3 GB -> 4.3 s /
#       150 MB (src/plan/verify/material.rs, raster.rs)
#   --verify on a clean plan: 4 MB nest 8.4 s, 11 MB 27.5 s / 1.6 GB, not
#       changed (the parts-freed check, verify/freed.rs: a raster per part
#       and a map of moves by cell): left.
# The default order's stages were not changed; see session 16 below.
#
# Issue 17, session 16 (2026-11-25, the same machine): the local
# searches screened on the threads (benches/tsp.rs, eighth pass) and the
# chaining in strips on the threads (src/contour/chain/strips.rs; the
# same chains as one thread). Programs of the 4/11/25 MB nests
# byte-identical (cmp) with 1 and 2 threads at each step. Paired A/B on
# the 25 MB nest, two threads, --rounds 3: plan 283 -> 261 ms (6 pairs),
# contours 102 -> 91 ms and total 497 -> 477 (12 pairs). This script:
#   06:53  1 thread 684 ms 15.5x, 2 threads 464 ms 22.8x (ezdxf 10,575 ms;
#          screens only: contours 104, plan 241 ms)
#   07:28  1 thread 749 ms 15.2x, 2 threads 540 ms 21.0x (ezdxf 11,355 ms)
#   07:31  1 thread 697 ms 15.5x, 2 threads 462 ms 23.3x (ezdxf 10,781 ms)
# Two threads, stages of the 23.3x run: parse 45 / 100, contours 91 / 80,
# kerf 18 / 50, plan 252 / 150, G-code 56 / 70 ms (measured / budget).
#
# Issue 17, session 15 (2026-11-25 02:58-03:55 UTC, the same machine, no
# speed change kept: see benches/tsp.rs for what was tried). This script
# three times, in one run each beside ezdxf's read:
#   02:58  1 thread 686 ms 15.4x, 2 threads 489 ms 21.7x (ezdxf 10,591 ms)
#   03:46  1 thread 755 ms 14.7x, 2 threads 612 ms 18.1x (ezdxf 11,098 ms)
#   03:55  1 thread 742 ms 16.8x, 2 threads 590 ms 21.1x (ezdxf 12,432 ms)
# The machine's speed moves by a quarter from hour to hour (ezdxf's read
# with it), so a ratio is worth only beside its own ezdxf run. Two
# threads, stages of the 21.1x run: parse 40, contours 120, kerf 23, plan
# 346, G-code 61 ms. glibc's malloc keeping freed memory
# (GLIBC_TUNABLES=glibc.malloc.mmap_threshold=1073741824:glibc.malloc.trim_threshold=4294967295,
# fewer fresh pages to fault in) took 4-8 % off a fresh process's total
# (669 -> 634, 907 -> 832 ms, 6 and 8 pairs); not set by the CLI, which
# would need unsafe FFI (mallopt) or an allocator crate.
#
# Issue 17, session 14, the stages on threads (2026-11-25 01:06 UTC, this
# 2-core AMD EPYC 2.6 GHz machine, idle): each stage shares its work among
# the cores natively (src/par.rs; the page's wasm has one thread), the
# program byte-identical with 1, 2 and 3 threads (cmp of the 4, 11, 25 MB
# nests' programs; tests/threads.rs, plan_threads.rs, gcode_threads.rs and
# the reader's chunk tests compare 1 against 2, 3, 8 threads). Wall ms on
# the 25 MB nest, examples/stages --rounds 1 (one process a round), 8
# rounds alternating before (47558f1) / after --threads 1 / after
# --threads 2, medians; the process's CPU is /usr/bin/time's user + sys:
#   stage       before  1 thread  2 threads  (2 threads / before)
#   parse         90.6      89.8       75.0   0.83
#   contours     177.2     173.9      157.2   0.89
#   kerf          50.9      50.0       30.0   0.59
#   plan         483.4     478.9      363.2   0.75
#   G-code       115.5     113.5       71.8   0.62
#   total        924.8     918.6      694.0   0.75
#   process CPU  995       985       1075     (threads cost ~8 % more CPU)
# This script (wall, best of 3 rounds in one process, 01:08 UTC, idle):
# one thread 746 ms, 14.7x ezdxf's read (10,989 ms); two threads 624 ms,
# 17.6x (target 20x, ~549 ms here); stages with two threads parse 59,
# contours 117, kerf 25, plan 354, G-code 68 ms. The 60k-site tour
# (benches/tsp.rs --time 20000 3 THREADS, wall, 2 runs each): one thread
# 261-273 ms grid, 237-239 random; two threads 215-235 grid, 205-208 random
# (the same tours). On two threads: the reader cuts ENTITIES into chunks
# at entity starts, each read by a reader forked after BLOCKS (dxf/
# chunks.rs); the contours' entity preparation and the containers' search
# on ranges; the kerf on ranges of contours; the plan's clearance index
# built while the tour is made, the precedence nearest-neighbour tour
# while the free tour is searched, the neighbour lists on ranges of sites,
# the cuts on ranges of the tour's visits; the program written in runs of
# cuts from a guessed state, each run checked against the one before and
# written again where the guess was wrong (gcode/runs.rs; numbered-block
# and knife posts on one thread). Left: the tour's search and the
# chaining run on one thread (~300 and ~60 ms); joining the program's
# runs copies 29 MB (~15 ms).
#
# Issue 17, session 13, the three branches merged (2026-11-24 22:15 UTC, a
# new machine of the same kind, ~1.4x slower than session 12's: AMD EPYC
# 2.6 GHz; idle; examples/stages --cpu --rounds 1, one process a round
# pinned to one core, 8 pairs alternating in both orders, medians; before
# = becbccb, after = d2935e9; programs byte-identical, cmp of the 4, 11,
# 25 MB nests' programs), CPU ms on the 25 MB nest:
#   parse 87.9 -> 88.0 (1.00), contours 190.0 -> 174.0 (0.92), kerf 76.0 ->
#   48.0 (0.63), plan 486.0 -> 475.9 (0.98), G-code 114.0 -> 112.0 (0.98);
#   whole pipeline 949.9 -> 897.8 (0.95). ezdxf 1.4.5 reads the same file
#   in 11.06-11.44 s of CPU on this machine (3 runs, pinned, interleaved
#   with ours at 876-963 ms): ~12x (target 20x, ~560 ms here). Peak RSS
#   291 MB, 95.8k minor page faults (374 MB touched): ~20 % of the CPU is
#   the kernel's (sys 0.17-0.24 s of ~1.05 s). Tried and dropped: other
#   allocators (jemalloc, mimalloc by LD_PRELOAD, 3 runs each: no gain,
#   more faults) and transparent huge pages for malloc (glibc.malloc.
#   hugetlb=1: faults 96k -> 11k, but sys time 0.2 -> 0.4-0.7 s: the
#   kernel's compaction on this 'madvise' machine).
#   This script itself (wall clock, best of 3 rounds in one process, so
#   later rounds reuse freed memory; 22:45 UTC, idle): whole pipeline
#   735 ms, ezdxf read 10,622 ms, 14.4x; per contour flat from 4k to 137k
#   contours but the plan (2.3, 2.8, 3.0 us at 22k, 61k, 137k: caches);
#   stages parse 77, contours 116, kerf 34, plan 415, G-code 94 ms. The
#   60k-site tour (benches/tsp.rs --time 20000 3): 250 ms grid, 220 ms
#   random (CPU; 180-200 on session 12's machine).
#
# Issue 17, session 13, kerf and G-code (2026-11-24 21:57 UTC, load ~3 on
# the 2 cores; CPU ms, examples/stages --cpu --rounds 1, one process a round
# pinned to one core, main at becbccb against branch s13-out, alternating
# pairs, medians; programs byte-identical: cmp of the 4, 11, 25 MB nests'
# programs at 3 and 6 decimals, every preset at 3 and 6 decimals on the
# 4 MB nest, the 49 shared DXFs through three posts at 3 and 6 decimals:
# 294 programs, none different; goldens unchanged):
#   nest       contours | kerf                 | G-code
#                       | before after  ratio  | before after  ratio
#   nest-4MB      22420 |   11.9   8.0  0.67   |   16.0  16.0  1.00 (3 pairs)
#   nest-11MB     61264 |   35.4  20.1  0.57   |   48.0  47.2  0.98 (3 pairs)
#   nest-25MB    137256 |   80.0  52.0  0.65   |  127.9 119.4  0.93 (11 pairs)
#   (25 MB with the "after" binary run first, 6 pairs: kerf 0.69, G-code
#   1.03; parse, whose code is the same, reads 0.91-0.92 either way: the
#   G-code stage is unchanged within that noise. The two stages alone, 20
#   rounds a process (a loop example since folded into examples/stages
#   --rounds 20, whose best rounds are the same warm figures): kerf 60 ->
#   37 ms.) Kerf:
#   the raw offset of a loop of lines with rounded corners (a rectangle
#   outwards) skips the library's local self-intersection search (lines
#   tangent to their corner arcs: proof at kerf_raw.rs no_local_crossing);
#   the drawn loop's local search skipped for lines meeting at corners
#   (the library's line-line test gives t = 1 exactly: proof at
#   kerf_simple.rs lines_meet_at_corners); an offset's area against the
#   tolerance by bounds on each arc's circular segment, no atan (the
#   library's area where the bounds straddle it); the corner pre-check's
#   |u||v| by one sqrt, not two hypot calls. Each with a property test
#   against the library. Left (~35 ms warm): the raw offset's divisions and
#   square roots, the approximate-box pair test and the distance check of
#   the first vertex (~20 %), the output vectors (one per path; an arena
#   would change KerfPath), the drawn polyline and its repeat scan.
#   G-code: an arc's nearest grid centre with equal squared radii needs no
#   square roots. Tried and dropped: the arc's centre by sqrt instead of
#   hypot (guarded to snap to the same grid point): 4 pairs of 20 rounds,
#   no difference to see; cavalier_contours and its index at opt-level 3
#   natively (they are "z" for the wasm): kerf ~0.97x, within noise, not
#   worth splitting the profile. Left (~80 ms idle): the digits' stores
#   into fresh lines of the 29 MB program (half of Words::num's samples are
#   its two 16-byte stores), the kernel's first touch of those pages
#   (~14 ms), snap's round, the plan's cuts read back (cache misses on
#   each cut's vectors).
#
# Issue 17, session 13, plan stage (2026-11-24 21:50-21:57 UTC, load 3-4
# on the 2 cores, other builds running; examples/stages --cpu --rounds 1,
# one process a round pinned to one core, ABBA groups (6 on each nest, 8
# more on the 25 MB one), medians; before = main at becbccb, after =
# s13-plan; programs byte-identical: cmp of the 4, 11, 25 MB nests'
# programs; goldens unchanged):
#   nest       contours | plan ms before after  ratio
#   nest-4MB      22420 |          90.0   94.2  1.05 (4 ms ticks)
#   nest-11MB     61264 |         225.8  212.1  0.94
#   nest-25MB    137256 |         556.1  534.1  0.96 (three more sets:
#                       |         559.4  502.5  0.90, 8 groups, load 4;
#                       |         484.0  489.9  1.01, 6 groups, load 1;
#                       |         545.9  516.0  0.95, 8 groups, load 1)
#   So ~0.95, within the noise of any one set. By perf (cpu-clock,
#   --rounds 3, three runs a binary): plan:: user samples 2997/2687/2742
#   -> 2595/2476/2699, contour_cut 406/332 -> 144/136, lead_in 341/266 ->
#   230/186, the grid's construction 80/87 -> 41/39; kernel samples of
#   the whole process up (716/632/863 -> 898/847/997) with the same page
#   faults (perf -e page-faults: ~96k both): the runs' totals equal.
#   Cuts: a batch of 64 visits' kerf paths read at once before their cuts
#   (Builder::warm): in tour order a path's record, then its loop, were
#   two cache misses one after the other; read together the core keeps
#   many in flight. A cut's start vertex found by equality with the
#   tour's entry, not a hypot a vertex. Clearance: the obstacles' segments
#   stored by the cell of their box's corner (counting sort), so a
#   lead-in's queries read neighbouring memory. Tour: the instance's
#   candidates copied in the caller's order to their renumbered places
#   (no gather); one grid for both constructions; the first search's
#   path not synced before its entry re-choice syncs it; the polished
#   length summed once. Tried and dropped: the grid's items holding their
#   point (and site) inline (slower: the sites' Hilbert numbering already
#   makes the look-ups local, and 24-byte slots were more to read); the
#   cuts built in path order and put in tour order (plan no faster, the
#   G-code stage ~30 ms slower: it then read cuts' steps scattered); the
#   obstacles' cells read a batch ahead like the paths (lead_in -60 %, but
#   the batch reads cost as much). Left: the two constructions (~45 ms),
#   the local searches (~60), the entry re-choices (~40), the neighbour
#   lists (~30), the cuts' fresh pages (~53 MB of steps, 64 B a step).
#
# Issue 17, session 13, the reader and the contours stage (branch s13-read,
# 2026-11-24 22:12 UTC, load 1-2 on the 2 cores, other helpers building;
# examples/stages --cpu --rounds 1, one process a round pinned to one core,
# before = becbccb, 12 pairs alternating in both orders, medians), CPU ms on
# the 25 MB nest: parse 91.0 -> 90.5 (0.99), contours 194.2 -> 180.1 (0.93;
# every "after" round below the "before" median). 11 MB nest (6 pairs):
# contours 88.0 -> 80.2; 4 MB (6 pairs): 32.2 -> 28.1. Best of 4 rounds a
# process (5 pairs, before the last change): contours 131.9 -> 120.0.
# Programs byte-identical (cmp of the 4, 11, 25 MB nests' programs).
# Page faults of the whole run 95.8k -> 92.4k. What changed: the depth
# pass keeps a loop slot (u32) per contour and the built loops in one
# vector reserved up front (an Option<Loop> of 120 B per contour was 16 MB
# written as None and dropped; rank/depth/parent u32); classify returns
# depth and parent and one pass in index order writes depth, parent,
# kind, part and reference (four passes over the 23 MB of contours
# before); Contour::layer an Arc<str> per layer (137k strings); each
# entity's layer and stamp flag listed by heal::prepare while the entity is
# in cache (the contour build read the 27 MB entity array once per contour:
# its hottest load); the reader's extent grown in add_entity (no pass over
# the finished drawing; parse unchanged within noise). Left: chaining
# (~40 % of the stage: the end grid's scattered fill and look-ups, two small
# vectors per chain), prepare (~20 %: a vector and trig measures per
# circle), the contour array's fresh pages (137k x 168 B), the depth pass's
# box grid and point tests; parse as session 12 left it (the pair loop, the
# number parser, per-entity compares). Plan/kerf/G-code columns moved by
# +-8 % between runs of one binary here: noise, not this branch (their
# page-fault counts per function are unchanged).
#
# Issue 17, session 12, the five branches merged and the native build at
# opt-level 3 (2026-11-24 20:01 UTC, nothing else running; examples/stages
# --cpu --rounds 1, one process a round pinned to one core, 5 alternating
# pairs, medians; before = cfda43a, after = 13889a2), CPU ms on the 25 MB
# nest (137,256 contours):
#   parse 76 -> 64, contours 156 -> 136, kerf 100 -> 56, plan 408 -> 356,
#   G-code 100 -> 80; whole pipeline 836 -> 688 (0.82x). ezdxf reads the
#   same file in 8.7-9.2 s of CPU (session 11): ~13x (target 20x, ~450 ms).
#   Programs byte-identical (cmp of the 4, 11, 25 MB nests' programs).
#   Of the 0.82x about half is opt-level 3 (the crate was "s" natively
#   too, for the page's wasm; the wasm stays "s": Cargo.toml), half the
#   branches below.
#
# Issue 17, session 12, the reader and the contours stage (2026-11-24
# 19:16 UTC, load 9 on the 2 cores; CPU ms, examples/stages --cpu, main at
# cfda43a against branch s12-chain, alternating pairs, medians; programs
# byte-identical: cmp of the 4, 11, 25 MB nests' programs; goldens,
# corpus and fixtures unchanged):
#   nest       contours | one round a process (5 pairs) | --rounds 3 (3 pairs)
#                       | parse        contours         | parse      contours
#   nest-4MB      22420 |  14.0  11.6   23.0  24.0      |  8.0  8.0  12.0  12.0
#   nest-11MB     61264 |  36.0  31.8   67.9  63.0      | 25.4 24.0  40.1  40.0
#   nest-25MB    137256 |  76.0  71.9  162.7 145.9      | 59.3 52.0 101.4  92.1
#   (earlier, at load ~4: parse 55 -> 48 warm, contours 153 -> 139 one
#   round a process.) Parse: an entity's body appended by the pair source
#   itself (each pair pushed from registers; returned one at a time as a
#   Result through memory, its reload stalled on store forwarding, ~40 % of
#   take_body). Contours: loops drawn twice found by a radix sort of their
#   keys' hashes, not two hash maps of every loop; no hypot where an axis
#   settles it; a chain's length summed only once its ends meet; the end
#   grid read from the pieces. Budgets (~40 parse, ~80 contours) not
#   reached. Left, parse: per-entity type and layer compares (memcmp calls
#   at opt-level "s"; a word compare was tried and measured slower), the
#   number parser (~12 %), the extent pass (~8 %), ~15 ms of first-touch
#   page faults (343k entities of 80 B plus a segment vector each). Left,
#   contours: ~50 ms of first-touch page faults one round a process (134 MB
#   touched: 137k contours of 176 B, the chains, the depth index), the
#   per-contour vectors and layer name, circles' measures (atan, sin).
#
# Issue 17, session 12, kerf and G-code (2026-11-24 19:20 UTC, load 8-9;
# CPU ms, examples/stages --cpu --rounds 3, main at cfda43a against branch
# s12-kerf, alternating pairs (4 on the 25 MB nest, 3 on the others),
# medians; programs byte-identical: cmp of the 4, 11, 25 MB nests'
# programs, goldens unchanged):
#   nest       contours | kerf                 | G-code
#                       | before after  ratio  | before after  ratio
#   nest-4MB      22420 |   12.0   8.0  0.67   |   11.9  12.0  1.00 (4 ms ticks)
#   nest-11MB     61264 |   33.7  21.9  0.65   |   33.7  32.4  0.96
#   nest-25MB    137256 |   84.8  54.7  0.65   |   85.5  80.8  0.95
#   Kerf: the raw offset built from the loop's geometry (src/kerf_raw.rs)
#   for loops whose meetings are all smooth or outer corners (the sheet's
#   rectangles outwards, its circles both ways), the library's up to
#   rounding (1e-9 mm on 20,000 random loops; programs byte-identical at 3
#   and 6 decimals), into buffers kept from loop to loop, no angle taken;
#   that raw offset taken as the answer where the stitch's copy would be
#   the same;
#   the drawn loop's and offset's polylines reused; the box test of short
#   loops in an 8-box array; the slight-turn bound (acos, tan) once a job;
#   the second repeat scan skipped when the first, wider, found nothing.
#   Left (~55 ms): the two local self-intersection searches (drawn loop,
#   raw offset: ~25 %), the box tests and arc boxes (~12 %), the loop's
#   area, from_pline and the output vectors (~15 %).
#   G-code: the emitter loops over cuts and steps (no chained iterator), a
#   cut's comment written straight into the program. Left (~80 ms): ~14 ms
#   a round is the kernel's (first touch of the 29 MB program: fresh mmap
#   pages, above glibc's 32 MB mmap ceiling; time shows sys 14 ms of 89),
#   the rest the text itself (digits stored into new cache lines, snap's
#   round, block framing) and arc centres (hypot, ~10 %). Tried and not
#   kept: the number written in place in the program (no gain: the stores
#   miss on fresh lines, not on forwarding), a table of three-decimal
#   fractions (0.98x, within noise, +4 KB of table).
#
# Issue 17, session 11, the four branches merged (2026-11-24 17:07 UTC,
# nothing else running; examples/stages --cpu --rounds 1, one process a
# round pinned to one core, 4 alternating pairs, medians; before =
# d40645f, after = 0969447), CPU ms on the 25 MB nest (137,256 contours):
#   parse 76 -> 72, contours 222 -> 154, kerf 160 -> 96, plan 510 -> 388,
#   G-code 124 -> 98; whole pipeline 1,100 -> 814 (0.74x). ezdxf reads the
#   same file in 8.7-9.2 s of CPU: ~11x (~8x before; target 20x, ~450 ms).
#   Programs byte-identical but for the tour above 20k sites (no kicks:
#   +0.01 % of rapid on this nest). The sections below are each branch's.
#
# Issue 17, plan stage, fifth pass (2026-11-24, load 3-5, paired A/B of
# examples/stages --cpu --rounds 3, 3 pairs, before = main at d40645f,
# after = s11-plan; medians):
#   nest         contours | plan ms before  after  ratio
#   nest-4MB        22420 |             76     55  0.72
#   nest-11MB       61264 |            204    161  0.79
#   nest-25MB      137256 |            528    414  0.78
#   One round a process (as the CLI runs), 25 MB: plan 526 -> 413, whole
#   pipeline 1110 -> 993. (With --rounds 3 the contours stage of the
#   "after" binary reads ~25 ms slower: its best round no longer finds the
#   heap pages the old plan's larger arrays left behind; one round a
#   process it is the same.) Fewer fresh pages (perf put a third of the old
#   plan in the kernel zeroing them): u32 lists, shared candidates, sizes
#   known up front, the sites built flat; a lead's pierce checked by
#   Obstacles::clear_of; no kicks above 20k sites (tours +0.3 % at 60k
#   sites, within 0.02 % on these sheets; see benches/tsp.rs). Programs
#   byte-identical except for that tour change. Target ~150 ms not reached.
#
# Issue 17, the contours stage and the reader (2026-11-24, load 6-7; CPU ms,
# examples/stages --cpu --rounds 3, main at d40645f against branch
# s11-chain, 3 alternating pairs, medians; programs byte-identical, cmp of
# the 4, 11, 25 MB nests' programs; goldens unchanged):
#   nest       contours | parse        | contours      ratio
#                       | before after | before after
#   nest-4MB      22420 |    8.0  10.5 |   23.6  15.9   0.67
#   nest-11MB     61264 |   24.8  26.3 |   64.9  45.9   0.71
#   nest-25MB    137256 |   57.6  57.8 |  179.4 113.8   0.63
#   Contours: open pieces stored flat and each chain written once (a
#   sheet's 270k lines were two vectors each, moved into deques and freed),
#   no hypot for ends farther than t along an axis, a chain's length summed
#   only until it passes 2t, short loops' point-test bands inline (no four
#   vectors per rectangle), floor without the libm call, the depth order by
#   a radix sort. Target ~80 not reached: left are the per-contour vectors
#   the contour keeps (segments, entities, the layer name cloned), the two
#   loop-key hash maps (closed entities, then all loops: ~7 %), circles'
#   measures (atan, sin, bbox trig) and first-touch page faults of the
#   stage's large vectors (~15 %). Parse unchanged (the OCS early return
#   for ±Z is in the noise; the 4 ms steps are the CPU clock's tick).
#   Chaining 1M isolated segments: examples/chain_scale.rs.
#
# Issue 17, kerf and G-code (2026-11-24, load 5-7; CPU ms, examples/stages
# --cpu --rounds 3, main at d40645f against branch s11-kerf, 4 alternating
# pairs, medians; programs byte-identical: cmp of the 4, 11, 25 MB nests'
# programs and of all 60 shared DXFs' programs, goldens unchanged):
#   nest       contours | kerf                 | G-code
#                       | before after  ratio  | before after  ratio
#   nest-4MB      22420 |   23.3  13.4  0.57   |   18.0  12.0  0.67
#   nest-11MB     61264 |   64.4  38.9  0.60   |   48.4  36.7  0.76
#   nest-25MB    137256 |  147.2  90.4  0.61   |  113.8  87.3  0.77
#   Kerf: cavalier_contours' offset taken step by step with its own raw
#   offset, local search and distance predicate, its two spatial indexes
#   replaced by a pairwise test of the same boxes (src/kerf_simple.rs): bit
#   for bit the library's answer where no non-adjacent boxes meet (a
#   rectangle, a round hole), the library's whole way elsewhere; the drawn
#   loop's self-crossing check the same way; the invalid-vertex scan skipped
#   where cross products show no corner can be invalid. Left (~90 ms):
#   create_raw_offset ~25 %, the two local searches ~20 %, allocation and
#   first-touch page faults ~25 % (137k output paths), the loop's polyline
#   and area. G-code: numbers by a per-decimals constant divisor, two
#   digits a division, fixed-size copies; round without the libm call;
#   single-byte words pushed; a cut's comment unsanitised when sanitising
#   changes nothing. Left (~87 ms): the text itself (~45 %: digits, the
#   block's words), motion bookkeeping, ~15 ms of page faults for the
#   29 MB program, the arcs' centre (hypot) and grid search (~10 %).
#
# Issue 17, the stages around the plan (2026-11-24, load 8-10; CPU ms,
# examples/stages --cpu --rounds 3, main at 5071ed7 against branch
# s10-front, 3 alternating pairs, medians; programs byte-identical, cmp of
# the 4, 11, 25 MB nests' programs):
#   nest       contours | parse        | contours      | kerf          | G-code
#                       | before after | before after  | before after  | before after
#   nest-4MB      22420 |    8.0   8.0 |   32.7  20.0  |   24.0  20.6  |   16.0  16.0
#   nest-11MB     61264 |   24.3  22.1 |  104.3  60.1  |   68.2  60.5  |   46.9  46.0
#   nest-25MB    137256 |   53.9  57.3 |  265.8 153.1  |  153.4 140.7  |  106.1 107.9
#   Contours 0.58x: each loop measured once (area, length, box in one pass,
#   geom::path_measure, carried from the entity through the chainer to the
#   contour; it was measured five times over), loop and edge keys under the
#   Fx hash (SipHash before), the closed loops' 400k edges no longer keyed
#   when nothing is open, closed pieces passed through the chainer without
#   a slot each, in-place splits (no partition copies of 137k chains), the
#   containment grid and bands as flat lists (a Vec per cell before).
#   Kerf 0.9x: the contour's own area gives its direction (no clone, no
#   second loop area), one polyline built where it was built twice, both end
#   tangents from one centre and start angle; the rest (~60 %) is
#   cavalier_contours' offset itself (opt-level 3 for it: no change under
#   LTO). G-code and parse: not changed here (a fixed-size digit copy and
#   an inline round were tried: 0.98x, not worth their wasm bytes).
#   Wasm: the cutting core 460,545 -> 460,495 B gzip (main built here).
#
# Issue 17, plan stage, fourth pass (2026-11-24, load ~4, paired A/B of
# examples/stages --cpu --rounds 3, 4 pairs, before = main at 5071ed7,
# after = s10-plan at 4c1b266):
#   nest         contours | plan ms before  after  ratio | total ms before after
#   nest-25MB      137256 |            545    455  0.83  |             1101  1019
#   (medians; program byte-identical, cmp). The tour's sites renumbered in
#   sheet order above 20k sites, its per-site and neighbour lists flat, the
#   polish's entry re-choice by changed stretches, the entry points handed
#   back with the tour; see benches/tsp.rs. Target ~150-180 ms not reached:
#   the tour is still ~320 ms of it (neighbour lists ~65, two constructions
#   ~60, entry re-choices ~100), the rest ~130 by perf shares (contour_cut
#   with lead_in and the clearance distance ~80, Obstacles::new ~15, the
#   sites' candidate vectors built and dropped ~20).
#   Wasm (scripts/build-wasm.sh, gzip -9, same machine and toolchain): the
#   cutting core 460,537 -> 464,890 B (449 -> 453 KiB: over the 450 KiB
#   bound again; the flat lists, renumbering, stretch re-choice and
#   neighbour array add ~4.3 K); the nester 563,724 -> 568,762 B.
# Issue 17, third pass (2026-11-24, load 6-9; CPU ms from examples/stages
# --cpu, before and after built from the same tree one after the other):
#   G-code writer, programs byte-identical (md5 of the 4, 11, 25 MB nests'):
#   nest         contours | G-code ms before  after
#   nest-4MB        22420 |               42     31
#   nest-11MB       61264 |              112     85
#   nest-25MB      137256 |              247    181   (paired, whole process
#   CPU 0.945x; target ~70: the rest
#   is the arc-centre search on the grid, the number writer and the copy)
#   G-code writer, fourth pass (2026-11-24, load 4-5, paired A/B of
#   examples/stages --cpu --rounds 3, medians; programs byte-identical):
#   the nearest grid centre taken at once when its radii agree (the
#   49-point search only for the others), the program built as bytes with
#   unnumbered blocks written in place (no UTF-8 check per number, no
#   block copy), {est_time_s}/{pierces} stats only when a template uses them
#   nest         contours | G-code ms before  after  ratio  (pairs)
#   nest-4MB        22420 |             27.8   16.0  0.58   (3)
#   nest-11MB       61264 |             74.9   49.0  0.65   (3)
#   nest-25MB      137256 |            159.8  107.1  0.67   (5; 29.3 MB of
#   program at ~270 MB/s; target ~70: left are Segment::arc_center's hypot
#   per feed segment, snap's round calls, the digit loop and per-word copies)
#   Wasm, fourth pass (scripts/build-wasm.sh, gzip -9 bytes): the cutting
#   core had grown back to 477,781 B (466 KiB) with the cut charts, heat
#   map, settings builder and contour references; each step measured alone:
#   step                                                   core gzip B after
#   seven copies of std's sorts fewer (src/sort.rs: sort_indices,
#     sort_floats, sort_cells on one LSD radix sort; chain's 4 buckets
#     by a sorting network)                                 471,219 (-6.6 K)
#   log's max_level_off in wasm (tiny-skia's warn!, no
#     logger); wasm-opt -Os --converge -iit                 468,130 (-3.1 K)
#   heat cells by radix (sort_cells)                        467,133 (-1.0 K)
#   presets_json / backplot_json without serde_json Values
#     (same text, unit-tested against the Value versions)   463,565 (-3.6 K)
#   simd128 (.cargo/config.toml; tiny-skia's vectors)       458,827 (-4.7 K)
#   wasm-opt --strip-producers; tour repair on the shared
#     sort; radix a byte a pass (native speed)               459,053 B = 448 KiB
#   nester module: 559 -> 543 KiB (556,839 B). CPU in Node, the 4 MB generated nest
#   through the Job, its report, program and three previews, simd128 build
#   against the same tree without it, 3 pairs: 0.99x (no loss).
#   Tried and not taken: Post's template lists through one deserialize_with
#   (+0.2 K), the page's settings through JSON.stringify + serde_json (-0.5
#   K, and 1-ULP float risk), opt-level "z" for zmij/itoa/ahash/smallvec/
#   arrayvec/num-traits (+0.2 K). Left: serde's derive code for Post (28 KB
#   raw), tiny-skia's unused blend-mode stages (~60 KB raw, reachable through
#   its stage table), core's Unicode printable table (kept by serde's
#   "string {:?}" messages).
#   Wasm, gzip -9, third pass (scripts/build-wasm.sh builds both modules):
#   module                                   before            after
#   www/pkg/kerfcam_bg.wasm (cutting core)   741 KiB (all in)  437 KiB
#   www/pkg/kerfcam_nest_bg.wasm (nester)    -                 530 KiB, loaded
#                                            when Sheet mode first needs it
#   What went from the core, KiB gzip, in the order taken: the nester's
#   bindings (feature "nester") -84; opt-level "z" for tiny-skia, serde_json,
#   serde_core, serde-wasm-bindgen -50 (CPU in Node side by side, the 11 MB
#   nest through the Job, report, program, 3 previews: 1.02x); encoding_rs,
#   whose East-Asian tables the browser's TextDecoder replaces in wasm -127;
#   16 cold stable sorts through one (src/sort.rs) -14; "z" for
#   cavalier_contours, static_aabb2d_index, integer-blossom, wasm-bindgen,
#   js-sys -2; serde_json's float_roundtrip with the nester only -9; the
#   Unicode case tables (src/case.rs: JavaScript folds non-ASCII names in
#   wasm) -15.
#
# Issue 17, 2026-11-23, the shared 2-core machine (load ~1-2), one round.
# Before = main at f9ae282, after = branch speed (the contour order's
# search: Or-3opt, pruned Or-opt, kick schedule; see benches/tsp.rs).
# Side by side, the two `stages` binaries one after the other per file:
#   nest         contours | plan ms before  after  after/before | total ms before  after
#   nest-0.2MB       1162 |             47     55     1.17      |              55     62
#   nest-1MB         5728 |            189    104     0.55      |             225    141
#   nest-11MB       61264 |           1247    721     0.58      |            1651   1120
#   nest-25MB      137256 |           2793   1616     0.58      |            3803   2588
# This script, after (µs per contour; before in brackets, same hour):
#   nest            contours  total ms | parse contours kerf  plan         G-code
#   nest-0.2MB.dxf      1162        65 |   0.8     2.1   1.5  49.3 (42.9)   2.4
#   nest-1MB.dxf        5728       150 |   0.5     2.3   1.3  19.6 (43.0)   2.5
#   nest-4MB.dxf       22420       465 |   0.5     2.2   1.6  13.9 (27.5)   2.5
#   nest-11MB.dxf      61264      1245 |   0.8     2.9   1.3  12.9 (23.0)   2.5
#   nest-25MB.dxf     137256      2661 |   0.5     2.9   1.3  12.3 (23.1)   2.4
#   25 MB nest: whole pipeline 2661 ms (was 4283), ezdxf read only 9089 ms:
#   3.4x (was 2.3x; target 20x). Stages of the 25 MB nest against their
#   budgets: parse 67/100, contours 395/80, kerf 178/50, plan 1691/150,
#   G-code 330/70 ms.
# No stage is superlinear here; the plan is still 64 % of the time (the
# tour's two nearest-neighbour constructions, local search and 10,000
# kicks; the rest of the plan stage is leads and clearance). Chaining of
# isolated segments is superlinear: examples/chain_scale.rs.
# Wasm (www/pkg/kerfcam_bg.wasm, gzip -9): 601 KiB with opt-level "s" (the
# release profile); "z" makes it 508 KiB but the pipeline 2.0-2.4x slower
# in Node (1 and 4 MB nests, side by side), so "s" stays (target 450 KiB).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
rounds="${1:-3}"
out=target/bench-sheet
mkdir -p "$out"

venv=target/bench-venv
if [ ! -x "$venv/bin/python" ] || ! "$venv/bin/python" -c 'import ezdxf' 2>/dev/null; then
  python3 -m venv "$venv"
  "$venv/bin/pip" install --quiet ezdxf
fi

cargo build --release --quiet --example stages
cargo bench --quiet --bench reader --no-run 2>/dev/null || true
files=()
for mb in 0.2 1 4 11 25; do
  f="$out/nest-${mb}MB.dxf"
  [ -s "$f" ] || cargo bench --quiet --bench reader -- --write-nest "$f" "$mb" >/dev/null
  files+=("$f")
done
# The nest issue 17 was measured on: 20,000 plates with a round and a
# rectangular hole each (benches/pipeline.rs; 60k contours, 8.4 MB).
parts20k="$out/nest-20000-parts.dxf"
[ -s "$parts20k" ] || cargo bench --quiet --bench pipeline -- --write-nest "$parts20k" 20000 >/dev/null

# One thread (one core's work), then the machine's cores (the CLI's
# default, at most 8; the program is the same: tests/threads.rs).
cores=$(nproc); [ "$cores" -gt 8 ] && cores=8
table() {
  printf '\n%s\n%-22s %9s %8s | %s\n' "$1" "nest" "contours" "total ms" "per contour, µs: parse  contours  kerf   plan   G-code"
  echo "$2" | awk -F'\t' '{
    n = $4; split($1, p, "/");
    printf "%-22s %9d %8.0f |                   %5.1f  %8.1f  %5.1f  %5.1f  %7.1f\n",
      p[length(p)], n, $10, 1000*$5/n, 1000*$6/n, 1000*$7/n, 1000*$8/n, 1000*$9/n }'
}
stages="${CARGO_TARGET_DIR:-target}/release/examples/stages"
rows1=$("$stages" --rounds "$rounds" --threads 1 "${files[@]}")
table "one thread (wall ms, best of $rounds):" "$rows1"
rowsn=$("$stages" --rounds "$rounds" --threads "$cores" "${files[@]}")
table "$cores threads (wall ms, best of $rounds):" "$rowsn"

big="${files[-1]}"
ezdxf_read() {
  "$venv/bin/python" - "$1" <<'PY'
import sys, time, ezdxf
best = float("inf")
for _ in range(2):
    t = time.perf_counter()
    ezdxf.readfile(sys.argv[1])
    best = min(best, time.perf_counter() - t)
print(f"{best * 1000:.0f}")
PY
}
ezdxf_ms=$(ezdxf_read "$big")
echo
for pair in "1:$rows1" "$cores:$rowsn"; do
  t="${pair%%:*}"
  echo "${pair#*:}" | tail -1 | awk -F'\t' -v ez="$ezdxf_ms" -v t="$t" '{
    printf "25 MB nest, %d contours, %d thread(s): kerfcam whole pipeline %.0f ms; ezdxf read only %.0f ms; ratio %.1fx (target 20x)\n", $4, t, $10, ez, ez / $10
    printf "  stage budgets of ~450 ms: parse %.0f/100, contours %.0f/80, kerf %.0f/50, plan %.0f/150, G-code %.0f/70 ms\n", $5, $6, $7, $8, $9 }'
done

# The two-hole nest, the same way (both thread counts, beside ezdxf's read).
ezdxf20k_ms=$(ezdxf_read "$parts20k")
for t in 1 "$cores"; do
  "$stages" --rounds "$rounds" --threads "$t" "$parts20k" | awk -F'\t' -v ez="$ezdxf20k_ms" -v t="$t" '{
    printf "20,000-part two-hole nest, %d contours, %d thread(s): kerfcam whole pipeline %.0f ms; ezdxf read only %.0f ms; ratio %.1fx (target 20x)\n", $4, t, $10, ez, ez / $10
    printf "  stage budgets of ~450 ms: parse %.0f/100, contours %.0f/80, kerf %.0f/50, plan %.0f/150, G-code %.0f/70 ms\n", $5, $6, $7, $8, $9 }'
done
