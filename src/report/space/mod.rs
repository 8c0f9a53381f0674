//! The report of an event in the plane or in space, or of N bodies on a line: what was solved,
//! the velocities as components and as speed @ angle, `V_COM`, the impulse, the collision of the
//! normal parts along the line of impact, energies and angles; as text for people (80 columns)
//! and as JSON (`in`, `fin` as arrays of per-body vectors).
//!
//! Every value is exact (`space::outcome`) and rounded once here: binary64 text and JSON carry the
//! correctly rounded value, `--exact` fractions (or `≈` digits of irrational ones).
//!
//! - this module: one event's sections, its time reverse;
//! - `frames`: the event from every standard frame;
//! - `solved`: a problem's solutions (what was solved, which are physical, the checks).

use std::cell::Cell;
use std::fmt::Write;

use num_traits::Signed;
use serde_json::{Map, Value, json};

use crate::space::angle::compass;
use crate::space::outcome::{Outcome, angle_between, dot, polar};
use crate::values::number::num;
use crate::values::quantity::{Exact, Scalar};
use crate::values::rational::{Q, to_f64};

use crate::values::units::Units;

use super::text::Block;

pub mod changes;
pub mod frames;
mod overflow;
pub mod solved;

use overflow::{BEYOND, beyond_at};
pub use overflow::{Overflow, named, unmarked};

/// What a planar report shows (`--show`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Show {
    pub vectors: bool,
    pub momentum: bool,
    pub forms: bool,
    pub energy: bool,
    pub angles: bool,
    /// Each body's dv, impulse and kinetic energy (`changes`).
    pub changes: bool,
    /// `angles` was asked for by name: where there are none, a note says why (issue 42).
    pub named_angles: bool,
}

impl Show {
    /// No section.
    pub fn none() -> Show {
        Show {
            vectors: false,
            momentum: false,
            forms: false,
            energy: false,
            angles: false,
            changes: false,
            named_angles: false,
        }
    }

    /// Every section.
    pub fn all() -> Show {
        Show {
            vectors: true,
            momentum: true,
            forms: true,
            energy: true,
            angles: true,
            changes: true,
            named_angles: false,
        }
    }
}

impl Default for Show {
    fn default() -> Show {
        Show {
            vectors: true,
            momentum: false,
            forms: false,
            energy: true,
            angles: true,
            changes: false,
            named_angles: false,
        }
    }
}

/// How values are written: binary64 (rounded once from exact) or exact fractions.
pub struct Style {
    pub exact: bool,
    /// Energies in another unit: the exact factor from the case's (`--energy-unit`).
    pub energy_scale: Option<Q>,
    /// Directions in the plane also as compass bearings (`@ 60° (N30E)`): when the problem
    /// typed one.
    pub bearings: bool,
    /// Set when a value is beyond binary64 (the report is then refused).
    overflow: Cell<bool>,
    /// Set by [`Style::energy`] when the energy it returns underflows: the value written next
    /// is that energy, marked beyond binary64 in JSON.
    underflow: Cell<bool>,
}

impl Style {
    pub fn new(exact: bool, energy_scale: Option<Q>) -> Style {
        Style {
            exact,
            energy_scale,
            bearings: false,
            overflow: Cell::new(false),
            underflow: Cell::new(false),
        }
    }

    /// The style that also writes directions as compass bearings when `bearings` is set.
    pub fn with_bearings(self, bearings: bool) -> Style {
        Style { bearings, ..self }
    }

    /// The binary64 nearest `q`. Beyond binary64's range is an error (set aside, and the
    /// report refused); a value below its smallest subnormal rounds to zero, as binary64
    /// arithmetic rounds it, within half that subnormal (a component of 1e-333 beside one of
    /// 1e35). Energies are not let underflow: see [`Style::energy`].
    fn f(&self, q: &Q) -> f64 {
        match to_f64(q) {
            // + 0.0: a negative value that rounds to zero prints as 0, not -0.
            Some(x) => x + 0.0,
            None => {
                self.overflow.set(true);
                0.0
            }
        }
    }

