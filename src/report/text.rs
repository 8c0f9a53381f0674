//! Text for people: one aligned block per section, in the lecture's notation, leaving out what
//! means nothing for the case (no energy lost when elastic, no separate FIN when the bodies stick,
//! no off-diagonal entries for a diagonal tensor).

use std::fmt::Write;

use super::{
    ChangeReport, Diagnostics, Ellipses, Energy, Forms, Momentum, Notes, Products, Report, Reverse,
    Vectors,
};
use crate::case::Case;
use crate::ellipse::Ellipse;
use crate::quantity::Scalar;

/// `(V1, V2)`.
pub fn pair<N: Scalar>(v: &[N; 2]) -> String {
    format!("({}, {})", v[0].show(), v[1].show())
}

/// Rows of cells aligned into columns (two spaces apart, trailing blanks trimmed), under an
/// optional heading: every aligned table collide prints for people.
pub struct Block {
    heading: Option<String>,
    indent: &'static str,
    rows: Vec<Option<Vec<String>>>,
    right: Vec<usize>,
    /// Lines wider than this put their last cell (a note) on a line of its own, under the
    /// value (`fit`).
    width: Option<usize>,
}

impl Block {
    /// `heading`, then rows indented by two spaces (a report section).
    pub fn new(heading: impl Into<String>) -> Block {
        Block {
            heading: Some(heading.into()),
            indent: "  ",
            rows: Vec::new(),
            right: Vec::new(),
            width: None,
        }
    }

    /// Rows only, not indented, with the columns in `right` aligned right (a table of numbers).
    pub fn table(right: &[usize]) -> Block {
        Block {
            heading: None,
            indent: "",
            rows: Vec::new(),
            right: right.to_vec(),
            width: None,
        }
    }

    /// Keeps lines within `width` columns: where a row would be wider, its last cell goes on a
    /// line of its own under the second column, and the other rows' last cells align without
    /// it.
    pub fn fit(mut self, width: usize) -> Block {
        self.width = Some(width);
        self
    }

    /// `label  value  note`.
    pub fn row(
        &mut self,
        label: impl Into<String>,
        value: impl Into<String>,
        note: impl Into<String>,
    ) {
        self.rows
            .push(Some(vec![label.into(), value.into(), note.into()]));
    }

    pub fn cells<const N: usize>(&mut self, cells: [String; N]) {
        self.rows.push(Some(cells.into()));
    }

    pub fn cell_vec(&mut self, cells: Vec<String>) {
        self.rows.push(Some(cells));
    }

    /// A blank line between groups of rows.
    pub fn gap(&mut self) {
        self.rows.push(None);
    }

    pub fn render(&self, out: &mut String) {
        let rows = || self.rows.iter().flatten();
        let columns = rows().map(Vec::len).max().unwrap_or(0);
        let stacked = self.stacked();
        let widths: Vec<usize> = (0..columns)
            .map(|i| {
                rows()
                    .filter(|r| !(stacked && r.len() >= 3 && i + 1 == r.len()))
                    .filter_map(|r| r.get(i))
                    .map(|c| c.chars().count())
                    .max()
                    .unwrap_or(0)
            })
            .collect();
        if let Some(h) = &self.heading {
            let _ = writeln!(out, "\n{h}");
        }
        for row in &self.rows {
            let Some(row) = row else {
                out.push('\n');
                continue;
            };
            let (row, moved) = if stacked && row.len() >= 3 {
                (&row[..row.len() - 1], row.last())
            } else {
                (&row[..], None)
            };
            let cells: Vec<String> = row
                .iter()
                .zip(&widths)
                .enumerate()
                .map(|(i, (cell, w))| {
                    let pad = w.saturating_sub(cell.chars().count());
                    if self.right.contains(&i) {
                        format!("{}{cell}", " ".repeat(pad))
                    } else {
                        format!("{cell}{}", " ".repeat(pad))
                    }
                })
                .collect();
            let line = format!("{}{}", self.indent, cells.join("  "));
            let _ = writeln!(out, "{}", line.trim_end());
            if let Some(note) = moved.filter(|n| !n.is_empty()) {
                let under = self.indent.len() + widths.first().map_or(0, |w| w + 2);
                let _ = writeln!(out, "{}{note}", " ".repeat(under));
            }
        }
    }

