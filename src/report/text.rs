//! Text for people: one aligned block per section, in the lecture's notation, leaving out what
//! means nothing for the case (no energy lost when elastic, no separate FIN when the bodies stick,
//! no off-diagonal entries for a diagonal tensor).

use super::{
    ChangeReport, Diagnostics, Ellipses, Energy, Forms, Momentum, Notes, Products, Report, Reverse,
    Sections, Vectors,
};
use crate::case::Case;
use crate::ellipse::Ellipse;
use crate::quantity::Scalar;

/// `(V1, V2)`.
pub fn pair<N: Scalar>(v: &[N; 2]) -> String {
    format!("({}, {})", v[0].show(), v[1].show())
}

/// Rows of cells aligned into columns (two spaces apart, trailing blanks trimmed), under an
/// optional heading: every aligned table collide prints for people. A block keeps within the
/// width of the terminal ([`crate::terminal::width`], or the one given to [`Block::fit`]) without
/// cutting a number: a row's note that does not fit goes on a line of its own below the row
/// (wrapped if need be), a label too long to leave room for its value goes on a line above it,
/// and a table too wide for the width is folded into groups of columns, each repeating the
/// first.
pub struct Block {
    heading: Option<String>,
    indent: &'static str,
    items: Vec<Item>,
    right: Vec<usize>,
    width: Option<usize>,
}

/// A row of cells; when `noted`, its last cell is a note that may go on a line of its own.
struct Row {
    cells: Vec<String>,
    noted: bool,
}

enum Item {
    Row(Row),
    /// A blank line between groups of rows.
    Gap,
    /// A line of text of its own among the rows, not indented, wrapped (a group's title).
    Line(String),
}

/// How a block's rows are laid out in the width: the columns' widths and their gap, which rows
/// have their note below (`moved`) or their label above (`stacked`), and the groups of columns
/// of a folded table.
#[derive(Clone)]
struct Layout {
    widths: Vec<usize>,
    gap: usize,
    moved: Vec<bool>,
    stacked: Vec<bool>,
    groups: Vec<Vec<usize>>,
}

impl Layout {
    /// Whether cell `c` of row `i` is on a line of its own: a label stacked above its value, or
    /// a note moved below its row.
    fn elsewhere(&self, row: &Row, i: usize, c: usize) -> bool {
        (c == 0 && self.stacked[i]) || (c + 1 == row.cells.len() && row.noted && self.moved[i])
    }
}

impl Block {
    /// `heading`, then rows indented by two spaces (a report section).
    pub fn new(heading: impl Into<String>) -> Block {
        Block {
            heading: Some(heading.into()),
            indent: "  ",
            items: Vec::new(),
            right: Vec::new(),
            width: None,
        }
    }

    /// Rows only, not indented, with the columns in `right` aligned right (a table of numbers).
    pub fn table(right: &[usize]) -> Block {
        Block {
            heading: None,
            indent: "",
            items: Vec::new(),
            right: right.to_vec(),
            width: None,
        }
    }

    /// The columns in `right` aligned right.
    pub fn align_right(mut self, right: &[usize]) -> Block {
        self.right = right.to_vec();
        self
    }

