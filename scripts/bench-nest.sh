#!/usr/bin/env bash
# MEASURED 2026-12-01 (collide/cells, issue 44): the points-inside half of
# the exact test answered from cells over each many-vertex shape (outside /
# inside / near, vertices by cell) instead of lists of the edges and
# vertices near the neighbour made for every pair. Nests cmp-identical to
# the main binary (six real-part instances seeds 1-2 at 10 000 evaluations,
# jakobs1 shapes0 marques dagli fu seeds 1-2 at 20 000). CPU ratio new/main,
# side by side: keyboard 0.87, brackets 0.89, panels 0.91, boxes 0.73,
# flanges 1.06 (27-63-vertex outers: the cells cost more than the short
# lists there; cells from 65 vertices measured ~1.0 on flanges).
# Then (same day) cells made on a shape's first exact test, from 65
# vertices: keyboard 0.68, panels 0.94, brackets 0.96, flanges 1.00,
# flanges-solid 1.00, boxes 0.99 (5 pairs; see collide/cells.rs).
# Nesting benchmark (issue 16): every ESICUP instance in ../shared/nesting/
# nested by `kerfcam nest --instance` for TIME seconds, each nest judged by
# ../shared/nesting/check_nest.py (the independent checker; never copied
# here), our density printed beside the README's "sparrow, 60 s on one
# core" column and the ratio (target ≥ 0.98).
#
# usage: scripts/bench-nest.sh [TIME_S (default 60)] [SEED (default 1)]
# env:   NEST_PY   a python with ezdxf, shapely, networkx (default: a venv
#                  made once in /tmp/nestvenv)
#        KERFCAM   the binary (default: release build in $CARGO_TARGET_DIR or target/)
#        NEST_OUT  where the nests are written (default /tmp/kerfcam-bench-nest)
#        NEST_FIXED=1  each instance at the fixed evaluation count of the
#                  table below (TIME_S ignored): the nests of a 60 s run
#                  on an idle core, whatever the load
#        NEST_REAL=0  skip the real-part instances (below)
#        NEST_ONLY=NAME[,NAME]  run only these instances
# One instance at a time: each run uses one core, as sparrow's column does.
#
# ISSUE 44, session 44 (2026-12-01, main 6a5ce81, release binaries, NEST_FIXED counts, two runs
# at once on the 2 cores, every density by check_nest.py):
#   What twice the evaluations buy on real parts (the counts of the seed-1 60 s run, then doubled):
#   keyboard 57.82 -> 58.56 (s1), 57.50 -> 57.73 (s2); brackets 65.76 -> 65.93, 63.52 -> 64.81:
#   +0.6 points (about +1 %), the slope ESICUP showed (+0.55 %). Speed alone stays a small lever.
#   Tried, not kept: sparrow's several separator workers on one core (each pass of the separation run
#   twice from the same layout and weights, other random draws, the lower total overlap kept; a
#   temporary KC_WORKERS switch): base -> two, density %: s1 shapes0 65.40 -> 65.22, marques 89.83 ->
#   88.71, dagli 85.89 -> 87.15, jakobs2 79.89 -> 80.39, blaz1 82.32 -> 81.53, fu 90.38 -> 90.47,
#   jakobs1 89.08 -> 89.05; s2 shapes0 67.73 -> 65.35, marques 89.36 -> 89.83, dagli 86.10 -> 86.61,
#   blaz1 81.50 -> 82.16, fu 90.85 -> 89.86: mean -0.24 points over 12 pairs. At equal moves the
#   second worker halves the passes; sparrow's workers are free only on idle cores.
#   Tried, not kept: every outline of more than 16 vertices simplified (simplify.rs MANY_VERTICES 16,
#   not 64; sparrow simplifies every item), --time 60, base and variant at once (one a core), real
#   parts, density % base -> 16 (evaluations): flanges s1 59.09 -> 58.32 (302 922 -> 377 687), s2
#   58.63 -> 58.97; brackets 65.11 -> 64.03 (79 591 -> 94 456), 63.52 -> 64.03; panels 87.19 ->
#   87.16, 88.41 -> 87.52; flanges-solid 84.89 -> 85.39, 85.28 -> 84.53; keyboard 57.80 -> 57.80,
#   57.33 -> 57.46: 15-25 % more evaluations, mean -0.20 points over 10 pairs (the area grown costs
#   what the speed buys; ESICUP's polygons, at most 14 vertices, are not touched either way).
# ISSUE 44, the team's exchange interval at 10 s (session 41, a temporary KC_EXCHANGE switch, not
# kept): --time 10 --threads 2 (the page's default), one run at a time, real parts, seeds 1-3, every
# nest valid. Exchange every 10 000 evaluations (team.rs EXCHANGE_EVERY) -> every 2 000: boxes -0.60,
# brackets -0.87, flanges-solid +0.41, flanges +0.78, keyboard +0.38, panels -0.47: mean -0.06 (se
# 0.22), with 10-40 % fewer evaluations (boxes s2 71 855 -> 42 618). Every 10 000 -> never (two
# independent searches, the better kept): boxes +0.30, brackets +0.21, flanges-solid 0, flanges
# +0.77, keyboard +0.18, panels -0.43: mean +0.21 (se 0.12, 17 runs), with 10-35 % more evaluations
# (flanges-solid s1 67 013 -> 91 677). The evaluations the exchanges cost (seed 1, two single runs
# one a core against --threads 2): boxes 75 642 against 63 189 (every 10 000) and 76 323 (never),
# flanges 108 351 / 84 927 / 94 279, panels 93 895 / 66 010 / 85 840: the searches wait for each other
# at each exchange (each pauses between two tries of the separation, up to ~3 600 moves past the
# count). A lead: fewer or no exchanges in short runs; the page's team (www/nest-team.js) and the
# two-worker determinism test run the same rule, so both would change together.
# Seeds 4-6 (session 42, the same build): never against every 10 000: boxes 0 0 0, brackets 0 0 -0.75,
# flanges-solid +0.83 0 0, flanges +0.14 -0.58 0, keyboard +0.55 0 0, panels 0 -0.88 0: mean -0.04
# (se 0.09, 18 runs). Over seeds 1-6 (36 runs): +0.04 (se 0.09): not told apart, the lead of seeds
# 1-3 was noise. The exchange stays at every 10 000; the evaluations it costs do not show in density.
#
# ISSUE 44, the sequence search's work a share of the operator's budget (2026-12-01 session 40): all
# of SEQUENCE_WORK (about 6.4 s) from a 30 s budget, in proportion below it (a fifth), so short runs
# no longer spend most of their time there. Sized from the budget (NestSettings::budget_s), never the
# clock: the page's Stop replays with 5 s more on the clock and the run's budget. Real parts, seeds
# 1-3, one process a core, every nest valid, density % change:
#   --time 10  main -> a fifth: keyboard +0.18, brackets -0.04, boxes +0.97 (89.34 on every seed),
#              panels +0.20, flanges +0.18, flanges-solid +0.27: mean +0.29 (evaluations: keyboard
#              s2 778 -> 15 935, panels s1 16 822 -> 50 342: main's 10 s went mostly to the phase)
#              a tenth (SEQUENCE_FULL_S 60) -> a fifth: mean +0.25; main -> a tenth: +0.16
#   --time 5   main -> a fifth: keyboard +0.33, brackets +6.57, boxes +1.10, panels +5.15, flanges
#              +4.17, flanges-solid +3.02: mean +3.39 (main's 5 s went to the phase: 52-209
#              evaluations on keyboard, brackets, panels, flanges, against 3 489-22 822)
#   ESICUP, seeds 1-2, main -> a fifth: --time 5: blaz1 +0.79 +1.60, dagli +0.23 +3.58, fu 0 0,
#              jakobs1 -0.86 +2.57, jakobs2 +3.03 +1.88, marques +1.73 -0.93, shapes0 +2.20 +0.92:
#              mean +1.20; --time 10: blaz1 -2.91 -0.40, dagli +1.70 -1.16, fu 0 +0.05, jakobs1
#              -0.89 -2.11, jakobs2 -0.01 -1.57, marques 0 +0.22, shapes0 +0.63 -0.34: mean -0.49
#              (seeds 3-4: blaz1 +0.48 +1.59, dagli 0 0, fu 0 0, jakobs1 -1.28 +1.73, jakobs2 -2.76
#              -0.78, marques -0.34 -0.30, shapes0 +2.85 -0.36: +0.06; four seeds -0.21, jakobs2
#              -1.28 on every seed)
#   --time 30  main -> a tenth: keyboard +0.29, brackets +0.21, boxes -0.09, panels +0.20, flanges
#              -0.18, flanges-solid -0.68: mean -0.04. A fifth is main at 30 s and more.
#   --time 10 --threads 2 (the page's default budget, two workers; one run at a time), main -> a
#              fifth: keyboard +0.19, brackets +0.57, boxes +0.26, panels +0.86, flanges -0.20,
#              flanges-solid +0.30: mean +0.33.
#   jakobs2 at 10 s (session 41, a temporary trace of the phase's end): the fifth ends the sequence
#   search at evaluation 853 (s1) and 627 (s2), all of SEQUENCE_WORK on a stall at 1374 and 1355; the
#   best order was found at evaluation 373 (s1) and 354 (s2) either way, so both separate the same
#   nest, from another random state and with more time in the fifth. Its -1.28 is the separation's
#   spread on jakobs2's 2-unit plateaus (76.97, 77.27, 78.84, 80.40 %), not a shorter sequence search.
#   At the fifth's end the real parts' search was still gaining (the last better nest 0-3 decodes
#   before), and ESICUP's had not for 11-874 evaluations (fu ends on its stall, as before).
#   --time 3 (session 41, one process a core, seeds 1-3): all of the budget's work (main's rule) ->
#              a fifth: boxes +2.26, brackets +3.54, flanges-solid +5.12, flanges +3.99, keyboard
#              +0.14, panels +5.20: mean +3.37 (standard error 0.48). Short budgets want the share too.
#   Tried, not kept: a third at 10 s (SEQUENCE_FULL_S 20), against the fifth, seeds 1-3 (real) and
#   1-4 (ESICUP): boxes -0.90, brackets -0.15, flanges-solid -1.11, flanges +1.05, keyboard 0,
#   panels +0.42 (real mean -0.12, se 0.30); blaz1 +0.40, dagli -0.15, fu +0.03, jakobs1 +0.86,
#   jakobs2 +2.14 (the same sequence search's best either way: the separation's spread), marques
#   -0.06, shapes0 -0.96 (ESICUP mean +0.32, se 0.29). Over the 46 runs +0.15: no difference told.
#   Tried, not kept: a fifth up to 60 s (twice SEQUENCE_WORK at 60 s, about 12.8 s), --time 60 against
#   this, one process a core: keyboard 57.80 -> 56.76, 57.50 -> 57.57, 57.75 -> 57.23; brackets 65.76
#   -> 63.86, 63.52 -> 63.56, 63.63 -> 63.80; boxes -0.49, panels -0.08, flanges -0.43, flanges-solid
#   +0.48: mean -0.26.
#
# ISSUE 44, the placer's work counts the exact tests by their vertices (2026-12-01 session 39): the
# unit was a position tested against every copy placed, weighted by vertices past 16, and cost 1.2 ns
# on keyboard (50 copies, nearly all refused by their boxes) to 15.6 ns on jakobs1, so the sequence
# search's "about 6 s" was 1.1 s on keyboard (no decode past the first nest) and 1.1 s on boxes. Now
# a unit is about a candidate made and a pair past the boxes costs 20 + its vertices / 8 (fitted to
# the CPU time of the phase on the 13 instances: 12 ns a candidate, 262 ns a pair, 1.3 ns a vertex
# of it; every instance within 0.64-1.32 of the mean time a unit). The phase now ends at: shapes0
# 5.9 s (decode 579, was 487), keyboard 6.4 (55, was 50), brackets 5.7 (116, was 111), panels 4.7
# (75, was 71), flanges 3.8, flanges-solid 2.7, boxes 2.7; the six other ESICUP instances end on a
# stall at the same decode (the same nests). Side by side, --time 60, main 9f40562 -> this, seeds
# 1 2 3, density % (every nest valid):
#   keyboard       56.69 -> 58.11   56.61 -> 57.54   57.45 -> 58.04   mean +0.98
#   boxes          89.76 -> 89.42   91.86 -> 90.58   90.04 -> 90.69   mean -0.32
#   brackets       63.04 -> 65.76   64.75 -> 63.52   64.03 -> 64.27   mean +0.58
#   panels         88.13 -> 87.19   87.81 -> 88.55   87.68 -> 88.25   mean +0.12
#   flanges        58.73 -> 59.45   59.45 -> 58.63   59.46 -> 58.11   mean -0.48
#   flanges-solid  85.97 -> 84.93   85.52 -> 85.97   85.19 -> 85.06   mean -0.24
#   real parts' mean 74.01 -> 74.11: keyboard gains on every seed, the rest within the seeds' spread.
#   shapes0 at its NEST_FIXED count: s1 66.49 -> 65.40, s2 66.30 -> 67.73 (mean 66.40 -> 66.57).
# Shorter budgets (the same pairs, three processes on the 2 cores: the sheets bench beside):
#   --time 30 (the default)  keyboard 56.23 -> 56.76, 56.30 -> 57.01, 56.93 -> 56.29 (+0.20)
#                            brackets 62.41 -> 64.45, 63.46 -> 62.89, 62.76 -> 63.63 (+0.78)
#                            boxes 88.44 -> 89.33, 89.89 -> 89.11, 88.78 -> 89.11 (+0.15)
#   --time 10                keyboard 54.76 -> 55.35, 55.32 -> 53.67, 54.49 -> 54.34 (-0.40)
#                            brackets 59.36 -> 58.88, 60.96 -> 57.45, 62.13 -> 61.12 (-1.67)
#                            boxes 88.44 -> 88.44, 88.44 -> 87.77, 88.44 -> 88.00 (-0.37)
#   At 10 s under load the phase is most of the run (keyboard 203 evaluations against 14 515).
#   The same at 10 s on the quiet machine: keyboard 55.32 -> 55.35, 55.88 -> 55.88, 55.04 -> 54.89;
#   brackets 61.79 -> 63.17, 63.46 -> 62.26, 62.76 -> 62.36; boxes 88.44 -> 88.44, 88.44 -> 88.66,
#   88.44 -> 88.00 (mean -0.06). With the limit at a sixth (8.3e7 units, a temporary build: what a
#   share of 10/60 of the budget would give) every nest is main's. A share of the operator's budget
#   would fit short runs, but the page's Stop replays a run with the clock 5 s longer
#   (www/nest-run.js): the share would have to come from a budget passed apart from the clock.
# Keyboard plates on a 1000 x 500 sheet (the job of session 38 below): the phase ends at 5.0 s (free
# turns) and 5.6 s (quarter turns), was 6.0 and 9.1.
# ISSUE 44, the sequence search's work counts every exact test (2026-12-01 session 38, a9759f1): a
# slide's steps and the fallback's were not counted, and with 24 free turns a full sheet's fallback
# slides hundreds of copies. Keyboard plates (corpus-svg/crkbd/plate-alps.svg:6, 1000 x 500 sheet)
# spent 24-30 s on 58 decodes, so at the default 30 s the separation never began. Now it ends at
# 6.0 s (free turns) and 9.1 s (quarter turns). Crop x of the sheet, mm, side by side, old -> new:
#   --time 30  free s1 866.5 -> 812.8, s2 867.9 -> 835.3, s3 885.0 -> 809.2;
#              quarter s1 812.6 -> 808.5, s2 820.7 -> 812.6, s3 810.6 -> 802.6
#   --time 60  free s1 814.2 -> 806.3, s2 813.2 -> 804.6; quarter s1 799.9 -> 801.8, s2 810.2 -> 792.5
# Real parts at 60 s, seed 1, main d2e1577 (this and the cells merged; load 2: the sheets bench on
# the other core), every nest valid: boxes 89.12 % (215 007 evaluations), brackets 63.04 (110 136),
# keyboard 56.57 (120 429), panels 87.35 (260 685), flanges 58.64 (352 262; strip 571.91 mm),
# flanges-solid 85.34 (210 509; 777.50 mm). Boxes' 92.53 above was seed 1's luck: at its 328 281
# evaluations the old binary (5c64c8e) reaches 92.53 and this one 89.76, but at 150 000 seeds 2-4
# give old 89.56, 89.56, 89.67 against new 89.95, 88.83, 90.28.
# Of the ESICUP instances only shapes0 ends the sequence search sooner (decode 487, was 501): the
# others end on a stall at the same decode, the same nests. shapes0 at its NEST_FIXED count (301 790),
# old and new side by side: s1 65.39 -> 66.49 %, s2 67.27 -> 66.30 % (the mean of the two the same). The real-part instances end 0-3 decodes
# sooner (boxes, panels, flanges, flanges-solid).
# ISSUE 44, the final main of 2026-12-01 (0ca463f, the few-vertex exact test and SHEET_TRIES merged):
# --time 60, one run at a time on the otherwise idle 2-core machine, ci-profile binary, every nest
# valid by check_nest.py. Density %, evaluations, ratio to sparrow's 60 s column:
#              seed 1                   seed 2
#   fu         90.38 (622 546) 0.996    90.85 (621 291) 1.001
#   jakobs1    89.08 (463 491) 1.000    89.08 (421 696) 1.000
#   jakobs2    79.88 (418 078) 0.994    80.33 (423 808) 0.999
#   shapes0    65.39 (299 142) 0.984    67.27 (297 954) 1.012
#   dagli      85.89 (363 162) 0.997    86.85 (309 533) 1.009
#   marques    89.83 (453 948) 0.994    88.85 (384 325) 0.984
#   blaz1      82.32 (495 850) 1.001    81.50 (499 946) 0.990
#   mean       0.995 (min 0.984)        0.999 (min 0.984)
# The machine gave fewer evaluations a minute than when NEST_FIXED's table was measured (fu 622k
# against 768k, marques 454k against 576k) though the engine is 11 % cheaper: the host is shared.
# Every density is the fixed-count table's (the same plateaus, reached earlier) but seed 2's dagli
# (87.23 there at 353 803) and marques (89.11 at 576 251), which got fewer evaluations here.
# Real parts, the same way, seed 1 (no sparrow figure): boxes 92.53 % (328 281), brackets 63.04
# (134 240), keyboard 56.57 (114 681), panels 87.53 (349 556), flanges 58.93 (479 393; strip 569.10
# mm), flanges-solid 85.36 (363 432; 777.29 mm): part-in-hole 26.8 % shorter. Every nest valid.
# ISSUE 44, the exploration's tries traced (2026-12-01, main fe40b96, seed 1, NEST_FIXED counts; a
# temporary trace, not kept). A 60 s run makes few tries: jakobs2 141 (about 3 600 moves each),
# marques 139, shapes0 83. Tries from the best layout (the first at a length) succeed 16 of 31 on
# jakobs2, 4 of 20 marques, 4 of 14 shapes0; tries from the pool with two large copies swapped 5 of
# 110, 5 of 119, 3 of 69, and end with 10-30 times the overlap of the first (jakobs2: 1.3 against
# 10-49). jakobs2 stalls at the length 24 (80.40 %, the pieces' 2-unit grid: 12 + 12, 16 + 8) on
# seeds 1 and 2 even at 2 000 000 evaluations (seed 1 80.40 %; seed 3 broke through to 83.51 %).
# Tried, not kept (density % at the fixed counts, seed 1, base -> variant):
#   every try from the best layout, cut at a new place (no pool): jakobs2 79.89 -> 79.35, marques
#     89.83 -> 89.03, shapes0 65.39 -> 65.40, dagli 85.89 -> 85.95;
#   the pool without the swap: jakobs2 79.89 -> 80.41, marques 89.83 -> 87.82, shapes0 65.39 ->
#     63.42, dagli 85.89 -> 85.24;
#   once persistent, the cut back to 1 % after the least cut fails (not halved for ever): jakobs2
#     identical (cmp): a 60 s run never turns persistent (STUCK is 60 rounds; jakobs2 made 2).
# The few successful pool tries are the ones that pass a stall; the many failed ones are its cost.
# ISSUE 44, what twice the evaluations buy (2026-11-30, main cb382d8, seeds 1 2): the fixed 60 s
# counts of NEST_FIXED doubled, density % at 1x -> 2x: shapes0 65.39 -> 66.49, 67.27 -> 67.62;
# marques 89.83 -> 89.83, 89.11 -> 89.50; dagli 85.89 -> 86.30, 87.23 -> 87.44; mean +0.55 %
# (0 to +1.7 %, within the seeds' spread). A faster engine alone will not reach the target (mean
# 1.01 x sparrow's 60 s): at this slope it would need about four times the evaluations.
# ISSUE 44, the exact test of few-vertex polygons cheaper, same nests (src/nest/collide/, 2026-12-01,
# helper `exact`). Counted on jakobs1 at 20 000 evaluations: 8.1 M pairs past the boxes, decided by
# b's interior point in a 2.7 M, edges_cross 3.5 M, a's point in b 0.18 M, a point of a's boundary in
# b 0.86 M, clear 0.79 M (the last test, b's boundary in a, never said yes); 6.4 and 7.1 vertices a
# part. At most 16 vertices (no runs) edges_cross and holds_a_point_of now mark the edges and
# vertices near in bit masks instead of copying them into Few lists (whose room was zeroed and moved
# each pair: memcpy in both under perf), and edges_cross is asked before a's interior point. CPU
# ratio new/base (cb382d8), both at once, 20 000 evaluations, seeds 1-3, every nest cmp-identical
# and valid: jakobs1 0.909, shapes0 0.837, marques 0.898, dagli 0.863, blaz1 0.893, jakobs2 0.847,
# fu 0.898; median of the 21 pairs 0.893 (the machine loaded by another job: pairs vary ±0.05).
# Real parts (many-vertex: only the order changes), 3 000 evaluations, seeds 1-2 run twice, every
# nest identical: medians flanges 0.99, keyboard 1.00, brackets 0.99.
# Tried, no gain (dropped): eps·|edge| once an edge instead of once a pair (1.00), the edges' boxes
# kept in an array (0.99, noisy), the cut's division only where 0 < dot < |d|² (1.00).
# ISSUE 44, the pole proxy's rows cheaper, same nests (src/nest/separate/overlap.rs, 2026-11-30,
# helper `poles`). perf, jakobs1 at 8 000-20 000 evaluations: Walk::rows 19-32 % of the run; in it
# the marking loop built each bit through a float's exponent (SSE2 has no per-lane shift) and the
# sum's decay was a jump on the square root just taken, going either way at random (the samples
# sat on the instructions after sqrtsd and divsd). Now a row is marked in blocks of four with the
# bit places fixed (one mask a block, movmskps) and the decay chosen without a jump
# (std::hint::select_unpredictable; a plain if had the division sunk into a branch again). Its
# share fell to 12 % at 8 000 (edges_cross 15.4 -> 17.8 %). Stats of a walk (jakobs1 / shapes0):
# b's poles 18.7 / 22.7, kept by the box 16.8 / 17.4, rows walked 8.7 / 11.4 of 17.6 / 21.6 (the
# limit gives up the rest), rows near b's box 6.9 / 8.3, pairs within reach 19.8 / 20.9 a walk
# (18 % of those tested). Tried and not kept: two marked pairs a step in the two lanes of sqrtpd
# (the compiler vectorised the root only): dagli, shapes0 at 20 000, 2 seeds, 0.80 1.00 0.995
# 0.997, noise. CPU s by /usr/bin/time, base 4deb30d then this, run at once, ci-profile binaries,
# load 10-12 on the 2 cores, every pair's DXF identical (cmp) and valid (check_nest.py); ratio
# new/base for seeds 1 2 3 (median):
#   --evaluations 40000  shapes0 0.911 0.844 0.872 (0.872)  jakobs1 0.914 0.991 0.965 (0.965)
#                        jakobs2 1.152 0.960 0.984 (0.984)  blaz1 0.906 0.905 0.853 (0.905)
#                        marques 0.935 0.985 0.888 (0.935)  dagli 0.906 0.804 0.816 (0.816)
#                        fu 0.995 0.957 0.901 (0.957)       median of the 21 pairs 0.911
#   --evaluations 8000   flanges 1.005 0.987 1.276 (1.005)  keyboard 0.959 0.986 0.970 (0.970)
#   (real parts: the     brackets 0.955 0.972 0.971 (0.971) boxes 0.862 1.152 0.971 (0.971)
#   exact test and the   median of the 12 pairs 0.972
#   placer weigh more)
# The base binary's jakobs1 at 8 000 evaluations, seeds 1 and 2, is INVALID by check_nest.py
# (parts 12 and 13 overlap by area 1.6e-5; at 40 000 valid): left for the lead.
# ISSUE 44, the exact test's touch distance a ten-thousandth of the tolerance, not a thousandth
# (NestSettings::touch, 2026-11-30): with a thousandth (4e-6 on jakobs1, whose tolerance is 1e-4 of
# the height) jakobs1 seed 1 at 4 000-12 000 evaluations was refused by check_nest.py (two triangles
# 4e-6 into each other along a 4-unit edge: 1.6e-5 of area, over 1e-6 of the smaller part's). At the
# fixed 60 s counts (NEST_FIXED), base dc7585f (with the cheaper proxy) -> touch, density %, every
# nest valid:      seed 1                    seed 2
#   jakobs1        89.08 -> 89.08 (1.000)    89.08 -> 89.08 (1.000)
#   shapes0        65.40 -> 65.39 (1.000)    66.11 -> 67.27 (1.018)
#   blaz1          82.40 -> 82.32 (0.999)    81.80 -> 81.50 (0.996)
#   marques        90.27 -> 89.83 (0.995)    89.83 -> 89.11 (0.992)
#   jakobs2        80.40 -> 79.89 (0.994)    80.41 -> 80.33 (0.999)
#   dagli          87.08 -> 85.89 (0.986)    86.18 -> 87.23 (1.012)
#   fu             90.04 -> 90.38 (1.004)    90.81 -> 90.85 (1.000)
#   mean ratio     0.997                     1.002                   (14 pairs: 1.000)
# Against sparrow's 60 s column: seed 1 mean 0.995 (shapes0 0.984 the lowest), seed 2 1.000
# (marques 0.986, blaz1 0.991 the lowest); the base's seed 1 was 0.998.
# ISSUE 44, the sequence search decodes a changed order from the positions it shares with the current
# one (src/nest/decode/: trail.rs, decode_after; 2026-11-30). A swap, move or turn at k leaves the
# copies before k placed the same; each room keeps the position of every change (copy placed, item
# refused, work), so the rooms after k are had back by cutting those lists. Found first (a probe
# of the base binary, seed 1): the share of a decode's time spent on the positions shared with the
# current order was 23 % on jakobs1, 25 % marques, 8 % shapes0 (later copies cost most, and shapes0
# has no turns to change), 38 % flanges, 60 % brackets, 28 % boxes; keyboard's first nest spends the
# whole SEQUENCE_WORK, so it has no sequence decode. Nests byte-identical (cmp of DXF and JSON less
# time_s) in every pair: 7 ESICUP strips at 2 500 evaluations and 6 real-part strips at 600, seeds
# 1-2; --sheet WxH:50 (W of bench-nest-sheets.sh) on 5 real parts at 600 and shapes0, blaz1 at 2 500.
# CPU s, base 201fb9a then this, run at once, ci-profile binaries, load 6-8 on the 2 cores, seeds
# 1 2 3, median ratio:
#   in the sequence phase   jakobs1 --evaluations 1000: 0.766 0.807 0.808 (0.807)
#                           marques 1000: 0.784 0.720 0.775 (0.775)   shapes0 480: 0.945 0.999 0.937 (0.945)
#                           flanges 125: 0.735 0.552 0.791 (0.735)    brackets 111: 0.722 0.842 0.568 (0.722)
#                           boxes 53: 0.813 0.875 0.791 (0.813)
#   the whole 60 s run      (the evaluations of a 60 s run, NEST_FIXED's table and the real parts' counts
#   (one pair, seed 1)      above; the sequence phase is a few seconds of it) jakobs1 1.001, shapes0 0.982,
#                           marques 1.007, flanges 0.960, brackets 0.956, keyboard 1.001, boxes 0.981.
# ISSUE 44, after this session's merges (main 604b7d8, 2026-11-30 15:45 UTC): --time 60, seed 1,
# ci-profile binary, two instances at once (one per core) on the quiet 2-core machine, every nest
# valid by check_nest.py. Density %, evaluations, ratio to sparrow's 60 s column:
#   blaz1 81.44 (341 723) 0.990   dagli 86.06 (207 393) 0.999   jakobs1 89.04 (269 943) 1.000
#   fu 91.06 (377 093) 1.003      marques 88.87 (233 474) 0.984 jakobs2 80.39 (226 457) 1.000
#   shapes0 64.33 (159 921) 0.968                                mean 0.992 (one seed)
#   real parts (no sparrow figure): boxes 90.10 (234 815), brackets 63.11 (81 437), keyboard
#   57.83 (79 529), panels 87.96 (216 629), flanges 58.59 (333 805), flanges-solid 84.81
#   (257 720): part-in-hole strip 572.46 against 782.41 mm, 26.8 % shorter.
# Two runs at once get about half an idle core's evaluations each (shapes0 159 921 here against the
# 301 790 of an idle core's 60 s in NEST_FIXED's table, where seed 1 reached 65.95, 0.992): these
# figures sit below the fixed-count table's, which stays the reference (mean 0.997 over 28 runs).
# ISSUE 44, the placer's candidates ranked faster (src/nest/place/best_first.rs, 2026-11-30).
# perf, flanges at 300 evaluations (the first nest and the sequence search's decodes: the run):
# selecting the best 4 x MAX_CANDIDATES and sorting them was 41 % (quicksort 11, total_cmp rank 9,
# select 5.5). Now the rank's numbers are integers that compare as total_cmp does, no selection
# pass (the lazy walk stops at the same count), and each bucket of about 8 candidates is sorted
# when reached instead of the doubling slices. Nests byte-identical (cmp), every one valid by
# check_nest.py. CPU s at fixed evaluations (--time 100000), base eb5d0ba and now run at once,
# 3 pairs, ci-profile binaries, load 6-8 on the 2 cores, median ratio now/base:
#   flanges 300 s1 7.57 7.76 6.78 -> 5.74 5.97 5.84 (0.77)   s2 7.10 7.28 7.84 -> 6.04 6.00 7.48 (0.83)
#   brackets 300: 4.44 4.09 4.86 -> 4.03 3.58 4.38 (0.91)    keyboard 800: 0.99 (its placer time is
#   the slide's exact tests, Bands::new 18 %: left); at 20 000, one pair: jakobs1 8.12 -> 7.55,
#   shapes0 18.16 -> 16.96, marques 11.69 -> 9.28.
# Then the right edges kept apart as they are made (the bucketing pass reads 8 bytes a candidate,
# not 48) and the integer keys made without a branch: against the above, 3 pairs at once,
#   flanges 300 s1 6.83 7.06 6.74 -> 6.51 6.24 6.56 (0.95), s2 7.80 7.07 5.98 -> 7.61 6.87 5.45
#   (0.97), brackets 300 4.65 3.93 3.79 -> 4.66 3.78 3.71 (0.98); nests byte-identical.
# ISSUE 44, a faster separation, same nests (2026-11-30, ci-profile binaries, eb5d0ba4 then
# this, run at once, load 7-10 on the 2 cores; CPU s by /usr/bin/time, every pair's DXF
# identical by cmp, every nest valid by check_nest.py). perf of the separation: on ESICUP the
# pole proxy (Walk::rows) is 50-60 %, its pairs within reach already marked without a branch;
# on keyboard plates the exact test's height buckets, built anew for every pair tested
# (Bands::new), were a third. Now a many-vertex shape keeps the buckets of all its edges,
# moved with it (collide/bands.rs, Outline), and the separator lends one working room to every
# pair and position (no walk struct made and copied per pair, no moved copy allocated per
# position). CPU s, before -> after (ratio):
#   --evaluations 8000    keyboard s1 12.12 -> 8.41 (0.69), s2 14.07 -> 9.46 (0.67);
#                         brackets s1 9.00 -> 8.80 (0.98), s2 9.67 -> 8.18 (0.85);
#                         boxes s1 6.71 -> 5.58 (0.83), s2 6.70 -> 6.64 (0.99); flanges s1 0.998
#   --evaluations 40000   shapes0 s1 0.967 s2 1.019, jakobs2 0.992 0.997, blaz1 0.978 0.987,
#                         dagli s1 0.966: ESICUP within noise (at most 14 vertices a part:
#                         no buckets; the proxy's work is what it is).
#
# ISSUE 44, why round parts separate slowly (2026-11-30, helper `round`). Instrumented on flanges:
# a separation at the 1 % cut took 1 000-2 500 moves and mostly failed (7 of 40 from one layout at
# 599.6 mm); 35 % of moves left the copy where it was and only 6 % freed it: a disc wedged between
# neighbours clears along the line of centres, which the x/y-only descent never stepped along. The
# pole proxy is not the cause (one pole a disc; a proxy linear or quadratic in depth instead of the
# square root: 0 of 40 separated, tiny overlaps never cleared; decay 0.3 %/0.1 %: within noise). At
# smaller cuts the diagonal steps decide: 8-direction descent, 40 separations, 0.5 % cut 40 ok in
# 378 moves each against 30 in 978; 0.25 % 40 in 84 against 38 in 270 (progress per move 3-4x);
# ESICUP at its hard lengths within noise. Kept (descend.rs): diagonals at every other step, four
# failures a step as before (8 a step cost 15-30 % more time a move). 60 s, A/B at once, load 7-8,
# strip base -> diagonals: flanges s1 581.80 -> 584.74, s2 587.68 -> 581.80; flanges-solid 802.27 ->
# 798.24, 797.85 -> 801.86; shapes0 64.00 -> 62.10, 63.07 -> 64.35; blaz1 27.21 -> 26.85, 26.57 ->
# 27.17; marques 77.98 -> 78.18, 77.94 -> 78.34; jakobs1 11.355 -> 11.018, 11.498 -> 11.018: 6
# better, 6 worse, density ratio mean 1.006 (noise). The 60 s runs stay at the 1 % cut (the cut
# halves only after 10 failures in a row), where the gain is small: the next lever is the cut.
# Then at fixed counts (the lead, after the merges; NEST_FIXED's counts, flanges 333 805 and
# flanges-solid 257 720; base and diagonals at once, quiet 2-core machine, every nest valid by
# check_nest.py), density base -> diagonals (ratio): shapes0 s1 65.95 -> 65.40 (0.992), s2 65.19 ->
# 66.11 (1.014); jakobs1 89.08 -> 89.08 (1.000); blaz1 81.82 -> 82.40 (1.007); marques 89.83 ->
# 90.27 (1.005); jakobs2 80.40 -> 80.40 (1.000); dagli 86.22 -> 87.08 (1.010); fu 91.06 -> 90.04
# (0.989); flanges 58.59 -> 58.59 (1.000); flanges-solid 84.81 -> 85.28 (1.006): mean 1.002 over
# 10 pairs, seed 1 ESICUP against sparrow's 60 s column 0.998 both.
# ISSUE 44, the exploration's cut halved after 10 failures at it in total instead of 10 in a row
# (helper `cut`, 2026-11-30; tried, not kept). Instrumented (flanges s1, the full fixed count): the
# run does leave 1 %: 9 successes at 1 % (643.31 -> 587.68), then 10 failures in a row; then 0.5 %
# 1 ok in 11, 0.25 % 1 in 11, 0.125 % 11 in 17, 0.0625 % 2 in 12, ... 0.01 % 12 ok in 60 (159 tries,
# ending 573.09). In a full run the small cuts fail most tries too: the 40-of-40 of one layout at
# 599.6 mm does not hold at the lengths reached later, so the schedule is not the lever there.
# Fixed counts (NEST_FIXED's table, flanges 333 805, flanges-solid 257 720), base 4deb30d then
# this, run at once, every nest valid by check_nest.py, density base -> total-count (ratio):
#   s1 flanges 58.59 -> 58.52 (0.999)  flanges-solid 85.28 -> 85.39 (1.001)  shapes0 65.40 -> 67.05
#      (1.025)  jakobs1 89.08 -> 89.07 (1.000)  blaz1 82.40 -> 82.01 (0.995)  marques 90.27 -> 89.83
#      (0.995)  jakobs2 80.40 -> 80.40 (1.000)  dagli 87.08 -> 86.89 (0.998)  fu 90.04 -> 89.82 (0.998)
#   s2 flanges 58.45 -> 57.96 (0.992)  flanges-solid 85.27 -> 84.81 (0.995)  shapes0 66.11 -> 65.40
#      (0.989)  jakobs1 89.08 -> 89.08 (1.000)
#   mean 0.999 over 13 pairs (0.989-1.025), 3 better (shapes0 s1 alone by more than 0.1 point), 10
#   worse (jakobs1 s1 and jakobs2 s1 by under 0.01 point): reverted. Against sparrow's 60 s column,
#   seed 1 ESICUP: base 0.998, total-count 1.000 (shapes0's 1.025 alone; its seed 2 0.989).
#
# ISSUE 44 item 1, many-vertex outlines simplified on the safe side
# (src/nest/simplify.rs, 2026-11-30): outlines of more than 64 vertices
# grown by tolerance/100, then simplified (grow only, 0.1 % of the area,
# sparrow's default); rooms (holes) exact. Collision vertices of all
# copies: boxes 34144 -> ~4700, keyboard 20714 -> ~1240, brackets 16170
# -> ~4900, panels 2240 -> ~700; flanges and the 7 ESICUP instances (at
# most 62 and 14 vertices a part) unchanged. Before (main, 7a478a6) and
# after run at once, one on each core, ci-profile binaries, quiet machine,
# every nest valid by check_nest.py. Density %, evaluations:
#   --time 60     before            after             diff
#   keyboard s1   55.89 ( 40225) -> 57.00 ( 54020)   +1.11
#   keyboard s2   57.45 ( 48284) -> 57.66 ( 60286)   +0.20
#   boxes    s1   88.29 ( 58233) -> 90.10 (211582)   +1.82
#   boxes    s2   89.18 ( 60378) -> 89.85 (203331)   +0.67
#   brackets s1   63.07 ( 36948) -> 63.74 ( 87291)   +0.67
#   brackets s2   61.82 ( 40519) -> 63.25 ( 79114)   +1.43
#   --time 20, seeds 1/2/3: boxes 88.29 x3 -> 89.78 89.34 88.44; keyboard
#   55.06 56.17 55.61 -> 55.04 54.76 54.76; brackets 61.82 59.98 63.07 ->
#   61.85 62.62 61.48; panels 86.49 84.86 84.93 -> 85.35 85.52 87.02;
#   flanges, flanges-solid identical (under the threshold).
# The first version (every outline and room, no margin; under load 8,
# --time 20) gave panels two INVALID nests: a 45.5 mm rectangle flush on
# another's straight edge 9.4e-5 mm deep (~2 x the exact test's eps of
# tolerance/1000), which check_nest.py's 1e-6-of-area rule refuses; and
# flanges 52.14 -> 49.65 % (round parts, rooms shrunk). Budgets 0.05 % /
# 0.5 % then: boxes 87.56 / 85.82, flanges 52.07 / 46.92 (0.1 % kept).
#
# ISSUE 44, round many-vertex parts (2026-11-30, ci-profile binaries, load 6-9 on the 2 cores).
# perf, flanges at 12 000 evaluations: the exact test was 52 % of the run (holds_a_point_of 30 %,
# edges_cross 17 %): in the separation, pairs whose boxes meet and shapes are clear (round parts
# meet box to box at the corners); in the placer's hole bins, discs tested inside bores (within).
# The pole proxy was 4 %. Two quick answers before the edges are walked (src/nest/collide/): apart
# along a diagonal (x ± y extents) = clear; a disc round the part inside a circle of the room's
# core = within, a core circle half out of the disc round the room = not. Nests byte-identical.
# CPU s at fixed evaluations, base 77df9ed then now, in turn, DXF identical in every pair:
#   flanges 4000: 14.48 -> 8.12, 11.40 -> 8.31   flanges-solid 4000: 6.95 -> 5.30
#   pih (tests/it/nest_part_in_hole.rs's job as an instance) 100: 4.17 -> 2.65, 4.22 -> 2.89
#   keyboard 200: 3.14 -> 3.32, 3.26 -> 3.53, 4.91 -> 4.39, 3.93 -> 3.94 (median ratio 1.03: noise)
#   brackets 400: 3.95 -> 4.16, 5.88 -> 4.79, 4.97 -> 4.25, 5.27 -> 4.64 (median 0.87)
#   jakobs1 20k 8.53 -> 8.82, fu 3.49 -> 3.05, shapes0 16.26 -> 15.58, marques 12.27 -> 11.52
# Equal CPU (base and now run at once, 60 s wall each, ~15 s CPU each), check_nest.py valid:
#   flanges s1 (the diagonal test alone): 15 161 -> 39 780 evals, 611.78 -> 593.61 mm (54.82 -> 56.50 %)
#   flanges s2:  7 809 -> 35 799 evals, 617.96 -> 611.78 mm (54.27 -> 54.82 %)
#   flanges-solid s1/s2: 2.1x / 2.5x the evals, same length (806.30, 801.86: stuck, not slow)
#   keyboard s2: 7 503 -> 8 171 evals, same nest; ESICUP (30 s at once, ~7.5 s CPU): same densities.
# The part-in-hole test's "100 evaluations in 45 times the time" were no separation: with 20
# copies the sequence search runs to 5 000 evaluations (sequence_most) before the separation starts,
# and its decodes (placer + hole bins) were the time. The separation cannot put a loose disc into a
# bore (hole guests are fixed by the decode and ride with their host): left for the search.
#
# ISSUE 44 item 4, loose copies into rooms (src/nest/separate/rooms.rs, 2026-11-30): for every
# new best strip, copies holding no guests, furthest right first, offered to the rooms of placed
# copies (placer, then a grid slid left/down: the placer's candidates never reach a diamond bore).
# flanges s1: 48 -> 80 of 120 copies in holes (every disc; item_1's 12 diamond bores were empty in
# every nest). 12 000 evaluations, main (eb5d0ba) A then rooms B, at once, ci profile, load ~7,
# every nest valid by check_nest.py; strip mm (CPU s):
#   flanges s1 617.96 (9.7) -> 617.96 (9.4)   s2 611.78 (10.5) -> 611.78 (10.5)
#           s3 624.20 (10.3) -> 605.66 (10.4) s4 605.66 (10.0) -> 611.78 (10.2)  mean 614.90 -> 611.80
#   flanges-solid s1-s4 806.30 801.86 804.67 818.13, DXF identical A/B (no rooms: nothing asked)
#   part-in-hole gain (solid / flanges strip, mean of 4 seeds): 1.314 -> 1.320
#   jakobs1, shapes0 20 000 evaluations seed 1: DXF identical (cmp).
# Not a density gain yet at this budget: the strip only shortens by the exploration's cuts, and on
# flanges each try (a separation of round parts) takes ~1 000 moves, so 12 000 evaluations make ~10
# tries and every seed ends on a length of the chain 643.31 x 0.99^n (636.88 630.51 624.20 617.96
# 611.78 605.66): stuck at the first cut (1 %), the halved cuts never reached. The room freed (~3 000
# mm2, ~12 mm of strip) lies scattered where the discs were, for those few tries to use;
# flanges-solid stalls the same way (left: why a separation of round parts needs that many moves).
#
# Real-part instances (issue 44): shop jobs of parts of real drawings in
# ../shared (scripts/nest-jobs.txt: file, part, quantity), made into ESICUP
# JSON at bench time by examples/nest_instance.rs (outlines grown by half
# the 2.5 mm spacing, holes shrunk by it) into $NEST_OUT/instances, nested
# and checked the same way. sparrow has no figure for them (it is not in
# the cargo registry here — the crate of that name is another program —
# and cannot be built offline), so they are compared with our own engine:
# the density is printed, and flanges (plates with bores and the discs
# that fit) beside flanges-solid (the same parts, holes filled: the nest
# without part-in-hole), as the ratio of their strip lengths.
#
# ISSUE 44 item 3, fixed sheets against the strip: scripts/bench-nest-sheets.sh
# (its figures at its top: sheets use 1.01-1.19 x the strip's length, mean 1.065).
# ISSUE 44 item 2, several searches (kerfcam nest --threads N, src/nest/team.rs; ci-profile binary,
# seed 1, 2026-11-29, load 8-12 on the 2 cores). Budgets in evaluations per search, not seconds: on
# this loaded machine wall time says nothing, and N searches at E evaluations each take the wall time
# of one search at E on N idle cores. Density by check_nest.py, every nest valid:
#   instance   N=1, E=20k   N=2, E=20k each   N=1, E=40k (equal CPU)
#   jakobs1    82.48 %      84.16 %           85.01 %
#   shapes0    62.34 %      63.90 %           64.25 %
#   fu         87.25 %      88.24 %           87.69 %
#   panels     86.49 %      86.49 %           86.49 %   (real parts: 20k is still the order search)
#   flanges    54.82 %      56.50 %           56.50 %
# Two searches at equal wall time beat one on 4 of 5 (+1.0 to +1.7 points), and come within 0.4-0.9
# of one search given their summed evaluations (fu above it, flanges equal).
# ISSUE 44, real parts (2026-11-29, load 6-11 on the 2 cores: wall-clock
# figures are not comparable with the tables below). The first nest of
# many-vertex CAD outlines was the loss: in 30 s (load 6) boxes placed 9
# of its 50 copies, keyboard 34 of 50, brackets 104 of 110 (an unfinished
# nest is INVALID here: copies missing), so the separation never ran.
# perf: 87 % of it in the exact test of candidates lying on copies
# already placed. Now (each A/B in one run, same seed, nests compared):
# - circles inside many-vertex shapes (collide/core.rs) answer "overlap"
#   before the exact test: first nest CPU, keyboard 17.55 -> 9.33 s,
#   boxes 38.97 -> 4.25 s (load 7.4); DXF byte-identical.
# - the touching test's point and cut searches indexed (collide/bands.rs,
#   inside.rs): keyboard 9.63 -> 7.42 s, brackets 8.46 -> 9.34 s (load
#   11, noise); byte-identical.
# - the placer's work weighted by vertices past 16: boxes at 30 s reaches
#   the separation (2223 evaluations, was 52) and stops at 30.0 s (was
#   40.0 s: one decode of the sequence search overran the budget).
# ESICUP nests byte-identical (jakobs1, shapes0, marques at 20 000
# evaluations; their parts have 4-14 vertices, under every threshold).
# This script, 12 s, seed 1, load 8-10 (18:35 UTC; ci-profile binary):
#   fu 87.25 % (0.961 of sparrow's 60 s: 12 s at a third of a core);
#   flanges 643.3 mm, flanges-solid 865.1 mm: part-in-hole 25.6 %
#   shorter (both first nests: 121-123 evaluations; both valid).
# 20 s, load 8-10, 2 runs at a time: boxes 25/50, keyboard 29/50,
# brackets 28/110, flanges-solid 75/120 copies placed when the clock ran
# out (INVALID); panels 61/61 valid, 77.62 %, but 35.0 s for 20 (a decode
# of the sequence search is not cut by the clock). Under this load the
# real-part first nests still need more than 20 s: the budget must also
# hold inside a decode, and the placer's candidates on many-vertex parts
# (VERTEX_PAIRS, MAX_CANDIDATES) are the next thing to measure.
#
# CURRENT (session 12, 2026-11-24 18:52–19:50 UTC). Fixed counts
# (NEST_FIXED=1), every nest valid by check_nest.py. sparrow's pool of
# failed layouts (src/nest/separate/explore.rs): a separation that fails
# at a length leaves its least-overlapping layout in a pool (8 kept,
# least overlap first); the next try at that length starts from one of
# them picked by rank (u², the better more often) with two large copies
# of different parts swapped; 10 tries a length (was 3, each from the
# last failure) before the cut halves. Before = session 11 (cfda43a, the
# table below; the search is deterministic for a seed and a count, and
# jakobs1 seed 2 was re-run today: 87.13 again). Density %, ratio to
# sparrow's 60 s density; CPU s a run of the new engine (load 4–12).
# jakobs1 s1/s2, jakobs2 s3 and marques s1 were run by the screening
# build, the same search (checked: the same nest at 30 000 moves):
#
#   instance  sparrow60  seed 1 before → after   seed 2 before → after   seed 3 before → after   mean before → after       CPU s after
#   blaz1     82.28 %    81.86 → 81.82 0.994   82.71 → 81.50 0.991   80.94 → (not run)     82.28 → 81.66 (2 seeds)   61–65
#   dagli     86.12 %    85.98 → 86.22 1.001   85.54 → 85.27 0.990   85.62 → (not run)     85.76 → 85.75 (2 seeds)   67–70
#   fu        90.75 %    90.47 → 91.06 1.003   89.72 → 90.96 1.002   90.47 → (not run)     90.09 → 91.01 (2 seeds)   73–74
#   jakobs1   89.06 %    89.08 → 89.08 1.000   87.13 → 89.08 1.000   89.05 → 89.08 1.000   88.42 → 89.08 (3 seeds)   69–71
#   jakobs2   80.40 %    80.37 → 80.40 1.000   80.41 → 80.41 1.000   78.76 → 80.40 1.000   79.85 → 80.40 (3 seeds)   69–76
#   marques   90.34 %    88.67 → 89.83 0.994   89.83 → 89.78 0.994   88.65 → 89.30 0.988   89.05 → 89.64 (3 seeds)   76–85
#   shapes0   66.47 %    66.06 → 65.95 0.992   66.12 → 65.19 0.981   66.69 → 66.33 0.998   66.29 → 65.82 (3 seeds)   70–75
#
# Runs 18: mean ratio before 0.9936, after 0.9961; below 0.98 before 2, after 0; min after 0.981.
#
# True 60 s wall-clock runs, the merged main (pool + the proxy speed-up +
# the native build at opt-level 3; 13889a2), 2026-11-24 19:54–20:01 UTC,
# nothing else running, seeds 1 and 2 each pinned to one of the two
# cores (as sparrow's column was measured). Density %, ratio, evaluations
# made; session 11's seed-1/seed-2 ratios and evaluations in brackets:
#
#   instance  seed 1                         seed 2
#   blaz1     81.85 0.995 621k (0.995 460k)  81.50 0.991 563k (1.000 445k)
#   dagli     86.22 1.001 407k (0.998 316k)  85.32 0.991 400k (0.993 310k)
#   fu        91.06 1.003 678k (0.997 651k)  90.96 1.002 692k (0.989 672k)
#   jakobs1   89.08 1.000 514k (1.000 446k)  89.08 1.000 519k (0.971 444k)
#   jakobs2   80.40 1.000 473k (0.997 413k)  80.41 1.000 480k (1.000 433k)
#   marques   89.57 0.991 557k (0.972 464k)  89.78 0.994 496k (0.994 377k)
#   shapes0   65.95 0.992 339k (0.984 260k)  65.31 0.983 342k (0.995 259k)
#
# Seeds 3 and 4, the same way (20:13–20:20 UTC), ratio:
#   blaz1 1.001 0.994, dagli 1.005 0.995, fu 0.997 0.996, jakobs1 1.000
#   1.000, jakobs2 1.000 1.009, marques 0.988 0.987, shapes0 1.000 0.993.
# 28 runs (seeds 1-4): mean 0.997, min 0.983 (shapes0 s2), none below
# 0.98: issue 16's bar (>= 0.98 of sparrow at equal time on every
# instance) met on every seed tried. Against the records (README): 0.918
# (jakobs2) to 0.998 (jakobs1) of the record density, 4-seed means.
#
# 14 runs: mean ratio 0.992 -> 0.996, below 0.98 2 -> 0, min 0.983. A
# 60 s run now makes 1.0-1.4x the evaluations of session 11's: above the
# fixed counts on blaz1, dagli, jakobs1 and shapes0, still 0.86-0.97 of
# them on fu, jakobs2 and marques.
#
# CPU a run unchanged: jakobs1 seed 2, before 66.9 and 68.6 s, after
# 68.8 s, same hour (the move is the same code; a failed try costs one
# layout copy). Runs marked (not run) did not fit before the deadline
# (load 10–12: ~5 min a run); they are for the next session, as is
# the 60 s wall-clock table. Losses: shapes0 seed 2 66.12 → 65.19
# (0.981), blaz1 seed 2 82.71 → 81.50; more seeds decide whether the
# pool costs shapes0 and blaz1.
# Screens (density % at the fixed count unless said; before in brackets):
# - persistence sooner (STUCK 60 → 10 rounds): jakobs1 s2 86.47 (87.13).
# - persistence after 30 k moves without a gain: jakobs1 s2 86.47.
# - the cut ×2 after each success (up to 1 %): jakobs1 s2 89.07, marques
#   s1 88.66 (88.67), jakobs2 s3 80.41 (78.76), jakobs1 s4 at 200 k
#   89.08 (89.08); with the pool as well, jakobs1 s4 at 200 k 88.71
#   (pool alone 89.04): dropped, the pool alone kept (marques s1 89.83).
# - jakobs1 seed 5 at 200 k moves stalls before (87.18): a stall seed
#   not yet run with the pool.
#
# SPEED (session 12, 2026-11-24 18:10–19:50 UTC): the
# separator's pole-pair proxy and the exact test made cheaper WITHOUT
# changing a nest (src/nest/separate/overlap.rs, poles.rs PoleSet,
# sample.rs, collide/few.rs): nests byte-identical (JSON but time_s, and
# DXF) to cfda43a's on all 7 instances, seeds 1 and 2, 20 000
# evaluations, and at 100 000 (seed 1) on every instance below; so the
# density tables stand (the pool's above is measured by evaluations). CPU s (user+sys) of a whole run at
# a fixed count, cfda43a then this branch back to back, load 5–7:
#
#   instance  100k evals: before  after  after/before   20k evals (s1, s2)
#   blaz1      14.61 s  11.76 s  0.805 (2 pairs)   0.885 / 0.871
#   dagli      21.99 s  16.71 s  0.760 (2 pairs)   0.866 / 0.845
#   fu          8.93 s   7.21 s  0.807 (2 pairs)   0.792 / 0.821
#   jakobs1    16.88 s  13.07 s  0.774 (2 pairs)   0.850 / 0.865
#   jakobs2    16.10 s  12.44 s  0.773 (2 pairs)   0.897 / 0.855
#   marques    15.66 s  12.30 s  0.786 (2 pairs)   0.861 / 0.879
#   shapes0    27.15 s  20.29 s  0.747 (1 pair)   0.810 / 0.797
#
# At 20 000 evaluations most of a run is the sequence search (the
# placer, not changed but for the exact test's lists), so the ratio is
# smaller there. What was cut (perf, jakobs1, 100 k: the proxy was 54 %
# of the run, the exact test 24 %): the poles' box and largest radius
# found once per variant, not at every pair; a row's pairs marked in
# reach without a branch, then summed in order (same sum, bit for bit:
# overlap_tests.rs compares with the old proxy); the proxy's first two
# rows walked before the exact test is asked, so a pair the exact test
# finds clear (a quarter of those whose boxes meet) skips the rest of
# the walk (0, 1 rows: 3–5 % and 1 % slower than 2); the box test ahead
# of the weight's division; no heap lists in the exact test. Not done:
# SIMD (the crate forbids unsafe code, and opt-level "s" turns LLVM's
# vectorisers off), a broad phase (four in five pairs end at the box
# test already, a few ns each).
#
# Session 11 (15:46–16:36 UTC). Same fixed counts
# (NEST_FIXED=1), every nest valid by check_nest.py. The separator counts
# a strike only when a run of passes cut the least overlap by less than
# 2 %, as sparrow does (src/nest/separate/mod.rs, STRIKE_GAIN); before,
# every run was a strike and separations still converging were given up.
# Density (%), ratio to sparrow's 60 s density, CPU seconds a run (load
# 5–7, so CPU is inflated); in brackets session 10's mean:
#
#   instance  sparrow60  evals     seed 1         seed 2         seed 3         mean          CPU s   (session 10)
#   blaz1     82.28 %    512525    81.86 0.995    82.71 1.005    80.94 0.984    81.84 0.995   66–75   (81.82 0.994)
#   dagli     86.12 %    353803    85.98 0.998    85.54 0.993    85.62 0.994    85.71 0.995   62–70   (86.77 1.008)
#   fu        90.75 %    768114    90.47 0.997    89.72 0.989    90.47 0.997    90.22 0.994   73–79   (90.26 0.995)
#   jakobs1   89.06 %    501105    89.08 1.000    87.13 0.978    89.05 1.000    88.42 0.993   69–71   (87.58 0.983)
#   jakobs2   80.40 %    506445    80.37 1.000    80.41 1.000    78.76 0.980    79.85 0.993   70–76   (79.61 0.990)
#   marques   90.34 %    576251    88.67 0.982    89.83 0.994    88.65 0.981    89.05 0.986   73–89   (89.08 0.986)
#   shapes0   66.47 %    301790    66.06 0.994    66.12 0.995    66.69 1.003    66.29 0.997   70–72   (65.53 0.986)
#
# Mean ratio over the 21 runs 0.993 (session 10: 0.992). jakobs1 seeds 1
# and 3 no longer stall (86.77 → 89.08, 86.93 → 89.05) but seed 2 now
# does (89.04 → 87.13: no gain from 12 k to 447 k moves); jakobs2 seed 3
# 0.9796 (79.98 → 78.76), dagli −1.06 points of mean. Below 0.98: 2 runs
# (session 10: 3). CPU a move unchanged (the move is the same code):
# jakobs1 seeds 1/3 68.5/70.1 s before, 68.6/70.8 s after, same load.
# Screens (jakobs1 at its full count, seeds 1/3, before 86.77/86.93):
# sparrow's sample counts (50 uniform, 25 focused) 86.26/86.47, +2 % CPU;
# a restart from the best with two large copies swapped after 50 k moves
# without a gain 85.05/88.92 (20 k moves, 3 swaps, 85.91/–); dropped.
# With the strike rule, that restart: jakobs1 seed 2 87.13 → 86.47,
# jakobs2 seed 3 78.76 → 77.19: dropped too.
#
# Session 10 (08:40–09:36 UTC), same counts: the separator refines its
# best uniform sample too; compression down to 0.01 % of the length.
#   blaz1 82.49/81.79/81.19, dagli 86.53/87.33/86.46, fu 90.78/90.23/89.76,
#   jakobs1 86.77/89.04/86.93, jakobs2 78.56/80.30/79.98, marques
#   88.77/89.83/88.64, shapes0 65.13/66.05/65.40 (seeds 1/2/3, density %);
#   mean ratio 0.992, a move ~15 % more CPU than session 9.
# Wall clock 60 s (`bench-nest.sh 60 SEED`), seeds 1 and 2 run at once,
# each pinned to one of the 2 cores, nothing else running (load ~2): the
# setting of the README's sparrow column. Density %, ratio to sparrow's
# 60 s density, evaluations made (the fixed counts above were an idle
# core's before session 10's ~15 % dearer move: a 60 s run now makes
# 60–90 % of them). Before = session 10's engine (15:14 UTC), after =
# this session's strike rule (16:59 UTC); every nest valid by check_nest.py:
#
#   instance  before seed 1      before seed 2      after seed 1       after seed 2
#   blaz1     82.38 1.001 477k   81.79 0.994 460k   81.86 0.995 460k   82.30 1.000 445k
#   dagli     86.53 1.005 314k   87.33 1.014 300k   85.98 0.998 316k   85.54 0.993 310k
#   fu        90.78 1.000 639k   90.23 0.994 635k   90.47 0.997 651k   89.72 0.989 672k
#   jakobs1   85.05 0.955 426k   89.04 1.000 426k   89.08 1.000 446k   86.47 0.971 444k
#   jakobs2   78.56 0.977 420k   80.10 0.996 413k   80.17 0.997 413k   80.41 1.000 433k
#   marques   88.77 0.983 361k   89.67 0.993 294k   87.77 0.972 464k   89.83 0.994 377k
#   shapes0   64.48 0.970 253k   66.05 0.994 245k   65.38 0.984 260k   66.12 0.995 259k
#
# Seed 1 (the seed of sparrow's column): below 0.98 on jakobs1, jakobs2
# and shapes0 before, on marques alone after (87.77: at its fixed count
# seed 1 reaches 88.67). Mean ratio of the 14 runs
# after (0.991 → 0.992). jakobs1 stalls on one seed in two either way.
#
# Free rotation (issue 16 item 4, src/nest/separate/turn.rs): a part whose
# rotations are free tries 8 random angles a move in the separation and
# refines the best one's angle (±4° halving to 0.1°); ESICUP's instances
# have fixed orientations, so this table does not move (checked: nests
# byte-identical to before at 20 000 and 30 000 evaluations).
#
# Session 9 (2026-11-24 05:10–06:10 UTC). Every figure at a fixed
# evaluation count (--evaluations N, N = the count of FINAL3's 60 s seed-1
# run below): the search depends on evaluations only, so these are the
# nests of a 60 s run on an idle core of this machine, whatever the load
# was (1.5–6.3 during these runs; a 60 s wall-clock run under load 5 makes
# 2–10× fewer evaluations). Seed 1 is FINAL3's nest (the engine's search
# is unchanged since; checked: jakobs1 at 40 000 evaluations gives 85.899 %
# before and after this session's commits). Density (%) and ratio to
# sparrow's 60 s density; every nest valid by check_nest.py.
#
#   instance  sparrow60  evals     seed 1         seed 2         seed 3         mean
#   blaz1     82.28 %    512525    82.99 1.009    81.95 0.996    81.07 0.985    82.00 0.997
#   dagli     86.12 %    353803    86.16 1.000    85.53 0.993    85.10 0.988    85.60 0.994
#   fu        90.75 %    768114    88.81 0.979    89.64 0.988    91.05 1.003    89.83 0.990
#   jakobs1   89.06 %    501105    89.05 1.000    89.04 1.000    86.61 0.972    88.23 0.991
#   jakobs2   80.40 %    506445    79.41 0.988    77.56 0.965    80.38 1.000    79.11 0.984
#   marques   90.34 %    576251    88.97 0.985    89.82 0.994    88.51 0.980    89.10 0.986
#   shapes0   66.47 %    301790    65.22 0.981    64.98 0.978    64.83 0.975    65.01 0.978
#
# Means over seeds 1–3 are ≥ 0.98 of sparrow on all but shapes0 (0.978);
# single seeds go down to 0.965 (jakobs2 seed 2) and 0.972 (jakobs1 seed
# 3): the spread between seeds (up to 2.8 points) is larger than any
# change measured this session.
# Tried and dropped (session 9): the separation's snap also trying
# vertex–edge contacts with the copies near (snap::contacts), not only box
# edges. New − old at the same counts, points: shapes0 +0.72/+0.66/−1.51
# (seeds 1/2/3), fu +2.52/−0.64/−1.62, jakobs2 −1.32/+2.61/−0.15, blaz1
# −3.02/−0.04, jakobs1 −0.07 and, seed 3, a nest check_nest.py refused
# (parts 14 and 19 overlapping by 5·10⁻⁶ of area: exact contacts computed
# in floating point), marques −0.41. No gain, one invalid nest: reverted.
#
# Measured 2026-11-24, 60 s, seed 1, this machine (2 cores shared with
# other jobs, load 4–6). "sequence": the sequence search alone (the engine
# before the separation phase); "clock split": sequence search for 10 % of
# the clock, then separation (src/nest/separate/), run side by side with
# "sequence" (same load); "now": the engine as committed, the sequence
# search ending on evaluations (stall or a cap), then separation — run
# later, alone but under a heavier load. Ratio = our density / sparrow's
# 60 s density; every nest valid by check_nest.py.
#
#   instance  sparrow60  sequence        clock split     now             length (sequence → now)
#   blaz1      82.28 %   77.60 % 0.943   82.06 % 0.997   82.99 % 1.009   27.834 → 26.024
#   dagli      86.12 %   83.72 % 0.972   85.58 % 0.994   85.73 % 0.995   60.412 → 58.993
#   fu         90.75 %   86.36 % 0.952   87.89 % 0.968   87.14 % 0.960   33.000 → 32.704
#   jakobs1    89.06 %   81.66 % 0.917   86.19 % 0.968   89.05 % 1.000   12.000 → 11.004
#   jakobs2    80.40 %   74.22 % 0.923   77.18 % 0.960   76.31 % 0.949   26.000 → 25.288
#   marques    90.34 %   84.36 % 0.934   86.07 % 0.953   86.37 % 0.956   82.000 → 80.091
#   shapes0    66.47 %   62.34 % 0.938   64.34 % 0.968   63.28 % 0.952   64.000 → 63.047
#
# Target ≥ 0.98 met on blaz1, dagli and jakobs1; fu, jakobs2, marques and
# shapes0 are at 0.949–0.960 (single runs vary by about a point).
#
# Session 8 (same day, FINAL3 below): the proxy gives up a sample past the
# best (sparrow's fail-fast: ~23 % less CPU a move, same nests); the
# sequence search ends on the placer's work (~6 s), not on decodes (17 s
# of shapes0's 60 before); the separation turns persistent once stuck
# (src/nest/separate/mod.rs, STUCK). At equal evaluations (the counts of
# the 60 s run before it, seed 1; immune to load) the separation change
# measured: blaz1 82.99 → 82.99, dagli 85.73 → 85.73, fu 87.14 → 88.37,
# jakobs1 89.05 → 89.05, jakobs2 74.21 → 78.03, marques 86.37 → 88.74 %.
# Timed 60 s runs on this machine (2 cores, 4 jobs) vary with the load by
# more than that: the evaluation counts are printed beside each figure.
# FINAL3, 2026-11-24 03:48–03:56 UTC, 60 s, seed 1, load 2.9 → 1.0, every
# nest valid by check_nest.py (a run under load 4.7–6.8 with a wasm build
# beside it made 2–10× fewer evaluations: jakobs2 0.923, fu 0.960):
#
#   instance  sparrow60  now             evaluations
#   blaz1      82.28 %   82.99 % 1.009   512525
#   dagli      86.12 %   86.16 % 1.000   353803
#   fu         90.75 %   88.81 % 0.979   768114
#   jakobs1    89.06 %   89.05 % 1.000   501105
#   jakobs2    80.40 %   79.41 % 0.988   506445
#   marques    90.34 %   88.97 % 0.985   576251
#   shapes0    66.47 %   65.22 % 0.981   301790
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
dir="$here/../shared/nesting"
time_s="${1:-60}"
seed="${2:-1}"
out="${NEST_OUT:-/tmp/kerfcam-bench-nest}"
mkdir -p "$out"
py="${NEST_PY:-}"
if [ -z "$py" ]; then
  py=/tmp/nestvenv/bin/python
  if ! "$py" -c "import ezdxf, shapely, networkx" 2>/dev/null; then
    echo "making a venv for check_nest.py in /tmp/nestvenv" >&2
    python3 -m venv /tmp/nestvenv
    /tmp/nestvenv/bin/pip install -q ezdxf shapely networkx
  fi