    /// A value for people.
    pub fn show(&self, q: &Q, approx: bool) -> String {
        self.underflow.set(false);
        // An approximation carries relative digits, so a zero among them is exactly zero (a
        // body at rest's part along an irrational unit normal): `0`, never `≈0`.
        let approx = approx && !q.is_zero();
        if self.exact {
            if approx {
                Exact::Approx(q.clone()).show()
            } else {
                Exact::Rational(q.clone()).show()
            }
        } else {
            match to_f64(q) {
                Some(x) => num(x + 0.0),
                // Beyond binary64: the report is refused (`checked`), but a line printed
                // before that (a solved value beside a failed check) shows the value itself,
                // never the 0 `f` stands in with.
                None => {
                    self.overflow.set(true);
                    Exact::Approx(q.clone()).show()
                }
            }
        }
    }

    /// A value for JSON: a number, or in exact mode a fraction string.
    /// Beyond binary64 (or an energy [`Style::energy`] found to underflow) it is marked, to
    /// be named by [`Style::checked_json`].
    pub fn json(&self, q: &Q, approx: bool) -> Value {
        let beyond = || Value::from(format!("{BEYOND}{}", Exact::Approx(q.clone()).show()));
        if self.underflow.replace(false) {
            return beyond();
        }
        if !self.exact && to_f64(q).is_none() {
            self.overflow.set(true);
            return beyond();
        }
        let approx = approx && !q.is_zero();
        if self.exact {
            let e = if approx {
                Exact::Approx(q.clone())
            } else {
                Exact::Rational(q.clone())
            };
            serde_json::to_value(&e).unwrap_or(Value::Null)
        } else {
            json!(self.f(q))
        }
    }

    /// An energy, in the unit asked for. In binary64 output a nonzero energy that would print
    /// as 0 is refused like an overflow: a lost or crunch energy of 0 beside a collision that
    /// loses energy would contradict its own label.
    pub fn energy(&self, q: &Q) -> Q {
        let q = match &self.energy_scale {
            Some(s) => q * s,
            None => q.clone(),
        };
        if !self.exact && !q.is_zero() && to_f64(&q) == Some(0.0) {
            self.overflow.set(true);
            self.underflow.set(true);
        }
        q
    }

    /// `t`, unless a value written with this style was beyond binary64.
    pub fn checked<T>(&self, t: T) -> Result<T, Overflow> {
        if self.overflow.get() {
            Err(Overflow { quantity: None })
        } else {
            Ok(t)
        }
    }

    /// A JSON report, unless a value in it was beyond binary64: then the error names the first
    /// such value by its path.
    pub fn checked_json(&self, v: Value) -> Result<Value, Overflow> {
        match beyond_at(&v) {
            Some(path) => Err(Overflow {
                quantity: Some(path),
            }),
            None => self.checked(v),
        }
    }
}

/// `(a, b)`, or `a` on a line.
pub(crate) fn vector(style: &Style, v: &[Q], approx: bool) -> String {
    vector_each(style, v, |_| approx)
}

/// `(a, b)` with component `k` marked approximate where `approx(k)`: a typed component beside
/// a solved irrational one stays exact.
pub(crate) fn vector_each(style: &Style, v: &[Q], approx: impl Fn(usize) -> bool) -> String {
    let parts: Vec<String> = v
        .iter()
        .enumerate()
        .map(|(k, x)| style.show(x, approx(k)))
        .collect();
    if parts.len() == 1 {
        parts[0].clone()
    } else {
        format!("({})", parts.join(", "))
    }
}

/// `4 @ 30°`: a vector's speed and direction (in the plane), or its speed (in space); with
/// bearings, `4 @ 60° (N30E)`.
/// A vector for JSON, component `k` marked approximate where `approx(k)`.
pub(crate) fn json_each(style: &Style, v: &[Q], approx: impl Fn(usize) -> bool) -> Value {
    Value::Array(
        v.iter()
            .enumerate()
            .map(|(k, x)| style.json(x, approx(k)))
            .collect(),
    )
}

pub(crate) fn speed_angle(style: &Style, v: &[Q]) -> String {
    let (speed, angle) = polar(v);
    match angle {
        Some(a) if v.len() == 2 && style.bearings => {
            let d = crate::values::rational::direction(v);
            format!(
                "{} @ {}° ({})",
                num(speed),
                num(a),
                compass(d[0], d[1], num)
            )
        }
        Some(a) if v.len() == 2 => format!("{} @ {}°", num(speed), num(a)),
        _ if v.len() == 1 => String::new(),
        _ if speed == 0.0 => "0".into(),
        _ => format!("|v| = {}", num(speed)),
    }
}

