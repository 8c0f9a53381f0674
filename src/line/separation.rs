//! Two bodies under momentum alone (issue 15, issue 27 §1): bodies that start together and are
//! pushed apart (an explosion, a recoil, a released spring), or one body passing through the
//! other (a bullet through a block). Restitution says nothing (`e` is undefined, or no law), and
//! only momentum holds: `m1 v1 + m2 v2 = m1 f1 + m2 f2`. By Koenig's theorem (lecture Sec. 2) the
//! centre of mass keeps `KE_COM`, and the kinetic energy of the relative motion changes from
//! `1/2 mu (v1 - v2)^2` to `1/2 mu (f1 - f2)^2`, `mu = m1 m2 / (m1 + m2)`: a separation releases
//! `1/2 mu (f1 - f2)^2`; a pass-through loses `1/2 mu (d_in - d_fin)(d_in + d_fin)` in the two
//! bodies, with `d = v1 - v2` (a product, never a difference of two energies). Everything is
//! exact: the values come from the solved problem.

use crate::values::rational::{Q, half};

use crate::line::changes::{Changes, Event};
use crate::values::number::Number;
use crate::values::units::Units;

/// Which event momentum alone describes.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Kind {
    /// The bodies start together (`V1 = V2`) and are pushed apart.
    #[default]
    Apart,
    /// One body passes through the other (`--pass-through`).
    PassThrough,
}

/// An event under momentum alone: a separation from a common velocity, or a pass-through.
#[derive(Clone, Debug, PartialEq)]
pub struct Separation {
    /// The masses as typed (or solved, as numbers).
    pub masses: [Number; 2],
    /// The velocities at IN, as typed (or solved); equal for `Kind::Apart`.
    pub velocities: [Number; 2],
    pub fin: [Q; 2],
    pub units: Units,
    pub kind: Kind,
}

impl Separation {
    pub fn m(&self) -> [Q; 2] {
        [self.masses[0].exact(), self.masses[1].exact()]
    }
    pub fn v_in(&self) -> [Q; 2] {
        [self.velocities[0].exact(), self.velocities[1].exact()]
    }
    pub fn total_momentum(&self) -> Q {
        let p = self.momentum(&self.v_in());
        &p[0] + &p[1]
    }
    /// `V_COM = P_total / M_total` (the common velocity, for a separation).
    pub fn v_com(&self) -> Q {
        let [m1, m2] = self.m();
        self.total_momentum() / (m1 + m2)
    }
    pub fn momentum(&self, v: &[Q; 2]) -> [Q; 2] {
        let [m1, m2] = self.m();
        [m1 * &v[0], m2 * &v[1]]
    }
    /// `mu = m1 m2 / (m1 + m2)`.
    pub fn reduced_mass(&self) -> Q {
        let [m1, m2] = self.m();
        &m1 * &m2 / (&m1 + &m2)
    }
    fn ke(&self, v: &[Q; 2]) -> Q {
        let [m1, m2] = self.m();
        half() * (m1 * &v[0] * &v[0] + m2 * &v[1] * &v[1])
    }
    /// `KE_IN` (`= KE_COM = 1/2 (m1 + m2) V^2` for a separation).
    pub fn ke_in(&self) -> Q {
        self.ke(&self.v_in())
    }
    /// `KE_COM = 1/2 V_COM P_total`.
    pub fn ke_com(&self) -> Q {
        half() * self.v_com() * self.total_momentum()
    }
    /// `KE_FIN - KE_IN = 1/2 mu (d_fin - d_in)(d_fin + d_in)`, `d = V1 - V2`: `1/2 mu (f1 -
    /// f2)^2` for a separation; negative (energy lost) for a pass-through.
    pub fn released(&self) -> Q {
        let v = self.v_in();
        let d_in = &v[0] - &v[1];
        let d_fin = &self.fin[0] - &self.fin[1];
        half() * self.reduced_mass() * (&d_fin - &d_in) * (&d_fin + &d_in)
    }
    pub fn ke_fin(&self) -> Q {
        self.ke_in() + self.released()
    }
    /// Momentum after minus before: zero for a consistent event (checked when made).
    pub fn momentum_residual(&self) -> Q {
        let p = self.momentum(&self.fin);
        &p[0] + &p[1] - self.total_momentum()
    }
    pub fn changes(&self, contact_time: Option<&Q>) -> Changes {
        let [m1, m2] = self.m();
        let zero = Q::ZERO;
        let v_in = self.v_in();
        Changes::of(
            &Event {
                tensor: [[&m1, &zero], [&zero, &m2]],
                v_in: &v_in,
                fin: &self.fin,
            },
            contact_time,
        )
    }
}

