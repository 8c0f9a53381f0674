//! The report of an event under momentum alone: a separation (bodies that start together and
//! are pushed apart: `separation`) or a pass-through (`pass-through`): the sections that mean
//! something for it, in the same JSON keys as a collision's (`in`, `com`, `fin`, `v_com`,
//! `momentum`, `energy`, `changes`), with `energy.released` (a separation) or `energy.lost` (a
//! pass-through) and no restitution, forms, ellipses or products (`e` is undefined or no law;
//! the rest would describe a collision).

use serde::Serialize;

use super::asked::{AskedError, AskedReport, Motion};
use super::text::{Block, changes, header_units, pair, parts, typed};
use super::{ChangeReport, Section, Sections};
use crate::line::order::Order;
use crate::line::separation::{Kind, Separation};
use crate::values::quantity::Scalar;
use crate::values::rational::Q;

/// A separation's numbers. Field names are the JSON schema.
#[derive(Clone, Debug, Serialize, PartialEq)]
pub struct SeparationReport<N> {
    /// `"separation"` (`e` is undefined) or `"pass-through"` (restitution is no law).
    pub event: &'static str,
    pub masses: [N; 2],
    #[serde(rename = "in")]
    pub v_in: [N; 2],
    pub com: [N; 2],
    pub fin: [N; 2],
    pub v_com: N,
    /// `2` when body 2 ends up on the left (`f1 > f2`: body 1 moves off to the right of it, or
    /// has passed through it); absent when body 1 does (`line::order`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub left: Option<u8>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub momentum: Option<SeparationMomentum<N>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub energy: Option<SeparationEnergy<N>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub changes: Option<ChangeReport<N>>,
    /// `--show heights`: the height of each IN and FIN speed, `v^2 / 2g`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub heights: Option<super::Heights<N>>,
    /// A pendulum's swing (`--length`).
    #[serde(flatten)]
    pub asked: AskedReport<N>,
}

#[derive(Clone, Debug, Serialize, PartialEq)]
pub struct SeparationMomentum<N> {
    #[serde(rename = "in")]
    pub p_in: [N; 2],
    pub fin: [N; 2],
    pub total: N,
}

#[derive(Clone, Debug, Serialize, PartialEq)]
pub struct SeparationEnergy<N> {
    #[serde(rename = "in")]
    pub ke_in: N,
    pub fin: N,
    pub com: N,
    /// `1/2 mu (f1 - f2)^2` (a separation).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub released: Option<N>,
    /// `1/2 mu ((v1 - v2)^2 - (f1 - f2)^2)` (a pass-through: in the two bodies).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub lost: Option<N>,
    /// `mu = m1 m2 / (m1 + m2)`.
    pub reduced_mass: N,
}

impl<N: Scalar> SeparationReport<N> {
    /// The sections of `sections` that mean something for a separation; each value exact, and
    /// rounded once in binary64.
    pub fn new(s: &Separation, sections: &Sections) -> Result<SeparationReport<N>, AskedError> {
        let one = |q: &crate::values::rational::Q| N::of_rational(q);
        let two = |p: &[crate::values::rational::Q; 2]| [one(&p[0]), one(&p[1])];
        let has = |x| sections.contains(x);
        let energy = |q: &crate::values::rational::Q| match &sections.energy_scale {
            Some(k) => one(&(q * k)),
            None => one(q),
        };
        let v = one(&s.v_com());
        let through = s.kind == Kind::PassThrough;
        let asked = if sections.asked.is_empty() {
            AskedReport::default()
        } else {
            let motion = Motion {
                v_in: s.v_in(),
                fin: s.fin.clone(),
                crunch: Q::ZERO,
                mu: s.reduced_mass(),
                e: None,
            };
            AskedReport::of(&motion, &sections.asked)?
        };
        Ok(SeparationReport {
            event: if through {
                "pass-through"
            } else {
                "separation"
            },
            masses: two(&s.m()),
            v_in: two(&s.v_in()),
            com: [v.clone(), v.clone()],
            fin: two(&s.fin),
            v_com: v,
            left: Order::after(&s.fin[0], &s.fin[1]).left_when_body_2(),
            momentum: has(Section::Momentum).then(|| SeparationMomentum {
                p_in: two(&s.momentum(&s.v_in())),
                fin: two(&s.momentum(&s.fin)),
                total: one(&s.total_momentum()),
            }),
            energy: has(Section::Energy).then(|| SeparationEnergy {
                ke_in: energy(&s.ke_in()),
                fin: energy(&s.ke_fin()),
                com: energy(&s.ke_com()),
                released: (!through).then(|| energy(&s.released())),
                lost: through.then(|| energy(&-s.released())),
                reduced_mass: one(&s.reduced_mass()),
            }),
            changes: has(Section::Changes).then(|| {
                ChangeReport::of(
                    &s.changes(sections.contact_time.as_ref()),
                    sections.energy_scale.as_ref(),
                    sections.force_scale.as_ref(),
                )
            }),
            heights: sections
                .heights
                .as_ref()
                .filter(|_| has(Section::Heights))
                .map(|h| super::Heights::of_speeds(&s.v_in(), &s.fin, h)),
            asked,
        })
    }

