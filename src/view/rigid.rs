//! A rigid impact for the page's rigid panel (docs/rigid.md, physics.md section 7): a ball hits
//! a rod or door (free or on a pivot), or a spinning ball meets a rough floor. The inputs as
//! typed (`collide solve`'s homework flags) are laid out by the command line's own path
//! (`rigid::homework`, `rigid::solve`, `report::rigid::json`), answered with the JSON that
//! `collide solve --format json` prints (byte for byte), the command line that reproduces it, and
//! what the panel draws at the instant of impact: the bodies, the contact's normal and tangent,
//! each body's velocity and spin before and after, and the lecture's velocity plane of the
//! contact points along the normal, with the effective masses `1/(n^T K_i n)`.

use serde::Serialize;

use crate::line::case::Case;
use crate::line::frame::Frame;
use crate::line::inertia::{InertiaTensor, Mass};
use crate::line::restitution::Restitution;
use crate::report::Sections;
use crate::report::json;
use crate::report::rigid::{self as report, RigidUnits};
use crate::report::space::Style;
use crate::rigid::body::{Body, Mobility, Motion};
use crate::rigid::homework::{HitTyped, Homework, HomeworkError, PivotTyped};
use crate::rigid::impact::ImpactError;
use crate::rigid::laws::Law;
use crate::rigid::outcome::Outcome;
use crate::rigid::pose::{Either, LawsTyped, MassTyped};
use crate::rigid::shape::ShapeTyped;
use crate::rigid::units::{Measure, Typed};
use crate::space::typed::split_bodies;
use crate::values::number::Number;
use crate::values::rational::{Q, to_f64};

use super::InputError;
use super::input::RigidInput;
use super::two_body::Picture as RailPicture;

/// The answer to a rigid impact.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct RigidSolved {
    /// `collide solve ... --format json` of the case, as the command line prints it.
    pub state: String,
    /// The `collide solve` command line of the case.
    pub command: String,
    /// `None` when the bodies do not approach at the contact (the state says so).
    pub picture: Option<RigidPicture>,
}

/// What the panel draws, each value rounded once from the exact outcome (the same values as the
/// state's).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct RigidPicture {
    pub bodies: [BodyPicture; 2],
    /// The contact point, the unit normal (from body 1 to body 2) and the unit tangent
    /// `t = (-n_y, n_x)`, along which `P_t` is counted.
    pub point: [f64; 2],
    pub normal: [f64; 2],
    pub tangent: [f64; 2],
    /// `smooth`, `stick`, `slip`, `reverse` or `joined` (the report's `contact`).
    pub contact: &'static str,
    /// The impulse on body 2, and its normal and tangential parts.
    pub impulse: [f64; 2],
    pub impulse_n: f64,
    pub impulse_t: f64,
    /// The contact points' velocities along the unit normal (IN, COM, FIN; the effective masses,
    /// `None` for an immovable body or a pivot that holds it along `n`).
    pub masses: [Option<f64>; 2],
    #[serde(rename = "in")]
    pub n_in: [f64; 2],
    pub com: f64,
    pub fin: [f64; 2],
    /// `-(v1n' - v2n') / (v1n - v2n)`.
    pub e_along: f64,
    /// The lecture's velocity plane of those contact points (both masses finite): the rail's
    /// momentum line and energy ellipses with the effective masses, its IN, COM and FIN the
    /// outcome's.
    pub normal_plane: Option<RailPicture>,
    /// Energy created (Kane's paradox): why the outcome is not physics (`collide solve` exits 1).
    pub paradox: Option<String>,
    /// `m/s` when the case is in SI.
    pub velocity_unit: Option<&'static str>,
}

/// One body at the instant of impact.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct BodyPicture {
    /// `point`, a shape (`rod`, `disk`, `sphere`, ...) or `wall`, `floor`, `ceiling`.
    pub kind: &'static str,
    /// The shape's lengths (a rod's length, a radius, a box's sides).
    pub sizes: Vec<f64>,
    pub position: [f64; 2],
    pub pivot: Option<[f64; 2]>,
    pub mass: Option<f64>,
    /// The centre's velocity and the spin about z (counterclockwise positive), before and after.
    pub v_in: [f64; 2],
    pub omega_in: f64,
    pub v_fin: [f64; 2],
    pub omega_fin: f64,
}

/// A field's text: trimmed; empty is a flag not given.
fn given(s: &str) -> Option<&str> {
    Some(s.trim()).filter(|t| !t.is_empty())
}

/// Binary64 of an exact value (0 where it does not fit: the state says why).
fn x(q: &Q) -> f64 {
    to_f64(q).filter(|v| v.is_finite()).unwrap_or(0.0)
}

