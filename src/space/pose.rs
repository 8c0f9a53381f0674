//! A problem in the plane or in space as typed (masses, velocities as vectors, a line of impact,
//! a restitution) turned into the laws' `Statement`: units resolved as on a line, vectors built,
//! the line of impact found from `--normal` or from the geometry of smooth disks.
//!
//! Values are exact rationals: the binary64 values of what was typed for a problem without
//! unknowns (so a case on the x-axis gives the line's answer bit for bit), the typed values
//! themselves for `--exact` and for problems with unknowns or final velocities (whose checks
//! must not fail for the rounding of a typed 0.1).

use num_traits::{Signed, Zero};

use crate::values::number::{Given, Number, num};
use crate::values::rational::{Q, from_f64};
use crate::values::units::{Quantity, ResolveError, Units, resolve};

use super::angle::Angle;
use super::outcome::{Marks, Outcome};
use super::solve::{self, SolveError, Statement, Velocity};
use super::typed::{Typed, TypedError, dimension};

/// The line of impact as typed.
#[derive(Clone, Debug, PartialEq)]
pub enum NormalGiven {
    /// `(1,1)`, `(0,0,1)`: any length.
    Components(Vec<Number>),
    /// `30deg`, `N30E`.
    Angle(Angle),
    /// Smooth disks or spheres of radii `R1, R2`, body 2's centre at distance `b` from the line
    /// of the relative velocity (positive: on its left): `sin(phi) = b / (R1 + R2)`.
    Geometry { radii: [Number; 2], b: Number },
}

/// Radii and an impact parameter as typed, each a number or a length with its unit (`2.5 cm`).
/// Only their ratio enters (`sin(phi) = b / (R1 + R2)`), so lengths with units are converted to
/// metres exactly and plain numbers are kept as typed; a mix of the two is refused.
pub fn geometry(radii: [&Quantity; 2], b: &Quantity) -> Result<([Number; 2], Number), String> {
    let all = [radii[0], radii[1], b];
    let with_unit = all.iter().filter(|q| q.unit.is_some()).count();
    if with_unit == 0 {
        return Ok((
            [radii[0].number.clone(), radii[1].number.clone()],
            b.number.clone(),
        ));
    }
    if with_unit < all.len() {
        return Err(
            "give the radii and the impact parameter all with a length unit (2.5 cm) or all \
             without"
                .into(),
        );
    }
    let metres = |q: &Quantity| -> Result<Number, String> {
        let si = q.number.exact() * q.unit.map(|u| u.si()).unwrap_or(Q::ONE);
        crate::values::quantity::number_of(&si).map_err(|e| e.to_string())
    };
    Ok(([metres(radii[0])?, metres(radii[1])?], metres(b)?))
}

impl std::str::FromStr for NormalGiven {
    type Err = TypedError;
    fn from_str(s: &str) -> Result<NormalGiven, TypedError> {
        let t = s.trim();
        if t.starts_with('(') {
            return match Typed::parse(t)? {
                Typed::Components { parts, unit: None } => Ok(NormalGiven::Components(
                    parts
                        .into_iter()
                        .map(|p| p.known().cloned())
                        .collect::<Option<Vec<_>>>()
                        .ok_or_else(|| TypedError::AfterParen(t.to_string()))?,
                )),
                _ => Err(TypedError::AfterParen(t.to_string())),
            };
        }
        Ok(NormalGiven::Angle(t.parse()?))
    }
}

/// A typed problem.
#[derive(Clone, Debug, Default)]
pub struct Input {
    pub masses: Vec<Given<Quantity>>,
    pub v_in: Vec<Typed>,
    /// Final velocities, when the problem gives them (`?` for unknown ones).
    pub fin: Option<Vec<Typed>>,
    pub normal: Option<NormalGiven>,
    /// Restitution: a number, `?`, or not given.
    pub e: Option<Given<Number>>,
    pub si: bool,
    pub exact: bool,
}

