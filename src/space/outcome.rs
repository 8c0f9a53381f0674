//! One solved event in the plane or in space, and what follows from it, exactly: momentum,
//! `V_COM`, kinetic energies, the crunch energy, the impulse, speeds and angles, the collision of
//! the normal parts along the line of impact, and the same seen from a moving frame.
//!
//! Every value is computed in exact rational arithmetic from the event's (binary64 or typed)
//! values and rounded once when printed, so no formula here can lose digits: a binary64 result
//! is the correctly rounded value of the exact one.

use num_traits::{Signed, Zero};

use crate::line::frame::Frame;
use crate::values::rational::{Q, direction, half, scaled, to_f64};

/// N bodies, before and after, in `dim` dimensions.
#[derive(Clone, Debug, PartialEq)]
pub struct Outcome {
    pub dim: usize,
    pub masses: Vec<Q>,
    pub v_in: Vec<Vec<Q>>,
    pub fin: Vec<Vec<Q>>,
    /// The line of impact between bodies 1 and 2, when there is one (any length).
    pub normal: Option<Vec<Q>>,
    /// Restitution, where it means something (two bodies).
    pub e: Option<Q>,
    /// Which values are irrational, held to [`crate::space::algebra::ROOT_DIGITS`] digits or
    /// rounded (an angle of 30 degrees): exact output marks those, and what is computed from
    /// them, `≈`; typed values stay exact.
    pub approx: Marks,
}

/// Which of an outcome's values are approximations. Empty lists mean none: an exact outcome is
/// `Marks::default()`. A value computed from several (an energy, `V_COM`, an impulse) is
/// approximate when any of them is.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Marks {
    /// Every value (a typed value was rounded: an angle of 30 degrees in binary64 mode).
    pub all: bool,
    pub masses: Vec<bool>,
    /// Per body, per component.
    pub v_in: Vec<Vec<bool>>,
    pub fin: Vec<Vec<bool>>,
    pub e: bool,
}

impl Marks {
    /// Every value approximate (`all`), or none.
    pub fn uniform(all: bool) -> Marks {
        Marks {
            all,
            ..Marks::default()
        }
    }

    fn get(list: &[bool], i: usize) -> bool {
        list.get(i).copied().unwrap_or(false)
    }

    fn body(list: &[Vec<bool>], i: usize) -> bool {
        list.get(i).is_some_and(|v| v.iter().any(|x| *x))
    }

    /// Whether any value is approximate.
    pub fn any(&self) -> bool {
        self.all
            || self.e
            || self.masses.iter().any(|x| *x)
            || (0..self.v_in.len()).any(|i| Marks::body(&self.v_in, i))
            || (0..self.fin.len()).any(|i| Marks::body(&self.fin, i))
    }

    /// Body `i`'s mass.
    pub fn mass(&self, i: usize) -> bool {
        self.all || Marks::get(&self.masses, i)
    }

    /// The restitution.
    pub fn e(&self) -> bool {
        self.all || self.e
    }

    /// Component `k` of body `i`'s velocity before.
    pub fn v_in(&self, i: usize, k: usize) -> bool {
        self.all || self.v_in.get(i).is_some_and(|v| Marks::get(v, k))
    }

    /// Component `k` of body `i`'s velocity after.
    pub fn fin(&self, i: usize, k: usize) -> bool {
        self.all || self.fin.get(i).is_some_and(|v| Marks::get(v, k))
    }

    /// What the state before determines (`V_COM`, `KE_IN`, `KE_COM`, the crunch, `P`): the
    /// masses and the velocities before.
    pub fn before(&self) -> bool {
        self.all
            || self.masses.iter().any(|x| *x)
            || (0..self.v_in.len()).any(|i| Marks::body(&self.v_in, i))
    }

    /// What the state after determines (`KE_FIN`, `P'`): the masses and the velocities after.
    pub fn after(&self) -> bool {
        self.all
            || self.masses.iter().any(|x| *x)
            || (0..self.fin.len()).any(|i| Marks::body(&self.fin, i))
    }

    /// Body `i`'s state before (its velocity, its energy): its mass and its velocity.
    pub fn body_in(&self, i: usize) -> bool {
        self.all || self.mass(i) || Marks::body(&self.v_in, i)
    }

    /// Body `i`'s state after.
    pub fn body_fin(&self, i: usize) -> bool {
        self.all || self.mass(i) || Marks::body(&self.fin, i)
    }

