//! What follows a rigid impact (issue 42 section 3): the swing of a body on a pivot under
//! gravity (`--show swing`, `rigid::swing`) and a round body sliding to rolling on the floor
//! (`--show rolling`, `rigid::rolling`), as text blocks and JSON. A section asked of a case it
//! does not apply to says why, never nothing.

use serde_json::{Map, Value, json};

use crate::rigid::outcome::Outcome;
use crate::rigid::rolling::{NoRoll, Rolling};
use crate::rigid::swing::{End, NoSwing, Swing, Who};
use crate::values::rational::Q;

use super::super::space::{Style, vector};
use super::super::text::Block;
use super::super::{Section, Sections};
use super::{RigidUnits, energy_unit, spin};

/// `g` (default: standard gravity, exact).
fn gravity(show: &Sections) -> Q {
    show.gravity.clone().unwrap_or_else(|| {
        crate::values::units::STANDARD_GRAVITY
            .parse::<crate::values::number::Number>()
            .map(|n| n.exact())
            .unwrap_or_default()
    })
}

fn value(r: &Result<Q, Q>) -> (&Q, bool) {
    match r {
        Ok(q) => (q, false),
        Err(q) => (q, true),
    }
}

fn who(w: Who) -> String {
    match w {
        Who::Joined => "the joined body".into(),
        Who::Body(i) => format!("body {}", i + 1),
    }
}

/// The swing of an outcome, when asked.
pub fn swing(o: &Outcome, show: &Sections) -> Option<Result<Swing, NoSwing>> {
    show.contains(Section::Swing)
        .then(|| Swing::of(o, &gravity(show)))
}

/// The rolling of an outcome, when asked.
pub fn rolling(o: &Outcome, show: &Sections) -> Option<Vec<(usize, Result<Rolling, NoRoll>)>> {
    let g = gravity(show);
    show.contains(Section::Rolling)
        .then(|| Rolling::of(o, show.floor_friction.as_ref().map(|mu| (mu, &g))))
}

/// The swing as a text block.
pub fn swing_block(
    o: &Outcome,
    s: &Result<Swing, NoSwing>,
    show: &Sections,
    style: &Style,
    u: &RigidUnits,
) -> Block {
    let a = o.approx();
    let g = gravity(show);
    let mut b = Block::new(format!(
        "The swing (gravity g = {}{} along -y)",
        style.show(&g, false),
        u.suffix("m/s^2")
    ));
    let s = match s {
        Ok(s) => s,
        Err(why) => {
            b.row("note", "", format!("no swing: {why}"));
            return b;
        }
    };
    let m = u.suffix("m");
    b.row(
        "body",
        who(s.who),
        format!("on its pivot {}{m}", vector(style, &s.pivot, a)),
    );
    b.row(
        "M",
        format!("{}{}", style.show(&s.mass, a), u.suffix("kg")),
        "",
    );
    b.row(
        "I_p",
        format!("{}{}", style.show(&s.inertia, a), u.suffix("kg m^2")),
        "about the pivot",
    );
    let (l, la) = value(&s.length);
    b.row(
        "l",
        format!("{}{m}", style.show(l, a || la)),
        "the centre's distance from the pivot",
    );
    let (w, note) = spin(style, std::slice::from_ref(&s.omega), a, u);
    b.row("omega", w, note);
    b.row(
        "KE",
        format!(
            "{}{}",
            style.show(&style.energy(&s.energy), a),
            energy_unit(u)
        ),
        "1/2 I_p omega^2",
    );
    match &s.end {
        End::Still => b.row("swing", "none", "no spin after the impact: it stays put"),
        End::OnAxle => b.row(
            "swing",
            "none",
            "its centre is on the axle: gravity does no work, it turns on at omega",
        ),
        End::Rises { rise, degrees } => {
            b.row(
                "rise",
                format!("{}{m}", style.show(rise, a)),
                "of the centre: KE / (M g)",
            );
            b.row(
                "theta",
                format!("{} deg", style.show(degrees, true)),
                "the angle it turns before it stops",
            );
        }
        End::Balanced { rise } => {
            b.row(
                "rise",
                format!("{}{m}", style.show(rise, a)),
                "of the centre: KE / (M g)",
            );
            b.row(
                "top",
                "reached",
                "its centre just reaches the top, with no spin left",
            );
        }
        End::OverTheTop { rise, omega_top } => {
            let (r, ra) = value(rise);
            b.row("top", "passed", "KE > M g (l - y0): it goes over the top");
            b.row(
                "rise",
                format!("{}{m}", style.show(r, a || ra)),
                "of the centre to the top, l - y0",
            );
            let (w, wa) = value(omega_top);
            b.row(
                "omega_top",
                format!("{}{}", style.show(w, a || wa), u.suffix("rad/s")),
                "as it passes the top: omega^2 - 2 M g (l - y0) / I_p",
            );
        }
    }
    b
}

