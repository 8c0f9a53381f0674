//! Solving a problem in the plane or in space for its unknowns (`../shared/physics.md` section 7):
//! the laws are written as polynomials in the unknowns (`algebra`), the linear ones solved
//! exactly, and the one or two parameters they leave fixed by the quadratic ones.
//!
//! The laws, for N bodies in d dimensions:
//! - momentum, d equations: `sum m_i v_i = sum m_i v_i'`;
//! - with a line of impact `n` between two bodies: restitution
//!   `n.(v1' - v2') = -e n.(v1 - v2)` and body 1's tangential parts kept, `t.(v1' - v1) = 0`
//!   for the d - 1 directions `t` across `n` (body 2's follow from momentum);
//! - without one: `e = 0`, every body ends with one velocity; `e = 1`, energy is kept,
//!   `sum m_i |v_i|^2 = sum m_i |v_i'|^2`; bodies that start together (a separation) only
//!   momentum;
//! - a direction unknown at a known speed is a unit vector `u`, `|u|^2 = 1`.

use num_traits::{Signed, Zero};

use crate::values::number::Given;
use crate::values::quantity::Exact;
use crate::values::rational::{Q, from_f64};

use super::algebra::{self, Poly, Root, TooNonlinear};

/// A velocity as a problem gives it.
#[derive(Clone, Debug, PartialEq)]
pub enum Velocity {
    /// Components, each known or unknown (`(4,1)`, `(?,3)`, `?`).
    Components(Vec<Given<Q>>),
    /// A known direction (a unit vector) at an unknown speed (`? @ 30deg`).
    Speed { unit: Vec<Q> },
    /// A known speed in an unknown direction, in the plane (`5.2 @ ?`).
    Direction { speed: Q },
}

impl Velocity {
    /// A known vector.
    pub fn known(v: Vec<Q>) -> Velocity {
        Velocity::Components(v.into_iter().map(Given::Known).collect())
    }

    /// The whole vector unknown.
    pub fn unknown(dim: usize) -> Velocity {
        Velocity::Components(vec![Given::Unknown; dim])
    }

    /// The vector when every part is known.
    pub fn value(&self) -> Option<Vec<Q>> {
        match self {
            Velocity::Components(c) => c.iter().map(|g| g.known().cloned()).collect(),
            _ => None,
        }
    }
}

/// What the problem gives: N bodies in `dim` dimensions.
#[derive(Clone, Debug, PartialEq)]
pub struct Statement {
    pub dim: usize,
    pub masses: Vec<Given<Q>>,
    pub v_in: Vec<Velocity>,
    pub fin: Vec<Velocity>,
    /// The line of impact between bodies 1 and 2 (any length).
    pub normal: Option<Vec<Q>>,
    /// `None`: not given (unknown when the problem gives final velocities, else elastic).
    pub e: Option<Given<Q>>,
    /// Some typed value was irrational (an angle of 30 degrees) and enters rounded: checks allow
    /// a relative residual of [`INEXACT_TOL`].
    pub inexact: bool,
}

/// The relative residual a check may have when inputs were rounded.
pub const INEXACT_TOL: f64 = 1e-12;

/// An unknown, named as output names it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Unknown {
    Mass(usize),
    /// Body, final?, component.
    Component(usize, bool, usize),
    /// Body, final?: the speed along a known direction.
    Speed(usize, bool),
    /// Body, final?, component of the unknown unit direction.
    Direction(usize, bool, usize),
    Restitution,
}

/// Which law an equation is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Law {
    Momentum(usize),
    Restitution,
    /// Restitution along the impulse, where no line of impact is given: `J.(v1' - v2') = -e
    /// J.(v1 - v2)` with `J = v1' - v1` (body 1's change, along the impulse).
    ImpulseRestitution,
    Tangential(usize),
    /// Body i ends with body 1's velocity, component k (`e = 0`).
    Stick(usize, usize),
    Energy,
    /// The unknown direction of body i (final?) is a unit vector.
    Unit(usize, bool),
}

