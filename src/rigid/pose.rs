//! A rigid impact as typed, body by body (a scene's `[[body]]` tables and its `[contact]`), turned
//! into the exact `Problem`: units resolved together (`units`), inertia from a number, a tensor
//! or a shape, a pivot's inertia by the parallel-axis theorem, motions checked against each
//! body's freedom.

use std::cell::Cell;

use num_traits::Signed;

use crate::values::number::Number;
use crate::values::rational::{Q, from_f64};

use super::algebra::{self, Mat, rot_dim};
use super::body::{Body, BodyError, Mobility, Motion};
use super::impact::Problem;
use super::jacobian::{Contact, Pair};
use super::laws::{Law, Tangential};
use super::shape::{ShapeError, ShapeTyped};
use super::slip::DEFAULT_RTOL;
use super::units::{Measure, RigidUnitError, Typed, TypedVec};
use crate::space::angle::Angle;
use crate::space::pose::NormalGiven;
use crate::space::typed::TypedError;

/// A mass, or an immovable body (`wall`, `floor`).
#[derive(Clone, Debug, PartialEq)]
pub enum MassTyped {
    Mass(Typed),
    Immovable(&'static str),
}

impl MassTyped {
    /// `0.05 kg`, `wall`, `floor` (also `inf`).
    pub fn parse(text: &str, what: &str) -> Result<MassTyped, RigidUnitError> {
        match text.trim().to_ascii_lowercase().as_str() {
            "wall" | "inf" | "infinity" | "∞" => Ok(MassTyped::Immovable("wall")),
            "floor" | "ground" => Ok(MassTyped::Immovable("floor")),
            "ceiling" => Ok(MassTyped::Immovable("ceiling")),
            _ => Typed::parse(text, Measure::Mass, what).map(MassTyped::Mass),
        }
    }
}

/// A value typed as one number or as a vector.
#[derive(Clone, Debug, PartialEq)]
pub enum Either {
    One(Typed),
    Vector(TypedVec),
}

impl Either {
    /// `(a,b[,c]) unit` or `size unit @ angle` as a vector, anything else as one number.
    pub fn parse(text: &str, measure: Measure, what: &str) -> Result<Either, RigidUnitError> {
        if text.trim_start().starts_with('(') || text.contains('@') {
            TypedVec::parse(text, measure, what, &[2, 3]).map(Either::Vector)
        } else {
            Typed::parse(text, measure, what).map(Either::One)
        }
    }

    fn has_unit(&self) -> bool {
        match self {
            Either::One(t) => t.unit.is_some(),
            Either::Vector(v) => v.has_unit(),
        }
    }

