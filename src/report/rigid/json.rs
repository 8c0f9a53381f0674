//! The JSON of a rigid impact: `in` and `fin` as per-body `{"v", "omega"}`, the impulse, the
//! effective mass, the contact's mode, pivot impulses, the collision along the normal, energies,
//! momentum, the tensor and the ODE's run (docs/json.md, "Rigid bodies").

use serde_json::{Map, Value, json};

use crate::rigid::algebra::Mat;
use crate::rigid::body::{Mobility, Motion};
use crate::rigid::join::Joined;
use crate::rigid::laws::Tangential;
use crate::rigid::outcome::{Energy, Outcome};
use crate::values::rational::Q;

use super::super::space::{Overflow, Style};
use super::super::{Section, Sections};
use super::RigidUnits;

fn motion_json(style: &Style, m: &Motion, a: bool) -> Value {
    let v: Vec<Value> = m.v.iter().map(|x| style.json(x, a)).collect();
    let omega = if m.omega.len() == 1 {
        style.json(&m.omega[0], a)
    } else {
        Value::Array(m.omega.iter().map(|x| style.json(x, a)).collect())
    };
    json!({ "v": v, "omega": omega })
}

/// The report as a JSON object.
pub fn json(
    o: &Outcome,
    show: &Sections,
    style: &Style,
    u: &RigidUnits,
) -> Result<Value, Overflow> {
    let a = o.approx();
    let na = a || !o.normal_length().1;
    let p = &o.problem;
    let vec1 = |v: &[Q], approx: bool| -> Value {
        Value::Array(v.iter().map(|x| style.json(x, approx)).collect())
    };
    let mut m = Map::new();
    m.insert("dim".into(), json!(o.dim()));
    let bodies: Vec<Value> = o
        .bodies()
        .iter()
        .map(|b| {
            let mut j = Map::new();
            match (&b.mass, b.immovable()) {
                (_, Some(word)) => {
                    j.insert("mass".into(), json!(word));
                }
                (Some(mass), None) => {
                    j.insert("mass".into(), style.json(mass, a));
                }
                _ => {}
            }
            j.insert("position".into(), vec1(&b.position, a));
            if let Some(i) = b.inertia() {
                j.insert("inertia".into(), mat_json(style, i, a));
            }
            if let Some(s) = &b.shape {
                j.insert("shape".into(), json!(s.kind.name()));
            }
            if let Mobility::Pivoted {
                pivot, about_pivot, ..
            } = &b.mobility
            {
                j.insert("pivot".into(), vec1(pivot, a));
                j.insert("inertia_pivot".into(), mat_json(style, about_pivot, a));
            }
            Value::Object(j)
        })
        .collect();
    m.insert("bodies".into(), bodies.into());
    m.insert("point".into(), vec1(&p.pair.contact.point, a));
    m.insert("normal".into(), vec1(&p.pair.contact.normal, false));
    m.insert("restitution".into(), style.json(&p.e, a));
    match &p.tangential {
        Tangential::Smooth => {}
        Tangential::Coulomb(mu) => {
            m.insert("friction".into(), style.json(mu, a));
        }
        Tangential::Rough { beta, mu } => {
            m.insert("tangential_restitution".into(), style.json(beta, a));
            if let Some(mu) = mu {
                m.insert("friction".into(), style.json(mu, a));
            }
        }
        Tangential::Join => {}
    }
    m.insert("law".into(), json!(p.law_name()));
    m.insert("contact".into(), json!(o.impact.mode.name()));
    let motions = |ms: &[Motion; 2]| -> Value {
        Value::Array(ms.iter().map(|x| motion_json(style, x, a)).collect())
    };
    m.insert("in".into(), motions(o.v_in()));
    m.insert("fin".into(), motions(&o.fin));
    let t = o.tangential_impulse();
    m.insert(
        "impulse".into(),
        json!({
            "normal": style.json(&o.normal_impulse(), na),
            "tangential": if t.len() == 1 { style.json(&t[0], na) } else { vec1(&t, na) },
            "vector": vec1(&o.impact.impulse, a),
            "compression": style.json(&o.compression_impulse(), na),
        }),
    );
    if let Some(me) = o.effective_mass() {
        m.insert("m_eff".into(), style.json(&me, a));
    }
    let pivots = o.pivot_impulses();
    if pivots.iter().any(Option::is_some) {
        let dim = o.dim();
        m.insert(
            "pivot_impulse".into(),
            Value::Array(
                pivots
                    .iter()
                    .map(|p| match p {
                        Some(p) => vec1(p, a),
                        None => vec1(&vec![Q::ZERO; dim], false),
                    })
                    .collect(),
            ),
        );
    }
    let n = o.along_normal();
    let an = a || !n.exact;
    let masses: Vec<Value> = n
        .masses
        .iter()
        .map(|x| match x {
            Some(q) => style.json(q, a),
            None => json!("immovable"),
        })
        .collect();
    m.insert(
        "along_normal".into(),
        json!({
            "masses": masses,
            "in": vec1(&n.v_in, an),
            "com": style.json(&n.v_com, an),
            "fin": vec1(&n.fin, an),
            "crunch": style.json(&style.energy(&n.crunch), a),
            "restitution": style.json(&o.restitution_along(), an),
        }),
    );
    if let Some(j) = Joined::of(o) {
        let omega = if j.omega.len() == 1 {
            style.json(&j.omega[0], a)
        } else {
            vec1(&j.omega, a)
        };
        let mut joined = Map::new();
        joined.insert("mass".into(), style.json(&j.mass, a));
        joined.insert("centre".into(), vec1(&j.centre, a));
        joined.insert("inertia".into(), mat_json(style, &j.inertia, a));
        if let Some(p) = &j.pivot {
            joined.insert("pivot".into(), vec1(p, a));
        }
        joined.insert("v".into(), vec1(&j.v, a));
        joined.insert("omega".into(), omega);
        m.insert("joined".into(), Value::Object(joined));
    }
    if show.contains(Section::Energy) {
        let e = |q: &Q| style.json(&style.energy(q), a);
        let parts = |ms: &[Motion; 2]| -> Value {
            Value::Array(
                o.energies(ms)
                    .iter()
                    .map(|(t, r)| json!({"translation": e(t), "rotation": e(r)}))
                    .collect(),
            )
        };
        let mut en = Map::new();
        en.insert("in".into(), e(&o.ke_in()));
        en.insert("fin".into(), e(&o.ke_fin()));
        en.insert("bodies_in".into(), parts(o.v_in()));
        en.insert("bodies_fin".into(), parts(&o.fin));
        match o.energy() {
            Energy::Lost(q) => en.insert("lost".into(), e(&q)),
            Energy::Kept => en.insert("lost".into(), e(&Q::ZERO)),
            Energy::Gained(q) => en.insert("gained".into(), e(&q)),
        };
        m.insert("energy".into(), Value::Object(en));
    }
    if show.contains(Section::Momentum) {
        let about = o.about();
        m.insert(
            "momentum".into(),
            json!({
                "in": vec1(&o.momentum(o.v_in()), a),
                "fin": vec1(&o.momentum(&o.fin), a),
                "kept": o.momentum_kept(),
                "angular": {
                    "about": vec1(&about.point, a),
                    "in": vec1(&o.angular(o.v_in(), &about.point), a),
                    "fin": vec1(&o.angular(&o.fin, &about.point), a),
                    "kept": about.kept,
                },
            }),
        );
    }
    if show.contains(Section::Forms) {
        let pair = &p.pair;
        let mut f = Map::new();
        f.insert("J_n".into(), vec1(&pair.row(&pair.contact.normal), false));
        if o.dim() == 2 {
            f.insert("J_t".into(), vec1(&pair.row(&pair.tangent()), false));
        }
        f.insert("K".into(), mat_json(style, &pair.collision_matrix(), a));
        f.insert(
            "M".into(),
            Value::Array(
                o.bodies()
                    .iter()
                    .filter(|b| b.coordinates() > 0)
                    .map(|b| mat_json(style, &b.block(), a))
                    .collect(),
            ),
        );
        m.insert("tensor".into(), Value::Object(f));
    }
    if let Some(s) = super::after::swing(o, show) {
        m.insert("swing".into(), super::after::swing_json(o, &s, style));
    }
    if let Some(r) = super::after::rolling(o, show) {
        m.insert("rolling".into(), super::after::rolling_json(o, &r, style));
    }
    if let Some(ode) = &o.impact.ode {
        let mut j = json!({
            "method": "tsit45",
            "rtol": ode.rtol,
            "steps": ode.steps,
            "rhs_evals": ode.run.rhs_evals,
            "error_estimate": ode.error,
            "seconds": ode.seconds,
        });
        if let Some(s) = ode.run.stick {
            j["stick_at"] = json!(s);
        }
        m.insert("ode".into(), j);
    }
    m.insert("physical".into(), json!(o.paradox().is_none()));
    if let Some(why) = o.paradox() {
        m.insert("paradox".into(), json!(why));
    }
    if let Some(note) = &o.impact.note {
        m.insert("note".into(), json!(note));
    }
    if u.si {
        m.insert(
            "units".into(),
            json!({
                "mass": "kg", "length": "m", "velocity": "m/s", "omega": "rad/s",
                "inertia": "kg m^2", "impulse": "N s", "energy": u.units.energy(),
            }),
        );
    }
    style.checked_json(Value::Object(m))
}

fn mat_json(style: &Style, m: &Mat, a: bool) -> Value {
    if m.len() == 1 {
        return style.json(&m[0][0], a);
    }
    Value::Array(
        m.iter()
            .map(|r| Value::Array(r.iter().map(|x| style.json(x, a)).collect()))
            .collect(),
    )
}

/// The top-level keys of the JSON report (for a scene's `[expect]`).
pub const KEYS: [&str; 26] = [
    "dim",
    "bodies",
    "point",
    "normal",
    "restitution",
    "friction",
    "tangential_restitution",
    "law",
    "contact",
    "in",
    "fin",
    "impulse",
    "m_eff",
    "pivot_impulse",
    "along_normal",
    "joined",
    "energy",
    "momentum",
    "tensor",
    "swing",
    "rolling",
    "ode",
    "physical",
    "paradox",
    "note",
    "units",
];