impl Law {
    pub fn name(self) -> String {
        let axis = |k: usize| ["x", "y", "z"].get(k).copied().unwrap_or("?");
        match self {
            Law::Momentum(k) => format!("momentum ({})", axis(k)),
            Law::Restitution => "restitution along the line of impact".into(),
            Law::ImpulseRestitution => "restitution along the impulse".into(),
            Law::Tangential(_) => "tangential velocity kept (smooth contact)".into(),
            Law::Stick(i, _) => format!("body {} moves with body 1 (e = 0)", i + 1),
            Law::Energy => "energy kept (elastic)".into(),
            Law::Unit(i, _) => format!("body {}'s direction is a unit vector", i + 1),
        }
    }
}

/// A law checked at a solution: its residual and the scale it is judged by.
#[derive(Clone, Debug, PartialEq)]
pub struct Check {
    pub law: Law,
    /// What the law misses by at the solution, exactly.
    pub residual: Q,
    /// The sum of the sizes of the law's terms there (the residual is relative to it).
    pub scale: Q,
    pub ok: bool,
}

/// One solution.
#[derive(Clone, Debug, PartialEq)]
pub struct Solution {
    pub masses: Vec<Exact>,
    pub v_in: Vec<Vec<Exact>>,
    pub fin: Vec<Vec<Exact>>,
    /// `None` where restitution means nothing (a separation, several bodies).
    pub e: Option<Exact>,
    pub checks: Vec<Check>,
}

/// What was solved: the unknowns and the solutions (one, or two from a quadratic, or none).
#[derive(Clone, Debug, PartialEq)]
pub struct Solved {
    pub unknowns: Vec<Unknown>,
    pub solutions: Vec<Solution>,
    /// The bodies start together and are pushed apart (e means nothing).
    pub separation: bool,
}

/// Why a problem cannot be solved.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum SolveError {
    #[error(
        "{unknowns} unknowns and {equations} independent equations ({laws}): give {more} more \
         known value{s}{hint}",
        s = if *.more == 1 { "" } else { "s" }
    )]
    TooFew {
        unknowns: usize,
        equations: usize,
        more: usize,
        laws: String,
        hint: &'static str,
    },
    #[error(
        "the given values contradict each other: {broken} cannot hold together with {kept}, \
         whatever the unknowns are (final directions that cannot carry the momentum, such as \
         two parallel directions across it); check the directions and values given"
    )]
    Contradiction { broken: String, kept: String },
    #[error(
        "a product of unknowns of degree three (an unknown mass with an unknown velocity in the \
         energy): give the mass or the velocity"
    )]
    Nonlinear,
    #[error(
        "restitution e = {0} without a line of impact: give --normal (the direction of the \
         impulse on body 2) or the final velocities; without a normal only e = 0 (they stick) \
         and e = 1 (elastic, energy kept) fix the outcome"
    )]
    NeedsNormal(String),
    #[error("these unknowns are not fixed by the laws in a way collide can solve: {0}")]
    Unsupported(&'static str),
    #[error(
        "a line of impact (--normal, --radii) is a contact between two bodies, and this case has \
         {0}: give two bodies with it; {0} bodies that stick take -e 0, and bodies pushed apart \
         their final velocities"
    )]
    NormalOfTwo(usize),
    #[error(
        "{0} bodies: collide solves at most {MAX_BODIES} bodies in one case (the solve and its \
         report grow with their number); split the case, or use collide track for a long row"
    )]
    TooMany(usize),
}

/// The most bodies one case takes (`SolveError::TooMany`).
pub const MAX_BODIES: usize = 10_000;

impl From<TooNonlinear> for SolveError {
    fn from(_: TooNonlinear) -> SolveError {
        SolveError::Nonlinear
    }
}

/// Variables and equations under construction.
struct Builder {
    unknowns: Vec<Unknown>,
}

impl Builder {
    fn var(&mut self, u: Unknown) -> Poly {
        self.unknowns.push(u);
        Poly::var(self.unknowns.len() - 1)
    }

    fn scalar(&mut self, g: &Given<Q>, u: Unknown) -> Poly {
        match g {
            Given::Known(q) => Poly::constant(q.clone()),
            _ => self.var(u),
        }
    }

