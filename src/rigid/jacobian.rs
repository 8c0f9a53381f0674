//! The contact Jacobian and the collision matrix (physics.md section 7; Stronge, *Impact
//! Mechanics*, ch. 5; Mirtich 1996). A contact at point `c` with normal `n` (from body 1 to body
//! 2, any length) has the relative velocity `w = J1 u1 - J2 u2` of the two material points at
//! `c`, with `J_i` each body's point Jacobian; its normal row is `J_n = n^T [J1, -J2]` and its
//! tangent rows `J_t` likewise. An impulse `P` on body 2 (and `-P` on body 1) changes
//! `u2` by `M2^-1 J2^T P` and `u1` by `-M1^-1 J1^T P`, so `w` changes by `-K P` with the collision
//! matrix `K = J M^-1 J^T = sum_i J_i M_i^-1 J_i^T` (`dim x dim`, symmetric, positive
//! semidefinite). Along the unit normal `1/K_nn` is the effective mass:
//! `(1/m1 + 1/m2 + (r1 x n).I1^-1.(r1 x n) + (r2 x n).I2^-1.(r2 x n))^-1` for free bodies.

use crate::values::rational::Q;

use super::algebra::{self, Mat, apply, dot, mul, transpose};
use super::body::{Body, Motion};

/// The point and line of a contact.
#[derive(Clone, Debug, PartialEq)]
pub struct Contact {
    pub point: Vec<Q>,
    /// From body 1 to body 2, any length.
    pub normal: Vec<Q>,
}

/// Two bodies touching at a contact.
#[derive(Clone, Debug, PartialEq)]
pub struct Pair {
    pub bodies: [Body; 2],
    pub contact: Contact,
}

impl Pair {
    pub fn dim(&self) -> usize {
        self.contact.point.len()
    }

    /// Each body's point Jacobian at the contact.
    pub fn jacobians(&self) -> [Mat; 2] {
        let c = &self.contact.point;
        [
            self.bodies[0].point_jacobian(c),
            self.bodies[1].point_jacobian(c),
        ]
    }

    /// `J_i M_i^-1 J_i^T`: body `i`'s share of the collision matrix.
    pub fn share(&self, i: usize) -> Mat {
        let j = &self.jacobians()[i];
        let b = &self.bodies[i];
        if b.coordinates() == 0 {
            return algebra::diag(self.dim(), &Q::ZERO);
        }
        mul(&mul(j, b.inverse()), &transpose(j))
    }

    /// The collision matrix `K = J M^-1 J^T`.
    pub fn collision_matrix(&self) -> Mat {
        algebra::add_mat(&self.share(0), &self.share(1))
    }

    /// `a^T K b`.
    pub fn k(&self, a: &[Q], b: &[Q]) -> Q {
        dot(a, &apply(&self.collision_matrix(), b))
    }

    /// The relative velocity of the material points at the contact, `w = J1 u1 - J2 u2`.
    pub fn relative_velocity(&self, motions: &[Motion; 2]) -> Vec<Q> {
        let [j1, j2] = self.jacobians();
        let u1 = self.bodies[0].u(&motions[0]);
        let u2 = self.bodies[1].u(&motions[1]);
        let p1 = if u1.is_empty() {
            vec![Q::ZERO; self.dim()]
        } else {
            apply(&j1, &u1)
        };
        let p2 = if u2.is_empty() {
            vec![Q::ZERO; self.dim()]
        } else {
            apply(&j2, &u2)
        };
        algebra::sub(&p1, &p2)
    }

    /// The velocity of body `i`'s material point at the contact.
    pub fn point_velocity(&self, i: usize, m: &Motion) -> Vec<Q> {
        let u = self.bodies[i].u(m);
        if u.is_empty() {
            return vec![Q::ZERO; self.dim()];
        }
        apply(&self.jacobians()[i], &u)
    }

    /// The row `d^T [J1, -J2]` over every generalized coordinate (body 1's, then body 2's).
    pub fn row(&self, d: &[Q]) -> Vec<Q> {
        let [j1, j2] = self.jacobians();
        let along = |j: &Mat| -> Vec<Q> {
            let t = transpose(j);
            t.iter().map(|col| dot(col, d)).collect()
        };
        let mut r = along(&j1);
        r.extend(along(&j2).into_iter().map(|x| -x));
        r
    }

    /// The motions after an impulse `p` on body 2 (and `-p` on body 1).
    pub fn apply_impulse(&self, motions: &[Motion; 2], p: &[Q]) -> [Motion; 2] {
        let jac = self.jacobians();
        let one = |i: usize, sign: Q| -> Motion {
            let b = &self.bodies[i];
            if b.coordinates() == 0 {
                return motions[i].clone();
            }
            let du = apply(b.inverse(), &apply(&transpose(&jac[i]), p));
            let u: Vec<Q> = b
                .u(&motions[i])
                .iter()
                .zip(&du)
                .map(|(x, d)| x + &sign * d)
                .collect();
            b.motion(&u)
        };
        [one(0, -Q::ONE), one(1, Q::ONE)]
    }

    /// The tangent of the plane, `t = (-n_y, n_x)`: `n` turned a quarter counterclockwise,
    /// of the same length.
    pub fn tangent(&self) -> Vec<Q> {
        let n = &self.contact.normal;
        vec![-n[1].clone(), n[0].clone()]
    }

    /// The effective mass along the unit normal, `1/K_nn = n.n / (n^T K n)` (`None` when
    /// neither body can move along the normal).
    pub fn effective_mass(&self) -> Option<Q> {
        let n = &self.contact.normal;
        let knn = self.k(n, n);
        (knn > Q::ZERO).then(|| dot(n, n) / knn)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rigid::body::Mobility;
    use crate::values::rational::{int, ratio};

    /// A free uniform rod (mass M, length L, along y, centre at the origin) and a particle
    /// (mass m) hitting it at height b along x.
    fn ball_and_rod(m: Q, big_m: Q, l: Q, b: Q) -> Pair {
        let i = big_m.clone() * &l * &l * ratio(1, 12);
        Pair {
            bodies: [
                Body::new(
                    1,
                    Some(m),
                    vec![int(-1), b.clone()],
                    Mobility::Free { inertia: None },
                    None,
                )
                .unwrap(),
                Body::new(
                    2,
                    Some(big_m),
                    vec![int(0), int(0)],
                    Mobility::Free {
                        inertia: Some(vec![vec![i]]),
                    },
                    None,
                )
                .unwrap(),
            ],
            contact: Contact {
                point: vec![int(0), b],
                normal: vec![int(1), int(0)],
            },
        }
    }

    #[test]
    fn effective_mass_of_a_free_rod() {
        // (1/m + 1/M + 12 b^2 / (M L^2))^-1 with m = 2, M = 3, L = 2, b = 1/2:
        // 1/2 + 1/3 + 12 (1/4) / 12 = 13/12, so 12/13.
        let p = ball_and_rod(int(2), int(3), int(2), ratio(1, 2));
        assert_eq!(p.effective_mass(), Some(ratio(12, 13)));
        // The row J_n = n^T [J1, -J2] over (v1x, v1y, v2x, v2y, w2): (1, 0, -1, 0, b).
        assert_eq!(
            p.row(&[int(1), int(0)]),
            vec![int(1), int(0), int(-1), int(0), ratio(1, 2)]
        );
    }
}
