//! Text for people: one aligned block per section, in the lecture's notation, leaving out what
//! means nothing for the case (no energy lost when elastic, no separate FIN when the bodies stick,
//! no off-diagonal entries for a diagonal tensor).

use std::fmt::Write;

use super::{Ellipses, Energy, Forms, Momentum, Products, Report, Vectors};
use crate::case::Case;

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

fn pair(v: [f64; 2]) -> String {
    format!("({}, {})", num(v[0]), num(v[1]))
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

/// Renders the report of `case` as text.
pub fn render(case: &Case, report: &Report) -> String {
    let mut out = String::new();
    let e = case.restitution();
    let _ = writeln!(
        out,
        "M = {}   V_IN = ({}, {})   e = {} ({})",
        case.inertia().describe(),
        case.velocities[0],
        case.velocities[1],
        e,
        e.kind()
    );
    if let Some(v) = &report.vectors {
        vectors(case, v).render(&mut out);
    }
    if let Some(m) = &report.momentum {
        momentum(case, m).render(&mut out);
    }
    if let Some(f) = &report.forms {
        forms(case, f, report.energy.as_ref()).render(&mut out);
    }
    if let Some(en) = &report.energy {
        energy(case, en).render(&mut out);
    }
    if let Some(el) = &report.ellipses {
        ellipses(case, el).render(&mut out);
    }
    if let Some(p) = &report.products {
        products(p).render(&mut out);
    }
    out
}

fn vectors(case: &Case, v: &Vectors) -> Block {
    let mut b = Block::new("Vectors (V1, V2)");
    b.row("IN   V_IN", pair(v.v_in), "");
    b.row(
        "COM  V_COM u",
        pair(v.com),
        format!("V_COM = P_total / M_total = {}", num(v.v_com)),
    );
    if case.restitution().is_totally_inelastic() {
        b.row("FIN  V_FIN", "= COM", "the bodies stick and move together");
    } else {
        b.row("FIN  V_FIN", pair(v.fin), "= (1 + e) V_COM u - e V_IN");
    }
    if v.v_in[0] == v.v_in[1] {
        b.row("", "", "V1 = V2: the bodies never meet, so FIN = IN");
    }
    b
}

fn momentum(case: &Case, p: &Momentum) -> Block {
    let mut b = Block::new("Momentum (P = M.V)");
    b.row("P_IN   M.V_IN", pair(p.p_in), "");
    if !case.restitution().is_totally_inelastic() {
        b.row("P_FIN  M.V_FIN", pair(p.fin), "");
    } else {
        b.row(
            "P_FIN  M.V_FIN",
            pair(p.fin),
            "the bodies' shares of P_total once stuck",
        );
    }
    let m = case.inertia().matrix();
    let (k1, k2) = (m[(0, 0)] + m[(0, 1)], m[(0, 1)] + m[(1, 1)]);
    b.row(
        "P_total  u.M.V",
        num(p.total),
        format!(
            "momentum line {} V1 + {} V2 = {}, slope {}",
            num(k1),
            num(k2),
            num(p.total),
            num(-k1 / k2)
        ),
    );
    b
}

fn forms(case: &Case, f: &Forms, energy: Option<&Energy>) -> Block {
    let mut b = Block::new("Quadratic forms (X.M.Y)");
    let e = case.restitution();
    if e.is_totally_inelastic() {
        b.row(
            "V_COM.M.V_IN = V_COM.M.V_COM = V_FIN.M.V_IN = V_FIN.M.V_FIN = V_COM P_total",
            num(f.com_m_in),
            "",
        );
        b.row("V_IN.M.V_IN", num(f.in_m_in), "");
        return b;
    }
    b.row(
        "V_COM.M.V_IN = V_COM.M.V_FIN = V_COM.M.V_COM = V_COM P_total",
        num(f.com_m_in),
        "",
    );
    b.row(
        "V_FIN.M.V_IN = V_IN.M.V_FIN",
        num(f.fin_m_in),
        "M is symmetric",
    );
    if e.is_elastic() {
        b.row(
            "V_IN.M.V_IN = V_FIN.M.V_FIN",
            num(f.in_m_in),
            "elastic: one energy ellipse",
        );
        // The lecture's check: crunch = V_IN.M.V_IN/4 - V_FIN.M.V_IN/4 when elastic.
        let crunch = energy
            .map(|en| format!(" = {}", num(en.crunch)))
            .unwrap_or_default();
        b.row(
            "V_IN.M.V_IN/4 - V_FIN.M.V_IN/4",
            format!("{} - {}", num(f.in_m_in / 4.0), num(f.fin_m_in / 4.0)),
            format!("= crunch{crunch} (elastic)"),
        );
    } else {
        b.row("V_IN.M.V_IN", num(f.in_m_in), "");
        b.row("V_FIN.M.V_FIN", num(f.fin_m_fin), "");
    }
    b
}

fn energy(case: &Case, en: &Energy) -> Block {
    let mut b = Block::new("Energy (KE = 1/2 V.M.V)");
    let e = case.restitution();
    let c = &case.collision;
    if e.is_elastic() {
        b.row(
            "KE_IN = KE_FIN",
            num(en.ke_in),
            "elastic: energy is conserved",
        );
    } else {
        b.row("KE_IN", num(en.ke_in), "");
    }
    if e.is_totally_inelastic() {
        b.row("KE_FIN = KE_COM = 1/2 V_COM P_total", num(en.com), "");
    } else {
        if !e.is_elastic() {
            b.row("KE_FIN = KE_COM + e^2 crunch", num(en.fin), "");
        }
        b.row("KE_COM = 1/2 V_COM P_total", num(en.com), "");
    }
    let mu = c.inertia.reduced_mass();
    let mu_name = if c.inertia.is_diagonal() {
        "mu = M1 M2 / (M1 + M2)"
    } else {
        "mu = det M / M_total"
    };
    b.row(
        "crunch = KE_IN - KE_COM = 1/2 mu (V1 - V2)^2",
        num(en.crunch),
        format!(
            "{mu_name} = {}, V1 - V2 = {}",
            num(mu),
            num(c.relative_velocity())
        ),
    );
    if e.is_totally_inelastic() {
        b.row(
            "lost = crunch",
            num(en.lost),
            "all of the crunch energy turns into heat",
        );
    } else if !e.is_elastic() {
        b.row("lost = (1 - e^2) crunch", num(en.lost), "");
    }
    b
}

fn ellipses(case: &Case, el: &Ellipses) -> Block {
    let e = case.restitution();
    let heading = match &el.e_in.axes {
        None => "Energy ellipses (1/2 V.M.V = KE; radius a along V1, b along V2)".to_string(),
        Some([qa, qb]) => format!(
            "Energy ellipses (1/2 V.M.V = KE; radius a along {}, b along {}: principal axes of M)",
            pair(*qa),
            pair(*qb)
        ),
    };
    let mut b = Block::new(heading);
    let mut row = |name: &str, x: &crate::ellipse::Ellipse| {
        b.cells([
            name.to_string(),
            format!("a = {}", num(x.a)),
            format!("b = {}", num(x.b)),
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

fn products(p: &Products) -> Block {
    let mut b = Block::new("Products");
    b.row("V_FIN . V_IN", num(p.dot_fin_in), "plain dot product");
    let o = p.outer_in_fin;
    b.row(
        "V_IN (x) V_FIN",
        format!(
            "[[{}, {}], [{}, {}]]",
            num(o[0][0]),
            num(o[0][1]),
            num(o[1][0]),
            num(o[1][1])
        ),
        "outer product",
    );
    b
}
