//! The common homework shapes, laid out in the plane without a scene file (`collide solve`):
//!
//! - a ball (body 1: a point particle, or `--ball 'sphere 3 cm'`) moving along +x hits a target
//!   (`--target 'rod 1.2 m'`, a door, a box, a disk...) whose centre is at the origin. A rod,
//!   door or box stands along y, hit on its left face at height `y`: from the centre when free
//!   (`--hit-at 0.3 m`, default 0), from the pivot when pivoted (`--pivot end` is the bottom end
//!   `(0, -L/2)`, `centre`, or a point `'(x,y)'` from the centre), `--hit-at end` the top end.
//!   A round target is hit on its left side at height `b` (the impact parameter): the contact
//!   is at `(-sqrt(R^2 - b^2), b)`, the normal through its centre;
//! - a ball on a floor (`-m '0.06 kg,floor'`, the contact below the ball, normal `(0, -1)`),
//!   under a ceiling or a table (`ceiling`, above), or against a wall (`wall`, to its right),
//!   with `--spin` (counterclockwise positive) and `--friction` or
//!   `--tangential-restitution`.

use num_traits::Signed;

use crate::values::rational::{Q, int, ratio, sqrt_exact};

use super::algebra::rot_dim;
use super::body::Motion;
use super::impact::Problem;
use super::jacobian::Contact;
use super::pose::{Either, Heavy, LawsTyped, MassTyped, PoseError, Resolver, Spec, problem};
use super::shape::{Kind, ShapeTyped};
use super::units::{Typed, TypedVec};

/// Where a target is pivoted.
#[derive(Clone, Debug, PartialEq)]
pub enum PivotTyped {
    /// The bottom end of a rod, door or box.
    End,
    Centre,
    /// A point from the target's centre.
    At(TypedVec),
}

impl std::str::FromStr for PivotTyped {
    type Err = super::units::RigidUnitError;
    fn from_str(s: &str) -> Result<PivotTyped, Self::Err> {
        match s.trim().to_ascii_lowercase().as_str() {
            "end" | "hinge" => Ok(PivotTyped::End),
            "centre" | "center" | "middle" => Ok(PivotTyped::Centre),
            _ => TypedVec::parse(s, super::units::Measure::Length, "--pivot", &[2])
                .map(PivotTyped::At),
        }
    }
}

/// Where the target is hit.
#[derive(Clone, Debug, PartialEq)]
pub enum HitTyped {
    /// The top end (away from an end pivot).
    End,
    At(Typed),
    /// `?`: solved for (`unknowns`), which puts a value in its place before the problem is
    /// laid out.
    Unknown,
}

impl std::str::FromStr for HitTyped {
    type Err = super::units::RigidUnitError;
    fn from_str(s: &str) -> Result<HitTyped, Self::Err> {
        match s.trim().to_ascii_lowercase().as_str() {
            "end" | "tip" => Ok(HitTyped::End),
            "?" => Ok(HitTyped::Unknown),
            _ => Typed::parse(s, super::units::Measure::Length, "--hit-at").map(HitTyped::At),
        }
    }
}

/// A homework impact as typed on the command line.
#[derive(Clone, Debug, PartialEq)]
pub struct Homework {
    pub masses: [MassTyped; 2],
    pub velocities: [Option<Either>; 2],
    pub spins: [Option<Typed>; 2],
    pub ball: Option<ShapeTyped>,
    pub target: Option<ShapeTyped>,
    pub pivot: Option<PivotTyped>,
    pub hit_at: Option<HitTyped>,
    pub laws: LawsTyped,
    pub exact: bool,
    pub rtol: Option<f64>,
}

/// Why a homework impact cannot be laid out.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum HomeworkError {
    #[error(transparent)]
    Pose(#[from] PoseError),
    #[error(
        "give the body hit: --target SHAPE (e.g. 'rod 1.2 m', 'door 0.9 m', 'disk 10 cm'), or a \
         wall, floor or ceiling as the second mass"
    )]
    NoTarget,
    #[error("body 1 is the ball and must move: give the {0} as the second mass")]
    FirstImmovable(&'static str),
    #[error("--target, --pivot and --hit-at describe a movable target, not a {0}")]
    TargetOfWall(&'static str),
    #[error(
        "on a {0} give the ball's velocity as a vector '(vx,vy)' (vy < 0: falling onto a floor)"
    )]
    Vector(&'static str),
    #[error(
        "the homework shapes are laid out in the plane: give 2-vectors (a case in space is a \
         scene with [[body]] tables)"
    )]
    Space,
    #[error(
        "--hit-at: the contact at y = {y} is off the target (it reaches {reach} from its centre)"
    )]
    Off { y: String, reach: String },
    #[error("--pivot end is an end of a rod, door or box; a {0} takes centre or '(x,y)'")]
    RoundEnd(&'static str),
    #[error("--hit-at end is the top end of a rod, door or box; on a {0} give the height b")]
    RoundHitEnd(&'static str),
    #[error("a pivoted target: give --hit-at (the distance from the pivot along the target)")]
    HitNeeded,
    #[error(
        "--join: the striking body lodges at the contact point as a point particle: leave out \
         --ball"
    )]
    JoinBall,
    #[error("--join makes two bodies one; a {0} does not move: give the body hit with --target")]
    JoinWall(&'static str),
    #[error("--hit-at ?: give a final value that fixes it (--fin-spin, --pivot-impulse 0)")]
    HitUnknown,
    #[error(
        "a target spins with the second value of --spin, and a pivoted one does not slide: give it no velocity"
    )]
    PivotVelocity,
}