    /// Body `i`'s change (its impulse, `dv`): its mass and both its velocities.
    pub fn change(&self, i: usize) -> bool {
        self.all || self.mass(i) || Marks::body(&self.v_in, i) || Marks::body(&self.fin, i)
    }

    /// Component `k` of body `i`'s change (`dv`, `dp`, the impulse): its mass and that
    /// component before and after (`J_y = m2 (v2'y - v2y)` is exact when momentum fixes
    /// `v2'y` exactly, whatever a root does to `v2'x`).
    pub fn change_at(&self, i: usize, k: usize) -> bool {
        self.mass(i) || self.v_in(i, k) || self.fin(i, k)
    }

    /// Before and after swapped (the event reversed in time).
    fn reversed(&self) -> Marks {
        Marks {
            v_in: self.fin.clone(),
            fin: self.v_in.clone(),
            ..self.clone()
        }
    }

    /// Every velocity of `bodies` bodies in `dim` dimensions less an observer's velocity,
    /// approximate or not.
    fn boosted(&self, w: bool, bodies: usize, dim: usize) -> Marks {
        if !w {
            return self.clone();
        }
        Marks {
            v_in: vec![vec![true; dim]; bodies],
            fin: vec![vec![true; dim]; bodies],
            ..self.clone()
        }
    }
}

/// `a.b`.
pub fn dot(a: &[Q], b: &[Q]) -> Q {
    a.iter().zip(b).fold(Q::ZERO, |s, (x, y)| s + x * y)
}

/// `a - b`.
pub fn sub(a: &[Q], b: &[Q]) -> Vec<Q> {
    a.iter().zip(b).map(|(x, y)| x - y).collect()
}

fn scale(a: &[Q], s: &Q) -> Vec<Q> {
    a.iter().map(|x| x * s).collect()
}

impl Outcome {
    /// The number of bodies.
    pub fn bodies(&self) -> usize {
        self.masses.len()
    }

    /// `M_total = sum m_i`.
    pub fn total_mass(&self) -> Q {
        self.masses.iter().fold(Q::ZERO, |s, m| s + m)
    }

    /// `P = sum m_i v_i` of a state.
    pub fn momentum(&self, v: &[Vec<Q>]) -> Vec<Q> {
        let mut p = vec![Q::ZERO; self.dim];
        for (m, vi) in self.masses.iter().zip(v) {
            for (pk, vk) in p.iter_mut().zip(vi) {
                *pk += m * vk;
            }
        }
        p
    }

    /// `V_COM = P / M_total` (the same before and after).
    pub fn v_com(&self) -> Vec<Q> {
        scale(&self.momentum(&self.v_in), &(Q::ONE / self.total_mass()))
    }

    /// `KE = 1/2 sum (m_i v_i).v_i`.
    pub fn kinetic(&self, v: &[Vec<Q>]) -> Q {
        self.masses
            .iter()
            .zip(v)
            .fold(Q::ZERO, |s, (m, vi)| s + m * dot(vi, vi))
            * half()
    }

    /// Each body's `KE_i = 1/2 m_i v_i.v_i` (exact; they add up to [`Outcome::kinetic`]).
    pub fn kinetic_each(&self, v: &[Vec<Q>]) -> Vec<Q> {
        self.masses
            .iter()
            .zip(v)
            .map(|(m, vi)| m * dot(vi, vi) * half())
            .collect()
    }

    pub fn ke_in(&self) -> Q {
        self.kinetic(&self.v_in)
    }

    pub fn ke_fin(&self) -> Q {
        self.kinetic(&self.fin)
    }

    /// `KE_COM = 1/2 M_total |V_COM|^2`, the least energy momentum allows.
    pub fn ke_com(&self) -> Q {
        let v = self.v_com();
        half() * self.total_mass() * dot(&v, &v)
    }

    /// The crunch energy: `1/2 mu (n.(v1 - v2))^2 / n.n` along a line of impact (what a
    /// totally inelastic impact along it turns into heat), else `KE_IN - KE_COM` (what sticking
    /// together would).
    pub fn crunch(&self) -> Q {
        match (&self.normal, self.bodies()) {
            (Some(n), 2) => {
                let along = dot(n, &sub(&self.v_in[0], &self.v_in[1]));
                half() * self.reduced_mass() * &along * &along / dot(n, n)
            }
            _ => self.ke_in() - self.ke_com(),
        }
    }

