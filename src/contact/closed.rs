//! Closed forms for a single contact of a pair with reduced mass `mu` hit at relative speed `v`
//! (a body against a wall: its own mass), with the force-zero end of contact.
//!
//! Linear spring-dashpot `F = k d + c d'`, damping ratio `zeta = c / (2 sqrt(k mu))`,
//! `omega0 = sqrt(k/mu)`, `beta = zeta omega0` (T. Schwager, T. Poeschel, Granular Matter 9
//! (2007) 465, eqs. 9-16, rewritten with `acos`/`artanh` so that they stay accurate near
//! `zeta = 1`):
//! - `zeta < 1`: `omega = omega0 sqrt(1 - zeta^2)`,
//!   `t_c = (pi - 2 atan(beta/omega)) / omega = 2 acos(zeta) / omega`;
//! - `zeta > 1`: `w = omega0 sqrt(zeta^2 - 1)`, `t_c = 2 artanh(w/beta) / w`, evaluated as
//!   `2 ln(zeta + sqrt(zeta^2 - 1)) / w` (the same number, without cancellation at large `zeta`);
//! - `zeta = 1`: `t_c = 2 / omega0`;
//! - in every case `e = exp(-beta t_c)`, the deepest overlap comes at `t_c / 2` and is
//!   `d_max = (v / omega0) exp(-beta t_c / 2) = (v / omega0) sqrt(e)`.
//!
//! Hertz `F = k d^(3/2)` (energy `2/5 k d^(5/2)`): `d_max = (5 mu v^2 / (4 k))^(2/5)` and
//! `t_c = C d_max / v` with `C = 2 int_0^1 (1 - x^(5/2))^(-1/2) dx = (4/5) sqrt(pi)
//! Gamma(2/5) / Gamma(9/10)` (L. D. Landau, E. M. Lifshitz, *Theory of Elasticity*, section 9,
//! problem 1; with material constants `t_c = 2.8683 (mu^2 / (R* E*^2 v))^(1/5)`).

/// `(4/5) sqrt(pi) Gamma(2/5) / Gamma(9/10)` = 2.943275184324704657... (computed to 30 digits
/// with mpmath; `tests` checks it against a quadrature of the integral).
pub const HERTZ_TIME: f64 = 2.943_275_184_324_704_7;

/// A linear spring-dashpot contact: `omega0 = sqrt(k/mu)` and the damping ratio.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Linear {
    pub omega0: f64,
    pub zeta: f64,
}

impl Linear {
    /// From the law's constants and the pair's reduced mass. `zeta = c / (2 sqrt(k) sqrt(mu))`
    /// with the roots taken apart, so a tiny `k mu` (5e-324 x 0.5 rounds to 0) gives a tiny
    /// root, not 0 and a NaN ratio; no damping is `zeta = 0` exactly.
    pub fn new(k: f64, c: f64, mu: f64) -> Linear {
        Linear {
            omega0: (k / mu).sqrt(),
            zeta: if c == 0.0 {
                0.0
            } else {
                c / (2.0 * k.sqrt() * mu.sqrt())
            },
        }
    }

    /// `omega0 t_c`, the contact time in units of `1/omega0`.
    pub fn scaled_contact_time(zeta: f64) -> f64 {
        if zeta < 1.0 {
            2.0 * zeta.acos() / ((1.0 - zeta) * (1.0 + zeta)).sqrt()
        } else if zeta == 1.0 {
            2.0
        } else if zeta < 1e150 {
            // artanh(s / zeta) = ln(zeta + s), since (zeta - s)(zeta + s) = 1: no cancellation
            // in 1 - s/zeta when zeta is large.
            let s = ((zeta - 1.0) * (zeta + 1.0)).sqrt();
            2.0 * ((zeta - 1.0) + s).ln_1p() / s
        } else {
            // (zeta - 1)(zeta + 1) would overflow from 1.3e154 (and made this NaN): here s =
            // zeta and zeta + s = 2 zeta, each to a relative 1/(2 zeta^2), far below an ulp.
            2.0 * (std::f64::consts::LN_2 + zeta.ln()) / zeta
        }
    }

    /// The contact time `t_c`.
    pub fn contact_time(&self) -> f64 {
        Self::scaled_contact_time(self.zeta) / self.omega0
    }

    /// `e = exp(-zeta omega0 t_c)`, which depends on `zeta` only.
    pub fn restitution_of(zeta: f64) -> f64 {
        (-zeta * Self::scaled_contact_time(zeta)).exp()
    }

    pub fn restitution(&self) -> f64 {
        Self::restitution_of(self.zeta)
    }

