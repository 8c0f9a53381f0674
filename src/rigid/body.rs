//! A rigid body at the instant of impact and its generalized velocity `u` (physics.md section
//! 7): a free body has `u = (v, omega)` (3 numbers in the plane, 6 in space) and the block
//! `diag(m I, I_cm)` of the inertia tensor; a point particle has `u = v` and `m I`; a body on a
//! fixed pivot `p` keeps only its rotation, `u = omega`, with `I_p = I_cm + m (|d|^2 1 - d d^T)`,
//! `d = x - p` (the parallel-axis theorem; `I_cm + m |d|^2` in the plane); a wall or a floor is
//! immovable and has no coordinates at all.

use num_traits::Zero;

use crate::values::rational::{Q, half};

use super::algebra::{self, Mat, dot, rot_dim, spin_at, spin_matrix, sub};
use super::shape::Shape;

/// How a body may move.
#[derive(Clone, Debug, PartialEq)]
pub enum Mobility {
    /// Free: translation and (unless a point particle, `inertia = None`) rotation about the
    /// centre of mass, with the inertia tensor about it in world axes.
    Free { inertia: Option<Mat> },
    /// Hinged at a fixed point: rotation only, `I_p` about the pivot.
    Pivoted {
        pivot: Vec<Q>,
        /// About the centre of mass (zero for a point particle on a massless arm).
        inertia: Mat,
        about_pivot: Mat,
    },
    /// A wall or a floor (`word`): infinitely heavy.
    Immovable { word: &'static str },
}

/// A body as the impact sees it.
#[derive(Clone, Debug, PartialEq)]
pub struct Body {
    /// `None` for an immovable body.
    pub mass: Option<Q>,
    /// The centre of mass.
    pub position: Vec<Q>,
    pub mobility: Mobility,
    /// The shape, when given (pictures and the contact geometry).
    pub shape: Option<Shape>,
    /// `M_i^-1`, the inverse of the body's block of the inertia tensor.
    inverse: Mat,
}

/// A body's motion: the velocity of its centre of mass and its angular velocity (one number in
/// the plane, a vector in space).
#[derive(Clone, Debug, PartialEq)]
pub struct Motion {
    pub v: Vec<Q>,
    pub omega: Vec<Q>,
}

/// Why a body is not one the impact can take.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum BodyError {
    #[error("body {0}: the inertia tensor must be symmetric and positive definite")]
    Inertia(usize),
    #[error(
        "body {0}: its moment of inertia about the pivot is 0 (a point on its own pivot): it \
         cannot turn"
    )]
    PivotInertia(usize),
    #[error("body {0}: a point particle has no spin: give its shape or inertia, or an omega of 0")]
    ParticleSpin(usize),
    #[error(
        "body {0} is pivoted: its velocity follows from omega (v = omega x (x - p)); give omega \
         alone, or a velocity that agrees with it"
    )]
    PivotVelocity(usize),
    #[error("body {0} is a {1}: it does not move (give it no velocity or omega)")]
    ImmovableMotion(usize, &'static str),
}

impl Body {
    /// A body, validated; `index` (from 1) names it in errors.
    pub fn new(
        index: usize,
        mass: Option<Q>,
        position: Vec<Q>,
        mobility: Mobility,
        shape: Option<Shape>,
    ) -> Result<Body, BodyError> {
        let dim = position.len();
        let block = match (&mobility, &mass) {
            (Mobility::Free { inertia }, Some(m)) => {
                let mut block = algebra::diag(dim + inertia.as_ref().map_or(0, Vec::len), m);
                if let Some(i) = inertia {
                    if !(algebra::symmetric(i) && algebra::positive_definite(i)) {
                        return Err(BodyError::Inertia(index));
                    }
                    for (r, row) in i.iter().enumerate() {
                        block[dim + r][dim..].clone_from_slice(row);
                    }
                }
                block
            }
            (Mobility::Pivoted { about_pivot, .. }, _) => {
                if !(algebra::symmetric(about_pivot) && algebra::positive_definite(about_pivot)) {
                    return Err(BodyError::PivotInertia(index));
                }
                about_pivot.clone()
            }
            _ => Vec::new(),
        };
        let inverse = algebra::inverse(&block).ok_or(BodyError::Inertia(index))?;
        Ok(Body {
            mass,
            position,
            mobility,
            shape,
            inverse,
        })
    }

    /// `I_p = I_cm + m (|d|^2 1 - d d^T)`, `d = x - p` (in the plane the z entry,
    /// `I_cm + m |d|^2`).
    pub fn parallel_axis(inertia: &Mat, m: &Q, x: &[Q], p: &[Q]) -> Mat {
        let d = sub(x, p);
        let dd = dot(&d, &d);
        if x.len() == 2 {
            return vec![vec![&inertia[0][0] + m * dd]];
        }
        (0..3)
            .map(|i| {
                (0..3)
                    .map(|j| {
                        let delta = if i == j { dd.clone() } else { Q::ZERO };
                        &inertia[i][j] + m * (delta - &d[i] * &d[j])
                    })
                    .collect()
            })
            .collect()
    }