fn pair(v: &[Q]) -> [f64; 2] {
    [v.first().map_or(0.0, x), v.get(1).map_or(0.0, x)]
}

impl RigidInput {
    /// The homework problem typed, read by the command line's parsers.
    fn homework(&self) -> Result<Homework, InputError> {
        let mass = |text: &str, field: &'static str| {
            MassTyped::parse(text, "mass").map_err(|e| InputError::new(field, e))
        };
        let velocity = |text: &str, field: &'static str| {
            given(text)
                .map(|t| Either::parse(t, Measure::Velocity, "velocity"))
                .transpose()
                .map_err(|e| InputError::new(field, e))
        };
        let shape = |text: &str, field: &'static str| {
            given(text)
                .map(str::parse::<ShapeTyped>)
                .transpose()
                .map_err(|e| InputError::new(field, e))
        };
        let spins: Vec<&str> = match given(&self.spin) {
            Some(t) => split_bodies(t).map_err(|e| InputError::new("spin", e))?,
            None => Vec::new(),
        };
        if spins.len() > 2 {
            return Err(InputError::new(
                "spin",
                format!(
                    "--spin '{}': give one or two values (the ball's, then the target's)",
                    self.spin.trim()
                ),
            ));
        }
        let spin = |i: usize| {
            spins
                .get(i)
                .map(|t| Typed::parse(t, Measure::Spin, "--spin"))
                .transpose()
                .map_err(|e| InputError::new("spin", e))
        };
        let restitution = match given(&self.e) {
            None => Number::from_f64(1.0).map_err(|e| InputError::new("e", e))?,
            Some(t) => t
                .parse::<Restitution>()
                .map_err(|e| InputError::new("e", format!("-e '{t}': {e}")))?
                .number()
                .clone(),
        };
        let number = |text: &str, field: &'static str, flag: &str| {
            given(text)
                .map(|t| {
                    t.parse::<Number>()
                        .map_err(|e| InputError::new(field, format!("{flag} '{t}': {e}")))
                })
                .transpose()
        };
        let law = match given(&self.law) {
            None => None,
            Some("newton") => Some(Law::Newton),
            Some("poisson") => Some(Law::Poisson),
            Some("stronge") => Some(Law::Stronge),
            Some(t) => {
                return Err(InputError::new(
                    "law",
                    format!("--law '{t}': newton, poisson or stronge"),
                ));
            }
        };
        Ok(Homework {
            masses: [mass(&self.m1, "m1")?, mass(&self.m2, "m2")?],
            // The command line takes both velocities: the target's empty is 0 (at rest).
            velocities: [
                velocity(&self.v1, "v1")?,
                velocity(given(&self.v2).unwrap_or("0"), "v2")?,
            ],
            spins: [spin(0)?, spin(1)?],
            ball: shape(&self.ball, "ball")?,
            target: shape(&self.target, "target")?,
            pivot: given(&self.pivot)
                .map(str::parse::<PivotTyped>)
                .transpose()
                .map_err(|e| InputError::new("pivot", e))?,
            hit_at: match given(&self.hit_at) {
                Some("?") => {
                    return Err(InputError::new(
                        "hit_at",
                        "the page solves no unknowns: give the hit point (collide solve \
                         --hit-at ? solves for it)",
                    ));
                }
                t => t
                    .map(str::parse::<HitTyped>)
                    .transpose()
                    .map_err(|e| InputError::new("hit_at", e))?,
            },
            laws: LawsTyped {
                restitution,
                friction: number(&self.friction, "friction", "--friction")?,
                law,
                tangential_restitution: number(&self.beta, "beta", "--tangential-restitution")?,
                join: false,
            },
            exact: false,
            rtol: None,
        })
    }

    /// The field a layout error is about.
    fn field_of(e: &HomeworkError) -> &'static str {
        match e {
            HomeworkError::NoTarget | HomeworkError::TargetOfWall(_) => "target",
            HomeworkError::FirstImmovable(_) => "m1",
            HomeworkError::Vector(_) | HomeworkError::Space => "v1",
            HomeworkError::Off { .. } | HomeworkError::RoundHitEnd(_) => "hit_at",
            HomeworkError::HitNeeded | HomeworkError::HitUnknown => "hit_at",
            HomeworkError::RoundEnd(_) => "pivot",
            HomeworkError::PivotVelocity => "v2",
            HomeworkError::JoinBall | HomeworkError::JoinWall(_) => "request",
            HomeworkError::Pose(_) => "m1",
        }
    }

    /// Lays out, solves and reports the impact as `collide solve --format json` does.
    pub fn solve(&self) -> Result<RigidSolved, InputError> {
        let problem = self.homework()?.pose().map_err(|e| {
            let field = RigidInput::field_of(&e);
            InputError::new(field, e)
        })?;
        let u = RigidUnits::new(problem.si);
        let style = Style::new(false, u.units.energy_scale());
        let command = super::shell::rigid_command(self);
        let outcome = match crate::rigid::solve(problem) {
            Ok(o) => o,
            Err(ImpactError::NotApproaching(along)) => {
                let note = report::not_approaching(&along);
                return Ok(RigidSolved {
                    state: json::render(&serde_json::json!({"approaching": false, "note": note})),
                    command,
                    picture: None,
                });
            }
            Err(e) => return Err(InputError::new("request", e)),
        };
        let show = Sections::new(report::DEFAULT.to_vec());
        let state = report::json(&outcome, &show, &style, &u)
            .map_err(|e| InputError::new(largest(self), e))?;
        Ok(RigidSolved {
            state: json::render(&state),
            command,
            picture: Some(picture(&outcome, &u)),
        })
    }
}