    /// Text for people.
    pub fn text(&self, s: &Separation, sections: &Sections) -> String {
        let through = s.kind == Kind::PassThrough;
        let what = if through {
            "no e (pass-through: one body passes through the other; only momentum holds)"
        } else {
            "e undefined (separation: the bodies start together and are pushed apart)"
        };
        let mut out = parts(&[
            format!("M = diag({}, {})", typed(&s.masses[0]), typed(&s.masses[1])),
            format!(
                "V_IN = ({}, {})",
                typed(&s.velocities[0]),
                typed(&s.velocities[1])
            ),
            what.into(),
        ]);
        out.push_str(&header_units(&s.units));
        if sections.contains(Section::Vectors) {
            let mut b = Block::new("Vectors (V1, V2)");
            let v_com = self.v_com.show();
            if through {
                b.row("IN   V_IN", pair(&self.v_in), "");
                b.row(
                    "COM  V_COM u",
                    pair(&self.com),
                    format!("V_COM = P_total / M_total = {v_com}"),
                );
            } else {
                b.row("IN   V_IN", pair(&self.v_in), "V1 = V2: together");
                b.row(
                    "COM  V_COM u",
                    pair(&self.com),
                    format!("V_COM = {v_com} (unchanged)"),
                );
            }
            let fin_note = match (through, self.left) {
                (true, Some(2)) => "as given or solved: body 1 has passed through body 2",
                (true, _) => "as given or solved: body 2 has passed through body 1",
                _ => "as given or solved",
            };
            b.row("FIN  V_FIN", pair(&self.fin), fin_note);
            if !through && self.left == Some(2) {
                b.row("", "", "f1 > f2: body 1 moves off to the right of body 2");
            }
            b.render(&mut out);
        }
        let shown = |x| sections.contains(x);
        if let Some(p) = self.momentum.as_ref().filter(|_| shown(Section::Momentum)) {
            let mut b = Block::new("Momentum (P = M.V)");
            b.row("P_IN   M.V_IN", pair(&p.p_in), "");
            b.row("P_FIN  M.V_FIN", pair(&p.fin), "");
            b.row("P_total  u.M.V", p.total.show(), "conserved");
            b.render(&mut out);
        }
        if let Some(e) = self.energy.as_ref().filter(|_| shown(Section::Energy)) {
            let mut b = Block::new(format!("Energy (KE = 1/2 V.M.V, in {})", s.units.energy()));
            let mu = e.reduced_mass.show();
            if let Some(lost) = &e.lost {
                b.row("KE_IN", e.ke_in.show(), "");
                b.row("KE_FIN", e.fin.show(), "");
                b.row("KE_COM = 1/2 V_COM P_total", e.com.show(), "");
                b.row(
                    "lost = 1/2 mu ((V1 - V2)^2 - (f1 - f2)^2)",
                    lost.show(),
                    if lost.magnitude() == 0.0 {
                        format!(
                            "mu = M1 M2 / (M1 + M2) = {mu}: nothing lost, the relative speed is \
                             unchanged (a perforation: no restitution)"
                        )
                    } else {
                        format!(
                            "mu = M1 M2 / (M1 + M2) = {mu}: turned into heat and deformation in \
                             the two bodies (a perforation: no restitution)"
                        )
                    },
                );
            }
            if let Some(released) = &e.released {
                b.row("KE_IN = KE_COM", e.ke_in.show(), "");
                b.row("KE_FIN", e.fin.show(), "");
                b.row(
                    "released = 1/2 mu (f1 - f2)^2",
                    released.show(),
                    format!(
                        "mu = M1 M2 / (M1 + M2) = {mu}: energy stored in the bodies (a spring, \
                         an explosive) is released"
                    ),
                );
            }
            b.render(&mut out);
        }
        if let Some(c) = self.changes.as_ref().filter(|_| shown(Section::Changes)) {
            changes(c, &s.units).render(&mut out);
        }
        if let Some(h) = self.heights.as_ref().filter(|_| shown(Section::Heights)) {
            super::text::heights(h, "").render(&mut out);
        }
        for b in self.asked.blocks() {
            b.render(&mut out);
        }
        out
    }
}