/// The velocities' unit after a vector (` m/s`), when the case has one.
pub(crate) fn unit_suffix(units: &Units) -> String {
    units.velocity.map(|u| format!(" {u}")).unwrap_or_default()
}

/// The header: bodies, masses, restitution and the line of impact.
pub fn header(o: &Outcome, style: &Style, units: &Units) -> String {
    let space = match o.dim {
        1 => "on a line",
        2 => "in the plane",
        _ => "in space",
    };
    let masses: Vec<String> = o
        .masses
        .iter()
        .enumerate()
        .map(|(i, m)| style.show(m, o.approx.mass(i)))
        .collect();
    // Many bodies' masses wrap (300 bodies on a line ran to 1,500 columns).
    let mut out = crate::values::terminal::wrap(
        &format!(
            "{} bodies {space}: masses {}{}",
            o.bodies(),
            masses.join(", "),
            units.mass.map(|u| format!(" {u}")).unwrap_or_default()
        ),
        crate::values::terminal::width(),
        "  ",
    );
    if let Some(e) = &o.e {
        let kind = if e.is_zero() {
            "totally inelastic: ka-runch"
        } else if *e == Q::ONE {
            "elastic: ka-bong"
        } else if *e > Q::ONE {
            "superelastic: energy released"
        } else if e.is_negative() {
            "negative: no collision"
        } else {
            "ka-whump"
        };
        let _ = writeln!(out, "e = {} ({kind})", style.show(e, o.approx.e()));
    }
    if let Some(n) = &o.normal {
        let line = format!(
            "Line of impact n = {} (from body 1 to body 2){}",
            vector(style, n, o.approx.all),
            match polar(n).1 {
                Some(a) => format!(", at {}°", num(a)),
                None => String::new(),
            }
        );
        out.push_str(&crate::values::terminal::wrap(
            &line,
            crate::values::terminal::width(),
            "  ",
        ));
    }
    out
}

/// `v2'`, `v1` and the like.
pub(crate) fn name(i: usize, fin: bool) -> String {
    format!("v{}{}", i + 1, if fin { "'" } else { "" })
}

