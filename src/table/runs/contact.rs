//! Sweeps of `collide contact`: any of its numbers as a parameter, one row per run with the
//! run's summary: per contact (in order of start) its restitution, duration, deepest overlap
//! and approach speed; the energy dissipated; the work (steps, rejected steps, right-hand sides,
//! Jacobians); the final velocities and positions; and, where one exists (a single possible
//! contact, linear or elastic Hertz), the error against the exact answer.

use super::{Kind, Knob};
use crate::contact::{self, ContactRun, Damping, Laws, Settings, Setup, work};
use crate::line::inertia::Mass;
use crate::table::row::ValueProblem;
use crate::track::Body;
use crate::values::number::Number;

/// A contact run to sweep: the base the grid's values go into.
#[derive(Clone, Debug)]
pub struct ContactSweep {
    pub bodies: Vec<Body>,
    pub walls: (Option<f64>, Option<f64>),
    pub laws: Laws,
    pub settings: Settings,
}

/// A finished run, the exact final velocities where known, and the initial relative speed.
pub struct Outcome {
    run: ContactRun,
    exact: Option<Vec<f64>>,
    speed: f64,
}

/// A summary column; contacts and bodies counted from 1.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Col {
    Contacts,
    E(usize),
    Duration(usize),
    MaxOverlap(usize),
    Speed(usize),
    Start(usize),
    Dissipated,
    EnergyStart,
    EnergyEnd,
    Time,
    Fin(usize),
    XFin(usize),
    Steps,
    Rejected,
    RhsEvals,
    Jacobians,
    VError,
}

const SCALARS: &[&str] = &[
    "stiffness",
    "damping",
    "zeta",
    "e",
    "wall_stiffness",
    "wall_damping",
    "wall_zeta",
    "wall_restitution",
    "left_wall",
    "right_wall",
    "until",
    "dt",
    "tol",
];

/// Named columns, and the prefixes of numbered ones (`e_1`, `fin2`).
const NAMED: [(&str, Col); 10] = [
    ("contacts", Col::Contacts),
    ("dissipated", Col::Dissipated),
    ("energy_start", Col::EnergyStart),
    ("energy_end", Col::EnergyEnd),
    ("time", Col::Time),
    ("steps", Col::Steps),
    ("rejected", Col::Rejected),
    ("rhs_evals", Col::RhsEvals),
    ("jacobians", Col::Jacobians),
    ("v_error", Col::VError),
];

impl ContactSweep {
    /// The base's setup: the possible contacts decide the default columns.
    fn setup(&self) -> Setup {
        Setup::new(self.bodies.clone(), self.walls, self.laws)
    }
}

fn range(ok: bool, what: &str) -> Result<(), ValueProblem> {
    if ok {
        Ok(())
    } else {
        Err(ValueProblem::Range(what.into()))
    }
}

impl Kind for ContactSweep {
    type Out = Outcome;
    type Col = Col;