    fn dim(&self) -> Option<usize> {
        match self {
            Either::One(_) => None,
            Either::Vector(v) => Some(v.dim()),
        }
    }
}

/// An inertia as typed: a number (the plane's, or `I 1` in space), principal moments
/// `(a,b,c)`, or a tensor row by row.
#[derive(Clone, Debug, PartialEq)]
pub enum InertiaTyped {
    One(Typed),
    Rows(Vec<TypedVec>),
}

/// One body as typed.
#[derive(Clone, Debug, PartialEq)]
pub struct BodyTyped {
    pub mass: MassTyped,
    pub position: Option<TypedVec>,
    pub velocity: Option<Either>,
    pub omega: Option<Either>,
    pub inertia: Option<InertiaTyped>,
    pub shape: Option<ShapeTyped>,
    pub pivot: Option<TypedVec>,
}

/// The contact as typed.
#[derive(Clone, Debug, PartialEq)]
pub struct ContactTyped {
    pub point: TypedVec,
    pub normal: NormalTyped,
    pub laws: LawsTyped,
}

/// A contact normal as typed: components of any length and no unit (`(1,0)`, `[1, 0]`), or in
/// the plane an angle or a compass bearing (`30deg`, `N30E`), as the plane's `--normal` reads
/// them.
#[derive(Clone, Debug, PartialEq)]
pub enum NormalTyped {
    Components(Vec<Number>),
    Angle(Angle),
}

impl std::str::FromStr for NormalTyped {
    type Err = TypedError;
    fn from_str(text: &str) -> Result<NormalTyped, TypedError> {
        match text.parse::<NormalGiven>()? {
            NormalGiven::Components(parts) => Ok(NormalTyped::Components(parts)),
            NormalGiven::Angle(a) => Ok(NormalTyped::Angle(a)),
            NormalGiven::Geometry { .. } => Err(TypedError::AfterParen(text.trim().to_string())),
        }
    }
}

impl NormalTyped {
    /// How many components it has (2 for an angle).
    fn dim(&self) -> usize {
        match self {
            NormalTyped::Components(parts) => parts.len(),
            NormalTyped::Angle(_) => 2,
        }
    }
}

/// Restitution and friction as typed.
#[derive(Clone, Debug, PartialEq)]
pub struct LawsTyped {
    pub restitution: Number,
    pub friction: Option<Number>,
    pub law: Option<Law>,
    pub tangential_restitution: Option<Number>,
    /// The bodies join (`--join`): `e = 0` and no slip, one rigid body after.
    pub join: bool,
}

/// A rigid impact as typed.
#[derive(Clone, Debug, PartialEq)]
pub struct Input {
    pub bodies: [BodyTyped; 2],
    pub contact: ContactTyped,
    pub exact: bool,
    pub rtol: Option<f64>,
}

/// Why a typed impact is not one.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum PoseError {
    #[error(transparent)]
    Unit(Box<RigidUnitError>),
    #[error(transparent)]
    Shape(#[from] ShapeError),
    #[error(transparent)]
    Body(#[from] BodyError),
    #[error("vectors mix dimensions: {0}; give every vector 2 components (the plane) or 3 (space)")]
    Dimension(String),
    #[error("body {0}: mass {1} must be > 0")]
    Mass(usize, String),
    #[error("body {0}: give its inertia or its shape (or neither for a point particle)")]
    InertiaAndShape(usize),
    #[error(
        "body {0}: the inertia must be 1 number in the plane, or in space 1 number, 3 principal \
         moments '(a,b,c)' or 3 rows of 3"
    )]
    InertiaShape(usize),
    #[error("body {0}: in space omega is a vector '(wx,wy,wz)'")]
    SpinVector(usize),
    #[error("body {0}: a {1} takes no inertia, shape or pivot")]
    Immovable(usize, &'static str),
    #[error("the contact normal has {got} components, the case {dim}")]
    NormalSize { got: usize, dim: usize },
    #[error("the contact normal is the zero vector: it has no direction")]
    ZeroNormal,
    #[error("restitution {0} must be in [0, 1] (a rigid impact does not release energy)")]
    Restitution(String),
    #[error("friction {0} must be a number >= 0")]
    Friction(String),
    #[error("tangential restitution {0} must be in [-1, 1]")]
    Tangential(String),
    #[error(
        "Garwin's rough contact (tangential_restitution) is kinematic, v_n' = -e v_n: the law is \
         newton (leave it out)"
    )]
    RoughLaw,
    #[error(
        "--join makes the bodies one rigid body (e = 0 and no slip at the contact): leave out \
         {0}"
    )]
    JoinLaws(&'static str),
    #[error("two immovable bodies: at least one body must move")]
    TwoWalls,
    #[error(
        "--exact: {0} is irrational, and exact arithmetic holds rationals only: {1}, or drop --exact"
    )]
    Irrational(String, &'static str),
    #[error(
        "--exact: friction in space is an ODE in the normal impulse, solved in binary64 with an \
         error estimate: drop --exact"
    )]
    ExactSlip,
    #[error(
        "body {index}: its {what} = {value}{} is beyond binary64's normal range (2.2e-308 to \
         1.8e308) and would print as 0 or inf while the impact uses it: rescale the units \
         (mm, g), or use --exact", if unit.is_empty() { String::new() } else { format!(" {unit}") }
    )]
    Unprintable {
        index: usize,
        what: &'static str,
        value: String,
        unit: &'static str,
    },
    #[error("the tolerance {0} must be a number in [1e-13, 1e-3]")]
    Tolerance(String),
}