/// The report's sections as text.
pub fn text(o: &Outcome, show: Show, style: &Style, units: &Units) -> Result<String, Overflow> {
    let mut out = String::new();
    let marks = &o.approx;
    let a = marks.any();
    let unit = unit_suffix(units);
    if show.vectors {
        let mut b = Block::new("Velocities (IN, then FIN)");
        for (fin, vs) in [(false, &o.v_in), (true, &o.fin)] {
            for (i, v) in vs.iter().enumerate() {
                let each = |k| {
                    if fin {
                        marks.fin(i, k)
                    } else {
                        marks.v_in(i, k)
                    }
                };
                b.row(
                    name(i, fin),
                    format!("{}{unit}", vector_each(style, v, each)),
                    speed_angle(style, v),
                );
            }
        }
        let com = o.v_com();
        b.row(
            "V_COM",
            format!("{}{unit}", vector(style, &com, marks.before())),
            speed_angle(style, &com),
        );
        if o.bodies() == 2 {
            let j = o.impulse(1);
            let unit = match (units.mass, units.velocity) {
                (Some(_), Some(_)) => format!(" {}", units.impulse()),
                _ => String::new(),
            };
            b.row(
                "J",
                format!(
                    "{}{unit}",
                    vector_each(style, &j, |k| marks.change_at(1, k))
                ),
                "impulse on body 2, m2 (v2' - v2)",
            );
        }
        b.render(&mut out);
        if let Some(parts) = o.normal_parts() {
            let a = a || !parts.exact;
            let mut b =
                Block::new("Along the line of impact (the normal parts collide as on a rail)");
            let com =
                (&o.masses[0] * &parts.v_in[0] + &o.masses[1] * &parts.v_in[1]) / o.total_mass();
            b.row(
                "IN",
                vector(style, &parts.v_in, a),
                "(v1.n, v2.n), n of unit length",
            );
            b.row(
                "COM",
                vector(style, &[com.clone(), com], a),
                "V_COM u along n",
            );
            b.row(
                "FIN",
                vector(style, &parts.fin, a),
                "tangential parts unchanged",
            );
            b.render(&mut out);
        }
    }
    if show.momentum {
        let mut b = Block::new(format!("Momentum (P = sum m v, in {})", units.impulse()));
        for (fin, vs) in [(false, &o.v_in), (true, &o.fin)] {
            for (i, v) in vs.iter().enumerate() {
                let p: Vec<Q> = v.iter().map(|x| x * &o.masses[i]).collect();
                let a = if fin {
                    marks.body_fin(i)
                } else {
                    marks.body_in(i)
                };
                b.row(
                    format!("p{}{}", i + 1, if fin { "'" } else { "" }),
                    vector(style, &p, a),
                    "",
                );
            }
        }
        b.row(
            "P_total",
            vector(style, &o.momentum(&o.v_in), marks.before()),
            "the same before and after",
        );
        b.render(&mut out);
    }
    if show.forms {
        // The lecture's quadratic forms in R^(dN), M = diag(m1 I, ..., mN I).
        let form = |x: &[Vec<Q>], y: &[Vec<Q>]| -> Q {
            o.masses
                .iter()
                .zip(x.iter().zip(y))
                .fold(Q::ZERO, |s, (m, (xi, yi))| s + m * dot(xi, yi))
        };
        let com: Vec<Vec<Q>> = vec![o.v_com(); o.bodies()];
        let mut b = Block::new("Quadratic forms (X.M.Y in R^(dN), M = diag(m1 I, ..., mN I))");
        b.row(
            "V_IN.M.V_IN",
            style.show(&form(&o.v_in, &o.v_in), marks.before()),
            "",
        );
        b.row(
            "V_FIN.M.V_FIN",
            style.show(&form(&o.fin, &o.fin), marks.after()),
            "",
        );
        b.row(
            "V_FIN.M.V_IN",
            style.show(&form(&o.fin, &o.v_in), a),
            "= V_IN.M.V_FIN",
        );
        b.row(
            "V_COM.M.V_IN",
            style.show(&form(&com, &o.v_in), marks.before()),
            "= V_COM.M.V_FIN = V_COM.P_total",
        );
        b.render(&mut out);
    }
    if show.energy {
        let e = |q: Q, a: bool| style.show(&style.energy(&q), a);
        let before = marks.before();
        let mut b = Block::new(format!("Energy (KE = 1/2 V.M.V, in {})", units.energy()));
        b.row("KE_IN", e(o.ke_in(), before), "");
        b.row("KE_FIN", e(o.ke_fin(), marks.after()), "");
        b.row("KE_COM = 1/2 M_total |V_COM|^2", e(o.ke_com(), before), "");
        match (&o.normal, o.bodies()) {
            (Some(_), 2) => b.row(
                "crunch = 1/2 mu (n.(v1 - v2))^2 / n.n",
                e(o.crunch(), before),
                format!(
                    "mu = {}",
                    style.show(&o.reduced_mass(), marks.mass(0) || marks.mass(1))
                ),
            ),
            _ => b.row("crunch = KE_IN - KE_COM", e(o.crunch(), before), ""),
        }
        let lost = o.lost();
        if lost.is_positive() {
            b.row("lost = KE_IN - KE_FIN", e(lost, a), "");
        } else if lost.is_negative() {
            b.row("released = KE_FIN - KE_IN", e(-lost, a), "");
        }
        b.render(&mut out);
    }
    if show.angles && o.dim >= 2 && o.bodies() == 2 {
        let mut b = Block::new("Angles");
        let mut any = false;
        if let Some(t) = angle_between(&o.fin[0], &o.fin[1]) {
            b.row("between v1' and v2'", format!("{}°", num(t)), "");
            any = true;
        }
        for i in 0..2 {
            if let Some(t) = angle_between(&o.v_in[i], &o.fin[i]) {
                b.row(
                    format!("body {} turned", i + 1),
                    format!("{}°", num(t)),
                    format!("from v{0} to v{0}'", i + 1),
                );
                any = true;
            }
        }
        // No heading without a row (every final velocity zero, or no body moving before),
        // unless asked for by name.
        if !any && show.named_angles {
            b.row("note", "", NO_ANGLE_AT_REST);
            any = true;
        }
        if any {
            b.render(&mut out);
        }
    } else if show.named_angles {
        let mut b = Block::new("Angles");
        b.row("note", "", no_angles(o));
        b.render(&mut out);
    }
    if show.changes {
        changes::text(o, style, units).render(&mut out);
    }
    style.checked(out)
}