/// Why a typed problem is not one collide can pose or solve.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum PoseError {
    #[error(transparent)]
    Typed(#[from] TypedError),
    #[error(transparent)]
    Resolve(#[from] ResolveError),
    #[error(transparent)]
    Solve(#[from] SolveError),
    #[error("--masses has {masses} values and --{list} {values}: give one per body")]
    Count {
        masses: usize,
        list: &'static str,
        values: usize,
    },
    #[error("at least two bodies: --masses has {0}")]
    OneBody(usize),
    #[error(
        "a wall, floor or ceiling in the plane is one smooth contact solved forward: give two \
         masses ('1 kg,wall'), the ball's velocity and e, without --fin, --normal or '?' (the \
         wall stands to the ball's right, a floor below it); among more bodies or in space a \
         wall is not supported (on a line: `collide solve`, `collide track`)"
    )]
    Wall,
    #[error("mass {0} must be a number > 0")]
    Mass(String),
    #[error(
        "--exact: {what} is irrational ({why}); exact arithmetic holds rationals only: give it \
         as components, e.g. {hint}, or drop --exact"
    )]
    Irrational {
        what: String,
        why: String,
        hint: &'static str,
    },
    #[error("--normal {0}: the line of impact has {1} components, the velocities {2}")]
    NormalSize(String, usize, usize),
    #[error("--normal: the zero vector has no direction")]
    ZeroNormal,
    #[error("the line of impact of --radii and --impact-parameter is drawn in the plane only")]
    GeometryDimension,
    #[error(
        "the line of impact from --impact-parameter needs both initial velocities (it is drawn \
         from the relative velocity), and they must differ"
    )]
    GeometryVelocities,
    #[error(
        "impact parameter |b| = {b} is larger than R1 + R2 = {sum}: the bodies miss each other"
    )]
    Miss { b: String, sum: String },
    #[error("radius {0} must be a number > 0")]
    Radius(String),
    #[error(
        "a speed along a direction must be >= 0 (a negative speed is the opposite direction): \
         '{0}'"
    )]
    NegativeSpeed(String),
}

/// The problem as the laws see it, and what it needs for output.
#[derive(Clone, Debug)]
pub struct Posed {
    pub statement: Statement,
    pub units: Units,
    /// Values are the typed ones (exact, or solved from them).
    pub typed_values: bool,
    /// Some velocity was typed as a compass bearing (`15 m/s @ N30E`): directions are printed
    /// as bearings too.
    pub bearings: bool,
}

/// How a typed number enters the laws: its typed value or its binary64 value.
pub(crate) fn q_of(n: &Number, typed: bool) -> Q {
    if typed {
        n.exact()
    } else {
        from_f64(n.value())
    }
}

impl Input {
    /// Whether the problem asks for anything (`?`) or gives final velocities.
    fn asks(&self) -> bool {
        let unknown = |t: &Typed| match t {
            Typed::Scalar(g) => g.is_unknown(),
            Typed::Components { parts, .. } => parts.iter().any(Given::is_unknown),
            Typed::Polar { speed, angle } => speed.is_unknown() || angle.is_unknown(),
        };
        self.fin.is_some()
            || self.masses.iter().any(Given::is_unknown)
            || self.v_in.iter().any(unknown)
            || self.e.as_ref().is_some_and(Given::is_unknown)
    }

    /// Whether some velocity was typed as a compass bearing (`@ N30E`).
    fn bearings(&self) -> bool {
        let bearing =
            |t: &Typed| matches!(t, Typed::Polar { angle: Given::Known(a), .. } if a.is_bearing());
        self.v_in
            .iter()
            .chain(self.fin.iter().flatten())
            .any(bearing)
    }

