//! The equations of motion of bodies on a track pushed apart by contact forces: the state is
//! `y = (u, v)`, displacements `u` of the body centres from where they were when the current
//! stretch of integration began (so tolerances apply to the motion, not to where the track's
//! origin happens to be), and velocities `v`; `u' = v`, `m v' = sum of contact forces`.
//!
//! Contacts are slots as in `collide track`: the left wall and body 1, each neighbouring pair,
//! the last body and the right wall. Only the active ones push; which ones are active changes
//! only at events, found by the integrators (`super::run`).

use crate::track::Contact;

use super::law::Law;

/// One possible contact: who, with which law, and the pair's reduced mass.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Slot {
    pub who: Contact,
    pub law: Law,
    /// `m1 m2 / (m1 + m2)`, or the body's mass against a wall.
    pub mu: f64,
    /// The overlap at which the centres meet, `(s1 + s2) / 2` (a body's centre reaches a wall
    /// at `s / 2`): an overlap this deep means one body went through the other or the wall.
    pub reach: f64,
}

/// The system for one stretch: the bodies, the slots, which slots are active, and the overlaps
/// at `u = 0`.
#[derive(Clone, Debug, PartialEq)]
pub struct System {
    pub m: Vec<f64>,
    pub slots: Vec<Slot>,
    pub active: Vec<bool>,
    /// Overlap of each slot at `u = 0`.
    pub d0: Vec<f64>,
}

impl System {
    pub fn n(&self) -> usize {
        self.m.len()
    }

    /// Overlap and its rate `(d, d')` of slot `s` at state `y`.
    #[inline]
    pub fn overlap(&self, s: usize, y: &[f64]) -> (f64, f64) {
        let n = self.n();
        let (u, v) = y.split_at(n);
        match self.slots[s].who {
            Contact::LeftWall => (self.d0[s] - u[0], -v[0]),
            Contact::Pair(i) => (self.d0[s] + (u[i] - u[i + 1]), v[i] - v[i + 1]),
            Contact::RightWall => (self.d0[s] + u[n - 1], v[n - 1]),
        }
    }

    /// `(body, sign)` pairs: the force of slot `s` pushes `body` in direction `sign`, and the
    /// overlap grows with `sign * -u[body]`... precisely: `d = d0 - sum sign * u[body]`.
    #[inline]
    fn arms(&self, s: usize) -> [(usize, f64); 2] {
        let n = self.n();
        match self.slots[s].who {
            Contact::LeftWall => [(0, 1.0), (usize::MAX, 0.0)],
            Contact::Pair(i) => [(i, -1.0), (i + 1, 1.0)],
            Contact::RightWall => [(n - 1, -1.0), (usize::MAX, 0.0)],
        }
    }

    /// `f = y'`.
    pub fn rhs(&self, y: &[f64], f: &mut [f64]) {
        let n = self.n();
        f[..n].copy_from_slice(&y[n..]);
        f[n..].iter_mut().for_each(|a| *a = 0.0);
        for s in 0..self.slots.len() {
            if !self.active[s] {
                continue;
            }
            let (d, rate) = self.overlap(s, y);
            let force = self.slots[s].law.force(d, rate);
            for (b, sign) in self.arms(s) {
                if sign != 0.0 {
                    f[n + b] += sign * force / self.m[b];
                }
            }
        }
    }

    /// `out = J w`, the Jacobian of `rhs` at `y` applied to `w`.
    pub fn jac_mul(&self, y: &[f64], w: &[f64], out: &mut [f64]) {
        let n = self.n();
        out[..n].copy_from_slice(&w[n..]);
        out[n..].iter_mut().for_each(|a| *a = 0.0);
        for s in 0..self.slots.len() {
            if !self.active[s] {
                continue;
            }
            let (d, rate) = self.overlap(s, y);
            let (kd, kr) = self.slots[s].law.slopes(d, rate);
            // d and d' as the same linear form of (u, v): d = d0 - sum sign u, d' = -sum sign v.
            let arms = self.arms(s);
            let (mut dd, mut dr) = (0.0, 0.0);
            for (b, sign) in arms {
                if sign != 0.0 {
                    dd -= sign * w[b];
                    dr -= sign * w[n + b];
                }
            }
            let df = kd * dd + kr * dr;
            for (b, sign) in arms {
                if sign != 0.0 {
                    out[n + b] += sign * df / self.m[b];
                }
            }
        }
    }

    /// The Jacobian as a dense matrix (row-major `2n x 2n`).
    pub fn jacobian(&self, y: &[f64]) -> nalgebra::DMatrix<f64> {
        let k = y.len();
        let mut j = nalgebra::DMatrix::zeros(k, k);
        let mut w = vec![0.0; k];
        let mut col = vec![0.0; k];
        for c in 0..k {
            w[c] = 1.0;
            self.jac_mul(y, &w, &mut col);
            w[c] = 0.0;
            for r in 0..k {
                j[(r, c)] = col[r];
            }
        }
        j
    }

    /// The event function of slot `s`: positive exactly when the contact pushes.
    #[inline]
    pub fn gate(&self, s: usize, y: &[f64]) -> f64 {
        let (d, rate) = self.overlap(s, y);
        self.slots[s].law.gate(d, rate)
    }

    /// Kinetic energy `sum (m v) v / 2` plus the elastic energy of the active contacts.
    pub fn energy(&self, y: &[f64]) -> f64 {
        let n = self.n();
        let kinetic: f64 = self
            .m
            .iter()
            .zip(&y[n..])
            .map(|(m, v)| 0.5 * (m * v) * v)
            .sum();
        let elastic: f64 = (0..self.slots.len())
            .filter(|&s| self.active[s])
            .map(|s| self.slots[s].law.potential(self.overlap(s, y).0))
            .sum();
        kinetic + elastic
    }
}
