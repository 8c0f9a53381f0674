//! The report of a ball against a wall (`wall`): the ball's numbers only where the wall's would
//! be infinite or meaningless (its kinetic energy, its momentum, the centre of mass). JSON:
//! `event = "wall"`, `wall` (1 or 2), `restitution`, `mass`, `in`, `fin`, `approaching`,
//! `momentum {in, fin}`, `energy {in, fin, crunch, lost | released}`, `changes {dv, impulse,
//! lost_fraction, kept_fraction, average_force}` (the ball's), `heights {in, fin}` (the ball's).
//! A ball whose mass is not given (`-m 'wall,?'`) has no `mass`, `momentum`, `energy`,
//! `impulse` or `average_force`: a rebound does not fix them (issue 45 §5).

use crate::values::rational::Q;
use serde::Serialize;

use super::text::{Block, header_units, pair, paragraph, parts, typed};
use super::{Section, Sections};
use crate::line::wall::WallCase;
use crate::values::quantity::Scalar;

/// A wall case's numbers. Field names are the JSON schema.
#[derive(Clone, Debug, Serialize, PartialEq)]
pub struct WallReport<N> {
    /// Always `"wall"`.
    pub event: &'static str,
    /// Which body is the wall, 1 or 2.
    pub wall: usize,
    pub restitution: N,
    /// The ball's mass (none when not given).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub mass: Option<N>,
    #[serde(rename = "in")]
    pub v_in: [N; 2],
    pub fin: [N; 2],
    /// Whether the ball moves toward the wall at IN.
    pub approaching: bool,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub momentum: Option<BallPair<N>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub energy: Option<WallEnergy<N>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub changes: Option<WallChanges<N>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub heights: Option<BallPair<N>>,
}

/// The ball's value at IN and FIN.
#[derive(Clone, Debug, Serialize, PartialEq)]
pub struct BallPair<N> {
    #[serde(rename = "in")]
    pub at_in: N,
    pub fin: N,
}

#[derive(Clone, Debug, Serialize, PartialEq)]
pub struct WallEnergy<N> {
    #[serde(rename = "in")]
    pub ke_in: N,
    pub fin: N,
    /// `1/2 m (v - w)^2`.
    pub crunch: N,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub lost: Option<N>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub released: Option<N>,
}

#[derive(Clone, Debug, Serialize, PartialEq)]
pub struct WallChanges<N> {
    pub dv: N,
    /// The impulse on the ball, `m dv` (the wall takes the opposite; none without a mass).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub impulse: Option<N>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub lost_fraction: Option<N>,
    /// The share kept, `1 - lost / crunch = e^2` (problems ask for both).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub kept_fraction: Option<N>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub average_force: Option<N>,
}

impl<N: Scalar> WallReport<N> {
    pub fn new(c: &WallCase, sections: &Sections) -> WallReport<N> {
        let one = |q: &Q| N::of_rational(q);
        let has = |x| sections.contains(x);
        let (v, f) = (c.v(), c.fin());
        let b = c.ball();
        let superelastic = c.restitution.is_superelastic();
        let energy = |q: &Q| match &sections.energy_scale {
            Some(k) => one(&(q * k)),
            None => one(q),
        };
        WallReport {
            event: "wall",
            wall: c.wall + 1,
            restitution: one(&c.e()),
            mass: c.m().map(|m| one(&m)),
            v_in: [one(&v[0]), one(&v[1])],
            fin: [one(&f[0]), one(&f[1])],
            approaching: c.approaching(),
            momentum: has(Section::Momentum)
                .then(|| {
                    Some(BallPair {
                        at_in: one(&c.p(&v[b])?),
                        fin: one(&c.p(&f[b])?),
                    })
                })
                .flatten(),
            energy: has(Section::Energy)
                .then(|| {
                    let lost = c.lost()?;
                    Some(WallEnergy {
                        ke_in: energy(&c.ke(&v[b])?),
                        fin: energy(&c.ke(&f[b])?),
                        crunch: energy(&c.crunch()?),
                        lost: (!superelastic).then(|| energy(&lost)),
                        released: superelastic.then(|| energy(&-lost.clone())),
                    })
                })
                .flatten(),
            changes: has(Section::Changes).then(|| {
                let impulse = c.m().map(|m| m * c.dv());
                // `lost / crunch = 1 - e^2` and `kept / crunch = e^2`, whatever the mass.
                let lost = c.lost_fraction().filter(|_| !superelastic);
                WallChanges {
                    dv: one(&c.dv()),
                    impulse: impulse.as_ref().map(one),
                    kept_fraction: lost.as_ref().map(|l| one(&(Q::ONE - l))),
                    lost_fraction: lost.as_ref().map(one),
                    average_force: impulse.as_ref().zip(sections.contact_time.as_ref()).map(
                        |(impulse, t)| {
                            let f = impulse / t;
                            one(&sections.force_scale.as_ref().map_or(f.clone(), |k| &f * k))
                        },
                    ),
                }
            }),
            heights: sections
                .heights
                .as_ref()
                .filter(|_| has(Section::Heights))
                .map(|h| {
                    let height = |v: &Q| {
                        let h = h.height(v);
                        one(&h).unless_underflow(&h)
                    };
                    BallPair {
                        at_in: height(&v[b]),
                        fin: height(&f[b]),
                    }
                }),
        }
    }