    fn vector(&mut self, v: &Velocity, body: usize, fin: bool, dim: usize) -> Vec<Poly> {
        match v {
            Velocity::Components(c) => (0..dim)
                .map(|k| {
                    let g = c.get(k).cloned().unwrap_or(Given::Known(Q::ZERO));
                    self.scalar(&g, Unknown::Component(body, fin, k))
                })
                .collect(),
            Velocity::Speed { unit } => {
                let s = self.var(Unknown::Speed(body, fin));
                unit.iter().map(|u| s.scale(u)).collect()
            }
            Velocity::Direction { speed } => (0..dim)
                .map(|k| self.var(Unknown::Direction(body, fin, k)).scale(speed))
                .collect(),
        }
    }
}

/// `a - b` of polynomial vectors.
fn sub_vec(a: &[Poly], b: &[Poly]) -> Vec<Poly> {
    a.iter().zip(b).map(|(a, b)| a.sub(b)).collect()
}

/// `a.b` of polynomial vectors.
fn dot(a: &[Poly], b: &[Poly]) -> Result<Poly, TooNonlinear> {
    let mut s = Poly::default();
    for (x, y) in a.iter().zip(b) {
        s = s.add(&x.mul(y)?);
    }
    Ok(s)
}

fn dot_q(a: &[Poly], n: &[Q]) -> Poly {
    let mut s = Poly::default();
    for (x, y) in a.iter().zip(n) {
        s = s.add(&x.scale(y));
    }
    s
}

/// `d - 1` rational directions across `n` (exactly orthogonal to it).
pub fn tangents(n: &[Q]) -> Vec<Vec<Q>> {
    match n.len() {
        1 => Vec::new(),
        2 => vec![vec![-n[1].clone(), n[0].clone()]],
        _ => {
            // n x a for the axis a least along n, then n x (n x a).
            let k = (0..3)
                .min_by(|&i, &j| n[i].abs().cmp(&n[j].abs()))
                .unwrap_or(0);
            let mut a = vec![Q::ZERO; 3];
            a[k] = Q::ONE;
            let t1 = cross(n, &a);
            let t2 = cross(n, &t1);
            vec![t1, t2]
        }
    }
}

fn cross(a: &[Q], b: &[Q]) -> Vec<Q> {
    vec![
        &a[1] * &b[2] - &a[2] * &b[1],
        &a[2] * &b[0] - &a[0] * &b[2],
        &a[0] * &b[1] - &a[1] * &b[0],
    ]
}

/// Solves `given` for its unknowns.
pub fn solve(given: &Statement) -> Result<Solved, SolveError> {
    solve_with(given, true)
}