    /// Keeps lines within `width` columns rather than the terminal's.
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
        self.cells_noted(vec![label.into(), value.into(), note.into()]);
    }

    pub fn cells<const N: usize>(&mut self, cells: [String; N]) {
        self.cell_vec(cells.into());
    }

    pub fn cell_vec(&mut self, cells: Vec<String>) {
        self.items.push(Item::Row(Row {
            cells,
            noted: false,
        }));
    }

    /// Cells whose last is a note (it goes below the row when the row is too wide).
    pub fn cells_noted(&mut self, cells: Vec<String>) {
        let noted = cells.len() >= 2;
        self.items.push(Item::Row(Row { cells, noted }));
    }

    /// A blank line between groups of rows.
    pub fn gap(&mut self) {
        self.items.push(Item::Gap);
    }

    /// A line of text among the rows (not indented, wrapped): a group's title.
    pub fn line(&mut self, text: impl Into<String>) {
        self.items.push(Item::Line(text.into()));
    }

    pub fn render(&self, out: &mut String) {
        let limit = self.width.unwrap_or_else(crate::terminal::width);
        if let Some(h) = &self.heading {
            out.push('\n');
            out.push_str(&wrap(h, limit, ""));
        }
        self.render_items(&self.layout(limit), limit, out);
    }

    /// The rows, gaps and lines, laid out by `lay`: a group of columns after another.
    fn render_items(&self, lay: &Layout, limit: usize, out: &mut String) {
        // Moved notes all under the values when they all fit there, else all indented under
        // their labels (wrapped).
        let under = self.indent.len() + lay.widths.first().map_or(0, |w| w + lay.gap);
        let aligned = self
            .rows()
            .filter(|(i, r)| r.noted && lay.moved[*i])
            .all(|(_, r)| under + r.cells.last().map_or(0, |n| n.chars().count()) <= limit);
        let groups = lay.groups.len();
        for (g, group) in lay.groups.iter().enumerate() {
            if g > 0 {
                out.push('\n');
            }
            for (i, item) in self.items.iter().enumerate() {
                match item {
                    Item::Gap => out.push('\n'),
                    Item::Line(text) => out.push_str(&wrap(text, limit, "  ")),
                    Item::Row(row) => {
                        let notes = (g + 1 == groups).then_some(aligned.then_some(under));
                        self.render_row(row, i, lay, group, notes, limit, out)
                    }
                }
            }
        }
    }

    /// A row's lines: its label above when stacked, its cells, its note below when moved
    /// (`notes`: in the last group of columns only, at the column given or indented under the
    /// label and wrapped).
    #[allow(clippy::too_many_arguments)]
    fn render_row(
        &self,
        row: &Row,
        i: usize,
        lay: &Layout,
        group: &[usize],
        notes: Option<Option<usize>>,
        limit: usize,
        out: &mut String,
    ) {
        if lay.stacked[i] {
            let indent = format!("{}  ", self.indent);
            out.push_str(&wrap(
                &format!("{}{}", self.indent, row.cells[0]),
                limit,
                &indent,
            ));
        }
        let line = self.line_of(row, i, lay, group);
        if !line.trim().is_empty() {
            out.push_str(&line);
            out.push('\n');
        }
        let note = row
            .cells
            .last()
            .filter(|n| row.noted && lay.moved[i] && !n.is_empty());
        match (note, notes) {
            (Some(note), Some(Some(under))) => {
                out.push_str(&format!("{}{note}\n", " ".repeat(under)));
            }
            (Some(note), Some(None)) => {
                let indent = format!("{}    ", self.indent);
                out.push_str(&wrap(&format!("{indent}{note}"), limit, &indent));
            }
            _ => {}
        }
    }

    /// The line of row `i`'s cells in `group`, padded to the columns' widths: without its label
    /// when stacked, without its note when moved.
    fn line_of(&self, row: &Row, i: usize, lay: &Layout, group: &[usize]) -> String {
        let cells: Vec<String> = group
            .iter()
            .filter(|&&c| c < row.cells.len())
            .map(|&c| {
                let cell = if lay.elsewhere(row, i, c) {
                    ""
                } else {
                    row.cells[c].as_str()
                };
                let pad = lay.widths[c].saturating_sub(cell.chars().count());
                if self.right.contains(&c) {
                    format!("{}{cell}", " ".repeat(pad))
                } else {
                    format!("{cell}{}", " ".repeat(pad))
                }
            })
            .collect();
        let line = format!("{}{}", self.indent, cells.join(&" ".repeat(lay.gap)));
        line.trim_end().to_string()
    }

    fn rows(&self) -> impl Iterator<Item = (usize, &Row)> {
        self.items
            .iter()
            .enumerate()
            .filter_map(|(i, item)| match item {
                Item::Row(r) => Some((i, r)),
                _ => None,
            })
    }

    /// Each column's width: its widest cell, leaving out stacked labels and moved notes.
    fn widths(&self, lay: &Layout) -> Vec<usize> {
        let columns = self.rows().map(|(_, r)| r.cells.len()).max().unwrap_or(0);
        (0..columns)
            .map(|c| {
                self.rows()
                    .filter(|(i, r)| c < r.cells.len() && !lay.elsewhere(r, *i, c))
                    .map(|(_, r)| r.cells[c].chars().count())
                    .max()
                    .unwrap_or(0)
            })
            .collect()
    }

    /// Whether every row's line fits in `limit` (notes below and labels above are wrapped).
    fn overflowing(&self, lay: &Layout, limit: usize) -> Vec<usize> {
        let all: Vec<usize> = (0..lay.widths.len()).collect();
        self.rows()
            .filter(|(i, r)| self.line_of(r, *i, lay, &all).chars().count() > limit)
            .map(|(i, _)| i)
            .collect()
    }

    /// The layout in `limit` columns: as is when it fits. Else, for a section (a label and a
    /// value a row, and a note), the fewest lines among: the longest labels (none, one, two...)
    /// above their values, and the notes that still do not fit below their rows. A table still
    /// too wide with its notes below is folded.
    fn layout(&self, limit: usize) -> Layout {
        let n = self.items.len();
        let mut lay = Layout {
            widths: Vec::new(),
            gap: 2,
            moved: vec![false; n],
            stacked: vec![false; n],
            groups: Vec::new(),
        };
        lay.widths = self.widths(&lay);
        lay.groups = vec![(0..lay.widths.len()).collect()];
        if limit == crate::terminal::UNLIMITED || self.overflowing(&lay, limit).is_empty() {
            return lay;
        }
        let section = self
            .rows()
            .all(|(_, r)| r.cells.len() - usize::from(r.noted) <= 2);
        if section {
            let mut longest: Vec<(usize, usize)> = self
                .rows()
                .filter(|(_, r)| !r.cells[0].is_empty())
                .map(|(i, r)| (r.cells[0].chars().count(), i))
                .collect();
            longest.sort_by(|a, b| b.cmp(a));
            let mut best: Option<((usize, usize, usize), Layout)> = None;
            for k in 0..=longest.len() {
                let mut candidate = lay.clone();
                for &(_, i) in &longest[..k] {
                    candidate.stacked[i] = true;
                }
                self.place_notes(&mut candidate, limit);
                let mut text = String::new();
                self.render_items(&candidate, limit, &mut text);
                let over = text.lines().filter(|l| l.chars().count() > limit).count();
                let score = (over, text.lines().count(), k);
                if best.as_ref().is_none_or(|(b, _)| score < *b) {
                    best = Some((score, candidate));
                }
            }
            return best.map_or(lay, |(_, l)| l);
        }
        self.place_notes(&mut lay, limit);
        if self.overflowing(&lay, limit).is_empty() {
            return lay;
        }
        lay.groups = crate::terminal::fold(
            &lay.widths,
            1,
            lay.gap,
            limit.saturating_sub(self.indent.len()),
        );
        lay
    }

    /// Moves below its row each note that does not fit beside it (until all that are left do).
    fn place_notes(&self, lay: &mut Layout, limit: usize) {
        loop {
            lay.widths = self.widths(lay);
            let over: Vec<usize> = self
                .overflowing(lay, limit)
                .into_iter()
                .filter(|&i| matches!(&self.items[i], Item::Row(r) if r.noted) && !lay.moved[i])
                .collect();
            if over.is_empty() {
                return;
            }
            for i in over {
                lay.moved[i] = true;
            }
        }
    }
}

