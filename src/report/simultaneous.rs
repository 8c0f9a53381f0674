//! The report of several contacts at once (`space::contacts`): the law used, each contact
//! (pair, line of impact, normal velocity before and after, impulse), each body's velocity
//! before and after as a table, the energies, and with `--sequential` the sequential answer
//! beside it; as text (80 columns) and JSON (`contacts: [{pair, normal, impulse, ...}]`).
//!
//! Every value is computed once, exactly, from the solved outcome and rounded once here;
//! speeds along a line of impact `n` divide by `|n|` and are irrational in general: the binary64
//! square root of the exact square (within an ulp), marked `≈` in exact output.

use num_traits::Signed;
use serde_json::{Map, Value, json};

use crate::space::balls::{Balls, BallsError, BallsInput};
use crate::space::contacts::{self, Contact, Sequential, Solved};
use crate::space::outcome::{Outcome, dot, polar};
use crate::values::number::num;
use crate::values::rational::{Q, sqrt_binary64, sqrt_exact};

use super::space::{Overflow, Style, header, speed_angle, unit_suffix, vector};
use super::text::Block;

/// What the report says of the law.
pub const LAW: &str = "Newton's restitution at every contact at once (a linear complementarity \
                       problem, solved exactly by Lemke's method); real simultaneous impacts \
                       are sensitive to the law: --sequential also shows the pairs colliding \
                       one at a time";

/// The order of the sequential answer.
pub const ORDER: &str = "the pairs collide one at a time by the two-body rule, in the order of \
                         the contacts table, swept again until none approaches";

/// A rendered report, with the solved outcome and the posed balls it renders (the page draws
/// those, `view::nbody`, rather than read the rounded numbers back).
pub struct Rendered {
    pub text: String,
    pub json: Value,
    pub outcome: Outcome,
    pub balls: Balls,
}

