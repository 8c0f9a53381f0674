//! Bodies that join (physics.md section 8): after a `--join` impact the striking particle stays
//! at the contact point and the pair is one rigid body, of mass `M = m1 + m2`, centre
//! `X = (m1 x1 + m2 x2)/M`, and inertia by the parallel-axis rule about its pivot `p` (pivoted)
//! or about `X` (free): `I = sum_i I_i + m_i (|x_i - o|^2 1 - d_i d_i^T)`, `d_i = x_i - o`. It
//! moves with one `v_cm = (m1 v1' + m2 v2')/M` and one `omega` (the body hit's `omega2'`: the
//! particle has none of its own). What is kept: linear and angular momentum about any fixed
//! point (free), or angular momentum about the pivot (pivoted); so a bullet of mass m at speed v
//! along a line at distance d from the pivot of a body with `I_p` gives
//! `omega' = m v d / (I_p + m d^2)`.

use crate::values::rational::Q;

use super::algebra::{self, Mat, scale};
use super::body::Body;
use super::laws::Tangential;
use super::outcome::Outcome;

/// The one rigid body two joined bodies make.
#[derive(Clone, Debug, PartialEq)]
pub struct Joined {
    pub mass: Q,
    /// The centre of mass `X`.
    pub centre: Vec<Q>,
    /// The inertia tensor about `about` (`1 x 1` in the plane).
    pub inertia: Mat,
    /// The pivot the body turns about, or `None`: the inertia is about the centre `X`.
    pub pivot: Option<Vec<Q>>,
    /// The velocity of the centre of mass.
    pub v: Vec<Q>,
    pub omega: Vec<Q>,
}

impl Joined {
    /// The joined body of a `--join` outcome (`None` for any other impact, or where a body is
    /// immovable).
    pub fn of(o: &Outcome) -> Option<Joined> {
        if !matches!(o.problem.tangential, Tangential::Join) {
            return None;
        }
        let [a, b] = o.bodies();
        let (m1, m2) = (a.mass.clone()?, b.mass.clone()?);
        if a.immovable().is_some() || b.immovable().is_some() {
            return None;
        }
        let mass = &m1 + &m2;
        let centre = scale(
            &algebra::add(&scale(&a.position, &m1), &scale(&b.position, &m2)),
            &(Q::ONE / &mass),
        );
        let pivot = a.pivot().or(b.pivot()).map(<[Q]>::to_vec);
        let about = pivot.clone().unwrap_or_else(|| centre.clone());
        let inertia = algebra::add_mat(&moment(a, &m1, &about), &moment(b, &m2, &about));
        let v = scale(&o.momentum(&o.fin), &(Q::ONE / &mass));
        Some(Joined {
            mass,
            centre,
            inertia,
            pivot,
            v,
            omega: o.fin[1].omega.clone(),
        })
    }
}

/// A body's inertia about `o` by the parallel-axis rule (a particle has none about its centre).
fn moment(body: &Body, m: &Q, o: &[Q]) -> Mat {
    let dim = algebra::rot_dim(body.dim());
    let zero = algebra::diag(dim, &Q::ZERO);
    Body::parallel_axis(body.inertia().unwrap_or(&zero), m, &body.position, o)
}
