//! The exploration's cut: the share of the length a try cuts out of the
//! best nest, and when it halves.
//!
//! The cut halves after [`TRIES`] failed separations at it *in total*,
//! the successes between them not counted: a cut that succeeds one try in
//! four (flanges at 1 %: 1 000-2 500 moves a try) reaches the smaller
//! cuts, where a try costs a few hundred moves and nearly always succeeds
//! (scripts/bench-nest.sh). Counted in a row, ten failures rarely came and
//! such a run stayed at its first cut. Gardeyn & Wauters (EJOR 2025,
//! arXiv 2509.13329) shrink the step of their compression on failures in
//! the same way; their exploration keeps its step and changes phase on
//! the clock, which this engine never reads (a run stopped after E moves
//! is the run given E moves).
//!
//! Down at [`LEAST_CUT`], [`STUCK`] rounds of failures turn the search
//! persistent: back to [`CUT`], with longer separations
//! ([`Cut::no_gain`]).

/// The first cut, share of the length, and its least value.
pub(super) const CUT: f64 = 0.01;
pub(super) const LEAST_CUT: f64 = 0.0001;
/// Failed separations at one cut before it halves.
pub(super) const TRIES: usize = 10;
/// Rounds of [`TRIES`] failures at the least cut before the search turns
/// persistent: the cut back to [`CUT`] and [`PERSIST_NO_GAIN`] passes a
/// strike. Measured at equal evaluations (seed 1), persistence from the
/// start gained 1–5 points on jakobs2, marques and fu and lost 1.5–6 on
/// blaz1 and jakobs1, which find their best early with short
/// separations: persistence only once the short ones are stuck keeps
/// both.
const STUCK: usize = 60;
const PERSIST_NO_GAIN: usize = 200;

/// The cut and how far the search has gone: failures at this cut, rounds
/// at the least one, persistence.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct Cut {
    /// The share of the length cut.
    pub(super) share: f64,
    failed: usize,
    stuck: usize,
    persist: bool,
}

impl Cut {
    /// The first cut, [`CUT`].
    pub(super) fn new() -> Cut {
        Cut {
            share: CUT,
            failed: 0,
            stuck: 0,
            persist: false,
        }
    }

    /// A separation failed at this cut; true when the cut changed (a new
    /// length: the pool's failed layouts are of the old one).
    pub(super) fn failed(&mut self) -> bool {
        self.failed += 1;
        if self.failed < TRIES {
            return false;
        }
        self.failed = 0;
        if self.share <= LEAST_CUT {
            self.stuck += 1;
        }
        self.share = (self.share * 0.5).max(LEAST_CUT);
        if !self.persist && self.stuck >= STUCK {
            self.persist = true;
            self.share = CUT;
        }
        true
    }

    /// Passes without a lower total overlap before a strike.
    pub(super) fn no_gain(&self) -> usize {
        if self.persist {
            PERSIST_NO_GAIN
        } else {
            super::NO_GAIN
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_cut_halves_after_its_failures_in_total_successes_between() {
        let mut cut = Cut::new();
        // One success in four (a success leaves the cut alone): the tenth
        // failure comes at the thirteenth try and halves it.
        let mut changed = 0;
        for k in 1..=13 {
            if k % 4 != 0 && cut.failed() {
                changed = k;
            }
        }
        assert_eq!(changed, 13);
        assert_eq!(cut.share, CUT / 2.0);
    }

    #[test]
    fn the_cut_stops_at_its_least_and_turns_persistent_when_stuck_there() {
        let mut cut = Cut::new();
        let mut rounds = 0;
        while !cut.persist {
            for _ in 0..TRIES {
                cut.failed();
            }
            rounds += 1;
            assert!(cut.share >= LEAST_CUT);
        }
        // 1 % halves 7 times to reach 0.01 % (the last clamped), then
        // STUCK rounds there.
        assert_eq!(rounds, 7 + STUCK);
        assert_eq!(cut.share, CUT);
        assert_eq!(cut.no_gain(), PERSIST_NO_GAIN);
        // Persistent, it halves as before and stays persistent.
        for _ in 0..TRIES {
            cut.failed();
        }
        assert_eq!(cut.share, CUT / 2.0);
        assert!(cut.persist);
    }
}
