//! The frames table of lecture Figs. 2.5 and 3.4: one collision seen from each frame, with the
//! quantities every frame must agree on (crunch, energy lost, relative velocity, `e`) computed in
//! each frame from its own velocities and checked equal, so a disagreement is an error, not a
//! table.

use std::fmt::Write;

use serde::Serialize;

use super::text::{Block, header, pair, paragraph, wrap};
use crate::line::case::Case;
use crate::line::frame::Frame;
use crate::report::{Energy, Report, Section, Sections, Unrepresentable};
use crate::solver::{Lab, Solver};
use crate::values::quantity::{Exact, Scalar};
use crate::values::rational::Q;

/// One row of the frames table.
#[derive(Clone, Debug, Serialize)]
pub struct FrameRow<N> {
    pub name: String,
    pub w: N,
    #[serde(rename = "in")]
    pub v_in: [N; 2],
    pub com: [N; 2],
    pub fin: [N; 2],
    pub energy: Energy<N>,
    /// Whether the time-reversed collision equals the original in this frame (`--reverse`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub reverse_equals_original: Option<bool>,
    #[serde(skip)]
    pub label: String,
}

/// The quantities every frame must agree on.
#[derive(Clone, Debug, Serialize)]
pub struct Invariants<N> {
    pub crunch: N,
    pub lost: N,
    pub relative_velocity: N,
    /// `e`, and in each frame `-(FIN1 - FIN2) / (IN1 - IN2)`; `None` when `V1 = V2`.
    pub restitution: N,
}

/// The frames table of lecture Figs. 2.5 and 3.4.
#[derive(Clone, Debug, Serialize)]
pub struct FramesTable<N> {
    pub frames: Vec<FrameRow<N>>,
    pub invariants: Invariants<N>,
}

/// An invariant that differs between frames.
#[derive(Clone, Debug, thiserror::Error)]
#[error("{quantity} is not the same in every frame: {lab} in the lab but {other} in frame {frame}")]
pub struct BrokenInvariant {
    pub quantity: &'static str,
    pub frame: String,
    pub lab: String,
    pub other: String,
}

/// Relative agreement within 2 ulps for binary64, beyond an absolute `slack` (the stated
/// rounding error of a quantity that cancels); exact equality for rationals.
pub trait Agree: Scalar {
    fn agrees(&self, other: &Self) -> bool {
        self.agrees_within(other, 0.0)
    }
    fn agrees_within(&self, other: &Self, slack: f64) -> bool;
}

impl Agree for f64 {
    fn agrees_within(&self, other: &f64, slack: f64) -> bool {
        (self - other).abs() <= 2.0 * f64::EPSILON * self.abs().max(other.abs()) + slack
    }
}

impl Agree for Exact {
    fn agrees_within(&self, other: &Exact, _slack: f64) -> bool {
        self.rational() == other.rational()
    }
}

/// The rounding error of `e` seen in one frame, `-(FIN1 - FIN2) / (IN1 - IN2)` from the frame's
/// double-double velocities: each of them is within a few units of 2^-106 of the magnitudes it
/// is made from (IN, FIN, the shift `w`), and `FIN1 - FIN2 = -e (IN1 - IN2)` cancels them all
/// when `e` is small (1e-17: a relative error of 1e-15; 1e-300: no digit left). Bounded
/// generously, 64 units of 2^-106 of their sum, over the relative velocity `relative`; beyond
/// it `e` is compared relative to its own size.
fn restitution_slack<N: Scalar>(v_in: &[N; 2], fin: &[N; 2], w: &N, relative: f64) -> f64 {
    let size: f64 = v_in
        .iter()
        .chain(fin)
        .chain([w])
        .map(Scalar::magnitude)
        .sum();
    64.0 * 2f64.powi(-106) * size / relative
}