    /// The statement of the laws.
    pub fn pose(&self) -> Result<Posed, PoseError> {
        let n = self.masses.len();
        if n < 2 {
            return Err(PoseError::OneBody(n));
        }
        if self.masses.iter().any(Given::is_wall) {
            return Err(PoseError::Wall);
        }
        for (list, values) in [("velocities", self.v_in.len())]
            .into_iter()
            .chain(self.fin.as_ref().map(|f| ("fin", f.len())))
        {
            if values != n {
                return Err(PoseError::Count {
                    masses: n,
                    list,
                    values,
                });
            }
        }
        let all: Vec<&Typed> = self.v_in.iter().chain(self.fin.iter().flatten()).collect();
        let dim = dimension(all.iter().copied())?;
        // Units: every magnitude (a number, a component, a speed) as one velocity list.
        let flat: Vec<Given<Quantity>> = all.iter().flat_map(|t| magnitudes(t)).collect();
        let (masses, resolved, units) = resolve(&self.masses, &flat, self.si)?;
        let typed = self.exact || self.asks();
        let mut inexact = false;
        let mut next = resolved.into_iter();
        let mut velocity = |t: &Typed| -> Result<Velocity, PoseError> {
            let count = magnitudes(t).len();
            let values: Vec<Given<Number>> = next.by_ref().take(count).collect();
            let q = |g: &Given<Number>| g.known().map(|n| q_of(n, typed));
            Ok(match t {
                Typed::Scalar(Given::Known(_)) => {
                    let x = q(&values[0]).unwrap_or_default();
                    let mut v = vec![Q::ZERO; dim];
                    v[0] = x;
                    Velocity::known(v)
                }
                Typed::Scalar(_) => Velocity::unknown(dim),
                Typed::Components { .. } => Velocity::Components(
                    values
                        .iter()
                        .map(|g| q(g).map_or(Given::Unknown, Given::Known))
                        .collect(),
                ),
                Typed::Polar { angle, .. } => {
                    let speed = q(&values[0]);
                    if let Some(s) = &speed
                        && s.is_negative()
                    {
                        return Err(PoseError::NegativeSpeed(describe(t)));
                    }
                    match (speed, angle) {
                        (Some(s), Given::Known(a)) => {
                            unit_of(a, self.exact, "a velocity typed with an angle")?;
                            let (v, rounded) = a.along(&s);
                            inexact |= rounded;
                            Velocity::known(v)
                        }
                        (None, Given::Known(a)) => {
                            let unit = unit_of(a, self.exact, "a velocity typed with an angle")?;
                            inexact |= unit.1;
                            Velocity::Speed { unit: unit.0 }
                        }
                        (Some(s), _) => Velocity::Direction { speed: s },
                        (None, _) => Velocity::unknown(dim),
                    }
                }
            })
        };
        let v_in = self
            .v_in
            .iter()
            .map(&mut velocity)
            .collect::<Result<Vec<_>, _>>()?;
        let fin = match &self.fin {
            Some(f) => f.iter().map(&mut velocity).collect::<Result<Vec<_>, _>>()?,
            None => vec![Velocity::unknown(dim); n],
        };
        let masses = masses
            .iter()
            .map(|m| match m {
                Given::Known(num) => {
                    let q = q_of(num, typed);
                    if q.is_positive() {
                        Ok(Given::Known(q))
                    } else {
                        Err(PoseError::Mass(num.to_string()))
                    }
                }
                _ => Ok(Given::Unknown),
            })
            .collect::<Result<Vec<_>, _>>()?;
        let normal = match &self.normal {
            None => None,
            Some(g) => {
                let (v, rounded) = self.normal_vector(g, dim, &v_in, typed)?;
                inexact |= rounded;
                Some(v)
            }
        };
        let e = self.e.as_ref().map(|g| g.clone().map(|n| q_of(&n, typed)));
        Ok(Posed {
            statement: Statement {
                dim,
                masses,
                v_in,
                fin,
                normal,
                e,
                inexact,
            },
            units,
            typed_values: typed,
            bearings: self.bearings(),
        })
    }