/// `solve`, with the closed form of bodies that stick (`stuck_together`) or, for the test that
/// compares the two, without it.
fn solve_with(given: &Statement, closed_forms: bool) -> Result<Solved, SolveError> {
    let dim = given.dim;
    let n = given.masses.len();
    if n > MAX_BODIES {
        return Err(SolveError::TooMany(n));
    }
    let mut b = Builder {
        unknowns: Vec::new(),
    };
    let masses: Vec<Poly> = given
        .masses
        .iter()
        .enumerate()
        .map(|(i, m)| b.scalar(m, Unknown::Mass(i)))
        .collect();
    let v_in: Vec<Vec<Poly>> = (0..n)
        .map(|i| b.vector(&given.v_in[i], i, false, dim))
        .collect();
    let fin: Vec<Vec<Poly>> = (0..n)
        .map(|i| b.vector(&given.fin[i], i, true, dim))
        .collect();
    let fin_given = given
        .fin
        .iter()
        .any(|f| !matches!(f, Velocity::Components(c) if c.iter().all(Given::is_unknown)));
    // `-e ?` beside final velocities and no line of impact asks what leaving e out asks: e
    // follows from the final velocities along the impulse (`impulse_restitution`), no law.
    let given_e = match &given.e {
        Some(Given::Unknown) if given.normal.is_none() && fin_given => None,
        e => e.clone(),
    };
    let e = match &given_e {
        Some(Given::Known(q)) => Some(Poly::constant(q.clone())),
        Some(_) => Some(b.var(Unknown::Restitution)),
        None => None,
    };
    let together = given.v_in.iter().all(|v| v.value().is_some())
        && given.v_in.windows(2).all(|w| w[0].value() == w[1].value());
    let separation = together && n >= 2 && given_e.is_none() && fin_given;

    let mut eqs: Vec<(Law, Poly)> = Vec::new();
    for k in 0..dim {
        let mut p = Poly::default();
        for i in 0..n {
            p.add_assign(&masses[i].mul(&v_in[i][k].sub(&fin[i][k]))?);
        }
        eqs.push((Law::Momentum(k), p));
    }
    let e_value = given_e.as_ref().and_then(|g| g.known().cloned());
    let mut e_used = e.clone();
    if separation {
        // Momentum alone: e means nothing for bodies pushed apart.
    } else if let Some(nrm) = &given.normal {
        if n != 2 {
            return Err(SolveError::NormalOfTwo(n));
        }
        // e given, or unknown: `?`, or not given beside final velocities (else elastic).
        let e = match (&e, fin_given) {
            (Some(e), _) => e.clone(),
            (None, true) => b.var(Unknown::Restitution),
            (None, false) => Poly::constant(Q::ONE),
        };
        let rel_fin = dot_q(&fin[0], nrm).sub(&dot_q(&fin[1], nrm));
        let rel_in = dot_q(&v_in[0], nrm).sub(&dot_q(&v_in[1], nrm));
        eqs.push((Law::Restitution, rel_fin.add(&e.mul(&rel_in)?)));
        e_used = Some(e);
        for (k, t) in tangents(nrm).iter().enumerate() {
            let p = dot_q(&fin[0], t).sub(&dot_q(&v_in[0], t));
            eqs.push((Law::Tangential(k), p));
        }
    } else if e_value.as_ref().is_some_and(Zero::is_zero) {
        for (i, f) in fin.iter().enumerate().skip(1) {
            for (k, (fk, f0)) in f.iter().zip(&fin[0]).enumerate() {
                eqs.push((Law::Stick(i, k), fk.sub(f0)));
            }
        }
    } else if e_value.as_ref().is_some_and(|q| *q == Q::ONE) || (e.is_none() && !fin_given) {
        let mut p = Poly::default();
        for i in 0..n {
            let ke = dot(&v_in[i], &v_in[i])?.sub(&dot(&fin[i], &fin[i])?);
            p.add_assign(&masses[i].mul(&ke)?);
        }
        eqs.push((Law::Energy, p));
    } else if let Some(q) = &e_value {
        if !fin_given || n != 2 {
            return Err(SolveError::NeedsNormal(crate::values::quantity::fraction(
                q,
            )));
        }
        // A final velocity given in part fixes the line of impact: it is the impulse's, along
        // body 1's change of velocity `J = v1' - v1`, and Newton's law holds along it (times
        // |J|): `J.(v1' - v2') + e J.(v1 - v2) = 0`. (The tangential parts are kept by
        // momentum: both changes lie along J.) A quadratic law, solved with the others; J = 0
        // (the bodies pass) satisfies it and is judged as no impulse.
        let e = e.as_ref().expect("e is known here");
        let j = sub_vec(&fin[0], &v_in[0]);
        let rel_fin = sub_vec(&fin[0], &fin[1]);
        let rel_in = sub_vec(&v_in[0], &v_in[1]);
        let law = dot(&j, &rel_fin)?.add(&e.mul(&dot(&j, &rel_in)?)?);
        eqs.push((Law::ImpulseRestitution, law));
    }
    // Otherwise e is unknown without a line of impact: the final velocities fix it.
    for (i, v) in given.v_in.iter().chain(&given.fin).enumerate() {
        if let Velocity::Direction { .. } = v {
            let (body, is_fin) = (i % n, i >= n);
            let u: Vec<Poly> = (0..dim)
                .map(|k| {
                    let idx = b
                        .unknowns
                        .iter()
                        .position(|x| *x == Unknown::Direction(body, is_fin, k))
                        .expect("allocated above");
                    Poly::var(idx)
                })
                .collect();
            let p = dot(&u, &u)?.sub(&Poly::constant(Q::ONE));
            eqs.push((Law::Unit(body, is_fin), p));
        }
    }
    let m = b.unknowns.len();
    // Unknown directions are the free parameters where two are left: their unit circle is then
    // t0^2 + t1^2 = 1 itself, and rational points on it give roots to 40 digits.
    let last: Vec<usize> = (0..m)
        .filter(|&i| matches!(b.unknowns[i], Unknown::Direction(..)))
        .collect();
    let stick = e_value.as_ref().is_some_and(Zero::is_zero) && given.normal.is_none();
    let xs = match stuck_together(given, &b.unknowns, stick && closed_forms) {
        Some(x) => vec![(x, vec![false; m])],
        None => solve_system(&eqs, m, &last)?,
    };
    let solutions = xs
        .into_iter()
        .map(|(x, rooted)| {
            // Only a value that involves an unknown the root moves is approximate: a typed
            // velocity, a given e, or an unknown that the linear laws fix alone (momentum's
            // v2'y = -1/2 beside an irrational v1'x) is exact whatever the roots are: `≈4`
            // beside a typed 4, or `e = ≈1 (elastic)`, would contradict it.
            let approx = rooted.iter().any(|r| *r);
            let value = |p: &Poly| {
                let q = p.eval(&x);
                if p.vars().any(|i| rooted[i]) {
                    Exact::Approx(q)
                } else {
                    Exact::Rational(q)
                }
            };
            let checks = eqs
                .iter()
                .map(|(law, p)| {
                    let r = p.eval(&x);
                    let scale = p.scale_at(&x);
                    // Compared exactly: terms beyond binary64's range (a momentum of 1e383)
                    // are no reason to fail.
                    let ok = r.is_zero()
                        || ((given.inexact || approx) && r.abs() <= from_f64(INEXACT_TOL) * &scale);
                    Check {
                        law: *law,
                        residual: r,
                        scale,
                        ok,
                    }
                })
                .collect();
            let v_in: Vec<Vec<Exact>> =
                v_in.iter().map(|v| v.iter().map(value).collect()).collect();
            let fin: Vec<Vec<Exact>> = fin.iter().map(|v| v.iter().map(value).collect()).collect();
            let e = if separation {
                None
            } else if let Some(e) = &e_used {
                Some(value(e))
            } else if n != 2 {
                None
            } else {
                impulse_restitution(&v_in, &fin).map(|q| {
                    if approx {
                        Exact::Approx(q)
                    } else {
                        Exact::Rational(q)
                    }
                })
            };
            Solution {
                masses: masses.iter().map(value).collect(),
                v_in,
                fin,
                e,
                checks,
            }
        })
        .collect();
    Ok(Solved {
        unknowns: b.unknowns,
        solutions,
        separation,
    })
}