    pub fn dim(&self) -> usize {
        self.position.len()
    }

    pub fn immovable(&self) -> Option<&'static str> {
        match self.mobility {
            Mobility::Immovable { word } => Some(word),
            _ => None,
        }
    }

    pub fn pivot(&self) -> Option<&[Q]> {
        match &self.mobility {
            Mobility::Pivoted { pivot, .. } => Some(pivot),
            _ => None,
        }
    }

    /// The inertia tensor about the centre of mass (`None` for a point particle or a wall).
    pub fn inertia(&self) -> Option<&Mat> {
        match &self.mobility {
            Mobility::Free { inertia } => inertia.as_ref(),
            Mobility::Pivoted { inertia, .. } => Some(inertia),
            Mobility::Immovable { .. } => None,
        }
    }

    /// The body's block of the inertia tensor `M` (empty for a wall).
    pub fn block(&self) -> Mat {
        algebra::inverse(&self.inverse).unwrap_or_default()
    }

    /// `M_i^-1`.
    pub fn inverse(&self) -> &Mat {
        &self.inverse
    }

    /// The number of generalized coordinates.
    pub fn coordinates(&self) -> usize {
        self.inverse.len()
    }

    /// The names of the generalized coordinates (`v1x`, `w1`, ...), for the printed tensor.
    pub fn coordinate_names(&self, index: usize) -> Vec<String> {
        let axes = ["x", "y", "z"];
        let dim = self.dim();
        let v = |k: usize| format!("v{index}{}", axes[k]);
        let w = |k: usize| {
            if dim == 2 {
                format!("w{index}")
            } else {
                format!("w{index}{}", axes[k])
            }
        };
        match &self.mobility {
            Mobility::Free { inertia } => (0..dim)
                .map(v)
                .chain((0..inertia.as_ref().map_or(0, |_| rot_dim(dim))).map(w))
                .collect(),
            Mobility::Pivoted { .. } => (0..rot_dim(dim)).map(w).collect(),
            Mobility::Immovable { .. } => Vec::new(),
        }
    }

    /// The Jacobian of the material point at `c`: `J_i u_i` is its velocity (`dim x n_i`):
    /// `[1 | W(c - x)]` free, `1` for a particle, `W(c - p)` pivoted, nothing for a wall, with
    /// `W(r) omega = omega x r`.
    pub fn point_jacobian(&self, c: &[Q]) -> Mat {
        let dim = self.dim();
        match &self.mobility {
            Mobility::Free { inertia } => {
                let mut j = algebra::diag(dim, &Q::ONE);
                if inertia.is_some() {
                    let w = spin_matrix(&sub(c, &self.position));
                    for (row, wrow) in j.iter_mut().zip(w) {
                        row.extend(wrow);
                    }
                }
                j
            }
            Mobility::Pivoted { pivot, .. } => spin_matrix(&sub(c, pivot)),
            Mobility::Immovable { .. } => vec![Vec::new(); dim],
        }
    }

    /// The generalized velocity of a motion.
    pub fn u(&self, m: &Motion) -> Vec<Q> {
        match &self.mobility {
            Mobility::Free { inertia: Some(_) } => m.v.iter().chain(&m.omega).cloned().collect(),
            Mobility::Free { inertia: None } => m.v.clone(),
            Mobility::Pivoted { .. } => m.omega.clone(),
            Mobility::Immovable { .. } => Vec::new(),
        }
    }

    /// The motion of a generalized velocity (a pivoted body's centre moves at
    /// `omega x (x - p)`).
    pub fn motion(&self, u: &[Q]) -> Motion {
        let dim = self.dim();
        let rot = rot_dim(dim);
        match &self.mobility {
            Mobility::Free { inertia: Some(_) } => Motion {
                v: u[..dim].to_vec(),
                omega: u[dim..].to_vec(),
            },
            Mobility::Free { inertia: None } => Motion {
                v: u.to_vec(),
                omega: vec![Q::ZERO; rot],
            },
            Mobility::Pivoted { pivot, .. } => Motion {
                v: spin_at(u, &sub(&self.position, pivot)),
                omega: u.to_vec(),
            },
            Mobility::Immovable { .. } => Motion::rest(dim),
        }
    }

    /// Checks a given motion against the body's freedom (`index` from 1), and completes a
    /// pivoted body's velocity from its spin.
    pub fn admit(&self, index: usize, m: Motion) -> Result<Motion, BodyError> {
        let spinning = !algebra::is_zero(&m.omega);
        match &self.mobility {
            Mobility::Free { inertia: None } if spinning => Err(BodyError::ParticleSpin(index)),
            Mobility::Pivoted { .. } => {
                let full = self.motion(&m.omega);
                if algebra::is_zero(&m.v) || m.v == full.v {
                    Ok(full)
                } else {
                    Err(BodyError::PivotVelocity(index))
                }
            }
            Mobility::Immovable { word } if spinning || !algebra::is_zero(&m.v) => {
                Err(BodyError::ImmovableMotion(index, word))
            }
            _ => Ok(m),
        }
    }

    /// Translational kinetic energy `1/2 (m v).v` of the centre of mass.
    pub fn translation_energy(&self, m: &Motion) -> Q {
        match &self.mass {
            Some(mass) if self.immovable().is_none() => half() * mass * dot(&m.v, &m.v),
            _ => Q::ZERO,
        }
    }

    /// Rotational kinetic energy `1/2 omega.I_cm.omega`.
    pub fn rotation_energy(&self, m: &Motion) -> Q {
        match self.inertia() {
            Some(i) => half() * dot(&m.omega, &algebra::apply(i, &m.omega)),
            None => Q::ZERO,
        }
    }

    /// Linear momentum `m v`.
    pub fn momentum(&self, m: &Motion) -> Vec<Q> {
        match &self.mass {
            Some(mass) if self.immovable().is_none() => algebra::scale(&m.v, mass),
            _ => vec![Q::ZERO; self.dim()],
        }
    }

    /// Angular momentum about the point `o`: `(x - o) x m v + I_cm omega`.
    pub fn angular_momentum(&self, m: &Motion, o: &[Q]) -> Vec<Q> {
        let orbit = algebra::moment(&sub(&self.position, o), &self.momentum(m));
        match self.inertia() {
            Some(i) => algebra::add(&orbit, &algebra::apply(i, &m.omega)),
            None => orbit,
        }
    }
}