fi
bin="${KERFCAM:-}"
if [ -z "$bin" ]; then
  (cd "$here" && cargo build --release --quiet)
  bin="${CARGO_TARGET_DIR:-$here/target}/release/kerfcam"
fi
# The evaluations of a 60 s seed-1 run on an idle core (FINAL3 below).
declare -A fixed=([blaz1]=512525 [dagli]=353803 [fu]=768114 [jakobs1]=501105
  [jakobs2]=506445 [marques]=576251 [shapes0]=301790)
printf "%-14s %6s %9s %9s %9s %7s %7s  %s\n" instance time_s length ours sparrow60 ratio evals check
fail=0
insts=("$dir"/*.json)
if [ "${NEST_REAL:-1}" != 0 ]; then
  (cd "$here" && cargo build --release --quiet --example nest_instance)
  "${CARGO_TARGET_DIR:-$here/target}/release/examples/nest_instance" \
    "$here/scripts/nest-jobs.txt" "$here/../shared" "$out/instances" 2>/dev/null
  insts+=("$out"/instances/*.json)
fi
results="$out/results.tsv"
: > "$results"
for inst in "${insts[@]}"; do
  name="$(basename "$inst" .json)"
  if [ -n "${NEST_ONLY:-}" ] && [[ ",$NEST_ONLY," != *",$name,"* ]]; then
    continue
  fi
  # The README's last column for this instance ("90.75 %" → 0.9075).
  ref="$(python3 - "$dir/README.md" "$name" <<'PY'
import sys
for line in open(sys.argv[1]):
    cells = [c.strip() for c in line.strip().strip("|").split("|")]
    if cells and cells[0] == sys.argv[2]:
        print(float(cells[-1].replace("%", "").strip()) / 100)
        break
PY
)"
  budget=(--time "$time_s")
  if [ "${NEST_FIXED:-0}" = 1 ] && [ -n "${fixed[$name]:-}" ]; then
    budget=(--time 1000000 --evaluations "${fixed[$name]}")
  fi
  json="$("$bin" nest --instance "$inst" "${budget[@]}" --seed "$seed" -o "$out/$name.dxf" --json)"
  set +e
  check="$(cd "$dir" && "$py" check_nest.py "$inst" "$out/$name.dxf")"
  rc=$?
  set -e
  [ $rc -eq 0 ] || fail=1
  python3 - "$json" "$check" "$rc" "${ref:-nan}" "$name" "$results" <<'PY'
import json, math, sys
ours, check, rc, ref, name = json.loads(sys.argv[1]), json.loads(sys.argv[2]), int(sys.argv[3]), float(sys.argv[4]), sys.argv[5]
d = check.get("density", 0.0) if rc == 0 else 0.0
problems = check.get("problems") or []
if check.get("missing"):
    problems = [f"{check['missing']} copies missing"] + problems
verdict = "valid" if rc == 0 else "INVALID " + "; ".join((problems or [check.get("error", "")])[:2])
ratio = d / ref if not math.isnan(ref) else float("nan")
length = check.get("strip_length", float("nan"))
sp = f"{ref*100:8.2f}%" if not math.isnan(ref) else "        -"
rt = f"{ratio:7.3f}" if not math.isnan(ratio) else "      -"
print(f"{name:<14} {ours['time_s']:6.1f} {length:9.3f} {d*100:8.2f}% {sp} {rt} {ours['evaluations']:7d}  {verdict}")
with open(sys.argv[6], "a") as f:
    f.write(f"{name}\t{d}\t{ratio}\t{length}\t{rc}\n")
PY
done
python3 - "$results" <<'PY'
import math, sys
rows = [l.rstrip("\n").split("\t") for l in open(sys.argv[1]) if l.strip()]
ratios = [float(r[2]) for r in rows if not math.isnan(float(r[2]))]
real = [float(r[1]) for r in rows if math.isnan(float(r[2]))]
if ratios:
    print(f"ESICUP: mean ratio to sparrow's 60 s density {sum(ratios)/len(ratios):.4f}, lowest {min(ratios):.4f} ({len(ratios)} instances)")
if real:
    print(f"real parts: mean density {100*sum(real)/len(real):.2f} % ({len(real)} instances; no sparrow figure)")
length = {r[0]: float(r[3]) for r in rows if r[4] == "0"}
if "flanges" in length and "flanges-solid" in length:
    a, b = length["flanges"], length["flanges-solid"]
    print(f"part-in-hole: flanges strip {a:.1f} mm, without part-in-hole (flanges-solid) {b:.1f} mm: {a/b:.3f} x, {100*(1-a/b):.1f} % shorter")
PY
exit $fail