impl From<RigidUnitError> for PoseError {
    fn from(e: RigidUnitError) -> PoseError {
        PoseError::Unit(Box::new(e))
    }
}

/// Resolves typed values to the case's units, remembering whether any was rounded.
pub struct Resolver {
    pub si: bool,
    pub exact: bool,
    rounded: Cell<bool>,
}

impl Resolver {
    /// `si` when any value has a unit.
    pub fn new(si: bool, exact: bool) -> Resolver {
        Resolver {
            si,
            exact,
            rounded: Cell::new(false),
        }
    }

    pub fn rounded(&self) -> bool {
        self.rounded.get()
    }

    fn note(&self, rounded: bool, text: &str) -> Result<(), PoseError> {
        if rounded && self.exact {
            return Err(PoseError::Irrational(
                text.to_string(),
                "turns and degrees carry pi, give rad/s",
            ));
        }
        self.rounded.set(self.rounded.get() | rounded);
        Ok(())
    }

    pub fn one(&self, t: &Typed) -> Result<Q, PoseError> {
        let (q, r) = t.value(self.si, self.exact)?;
        self.note(r, &t.text)?;
        Ok(q)
    }

    pub fn vector(&self, t: &TypedVec) -> Result<Vec<Q>, PoseError> {
        let (q, r) = t.value(self.si, self.exact)?;
        self.note(r, &t.text)?;
        Ok(q)
    }

    /// A dimensionless number.
    pub fn plain(&self, n: &Number) -> Q {
        if self.exact {
            n.exact()
        } else {
            from_f64(n.value())
        }
    }

    /// A vector typed as one number: along x.
    pub fn along_x(&self, e: &Either, dim: usize) -> Result<Vec<Q>, PoseError> {
        match e {
            Either::One(t) => {
                let mut v = vec![Q::ZERO; dim];
                v[0] = self.one(t)?;
                Ok(v)
            }
            Either::Vector(v) => self.vector(v),
        }
    }
}

/// The mass, restitution, friction and law of a contact, checked.
pub fn contact_laws(r: &Resolver, c: &LawsTyped) -> Result<(Q, Law, Tangential), PoseError> {
    if c.join {
        let other = [
            (c.friction.is_some(), "--friction"),
            (
                c.tangential_restitution.is_some(),
                "--tangential-restitution",
            ),
            (c.law.is_some(), "--law"),
        ];
        if let Some((_, flag)) = other.iter().find(|(on, _)| *on) {
            return Err(PoseError::JoinLaws(flag));
        }
        return Ok((Q::ZERO, Law::default(), Tangential::Join));
    }
    let e = r.plain(&c.restitution);
    if e.is_negative() || e > Q::ONE {
        return Err(PoseError::Restitution(c.restitution.to_string()));
    }
    let mu = match &c.friction {
        Some(m) => {
            let q = r.plain(m);
            if q.is_negative() {
                return Err(PoseError::Friction(m.to_string()));
            }
            Some(q)
        }
        None => None,
    };
    let tangential = match (&c.tangential_restitution, mu) {
        (Some(b), mu) => {
            let beta = r.plain(b);
            if beta > Q::ONE || beta < -Q::ONE {
                return Err(PoseError::Tangential(b.to_string()));
            }
            if c.law.is_some_and(|l| l != Law::Newton) {
                return Err(PoseError::RoughLaw);
            }
            Tangential::Rough { beta, mu }
        }
        (None, Some(mu)) => Tangential::Coulomb(mu),
        (None, None) => Tangential::Smooth,
    };
    let law = match tangential {
        Tangential::Rough { .. } => Law::Newton,
        _ => c.law.unwrap_or_default(),
    };
    Ok((e, law, tangential))
}

