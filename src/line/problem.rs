//! A problem as typed, on the command line or in a scene: masses (or a tensor), velocities,
//! perhaps final velocities, a restitution; numbers with units or `?` for unknowns (issue 8).
//! Units are resolved first; the unknowns are then solved exactly (`unknowns`), and the result
//! is an ordinary `Case`.

use crate::values::rational::Q;

use crate::line::case::Case;
use crate::line::inertia::{InertiaError, InertiaTensor, Mass, MassError};
use crate::line::knowns::Laws;
use crate::line::restitution::{Restitution, RestitutionError};
use crate::line::separation::{Kind, Separation};
use crate::line::unknowns::{Solved, UnknownError, Var};
use crate::line::wall::{WallCase, WallProblem};
use crate::values::derived::Derived;
use crate::values::number::{Given, Number, NumberError};
use crate::values::units::{Pair, Quantity, ResolveError, Unit, Units, resolve};

/// The typed values of a problem.
#[derive(Clone, Debug)]
pub struct Problem {
    /// `None` with a general tensor instead.
    pub masses: Option<Pair>,
    pub velocities: Pair,
    /// Final velocities, when the problem gives them.
    pub fin: Option<Pair>,
    /// Not given: elastic, or unknown when FIN is given.
    pub restitution: Option<Given<Restitution>>,
    /// Convert to kg and m/s.
    pub si: bool,
    /// `g` for velocities typed as heights (default 9.80665 m/s^2).
    pub gravity: Option<Number>,
    /// The unit energies are printed in (`--energy-unit`), when not the case's own.
    pub energy_unit: Option<&'static crate::values::units::EnergyUnit>,
    /// Exact arithmetic follows (`--exact`): a velocity typed as a height whose speed
    /// `sqrt(2 g h)` is irrational is refused, since no rational holds it.
    pub exact: bool,
    /// What the problem gives beyond masses, velocities and restitution (`line::knowns`).
    pub knowns: Knowns,
    /// The unit speeds are printed in (`--velocity-unit`): every velocity is converted to it
    /// exactly before the problem is solved, so every output renders the one solution in it.
    pub velocity_unit: Option<&'static Unit>,
}

/// Knowns a problem may give beyond masses, velocities and restitution, as typed.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Knowns {
    /// One body passes through the other (`--pass-through`).
    pub pass_through: bool,
    /// The impulse on body 2 (`--impulse`).
    pub impulse: Option<Derived>,
    /// The energy released in a separation (`--released`).
    pub released: Option<Derived>,
    /// The total mass `m1 + m2`, with one mass `?` (`--total-mass`).
    pub total_mass: Option<Quantity>,
    /// The relative speed of separation `|f1 - f2|`: `e = |S| / |v1 - v2|`
    /// (`--separation-speed`).
    pub separation_speed: Option<Quantity>,
}

impl Knowns {
    /// The flag of the first known given, for errors (`None`: none given).
    pub fn first_flag(&self) -> Option<&'static str> {
        let flag = |d: &Option<Derived>| d.as_ref().map(|d| d.kind.flag());
        (self.pass_through.then_some("--pass-through"))
            .or(flag(&self.impulse))
            .or(flag(&self.released))
            .or(self.total_mass.as_ref().map(|_| "--total-mass"))
            .or(self.separation_speed.as_ref().map(|_| "--separation-speed"))
    }
}

/// What a solved problem describes.
#[derive(Clone, Debug)]
#[allow(clippy::large_enum_variant)] // one per run
pub enum Posed {
    /// A collision (with what was solved, when the problem had unknowns or gave FIN).
    Collision(Case, Option<Solved>),
    /// Bodies that start together and are pushed apart: `e` is undefined (an explosion, a
    /// recoil, a released spring).
    Separation(Separation, Solved),
    /// A body against a wall (an immovable body), with what was solved.
    Wall(WallCase, Option<Solved>),
    /// A separation with the energy released given and both final velocities unknown: the
    /// energy fixes the relative speed, not which piece ends up ahead, so there are two (body 1
    /// on the left, then on the right).
    Separations(Box<[(Separation, Solved); 2]>),
}

