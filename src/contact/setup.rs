//! What a run is asked: bodies on a track between optional walls, and the contact law of each
//! pair and wall as the user gives it (a kind, a stiffness, a damping as a coefficient, a ratio or
//! a restitution), resolved per contact with its reduced mass.

use serde::Serialize;

use super::closed;
use super::error::ContactError;
use super::law::Law;
use super::system::Slot;
use crate::track::{Body, Contact, Track};

/// Which law, as asked.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, serde::Deserialize, clap::ValueEnum)]
#[serde(rename_all = "kebab-case")]
pub enum LawKind {
    /// F = k d + c d' (Kelvin-Voigt spring-dashpot)
    Linear,
    /// F = k d^(3/2) (elastic spheres, no damping)
    Hertz,
    /// F = k d^(3/2) (1 + chi d') (Hertz with Hunt-Crossley damping)
    HuntCrossley,
}

impl LawKind {
    pub fn name(self) -> &'static str {
        match self {
            LawKind::Linear => "linear",
            LawKind::Hertz => "hertz",
            LawKind::HuntCrossley => "hunt-crossley",
        }
    }
}

/// How the damping of a contact is given.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Damping {
    /// None: a purely elastic contact.
    None,
    /// The coefficient itself: `c` (linear) or `chi` (Hunt-Crossley).
    Absolute(f64),
    /// The damping ratio `zeta = c / (2 sqrt(k mu))` (linear).
    Zeta(f64),
    /// The restitution the contact must give (linear: `zeta` found from `e` exactly).
    Restitution(f64),
}

/// A contact law as asked: kind, stiffness and damping.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Spec {
    pub kind: LawKind,
    pub k: f64,
    pub damping: Damping,
}

impl Damping {
    /// The damping given as at most one of a coefficient, a ratio or a restitution.
    pub fn given(c: Option<f64>, zeta: Option<f64>, e: Option<f64>) -> Option<Damping> {
        match (c, zeta, e) {
            (Some(c), _, _) => Some(Damping::Absolute(c)),
            (_, Some(z), _) => Some(Damping::Zeta(z)),
            (_, _, Some(e)) => Some(Damping::Restitution(e)),
            _ => None,
        }
    }
}

/// The laws as a user gives them: one kind; stiffness and damping between bodies; the walls'
/// stiffness and damping, each defaulting to the bodies' values.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Laws {
    pub kind: LawKind,
    pub k: f64,
    pub damping: Option<Damping>,
    pub wall_k: Option<f64>,
    pub wall_damping: Option<Damping>,
}

impl Laws {
    /// Between bodies, and at the walls.
    pub fn specs(&self) -> (Spec, Spec) {
        let law = Spec {
            kind: self.kind,
            k: self.k,
            damping: self.damping.unwrap_or(Damping::None),
        };
        let wall = Spec {
            kind: self.kind,
            k: self.wall_k.unwrap_or(self.k),
            damping: self.wall_damping.unwrap_or(law.damping),
        };
        (law, wall)
    }
}

/// A layout and its contact laws.
#[derive(Clone, Debug, PartialEq)]
pub struct Setup {
    pub bodies: Vec<Body>,
    pub left_wall: Option<f64>,
    pub right_wall: Option<f64>,
    /// Between bodies, and at the walls.
    pub law: Spec,
    pub wall: Spec,
}

impl Setup {
    /// Bodies between optional walls, with the laws as given.
    pub fn new(
        bodies: Vec<Body>,
        (left_wall, right_wall): (Option<f64>, Option<f64>),
        laws: Laws,
    ) -> Setup {
        let (law, wall) = laws.specs();
        Setup {
            bodies,
            left_wall,
            right_wall,
            law,
            wall,
        }
    }

    pub(super) fn track(&self) -> Track {
        Track {
            bodies: self.bodies.clone(),
            left_wall: self.left_wall,
            right_wall: self.right_wall,
            e: 1.0,
            e_wall: 1.0,
            gravity: 0.0,
        }
    }

    pub(super) fn masses(&self) -> Vec<f64> {
        self.bodies.iter().map(|b| b.m.value()).collect()
    }

    /// The possible contacts: left wall, neighbouring pairs, right wall.
    pub fn contacts(&self) -> Vec<Contact> {
        let n = self.bodies.len();
        let mut out = Vec::new();
        if self.left_wall.is_some() {
            out.push(Contact::LeftWall);
        }
        out.extend((0..n.saturating_sub(1)).map(Contact::Pair));
        if self.right_wall.is_some() {
            out.push(Contact::RightWall);
        }
        out
    }