    fn scalars(&self) -> &'static [&'static str] {
        SCALARS
    }

    fn bodies(&self) -> usize {
        self.bodies.len()
    }

    fn check(&self, knob: Knob, n: &Number) -> Result<(), ValueProblem> {
        let v = n.value();
        match knob {
            Knob::Mass(_) => drop(Mass::new(n.clone())?),
            Knob::Size(_) => range(v >= 0.0, "a size must be >= 0")?,
            Knob::Position(_) | Knob::Velocity(_) => {}
            Knob::Named("stiffness" | "wall_stiffness") => {
                range(v > 0.0, "a stiffness must be > 0")?
            }
            Knob::Named("damping" | "zeta" | "wall_damping" | "wall_zeta") => {
                range(v >= 0.0, "damping must be >= 0")?
            }
            Knob::Named("e" | "wall_restitution") => range(
                v > 0.0 && v <= 1.0,
                "a linear contact's restitution must be in (0, 1]",
            )?,
            Knob::Named("until") => range(v >= 0.0, "until must be >= 0")?,
            Knob::Named("dt") => range(v > 0.0, "dt must be > 0")?,
            Knob::Named("tol") => range((1e-14..=0.1).contains(&v), "tol must be in [1e-14, 0.1]")?,
            Knob::Named(_) => {}
        }
        Ok(())
    }

    fn run(&self, point: &[(Knob, f64)]) -> Result<Outcome, String> {
        let mut base = self.clone();
        for &(knob, v) in point {
            match knob {
                Knob::Mass(i) => {
                    base.bodies[i].m = Number::from_f64(v)
                        .map_err(|e| e.to_string())
                        .and_then(|n| Mass::new(n).map_err(|e| e.to_string()))?;
                }
                Knob::Position(i) => base.bodies[i].x = v,
                Knob::Velocity(i) => base.bodies[i].v = v,
                Knob::Size(i) => base.bodies[i].size = v,
                Knob::Named("stiffness") => base.laws.k = v,
                Knob::Named("damping") => base.laws.damping = Some(Damping::Absolute(v)),
                Knob::Named("zeta") => base.laws.damping = Some(Damping::Zeta(v)),
                Knob::Named("e") => base.laws.damping = Some(Damping::Restitution(v)),
                Knob::Named("wall_stiffness") => base.laws.wall_k = Some(v),
                Knob::Named("wall_damping") => {
                    base.laws.wall_damping = Some(Damping::Absolute(v));
                }
                Knob::Named("wall_zeta") => base.laws.wall_damping = Some(Damping::Zeta(v)),
                Knob::Named("wall_restitution") => {
                    base.laws.wall_damping = Some(Damping::Restitution(v));
                }
                Knob::Named("left_wall") => base.walls.0 = Some(v),
                Knob::Named("right_wall") => base.walls.1 = Some(v),
                Knob::Named("until") => base.settings.until = Some(v),
                Knob::Named("dt") => base.settings.dt = Some(v),
                Knob::Named("tol") => base.settings.tol = Some(v),
                Knob::Named(other) => return Err(format!("'{other}' is not a parameter")),
            }
        }
        let setup = base.setup();
        let run = contact::simulate(&setup, &base.settings).map_err(|e| e.to_string())?;
        // The exact answer exists for a whole run only (no --until).
        let exact = match base.settings.until {
            None => work::exact(&setup).ok().flatten(),
            Some(_) => None,
        };
        Ok(Outcome {
            run,
            exact,
            speed: setup.speed_scale(),
        })
    }

    fn column(&self, name: &str) -> Option<Col> {
        if let Some((_, c)) = NAMED.iter().find(|(n, _)| *n == name) {
            return Some(*c);
        }
        let numbered = |prefix: &str| -> Option<usize> {
            let k: usize = name.strip_prefix(prefix)?.parse().ok()?;
            (k >= 1).then_some(k)
        };
        let body = |prefix: &str| numbered(prefix).filter(|i| *i <= self.bodies.len());
        type Numbered = (&'static str, fn(usize) -> Col);
        let per_contact: [Numbered; 5] = [
            ("e_", Col::E),
            ("duration_", Col::Duration),
            ("max_overlap_", Col::MaxOverlap),
            ("speed_", Col::Speed),
            ("start_", Col::Start),
        ];
        for (prefix, col) in per_contact {
            if let Some(k) = numbered(prefix) {
                return Some(col(k));
            }
        }
        body("fin")
            .map(Col::Fin)
            .or_else(|| body("xfin").map(Col::XFin))
    }

    fn defaults(&self) -> Vec<String> {
        let k = self.setup().contacts().len();
        let n = self.bodies.len();
        let mut out = vec!["contacts".to_string()];
        for prefix in ["e_", "duration_", "max_overlap_"] {
            out.extend((1..=k).map(|i| format!("{prefix}{i}")));
        }
        out.push("dissipated".into());
        out.extend((1..=n).map(|i| format!("fin{i}")));
        out.push("steps".into());
        if k == 1 {
            out.push("v_error".into());
        }
        out
    }

    fn column_forms(&self) -> String {
        let n = self.bodies.len();
        format!(
            "{}, e_K, duration_K, max_overlap_K, speed_K, start_K (the K-th contact), fin1..fin{n}, \
             xfin1..xfin{n}",
            NAMED.iter().map(|(n, _)| *n).collect::<Vec<_>>().join(", ")
        )
    }

    /// The contacts and the solver's work: steps, rejected steps, right-hand sides, Jacobians.
    fn counts(&self, col: Col) -> bool {
        matches!(
            col,
            Col::Contacts | Col::Steps | Col::Rejected | Col::RhsEvals | Col::Jacobians
        )
    }

    fn value(&self, col: Col, o: &Outcome) -> Option<f64> {
        let run = &o.run;
        let contact = |k: usize| run.contacts.get(k - 1);
        Some(match col {
            Col::Contacts => run.contacts.len() as f64,
            Col::E(k) => contact(k)?.restitution?,
            Col::Duration(k) => contact(k)?.duration?,
            Col::MaxOverlap(k) => contact(k)?.max_overlap,
            Col::Speed(k) => contact(k)?.speed,
            Col::Start(k) => contact(k)?.start,
            Col::Dissipated => run.energy.dissipated,
            Col::EnergyStart => run.energy.start,
            Col::EnergyEnd => run.energy.end,
            Col::Time => run.time,
            Col::Fin(i) => run.v[i - 1],
            Col::XFin(i) => run.x[i - 1],
            Col::Steps => run.stats.steps as f64,
            Col::Rejected => run.stats.rejected as f64,
            Col::RhsEvals => run.stats.rhs_evals as f64,
            Col::Jacobians => run.stats.jacobians as f64,
            Col::VError => {
                let exact = o.exact.as_ref()?;
                let d = run
                    .v
                    .iter()
                    .zip(exact)
                    .map(|(a, b)| (a - b).abs())
                    .fold(0.0, f64::max);
                (o.speed > 0.0).then(|| d / o.speed)?
            }
        })
    }
}
