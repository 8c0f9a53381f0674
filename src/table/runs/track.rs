//! Sweeps of `collide track`: any of its numbers as a parameter, one row per run with the run's
//! summary: collisions (between bodies, with walls, simultaneous instants), the final time,
//! velocities and positions, the energy and momentum at both ends with the energy's relative
//! drift, and for pi billiards the exact count (`track::pi`).

use super::{Kind, Knob};
use crate::line::inertia::Mass;
use crate::line::restitution::Restitution;
use crate::table::row::ValueProblem;
use crate::track::{Limits, Run, Stop, Track, pi};
use crate::values::number::Number;

/// A track run to sweep: the base the grid's values go into.
#[derive(Clone, Debug)]
pub struct TrackSweep {
    pub track: Track,
    pub limits: Limits,
    /// The walls' restitution as given (`--wall-restitution`); `None`: the walls take `e`, the
    /// base's or a varied one ([`Track::walls_restitution`]), as `-e` alone would give them.
    pub wall_restitution: Option<f64>,
}

/// A summary column; bodies counted from 1.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Col {
    Collisions,
    PairCollisions,
    WallCollisions,
    Simultaneous,
    Time,
    Fin(usize),
    XFin(usize),
    EnergyStart,
    EnergyEnd,
    Drift,
    MomentumStart,
    MomentumEnd,
    /// Pi billiards' exact count `ceil(pi/theta) - 1`.
    Pi,
    /// Where a Zeno sequence accumulates (its time).
    Accumulation,
}

const SCALARS: &[&str] = &[
    "e",
    "wall_restitution",
    "gravity",
    "until",
    "left_wall",
    "right_wall",
];

const NAMED: [(&str, Col); 12] = [
    ("collisions", Col::Collisions),
    ("pair_collisions", Col::PairCollisions),
    ("wall_collisions", Col::WallCollisions),
    ("simultaneous", Col::Simultaneous),
    ("time", Col::Time),
    ("energy_start", Col::EnergyStart),
    ("energy_end", Col::EnergyEnd),
    ("drift", Col::Drift),
    ("momentum_start", Col::MomentumStart),
    ("momentum_end", Col::MomentumEnd),
    ("pi", Col::Pi),
    ("accumulation", Col::Accumulation),
];

fn range(ok: bool, what: &str) -> Result<(), ValueProblem> {
    if ok {
        Ok(())
    } else {
        Err(ValueProblem::Range(what.into()))
    }
}

impl Kind for TrackSweep {
    /// The track as run (for the pi count) and its run.
    type Out = (Track, Run);
    type Col = Col;

    fn scalars(&self) -> &'static [&'static str] {
        SCALARS
    }

    fn bodies(&self) -> usize {
        self.track.bodies.len()
    }

    fn check(&self, knob: Knob, n: &Number) -> Result<(), ValueProblem> {
        let v = n.value();
        match knob {
            Knob::Mass(_) => drop(Mass::new(n.clone())?),
            Knob::Size(_) => range(v >= 0.0, "a size must be >= 0")?,
            Knob::Named("e" | "wall_restitution") => {
                drop(Restitution::dissipative(n.clone())?);
            }
            Knob::Named("gravity") => range(v >= 0.0, "gravity must be >= 0")?,
            Knob::Named("until") => range(v >= 0.0, "until must be >= 0")?,
            _ => {}
        }
        Ok(())
    }

    fn run(&self, point: &[(Knob, f64)]) -> Result<(Track, Run), String> {
        let mut track = self.track.clone();
        let mut limits = self.limits;
        let mut wall_restitution = self.wall_restitution;
        for &(knob, v) in point {
            match knob {
                Knob::Mass(i) => {
                    track.bodies[i].m = Number::from_f64(v)
                        .map_err(|e| e.to_string())
                        .and_then(|n| Mass::new(n).map_err(|e| e.to_string()))?;
                }
                Knob::Position(i) => track.bodies[i].x = v,
                Knob::Velocity(i) => track.bodies[i].v = v,
                Knob::Size(i) => track.bodies[i].size = v,
                Knob::Named("e") => track.e = v,
                Knob::Named("wall_restitution") => wall_restitution = Some(v),
                Knob::Named("gravity") => track.gravity = v,
                Knob::Named("until") => limits.until = Some(v),
                Knob::Named("left_wall") => track.left_wall = Some(v),
                Knob::Named("right_wall") => track.right_wall = Some(v),
                Knob::Named(other) => return Err(format!("'{other}' is not a parameter")),
            }
        }
        track.e_wall = Track::walls_restitution(track.e, wall_restitution);
        track.check().map_err(|e| e.to_string())?;
        limits.check().map_err(|e| e.to_string())?;
        let run = track.run(limits, None).map_err(|e| e.to_string())?;
        Ok((track, run))
    }

    fn column(&self, name: &str) -> Option<Col> {
        if let Some((_, c)) = NAMED.iter().find(|(n, _)| *n == name) {
            return Some(*c);
        }
        let body = |prefix: &str| -> Option<usize> {
            let i: usize = name.strip_prefix(prefix)?.parse().ok()?;
            (1..=self.track.bodies.len()).contains(&i).then_some(i)
        };
        body("fin")
            .map(Col::Fin)
            .or_else(|| body("xfin").map(Col::XFin))
    }

    fn defaults(&self) -> Vec<String> {
        let n = self.track.bodies.len();
        let mut out = vec!["collisions".to_string(), "time".into()];
        out.extend((1..=n).map(|i| format!("fin{i}")));
        out.push("drift".into());
        out
    }

    fn column_forms(&self) -> String {
        let n = self.track.bodies.len();
        format!(
            "{}, fin1..fin{n}, xfin1..xfin{n}",
            NAMED.iter().map(|(n, _)| *n).collect::<Vec<_>>().join(", ")
        )
    }

    /// The counts of collisions. Not `pi`: a count of pi billiards for any mass ratio,
    /// beyond 2^53 (and i64) for a ratio past about 1e32, so a float like `time`.
    fn counts(&self, col: Col) -> bool {
        matches!(
            col,
            Col::Collisions | Col::PairCollisions | Col::WallCollisions | Col::Simultaneous
        )
    }

    fn value(&self, col: Col, (track, run): &(Track, Run)) -> Option<f64> {
        Some(match col {
            Col::Collisions => run.collisions as f64,
            Col::PairCollisions => run.pair_collisions as f64,
            Col::WallCollisions => run.wall_collisions as f64,
            Col::Simultaneous => run.simultaneous as f64,
            Col::Time => run.time,
            Col::Fin(i) => run.v[i - 1],
            Col::XFin(i) => run.x[i - 1],
            Col::EnergyStart => run.energy.start,
            Col::EnergyEnd => run.energy.end,
            // Relative to the start; none for a track with no energy.
            Col::Drift => {
                let e = run.energy;
                (e.start != 0.0).then(|| (e.end - e.start) / e.start.abs())?
            }
            Col::MomentumStart => run.momentum.start,
            Col::MomentumEnd => run.momentum.end,
            Col::Pi => {
                let (m, big_m) = track.pi_masses()?;
                // Exact; as binary64 it is exact below 2^53 collisions.
                pi::pi_count(&m, &big_m).to_string().parse().ok()?
            }
            Col::Accumulation => match run.stop {
                Stop::Zeno { accumulation, .. } => accumulation,
                _ => return None,
            },
        })
    }
}
