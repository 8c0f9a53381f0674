//! Text for people: one aligned block per section, in the lecture's notation, leaving out what
//! means nothing for the case (no energy lost when elastic, no separate FIN when the bodies stick,
//! no off-diagonal entries for a diagonal tensor).

use std::fmt::Write;

use super::{
    Diagnostics, Ellipses, Energy, Forms, Momentum, Notes, Products, Report, Reverse, Vectors,
};
use crate::case::Case;
use crate::ellipse::Ellipse;
use crate::frame::FramesTable;
use crate::quantity::Scalar;

/// A number as people read it: shortest round-trip digits, plain for 1e-5 <= |x| < 1e16 and in
/// scientific notation outside.
pub fn num(x: f64) -> String {
    let a = x.abs();
    if x == 0.0 {
        "0".to_string()
    } else if (1e-5..1e16).contains(&a) {
        format!("{x}")
    } else {
        format!("{x:e}")
    }
}

fn pair<N: Scalar>(v: &[N; 2]) -> String {
    format!("({}, {})", v[0].show(), v[1].show())
}

/// Rows of cells (`label  value  note ...`), aligned into columns under a heading.
struct Block {
    heading: String,
    rows: Vec<Vec<String>>,
}

impl Block {
    fn new(heading: impl Into<String>) -> Block {
        Block {
            heading: heading.into(),
            rows: Vec::new(),
        }
    }
    fn row(&mut self, label: impl Into<String>, value: impl Into<String>, note: impl Into<String>) {
        self.rows
            .push(vec![label.into(), value.into(), note.into()]);
    }
    fn cells<const N: usize>(&mut self, cells: [String; N]) {
        self.rows.push(cells.into());
    }
    fn render(&self, out: &mut String) {
        let columns = self.rows.iter().map(Vec::len).max().unwrap_or(0);
        let widths: Vec<usize> = (0..columns)
            .map(|i| {
                self.rows
                    .iter()
                    .filter_map(|r| r.get(i))
                    .map(|c| c.chars().count())
                    .max()
                    .unwrap_or(0)
            })
            .collect();
        let _ = writeln!(out, "\n{}", self.heading);
        for row in &self.rows {
            let mut line = String::from(" ");
            for (cell, w) in row.iter().zip(&widths) {
                let _ = write!(line, " {cell:<w$} ");
            }
            let _ = writeln!(out, "{}", line.trim_end());
        }
    }
}

/// `M = diag(4, 1)   V_IN = (60, 10)   e = 1 (elastic: ka-bong)`, a line.
fn header(case: &Case) -> String {
    let e = case.restitution();
    let mut out = format!(
        "M = {}   V_IN = ({}, {})   e = {} ({})\n",
        case.inertia().describe(),
        case.velocities[0],
        case.velocities[1],
        e,
        e.kind()
    );
    let u = &case.units;
    if u.mass.is_some() || u.velocity.is_some() {
        let given = |unit: Option<&str>| unit.map_or("as given".to_string(), |n| format!("in {n}"));
        out.push_str(&format!(
            "Units: masses {}, velocities {}, energies in {}\n",
            given(u.mass),
            given(u.velocity),
            u.energy()
        ));
    }
    out
}

/// Renders the report of `case` as text.
pub fn render<N: Scalar>(case: &Case, report: &Report<N>) -> String {
    let mut out = String::new();
    out.push_str(&header(case));
    if let Some(f) = &report.frame {
        let _ = writeln!(
            out,
            "Frame: {} (observer velocity w = {}; every velocity shifted by -w)",
            f.name,
            f.w.show()
        );
    }
    if let Some(v) = &report.vectors {
        vectors(case, v).render(&mut out);
    }
    if let Some(m) = &report.momentum {
        momentum(case, m, &report.notes).render(&mut out);
    }
    if let Some(f) = &report.forms {
        forms(case, f, report.energy.as_ref()).render(&mut out);
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
        b.row(
            "e'",
            r.restitution.show(),
            "= 1/e > 1: an explosion, not a collision",
        );
        b.row("KE_IN' = KE_FIN", r.energy.ke_in.show(), "");
        b.row("KE_FIN' = KE_IN", r.energy.fin.show(), "");
        b.row(
            "energy gained",
            r.energy.gained.show(),
            "= the original's energy lost",
        );
    }
    b
}