/// Why a case has no angles (`--show angles` named).
fn no_angles(o: &Outcome) -> &'static str {
    if o.dim < 2 {
        "angles are between velocities in the plane or space: on a line every velocity is \
         along it"
    } else {
        "angles are printed for two bodies (between v1' and v2', and each body's turn)"
    }
}

/// Why a two-body case asked for its angles has none.
const NO_ANGLE_AT_REST: &str =
    "no angle: a body at rest before or after has no direction to turn from or to";

/// The time-reversed event (t -> -t: every velocity negated, IN and FIN trade places, e' = 1/e).
pub fn reverse_text(o: &Outcome, style: &Style) -> Result<String, Overflow> {
    let r = o.reversed();
    let a = o.approx.any();
    let mut b = Block::new("Time reversed (t -> -t: V -> -V, IN and FIN trade places)");
    for (i, v) in r.v_in.iter().enumerate() {
        b.row(
            format!("v{}  = -v{}'", i + 1, i + 1),
            vector_each(style, v, |k| r.approx.v_in(i, k)),
            "",
        );
    }
    for (i, v) in r.fin.iter().enumerate() {
        b.row(
            format!("v{}' = -v{}", i + 1, i + 1),
            vector_each(style, v, |k| r.approx.fin(i, k)),
            "",
        );
    }
    match (&o.e, &r.e) {
        (Some(_), Some(e)) if *e > Q::ONE => b.row(
            "e'",
            style.show(e, r.approx.e()),
            "= 1/e > 1: an explosion, not a collision",
        ),
        (Some(_), Some(e)) => b.row("e'", style.show(e, r.approx.e()), "= 1/e"),
        (Some(_), None) => b.row(
            "e'",
            "undefined",
            "1/e with e = 0: the stuck bodies fly apart",
        ),
        _ => {}
    }
    let lost = o.lost();
    if lost.is_positive() {
        b.row(
            "energy gained",
            style.show(&style.energy(&lost), a),
            "= the original's energy lost",
        );
    }
    let mut out = String::new();
    b.render(&mut out);
    style.checked(out)
}

/// The reversed event's JSON: `{"in", "fin", "restitution"}`.
pub fn reverse_json(o: &Outcome, style: &Style) -> Result<Value, Overflow> {
    let r = o.reversed();
    let mut m = Map::new();
    m.insert("in".into(), velocities(style, &r, false));
    m.insert("fin".into(), velocities(style, &r, true));
    if let Some(e) = &r.e {
        m.insert("restitution".into(), style.json(e, r.approx.e()));
    }
    style.checked_json(Value::Object(m))
}

/// Every body's velocity before (or after, `fin`), each component marked as it is.
pub(crate) fn velocities(style: &Style, o: &Outcome, fin: bool) -> Value {
    let vs = if fin { &o.fin } else { &o.v_in };
    Value::Array(
        vs.iter()
            .enumerate()
            .map(|(i, v)| {
                json_each(style, v, |k| {
                    if fin {
                        o.approx.fin(i, k)
                    } else {
                        o.approx.v_in(i, k)
                    }
                })
            })
            .collect(),
    )
}