    /// `mu = m1 m2 / (m1 + m2)` of two bodies.
    pub fn reduced_mass(&self) -> Q {
        &self.masses[0] * &self.masses[1] / (&self.masses[0] + &self.masses[1])
    }

    /// `KE_IN - KE_FIN`: lost when positive, released when negative. For an outcome held to
    /// 40 digits (an irrational root of the energy law) a difference below `1e-30` of the
    /// energies is that law's own rounding, and is 0.
    pub fn lost(&self) -> Q {
        let (ki, kf) = (self.ke_in(), self.ke_fin());
        let d = &ki - &kf;
        if self.approx.any()
            && d.clone().abs() * Q::from(crate::values::rational::pow10(30)) <= ki + kf
        {
            return Q::ZERO;
        }
        d
    }

    /// The impulse on body `i`, `m_i (v_i' - v_i)`.
    pub fn impulse(&self, i: usize) -> Vec<Q> {
        scale(&sub(&self.fin[i], &self.v_in[i]), &self.masses[i])
    }

    /// The collision of the normal parts along the line of impact, the lecture's 1D picture:
    /// `(v1.n, v2.n)` before and after, with `n` of unit length (irrational in general: `None`
    /// unless `n.n` is a rational square, then exact).
    pub fn normal_parts(&self) -> Option<NormalParts> {
        let n = self.normal.as_ref()?;
        if self.bodies() != 2 {
            return None;
        }
        let nn = dot(n, n);
        let (len, exact) = match crate::values::rational::sqrt_exact(&nn) {
            Some(r) => (r, true),
            None => (crate::values::quantity::sqrt(&nn, 40), false),
        };
        let along = |v: &[Q]| dot(v, n) / &len;
        Some(NormalParts {
            v_in: [along(&self.v_in[0]), along(&self.v_in[1])],
            fin: [along(&self.fin[0]), along(&self.fin[1])],
            exact,
        })
    }

    /// The same event seen from a frame moving at `w`: every velocity less `w`.
    /// `w_approx` marks an observer velocity that is itself approximate
    /// ([`Outcome::observer_approx`]).
    pub fn boost(&self, w: &[Q], w_approx: bool) -> Outcome {
        let shift = |vs: &[Vec<Q>]| vs.iter().map(|v| sub(v, w)).collect();
        Outcome {
            v_in: shift(&self.v_in),
            fin: shift(&self.fin),
            approx: self.approx.boosted(w_approx, self.bodies(), self.dim),
            ..self.clone()
        }
    }

    /// Whether the observer velocity of `frame` is approximate: `V_COM` as the state before
    /// is, a body's velocity as it is; a typed one never.
    pub fn observer_approx(&self, frame: &Frame) -> bool {
        let body = |list: &dyn Fn(usize, usize) -> bool, i: usize| {
            (0..self.dim).any(|k| list(i.saturating_sub(1), k))
        };
        match frame {
            Frame::Com => self.approx.before(),
            Frame::RestIn(i) => body(&|b, k| self.approx.v_in(b, k), *i),
            Frame::RestFin(i) => body(&|b, k| self.approx.fin(b, k), *i),
            _ => false,
        }
    }

    /// The velocity of the observer of `frame` (lecture Sec. 4): 0 in the lab, `V_COM`, body
    /// i's velocity before (`rest-in:i`) or after (`rest-fin:i`), or the vector given (its
    /// typed value with `typed`, else its binary64 value).
    pub fn observer(&self, frame: &Frame, typed: bool) -> Result<Vec<Q>, FrameVelocityError> {
        let q = |n: &crate::values::number::Number| {
            if typed {
                n.exact()
            } else {
                crate::values::rational::from_f64(n.value())
            }
        };
        let body = |i: usize| {
            (1..=self.bodies())
                .contains(&i)
                .then_some(i - 1)
                .ok_or(FrameVelocityError::Body(frame.to_string(), self.bodies()))
        };
        Ok(match frame {
            Frame::Lab => vec![Q::ZERO; self.dim],
            Frame::Com => self.v_com(),
            Frame::RestIn(i) => self.v_in[body(*i)?].clone(),
            Frame::RestFin(i) => self.fin[body(*i)?].clone(),
            Frame::Velocity(n) if self.dim == 1 => vec![q(n)],
            Frame::Velocity(_) => {
                return Err(FrameVelocityError::Size(frame.to_string(), 1, self.dim));
            }
            Frame::Vector(v) if v.len() == self.dim => v.iter().map(q).collect(),
            Frame::Vector(v) => {
                return Err(FrameVelocityError::Size(
                    frame.to_string(),
                    v.len(),
                    self.dim,
                ));
            }
        })
    }