/// The frames table of `lab` for the frames given, checking the invariants row by row, energies
/// times `energy_scale` (`--energy-unit`); `reverse` adds whether the time-reversed collision
/// equals the original in each frame.
pub fn table<L: Lab>(
    lab: &L,
    list: impl IntoIterator<Item = Frame>,
    reverse: bool,
    energy_scale: Option<&Q>,
) -> Result<FramesTable<L::N>, FramesError>
where
    L::N: Agree,
{
    let mut sections = Sections::new([Section::Vectors, Section::Energy]);
    sections.energy_scale = energy_scale.cloned();
    let mut frames = Vec::new();
    let mut invariants: Option<Invariants<L::N>> = None;
    for frame in list {
        let (w, solver) = lab.seen_from(&frame);
        let reverse = reverse.then(|| lab.is_own_time_reverse(&frame));
        let r: Report<L::N> = Report::build(&solver, &sections).map_err(|u| Unrepresentable {
            quantity: format!("{} in frame {frame}", u.quantity),
            ..u
        })?;
        let (v, energy) = (r.vectors.expect("vectors"), r.energy.expect("energy"));
        // e as the case has it; each frame's own -(FIN1 - FIN2)/(IN1 - IN2) must agree with
        // it relative to its size, beyond the rounding the frame's velocities carry.
        let e = solver.restitution();
        let relative = solver.relative_velocity();
        if let Some(seen) = solver.restitution_seen() {
            let slack = restitution_slack(&v.v_in, &v.fin, &w, relative.magnitude());
            if !seen.agrees_within(&e, slack) {
                return Err(FramesError::Broken(BrokenInvariant {
                    quantity: "restitution e",
                    frame: frame.to_string(),
                    lab: e.show(),
                    other: seen.show(),
                }));
            }
        }
        let inv = Invariants {
            crunch: energy.crunch.clone(),
            lost: energy.lost_signed(),
            relative_velocity: relative,
            restitution: e,
        };
        if let Some(lab) = &invariants {
            for (quantity, a, b) in [
                ("crunch", &lab.crunch, &inv.crunch),
                ("energy lost", &lab.lost, &inv.lost),
                (
                    "relative velocity V1 - V2",
                    &lab.relative_velocity,
                    &inv.relative_velocity,
                ),
            ] {
                if !a.agrees(b) {
                    return Err(FramesError::Broken(BrokenInvariant {
                        quantity,
                        frame: frame.to_string(),
                        lab: a.show(),
                        other: b.show(),
                    }));
                }
            }
        } else {
            invariants = Some(inv);
        }
        frames.push(FrameRow {
            name: frame.to_string(),
            label: frame.describe(),
            w,
            v_in: v.v_in,
            com: v.com,
            fin: v.fin,
            energy,
            reverse_equals_original: reverse,
        });
    }
    Ok(FramesTable {
        frames,
        invariants: invariants.expect("the lab row comes first"),
    })
}