/// Bodies that stick (`-e 0`, no line of impact) with every mass and initial velocity given and
/// every final velocity asked: each final velocity is the centre of mass's, `V_COM = sum m_i v_i
/// / sum m_i` (momentum, and the stick laws `v_i' = v_1'`), in `O(N)` exact operations where the
/// elimination of `solve_system` takes `O(N^3)` on `N` bodies: the unknowns' values, in the
/// order they were made (`Builder::vector`: body by body, component by component); `None` for
/// any other problem. The solution is the one `solve_system` finds (it is unique).
fn stuck_together(given: &Statement, unknowns: &[Unknown], stick: bool) -> Option<Vec<Q>> {
    let asked = |v: &Velocity| {
        matches!(v, Velocity::Components(c)
            if c.len() == given.dim && c.iter().all(Given::is_unknown))
    };
    if !stick
        || !given.fin.iter().all(asked)
        || !unknowns
            .iter()
            .all(|u| matches!(u, Unknown::Component(_, true, _)))
    {
        return None;
    }
    let masses: Vec<&Q> = given
        .masses
        .iter()
        .map(Given::known)
        .collect::<Option<_>>()?;
    let total = masses.iter().fold(Q::ZERO, |s, m| s + *m);
    if total.is_zero() {
        return None;
    }
    let mut momentum = vec![Q::ZERO; given.dim];
    for (m, v) in masses.iter().zip(&given.v_in) {
        let Velocity::Components(c) = v else {
            return None;
        };
        for (k, p) in momentum.iter_mut().enumerate() {
            match c.get(k) {
                Some(Given::Known(q)) => *p += *m * q,
                None => {}
                Some(_) => return None,
            }
        }
    }
    let v_com: Vec<Q> = momentum.into_iter().map(|p| p / &total).collect();
    Some(
        unknowns
            .iter()
            .map(|u| match u {
                Unknown::Component(_, _, k) => v_com[*k].clone(),
                _ => unreachable!("only final components, checked above"),
            })
            .collect(),
    )
}