/// Why the report cannot be made.
#[derive(Debug, thiserror::Error)]
pub enum ReportError {
    #[error(transparent)]
    Balls(#[from] BallsError),
    #[error(transparent)]
    Contacts(#[from] contacts::ContactsError),
    #[error(transparent)]
    Overflow(#[from] Overflow),
    #[error("--energy-unit: {0}")]
    EnergyUnit(String),
}

/// Poses, solves and renders touching balls; `sequential` adds the sequential answer.
pub fn run(
    input: &BallsInput,
    sequential: bool,
    energy_unit: Option<&'static crate::values::units::EnergyUnit>,
) -> Result<Rendered, ReportError> {
    let balls = input.pose()?;
    let solved = contacts::simultaneous(&balls.masses, &balls.v_in, &balls.contacts, &balls.e)?;
    let seq = if sequential {
        Some(contacts::sequential(
            &balls.masses,
            &balls.v_in,
            &balls.contacts,
            &balls.e,
        )?)
    } else {
        None
    };
    let mut units = balls.posed.units.clone();
    if let Some(u) = energy_unit {
        units = units
            .with_energy_unit(u)
            .map_err(|e| ReportError::EnergyUnit(e.to_string()))?;
    }
    let style =
        Style::new(input.input.exact, units.energy_scale()).with_bearings(balls.posed.bearings);
    let o = Outcome {
        dim: balls.posed.statement.dim,
        masses: balls.masses.clone(),
        v_in: balls.v_in.clone(),
        fin: solved.fin.clone(),
        normal: None,
        e: Some(balls.e.clone()),
        approx: crate::space::outcome::Marks::uniform(balls.rounded),
    };
    let text = text(&o, &balls, &solved, seq.as_ref(), &style, &units);
    let json = json(&o, &balls, &solved, seq.as_ref(), &style)?;
    let text = style.checked(text)?;
    Ok(Rendered {
        text,
        json,
        outcome: o,
        balls,
    })
}

/// `sign(w) sqrt(w^2 / n.n)`: a rate along `n` per unit length of `n`, and whether it is
/// rounded.
fn along(w: &Q, n: &[Q]) -> (Q, bool) {
    let sq = w * w / dot(n, n);
    let (r, rounded) = match sqrt_exact(&sq) {
        Some(r) => (r, false),
        None => (sqrt_binary64(&sq), true),
    };
    (if w.is_negative() { -r } else { r }, rounded)
}

/// The impulse's size `P |n|`.
fn impulse_size(p: &Q, n: &[Q]) -> (Q, bool) {
    along(&(p * dot(n, n)), n)
}

fn pair(c: &Contact) -> String {
    format!("{}-{}", c.a + 1, c.b + 1)
}

/// `30°` in the plane; the components in space.
fn direction(style: &Style, c: &Contact, approx: bool) -> String {
    match polar(&c.normal).1 {
        Some(a) => format!("{}°", num(a)),
        None => vector(style, &c.normal, approx),
    }
}

fn text(
    o: &Outcome,
    balls: &Balls,
    s: &Solved,
    seq: Option<&Sequential>,
    style: &Style,
    units: &crate::values::units::Units,
) -> String {
    let a = o.approx.any();
    let show = |(q, r): (Q, bool)| style.show(&q, a || r);
    let mut out = header(o, style, units);
    out.push_str(&super::block::paragraph(&format!("Law: {LAW}.")));
    let mut b = Block::new("Contacts (n from a to b; u = n.(v_b - v_a)/|n|, < 0: approaching)");
    b.cell_vec(
        ["a-b", "n at", "u IN", "u FIN", "impulse"]
            .map(String::from)
            .to_vec(),
    );
    for (k, c) in balls.contacts.iter().enumerate() {
        b.cell_vec(vec![
            pair(c),
            direction(style, c, a),
            show(along(&s.w_in[k], &c.normal)),
            show(along(&s.w_fin[k], &c.normal)),
            show(impulse_size(&s.impulses[k], &c.normal)),
        ]);
    }
    b.render(&mut out);
    if s.indeterminate {
        out.push_str(&super::block::paragraph(
            "The impulses are one choice of many (more contacts than the bodies can feel); \
             the final velocities are the same for every choice.",
        ));
    }
    let unit = unit_suffix(units);
    velocities(
        &mut out,
        "Velocities (IN, FIN)",
        &o.v_in,
        &o.fin,
        style,
        a,
        &unit,
    );
    let ki = o.ke_in();
    energy(&mut out, "Energy (KE = 1/2 V.M.V)", &ki, &o.fin, o, style);
    if let Some(Sequential { fin, impacts, .. }) = seq {
        out.push('\n');
        out.push_str(&super::block::paragraph(&format!(
            "Sequential answer ({ORDER}): {impacts} two-body impact{}.",
            if *impacts == 1 { "" } else { "s" }
        )));
        velocities(
            &mut out,
            "Velocities (IN, FIN sequential)",
            &o.v_in,
            fin,
            style,
            a,
            &unit,
        );
        energy(&mut out, "Energy, sequential", &ki, fin, o, style);
    }
    out
}

/// KE_IN, KE_FIN of `fin` and what was lost, under `title`.
fn energy(out: &mut String, title: &str, ki: &Q, fin: &[Vec<Q>], o: &Outcome, style: &Style) {
    let kf = contacts::kinetic(&o.masses, fin);
    let mut e = Block::new(title);
    for (label, q) in [
        ("KE_IN", ki.clone()),
        ("KE_FIN", kf.clone()),
        ("lost = KE_IN - KE_FIN", ki - &kf),
    ] {
        e.row(label, style.show(&style.energy(&q), o.approx.any()), "");
    }
    e.render(out);
}

/// The table of each body's velocity before and after.
fn velocities(
    out: &mut String,
    title: &str,
    v_in: &[Vec<Q>],
    fin: &[Vec<Q>],
    style: &Style,
    a: bool,
    unit: &str,
) {
    let mut b = Block::new(title);
    b.cell_vec(
        ["body", "IN", "FIN", "|FIN| @ angle"]
            .map(String::from)
            .to_vec(),
    );
    for (i, (v, f)) in v_in.iter().zip(fin).enumerate() {
        b.cell_vec(vec![
            format!("{}", i + 1),
            format!("{}{unit}", vector(style, v, a)),
            format!("{}{unit}", vector(style, f, a)),
            speed_angle(style, f),
        ]);
    }
    b.render(out);
}

fn json(
    o: &Outcome,
    balls: &Balls,
    s: &Solved,
    seq: Option<&Sequential>,
    style: &Style,
) -> Result<Value, Overflow> {
    let a = o.approx.any();
    let base = super::space::json(o, super::space::Show::default(), style)?;
    let mut m: Map<String, Value> = match base {
        Value::Object(m) => m,
        _ => Map::new(),
    };
    let jq = |(q, r): (Q, bool)| style.json(&q, a || r);
    let vecs = |vs: &[Vec<Q>]| -> Value {
        Value::Array(
            vs.iter()
                .map(|v| Value::Array(v.iter().map(|x| style.json(x, a)).collect()))
                .collect(),
        )
    };
    m.insert("law".into(), json!("newton-simultaneous"));
    if let Some(p) = &balls.positions {
        m.insert("positions".into(), vecs(p));
    }
    if let Some(r) = &balls.radii {
        m.insert(
            "radii".into(),
            Value::Array(r.iter().map(|x| style.json(x, a)).collect()),
        );
    }
    let contact_json = |impulses: &[Q], w_fin: &[Q]| -> Value {
        Value::Array(
            balls
                .contacts
                .iter()
                .enumerate()
                .map(|(k, c)| {
                    let on_b: Vec<Q> = c.normal.iter().map(|x| x * &impulses[k]).collect();
                    let mut row = json!({
                        "pair": [c.a + 1, c.b + 1],
                        "normal": c.normal.iter().map(|x| style.json(x, a)).collect::<Vec<_>>(),
                        "impulse": jq(impulse_size(&impulses[k], &c.normal)),
                        "impulse_vector": on_b.iter().map(|x| style.json(x, a)).collect::<Vec<_>>(),
                        "normal_velocity": {
                            "in": jq(along(&s.w_in[k], &c.normal)),
                            "fin": jq(along(&w_fin[k], &c.normal)),
                        },
                    });
                    if let (Some(angle), Value::Object(r)) = (polar(&c.normal).1, &mut row) {
                        r.insert("normal_angle_deg".into(), json!(angle));
                    }
                    row
                })
                .collect(),
        )
    };
    m.insert("contacts".into(), contact_json(&s.impulses, &s.w_fin));
    m.insert("impulses_unique".into(), json!(!s.indeterminate));
    if let Some(Sequential {
        fin,
        impulses: total,
        impacts,
    }) = seq
    {
        let w_fin = contacts::gap_rates(&balls.contacts, fin);
        let kf = contacts::kinetic(&o.masses, fin);
        let ki = o.ke_in();
        m.insert(
            "sequential".into(),
            json!({
                "order": ORDER,
                "impacts": impacts,
                "fin": vecs(fin),
                "contacts": contact_json(total, &w_fin),
                "energy": {
                    "fin": style.json(&style.energy(&kf), a),
                    "lost": style.json(&style.energy(&(&ki - &kf)), a),
                },
            }),
        );
    }
    style.checked_json(Value::Object(m))
}