fn f(q: &Q) -> String {
    crate::values::number::num(crate::values::rational::to_f64(q).unwrap_or(f64::NAN))
}

impl Homework {
    /// Whether any value carries a unit (then the case is in SI).
    pub fn has_unit(&self) -> bool {
        let mass = |m: &MassTyped| matches!(m, MassTyped::Mass(t) if t.unit.is_some());
        let either = |e: &Option<Either>| {
            e.as_ref().is_some_and(|e| match e {
                Either::One(t) => t.unit.is_some(),
                Either::Vector(v) => v.has_unit(),
            })
        };
        self.masses.iter().any(mass)
            || self.velocities.iter().any(either)
            || self.spins.iter().flatten().any(|t| t.unit.is_some())
            || [&self.ball, &self.target]
                .iter()
                .any(|s| s.as_ref().is_some_and(|s| s.sizes.has_unit()))
            || matches!(&self.pivot, Some(PivotTyped::At(v)) if v.has_unit())
            || matches!(&self.hit_at, Some(HitTyped::At(t)) if t.unit.is_some())
    }

    /// The problem, laid out.
    pub fn pose(&self) -> Result<Problem, HomeworkError> {
        if matches!(self.hit_at, Some(HitTyped::Unknown)) {
            return Err(HomeworkError::HitUnknown);
        }
        if self
            .velocities
            .iter()
            .flatten()
            .any(|e| matches!(e, Either::Vector(v) if v.dim() != 2))
        {
            return Err(HomeworkError::Space);
        }
        if self.laws.join {
            if self.ball.is_some() {
                return Err(HomeworkError::JoinBall);
            }
            if let MassTyped::Immovable(word) = &self.masses[1] {
                return Err(HomeworkError::JoinWall(word));
            }
        }
        let r = Resolver::new(self.has_unit(), self.exact);
        let spin = |i: usize| -> Result<Vec<Q>, PoseError> {
            Ok(match &self.spins[i] {
                Some(t) => vec![r.one(t)?],
                None => vec![Q::ZERO; rot_dim(2)],
            })
        };
        let velocity = |i: usize| -> Result<Vec<Q>, PoseError> {
            match &self.velocities[i] {
                Some(e) => r.along_x(e, 2),
                None => Ok(vec![Q::ZERO; 2]),
            }
        };
        let m1 = match &self.masses[0] {
            MassTyped::Mass(t) => r.one(t)?,
            MassTyped::Immovable(w) => return Err(HomeworkError::FirstImmovable(w)),
        };
        let ball_shape = match &self.ball {
            Some(s) => {
                let (shape, rounded) = s.resolve(r.si, r.exact).map_err(PoseError::from)?;
                if rounded {
                    return Err(PoseError::Irrational(s.text.clone(), "give lengths").into());
                }
                Some((shape, s.text.clone()))
            }
            None => None,
        };
        let rb = ball_shape.as_ref().map_or(Q::ZERO, |(s, _)| s.radius());
        let ball = |position: Vec<Q>| -> Result<Spec, PoseError> {
            Ok(Spec {
                mass: Heavy::Mass(m1.clone()),
                position,
                motion: Motion {
                    v: velocity(0)?,
                    omega: spin(0)?,
                },
                inertia: None,
                shape: ball_shape.clone(),
                pivot: None,
            })
        };
        let origin = vec![Q::ZERO, Q::ZERO];
        let (specs, contact) = match &self.masses[1] {
            MassTyped::Immovable(word) => {
                if self.target.is_some() || self.pivot.is_some() || self.hit_at.is_some() {
                    return Err(HomeworkError::TargetOfWall(word));
                }
                let vertical = *word != "wall";
                if vertical && !matches!(self.velocities[0], Some(Either::Vector(_))) {
                    return Err(HomeworkError::Vector(word));
                }
                let (centre, normal) = match *word {
                    "floor" => (vec![Q::ZERO, rb.clone()], vec![int(0), int(-1)]),
                    "ceiling" => (vec![Q::ZERO, -rb.clone()], vec![int(0), int(1)]),
                    _ => (vec![-rb.clone(), Q::ZERO], vec![int(1), int(0)]),
                };
                let wall = Spec {
                    mass: Heavy::Immovable(word),
                    position: origin.clone(),
                    motion: Motion {
                        v: velocity(1)?,
                        omega: spin(1)?,
                    },
                    inertia: None,
                    shape: None,
                    pivot: None,
                };
                (
                    [ball(centre)?, wall],
                    Contact {
                        point: origin,
                        normal,
                    },
                )
            }
            MassTyped::Mass(t) => {
                let m2 = r.one(t)?;
                let Some(target) = &self.target else {
                    return Err(HomeworkError::NoTarget);
                };
                let (shape, rounded) = target.resolve(r.si, r.exact).map_err(PoseError::from)?;
                if rounded {
                    return Err(PoseError::Irrational(target.text.clone(), "give lengths").into());
                }
                let pivot = match &self.pivot {
                    None => None,
                    Some(PivotTyped::Centre) => Some(origin.clone()),
                    Some(PivotTyped::End) if shape.kind.round() => {
                        return Err(HomeworkError::RoundEnd(shape.kind.name()));
                    }
                    Some(PivotTyped::End) => Some(vec![Q::ZERO, -shape.half_height()]),
                    Some(PivotTyped::At(v)) => Some(r.vector(v)?),
                };
                if pivot.is_some()
                    && self.velocities[1]
                        .as_ref()
                        .is_some_and(|e| !matches!(e, Either::One(t) if t.number.value() == 0.0))
                {
                    return Err(HomeworkError::PivotVelocity);
                }
                let (point, normal, len) = if shape.kind.round() {
                    let b = match &self.hit_at {
                        None => Q::ZERO,
                        Some(HitTyped::End) => {
                            return Err(HomeworkError::RoundHitEnd(shape.kind.name()));
                        }
                        Some(HitTyped::At(t)) => r.one(t)?,
                        Some(HitTyped::Unknown) => return Err(HomeworkError::HitUnknown),
                    };
                    let rad = shape.radius();
                    if b.clone().abs() > rad {
                        return Err(HomeworkError::Off {
                            y: f(&b),
                            reach: f(&rad),
                        });
                    }
                    let c2 = &rad * &rad - &b * &b;
                    let root = match sqrt_exact(&c2) {
                        Some(x) => x,
                        None if self.exact => {
                            return Err(PoseError::Irrational(
                                format!("the contact point sqrt(R^2 - b^2) on the {}", target.text),
                                "choose --hit-at b with R^2 - b^2 a square (R = 5, b = 3)",
                            )
                            .into());
                        }
                        None => {
                            let x = crate::values::quantity::sqrt(&c2, 40);
                            crate::values::rational::from_f64(
                                crate::values::rational::to_f64(&x).unwrap_or(0.0),
                            )
                        }
                    };
                    (vec![-root.clone(), b.clone()], vec![root, -b], rad)
                } else {
                    let half = shape.half_height();
                    let face = match shape.kind {
                        Kind::Box => -(&shape.sizes[0] * ratio(1, 2)),
                        _ => Q::ZERO,
                    };
                    let y = match (&self.hit_at, &pivot) {
                        (Some(HitTyped::End), _) => half.clone(),
                        (Some(HitTyped::At(t)), Some(p)) => &p[1] + r.one(t)?,
                        (Some(HitTyped::At(t)), None) => r.one(t)?,
                        (Some(HitTyped::Unknown), _) => return Err(HomeworkError::HitUnknown),
                        (None, Some(_)) => return Err(HomeworkError::HitNeeded),
                        (None, None) => Q::ZERO,
                    };
                    if y.clone().abs() > half {
                        return Err(HomeworkError::Off {
                            y: f(&y),
                            reach: f(&half),
                        });
                    }
                    (vec![face, y], vec![int(1), int(0)], Q::ONE)
                };
                // The ball's centre: back from the contact along the normal by its radius.
                let back = &rb / len;
                let centre = vec![
                    &point[0] - &back * &normal[0],
                    &point[1] - &back * &normal[1],
                ];
                let target = Spec {
                    mass: Heavy::Mass(m2),
                    position: origin,
                    motion: Motion {
                        v: velocity(1)?,
                        omega: spin(1)?,
                    },
                    inertia: None,
                    shape: Some((shape, target.text.clone())),
                    pivot,
                };
                ([ball(centre)?, target], Contact { point, normal })
            }
        };
        Ok(problem(specs, contact, &r, &self.laws, self.rtol)?)
    }
}
