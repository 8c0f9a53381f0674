//! The event in the plane or in space seen from every standard frame (lecture Figs. 2.5 and 3.4):
//! per frame the observer's velocity, IN and FIN, the kinetic energies; then what is the same in
//! every frame.

use std::fmt::Write;

use num_traits::Signed;
use serde_json::{Map, Value, json};

use super::{Overflow, Style, name, vector, vector_each, velocities};
use crate::space::outcome::{Outcome, sub};
use crate::values::rational::Q;
use crate::values::units::Units;

use super::super::text::Block;

/// One frame of the frames table: its name, the observer's velocity and the event seen from it.
pub struct FrameView<'a> {
    pub name: String,
    pub w: Vec<Q>,
    /// Whether `w` is approximate (`V_COM` of an irrational solution).
    pub w_approx: bool,
    pub seen: &'a Outcome,
}

/// The frames table (lecture Figs. 2.5 and 3.4 in the plane): per frame the observer's
/// velocity, IN and FIN, the kinetic energies; then what is the same in every frame.
pub fn text(
    frames: &[FrameView],
    reverse: bool,
    style: &Style,
    units: &Units,
) -> Result<String, Overflow> {
    let mut out = String::new();
    let Some(first) = frames.first() else {
        return Ok(out);
    };
    let marks = &first.seen.approx;
    let a = marks.any();
    let e = |q: Q, a: bool| style.show(&style.energy(&q), a);
    out.push('\n');
    out.push_str(&super::super::text::wrap(
        &format!(
            "Frames (every velocity less the observer's w; energies in {})",
            units.energy()
        ),
        crate::values::terminal::width(),
        "  ",
    ));
    for (k, f) in frames.iter().enumerate() {
        if k > 0 {
            out.push('\n');
        }
        let _ = writeln!(
            out,
            "  {}   w = {}",
            f.name,
            vector(style, &f.w, f.w_approx)
        );
        // Body by body: before and after side by side where they fit, else one to a line.
        let cells: Vec<(String, String)> = (0..f.seen.bodies())
            .map(|i| {
                (
                    format!(
                        "{:<4} {}",
                        name(i, false),
                        vector_each(style, &f.seen.v_in[i], |k| f.seen.approx.v_in(i, k))
                    ),
                    format!(
                        "{:<4} {}",
                        name(i, true),
                        vector_each(style, &f.seen.fin[i], |k| f.seen.approx.fin(i, k))
                    ),
                )
            })
            .collect();
        let left = cells.iter().map(|c| c.0.chars().count()).max().unwrap_or(0);
        let right = cells.iter().map(|c| c.1.chars().count()).max().unwrap_or(0);
        for (vin, fin) in &cells {
            if 4 + left + 3 + right <= crate::values::terminal::width() {
                let _ = writeln!(out, "    {vin:<left$}   {fin}");
            } else {
                let _ = writeln!(out, "    {vin}\n    {fin}");
            }
        }
        let mut energies = format!(
            "KE_IN {}   KE_FIN {}",
            e(f.seen.ke_in(), f.seen.approx.before()),
            e(f.seen.ke_fin(), f.seen.approx.after())
        );
        if reverse {
            let same = f.seen.reversed() == *f.seen;
            energies.push_str(if same {
                "   reversed: the same event"
            } else {
                "   reversed: another event"
            });
        }
        let _ = writeln!(out, "    {energies}");
    }
    let mut inv = Block::new("Invariants (the same in every frame)");
    inv.row("crunch", e(first.seen.crunch(), marks.before()), "");
    let lost = first.seen.lost();
    if !lost.is_zero() {
        inv.row(
            if lost.is_negative() {
                "released"
            } else {
                "lost"
            },
            e(lost.abs(), a),
            "",
        );
    }
    if let Some(r) = &first.seen.e {
        inv.row("e", style.show(r, marks.e()), "");
    }
    if first.seen.bodies() == 2 {
        let rel = sub(&first.seen.v_in[0], &first.seen.v_in[1]);
        let a = marks.body_in(0) || marks.body_in(1);
        inv.row("v1 - v2", vector(style, &rel, a), "");
    }
    inv.render(&mut out);
    style.checked(out)
}

/// The frames table as JSON: `{"frames": [{"name", "w", "in", "fin", "energy"}], "invariants"}`.
pub fn json(frames: &[FrameView], reverse: bool, style: &Style) -> Result<Value, Overflow> {
    let mut list = Vec::new();
    for f in frames {
        let marks = &f.seen.approx;
        let e = |q: Q, a: bool| style.json(&style.energy(&q), a);
        let mut m = Map::new();
        m.insert("name".into(), f.name.clone().into());
        m.insert(
            "w".into(),
            f.w.iter()
                .map(|x| style.json(x, f.w_approx))
                .collect::<Vec<_>>()
                .into(),
        );
        m.insert("in".into(), velocities(style, f.seen, false));
        m.insert("fin".into(), velocities(style, f.seen, true));
        let before = marks.before();
        m.insert(
            "energy".into(),
            json!({
                "in": e(f.seen.ke_in(), before),
                "fin": e(f.seen.ke_fin(), marks.after()),
                "com": e(f.seen.ke_com(), before),
            }),
        );
        if reverse {
            m.insert(
                "reverse_equals_original".into(),
                (f.seen.reversed() == *f.seen).into(),
            );
        }
        list.push(Value::Object(m));
    }
    let mut inv = Map::new();
    if let Some(first) = frames.first() {
        let marks = &first.seen.approx;
        let e = |q: Q, a: bool| style.json(&style.energy(&q), a);
        inv.insert("crunch".into(), e(first.seen.crunch(), marks.before()));
        inv.insert("lost".into(), e(first.seen.lost(), marks.any()));
        if let Some(r) = &first.seen.e {
            inv.insert("restitution".into(), style.json(r, marks.e()));
        }
        let a = marks.body_in(0) || marks.body_in(1);
        if first.seen.bodies() == 2 {
            let rel = sub(&first.seen.v_in[0], &first.seen.v_in[1]);
            inv.insert(
                "relative_velocity".into(),
                rel.iter()
                    .map(|x| style.json(x, a))
                    .collect::<Vec<_>>()
                    .into(),
            );
        }
    }
    style.checked_json(json!({"frames": list, "invariants": inv}))
}