/// The report as a JSON object.
pub fn json(o: &Outcome, show: Show, style: &Style) -> Result<Value, Overflow> {
    let marks = &o.approx;
    let a = marks.any();
    let vec1 = |v: &[Q], a: bool| json_each(style, v, |_| a);
    let mut m = Map::new();
    m.insert("dim".into(), json!(o.dim));
    // Exact output: values that hang on an irrational root are decimal strings (20 digits,
    // rounded), which "8" alone would not tell from the fraction 8.
    if style.exact && a {
        m.insert("approx".into(), json!(true));
    }
    m.insert(
        "masses".into(),
        json_each(style, &o.masses, |i| marks.mass(i)),
    );
    if let Some(e) = &o.e {
        m.insert("restitution".into(), style.json(e, marks.e()));
    }
    if let Some(n) = &o.normal {
        m.insert("normal".into(), vec1(n, marks.all));
    }
    if show.vectors {
        m.insert("in".into(), velocities(style, o, false));
        m.insert("fin".into(), velocities(style, o, true));
        let polar_of: Vec<(f64, Option<f64>)> = o.fin.iter().map(|v| polar(v)).collect();
        m.insert(
            "fin_speed".into(),
            json!(polar_of.iter().map(|p| p.0).collect::<Vec<_>>()),
        );
        if o.dim == 2 {
            m.insert(
                "fin_angle_deg".into(),
                json!(
                    polar_of
                        .iter()
                        .map(|p| p.1.unwrap_or(0.0))
                        .collect::<Vec<_>>()
                ),
            );
        }
        m.insert("v_com".into(), vec1(&o.v_com(), marks.before()));
        if o.bodies() == 2 {
            m.insert(
                "impulse".into(),
                json_each(style, &o.impulse(1), |k| marks.change_at(1, k)),
            );
        }
        if let Some(parts) = o.normal_parts() {
            let a = a || !parts.exact;
            m.insert(
                "normal_parts".into(),
                json!({
                    "in": parts.v_in.iter().map(|x| style.json(x, a)).collect::<Vec<_>>(),
                    "fin": parts.fin.iter().map(|x| style.json(x, a)).collect::<Vec<_>>(),
                }),
            );
        }
    }
    if show.momentum {
        m.insert(
            "momentum".into(),
            json!({ "total": vec1(&o.momentum(&o.v_in), marks.before()) }),
        );
    }
    if show.energy {
        let e = |q: Q, a: bool| style.json(&style.energy(&q), a);
        let before = marks.before();
        let lost = o.lost();
        let mut energy = Map::new();
        energy.insert("in".into(), e(o.ke_in(), before));
        energy.insert("fin".into(), e(o.ke_fin(), marks.after()));
        energy.insert("com".into(), e(o.ke_com(), before));
        energy.insert("crunch".into(), e(o.crunch(), before));
        if lost.is_negative() {
            energy.insert("released".into(), e(-lost, a));
        } else {
            energy.insert("lost".into(), e(lost, a));
        }
        m.insert("energy".into(), Value::Object(energy));
    }
    if show.angles && o.dim >= 2 && o.bodies() == 2 {
        if let Some(t) = angle_between(&o.fin[0], &o.fin[1]) {
            m.insert("angle_between_deg".into(), json!(t));
        }
        // How far each body turned, from v to v' (0 for a body at rest before or after).
        let turned: Vec<f64> = (0..2)
            .map(|i| angle_between(&o.v_in[i], &o.fin[i]).unwrap_or(0.0))
            .collect();
        m.insert("turned_deg".into(), json!(turned));
    } else if show.named_angles {
        m.insert("not_shown".into(), json!({ "angles": no_angles(o) }));
    }
    if show.changes {
        m.insert("changes".into(), changes::json(o, style));
    }
    style.checked_json(Value::Object(m))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::values::rational::int;

    fn pucks() -> Outcome {
        let v = |xs: &[i64]| xs.iter().map(|x| int(*x)).collect::<Vec<Q>>();
        Outcome {
            dim: 2,
            masses: v(&[1, 1]),
            v_in: vec![v(&[4, 0]), v(&[0, 0])],
            fin: vec![v(&[2, -2]), v(&[2, 2])],
            normal: Some(v(&[1, 1])),
            e: Some(int(1)),
            approx: crate::space::outcome::Marks::default(),
        }
    }

    #[test]
    fn text_fits_80_columns_and_names_every_vector() {
        let o = pucks();
        let s = Style::new(false, None);
        let t = text(&o, Show::default(), &s, &Units::default()).unwrap();
        for line in t.lines() {
            assert!(line.chars().count() <= 80, "{line}");
        }
        assert!(t.contains("v2'    (2, 2)   2.82842712474619 @ 45°"), "{t}");
        assert!(t.contains("between v1' and v2'  90°"), "{t}");
    }

    #[test]
    fn json_carries_vectors_per_body() {
        let o = pucks();
        let j = json(&o, Show::default(), &Style::new(false, None)).unwrap();
        assert_eq!(j["fin"], json!([[2.0, -2.0], [2.0, 2.0]]));
        assert_eq!(j["impulse"], json!([2.0, 2.0]));
        assert_eq!(j["energy"]["crunch"], json!(2.0));
        let j = json(&o, Show::default(), &Style::new(true, None)).unwrap();
        assert_eq!(j["v_com"], json!(["2", "0"]));
    }
}
