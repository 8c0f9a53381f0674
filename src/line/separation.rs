//! Two bodies that start together and are pushed apart: an explosion, a recoil, a released spring
//! (issue 15). With no relative velocity at IN (`V1 = V2`) restitution says nothing (`e` is
//! undefined), and only momentum holds: `m1 V + m2 V = m1 f1 + m2 f2`. The energy released is
//! the kinetic energy of the relative motion after, by Koenig's theorem (lecture Sec. 2):
//! `KE_FIN - KE_IN = 1/2 mu (f1 - f2)^2` with `mu = m1 m2 / (m1 + m2)`, since the centre of mass
//! keeps `KE_COM = KE_IN`. Everything is exact: the values come from the solved problem.

use crate::values::rational::{Q, half};

use crate::line::changes::{Changes, Event};
use crate::values::number::Number;
use crate::values::units::Units;

/// A separation from a common velocity.
#[derive(Clone, Debug, PartialEq)]
pub struct Separation {
    /// The masses as typed (or solved, as numbers).
    pub masses: [Number; 2],
    /// The common velocity at IN, as typed.
    pub velocities: [Number; 2],
    pub fin: [Q; 2],
    pub units: Units,
}

impl Separation {
    pub fn m(&self) -> [Q; 2] {
        [self.masses[0].exact(), self.masses[1].exact()]
    }
    /// The common velocity `V = V1 = V2`.
    pub fn v(&self) -> Q {
        self.velocities[0].exact()
    }
    pub fn v_in(&self) -> [Q; 2] {
        [self.v(), self.v()]
    }
    pub fn total_momentum(&self) -> Q {
        let [m1, m2] = self.m();
        (m1 + m2) * self.v()
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
    /// `KE_IN = KE_COM = 1/2 (m1 + m2) V^2`.
    pub fn ke_in(&self) -> Q {
        let [m1, m2] = self.m();
        half() * (m1 + m2) * self.v() * self.v()
    }
    /// `1/2 mu (f1 - f2)^2`.
    pub fn released(&self) -> Q {
        let d = &self.fin[0] - &self.fin[1];
        half() * self.reduced_mass() * &d * &d
    }
    pub fn ke_fin(&self) -> Q {
        self.ke_in() + self.released()
    }
    /// Momentum after minus before: zero for a consistent separation (checked when made).
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
        };
        assert_eq!(s.momentum_residual(), Q::ZERO);
        assert_eq!(s.released(), n("210").exact());
        assert_eq!(s.ke_fin(), n("210").exact());
        let c = s.changes(None);
        assert_eq!(c.impulse, [n("-40").exact(), n("40").exact()]);
        assert_eq!(c.lost_fraction, None);
    }
}
