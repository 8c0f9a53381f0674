//! Sliding to rolling after an impact (physics.md section 8, issue 42 section 3): a round body
//! (a sphere, shell, disk or ring of radius `R`) leaving the impact along a floor beneath it
//! (`v_y = 0`; the plane is vertical, `y` up) slides while its contact point slips,
//! `w = v + omega R` (`omega` counterclockwise). Friction acts at the contact point, so the
//! angular momentum about it is kept: `L = I omega - m R v` is constant, and pure rolling
//! (`omega = -v/R`) begins at
//!
//! `v_roll = (m v - (I/R) omega) / (m + I/R^2) = (m R^2 v - I R omega) / (m R^2 + I)`,
//!
//! whatever the coefficient (solid sphere: `(5 v - 2 R omega)/7`). With the floor's kinetic
//! friction `mu` and gravity `g`, `dv/dt = -mu g sgn(w)` and `R domega/dt = -mu g (m R^2/I)
//! sgn(w)`, so the slip stops after `t = |w| I / (mu g (I + m R^2))`, the centre having moved
//! `v t - 1/2 mu g sgn(w) t^2`. All exact rational arithmetic.

use num_traits::Signed;

use crate::values::rational::{Q, half};

use super::body::Mobility;
use super::outcome::Outcome;

/// A round body sliding to rolling after the impact.
#[derive(Clone, Debug, PartialEq)]
pub struct Rolling {
    /// The body (0 or 1).
    pub body: usize,
    pub radius: Q,
    pub mass: Q,
    /// About its centre.
    pub inertia: Q,
    /// Its velocity along the floor and its spin as it leaves the impact.
    pub v: Q,
    pub omega: Q,
    /// The contact point's slip `v + omega R`.
    pub slip: Q,
    pub v_roll: Q,
    /// `-v_roll / R`.
    pub omega_roll: Q,
    /// With the floor's friction: how long it slides and how far its centre moves meanwhile.
    pub slide: Option<Slide>,
}

/// The slide before rolling, with the floor's kinetic friction.
#[derive(Clone, Debug, PartialEq)]
pub struct Slide {
    pub mu: Q,
    pub g: Q,
    pub time: Q,
    pub distance: Q,
}

/// Why a body does not roll on: said for each body asked about.
#[derive(Clone, Copy, Debug, PartialEq, Eq, thiserror::Error)]
pub enum NoRoll {
    #[error("a point particle has no radius to roll on (give it a shape: --ball 'sphere R')")]
    Point,
    #[error("a body on a pivot turns about it and does not roll")]
    Pivoted,
    #[error("a {0} is not round (rolling is for a sphere, shell, disk or ring)")]
    NotRound(&'static str),
    #[error(
        "it leaves the impact with a vertical velocity (v_y' is not 0): it rolls only once it \
         is back on the floor"
    )]
    Airborne,
    #[error("rolling is computed in the plane (a vertical plane with the floor along x)")]
    Space,
}

impl Rolling {
    /// Each movable body's rolling after the impact, or why it does not roll on (walls are
    /// left out; a `--join`ed pair is one body that is not round). `floor`: the floor's
    /// friction `mu > 0` and gravity `g > 0`.
    pub fn of(o: &Outcome, floor: Option<(&Q, &Q)>) -> Vec<(usize, Result<Rolling, NoRoll>)> {
        o.bodies()
            .iter()
            .enumerate()
            .filter(|(_, b)| b.immovable().is_none())
            .map(|(i, _)| (i, Rolling::body(o, i, floor)))
            .collect()
    }

    fn body(o: &Outcome, i: usize, floor: Option<(&Q, &Q)>) -> Result<Rolling, NoRoll> {
        if o.dim() != 2 {
            return Err(NoRoll::Space);
        }
        let b = &o.bodies()[i];
        let inertia = match &b.mobility {
            Mobility::Pivoted { .. } => return Err(NoRoll::Pivoted),
            Mobility::Free { inertia: None } | Mobility::Immovable { .. } => {
                return Err(NoRoll::Point);
            }
            Mobility::Free { inertia: Some(i) } => i[0][0].clone(),
        };
        let Some(shape) = b.shape.as_ref() else {
            return Err(NoRoll::NotRound("rigid body"));
        };
        if !shape.kind.round() {
            return Err(NoRoll::NotRound(shape.kind.name()));
        }
        if matches!(o.problem.tangential, super::laws::Tangential::Join) {
            return Err(NoRoll::NotRound("joined pair"));
        }
        let m = b.mass.clone().ok_or(NoRoll::Point)?;
        let fin = &o.fin[i];
        if !fin.v[1].is_zero() {
            return Err(NoRoll::Airborne);
        }
        let r = shape.radius();
        let (v, omega) = (fin.v[0].clone(), fin.omega[0].clone());
        let mr2 = &m * &r * &r;
        let v_roll = (&mr2 * &v - &inertia * &r * &omega) / (&mr2 + &inertia);
        let slip = &v + &omega * &r;
        let slide = floor.map(|(mu, g)| {
            let time = slip.clone().abs() * &inertia / (mu * g * (&inertia + &mr2));
            let a = if slip.is_negative() {
                mu * g
            } else {
                -(mu * g)
            };
            let distance = &v * &time + half() * a * &time * &time;
            Slide {
                mu: mu.clone(),
                g: g.clone(),
                time,
                distance,
            }
        });
        Ok(Rolling {
            body: i,
            omega_roll: -(&v_roll / &r),
            radius: r,
            mass: m,
            inertia,
            v,
            omega,
            slip,
            v_roll,
            slide,
        })
    }
}
