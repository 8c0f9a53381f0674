//! `--show changes` in the plane, in space and for N bodies on a line (issue 45 §5): each body's
//! change of velocity `dv_i = v_i' - v_i`, impulse `dp_i = m_i dv_i` (they sum to zero, momentum
//! kept), kinetic energy before and after, `1/2 m_i |v_i|^2` and `1/2 m_i |v_i'|^2`, its change,
//! and the share of the energy lost, `(KE_IN - KE_FIN) / KE_IN`: the two-body rail's section
//! (`report::changes`), body by body. Exact, rounded once.

use serde_json::{Map, Value};

use super::{Style, vector_each};
use crate::report::text::Block;
use crate::space::outcome::{Outcome, dot, sub};
use crate::values::rational::{Q, half};
use crate::values::units::Units;

/// One body's change of velocity, impulse, and kinetic energy before and after.
struct Change {
    dv: Vec<Q>,
    dp: Vec<Q>,
    ke_in: Q,
    ke_fin: Q,
}

/// Body `i`'s change.
fn body(o: &Outcome, i: usize) -> Change {
    let m = &o.masses[i];
    let ke = |v: &[Q]| half() * m * dot(v, v);
    Change {
        dv: sub(&o.fin[i], &o.v_in[i]),
        dp: o.impulse(i),
        ke_in: ke(&o.v_in[i]),
        ke_fin: ke(&o.fin[i]),
    }
}

/// `lost / KE_IN`, when anything moved before.
fn lost_fraction(o: &Outcome) -> Option<Q> {
    let ke = o.ke_in();
    (ke != Q::ZERO).then(|| o.lost() / ke)
}

/// The section as text: a row per body and quantity.
pub fn text(o: &Outcome, style: &Style, units: &Units) -> Block {
    let m = &o.approx;
    let e = |q: &Q, a: bool| style.show(&style.energy(q), a);
    let impulse = match (units.mass, units.velocity) {
        (Some(_), Some(_)) => format!("impulse in {}, ", units.impulse()),
        _ => String::new(),
    };
    let mut b = Block::new(format!(
        "Changes (each body; {impulse}energies in {})",
        units.energy()
    ));
    let n = o.bodies();
    let all: Vec<_> = (0..n).map(|i| body(o, i)).collect();
    for (i, c) in all.iter().enumerate() {
        let k = i + 1;
        b.row(
            format!("dv{k} = v{k}' - v{k}"),
            vector_each(style, &c.dv, |k| m.change_at(i, k)),
            "",
        );
    }
    for (i, c) in all.iter().enumerate() {
        let k = i + 1;
        let note = if k == n { "the impulses sum to 0" } else { "" };
        b.row(
            format!("dp{k} = m{k} dv{k}"),
            vector_each(style, &c.dp, |k| m.change_at(i, k)),
            note,
        );
    }
    for (i, c) in all.iter().enumerate() {
        let k = i + 1;
        b.row(
            format!("KE{k}: IN, FIN"),
            format!(
                "{}, {}",
                e(&c.ke_in, m.body_in(i)),
                e(&c.ke_fin, m.body_fin(i))
            ),
            format!("1/2 m{k} |v{k}|^2, 1/2 m{k} |v{k}'|^2"),
        );
    }
    for (i, c) in all.iter().enumerate() {
        let k = i + 1;
        b.row(
            format!("dKE{k}"),
            e(&(&c.ke_fin - &c.ke_in), m.change(i)),
            "",
        );
    }
    let a = m.any();
    if let Some(f) = lost_fraction(o) {
        // As a percentage too, of the exact share (`--exact` prints the fraction alone).
        let percent = if style.exact {
            String::new()
        } else {
            format!("= {} %", style.show(&(&f * Q::from(100)), a))
        };
        b.row("lost / KE_IN", style.show(&f, a), percent);
    }
    b
}

/// The section as JSON: `dv`, `impulse` (per-body vectors), `ke_in`, `ke_fin`, `dke` (per
/// body) and `lost_fraction`.
pub fn json(o: &Outcome, style: &Style) -> Value {
    let marks = &o.approx;
    let all: Vec<_> = (0..o.bodies()).map(|i| body(o, i)).collect();
    let vecs = |pick: fn(&Change) -> &Vec<Q>| {
        Value::Array(
            all.iter()
                .enumerate()
                .map(|(i, c)| {
                    Value::Array(
                        pick(c)
                            .iter()
                            .enumerate()
                            .map(|(k, x)| style.json(x, marks.change_at(i, k)))
                            .collect(),
                    )
                })
                .collect(),
        )
    };
    let energies = |pick: fn(&Change) -> Q, approx: &dyn Fn(usize) -> bool| {
        Value::Array(
            all.iter()
                .enumerate()
                .map(|(i, c)| style.json(&style.energy(&pick(c)), approx(i)))
                .collect(),
        )
    };
    let mut m = Map::new();
    m.insert("dv".into(), vecs(|c| &c.dv));
    m.insert("impulse".into(), vecs(|c| &c.dp));
    m.insert(
        "ke_in".into(),
        energies(|c| c.ke_in.clone(), &|i| marks.body_in(i)),
    );
    m.insert(
        "ke_fin".into(),
        energies(|c| c.ke_fin.clone(), &|i| marks.body_fin(i)),
    );
    m.insert(
        "dke".into(),
        energies(|c| &c.ke_fin - &c.ke_in, &|i| marks.change(i)),
    );
    if let Some(f) = lost_fraction(o) {
        m.insert("lost_fraction".into(), style.json(&f, marks.any()));
    }
    Value::Object(m)
}