    /// Whether the block is wider than the width asked for (`fit`): then every row's last cell
    /// (a note) goes on a line of its own.
    fn stacked(&self) -> bool {
        let Some(limit) = self.width else {
            return false;
        };
        let rows = || self.rows.iter().flatten();
        let columns = rows().map(Vec::len).max().unwrap_or(0);
        let widths: Vec<usize> = (0..columns)
            .map(|i| {
                rows()
                    .filter_map(|r| r.get(i))
                    .map(|c| c.chars().count())
                    .max()
                    .unwrap_or(0)
            })
            .collect();
        rows().any(|r| {
            let cells: usize = r
                .iter()
                .zip(&widths)
                .map(|(c, w)| if c.is_empty() { 0 } else { *w + 2 })
                .sum();
            self.indent.len() + cells > limit + 2
        })
    }
}

/// `text` wrapped at spaces to lines of at most `width` characters (a word longer than that
/// keeps its own line: numbers are never cut), each line after the first indented by `indent`.
pub fn wrap(text: &str, width: usize, indent: &str) -> String {
    let mut out = String::new();
    let mut line = String::new();
    for word in text.split(' ').filter(|w| !w.is_empty()) {
        let len = line.chars().count();
        if len > 0 && len + 1 + word.chars().count() > width {
            out.push_str(line.trim_end());
            out.push('\n');
            line = indent.to_string();
        } else if len > 0 && !line.ends_with(' ') {
            line.push(' ');
        }
        line.push_str(word);
    }
    out.push_str(line.trim_end());
    out.push('\n');
    out
}

/// A value for the header (`Number::brief`).
pub fn typed(n: &crate::number::Number) -> String {
    n.brief()
}

/// `M = diag(4, 1)   V_IN = (60, 10)   e = 1 (elastic: ka-bong)`, a line.
pub fn header(case: &Case) -> String {
    let e = case.restitution();
    let mut out = format!(
        "M = {}   V_IN = ({}, {})   e = {} ({})\n",
        case.inertia().describe(),
        typed(&case.velocities[0]),
        typed(&case.velocities[1]),
        typed(e.number()),
        e.kind()
    );
    out.push_str(&header_units(&case.units));
    out
}

/// `Units: masses in kg, velocities in m/s, energies in J`, when units were given.
pub fn header_units(u: &crate::units::Units) -> String {
    if u.mass.is_none() && u.velocity.is_none() {
        return String::new();
    }
    let given = |unit: Option<&str>| unit.map_or("as given".to_string(), |n| format!("in {n}"));
    format!(
        "Units: masses {}, velocities {}, energies in {}\n",
        given(u.mass),
        given(u.velocity),
        u.energy()
    )
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
        let mut b = Block::new(format!(
            "Heights (v^2 / 2g with g = {} m/s^2, in m)",
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
fn snapped<N: Scalar>(v: &[N; 2], scale: f64) -> String {
    pair(&[v[0].snap(scale), v[1].snap(scale)])
}

fn vectors<N: Scalar>(case: &Case, v: &Vectors<N>) -> Block {
    let mut b = Block::new("Vectors (V1, V2)");
    let scale = v
        .v_in
        .iter()
        .chain(&v.fin)
        .map(N::magnitude)
        .fold(0.0, f64::max);
    b.row("IN   V_IN", pair(&v.v_in), "");
    b.row(
        "COM  V_COM u",
        snapped(&v.com, scale),
        format!("V_COM = P_total / M_total = {}", v.v_com.snap(scale).show()),
    );
    if case.restitution().is_totally_inelastic() {
        b.row("FIN  V_FIN", "= COM", "the bodies stick and move together");
    } else {
        b.row(
            "FIN  V_FIN",
            snapped(&v.fin, scale),
            "= (1 + e) V_COM u - e V_IN",
        );
    }
    if case.collision.v_in.x < case.collision.v_in.y {
        b.row(
            "",
            "",
            "V1 < V2: the bodies move apart and do not meet (unless body 1 is on the right: \
             check the order of the velocities)",
        );
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
pub fn changes<N: Scalar>(c: &ChangeReport<N>, units: &crate::units::Units) -> Block {
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
            format!(
                "{}: KE_FIN of the body at rest / KE_IN of the other",
                percent(t)
            ),
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
        .map(|v| format!("= {} %", crate::number::num(v * 100.0)))
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

#[cfg(test)]
mod wrap_tests {
    #[test]
    fn wraps_at_spaces_and_never_cuts_a_word() {
        let t = super::wrap("aaa bbb ccc ddddddddddd e", 8, "  ");
        assert_eq!(t, "aaa bbb\n  ccc\n  ddddddddddd\n  e\n");
    }
}