    /// The deepest overlap for an impact at relative speed `v`: `(v / omega0) sqrt(e)`.
    pub fn max_overlap(&self, v: f64) -> f64 {
        v / self.omega0 * self.restitution().sqrt()
    }

    /// The damping ratio that gives restitution `e` in (0, 1]: the root of `e(zeta) = e`, which
    /// falls monotonically from 1 at `zeta = 0` toward 0, found by bisection to the last bit.
    /// `None` for `e` outside (0, 1] (sticking, `e = 0`, would need infinite damping).
    pub fn zeta_for(e: f64) -> Option<f64> {
        if !(e > 0.0 && e <= 1.0) {
            return None;
        }
        if e == 1.0 {
            return Some(0.0);
        }
        // ln(1/e) = zeta omega0 t_c(zeta), increasing in zeta.
        let target = -e.ln();
        let g = |z: f64| z * Self::scaled_contact_time(z);
        let (mut lo, mut hi) = (0.0f64, 1.0f64);
        while g(hi) < target {
            hi *= 2.0;
            if hi > 1e300 {
                return None;
            }
        }
        for _ in 0..2000 {
            let mid = 0.5 * (lo + hi);
            if mid <= lo || mid >= hi {
                break;
            }
            if g(mid) < target {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        // The end whose restitution is nearer.
        let miss = |z: f64| (Self::restitution_of(z) - e).abs();
        Some(if miss(lo) <= miss(hi) { lo } else { hi })
    }

    /// The damping coefficient `c = 2 zeta sqrt(k) sqrt(mu)` (the inverse of `new`'s `zeta`).
    pub fn damping(k: f64, mu: f64, zeta: f64) -> f64 {
        2.0 * zeta * (k.sqrt() * mu.sqrt())
    }
}

/// Hertz: `d_max = (5 mu v^2 / (4 k))^(2/5)`.
pub fn hertz_max_overlap(k: f64, mu: f64, v: f64) -> f64 {
    (1.25 * mu * v * v / k).powf(0.4)
}

/// Hertz: `t_c = C d_max / v`.
pub fn hertz_contact_time(k: f64, mu: f64, v: f64) -> f64 {
    HERTZ_TIME * hertz_max_overlap(k, mu, v) / v
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    #[test]
    fn the_issue_numbers_at_zeta_0_2() {
        // e = 0.5717400276, omega0 t_c = 2.7953544 (issue 14); 30 digits from mpmath:
        // 0.571740027584776825..., 2.795354440734607805...
        let c = Linear {
            omega0: 1.0,
            zeta: 0.2,
        };
        assert!((c.restitution() - 0.571_740_027_584_776_8).abs() < 1e-15);
        assert!((c.contact_time() - 2.795_354_440_734_607_8).abs() < 1e-14);
        // pi - 2 atan(beta/omega) over omega, the textbook form, agrees.
        let w = (1.0f64 - 0.04).sqrt();
        let textbook = (PI - 2.0 * (0.2 / w).atan()) / w;
        assert!((c.contact_time() - textbook).abs() < 1e-14);
    }

    /// The contact time and deepest overlap in units: a spring of k = 4 N/m on mu = 1 kg has
    /// omega0 = 2 /s; undamped, t_c = pi / omega0 = pi/2 s and d_max = v / omega0 (e = 1): 1.5 m
    /// at 3 m/s. At zeta = 0.2, both scale as 1/omega0 from the issue's numbers (the test
    /// above).
    #[test]
    fn contact_time_and_overlap_scale_with_omega0() {
        let c = Linear::new(4.0, 0.0, 1.0);
        assert_eq!(c.omega0, 2.0);
        assert_eq!(c.contact_time(), PI / 2.0);
        assert_eq!(c.max_overlap(3.0), 1.5);
        let c = Linear {
            omega0: 2.0,
            zeta: 0.2,
        };
        assert!((c.contact_time() - 2.795_354_440_734_607_8 / 2.0).abs() < 1e-14);
        let root_e = 0.571_740_027_584_776_8f64.sqrt();
        assert!((c.max_overlap(3.0) - 1.5 * root_e).abs() < 1e-15);
    }

    /// Hertz's deepest overlap `(5 mu v^2 / (4 k))^(2/5)` with numbers chosen so that the
    /// power is exact: mu = 1 kg, v = 4 m/s, k = 0.625 N/m^1.5 give 5/4 * 16 / 0.625 = 32 and
    /// 32^(2/5) = 4 m; the contact time is `HERTZ_TIME d_max / v` = HERTZ_TIME s.
    #[test]
    fn hertz_overlap_and_time_by_hand() {
        let d = hertz_max_overlap(0.625, 1.0, 4.0);
        assert!((d - 4.0).abs() <= 2.0 * 4.0 * f64::EPSILON, "{d}");
        let t = hertz_contact_time(0.625, 1.0, 4.0);
        assert!(
            (t - HERTZ_TIME).abs() <= 4.0 * HERTZ_TIME * f64::EPSILON,
            "{t}"
        );
        // Scaling: d ~ (mu v^2 / k)^(2/5): 32 times the mass, 32^(2/5) = 4 times as deep.
        let deeper = hertz_max_overlap(0.625, 32.0, 4.0);
        assert!(
            (deeper - 16.0).abs() <= 2.0 * 16.0 * f64::EPSILON,
            "{deeper}"
        );
    }

    #[test]
    fn continuous_through_critical_damping() {
        for z in [1.0 - 1e-9, 1.0, 1.0 + 1e-9] {
            let t = Linear::scaled_contact_time(z);
            assert!((t - 2.0).abs() < 1e-8, "zeta {z}: {t}");
        }
        assert!((Linear::restitution_of(1.0) - (-2.0f64).exp()).abs() < 1e-16);
    }

    /// Overdamped to the top of binary64: omega0 t_c = 2 ln(zeta + s) / s with s the square
    /// root of zeta^2 less 1, which is 2 ln(2 zeta) / zeta once zeta^2 is beyond reach (from
    /// 1.3e154 it overflowed, and t_c and e were NaN); the two forms meet at 1e150. So e =
    /// exp(-2 ln(2 zeta)) = 1 / (4 zeta^2): 2.5e-321 (subnormal) at 1e160, 0 at 1e200 and at
    /// the largest zeta.
    #[test]
    fn heavily_overdamped_contacts_stay_finite() {
        let by_hand = |z: f64| 2.0 * (2.0 * z).ln() / z;
        for z in [1e149, 1e151, 1e160, 1e200, 1e300] {
            let t = Linear::scaled_contact_time(z);
            assert!(
                (t - by_hand(z)).abs() <= 4.0 * f64::EPSILON * t,
                "zeta {z}: {t}"
            );
        }
        let below = Linear::scaled_contact_time(1e150 * (1.0 - f64::EPSILON));
        let above = Linear::scaled_contact_time(1e150);
        assert!((below - above).abs() <= 4.0 * f64::EPSILON * above);
        let e = Linear::restitution_of(1e160);
        assert!((e - 2.5e-321).abs() <= 1e-323, "{e}");
        assert_eq!(Linear::restitution_of(1e200), 0.0);
        assert_eq!(Linear::restitution_of(f64::MAX), 0.0);
    }

    #[test]
    fn zeta_from_e_round_trips() {
        for e in [
            1.0,
            0.999999,
            0.9,
            0.5717400275847768,
            0.5,
            0.2,
            (-2.0f64).exp(),
            0.05,
            1e-6,
        ] {
            let z = Linear::zeta_for(e).unwrap();
            let back = Linear::restitution_of(z);
            assert!(
                (back - e).abs() <= 4.0 * f64::EPSILON * e,
                "e {e}: zeta {z} gives {back}"
            );
        }
        assert!((Linear::zeta_for(0.5717400275847768).unwrap() - 0.2).abs() < 1e-14);
        assert_eq!(Linear::zeta_for(0.0), None);
        assert_eq!(Linear::zeta_for(1.5), None);
    }

    #[test]
    fn hertz_constant_is_the_integral() {
        // 2 int_0^1 (1 - x^(5/2))^(-1/2) dx, with x = 1 - s^2 to remove the end singularity:
        // = 4 int_0^1 s (1 - (1 - s^2)^(5/2))^(-1/2) ds, Gauss-Legendre on many panels.
        let f = |s: f64| {
            let x = 1.0 - s * s;
            let g = 1.0 - x * x * x.sqrt();
            if g <= 0.0 { 0.0 } else { 4.0 * s / g.sqrt() }
        };
        let (nodes, weights) = (
            [
                -0.906_179_845_938_664,
                -0.538_469_310_105_683,
                0.0,
                0.538_469_310_105_683,
                0.906_179_845_938_664,
            ],
            [
                0.236_926_885_056_189,
                0.478_628_670_499_366,
                0.568_888_888_888_889,
                0.478_628_670_499_366,
                0.236_926_885_056_189,
            ],
        );
        let panels = 2000;
        let mut sum = 0.0;
        for p in 0..panels {
            let (a, b) = (p as f64 / panels as f64, (p + 1) as f64 / panels as f64);
            for (x, w) in nodes.iter().zip(weights) {
                sum += w * (b - a) / 2.0 * f(a + (b - a) * (x + 1.0) / 2.0);
            }
        }
        assert!((sum - HERTZ_TIME).abs() < 1e-10, "{sum}");
    }
}