pub use crate::terminal::wrap;

/// A duration for people, to 3 significant digits in the unit that suits it: `1.27 s`,
/// `905 ms`, `64.2 us`, `850 ns`.
pub fn duration(seconds: f64) -> String {
    let (value, unit) = match seconds.abs() {
        s if s >= 1.0 => (seconds, "s"),
        s if s >= 1e-3 => (seconds * 1e3, "ms"),
        s if s >= 1e-6 => (seconds * 1e6, "us"),
        _ => (seconds * 1e9, "ns"),
    };
    let digits = match value.abs() {
        v if v >= 99.95 => 0,
        v if v >= 9.995 => 1,
        _ => 2,
    };
    format!("{value:.digits$} {unit}")
}

/// A value for the header (`Number::brief`).
pub fn typed(n: &crate::number::Number) -> String {
    n.brief()
}

/// `M = diag(4, 1)   V_IN = (60, 10)   e = 1 (elastic: ka-bong)`, a line.
pub fn header(case: &Case) -> String {
    header_in(case, false)
}

/// The header; `exact`: a solved value (e, a velocity) is shown as the fraction it is (`Solved: e = 3/7` and `e =
/// 3/7` in the header), not as `≈` digits.
pub fn header_in(case: &Case, exact: bool) -> String {
    let e = case.restitution();
    let shown = |n: &crate::number::Number| match n.text() {
        t if exact && t.len() <= 40 => t.into_owned(),
        _ => typed(n),
    };
    let e_text = shown(e.number());
    let mut out = parts(&[
        format!("M = {}", case.inertia().describe()),
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

/// `parts` three spaces apart, as many on a line as fit the terminal (a part too long for a
/// line of its own is wrapped).
pub fn parts(parts: &[String]) -> String {
    let width = crate::terminal::width();
    let mut out = String::new();
    let mut line = String::new();
    for p in parts {
        if !line.is_empty() && line.chars().count() + 3 + p.chars().count() > width {
            out.push_str(&wrap(&line, width, "  "));
            line.clear();
        }
        if !line.is_empty() {
            line.push_str("   ");
        }
        line.push_str(p);
    }
    out.push_str(&wrap(&line, width, "  "));
    out
}

/// `text` wrapped to the terminal's width, lines after the first indented by two spaces.
pub fn paragraph(text: &str) -> String {
    wrap(text, crate::terminal::width(), "  ")
}

/// `Units: masses in kg, velocities in m/s, energies in J`, when units were given.
pub fn header_units(u: &crate::units::Units) -> String {
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
    Some(if case.restitution().is_totally_inelastic() {
        format!("FIN: v1' = v2' = {f1} {unit} (the bodies stick)\n")
    } else {
        format!("FIN: v1' = {f1} {unit}, v2' = {f2} {unit}\n")
    })
}

/// Renders the report of `case` as text. A pair that moves apart (`V1 < V2`) shows its vectors
/// and the note that the bodies never meet, unless sections were asked for (`show.asked`).
pub fn render<N: Scalar>(case: &Case, report: &Report<N>, show: &Sections) -> String {
    let mut out = String::new();
    out.push_str(&header_in(case, N::EXACT));
    let apart = case.collision.v_in.x < case.collision.v_in.y;
    if apart && !show.asked {
        if let Some(v) = &report.vectors {
            vectors(case, v, false, report.frame.is_none()).render(&mut out);
        }
        return out;
    }
    if let Some(f) = &report.frame {
        out.push_str(&paragraph(&format!(
            "Frame: {} (observer velocity w = {}; every velocity shifted by -w)",
            f.name,
            f.w.show()
        )));
    }
    if let Some(v) = &report.vectors {
        vectors(case, v, true, report.frame.is_none()).render(&mut out);
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

/// The vectors section; `fin`: with the FIN row (also for a pair that moves apart); `lab`: seen
/// from the lab.
fn vectors<N: Scalar>(case: &Case, v: &Vectors<N>, fin: bool, lab: bool) -> Block {
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
    if fin && case.restitution().is_totally_inelastic() {
        b.row("FIN  V_FIN", "= COM", "the bodies stick and move together");
    } else if fin {
        b.row(
            "FIN  V_FIN",
            snapped(&v.fin, own.fin),
            "= (1 + e) V_COM u - e V_IN",
        );
    }
    if case.collision.v_in.x < case.collision.v_in.y {
        b.row(
            "",
            "",
            if fin {
                "V1 < V2: the bodies move apart and do not meet; FIN is the collision they would \
                 have if body 1 were on the right"
            } else {
                "V1 < V2: the bodies move apart and do not meet, so there is no FIN (unless body 1 \
                 is on the right: check the order of the velocities; --show vectors gives the FIN \
                 it would then have)"
            },
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
mod tests {
    use super::duration;

    #[test]
    fn durations_read_in_their_unit() {
        assert_eq!(duration(1.2717191), "1.27 s");
        assert_eq!(duration(0.905), "905 ms");
        assert_eq!(duration(64.2e-6), "64.2 us");
        assert_eq!(duration(850e-9), "850 ns");
        assert_eq!(duration(9.9996e-3), "10.0 ms");
        assert_eq!(duration(0.0), "0.00 ns");
    }
}