/// The problem of two bodies' values at a contact, checked.
pub fn problem(
    [s1, s2]: [Spec; 2],
    contact: Contact,
    r: &Resolver,
    c: &LawsTyped,
    rtol: Option<f64>,
) -> Result<Problem, PoseError> {
    let dim = contact.point.len();
    let (b1, m1) = s1.build(1)?;
    let (b2, m2) = s2.build(2)?;
    if b1.immovable().is_some() && b2.immovable().is_some() {
        return Err(PoseError::TwoWalls);
    }
    if !r.exact {
        printable(&b1, 1, r.si)?;
        printable(&b2, 2, r.si)?;
    }
    let (e, law, tangential) = contact_laws(r, c)?;
    exact_allowed(r.exact, dim, &tangential)?;
    Ok(Problem {
        pair: Pair {
            bodies: [b1, b2],
            contact,
        },
        motions: [m1, m2],
        e,
        law,
        tangential,
        approx: r.rounded(),
        rtol: tolerance(rtol)?,
        si: r.si,
    })
}

/// In binary64 output a body's mass and moments of inertia print as the binary64 nearest the
/// exact values the impact uses: a value that is not 0 but below binary64's normal range would
/// print as 0 (or a subnormal of few digits), one above it as inf. Refused, named (issue 41: a
/// rod of 1e-308 m printed `I_cm = 0` while its spin came from 3.3e-617).
fn printable(body: &Body, index: usize, si: bool) -> Result<(), PoseError> {
    let diagonal = |m: &Mat| (0..m.len()).map(|k| m[k][k].clone()).collect::<Vec<_>>();
    let mut values: Vec<(&'static str, Q, &'static str)> = body
        .mass
        .iter()
        .map(|m| ("mass m", m.clone(), "kg"))
        .collect();
    if let Some(i) = body.inertia() {
        values.extend(
            diagonal(i)
                .into_iter()
                .map(|x| ("inertia I_cm", x, "kg m^2")),
        );
    }
    if let Mobility::Pivoted { about_pivot, .. } = &body.mobility {
        values.extend(
            diagonal(about_pivot)
                .into_iter()
                .map(|x| ("inertia about the pivot I_p", x, "kg m^2")),
        );
    }
    for (what, q, unit) in values {
        let fits = q.is_zero()
            || crate::values::rational::to_f64(&q)
                .is_some_and(|x| x.is_finite() && x.abs() >= f64::MIN_POSITIVE);
        if !fits {
            return Err(PoseError::Unprintable {
                index,
                what,
                value: crate::values::quantity::significant(&q, 6),
                unit: if si { unit } else { "" },
            });
        }
    }
    Ok(())
}

/// The tolerance of the ODE, checked.
pub fn tolerance(rtol: Option<f64>) -> Result<f64, PoseError> {
    let t = rtol.unwrap_or(DEFAULT_RTOL);
    if !(1e-13..=1e-3).contains(&t) {
        return Err(PoseError::Tolerance(crate::values::number::num(t)));
    }
    Ok(t)
}

/// Refuses `--exact` where the answer comes from the ODE.
pub fn exact_allowed(exact: bool, dim: usize, t: &Tangential) -> Result<(), PoseError> {
    if exact && dim == 3 && matches!(t, Tangential::Coulomb(mu) if mu.is_positive()) {
        return Err(PoseError::ExactSlip);
    }
    Ok(())
}

impl BodyTyped {
    fn has_unit(&self) -> bool {
        let mass = matches!(&self.mass, MassTyped::Mass(t) if t.unit.is_some());
        let inertia = match &self.inertia {
            Some(InertiaTyped::One(t)) => t.unit.is_some(),
            Some(InertiaTyped::Rows(rows)) => rows.iter().any(TypedVec::has_unit),
            None => false,
        };
        mass || inertia
            || self.position.as_ref().is_some_and(TypedVec::has_unit)
            || self.pivot.as_ref().is_some_and(TypedVec::has_unit)
            || self.velocity.as_ref().is_some_and(Either::has_unit)
            || self.omega.as_ref().is_some_and(Either::has_unit)
            || self.shape.as_ref().is_some_and(|s| s.sizes.has_unit())
    }