/// Restitution along the impulse of a two-body outcome: `n` along body 2's change of velocity,
/// `e = -n.(v1' - v2') / n.(v1 - v2)`; `None` without an impulse or an approach along it.
fn impulse_restitution(v_in: &[Vec<Exact>], fin: &[Vec<Exact>]) -> Option<Q> {
    let q = |e: &Exact| e.rational().clone();
    let n: Vec<Q> = fin[1]
        .iter()
        .zip(&v_in[1])
        .map(|(f, v)| q(f) - q(v))
        .collect();
    let along = |a: &[Exact], b: &[Exact]| -> Q {
        n.iter()
            .zip(a.iter().zip(b))
            .map(|(n, (x, y))| n * (q(x) - q(y)))
            .fold(Q::ZERO, |s, t| s + t)
    };
    let approach = along(&v_in[0], &v_in[1]);
    if approach.is_zero() {
        return None;
    }
    Some(-along(&fin[0], &fin[1]) / approach)
}

/// A solution point: the unknowns' values, and per unknown whether it hangs on an irrational
/// root.
type Point = (Vec<Q>, Vec<bool>);

/// The solutions of the equations in `m` unknowns: the values, and per unknown whether it is
/// approximate. The linear laws leave `x = x0 + sum t_k z_k`; where a parameter `t_k` is an
/// irrational root, exactly the unknowns with `z_k[i] != 0` hang on it, and the others are
/// `x0[i]`, fixed exactly by the linear laws alone.
fn solve_system(eqs: &[(Law, Poly)], m: usize, last: &[usize]) -> Result<Vec<Point>, SolveError> {
    let mut linear: Vec<(Law, &Poly)> = eqs
        .iter()
        .filter(|(_, p)| p.is_linear())
        .map(|(l, p)| (*l, p))
        .collect();
    let quadratic: Vec<&(Law, Poly)> = eqs.iter().filter(|(_, p)| !p.is_linear()).collect();
    // A linear law that contradicts the others is dropped here and judged as a check.
    let mut dropped: Vec<Law> = Vec::new();
    let affine = loop {
        let polys: Vec<&Poly> = linear.iter().map(|(_, p)| *p).collect();
        match algebra::solve_linear(&polys, m, last) {
            Ok(a) => break a,
            Err(c) => {
                dropped.push(linear.remove(c.equation).0);
            }
        }
    };
    let rank = m - affine.basis.len();
    let point = |t: &[Q]| -> Vec<Q> {
        let mut x = affine.x0.clone();
        for (tk, z) in t.iter().zip(&affine.basis) {
            for (xi, zi) in x.iter_mut().zip(z) {
                *xi += tk * zi;
            }
        }
        x
    };
    let free = affine.basis.len();
    // Which unknowns a parameter moves, if its value is approximate.
    let rooted = |approx: bool| -> Vec<bool> {
        (0..m)
            .map(|i| approx && affine.basis.iter().any(|z| !z[i].is_zero()))
            .collect()
    };
    let in_t: Vec<(Law, Poly)> = quadratic
        .iter()
        .map(|(law, p)| (*law, p.substitute(&affine.x0, &affine.basis)))
        .filter(|(_, p)| !(p.lin.is_empty() && p.is_linear()))
        .collect();
    let too_few = |used: usize| {
        // Laws that contradict the others leave too few to fix the unknowns: the data, not
        // a missing value, are at fault (issue 42 section 5), so say which laws cannot hold.
        if !dropped.is_empty() {
            let names = |laws: &mut dyn Iterator<Item = Law>| -> String {
                let mut v: Vec<String> = laws.map(Law::name).collect();
                v.dedup();
                v.join(", ")
            };
            return SolveError::Contradiction {
                broken: names(&mut dropped.iter().copied()),
                kept: names(&mut linear.iter().map(|(l, _)| *l)),
            };
        }
        let laws: Vec<String> = eqs.iter().map(|(l, _)| l.name()).collect();
        let mut laws_unique = laws.clone();
        laws_unique.dedup();
        SolveError::TooFew {
            unknowns: m,
            equations: rank + used,
            more: free.saturating_sub(used),
            laws: laws_unique.join(", "),
            hint: "",
        }
    };
    match free {
        0 => Ok(vec![(affine.x0.clone(), vec![false; m])]),
        1 => {
            let Some((_, p)) = in_t.first() else {
                return Err(too_few(0));
            };
            let a = p.quad.get(&(0, 0)).cloned().unwrap_or_default();
            let b = p.lin.get(&0).cloned().unwrap_or_default();
            Ok(algebra::quadratic_roots(&a, &b, &p.c)
                .into_iter()
                .map(|r| {
                    let approx = matches!(r, Root::Approx(_));
                    (point(&[r.value().clone()]), rooted(approx))
                })
                .collect())
        }
        2 => {
            if in_t.len() < 2 {
                return Err(too_few(in_t.len()));
            }
            let roots: Vec<(Vec<Q>, bool)> = match unit_circle(&in_t) {
                Some(k) => on_unit_circle(&in_t[1 - k.min(1)].1)
                    .into_iter()
                    .map(|(t, exact)| (t.to_vec(), exact))
                    .collect(),
                None => {
                    return Err(SolveError::Unsupported(
                        "two free parameters whose equations are not a unit direction and a conic",
                    ));
                }
            };
            Ok(roots
                .into_iter()
                .map(|(t, exact)| (point(&t), rooted(!exact)))
                .collect())
        }
        _ => Err(too_few(in_t.len().min(free))),
    }
}

