//! Text for people: one aligned block per section, in the lecture's notation, leaving out what
//! means nothing for the case (no energy lost when elastic, no separate FIN when the bodies stick,
//! no off-diagonal entries for a diagonal tensor).

pub use super::block::{Block, duration, pair, paragraph, parts, wrap};
use super::{
    ChangeReport, Diagnostics, Ellipses, Energy, Forms, Momentum, Notes, Products, Report, Reverse,
    Vectors,
};
use crate::line::case::Case;
use crate::line::ellipse::Ellipse;
use crate::values::quantity::Scalar;

/// A value for the header (`Number::brief`).
pub fn typed(n: &crate::values::number::Number) -> String {
    n.brief()
}

/// `M = diag(4, 1)   V_IN = (60, 10)   e = 1 (elastic: ka-bong)`, a line.
pub fn header(case: &Case) -> String {
    header_in(case, false)
}

/// The header; `exact`: a solved value (e, a mass, a velocity) is shown as the fraction it is,
/// as `Solved:` and FIN show it (`Solved: e = 25/32` and `e = 25/32`, `M = diag(800/11, 200)`;
/// issue 45 §5), not as its decimal (`0.78125`) or `≈` digits; a unit conversion keeps its
/// decimal (`10 g` is `0.01` kg).
pub fn header_in(case: &Case, exact: bool) -> String {
    use crate::values::number::Number;
    use crate::values::quantity::Exact;
    let e = case.restitution();
    let solved = |n: &Number| (exact && n.is_answer()).then(|| Exact::Rational(n.exact()).show());
    // Typed (or solved) text as it is; a binary64-born value (the default e = 1) as a header
    // shows it, not as its Debug digits ("1.0").
    let shown = |n: &Number| {
        solved(n).unwrap_or_else(|| match n.text() {
            std::borrow::Cow::Borrowed(t) if exact && t.len() <= 40 => t.to_string(),
            _ => typed(n),
        })
    };
    let mass = |n: &Number| solved(n).unwrap_or_else(|| n.brief());
    let e_text = shown(e.number());
    let mut out = parts(&[
        format!("M = {}", case.inertia().describe_with(mass)),
        format!(
            "V_IN = ({}, {})",
            shown(&case.velocities[0]),
            shown(&case.velocities[1])
        ),
        format!("e = {e_text} ({})", e.kind()),
    ]);
    out.push_str(&header_units(&case.units));
    out
}

/// `Units: masses in kg, velocities in m/s, energies in J`, when units were given.
pub fn header_units(u: &crate::values::units::Units) -> String {
    if u.mass.is_none() && u.velocity.is_none() {
        return String::new();
    }
    let given = |unit: Option<&str>| unit.map_or("as given".to_string(), |n| format!("in {n}"));
    paragraph(&format!(
        "Units: masses {}, velocities {}, energies in {}",
        given(u.mass),
        given(u.velocity),
        u.energy()
    ))
}

/// `FIN: v1' = 40 mph, v2' = 90 mph`, the answer to a homework case with units (seen from the
/// lab, when the bodies meet); `None` otherwise.
pub fn answer<N: Scalar>(case: &Case, report: &Report<N>) -> Option<String> {
    let unit = case.units.velocity?;
    let v = report.vectors.as_ref().filter(|_| report.frame.is_none())?;
    if !v.approaching {
        return None;
    }
    let own = Scales::of(case, v, true);
    let [f1, f2] = [
        v.fin[0].snap(own.fin[0]).show(),
        v.fin[1].snap(own.fin[1]).show(),
    ];
    // Wrapped to the terminal like every line of text (COLUMNS=40 too).
    Some(paragraph(&if case.restitution().is_totally_inelastic() {
        format!("FIN: v1' = v2' = {f1} {unit} (the bodies stick)")
    } else {
        format!("FIN: v1' = {f1} {unit}, v2' = {f2} {unit}")
    }))
}

