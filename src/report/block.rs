//! Text blocks for people: a titled block of aligned rows (name, value, note) that fits the
//! terminal's width, folding what does not fit; several short parts on a line; wrapped
//! paragraphs; durations in their unit. Every text report is built from these.

use crate::values::quantity::Scalar;
pub use crate::values::terminal::wrap;

/// `(V1, V2)`.
pub fn pair<N: Scalar>(v: &[N; 2]) -> String {
    format!("({}, {})", v[0].show(), v[1].show())
}

/// Rows of cells aligned into columns (two spaces apart, trailing blanks trimmed), under an
/// optional heading: every aligned table collide prints for people. A block keeps within the
/// width of the terminal ([`crate::values::terminal::width`], or the one given to [`Block::fit`]) without
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
        let limit = self.width.unwrap_or_else(crate::values::terminal::width);
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
        if limit == crate::values::terminal::UNLIMITED || self.overflowing(&lay, limit).is_empty() {
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
        lay.groups = crate::values::terminal::fold(
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

/// `parts` three spaces apart, as many on a line as fit the terminal (a part too long for a
/// line of its own is wrapped).
pub fn parts(parts: &[String]) -> String {
    let width = crate::values::terminal::width();
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
    wrap(text, crate::values::terminal::width(), "  ")
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
