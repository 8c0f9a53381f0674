//! Zeno sequences: infinitely many collisions in finite time (an inelastic collapse, a ball
//! bouncing to rest), recognised from the engine's recent collisions and their accumulation time
//! extrapolated.

use std::collections::VecDeque;

/// Collisions that must fit in a vanishing span of time to call it a Zeno sequence.
pub(super) const ZENO_WINDOW: usize = 200;

/// The accumulation time of the run's last collisions, if they are a Zeno tail: at least 20 of
/// them, among at most 8 contacts, the gaps between them shrinking geometrically (each of the
/// last ten at most 0.99 of the one before).
pub(super) fn zeno_tail(recent: &VecDeque<(f64, usize)>) -> Option<f64> {
    if recent.len() < 20 {
        return None;
    }
    let tail: VecDeque<(f64, usize)> = recent.iter().skip(recent.len() - 20).copied().collect();
    if !few_contacts(&tail) {
        return None;
    }
    let times: Vec<f64> = tail.iter().map(|r| r.0).collect();
    let gaps: Vec<f64> = times.windows(2).map(|w| w[1] - w[0]).collect();
    let shrinking = gaps[gaps.len() - 11..]
        .windows(2)
        .all(|w| w[1] <= 0.99 * w[0]);
    if shrinking { extrapolate(&times) } else { None }
}

/// Whether the window's collisions involve at most 8 distinct contacts.
pub(super) fn few_contacts(recent: &VecDeque<(f64, usize)>) -> bool {
    let mut seen: Vec<usize> = Vec::with_capacity(9);
    for &(_, slot) in recent {
        if !seen.contains(&slot) {
            seen.push(slot);
            if seen.len() > 8 {
                return false;
            }
        }
    }
    true
}

/// The limit of event times shrinking geometrically: `t + dt r / (1 - r)` from the last two
/// positive gaps (still resolved, not yet lost to rounding).
pub(super) fn extrapolate(times: &[f64]) -> Option<f64> {
    let g: Vec<f64> = times
        .windows(2)
        .map(|w| w[1] - w[0])
        .filter(|g| *g > 0.0)
        .collect();
    let [.., a, b] = g.as_slice() else {
        return None;
    };
    let r = b / a;
    (r > 0.0 && r < 1.0).then(|| times.last().copied().unwrap_or(0.0) + b * r / (1.0 - r))
}