    /// Reversed in time: IN' = -FIN, FIN' = -IN (restitution 1/e).
    pub fn reversed(&self) -> Outcome {
        let neg = |vs: &[Vec<Q>]| vs.iter().map(|v| v.iter().map(|x| -x).collect()).collect();
        Outcome {
            v_in: neg(&self.fin),
            fin: neg(&self.v_in),
            approx: self.approx.reversed(),
            e: self
                .e
                .as_ref()
                .and_then(|e| (!e.is_zero()).then(|| Q::ONE / e)),
            ..self.clone()
        }
    }

    /// Whether bodies 1 and 2 approach along the line of impact before (`n.(v1 - v2) > 0`) and
    /// do not approach after; `None` without a line (or for other than two bodies).
    pub fn physical(&self) -> Option<bool> {
        let n = self.impulse_line()?;
        let before = dot(&n, &sub(&self.v_in[0], &self.v_in[1]));
        let after = dot(&n, &sub(&self.fin[0], &self.fin[1]));
        // They approach and then do not; or they start together and are pushed apart.
        Some(
            (before.is_positive() && !after.is_positive())
                || (before.is_zero() && after.is_negative()),
        )
    }

    /// Whether bodies 1 and 2 keep their distance or move apart along a given line of impact
    /// before, `n.(v1 - v2) <= 0`: they do not collide (`false` without a line, or for other
    /// than two bodies).
    pub fn receding(&self) -> bool {
        match &self.normal {
            Some(n) if self.bodies() == 2 => {
                !dot(n, &sub(&self.v_in[0], &self.v_in[1])).is_positive()
            }
            _ => false,
        }
    }

    /// The event as it happens: bodies that do not approach along the line of impact do not
    /// collide, so FIN = IN (and a frame "finally at rest" is the one "initially at rest", never
    /// the FIN of a collision that does not happen); any other outcome as it is.
    pub fn as_happens(&self) -> Outcome {
        if self.receding() {
            Outcome {
                fin: self.v_in.clone(),
                ..self.clone()
            }
        } else {
            self.clone()
        }
    }

    /// The line of impact, or where none was given, the direction of the impulse on body 2
    /// (`None` without an impulse).
    pub fn impulse_line(&self) -> Option<Vec<Q>> {
        if self.bodies() != 2 {
            return None;
        }
        if let Some(n) = &self.normal {
            return Some(n.clone());
        }
        let j = self.impulse(1);
        (!j.iter().all(Zero::is_zero)).then_some(j)
    }
}

/// A frame this event cannot be seen from.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum FrameVelocityError {
    #[error("frame '{0}': there are {1} bodies")]
    Body(String, usize),
    #[error(
        "frame '{0}': an observer velocity of {1} component(s) for velocities of {2}: give it as \
         the velocities are, e.g. '(2,1)' in the plane"
    )]
    Size(String, usize, usize),
}

/// The normal parts of two bodies' velocities, before and after.
#[derive(Clone, Debug, PartialEq)]
pub struct NormalParts {
    pub v_in: [Q; 2],
    pub fin: [Q; 2],
    /// Whether `|n|` is rational (else the parts are to 40 digits).
    pub exact: bool,
}

/// `|v|` and the angle from +x in degrees (counterclockwise, in (-180, 180]), in binary64:
/// `hypot` of the rounded components, `atan2` in degrees of the direction (scaled by a power of
/// two, so that no size of vector loses it); `None` for the angle of a vector that prints as
/// zero: the zero vector, or one whose components all round to 0 (1e-333 beside 1e35 elsewhere
/// in the report), which has no direction to print beside its speed of 0.
pub fn polar(v: &[Q]) -> (f64, Option<f64>) {
    let f: Vec<f64> = v.iter().map(|x| to_f64(x).unwrap_or(f64::NAN)).collect();
    let speed = f.iter().fold(0.0f64, |s, x| libm::hypot(s, *x));
    let angle = (v.len() == 2 && speed != 0.0).then(|| {
        let d = direction(v);
        libm::atan2(d[1], d[0]).to_degrees()
    });
    (speed, angle)
}

