//! Energy ellipses (lecture Sec. 3): `1/2 V.M.V = KE` is an ellipse in the velocity plane with
//! radius `sqrt(2 KE / lambda)` along each principal axis of `M` (eigenvalue `lambda`); for a
//! diagonal `M`, `a = sqrt(2 KE / M1)` along V1 and `b = sqrt(2 KE / M2)` along V2.

use nalgebra::Vector2;
use serde::{Deserialize, Serialize};

use crate::line::inertia::InertiaTensor;

/// Radii `a`, `b` of one energy ellipse; `axes` (general `M` only) are the unit directions of `a`
/// and `b`: the eigenvectors of `M` in ascending eigenvalue order, so `a >= b`. In exact mode the
/// radii are irrational and `approx` is true (serialized only then).
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq, Default)]
pub struct Ellipse<N = f64> {
    pub a: N,
    pub b: N,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub axes: Option<[[N; 2]; 2]>,
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub approx: bool,
}

/// `sqrt(2 KE)` without overflow; a radius is `sqrt(2 KE) / sqrt(lambda)`.
pub fn root_2ke(ke: f64) -> f64 {
    if ke < f64::MAX / 2.0 {
        (2.0 * ke).sqrt()
    } else {
        std::f64::consts::SQRT_2 * ke.sqrt()
    }
}

impl Ellipse<f64> {
    /// The ellipse of energy `ke`; `axes` are `M`'s principal axes for a general tensor, `None`
    /// for a diagonal one. Radii are `sqrt(2 KE) / sqrt(lambda)`, which cannot overflow.
    pub fn new(m: &InertiaTensor, ke: f64, axes: Option<&[(f64, Vector2<f64>); 2]>) -> Ellipse {
        let root = root_2ke(ke);
        let r = |lambda: f64| root / lambda.sqrt();
        match axes {
            None => {
                let d = m.matrix();
                Ellipse {
                    a: r(d[(0, 0)]),
                    b: r(d[(1, 1)]),
                    axes: None,
                    approx: false,
                }
            }
            Some([(l1, q1), (l2, q2)]) => Ellipse {
                a: r(*l1),
                b: r(*l2),
                axes: Some([[q1.x, q1.y], [q2.x, q2.y]]),
                approx: false,
            },
        }
    }
}