/// The field likeliest to have put a value beyond binary64.
fn largest(r: &RigidInput) -> &'static str {
    super::input::largest_field(&[
        ("m1", &r.m1),
        ("m2", &r.m2),
        ("v1", &r.v1),
        ("v2", &r.v2),
        ("spin", &r.spin),
    ])
}

fn body_picture(b: &Body, before: &Motion, after: &Motion) -> BodyPicture {
    let kind = match (&b.mobility, &b.shape) {
        (Mobility::Immovable { word }, _) => word,
        (_, Some(s)) => s.kind.name(),
        (_, None) => "point",
    };
    BodyPicture {
        kind,
        sizes: b
            .shape
            .as_ref()
            .map_or(Vec::new(), |s| s.sizes.iter().map(x).collect()),
        position: pair(&b.position),
        pivot: match &b.mobility {
            Mobility::Pivoted { pivot, .. } => Some(pair(pivot)),
            _ => None,
        },
        mass: b.mass.as_ref().map(x),
        v_in: pair(&before.v),
        omega_in: before.omega.first().map_or(0.0, x),
        v_fin: pair(&after.v),
        omega_fin: after.omega.first().map_or(0.0, x),
    }
}

fn picture(o: &Outcome, u: &RigidUnits) -> RigidPicture {
    let b = o.bodies();
    let n = pair(&o.unit_normal());
    let a = o.along_normal();
    let masses = [a.masses[0].as_ref().map(x), a.masses[1].as_ref().map(x)];
    let (n_in, com, fin) = (
        [x(&a.v_in[0]), x(&a.v_in[1])],
        x(&a.v_com),
        [x(&a.fin[0]), x(&a.fin[1])],
    );
    let e_along = x(&o.restitution_along());
    RigidPicture {
        bodies: [
            body_picture(&b[0], &o.v_in()[0], &o.fin[0]),
            body_picture(&b[1], &o.v_in()[1], &o.fin[1]),
        ],
        point: pair(&o.problem.pair.contact.point),
        normal: n,
        tangent: [-n[1], n[0]],
        contact: o.impact.mode.name(),
        impulse: pair(&o.impact.impulse),
        impulse_n: x(&o.normal_impulse()),
        impulse_t: o.tangential_impulse().first().map_or(0.0, x),
        masses,
        n_in,
        com,
        fin,
        e_along,
        normal_plane: normal_plane(masses, n_in, [com, com], fin, e_along),
        paradox: o.paradox(),
        velocity_unit: u.si.then_some("m/s"),
    }
}

/// The velocity plane of the contact points along the normal: the rail's geometry (momentum
/// line, ellipses) for the effective masses, its points the outcome's own (`None` with an
/// immovable body, or a value beyond binary64).
fn normal_plane(
    masses: [Option<f64>; 2],
    v_in: [f64; 2],
    com: [f64; 2],
    fin: [f64; 2],
    e: f64,
) -> Option<RailPicture> {
    let mass = |m: Option<f64>| Mass::from_f64(m?).ok();
    let speed = |v: f64| Number::from_f64(v).ok();
    let inertia = InertiaTensor::diagonal(&mass(masses[0])?, &mass(masses[1])?).ok()?;
    let e = Restitution::new(Number::from_f64(e.max(0.0)).ok()?).ok()?;
    let case = Case::new(inertia, [speed(v_in[0])?, speed(v_in[1])?], e);
    let mut p = super::two_body::picture(&case.collision, &Frame::Lab, false).ok()?;
    p.com = com;
    p.fin = fin;
    Some(p)
}