/// The angle between two vectors, in degrees (`None` if either is zero): `atan2(|a x b|, a.b)`
/// (accurate at every angle, where acos is not near 0 and 180) of their directions, each scaled
/// by a power of two so that neither the products of vectors of 1e-170 nor of 1e155 leave
/// binary64. The dot and cross products are exact, then rounded once.
pub fn angle_between(a: &[Q], b: &[Q]) -> Option<f64> {
    if a.iter().all(Zero::is_zero) || b.iter().all(Zero::is_zero) {
        return None;
    }
    let (qa, qb) = (scaled(a), scaled(b));
    let ab = to_f64(&dot(&qa, &qb))?;
    let cross = match a.len() {
        2 => to_f64(&(&qa[0] * &qb[1] - &qa[1] * &qb[0]))?.abs(),
        3 => {
            let c = [
                &qa[1] * &qb[2] - &qa[2] * &qb[1],
                &qa[2] * &qb[0] - &qa[0] * &qb[2],
                &qa[0] * &qb[1] - &qa[1] * &qb[0],
            ];
            c.iter()
                .fold(0.0f64, |s, x| libm::hypot(s, to_f64(x).unwrap_or(0.0)))
        }
        _ => 0.0,
    };
    Some(libm::atan2(cross, ab).to_degrees())
}

/// `|q|` as a binary64.
pub fn magnitude(q: &Q) -> f64 {
    to_f64(&q.abs()).unwrap_or(f64::INFINITY)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::values::rational::{int, ratio};

    fn v(xs: &[i64]) -> Vec<Q> {
        xs.iter().map(|x| int(*x)).collect()
    }

    /// Two equal pucks, elastic, n = (1, 1): physics.md section 7's construction by hand.
    fn pucks() -> Outcome {
        Outcome {
            dim: 2,
            masses: v(&[1, 1]),
            v_in: vec![v(&[4, 0]), v(&[0, 0])],
            fin: vec![v(&[2, -2]), v(&[2, 2])],
            normal: Some(v(&[1, 1])),
            e: Some(int(1)),
            approx: Marks::default(),
        }
    }

    #[test]
    fn energies_and_crunch() {
        let o = pucks();
        assert_eq!(o.ke_in(), int(8));
        assert_eq!(o.ke_fin(), int(8));
        assert_eq!(o.v_com(), v(&[2, 0]));
        assert_eq!(o.ke_com(), int(4));
        // crunch = 1/2 (1/2) (n.(v1 - v2))^2 / n.n = 1/4 * 16 / 2 = 2.
        assert_eq!(o.crunch(), int(2));
        assert_eq!(o.impulse(1), v(&[2, 2]));
        assert_eq!(o.physical(), Some(true));
        let parts = o.normal_parts().unwrap();
        assert!(!parts.exact);
        // Final velocities at right angles (equal masses, elastic, target at rest).
        assert_eq!(angle_between(&o.fin[0], &o.fin[1]), Some(90.0));
    }

    #[test]
    fn frames_keep_the_crunch_and_reversal_swaps() {
        let o = pucks();
        let b = o.boost(&[ratio(7, 3), int(-5)], false);
        assert_eq!(b.crunch(), o.crunch());
        assert_eq!(b.lost(), o.lost());
        assert_ne!(b.ke_in(), o.ke_in());
        let r = o.reversed();
        assert_eq!(r.v_in[0], v(&[-2, 2]));
        assert_eq!(r.reversed(), o);
    }

    #[test]
    fn polar_form() {
        let (s, a) = polar(&v(&[3, 4]));
        assert_eq!(s, 5.0);
        assert!((a.unwrap() - 53.13010235415598).abs() < 1e-12);
        assert_eq!(polar(&v(&[0, 0])).1, None);
        assert_eq!(polar(&v(&[-1, 0])).1, Some(180.0));
        // Not zero, but below binary64's smallest subnormal: it prints (0, 0), with no angle.
        let tiny = [Q::ZERO, -(Q::ONE / crate::values::rational::pow2(1110))];
        assert_eq!(polar(&tiny), (0.0, None));
        let small = [Q::ZERO, -(Q::ONE / crate::values::rational::pow2(1070))];
        assert_eq!(polar(&small).1, Some(-90.0));
    }
}
