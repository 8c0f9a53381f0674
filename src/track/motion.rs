//! The primitives every track engine shares, so that they all make the same decisions: when two
//! bodies (or a body and a wall) approach, when a gap closes, the impulse a collision gives, and
//! how positions are put back into contact after rounding.

use crate::values::rational::Q;
use num_traits::One;

use crate::values::compensated::{Dd, two_prod, two_sum};

/// Two bodies approach when their closing speed `v1 - v2` exceeds `2^-50` (about 8.9e-16) of the
/// sum of their own speeds `|v1| + |v2|`. Each velocity after a collision is the exact result
/// rounded once, so two velocities that are equal in exact arithmetic differ by at most one ulp
/// (`2^-52` relative) after rounding: below this threshold a closing speed cannot be told from
/// rounding, and the pair moves together. The rule belongs to the pair: no other body, no
/// run-wide scale, enters it.
pub const APPROACH: f64 = 1.0 / (1u64 << 50) as f64;

/// Whether a body at `v1` left of a body at `v2` approaches it (see [`APPROACH`]).
#[inline]
pub fn closing(v1: f64, v2: f64) -> bool {
    v1 - v2 > APPROACH * (v1.abs() + v2.abs())
}

/// The double-double nearest an exact value: `hi` the nearest binary64, `lo` the nearest to the
/// rest.
pub fn dd_of(q: &Q) -> Dd {
    let hi = q.to_f64().value();
    if !hi.is_finite() {
        return Dd::new(hi);
    }
    let rest = q - crate::values::rational::from_f64(hi);
    Dd {
        hi,
        lo: rest.to_f64().value(),
    }
}

/// What a collision between two bodies does, from exact masses and restitution: the coefficients
/// `k1 = (1 + e) m1 / (m1 + m2)` and `k2 = (1 + e) m2 / (m1 + m2)` as double-doubles (exact
/// rationals rounded once each, so whole-number mass ratios give the exact weights: 1/4 and 3/4
/// for masses 1 and 3, or 0.1 and 0.3 as typed), and whether the bodies stick (`e = 0`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Kick {
    k1: Dd,
    k2: Dd,
    sticks: bool,
}

impl Kick {
    pub fn new(m1: &Q, m2: &Q, e: f64) -> Kick {
        let e_exact = crate::values::rational::from_f64(e);
        let total = m1 + m2;
        let k = Q::one() + e_exact;
        Kick {
            k1: dd_of(&(&k * m1 / &total)),
            k2: dd_of(&(&k * m2 / &total)),
            sticks: e == 0.0,
        }
    }

    /// `(v1', v2')` by the impulse form `v1' = v1 + k2 (v2 - v1)`, `v2' = v2 - k1 (v2 - v1)`
    /// (lecture: the final velocities from the relative velocity), each an accurate sum of
    /// error-free terms (about 2^-100 relative) rounded once: correctly rounded but for
    /// near-ties. Bodies that stick get one common velocity, so they cannot approach again.
    #[inline(always)]
    pub fn apply(&self, v1: f64, v2: f64) -> (f64, f64) {
        let (dh, dl) = two_sum(v2, -v1);
        let a = plus_times(v1, self.k2, dh, dl);
        if self.sticks {
            return (a, a);
        }
        (a, plus_times(v2, -self.k1, dh, dl))
    }
}

/// `v + k (dh + dl)` rounded once: `v + k.hi dh` split error-free (TwoProduct, TwoSum), the
/// cross terms `k.hi dl + k.lo dh` added to the errors, one final rounding. Fewer
/// renormalisations than double-double arithmetic, the same result (Ogita, Rump & Oishi 2005).
#[inline(always)]
fn plus_times(v: f64, k: Dd, dh: f64, dl: f64) -> f64 {
    let (p, pe) = two_prod(k.hi, dh);
    let (s, se) = two_sum(v, p);
    s + (se + (pe + k.hi.mul_add(dl, k.lo * dh)))
}

/// The first `s >= 0` at which a gap `d0 + r s + (a/2) s^2` closes (`d0 >= 0`), if it ever does;
/// `approach` says whether the bodies approach now by the rule of [`closing`] (used when `a = 0`).
/// Roots in the stable forms `2 d0 / (-r + sqrt(r^2 - 2 a d0))` and `(r + sqrt(...)) / -a`
/// (no cancellation), with `r^2 - 2 a d0` formed without overflow. A gap that closes later
/// than binary64 can count gives an infinite `s`: it does close (a horizon), unlike `None`.
pub fn first_contact(d0: f64, r: f64, a: f64, approach: bool) -> Option<f64> {
    let d0 = d0.max(0.0);
    if a == 0.0 {
        return approach.then(|| d0 / -r).filter(|s| !s.is_nan());
    }
    // sqrt(2 |a| d0) without overflow.
    let q = (std::f64::consts::SQRT_2 * a.abs().sqrt()) * d0.sqrt();
    let s = if a < 0.0 {
        // The gap's acceleration closes it: it always closes.
        let root = libm::hypot(r, q);
        if r <= 0.0 {
            2.0 * d0 / (root - r)
        } else {
            (r + root) / -a
        }
    } else {
        // The gap's acceleration opens it: it closes only if it shrinks fast enough.
        if r >= 0.0 || -r < q {
            return None;
        }
        2.0 * d0 / (-r + ((-r - q) * (-r + q)).sqrt())
    };
    (!s.is_nan()).then_some(s)
}

/// Allowed rounding in a gap between two positions: `2^-40` (about 9e-13) of the positions'
/// magnitudes (now and at the last event) and the bodies' reach. A gap more negative than this is
/// not rounding but a broken state.
#[inline]
pub fn slack(magnitudes: f64) -> f64 {
    magnitudes * (1.0 / (1u64 << 40) as f64)
}

/// The time of an event `s` after `now`; infinite when binary64 cannot hold it (the contact
/// closes, but beyond binary64's times: the engine stops there with a horizon, it is not "no
/// collision any more").
#[inline]
pub fn event_at(now: f64, s: Option<f64>) -> Option<f64> {
    s.map(|s| now + s)
}