    /// The line of impact as a vector (any length) and whether it was rounded.
    fn normal_vector(
        &self,
        g: &NormalGiven,
        dim: usize,
        v_in: &[Velocity],
        typed: bool,
    ) -> Result<(Vec<Q>, bool), PoseError> {
        let (v, rounded) = match g {
            NormalGiven::Components(c) => {
                let v: Vec<Q> = c.iter().map(|n| q_of(n, typed)).collect();
                if v.len() != dim {
                    return Err(PoseError::NormalSize(
                        format!(
                            "({})",
                            c.iter()
                                .map(Number::to_string)
                                .collect::<Vec<_>>()
                                .join(",")
                        ),
                        v.len(),
                        dim,
                    ));
                }
                (v, false)
            }
            NormalGiven::Angle(a) => {
                if dim != 2 {
                    return Err(PoseError::NormalSize(a.typed.clone(), 2, dim));
                }
                if a.rational_direction().is_none() {
                    unit_of(a, self.exact, "the line of impact")?;
                }
                a.direction()
            }
            NormalGiven::Geometry { radii, b } => {
                if dim != 2 {
                    return Err(PoseError::GeometryDimension);
                }
                let r: Vec<Q> = radii.iter().map(|n| q_of(n, typed)).collect();
                for (q, n) in r.iter().zip(radii) {
                    if !q.is_positive() {
                        return Err(PoseError::Radius(n.to_string()));
                    }
                }
                let sum = &r[0] + &r[1];
                let b_q = q_of(b, typed);
                if b_q.abs() > sum {
                    // As people read them; to every digit where that shows the difference
                    // (the binary64 values of 0.7 + 0.4 and of 1.1 differ).
                    let f = |q: &Q| crate::values::rational::to_f64(q).unwrap_or(f64::INFINITY);
                    let (b, s) = (num(f(&b_q.abs())), num(f(&sum)));
                    let sum = if b == s {
                        format!(
                            "{s} (by {} in binary64; --exact reads the values as typed)",
                            num(f(&(b_q.abs() - &sum)))
                        )
                    } else {
                        s
                    };
                    return Err(PoseError::Miss { b, sum });
                }
                let (Some(v1), Some(v2)) = (v_in[0].value(), v_in[1].value()) else {
                    return Err(PoseError::GeometryVelocities);
                };
                let d: Vec<Q> = v1.iter().zip(&v2).map(|(a, b)| a - b).collect();
                if d.iter().all(Zero::is_zero) {
                    return Err(PoseError::GeometryVelocities);
                }
                // n = cos(phi) d + sin(phi) d_perp with sin(phi) = s = b / (R1 + R2): from the
                // ratio, so no radius is squared (`impact::disks`), times R1 + R2 where that is
                // exact (n = sqrt((R1 + R2)^2 - b^2) d + b d_perp, as typed radii read).
                let s = &b_q / &sum;
                let c2 = (Q::ONE - s.abs()) * (Q::ONE + s.abs());
                let (c, rounded) = match crate::values::rational::sqrt_exact(&c2) {
                    Some(c) => (c * &sum, false),
                    None if self.exact => {
                        return Err(PoseError::Irrational {
                            what: "the line of impact".into(),
                            why: "sqrt((R1 + R2)^2 - b^2) is irrational".into(),
                            hint: "--normal '(3,4)'",
                        });
                    }
                    // c: the square root of (1 - s^2) held to 40 digits, as an unknown
                    // direction is: every value of the report is then the exact one rounded
                    // once (docs/plane.md). The square root of the binary64 value of 1 - s^2
                    // was within an ulp, and FIN 69 of its own ulps off (issue 41).
                    None => (crate::values::quantity::sqrt(&c2, 40), true),
                };
                let (c, sin) = if rounded { (c, s) } else { (c, b_q.clone()) };
                let perp = [-d[1].clone(), d[0].clone()];
                let v = vec![&c * &d[0] + &sin * &perp[0], &c * &d[1] + &sin * &perp[1]];
                (v, rounded)
            }
        };
        if v.iter().all(Zero::is_zero) {
            return Err(PoseError::ZeroNormal);
        }
        Ok((v, rounded))
    }
}

/// The magnitudes of a typed velocity that carry its unit.
fn magnitudes(t: &Typed) -> Vec<Given<Quantity>> {
    match t {
        Typed::Scalar(g) => vec![g.clone()],
        Typed::Components { parts, unit } => parts
            .iter()
            .map(|p| {
                p.clone().map(|number| Quantity {
                    number,
                    unit: *unit,
                    height: false,
                })
            })
            .collect(),
        Typed::Polar { speed, .. } => vec![speed.clone()],
    }
}

/// A unit vector along `a` and whether it is rounded (refused in exact arithmetic).
fn unit_of(a: &Angle, exact: bool, what: &str) -> Result<(Vec<Q>, bool), PoseError> {
    let (unit, rounded) = a.unit_rational();
    if rounded && exact {
        return Err(PoseError::Irrational {
            what: what.to_string(),
            why: format!("cos and sin of {a} are irrational"),
            hint: "(4,3) m/s or --normal '(1,1)'",
        });
    }
    Ok((unit, rounded))
}