    /// Text for people.
    pub fn text(&self, c: &WallCase, sections: &Sections) -> String {
        let shown = |x| sections.contains(x);
        let ball = c.mass.as_ref().map_or("?".into(), typed);
        let mut m = [ball.clone(), ball];
        m[c.wall] = "wall".into();
        let mut out = parts(&[
            format!("M = ({}, {})", m[0], m[1]),
            format!(
                "V_IN = ({}, {})",
                typed(&c.velocities[0]),
                typed(&c.velocities[1])
            ),
            format!(
                "e = {} ({})",
                typed(c.restitution.number()),
                c.restitution.kind()
            ),
        ]);
        out.push_str(&header_units(&c.units));
        out.push_str(&paragraph(&match c.mass {
            Some(_) => format!(
                "Body {} is a wall: immovable (infinite mass), so only the ball's momentum and \
                 energy are shown",
                c.wall + 1
            ),
            None => format!(
                "Body {} is a wall: immovable (infinite mass). The ball's mass is not given: its \
                 rebound (e, the velocities) does not depend on it; its momentum, energy and \
                 impulse do (give it with -m to see them)",
                c.wall + 1
            ),
        }));
        if !self.approaching {
            out.push_str(&approach_note(c.wall));
        }
        if shown(Section::Vectors) {
            let mut b = Block::new("Vectors (V1, V2)");
            b.row("IN   V_IN", pair(&self.v_in), "");
            b.row(
                "FIN  V_FIN",
                pair(&self.fin),
                "ball: w - e (v - w); the wall keeps w",
            );
            b.render(&mut out);
        }
        if let Some(p) = self.momentum.as_ref().filter(|_| shown(Section::Momentum)) {
            let mut b = Block::new("The ball's momentum (m v)");
            b.row("P_IN", p.at_in.show(), "");
            b.row("P_FIN", p.fin.show(), "the wall takes the difference");
            b.render(&mut out);
        }
        if let Some(e) = self.energy.as_ref().filter(|_| shown(Section::Energy)) {
            let mut b = Block::new(format!(
                "The ball's energy (KE = 1/2 m v^2, in {})",
                c.units.energy()
            ));
            b.row("KE_IN", e.ke_in.show(), "");
            b.row("KE_FIN", e.fin.show(), "");
            b.row(
                "crunch = 1/2 m (v - w)^2",
                e.crunch.show(),
                "the ball's energy in the wall's frame",
            );
            if let Some(l) = e.lost.as_ref().filter(|_| !c.restitution.is_elastic()) {
                b.row("lost = (1 - e^2) crunch", l.show(), "");
            }
            if let Some(r) = &e.released {
                b.row(
                    "released = (e^2 - 1) crunch",
                    r.show(),
                    format!("superelastic, e = {}", typed(c.restitution.number())),
                );
            }
            b.render(&mut out);
        }
        if let Some(ch) = self.changes.as_ref().filter(|_| shown(Section::Changes)) {
            let mut b = Block::new(format!(
                "The ball's changes (impulse in {})",
                c.units.impulse()
            ));
            b.row("dv = f - v", ch.dv.show(), "");
            if let Some(dp) = &ch.impulse {
                b.row("impulse dp = m dv", dp.show(), "the wall takes -dp");
            }
            if let Some(l) = &ch.lost_fraction {
                b.row(
                    "lost / crunch",
                    l.show(),
                    "the share of the ball's energy (wall frame) lost",
                );
            }
            if let Some(k) = &ch.kept_fraction {
                b.row("kept / crunch", k.show(), "the share kept: e^2");
            }
            if let Some(fc) = &ch.average_force {
                b.row(
                    "average force dp / T",
                    fc.show(),
                    format!("in {}", c.units.force()),
                );
            }
            b.render(&mut out);
        }
        if let Some(h) = self.heights.as_ref().filter(|_| shown(Section::Heights)) {
            let g = sections
                .heights
                .as_ref()
                .map(|h| h.g_text())
                .unwrap_or_default();
            let mut b = Block::new(format!(
                "The ball's heights (v^2 / 2g, g = {g} m/s^2, in m)"
            ));
            b.row(
                "IN",
                h.at_in.show(),
                "the height a fall from rest needs for this speed",
            );
            b.row("FIN", h.fin.show(), "how high the ball rises");
            b.render(&mut out);
        }
        out
    }
}

/// A note when the ball moves away from the wall at IN (no collision happens).
pub fn approach_note(wall: usize) -> String {
    let side = if wall == 0 { "left" } else { "right" };
    paragraph(&format!(
        "Note: the ball moves away from the wall (on the {side}), so they do not meet: \
         check the signs of the velocities"
    ))
}