/// The two ways pieces of masses `m` moving together at `v` can part when the energy `e` is
/// released: momentum keeps the centre of mass at `v`, and `1/2 mu d^2 = e` fixes the relative
/// speed `|d| = sqrt(2 e / mu)`, `d = f1 - f2`, but not its sign. `f1 = v + (m2 / M) d`,
/// `f2 = v - (m1 / M) d`; first body 1 on the left (`d < 0`), then on the right. Exact when
/// `2 e / mu` is a rational square; otherwise `Err` with it when `exact`, else `d` is its
/// root within an ulp (`rational::sqrt_binary64`, scaled: whatever the size of `2 e / mu`),
/// and the velocities follow from that `d` exactly.
pub fn split(m: [&Q; 2], v: &Q, e: &Q, exact: bool) -> Result<[[Q; 2]; 2], Q> {
    let total = m[0] + m[1];
    let mu = m[0] * m[1] / &total;
    let square = Q::from(2) * e / &mu;
    let d = match crate::values::rational::sqrt_exact(&square) {
        Some(d) => d,
        None if exact => return Err(square),
        None => crate::values::rational::sqrt_binary64(&square),
    };
    let fin = |d: &Q| [v + m[1] / &total * d, v - m[0] / &total * d];
    Ok([fin(&-&d), fin(&d)])
}

#[cfg(test)]
mod tests {
    use super::*;

    fn n(s: &str) -> Number {
        s.parse().unwrap()
    }

    #[test]
    fn recoil_from_rest_by_hand() {
        // A clown of 80 kg pushes off a 4 kg barbell: -0.5 and 10 m/s; 1/2 80 0.25 + 1/2 4 100.
        let s = Separation {
            masses: [n("80"), n("4")],
            velocities: [n("0"), n("0")],
            fin: [n("-0.5").exact(), n("10").exact()],
            units: Units::default(),
            kind: Kind::Apart,
        };
        assert_eq!(s.momentum_residual(), Q::ZERO);
        assert_eq!(s.released(), n("210").exact());
        assert_eq!(s.ke_fin(), n("210").exact());
        let c = s.changes(None);
        assert_eq!(c.impulse, [n("-40").exact(), n("40").exact()]);
        assert_eq!(c.lost_fraction, None);
    }

    #[test]
    fn the_energy_fixes_the_relative_speed_not_its_sign() {
        // Cutnell & Johnson 7.51 read backwards: stages of 1200 and 2400 kg at 4900 m/s part
        // with 5.76e8 J: mu = 800, d^2 = 2 5.76e8 / 800 = 1.44e6, d = 1200; the upper stage
        // (body 1) at 4900 +- (2/3) 1200 = 5700 or 4100, the lower at 4900 -+ 400.
        let q = |s: &str| n(s).exact();
        let [left, right] =
            split([&q("1200"), &q("2400")], &q("4900"), &q("5.76e8"), true).unwrap();
        assert_eq!(left, [q("4100"), q("5300")]);
        assert_eq!(right, [q("5700"), q("4500")]);
        // 1 and 2 kg from rest given 48 J: mu = 2/3, d^2 = 144: (-8, 4) or (8, -4).
        let [left, right] = split([&q("1"), &q("2")], &q("0"), &q("48"), true).unwrap();
        assert_eq!((left, right), ([q("-8"), q("4")], [q("8"), q("-4")]));
        // 2 and 3 kg given 7500 J: d^2 = 2 7500 / (6/5) = 12500, irrational: refused exactly,
        // else d = sqrt(12500) = 111.803398874989... to an ulp.
        assert_eq!(
            split([&q("2"), &q("3")], &q("0"), &q("7500"), true),
            Err(q("12500"))
        );
        let [_, right] = split([&q("2"), &q("3")], &q("0"), &q("7500"), false).unwrap();
        let d = crate::values::rational::to_f64(&(&right[0] - &right[1])).unwrap();
        assert_eq!(d, 12500f64.sqrt());
    }

    #[test]
    fn a_bullet_through_a_block_by_hand() {
        // Serway & Jewett: 5.00 g at 400 m/s through a 1.00 kg block at rest; out at 100 m/s,
        // the block at 1.5 m/s. KE_IN = 1/2 0.005 160000 = 400 J; KE_FIN = 1/2 0.005 10000 +
        // 1/2 1 2.25 = 25 + 1.125; lost 373.875 J = 2991/8 (published: 374 J). By the product:
        // mu = 0.005/1.005 = 1/201, d_in = 400, d_fin = 98.5: 1/2 (1/201) 301.5 498.5 = 2991/8.
        let s = Separation {
            masses: [n("0.005"), n("1")],
            velocities: [n("400"), n("0")],
            fin: [n("100").exact(), n("1.5").exact()],
            units: Units::default(),
            kind: Kind::PassThrough,
        };
        assert_eq!(s.momentum_residual(), Q::ZERO);
        assert_eq!(s.released(), -n("2991/8").exact());
        assert_eq!(s.ke_fin(), n("26.125").exact());
        // V_COM = 2 / 1.005 = 400/201; KE_COM = 1/2 V_COM P_total = 400/201.
        assert_eq!(s.v_com(), n("400/201").exact());
        assert_eq!(s.ke_com(), n("400/201").exact());
    }
}