/// Renders the report of `case` as text.
pub fn render<N: Scalar>(case: &Case, report: &Report<N>) -> String {
    let mut out = String::new();
    out.push_str(&header_in(case, N::EXACT));
    if let Some(f) = &report.frame {
        out.push_str(&paragraph(&format!(
            "Frame: {} (observer velocity w = {}; every velocity shifted by -w)",
            f.name,
            f.w.show()
        )));
    }
    if let Some(v) = &report.vectors {
        vectors(case, v, report.frame.is_none()).render(&mut out);
    }
    if let Some(m) = &report.momentum {
        momentum(case, m, &report.notes).render(&mut out);
    }
    if let Some(f) = &report.forms {
        forms(case, f, report.energy.as_ref(), &report.notes).render(&mut out);
    }
    if let Some(en) = &report.energy {
        energy(case, en, &report.notes).render(&mut out);
    }
    if let Some(el) = &report.ellipses {
        ellipses(case, el).render(&mut out);
    }
    if let Some(p) = &report.products {
        products(p).render(&mut out);
    }
    if let Some(c) = &report.changes {
        changes(c, &case.units).render(&mut out);
    }
    if let Some(h) = &report.heights {
        // Always of the lab's speeds (`Report::of`), which a moving frame's vectors are not.
        let lab = if report.frame.is_some() {
            "; the lab's speeds"
        } else {
            ""
        };
        heights(h, lab).render(&mut out);
    }
    for b in report.asked.blocks() {
        b.render(&mut out);
    }
    if let Some(d) = &report.diagnostics {
        diagnostics(d).render(&mut out);
    }
    if let Some(r) = &report.reverse {
        reverse(case, r).render(&mut out);
    }
    out
}

fn reverse<N: Scalar>(case: &Case, r: &Reverse<N>) -> Block {
    let mut b = Block::new("Time reversed (t -> -t: V -> -V, IN and FIN trade places)");
    b.row("IN'  = -FIN", pair(&r.v_in), "");
    b.row("FIN' = -IN", pair(&r.fin), "");
    if case.restitution().is_elastic() {
        let (same, why) = if r.equals_original {
            ("yes", "elastic, seen from the COM frame")
        } else {
            (
                "no",
                "only in the COM frame is an elastic collision its own time reverse",
            )
        };
        b.row("same as the original?", same, why);
    } else {
        let superelastic = case.restitution().is_superelastic();
        let (why, gained, from) = if superelastic {
            (
                "= 1/e < 1: an ordinary collision, which loses what the original released",
                "energy lost",
                "= the original's energy released",
            )
        } else {
            (
                "= 1/e > 1: an explosion, not a collision",
                "energy gained",
                "= the original's energy lost",
            )
        };
        b.row("e'", r.restitution.show(), why);
        b.row("KE_IN' = KE_FIN", r.energy.ke_in.show(), "");
        b.row("KE_FIN' = KE_IN", r.energy.fin.show(), "");
        let amount = r.energy.gained.as_ref().or(r.energy.lost.as_ref());
        b.row(gained, amount.map(N::show).unwrap_or_default(), from);
    }
    b
}

fn diagnostics(d: &Diagnostics) -> Block {
    let mut b = Block::new("Diagnostics (this run's own error and run time)");
    let ulps = |r: f64| format!("{:.2} ulp", r / f64::EPSILON);
    b.row(
        "momentum residual",
        format!("{:.1e}", d.momentum_residual),
        ulps(d.momentum_residual),
    );
    b.row(
        "KE_FIN - (KE_COM + e^2 crunch)",
        format!("{:.1e}", d.energy_residual),
        ulps(d.energy_residual),
    );
    b.row(
        "solve time",
        format!("{:.0} ns", d.solve_ns),
        format!("median, {} solves", d.repetitions),
    );
    b
}

/// `pair`, with rounding noise below the scale's error bound shown as 0 (`Scalar::snap`).
fn snapped<N: Scalar>(v: &[N; 2], scale: [f64; 2]) -> String {
    pair(&[v[0].snap(scale[0]), v[1].snap(scale[1])])
}

/// The largest velocity of IN and FIN: the scale of their rounding noise (`Scalar::snap`).
fn scale<N: Scalar>(v: &Vectors<N>) -> f64 {
    v.v_in
        .iter()
        .chain(&v.fin)
        .map(N::magnitude)
        .fold(0.0, f64::max)
}