    fn dims(&self) -> Vec<usize> {
        [
            self.position.as_ref().map(TypedVec::dim),
            self.pivot.as_ref().map(TypedVec::dim),
            self.velocity.as_ref().and_then(Either::dim),
            self.omega.as_ref().and_then(Either::dim),
        ]
        .into_iter()
        .flatten()
        .collect()
    }

    /// The body's values in the case's units.
    fn spec(&self, index: usize, dim: usize, r: &Resolver) -> Result<Spec, PoseError> {
        let position = match &self.position {
            Some(p) => r.vector(p)?,
            None => vec![Q::ZERO; dim],
        };
        let v = match &self.velocity {
            Some(e) => r.along_x(e, dim)?,
            None => vec![Q::ZERO; dim],
        };
        let omega = match &self.omega {
            None => vec![Q::ZERO; rot_dim(dim)],
            Some(Either::One(t)) if dim == 2 => vec![r.one(t)?],
            Some(Either::Vector(t)) if dim == 3 => r.vector(t)?,
            Some(_) => return Err(PoseError::SpinVector(index)),
        };
        let mass = match &self.mass {
            MassTyped::Immovable(word) => {
                if self.inertia.is_some() || self.shape.is_some() || self.pivot.is_some() {
                    return Err(PoseError::Immovable(index, word));
                }
                Heavy::Immovable(word)
            }
            MassTyped::Mass(t) => Heavy::Mass(r.one(t)?),
        };
        let shape = match &self.shape {
            Some(s) => {
                let (shape, rounded) = s.resolve(r.si, r.exact)?;
                r.note(rounded, &s.text)?;
                Some((shape, s.text.clone()))
            }
            None => None,
        };
        if self.inertia.is_some() && shape.is_some() {
            return Err(PoseError::InertiaAndShape(index));
        }
        let inertia = match &self.inertia {
            Some(i) => Some(inertia(index, i, dim, r)?),
            None => None,
        };
        Ok(Spec {
            mass,
            position,
            motion: Motion { v, omega },
            inertia,
            shape,
            pivot: self.pivot.as_ref().map(|p| r.vector(p)).transpose()?,
        })
    }
}

