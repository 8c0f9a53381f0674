//! `collide pi N`: the exact count, the digits of pi it spells, and the simulation against it.

use crate::values::rational::UBig;
use serde_json::json;

use super::text::{Block, duration};
use crate::track::{Stop, TrackReport};

/// The count for mass ratio 100^N, and the simulation when one ran.
pub struct Pi {
    pub n: u32,
    pub count: UBig,
    /// The run, and its wall-clock time in seconds.
    pub simulation: Option<(TrackReport, f64)>,
}

impl Pi {
    pub fn new(n: u32, count: UBig, simulation: Option<(TrackReport, f64)>) -> Pi {
        Pi {
            n,
            count,
            simulation,
        }
    }

    /// The count's digits as pi: `3.14159...`.
    fn as_pi(&self) -> String {
        let digits = self.count.to_string();
        match digits.split_at(1) {
            (head, "") => head.to_string(),
            (head, tail) => format!("{head}.{tail}"),
        }
    }

    pub fn json(&self) -> serde_json::Value {
        let mut v = json!({
            "n": self.n,
            "mass_ratio": format!("1e{}", 2 * u64::from(self.n)),
            "count": self.count.to_string(),
            "pi": self.as_pi(),
        });
        if let Some((r, seconds)) = &self.simulation {
            v["simulation"] = json!({
                "collisions": r.run.collisions,
                "agrees": r.run.stop == Stop::Done && UBig::from(r.run.collisions) == self.count,
                "seconds": seconds,
                "ns_per_collision": seconds * 1e9 / r.run.collisions.max(1) as f64,
                "energy_drift": (r.run.energy.end - r.run.energy.start) / r.run.energy.start,
            });
        }
        v
    }

    pub fn text(&self) -> String {
        let mut out = String::new();
        let mut b = Block::new(format!(
            "Pi billiards, mass ratio 100^{} (a block of mass 1 at rest between a wall and one of \
             mass 1e{} moving toward it)",
            self.n,
            2 * u64::from(self.n)
        ));
        b.row(
            "collisions",
            self.count.to_string(),
            "the exact count ceil(pi/theta) - 1, theta = atan(10^-N)",
        );
        b.row("pi", self.as_pi(), "the count's digits");
        if let Some((r, seconds)) = &self.simulation {
            let agrees = r.run.stop == Stop::Done && UBig::from(r.run.collisions) == self.count;
            b.row(
                "simulated",
                r.run.collisions.to_string(),
                format!(
                    "{}, in {} ({} each); energy drift {:.1e}",
                    if agrees { "agrees" } else { "DISAGREES" },
                    duration(*seconds),
                    duration(seconds / r.run.collisions.max(1) as f64),
                    (r.run.energy.end - r.run.energy.start) / r.run.energy.start
                ),
            );
        }
        b.render(&mut out);
        out.trim_start_matches('\n').to_string()
    }
}