/// The error bounds a printed velocity is zeroed within (`Scalar::snap`): each value's own.
/// `V_COM = w1 V1 + w2 V2` (`w_i = m_i / M`) is a quotient accurate to ulps of `w1 |V1| + w2
/// |V2|`, and `FIN_i = V_i + (1 + e) w_j (V_j - V_i)` to ulps of `|V_i| + (1 + e) w_j (|V1| +
/// |V2|)`: a Moon's recoil of 6.79e-17 m/s beside a 5 m/s body is a number, not noise. Seen
/// from another frame, or with a general tensor, the largest velocity of IN and FIN bounds
/// them all.
struct Scales {
    com: f64,
    fin: [f64; 2],
}

impl Scales {
    fn of<N: Scalar>(case: &Case, v: &Vectors<N>, lab: bool) -> Scales {
        let global = scale(v);
        let whole = Scales {
            com: global,
            fin: [global, global],
        };
        let m = case.inertia().matrix();
        if !lab || !case.inertia().is_diagonal() {
            return whole;
        }
        let (m1, m2) = (m[(0, 0)], m[(1, 1)]);
        let total = m1 + m2;
        let (w1, w2) = (m1 / total, m2 / total);
        let (a, b) = (case.collision.v_in.x.abs(), case.collision.v_in.y.abs());
        let com = w1 * a + w2 * b;
        let k = 1.0 + case.restitution().value();
        let fin = if case.restitution().is_totally_inelastic() {
            [com, com]
        } else {
            [a + k * w2 * a + k * w2 * b, b + k * w1 * a + k * w1 * b]
        };
        if [com, fin[0], fin[1]].iter().all(|x| x.is_finite()) {
            Scales { com, fin }
        } else {
            whole
        }
    }
}

/// The vectors section; `lab`: seen from the lab.
fn vectors<N: Scalar>(case: &Case, v: &Vectors<N>, lab: bool) -> Block {
    let mut b = Block::new("Vectors (V1, V2)");
    let own = Scales::of(case, v, lab);
    b.row("IN   V_IN", pair(&v.v_in), "");
    b.row(
        "COM  V_COM u",
        snapped(&v.com, [own.com, own.com]),
        format!(
            "V_COM = P_total / M_total = {}",
            v.v_com.snap(own.com).show()
        ),
    );
    if case.restitution().is_totally_inelastic() {
        b.row("FIN  V_FIN", "= COM", "the bodies stick and move together");
    } else {
        b.row(
            "FIN  V_FIN",
            snapped(&v.fin, own.fin),
            "= (1 + e) V_COM u - e V_IN",
        );
    }
    if v.left == Some(2) {
        b.row(
            "",
            "",
            "V1 < V2: body 2 is behind (on the left) and catches body 1; with no positions \
             the order follows from the velocities",
        );
    }
    if !v.approaching {
        b.row("", "", "V1 = V2: the bodies never meet, so FIN = IN");
    }
    b
}

fn momentum<N: Scalar>(case: &Case, p: &Momentum<N>, notes: &Notes<N>) -> Block {
    let mut b = Block::new("Momentum (P = M.V)");
    b.row("P_IN   M.V_IN", pair(&p.p_in), "");
    let stuck = case.restitution().is_totally_inelastic();
    let note = if stuck {
        "the bodies' shares of P_total once stuck"
    } else {
        ""
    };
    b.row("P_FIN  M.V_FIN", pair(&p.fin), note);
    let (k1, k2, slope) = &notes.line;
    let slope = match slope {
        Some(s) => format!("slope {}", s.show()),
        None => "vertical".to_string(),
    };
    b.row(
        "P_total  u.M.V",
        p.total.show(),
        format!(
            "momentum line {} V1 + {} V2 = {}, {slope}",
            k1.show(),
            k2.show(),
            p.total.show()
        ),
    );
    b
}