impl Posed {
    /// The units the event's numbers are in.
    pub fn units(&self) -> &Units {
        match self {
            Posed::Collision(case, _) => &case.units,
            Posed::Separation(s, _) => &s.units,
            Posed::Separations(pair) => &pair[0].0.units,
            Posed::Wall(w, _) => &w.units,
        }
    }
}

/// Why a problem cannot be solved.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum ProblemError {
    #[error("give --masses M1,M2 or --inertia 'M11,M12;M21,M22'")]
    NoMasses,
    #[error("unknowns and --fin need --masses M1,M2 (not --inertia)")]
    UnknownsNeedMasses,
    #[error("{0} needs --masses M1,M2 (not --inertia): its laws hold each body's own mass")]
    KnownNeedsMasses(&'static str),
    #[error(
        "'?' marks an unknown: `collide solve` solves for unknowns (with --fin for final velocities)"
    )]
    UnknownsOnlyInSolve,
    #[error("a wall (an immovable body) is for `collide solve` (and `collide track --left-wall`)")]
    WallOnlyInSolve,
    #[error(
        "{0}: one body is a wall (immovable), so momentum says nothing; {0} needs two movable bodies"
    )]
    KnownWithWall(&'static str),
    #[error(
        "--released {0}: the energy released is a known of bodies that start together (an \
         explosion, a recoil: V1 = V2); {1}"
    )]
    ReleasedNeedsSeparation(String, String),
    #[error(
        "--released {text}: the pieces separate at the relative speed sqrt(2 E / mu) = \
         sqrt({square}), which is irrational, and exact arithmetic (--exact) holds rationals \
         only: compute in binary64 (within an ulp), or choose E with 2 E / mu a square"
    )]
    IrrationalRelease { text: String, square: String },
    #[error(
        "--total-mass gives m1 + m2: mark exactly one mass '?' (-m '?,5.9 kg'), the one it fixes"
    )]
    TotalMass,
    #[error(
        "--velocity-unit {0}: the velocity {1} has no unit to convert from: give every velocity \
         its unit ('35 mph')"
    )]
    VelocityUnit(&'static str, String),
    #[error("--separation-speed: {0}")]
    SeparationSpeed(&'static str),
    #[error("two walls: at most one body can be immovable")]
    TwoWalls,
    #[error("a wall needs --masses M1,wall (not --inertia)")]
    WallNeedsMasses,
    #[error("the ball's mass against a wall: an impulse needs it (give it with -m)")]
    WallBallMass,
    #[error("gravity {0}: expected a number > 0 in m/s^2 (9.80665 standard, 9.8 or 9.81)")]
    Gravity(String),
    #[error(
        "the speed of a fall through {height} m (or of a slide, with mu d = {height} m), \
         sqrt(2 g h) = sqrt({two_gh}) m/s, is irrational, \
         and exact arithmetic (--exact, a scene's exact = true) holds rationals only: compute in \
         binary64 (the speed within an ulp), or choose g and h with 2 g h a square (g = 10, \
         h = 0.2 m: 2 m/s)"
    )]
    IrrationalSpeed { height: String, two_gh: String },
    #[error("{var} = {text}: {error}")]
    Solved {
        var: Var,
        text: String,
        error: NumberError,
    },
    #[error(transparent)]
    Resolve(#[from] ResolveError),
    #[error(transparent)]
    Derived(#[from] crate::values::derived::DerivedError),
    #[error(transparent)]
    EnergyUnit(#[from] crate::values::units::EnergyUnitError),
    #[error(transparent)]
    Unknown(#[from] UnknownError),
    #[error(transparent)]
    Mass(#[from] MassError),
    #[error(transparent)]
    Inertia(#[from] InertiaError),
    #[error(transparent)]
    Restitution(#[from] RestitutionError),
}

impl Problem {
    /// Whether a typed value is `?`.
    pub fn has_unknowns(&self) -> bool {
        let pair = |p: &Pair| p.0.iter().any(Given::is_unknown);
        self.masses.as_ref().is_some_and(pair)
            || pair(&self.velocities)
            || self.fin.as_ref().is_some_and(pair)
            || self.restitution.as_ref().is_some_and(Given::is_unknown)
    }

    /// The case, with units resolved; a problem with unknowns is refused (only `collide solve`
    /// solves for them).
    pub fn into_case(self, inertia: Option<InertiaTensor>) -> Result<Case, ProblemError> {
        if self.has_unknowns() {
            return Err(ProblemError::UnknownsOnlyInSolve);
        }
        match self.solve(inertia)? {
            Posed::Collision(case, _) => Ok(case),
            Posed::Separation(..) | Posed::Separations(..) => {
                Err(ProblemError::UnknownsOnlyInSolve)
            }
            Posed::Wall(..) => Err(ProblemError::WallOnlyInSolve),
        }
    }

    /// Resolves units and solves any unknowns; returns the case, and what was solved when the
    /// problem had unknowns or gave FIN (or the separation, when the bodies start together).
    pub fn solve(&self, inertia: Option<InertiaTensor>) -> Result<Posed, ProblemError> {
        let masses: Vec<_> = self.masses.as_ref().map_or(Vec::new(), |p| p.0.to_vec());
        if masses.is_empty() && inertia.is_none() {
            return Err(ProblemError::NoMasses);
        }
        let mut velocities = self.velocities.0.to_vec();
        if let Some(f) = &self.fin {
            velocities.extend(f.0.iter().cloned());
        }
        // Heights become speeds with g (exact), before units are resolved.
        let g = self.g()?;
        let mut speeds = Vec::with_capacity(velocities.len());
        for v in velocities {
            speeds.push(match v {
                Given::Known(q) => {
                    let (speed, rational) = q
                        .with_gravity(&g)
                        .map_err(|e| ProblemError::Resolve(e.into()))?;
                    if self.exact && !rational {
                        let h = num_traits::Signed::abs(&q.number.exact());
                        let two_gh = crate::values::rational::int(2) * &g * &h;
                        return Err(ProblemError::IrrationalSpeed {
                            height: crate::values::quantity::significant(&h, 15),
                            two_gh: crate::values::quantity::significant(&two_gh, 15),
                        });
                    }
                    Given::Known(speed)
                }
                other => other,
            });
        }
        let mut velocities = speeds;
        // The speed of separation is resolved with the velocities, in their unit.
        let separation_typed = self.knowns.separation_speed.clone().map(Given::Known);
        let has_separation = separation_typed.is_some();
        velocities.extend(separation_typed);
        if let Some(unit) = self.velocity_unit {
            velocities = in_unit(velocities, unit)?;
        }
        // The total mass is resolved with the masses, in their unit; one of them must be `?`.
        let total_typed = self.knowns.total_mass.clone().map(Given::Known);
        if total_typed.is_some() && masses.iter().filter(|m| m.is_unknown()).count() != 1 {
            return Err(ProblemError::TotalMass);
        }
        let (mut m, mut v, units) = resolve(
            &[masses.clone(), total_typed.into_iter().collect()].concat(),
            &velocities,
            self.si,
        )?;
        let separation = match has_separation {
            true => v.pop().and_then(|s| s.known().map(Number::exact)),
            false => None,
        };
        let total = match self.knowns.total_mass {
            Some(_) => m.pop().and_then(|t| t.known().map(Number::exact)),
            None => None,
        };
        let units = match self.energy_unit {
            Some(u) => units.with_energy_unit(u)?,
            // Speeds in another unit keep energies in J when the masses have a unit.
            None if self.velocity_unit.is_some() && units.mass.is_some() => {
                units.with_energy_unit(crate::values::units::energy_unit("J")?)?
            }
            None => units,
        };
        if let Some(wall) = m.iter().position(Given::is_wall) {
            if inertia.is_some() {
                return Err(ProblemError::WallNeedsMasses);
            }
            // An impulse is the ball's own law; the others need two movable bodies.
            let beyond_impulse = Knowns {
                impulse: None,
                ..self.knowns.clone()
            };
            if let Some(flag) = beyond_impulse.first_flag() {
                return Err(ProblemError::KnownWithWall(flag));
            }
            return self.solve_wall(wall, &m, &v, units);
        }
        let laws = Laws {
            total_mass: total,
            ..self.laws(&units)?
        };
        // Any known beyond masses and velocities (--released too, which no linear law carries)
        // makes the final velocities unknowns: `--released E` alone is `--fin '?,?'`. The total
        // mass is a known of the masses: it leaves e as given (elastic by default).
        let knowns = Knowns {
            total_mass: None,
            separation_speed: None,
            ..self.knowns.clone()
        }
        .first_flag()
        .is_some();
        let restitution = match separation {
            Some(s) => Some(Given::Known(restitution_of_separation(&s, &v)?)),
            None => self.restitution.clone(),
        };
        let e = match &restitution {
            Some(r) => r.clone().map(|r| r.number().clone()),
            None if self.fin.is_some() || knowns => Given::Unknown,
            None => Given::Known(Restitution::elastic().number().clone()),
        };
        if !(self.fin.is_some() || self.has_unknowns() || knowns) {
            let case = build(&m, &v, e, inertia, units)?;
            return Ok(Posed::Collision(case, None));
        }
        if let Some(flag) = self.knowns.first_flag().filter(|_| inertia.is_some()) {
            return Err(ProblemError::KnownNeedsMasses(flag));
        }
        if inertia.is_some() || m.is_empty() {
            return Err(ProblemError::UnknownsNeedMasses);
        }
        let fin = if self.fin.is_some() {
            v[2..4].to_vec()
        } else {
            vec![Given::Unknown, Given::Unknown]
        };
        let known: Vec<Given<Number>> = m
            .iter()
            .chain(&v[..2])
            .chain(&fin)
            .cloned()
            .chain([e])
            .collect();
        let exact: [Option<Q>; 7] = std::array::from_fn(|i| known[i].known().map(Number::exact));
        if let Some(released) = &self.knowns.released {
            let e = match (&released.unit_si, units.energy_scale()) {
                // A plain number is in the unit energies are printed in (`--energy-unit kJ`),
                // as the Units line says; the report's energies are that unit over `scale`.
                (None, Some(scale)) => released.number.exact() / scale,
                _ => released.in_units(units.energy_si().as_ref(), &units)?,
            };
            return self.solve_released(&known, exact, (released, e), &laws, units);
        }
        let solved = crate::line::knowns::solve(exact, &laws)?;
        // A value as typed when it was given (the header repeats it), else its solved fraction.
        let number = |var: Var| -> Result<Given<Number>, ProblemError> {
            if let Some(n) = known[var as usize].known() {
                return Ok(Given::Known(n.clone()));
            }
            solved_number(var, solved.get(var)).map(Given::Known)
        };
        let m = vec![number(Var::M1)?, number(Var::M2)?];
        let v = vec![number(Var::V1)?, number(Var::V2)?];
        if solved.separation || solved.pass_through {
            let separation = Problem::momentum_only(&known, &solved, units)?;
            return Ok(Posed::Separation(separation, solved));
        }
        let case = build(&m, &v, number(Var::E)?, None, units)?;
        Ok(Posed::Collision(case, Some(solved)))
    }
}

impl Problem {
    /// `g` for velocities typed as heights: as given (positive), or standard gravity.
    pub fn g(&self) -> Result<Q, ProblemError> {
        Ok(match &self.gravity {
            Some(g) if g.value() > 0.0 => g.exact(),
            Some(g) => return Err(ProblemError::Gravity(g.to_string())),
            None => crate::values::units::STANDARD_GRAVITY
                .parse::<Number>()
                .map(|n| n.exact())
                .unwrap_or_default(),
        })
    }

    /// The laws the knowns bring, in the case's units.
    fn laws(&self, units: &Units) -> Result<Laws, ProblemError> {
        let impulse = match &self.knowns.impulse {
            Some(j) => Some(j.in_units(units.force_scale().as_ref(), units)?),
            None => None,
        };
        Ok(Laws {
            pass_through: self.knowns.pass_through,
            impulse,
            total_mass: None,
        })
    }

    /// A separation with the energy released `e` given: both final velocities unknown give
    /// two solutions (`separation::split`); otherwise momentum solves one unknown and the energy
    /// is checked.
    fn solve_released(
        &self,
        known: &[Given<Number>],
        exact: [Option<Q>; 7],
        (typed, e): (&Derived, Q),
        laws: &Laws,
        units: Units,
    ) -> Result<Posed, ProblemError> {
        let refuse = |why: &str| {
            Err(ProblemError::ReleasedNeedsSeparation(
                typed.text.clone(),
                why.to_string(),
            ))
        };
        let (v1, v2) = (&exact[Var::V1 as usize], &exact[Var::V2 as usize]);
        match (v1, v2) {
            (Some(a), Some(b)) if a == b => {}
            (Some(_), Some(_)) => {
                return refuse("here V1 != V2: for a collision give -e or the final velocities");
            }
            _ => return refuse("give both initial velocities"),
        }
        let [m1, m2] = [Var::M1, Var::M2].map(|v| exact[v as usize].clone());
        let both_unknown = exact[Var::F1 as usize].is_none() && exact[Var::F2 as usize].is_none();
        if let (true, Some(m1), Some(m2)) = (both_unknown, m1, m2) {
            let v = exact[Var::V1 as usize].clone().unwrap_or_default();
            let fins = crate::line::separation::split([&m1, &m2], &v, &e, self.exact).map_err(
                |square| ProblemError::IrrationalRelease {
                    text: typed.text.clone(),
                    square: crate::values::quantity::significant(&square, 15),
                },
            )?;
            let solution = |fin: [Q; 2]| -> Result<(Separation, Solved), ProblemError> {
                let mut values = exact.clone().map(Option::unwrap_or_default);
                [values[Var::F1 as usize], values[Var::F2 as usize]] = fin;
                let solved = Solved {
                    values,
                    unknowns: vec![Var::F1, Var::F2],
                    checks: Vec::new(),
                    separation: true,
                    wall: None,
                    pass_through: false,
                };
                Ok((
                    Problem::momentum_only(known, &solved, units.clone())?,
                    solved,
                ))
            };
            let [a, b] = fins;
            return Ok(Posed::Separations(Box::new([solution(a)?, solution(b)?])));
        }
        let mut solved = crate::line::knowns::solve(exact.clone(), laws)?;
        if !solved.separation {
            return refuse("the final velocities are equal, so nothing was released");
        }
        let separation = Problem::momentum_only(known, &solved, units)?;
        solved.checks.push(("energy", separation.released() - &e));
        Ok(Posed::Separation(separation, solved))
    }

    /// The separation or pass-through of solved values (a value as typed when it was given,
    /// `known`, else its solved fraction).
    fn momentum_only(
        known: &[Given<Number>],
        solved: &Solved,
        units: Units,
    ) -> Result<Separation, ProblemError> {
        let number = |var: Var| match known[var as usize].known() {
            Some(n) => Ok(n.clone()),
            None => solved_number(var, solved.get(var)),
        };
        let [m1, m2] = [Mass::new(number(Var::M1)?)?, Mass::new(number(Var::M2)?)?];
        Ok(Separation {
            masses: [m1.number().clone(), m2.number().clone()],
            velocities: [number(Var::V1)?, number(Var::V2)?],
            fin: [solved.get(Var::F1).clone(), solved.get(Var::F2).clone()],
            units,
            kind: if solved.pass_through {
                Kind::PassThrough
            } else {
                Kind::Apart
            },
        })
    }

    /// A ball against a wall (body `wall`): restitution alone, exact.
    fn solve_wall(
        &self,
        wall: usize,
        m: &[Given<Number>],
        v: &[Given<Number>],
        units: Units,
    ) -> Result<Posed, ProblemError> {
        let ball = 1 - wall;
        if m[ball].is_wall() {
            return Err(ProblemError::TwoWalls);
        }
        let q = |x: Option<&Given<Number>>| x.and_then(Given::known).map(Number::exact);
        // `--impulse J` is the impulse on body 2: on the ball it is J when the ball is body 2,
        // -J when it is body 1 (the wall, body 2, takes J).
        let impulse = match &self.knowns.impulse {
            Some(j) => Some(j.in_units(units.force_scale().as_ref(), &units)?),
            None => None,
        };
        let j_ball = impulse.map(|j| if ball == 1 { j } else { -j });
        // The ball's mass; `?` only when nothing needs it: a rebound asked in speeds and e
        // does not depend on it (issue 45 §5), an impulse does.
        let mass = match &m[ball] {
            Given::Known(n) => Some(Mass::new(n.clone())?),
            _ if j_ball.is_some() => return Err(ProblemError::WallBallMass),
            _ => None,
        };
        let e = match &self.restitution {
            Some(r) => r.known().map(|r| r.number().exact()),
            None if self.fin.is_some() || j_ball.is_some() => None,
            None => Some(crate::values::rational::int(1)),
        };
        let given_fin = self.fin.is_some();
        let fin = |i: usize| if given_fin { q(v.get(2 + i)) } else { None };
        let (ball_v, ball_f, impulse_check) = match &mass {
            Some(mass) => impulse_on_ball(
                q(v.get(ball)),
                fin(ball),
                j_ball.as_ref(),
                &mass.number().exact(),
            ),
            None => (q(v.get(ball)), fin(ball), None),
        };
        let problem = WallProblem {
            ball: (ball_v, ball_f),
            wall: (q(v.get(wall)), fin(wall)),
            e: e.clone(),
            side: wall,
        };
        let s = crate::line::wall::solve(problem)?;
        let ((bv, bf), (wv, wf)) = crate::line::wall::vars(wall);
        // A value as typed when it was given, else its solved value.
        let number =
            |var: Var, x: &Q, typed: Option<&Given<Number>>| match typed.and_then(Given::known) {
                Some(n) => Ok(n.clone()),
                None => solved_number(var, x),
            };
        let mut velocities = [
            number(wv, &s.w, v.get(wall))?,
            number(wv, &s.w, v.get(wall))?,
        ];
        velocities[ball] = number(bv, &s.v, v.get(ball))?;
        let typed_e = self.restitution.as_ref().and_then(Given::known);
        let restitution = match typed_e {
            Some(r) => r.clone(),
            None => Restitution::new(solved_number(Var::E, &s.e)?)?,
        };
        let case = WallCase {
            wall,
            mass: mass.as_ref().map(|m| m.number().clone()),
            velocities,
            restitution,
            units,
        };
        if !(given_fin || self.has_unknowns() || j_ball.is_some()) {
            return Ok(Posed::Wall(case, None));
        }
        // What was solved, in the two-body variables (the wall's mass means nothing).
        let mut values: [Q; 7] = Default::default();
        // M1 or M2; without a mass 0, never shown (the mass is not among the unknowns solved).
        values[ball] = mass.map(|m| m.number().exact()).unwrap_or_default();
        values[bv as usize] = s.v.clone();
        values[bf as usize] = s.f.clone();
        values[wv as usize] = s.w.clone();
        values[wf as usize] = s.w.clone();
        values[Var::E as usize] = s.e.clone();
        let was_unknown = |var: Var| match var {
            Var::E => e.is_none(),
            _ if var == bv => q(v.get(ball)).is_none(),
            _ if var == bf => fin(ball).is_none(),
            _ if var == wv => q(v.get(wall)).is_none(),
            _ if var == wf => fin(wall).is_none() && given_fin,
            _ => false,
        };
        let unknowns = Var::ALL.into_iter().filter(|x| was_unknown(*x)).collect();
        let mut checks: Vec<(&'static str, Q)> = s
            .residual
            .map(|r| vec![("restitution", r)])
            .unwrap_or_default();
        if let Some(r) = impulse_check {
            checks.push((if ball == 0 { "impulse1" } else { "impulse2" }, r));
        }
        let solved = Solved {
            values,
            unknowns,
            checks,
            separation: false,
            wall: Some(wall),
            pass_through: false,
        };
        Ok(Posed::Wall(case, Some(solved)))
    }
}

/// The ball's law of an impulse `j` on it (`j = m (f - v)`): its unknown velocity from the
/// other, or, with both given, the residual `m (f - v) - j` to check. No impulse, or neither
/// velocity given: as they are.
fn impulse_on_ball(
    v: Option<Q>,
    f: Option<Q>,
    j: Option<&Q>,
    m: &Q,
) -> (Option<Q>, Option<Q>, Option<Q>) {
    match (v, f, j) {
        (Some(v), None, Some(j)) => {
            let f = &v + j / m;
            (Some(v), Some(f), None)
        }
        (None, Some(f), Some(j)) => (Some(&f - j / m), Some(f), None),
        (Some(v), Some(f), Some(j)) => {
            let r = m * (&f - &v) - j;
            (Some(v), Some(f), Some(r))
        }
        (v, f, _) => (v, f, None),
    }
}

/// A solved value as a `Number` (`quantity::number_of`), its error naming the variable.
fn solved_number(var: Var, q: &Q) -> Result<Number, ProblemError> {
    crate::values::quantity::number_of(q)
        .map(Number::answer)
        .map_err(|error| ProblemError::Solved {
            var,
            text: crate::values::quantity::fraction(q),
            error,
        })
}

/// Velocities converted exactly to `unit` (`--velocity-unit`); each needs a unit of its own
/// (a bare 0 is 0 in any).
fn in_unit(
    velocities: Vec<Given<Quantity>>,
    unit: &'static Unit,
) -> Result<Vec<Given<Quantity>>, ProblemError> {
    velocities
        .into_iter()
        .map(|v| match v {
            Given::Known(q) if q.number.value() == 0.0 && q.unit.is_none() => Ok(Given::Known(q)),
            Given::Known(q) => {
                let Some(from) = q.unit else {
                    return Err(ProblemError::VelocityUnit(
                        unit.name(),
                        q.number.to_string(),
                    ));
                };
                let value = q.number.exact() * from.si() / unit.si();
                let number = crate::values::quantity::number_of(&value).map_err(|error| {
                    ProblemError::Solved {
                        var: Var::V1,
                        text: crate::values::quantity::fraction(&value),
                        error,
                    }
                })?;
                Ok(Given::Known(Quantity {
                    number,
                    unit: Some(unit),
                    height: false,
                }))
            }
            other => Ok(other),
        })
        .collect()
}

/// `e = |S| / |v1 - v2|` from the relative speed of separation `S` (issue 42 section 5): both
/// initial velocities must be given and differ (bodies that start together have no e).
fn restitution_of_separation(s: &Q, v: &[Given<Number>]) -> Result<Restitution, ProblemError> {
    use num_traits::Signed;
    let (Some(v1), Some(v2)) = (v[0].known(), v[1].known()) else {
        return Err(ProblemError::SeparationSpeed(
            "give both initial velocities (e = |S| / |v1 - v2|)",
        ));
    };
    let approach = (v1.exact() - v2.exact()).abs();
    if approach.is_zero() {
        return Err(ProblemError::SeparationSpeed(
            "the bodies start together (v1 = v2), so e is undefined: a separation from rest is \
             fixed by --fin or --released, not by e",
        ));
    }
    let e = solved_number(Var::E, &(s.abs() / approach))?;
    Ok(Restitution::new(e)?)
}

/// The case of resolved values, none of them unknown.
fn build(
    m: &[Given<Number>],
    v: &[Given<Number>],
    e: Given<Number>,
    inertia: Option<InertiaTensor>,
    units: Units,
) -> Result<Case, ProblemError> {
    let need = |x: &Given<Number>| x.known().cloned().ok_or(ProblemError::UnknownsOnlyInSolve);
    let inertia = match inertia {
        Some(t) if m.is_empty() => t,
        _ => {
            let mass =
                |x: &Given<Number>| -> Result<Mass, ProblemError> { Ok(Mass::new(need(x)?)?) };
            InertiaTensor::diagonal(&mass(&m[0])?, &mass(&m[1])?)?
        }
    };
    let e = Restitution::new(need(&e)?)?;
    let mut case = Case::new(inertia, [need(&v[0])?, need(&v[1])?], e);
    case.units = units;
    Ok(case)
}