    /// Checks the layout (as `collide track`) and the laws, and resolves each slot's law.
    pub fn slots(&self) -> Result<Vec<Slot>, ContactError> {
        self.track().check()?;
        let m = self.masses();
        self.contacts()
            .into_iter()
            .map(|who| {
                let s = |i: usize| self.bodies[i].size;
                let n = m.len();
                let (spec, which, mu, reach) = match who {
                    // m1 (m2 / (m1 + m2)): the product m1 m2 would underflow (1e-200 each)
                    // or overflow (1e200) where the reduced mass does not.
                    Contact::Pair(i) => (
                        self.law,
                        "",
                        m[i] * (m[i + 1] / (m[i] + m[i + 1])),
                        (s(i) + s(i + 1)) / 2.0,
                    ),
                    Contact::LeftWall => (self.wall, "wall ", m[0], s(0) / 2.0),
                    Contact::RightWall => (self.wall, "wall ", m[n - 1], s(n - 1) / 2.0),
                };
                Ok(Slot {
                    who,
                    law: resolve(spec, mu, which)?,
                    mu,
                    reach,
                })
            })
            .collect()
    }

    /// The overlap of slot `who` at positions `x`.
    pub(super) fn overlap(&self, who: Contact, x: &[f64]) -> f64 {
        let s = |i: usize| self.bodies[i].size;
        match who {
            Contact::LeftWall => self.left_wall.unwrap_or(f64::NEG_INFINITY) - (x[0] - s(0) / 2.0),
            Contact::Pair(i) => (s(i) + s(i + 1)) / 2.0 - (x[i + 1] - x[i]),
            Contact::RightWall => {
                let n = x.len() - 1;
                x[n] + s(n) / 2.0 - self.right_wall.unwrap_or(f64::INFINITY)
            }
        }
    }

    /// The largest relative speed at the start: between any two bodies, or a body and a wall.
    pub fn speed_scale(&self) -> f64 {
        let v: Vec<f64> = self.bodies.iter().map(|b| b.v).collect();
        let hi = v.iter().fold(f64::NEG_INFINITY, |a, b| a.max(*b));
        let lo = v.iter().fold(f64::INFINITY, |a, b| a.min(*b));
        let mut s = hi - lo;
        if self.left_wall.is_some() || self.right_wall.is_some() {
            s = s.max(hi.abs()).max(lo.abs());
        }
        s
    }
}

/// The law of one slot from its spec and reduced mass.
fn resolve(spec: Spec, mu: f64, which: &'static str) -> Result<Law, ContactError> {
    if !(spec.k > 0.0 && spec.k.is_finite()) {
        return Err(ContactError::Stiffness { which, k: spec.k });
    }
    let k = spec.k;
    let check = |value: f64| {
        if value >= 0.0 && value.is_finite() {
            Ok(value)
        } else {
            Err(ContactError::Damping { which, value })
        }
    };
    Ok(match (spec.kind, spec.damping) {
        (LawKind::Linear, Damping::None) => Law::Linear { k, c: 0.0 },
        (LawKind::Linear, Damping::Absolute(c)) => Law::Linear { k, c: check(c)? },
        (LawKind::Linear, Damping::Zeta(z)) => Law::Linear {
            k,
            c: closed::Linear::damping(k, mu, check(z)?),
        },
        (LawKind::Linear, Damping::Restitution(e)) => {
            let z = closed::Linear::zeta_for(e).ok_or(ContactError::Restitution { which, e })?;
            Law::Linear {
                k,
                c: closed::Linear::damping(k, mu, z),
            }
        }
        (LawKind::Hertz, Damping::None) => Law::Hertz { k, chi: 0.0 },
        (LawKind::Hertz, Damping::Absolute(0.0)) => Law::Hertz { k, chi: 0.0 },
        (LawKind::Hertz, _) => {
            return Err(ContactError::NotForLaw {
                which,
                kind: "hertz",
                why: "they are elastic (e = 1); use --law hunt-crossley --damping CHI for damping",
            });
        }
        (LawKind::HuntCrossley, Damping::None) => Law::Hertz { k, chi: 0.0 },
        (LawKind::HuntCrossley, Damping::Absolute(chi)) => Law::Hertz {
            k,
            chi: check(chi)?,
        },
        (LawKind::HuntCrossley, _) => {
            return Err(ContactError::NotForLaw {
                which,
                kind: "hunt-crossley",
                why: "their restitution depends on the impact speed; give --damping CHI (1/speed)",
            });
        }
    })
}