/// Why a frames table could not be made.
#[derive(Clone, Debug, thiserror::Error)]
pub enum FramesError {
    #[error(transparent)]
    Unrepresentable(#[from] Unrepresentable),
    #[error(transparent)]
    Broken(#[from] BrokenInvariant),
}

/// The frames table for people, with its checked invariants.
pub fn text<N: Scalar>(case: &Case, t: &FramesTable<N>) -> String {
    let e = case.restitution();
    let mut out = String::new();
    out.push_str(&header(case));
    let mut velocities =
        Block::new("Velocities (an observer moving at w sees every velocity shifted by -w)");
    let mut columns = vec!["frame", "w", "IN", "COM"];
    if !e.is_totally_inelastic() {
        columns.push("FIN");
    }
    velocities.cell_vec(columns.into_iter().map(String::from).collect());
    let mut energies = Block::new("Energies in each frame");
    let mut columns = vec!["frame"];
    if e.is_elastic() {
        columns.extend(["KE_IN = KE_FIN", "KE_COM", "crunch"]);
    } else if e.is_totally_inelastic() {
        columns.extend(["KE_IN", "KE_FIN = KE_COM", "crunch = lost"]);
    } else {
        columns.extend(["KE_IN", "KE_FIN", "KE_COM", "crunch", "lost"]);
    }
    let reversing = t.frames.iter().any(|r| r.reverse_equals_original.is_some());
    if reversing {
        columns.push("reversed = original");
    }
    energies.cell_vec(columns.into_iter().map(String::from).collect());
    for r in &t.frames {
        let en = &r.energy;
        let mut row = vec![r.label.clone(), r.w.show(), pair(&r.v_in), pair(&r.com)];
        if !e.is_totally_inelastic() {
            row.push(pair(&r.fin));
        }
        velocities.cell_vec(row);
        let mut row = vec![r.label.clone()];
        if e.is_elastic() || e.is_totally_inelastic() {
            // Elastic: KE_IN = KE_FIN; stuck: KE_FIN = KE_COM and lost = crunch.
            row.extend([en.ke_in.show(), en.com.show(), en.crunch.show()]);
        } else {
            row.extend([
                en.ke_in.show(),
                en.fin.show(),
                en.com.show(),
                en.crunch.show(),
                en.lost_signed().show(),
            ]);
        }
        if let Some(same) = r.reverse_equals_original {
            row.push(if same { "yes" } else { "no" }.into());
        }
        energies.cell_vec(row);
    }
    velocities.render(&mut out);
    energies.render(&mut out);
    let inv = &t.invariants;
    let mut lines = vec![
        format!("crunch = 1/2 mu (V1 - V2)^2 = {}", inv.crunch.show()),
        format!(
            "relative velocity V1 - V2 = {}",
            inv.relative_velocity.show()
        ),
        format!(
            "e = -(FIN1 - FIN2)/(IN1 - IN2) = {}",
            inv.restitution.show()
        ),
    ];
    if !e.is_elastic() {
        lines.insert(1, format!("energy lost = {}", inv.lost.show()));
    }
    out.push('\n');
    out.push_str(&paragraph(
        "Invariants, computed in each frame from its own velocities and equal in all:",
    ));
    for l in lines {
        out.push_str(&wrap(
            &format!("  {l}"),
            crate::values::terminal::width(),
            "    ",
        ));
    }
    if e.is_totally_inelastic() {
        let _ = writeln!(
            out,
            "  (e = 0: FIN = COM, so the bodies' \"finally at rest\" frames are the COM frame)"
        );
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::accuracy::case;
    use crate::line::collision::Collision;
    use crate::solver::binary64::Binary64;

    /// A lab whose COM row is another collision: the check must catch the different crunch.
    struct Mismatched(Collision, Collision);

    impl Lab for Mismatched {
        type N = f64;
        type Seen<'a> = Binary64<'a>;
        fn seen_from(&self, frame: &Frame) -> (f64, Binary64<'_>) {
            let c = if *frame == Frame::Lab {
                &self.0
            } else {
                &self.1
            };
            (0.0, Binary64::lab(c))
        }
        fn is_own_time_reverse(&self, _: &Frame) -> bool {
            false
        }
    }

    #[test]
    fn a_frame_that_disagrees_is_reported() {
        let a = case([[6.0, 0.0], [0.0, 1.0]], [3.0, -4.0], 1.0).unwrap();
        let b = case([[6.0, 0.0], [0.0, 1.0]], [3.0, -5.0], 1.0).unwrap();
        match table(&Mismatched(a, b), [Frame::Lab, Frame::Com], false, None) {
            Err(FramesError::Broken(e)) => {
                assert_eq!(e.quantity, "crunch");
                assert_eq!(e.frame, "com");
                // 1/2 (6/7) 7^2 = 21 against 1/2 (6/7) 8^2 = 192/7.
                assert_eq!(e.lab, "21");
                // Shown to the text digits (15): 192/7 = 27.428571428571428...
                assert_eq!(e.other, "27.4285714285714");
            }
            other => panic!("expected a broken invariant, got {other:?}"),
        }
    }
}