fn forms<N: Scalar>(
    case: &Case,
    f: &Forms<N>,
    energy: Option<&Energy<N>>,
    notes: &Notes<N>,
) -> Block {
    let mut b = Block::new("Quadratic forms (X.M.Y)");
    let e = case.restitution();
    if e.is_totally_inelastic() {
        b.row(
            "V_COM.M.V_IN = V_COM.M.V_COM = V_FIN.M.V_IN = V_FIN.M.V_FIN = V_COM P_total",
            f.com_m_in.show(),
            "",
        );
        b.row("V_IN.M.V_IN", f.in_m_in.show(), "");
        return b;
    }
    b.row(
        "V_COM.M.V_IN = V_COM.M.V_FIN = V_COM.M.V_COM = V_COM P_total",
        f.com_m_in.show(),
        "",
    );
    b.row(
        "V_FIN.M.V_IN = V_IN.M.V_FIN",
        f.fin_m_in.show(),
        "M is symmetric",
    );
    if e.is_elastic() {
        b.row(
            "V_IN.M.V_IN = V_FIN.M.V_FIN",
            f.in_m_in.show(),
            "elastic: one energy ellipse",
        );
        // The lecture's check: crunch = V_IN.M.V_IN/4 - V_FIN.M.V_IN/4 when elastic, in the
        // forms' own unit (the energy section's may be another, --energy-unit).
        let crunch = energy
            .map(|_| format!(" = {}", notes.crunch.show()))
            .unwrap_or_default();
        b.row(
            "V_IN.M.V_IN/4 - V_FIN.M.V_IN/4",
            format!(
                "{} - {}",
                f.in_m_in.quarter().show(),
                f.fin_m_in.quarter().show()
            ),
            format!("= crunch{crunch} (elastic)"),
        );
    } else {
        b.row("V_IN.M.V_IN", f.in_m_in.show(), "");
        b.row("V_FIN.M.V_FIN", f.fin_m_fin.show(), "");
    }
    b
}

fn energy<N: Scalar>(case: &Case, en: &Energy<N>, notes: &Notes<N>) -> Block {
    let mut b = Block::new(format!(
        "Energy (KE = 1/2 V.M.V, in {})",
        case.units.energy()
    ));
    let e = case.restitution();
    if e.is_elastic() {
        b.row(
            "KE_IN = KE_FIN",
            en.ke_in.show(),
            "elastic: energy is conserved",
        );
    } else {
        b.row("KE_IN", en.ke_in.show(), "");
    }
    if e.is_totally_inelastic() {
        b.row("KE_FIN = KE_COM = 1/2 V_COM P_total", en.com.show(), "");
    } else {
        if !e.is_elastic() {
            b.row("KE_FIN = KE_COM + e^2 crunch", en.fin.show(), "");
        }
        b.row("KE_COM = 1/2 V_COM P_total", en.com.show(), "");
    }
    let mu_name = if case.inertia().is_diagonal() {
        "mu = M1 M2 / (M1 + M2)"
    } else {
        "mu = det M / M_total"
    };
    b.row(
        "crunch = KE_IN - KE_COM = 1/2 mu (V1 - V2)^2",
        en.crunch.show(),
        format!(
            "{mu_name} = {}, V1 - V2 = {}",
            notes.reduced_mass.show(),
            notes.relative_velocity.show()
        ),
    );
    let lost = en.lost.clone().unwrap_or_default();
    if e.is_totally_inelastic() {
        b.row(
            "lost = crunch",
            lost.show(),
            "all of the crunch energy turns into heat",
        );
    } else if let Some(released) = &en.released {
        b.row(
            "released = (e^2 - 1) crunch",
            released.show(),
            format!("superelastic, e = {e}: energy stored in the bodies is released"),
        );
    } else if !e.is_elastic() {
        b.row("lost = (1 - e^2) crunch", lost.show(), "");
    }
    b
}