/// The rolling as a text block.
pub fn rolling_block(
    o: &Outcome,
    rolls: &[(usize, Result<Rolling, NoRoll>)],
    style: &Style,
    u: &RigidUnits,
) -> Block {
    let a = o.approx();
    let mut b = Block::new("Rolling (on a floor along x, below each body)");
    let (ms, m) = (u.suffix("m/s"), u.suffix("m"));
    for (n, (i, r)) in rolls.iter().enumerate() {
        let k = i + 1;
        if n > 0 {
            b.gap();
        }
        let r = match r {
            Ok(r) => r,
            Err(why) => {
                b.row(format!("body {k}"), "", format!("does not roll: {why}"));
                continue;
            }
        };
        b.row(
            format!("body {k}"),
            format!("R = {}{m}", style.show(&r.radius, a)),
            format!("I = {}{}", style.show(&r.inertia, a), u.suffix("kg m^2")),
        );
        b.row(
            "slip",
            format!("{}{ms}", style.show(&r.slip, a)),
            format!("v{k}' + omega{k}' R, the contact point's speed"),
        );
        b.row(
            "v_roll",
            format!("{}{ms}", style.show(&r.v_roll, a)),
            "(m R^2 v - I R omega)/(m R^2 + I)",
        );
        let (w, note) = spin(style, std::slice::from_ref(&r.omega_roll), a, u);
        let note = if note.is_empty() {
            "-v_roll / R".to_string()
        } else {
            format!("-v_roll / R, {note}")
        };
        b.row("omega_roll", w, note);
        match &r.slide {
            Some(s) => {
                b.row(
                    "t",
                    format!("{}{}", style.show(&s.time, a), u.suffix("s")),
                    format!(
                        "|slip| I / (mu g (I + m R^2)), floor mu = {}",
                        style.show(&s.mu, a)
                    ),
                );
                b.row(
                    "distance",
                    format!("{}{m}", style.show(&s.distance, a)),
                    "v t - 1/2 mu g sgn(slip) t^2, the centre's travel",
                );
            }
            None => b.row(
                "t",
                "",
                "the time and distance to roll need --floor-friction MU",
            ),
        }
    }
    b
}

/// The swing as JSON.
pub fn swing_json(o: &Outcome, s: &Result<Swing, NoSwing>, style: &Style) -> Value {
    let a = o.approx();
    let s = match s {
        Ok(s) => s,
        Err(why) => return json!({ "note": format!("no swing: {why}") }),
    };
    let vec1 = |v: &[Q]| Value::Array(v.iter().map(|x| style.json(x, a)).collect());
    let (l, la) = value(&s.length);
    let mut m = Map::new();
    m.insert(
        "body".into(),
        match s.who {
            Who::Joined => json!("joined"),
            Who::Body(i) => json!(i + 1),
        },
    );
    m.insert("mass".into(), style.json(&s.mass, a));
    m.insert("inertia".into(), style.json(&s.inertia, a));
    m.insert("pivot".into(), vec1(&s.pivot));
    m.insert("arm".into(), vec1(&s.arm));
    m.insert("length".into(), style.json(l, a || la));
    m.insert("omega".into(), style.json(&s.omega, a));
    m.insert("energy".into(), style.json(&style.energy(&s.energy), a));
    let end = match &s.end {
        End::Still => "still",
        End::OnAxle => "on the axle",
        End::Rises { rise, degrees } => {
            m.insert("rise".into(), style.json(rise, a));
            m.insert("angle_deg".into(), style.json(degrees, true));
            "stops"
        }
        End::Balanced { rise } => {
            m.insert("rise".into(), style.json(rise, a));
            "reaches the top"
        }
        End::OverTheTop { rise, omega_top } => {
            let (r, ra) = value(rise);
            let (w, wa) = value(omega_top);
            m.insert("rise".into(), style.json(r, a || ra));
            m.insert("omega_top".into(), style.json(w, a || wa));
            "over the top"
        }
    };
    m.insert("end".into(), json!(end));
    m.insert(
        "over_the_top".into(),
        json!(matches!(s.end, End::OverTheTop { .. })),
    );
    Value::Object(m)
}

/// The rolling as JSON: one object per movable body.
pub fn rolling_json(
    o: &Outcome,
    rolls: &[(usize, Result<Rolling, NoRoll>)],
    style: &Style,
) -> Value {
    let a = o.approx();
    let q = |x: &Q| style.json(x, a);
    Value::Array(
        rolls
            .iter()
            .map(|(i, r)| match r {
                Err(why) => json!({ "body": i + 1, "note": format!("does not roll: {why}") }),
                Ok(r) => {
                    let mut m = Map::new();
                    m.insert("body".into(), json!(i + 1));
                    m.insert("radius".into(), q(&r.radius));
                    m.insert("v".into(), q(&r.v));
                    m.insert("omega".into(), q(&r.omega));
                    m.insert("slip".into(), q(&r.slip));
                    m.insert("v_roll".into(), q(&r.v_roll));
                    m.insert("omega_roll".into(), q(&r.omega_roll));
                    if let Some(s) = &r.slide {
                        m.insert("friction".into(), q(&s.mu));
                        m.insert("g".into(), q(&s.g));
                        m.insert("time".into(), q(&s.time));
                        m.insert("distance".into(), q(&s.distance));
                    }
                    Value::Object(m)
                }
            })
            .collect(),
    )
}
