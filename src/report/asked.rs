//! What a homework problem asks beyond the lecture's sections (issue 27 §1), each shown when
//! its flag is given: a spring between the bodies (`--spring K`: `spring`). Values are in SI
//! (metres, seconds), computed exactly from the collision and rounded once; irrational ones
//! (roots, pi) are taken to 30 digits first, and marked approximate in exact mode.

use serde::{Deserialize, Serialize};

use super::text::Block;
use crate::solver::exact::ExactCollision;
use crate::values::quantity::Scalar;
use crate::values::rational::{Q, int};

/// What was asked, in SI, with the case's units in SI (1 when a case has none: masses are then
/// taken as kg and velocities as m/s).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Asked {
    /// A spring between the bodies: `k` in N/m, and as typed (`--spring`).
    pub spring: Option<(Q, String)>,
    /// The case's mass unit in kg.
    pub mass_si: Q,
    /// The case's velocity unit in m/s.
    pub velocity_si: Q,
    /// Whether the case had no units (so they were taken as kg and m/s).
    pub assumed: bool,
}

impl Default for Asked {
    fn default() -> Asked {
        Asked {
            spring: None,
            mass_si: int(1),
            velocity_si: int(1),
            assumed: true,
        }
    }
}

impl Asked {
    /// Nothing asked.
    pub fn is_empty(&self) -> bool {
        self.spring.is_none()
    }

    /// For a case in `units`.
    pub fn in_units(units: &crate::values::units::Units) -> Asked {
        use crate::values::units::{Dimension, lookup};
        let si = |name: Option<&str>, d| name.and_then(|n| lookup(n, d).ok()).map(|u| u.si());
        let m = si(units.mass, Dimension::Mass);
        let v = si(units.velocity, Dimension::Velocity);
        Asked {
            assumed: m.is_none() || v.is_none(),
            mass_si: m.unwrap_or_else(|| int(1)),
            velocity_si: v.unwrap_or_else(|| int(1)),
            ..Asked::default()
        }
    }

    /// The note on units for a block's title.
    fn units_note(&self) -> &'static str {
        if self.assumed {
            "; masses taken as kg, velocities as m/s"
        } else {
            ""
        }
    }
}

/// The sections asked for. Field names are the JSON schema (top-level keys of `solve`).
#[derive(Clone, Debug, Default, Serialize, Deserialize, PartialEq)]
pub struct AskedReport<N> {
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub spring: Option<SpringReport<N>>,
    /// What was asked, for the text (not part of the JSON schema).
    #[serde(skip)]
    pub asked: Option<Asked>,
}

/// `spring`: the spring constant, the compression at closest approach and the time of contact.
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct SpringReport<N> {
    /// `k` in N/m.
    pub k: N,
    /// `x_max = sqrt(2 crunch / k)` in metres.
    pub compression: N,
    /// `t = pi sqrt(mu / k)` in seconds.
    pub contact_time: N,
}

/// An exact value or an approximation to 30 digits (`line::spring::root`).
fn either<N: Scalar>(x: Result<Q, Q>) -> N {
    match x {
        Ok(q) => N::of_rational(&q),
        Err(q) => N::of_approx(&q),
    }
}

impl<N: Scalar> AskedReport<N> {
    /// The sections of `asked` for the collision `x`.
    pub fn of(x: &ExactCollision, asked: &Asked) -> AskedReport<N> {
        let mass = &asked.mass_si;
        let v2 = &asked.velocity_si * &asked.velocity_si;
        AskedReport {
            spring: asked.spring.as_ref().map(|(k, _)| {
                // mu = det M / M_total (a diagonal tensor: m1 m2 / (m1 + m2)), in kg.
                let mu = (&x.a * &x.b - &x.c * &x.c) / (&x.a + &x.b + int(2) * &x.c) * mass;
                let crunch = x.crunch_q() * mass * &v2;
                use crate::line::spring::{compression, contact_time};
                SpringReport {
                    k: N::of_rational(k),
                    compression: either(compression(&crunch, k)),
                    contact_time: N::of_approx(&contact_time(&mu, k)),
                }
            }),
            asked: Some(asked.clone()),
        }
    }

    /// The text blocks.
    pub fn blocks(&self) -> Vec<Block> {
        let mut out = Vec::new();
        let Some(asked) = &self.asked else {
            return out;
        };
        if let (Some(s), Some((_, typed))) = (&self.spring, &asked.spring) {
            let mut b = Block::new(format!(
                "Spring between the bodies (k = {typed}{})",
                asked.units_note()
            ));
            b.row(
                "x_max = sqrt(2 crunch / k)",
                format!("{} m", s.compression.show()),
                "the compression at closest approach: the spring holds the crunch energy",
            );
            b.row(
                "t = pi sqrt(mu / k)",
                format!("{} s", s.contact_time.show()),
                "in contact half a period of the reduced mass on the spring (an ideal spring \
                 gives it all back: e = 1)",
            );
            out.push(b);
        }
        out
    }
}