/// `--show changes`: per body, then the fractions and forces (a collision or a separation).
pub fn changes<N: Scalar>(c: &ChangeReport<N>, units: &crate::values::units::Units) -> Block {
    let mut b = Block::new(format!(
        "Changes (body 1, body 2; impulse in {}, energies in {})",
        units.impulse(),
        units.energy()
    ));
    b.row("dv = FIN - IN", pair(&c.dv), "");
    b.row("impulse dp = M.dv", pair(&c.impulse), "equal and opposite");
    if let (Some(i), Some(f), Some(d)) = (&c.ke_in, &c.ke_fin, &c.dke) {
        b.row("KE_IN  1/2 m v^2", pair(i), "");
        b.row("KE_FIN 1/2 m f^2", pair(f), "");
        b.row("dKE = 1/2 m dv (f + v)", pair(d), "");
    }
    if let Some(l) = &c.lost_fraction {
        b.row("lost / KE_IN", l.show(), percent(l));
    }
    if let Some(t) = &c.transferred_fraction {
        b.row(
            "transferred",
            t.show(),
            match percent(t) {
                // Exact mode prints the fraction alone (8/9): no percentage, no orphan ':'.
                p if p.is_empty() => "KE_FIN of the body at rest / KE_IN of the other".into(),
                p => format!("{p}: KE_FIN of the body at rest / KE_IN of the other"),
            },
        );
    }
    if let Some(f) = &c.average_force {
        b.row(
            "average force dp / T",
            pair(f),
            format!("in {}", units.force()),
        );
    }
    b
}

/// `= 12.5 %`, from the printed value.
fn percent<N: Scalar>(x: &N) -> String {
    x.show()
        .parse::<f64>()
        .map(|v| format!("= {} %", crate::values::number::num(v * 100.0)))
        .unwrap_or_default()
}

fn ellipses<N: Scalar>(case: &Case, el: &Ellipses<N>) -> Block {
    let e = case.restitution();
    let heading = match &el.e_in.axes {
        None => "Energy ellipses (1/2 V.M.V = KE; radius a along V1, b along V2)".to_string(),
        Some([qa, qb]) => format!(
            "Energy ellipses (1/2 V.M.V = KE; radius a along {}, b along {}: principal axes of M)",
            pair(qa),
            pair(qb)
        ),
    };
    let mut b = Block::new(heading);
    let mut row = |name: &str, x: &Ellipse<N>| {
        b.cells([
            name.to_string(),
            format!("a = {}", x.a.show()),
            format!("b = {}", x.b.show()),
        ]);
    };
    if e.is_elastic() {
        row("IN = FIN", &el.e_in);
        row("COM", &el.com);
    } else if e.is_totally_inelastic() {
        row("IN", &el.e_in);
        row("COM = FIN", &el.com);
    } else {
        row("IN", &el.e_in);
        row("FIN", &el.fin);
        row("COM", &el.com);
    }
    b
}

fn products<N: Scalar>(p: &Products<N>) -> Block {
    let mut b = Block::new("Products");
    b.row("V_FIN . V_IN", p.dot_fin_in.show(), "plain dot product");
    let o = &p.outer_in_fin;
    let rows = [
        format!("[{}, {}]", o[0][0].show(), o[0][1].show()),
        format!("[{}, {}]", o[1][0].show(), o[1][1].show()),
    ];
    let whole = format!("[{}, {}]", rows[0], rows[1]);
    // The label and a matrix of long numbers pass 80 columns on one line: a row a line then.
    if "  V_IN (x) V_FIN  ".len() + whole.chars().count() <= crate::values::terminal::width() {
        b.row("V_IN (x) V_FIN", whole, "outer product");
    } else {
        b.row("V_IN (x) V_FIN", format!("[{},", rows[0]), "outer product");
        b.row("", format!(" {}]", rows[1]), "");
    }
    b
}

/// `--show heights`: the height of each IN and FIN speed (`lab`: a note on the frame).
pub fn heights<N: Scalar>(h: &super::Heights<N>, lab: &str) -> Block {
    let mut b = Block::new(format!(
        "Heights (v^2 / 2g with g = {} m/s^2, in m{lab})",
        h.g.show()
    ));
    b.row(
        "IN",
        pair(&h.at_in),
        "the height a fall from rest needs for each speed",
    );
    b.row(
        "FIN",
        pair(&h.fin),
        "how high each body rises (a pendulum's swing)",
    );
    b
}