/// A mass, or the word of an immovable body.
#[derive(Clone, Debug, PartialEq)]
pub enum Heavy {
    Mass(Q),
    Immovable(&'static str),
}

/// A body's values in the case's units, before it is built.
#[derive(Clone, Debug, PartialEq)]
pub struct Spec {
    pub mass: Heavy,
    pub position: Vec<Q>,
    pub motion: Motion,
    /// A given inertia tensor (else the shape's, else a point particle).
    pub inertia: Option<Mat>,
    /// The shape and its text.
    pub shape: Option<(super::shape::Shape, String)>,
    pub pivot: Option<Vec<Q>>,
}

impl Spec {
    /// The body (`index` from 1 names it in errors) and its motion before, checked.
    pub fn build(self, index: usize) -> Result<(Body, Motion), PoseError> {
        let dim = self.position.len();
        let mass = match self.mass {
            Heavy::Immovable(word) => {
                let body = Body::new(
                    index,
                    None,
                    self.position,
                    Mobility::Immovable { word },
                    None,
                )?;
                let m = body.admit(index, self.motion)?;
                return Ok((body, m));
            }
            Heavy::Mass(m) if m.is_positive() => m,
            Heavy::Mass(m) => {
                let shown = crate::values::rational::to_f64(&m)
                    .map_or_else(|| m.to_string(), crate::values::number::num);
                return Err(PoseError::Mass(index, shown));
            }
        };
        let inertia = match (self.inertia, &self.shape) {
            (Some(i), _) => Some(i),
            (None, Some((s, text))) => Some(s.inertia(&mass, dim, text)?),
            (None, None) => None,
        };
        let mobility = match self.pivot {
            Some(p) => {
                let i = inertia.unwrap_or_else(|| algebra::diag(rot_dim(dim), &Q::ZERO));
                let about_pivot = Body::parallel_axis(&i, &mass, &self.position, &p);
                Mobility::Pivoted {
                    pivot: p,
                    inertia: i,
                    about_pivot,
                }
            }
            None => Mobility::Free { inertia },
        };
        let shape = self.shape.map(|(s, _)| s);
        let body = Body::new(index, Some(mass), self.position, mobility, shape)?;
        let motion = body.admit(index, self.motion)?;
        Ok((body, motion))
    }
}

/// An inertia as typed, in the case's units.
fn inertia(index: usize, i: &InertiaTyped, dim: usize, r: &Resolver) -> Result<Mat, PoseError> {
    match (i, dim) {
        (InertiaTyped::One(t), 2) => Ok(vec![vec![r.one(t)?]]),
        (InertiaTyped::One(t), _) => Ok(algebra::diag(3, &r.one(t)?)),
        (InertiaTyped::Rows(rows), 3) if rows.len() == 1 && rows[0].dim() == 3 => {
            let d = r.vector(&rows[0])?;
            let mut m = algebra::diag(3, &Q::ZERO);
            for (k, x) in d.into_iter().enumerate() {
                m[k][k] = x;
            }
            Ok(m)
        }
        (InertiaTyped::Rows(rows), 3)
            if rows.len() == 3 && rows.iter().all(|row| row.dim() == 3) =>
        {
            rows.iter().map(|row| r.vector(row)).collect()
        }
        _ => Err(PoseError::InertiaShape(index)),
    }
}

impl Input {
    /// Whether any value carries a unit (then the case is in SI).
    pub fn has_unit(&self) -> bool {
        self.bodies.iter().any(BodyTyped::has_unit) || self.contact.point.has_unit()
    }

    /// The dimension every vector agrees on.
    fn dim(&self) -> Result<usize, PoseError> {
        let mut dims: Vec<usize> = self.bodies.iter().flat_map(BodyTyped::dims).collect();
        dims.push(self.contact.point.dim());
        dims.sort_unstable();
        dims.dedup();
        match dims.as_slice() {
            [d] => Ok(*d),
            many => Err(PoseError::Dimension(
                many.iter()
                    .map(|d| format!("{d}-vectors"))
                    .collect::<Vec<_>>()
                    .join(" and "),
            )),
        }
    }

    /// The exact problem.
    pub fn pose(&self) -> Result<Problem, PoseError> {
        let dim = self.dim()?;
        let r = Resolver::new(self.has_unit(), self.exact);
        let specs = [
            self.bodies[0].spec(1, dim, &r)?,
            self.bodies[1].spec(2, dim, &r)?,
        ];
        let c = &self.contact;
        if c.normal.dim() != dim {
            return Err(PoseError::NormalSize {
                got: c.normal.dim(),
                dim,
            });
        }
        let normal: Vec<Q> = match &c.normal {
            NormalTyped::Components(parts) => parts.iter().map(|n| r.plain(n)).collect(),
            NormalTyped::Angle(a) => {
                let (d, rounded) = a.direction();
                if rounded && r.exact {
                    return Err(PoseError::Irrational(
                        format!("the normal {a}"),
                        "cos and sin of the angle are irrational, give components such as [1, 1]",
                    ));
                }
                r.note(rounded, &a.typed)?;
                d
            }
        };
        if algebra::is_zero(&normal) {
            return Err(PoseError::ZeroNormal);
        }
        let point = r.vector(&c.point)?;
        problem(specs, Contact { point, normal }, &r, &c.laws, self.rtol)
    }
}