impl Motion {
    /// At rest in `dim` dimensions.
    pub fn rest(dim: usize) -> Motion {
        Motion {
            v: vec![Q::ZERO; dim],
            omega: vec![Q::ZERO; rot_dim(dim)],
        }
    }

    /// Every velocity less `w` (a Galilean boost; spins are the same in every such frame).
    pub fn boosted(&self, w: &[Q]) -> Motion {
        Motion {
            v: sub(&self.v, w),
            omega: self.omega.clone(),
        }
    }

    pub fn is_rest(&self) -> bool {
        self.v.iter().chain(&self.omega).all(Zero::is_zero)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::values::rational::{int, ratio};

    #[test]
    fn a_pivoted_rod_turns_about_its_end() {
        // Rod m = 3, L = 2 along y, centre (0, 1), pivot at the origin: I_cm = m L^2/12 = 1,
        // I_p = 1 + 3 * 1 = 4 = m L^2/3.
        let i = vec![vec![int(1)]];
        let x = vec![int(0), int(1)];
        let p = vec![int(0), int(0)];
        let ip = Body::parallel_axis(&i, &int(3), &x, &p);
        assert_eq!(ip, vec![vec![int(4)]]);
        let b = Body::new(
            1,
            Some(int(3)),
            x,
            Mobility::Pivoted {
                pivot: p,
                inertia: i,
                about_pivot: ip,
            },
            None,
        )
        .unwrap();
        // omega = 2: the centre moves at omega x (0, 1) = (-2, 0); KE = 1/2 I_p omega^2 = 8 =
        // 1/2 m v^2 + 1/2 I_cm omega^2 = 6 + 2.
        let m = b.motion(&[int(2)]);
        assert_eq!(m.v, vec![int(-2), int(0)]);
        assert_eq!(b.translation_energy(&m) + b.rotation_energy(&m), int(8));
        assert_eq!(b.inverse(), &vec![vec![ratio(1, 4)]]);
        // The tip (0, 2) moves at (-4, 0).
        let j = b.point_jacobian(&[int(0), int(2)]);
        assert_eq!(algebra::apply(&j, &[int(2)]), vec![int(-4), int(0)]);
    }

    #[test]
    fn parallel_axis_in_space() {
        // A point mass 2 at d = (1, 2, 0) from the pivot: I_p = 2 (|d|^2 1 - d d^T).
        let zero = algebra::diag(3, &Q::ZERO);
        let ip = Body::parallel_axis(
            &zero,
            &int(2),
            &[int(1), int(2), int(0)],
            &[int(0), int(0), int(0)],
        );
        assert_eq!(ip[0], vec![int(8), int(-4), int(0)]);
        assert_eq!(ip[2][2], int(10));
    }
}
