//! Pi billiards (Galperin 2003): the count of collisions a block makes between a wall and a
//! heavier block, exact for any mass ratio, against the simulation.

use dashu_float::FBig;
use dashu_float::round::mode::HalfEven;
use num_traits::One;

use crate::values::rational::{IBig, Q, UBig};
use serde::Serialize;

use super::{Run, Stop, Track};

/// A binary arbitrary-precision float, correctly rounded (to nearest, ties to even) in every
/// operation, `sqrt`, `atan` and `pi` included (dashu-float).
type Big = FBig<HalfEven, 2>;

fn big(n: impl Into<IBig>, bits: usize) -> Big {
    Big::from(n.into()).with_precision(bits).value()
}

/// Pi billiards (Galperin 2003): a block of mass `m` at rest between a wall and a block of mass
/// `M` moving toward it makes `ceil(pi / theta) - 1` collisions, `theta = atan(sqrt(m / M))`,
/// exactly (from the exact masses):
/// - `pi / theta` is a whole number only for `m / M` in {3, 1, 1/3} (theta = pi/3, pi/4, pi/6:
///   `tan^2(pi/k)` is rational only for k = 3, 4, 6), which are decided exactly: 2, 3, 5;
/// - otherwise `pi / theta` is evaluated at `p` bits with five correctly rounded operations
///   (relative error below `5 * 2^-p`, under 8 ulps), and `p` doubles from 128 until the ceiling
///   is the same at both ends of that interval.
pub fn pi_count(m: &Q, big_m: &Q) -> UBig {
    let r = m / big_m;
    let third = crate::values::rational::ratio(1, 3);
    for (q, k) in [
        (crate::values::rational::int(3), 2u32),
        (Q::one(), 3),
        (third, 5),
    ] {
        if r == q {
            return UBig::from(k);
        }
    }
    let mut bits = 128;
    loop {
        let ratio = big(r.numerator().clone(), bits) / big(r.denominator().clone(), bits);
        let theta = ratio.sqrt().atan();
        let q = Big::pi(bits) / theta;
        let err = q.ulp() * 8u8;
        let (lo, hi) = ((&q - &err).ceil(), (&q + &err).ceil());
        if lo == hi {
            let count = lo.to_int().value() - IBig::ONE;
            return UBig::try_from(count).unwrap_or_default();
        }
        bits *= 2;
    }
}

/// `atan(sqrt(m / M))` in binary64.
pub fn pi_theta(m: &Q, big_m: &Q) -> f64 {
    let r = m / big_m;
    let bits = 64;
    let ratio = big(r.numerator().clone(), bits) / big(r.denominator().clone(), bits);
    ratio.sqrt().atan().to_f64().value()
}

/// Pi billiards' theoretical count, when a run is that experiment.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct PiTheory {
    /// `ceil(pi / theta) - 1`, as decimal digits (exact at any size).
    pub theory: String,
    /// `atan(sqrt(m1 / m2))`.
    pub theta: f64,
    /// Whether the simulation made exactly that many collisions; absent when the run did not
    /// end by itself (a cap or `--until` stopped it), so there is nothing to compare.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub agrees: Option<bool>,
}

/// `collide track`'s output: the run, and the pi-billiards theory when it applies.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct TrackReport {
    #[serde(flatten)]
    pub run: Run,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub pi: Option<PiTheory>,
}

impl TrackReport {
    pub fn new(track: &Track, run: Run) -> TrackReport {
        let pi = track.pi_masses().map(|(m, big_m)| {
            let theory = pi_count(&m, &big_m);
            let agrees = (run.stop == Stop::Done).then(|| UBig::from(run.collisions) == theory);
            PiTheory {
                theory: theory.to_string(),
                theta: pi_theta(&m, &big_m),
                agrees,
            }
        });
        TrackReport { run, pi }
    }
}

impl Track {
    /// The masses `(m, M)` if the track is pi billiards: block 1 at rest between a left wall and
    /// block 2 moving toward it, elastic, no gravity, no right wall.
    pub fn pi_masses(&self) -> Option<(Q, Q)> {
        let b = &self.bodies;
        let is_pi = b.len() == 2
            && self.left_wall.is_some()
            && self.right_wall.is_none()
            && self.gravity == 0.0
            && self.e == 1.0
            && self.e_wall == 1.0
            && b[0].v == 0.0
            && b[1].v < 0.0;
        is_pi.then(|| (b[0].m.number().exact(), b[1].m.number().exact()))
    }
}

/// The first `n + 1` digits of the count for the mass ratio `100^n` (which are the first `n + 1`
/// digits of pi), as `collide pi N` gives them.
pub fn pi_digits(n: u32) -> UBig {
    let big_m = Q::from(UBig::from(100u8).pow(n as usize));
    pi_count(&Q::one(), &big_m)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Pi to 60 decimals (OEIS A000796).
    const PI: &str = "3141592653589793238462643383279502884197169399375105820974944";

    #[test]
    fn counts_for_mass_ratios_100_to_the_n_are_the_digits_of_pi() {
        for n in 0..=50u32 {
            assert_eq!(pi_digits(n).to_string(), PI[..n as usize + 1], "N = {n}");
        }
    }

    #[test]
    fn whole_multiple_ratios_are_exact() {
        let q = crate::values::rational::ratio;
        assert_eq!(pi_count(&q(1, 1), &q(1, 1)), UBig::from(3u8));
        assert_eq!(pi_count(&q(1, 1), &q(3, 1)), UBig::from(5u8));
        assert_eq!(pi_count(&q(3, 1), &q(1, 1)), UBig::from(2u8));
        assert_eq!(pi_count(&q(1, 10), &q(3, 10)), UBig::from(5u8));
        // Near a whole multiple the count is the one of the neighbouring angle: theta just above
        // pi/4 (m slightly larger than M) gives pi/theta just below 4: ceil 4, count 3; just
        // below pi/4 gives pi/theta just above 4: count 4.
        let near = q(1_000_000_000_000_000_001, 1_000_000_000_000_000_000);
        assert_eq!(pi_count(&near, &q(1, 1)), UBig::from(3u8));
        assert_eq!(pi_count(&q(1, 1), &near), UBig::from(4u8));
    }
}