fn describe(t: &Typed) -> String {
    match t {
        Typed::Polar { speed, angle } => {
            let s = speed.known().map_or("?".into(), |q| q.number.to_string());
            let a = angle.known().map_or("?".into(), |a| a.typed.clone());
            format!("{s} @ {a}")
        }
        _ => String::new(),
    }
}

/// The outcomes of a solved statement: one per solution, the physical ones first.
pub fn outcomes(posed: &Posed, solved: &solve::Solved) -> Vec<(Outcome, Vec<solve::Check>)> {
    let st = &posed.statement;
    solved
        .solutions
        .iter()
        .map(|s| {
            let is = |x: &crate::values::quantity::Exact| {
                matches!(x, crate::values::quantity::Exact::Approx(_))
            };
            let each = |vs: &[Vec<crate::values::quantity::Exact>]| -> Vec<Vec<bool>> {
                vs.iter().map(|v| v.iter().map(is).collect()).collect()
            };
            let approx = Marks {
                all: st.inexact,
                masses: s.masses.iter().map(is).collect(),
                v_in: each(&s.v_in),
                fin: each(&s.fin),
                e: s.e.as_ref().is_some_and(is),
            };
            let q = |e: &crate::values::quantity::Exact| e.rational().clone();
            let outcome = Outcome {
                dim: st.dim,
                masses: s.masses.iter().map(q).collect(),
                v_in: s.v_in.iter().map(|v| v.iter().map(q).collect()).collect(),
                fin: s.fin.iter().map(|v| v.iter().map(q).collect()).collect(),
                normal: st.normal.clone(),
                e: s.e.as_ref().map(q),
                approx,
            };
            (outcome, s.checks.clone())
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::space::typed::parse_list;
    use crate::values::rational::int;

    fn input(m: &str, v: &str) -> Input {
        Input {
            masses: m
                .split(',')
                .map(|s| {
                    Given::parse_mass(s, |s| {
                        crate::values::units::parse(s, crate::values::units::Dimension::Mass)
                    })
                    .unwrap()
                })
                .collect(),
            v_in: parse_list(v).unwrap(),
            ..Input::default()
        }
    }

    #[test]
    fn car_and_van_from_typed_units() {
        // physics.md section 7: 1500 kg at 25 m/s east, 2500 kg at 20 m/s north, stick.
        let mut p = input("1500 kg,2500 kg", "25 m/s @ E,20 m/s @ N");
        p.e = Some(Given::Known("0".parse().unwrap()));
        let posed = p.pose().unwrap();
        let solved = solve::solve(&posed.statement).unwrap();
        let (o, _) = &outcomes(&posed, &solved)[0];
        assert_eq!(
            o.fin[0],
            vec![
                crate::values::rational::ratio(75, 8),
                crate::values::rational::ratio(25, 2)
            ]
        );
        assert_eq!(posed.units.velocity, Some("m/s"));
    }

    #[test]
    fn geometry_gives_the_line_of_impact() {
        // R1 + R2 = 5, b = 3, d = (2, 0): n along 4 d + 3 d_perp = (8, 6), exact.
        let mut p = input("1,1", "(2,0),0");
        p.normal = Some(NormalGiven::Geometry {
            radii: ["2".parse().unwrap(), "3".parse().unwrap()],
            b: "3".parse().unwrap(),
        });
        let posed = p.pose().unwrap();
        assert_eq!(posed.statement.normal, Some(vec![int(8), int(6)]));
        p.normal = Some(NormalGiven::Geometry {
            radii: ["2".parse().unwrap(), "3".parse().unwrap()],
            b: "6".parse().unwrap(),
        });
        let e = p.pose().unwrap_err().to_string();
        assert!(e.contains("miss"), "{e}");
    }

    #[test]
    fn exact_refuses_irrational_directions() {
        let mut p = input("1,1", "6 @ 30deg,0");
        p.exact = true;
        let e = p.pose().unwrap_err().to_string();
        assert!(e.contains("irrational"), "{e}");
        p.exact = false;
        assert!(p.pose().unwrap().statement.inexact);
    }
}