/// The frames table (lecture Figs. 2.5 and 3.4) with its checked invariants.
pub fn frames<N: Scalar>(case: &Case, t: &FramesTable<N>) -> String {
    let e = case.restitution();
    let mut out = String::new();
    out.push_str(&header(case));
    let heading = "Frames (an observer moving at w sees every velocity shifted by -w)";
    let mut b = Block::new(heading);
    let mut header = vec!["frame", "w", "IN", "COM"];
    if !e.is_totally_inelastic() {
        header.push("FIN");
    }
    if e.is_elastic() {
        header.extend(["KE_IN = KE_FIN", "KE_COM", "crunch"]);
    } else if e.is_totally_inelastic() {
        header.extend(["KE_IN", "KE_FIN = KE_COM", "crunch = lost"]);
    } else {
        header.extend(["KE_IN", "KE_FIN", "KE_COM", "crunch", "lost"]);
    }
    let reversing = t.frames.iter().any(|r| r.reverse_equals_original.is_some());
    if reversing {
        header.push("reversed = original");
    }
    b.rows.push(header.into_iter().map(String::from).collect());
    for r in &t.frames {
        let en = &r.energy;
        let mut row = vec![r.label.clone(), r.w.show(), pair(&r.v_in), pair(&r.com)];
        if !e.is_totally_inelastic() {
            row.push(pair(&r.fin));
        }
        if e.is_elastic() || e.is_totally_inelastic() {
            // Elastic: KE_IN = KE_FIN; stuck: KE_FIN = KE_COM and lost = crunch.
            row.extend([en.ke_in.show(), en.com.show(), en.crunch.show()]);
        } else {
            row.extend([
                en.ke_in.show(),
                en.fin.show(),
                en.com.show(),
                en.crunch.show(),
                en.lost.show(),
            ]);
        }
        if let Some(same) = r.reverse_equals_original {
            row.push(if same { "yes" } else { "no" }.into());
        }
        b.rows.push(row);
    }
    b.render(&mut out);
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
    let _ = writeln!(
        out,
        "\nInvariants, computed in each frame from its own velocities and equal in all:"
    );
    for l in lines {
        let _ = writeln!(out, "  {l}");
    }
    if e.is_totally_inelastic() {
        let _ = writeln!(
            out,
            "  (e = 0: FIN = COM, so the bodies' \"finally at rest\" frames are the COM frame)"
        );
    }
    out
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

fn vectors<N: Scalar>(case: &Case, v: &Vectors<N>) -> Block {
    let mut b = Block::new("Vectors (V1, V2)");
    b.row("IN   V_IN", pair(&v.v_in), "");
    b.row(
        "COM  V_COM u",
        pair(&v.com),
        format!("V_COM = P_total / M_total = {}", v.v_com.show()),
    );
    if case.restitution().is_totally_inelastic() {
        b.row("FIN  V_FIN", "= COM", "the bodies stick and move together");
    } else {
        b.row("FIN  V_FIN", pair(&v.fin), "= (1 + e) V_COM u - e V_IN");
    }
    if case.collision.v_in.x == case.collision.v_in.y {
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

fn forms<N: Scalar>(case: &Case, f: &Forms<N>, energy: Option<&Energy<N>>) -> Block {
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
        // The lecture's check: crunch = V_IN.M.V_IN/4 - V_FIN.M.V_IN/4 when elastic.
        let crunch = energy
            .map(|en| format!(" = {}", en.crunch.show()))
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
    if e.is_totally_inelastic() {
        b.row(
            "lost = crunch",
            en.lost.show(),
            "all of the crunch energy turns into heat",
        );
    } else if !e.is_elastic() {
        b.row("lost = (1 - e^2) crunch", en.lost.show(), "");
    }
    b
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
    b.row(
        "V_IN (x) V_FIN",
        format!(
            "[[{}, {}], [{}, {}]]",
            o[0][0].show(),
            o[0][1].show(),
            o[1][0].show(),
            o[1][1].show()
        ),
        "outer product",
    );
    b
}

/// `collide track` for people.
pub fn track(
    t: &crate::track::Track,
    r: &crate::track::TrackReport,
    limits: crate::track::Limits,
) -> String {
    use crate::track::Stop;
    let run = &r.run;
    let mut out = String::new();
    let walls = match (t.left_wall, t.right_wall) {
        (Some(l), Some(rw)) => format!("walls at {} and {}", num(l), num(rw)),
        (Some(l), None) => format!("a left wall at {}", num(l)),
        (None, Some(rw)) => format!("a right wall at {}", num(rw)),
        (None, None) => "no walls".into(),
    };
    let gravity = if t.gravity > 0.0 {
        format!(", gravity {} toward the left wall", num(t.gravity))
    } else {
        String::new()
    };
    let _ = writeln!(
        out,
        "{} bodies, {walls}{gravity}; e = {} between bodies, {} at walls",
        t.bodies.len(),
        num(t.e),
        num(t.e_wall)
    );
    let why = match &run.stop {
        Stop::Done => "no collision can happen any more".to_string(),
        Stop::Until => "reached --until".to_string(),
        Stop::MaxCollisions => format!(
            "stopped at the --max-collisions cap of {}; raise it to go on",
            limits.max_collisions
        ),
        Stop::Zeno {
            at,
            accumulation,
            who,
            x,
        } => format!(
            "infinitely many collisions in finite time (inelastic collapse): collisions {who} near x = {} \
             accumulate at t = {}; stopped at t = {}",
            num(*x),
            num(*accumulation),
            num(*at)
        ),
    };
    let _ = writeln!(out, "Stopped: {why}");
    let mut b = Block::new(format!(
        "After {} collisions at t = {}",
        run.collisions,
        num(run.time)
    ));
    b.row(
        "collisions",
        run.collisions.to_string(),
        format!(
            "{} between bodies, {} with walls",
            run.pair_collisions, run.wall_collisions
        ),
    );
    if run.simultaneous > 0 {
        b.row(
            "simultaneous",
            run.simultaneous.to_string(),
            "instants with more than one collision, resolved left to right",
        );
    }
    if let Some(pi) = &r.pi {
        let verdict = if pi.agrees { "agrees" } else { "DISAGREES" };
        b.row(
            "pi billiards",
            pi.theory.to_string(),
            format!(
                "ceil(pi/theta) - 1 with theta = atan(sqrt(m1/m2)) = {}: {verdict}",
                num(pi.theta)
            ),
        );
    }
    b.render(&mut out);
    let mut bodies = Block::new("Bodies");
    bodies.cells(["body".to_string(), "m".into(), "x".into(), "v".into()]);
    for (i, body) in t.bodies.iter().enumerate() {
        bodies.cells([
            (i + 1).to_string(),
            num(body.m),
            num(run.x[i]),
            num(run.v[i]),
        ]);
    }
    bodies.render(&mut out);
    let mut book = Block::new("Bookkeeping");
    let walled = t.left_wall.is_some() || t.right_wall.is_some();
    let walls_note = match (walled, t.gravity > 0.0) {
        (true, true) => "walls and gravity change it",
        (true, false) => "the walls change it",
        (false, true) => "gravity changes it",
        (false, false) => "conserved",
    };
    book.cells([
        "momentum".to_string(),
        num(run.momentum.start),
        num(run.momentum.end),
        walls_note.into(),
    ]);
    let rel = (run.energy.end - run.energy.start) / run.energy.start.abs().max(f64::MIN_POSITIVE);
    let energy_note = if t.e == 1.0 && t.e_wall == 1.0 {
        format!("elastic: relative change {rel:.1e}")
    } else {
        format!("relative change {rel:.1e} (lost to heat)")
    };
    book.cells([
        "energy".to_string(),
        num(run.energy.start),
        num(run.energy.end),
        energy_note,
    ]);
    book.render(&mut out);
    out
}