/// Which of the first two equations in the parameters is the unit circle `t0^2 + t1^2 = 1`
/// (times a constant).
fn unit_circle(in_t: &[(Law, Poly)]) -> Option<usize> {
    in_t.iter().take(2).position(|(_, p)| {
        let a = p.quad.get(&(0, 0));
        a.is_some()
            && p.quad.get(&(1, 1)) == a
            && !p.quad.contains_key(&(0, 1))
            && p.lin.is_empty()
            && a.is_some_and(|a| p.c == -a.clone())
    })
}

/// The points of the unit circle where the conic `q(t0, t1) = 0`, and whether each is exact,
/// from its rational points `((1 - s^2)/(1 + s^2), 2s/(1 + s^2))`: `(1 + s^2)^2 q` is a quartic
/// in `s` with rational coefficients, its roots (double ones too: a tangency) narrowed exactly
/// to 40 digits or found exactly when rational (the points lie on the circle exactly);
/// `s = infinity` is the point `(-1, 0)`.
fn on_unit_circle(q: &Poly) -> Vec<([Q; 2], bool)> {
    let c = |k: (usize, usize)| q.quad.get(&k).cloned().unwrap_or_default();
    let l = |k: usize| q.lin.get(&k).cloned().unwrap_or_default();
    let (a, b, cc, d, e, f) = (c((0, 0)), c((0, 1)), c((1, 1)), l(0), l(1), q.c.clone());
    let two = Q::from(2);
    let four = Q::from(4);
    let coeffs = [
        &a + &d + &f,
        &two * (&b + &e),
        &four * &cc + &two * (&f - &a),
        &two * (&e - &b),
        &a - &d + &f,
    ];
    let mut points: Vec<([Q; 2], bool)> = algebra::real_roots(&coeffs, algebra::ROOT_DIGITS)
        .into_iter()
        .map(|(s, exact)| {
            let den = Q::ONE + &s * &s;
            ([(Q::ONE - &s * &s) / &den, &two * &s / &den], exact)
        })
        .collect();
    if coeffs[4].is_zero() {
        points.push(([-Q::ONE, Q::ZERO], true));
    }
    points
}

#[cfg(test)]
#[path = "solve_tests.rs"]
mod tests;
