//! Rows written as CSV (the csv crate), JSON Lines or aligned text, numbers shortest round-trip
//! (ryu) with no allocation per field.

use super::columns::Column;

/// How rows are written (`--format`, `format` in a scene's `[sweep]`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum, serde::Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum RowFormat {
    /// Comma-separated values with a header line
    Csv,
    /// One JSON object a line
    Jsonl,
    /// Aligned columns for people
    Text,
}

/// Which pieces of a table carry its header line (`--header`): a sharded table's shards, read
/// on their own (each file a table: Dask, Polars and the csv crate take a file's first line as
/// its header), or concatenated (`cat`: only the first may have it).
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum Header {
    /// Every shard (each file reads on its own)
    Always,
    /// Only shard 1 (the shards concatenated are the whole table, byte for byte)
    First,
    /// None (rows only)
    Never,
}

impl Header {
    /// Whether the piece `k` (1 for the first or only one) has the header.
    pub fn in_piece(self, k: u64) -> bool {
        match self {
            Header::Always => true,
            Header::First => k == 1,
            Header::Never => false,
        }
    }
}

impl RowFormat {
    /// The name as typed (`--format jsonl`).
    pub fn name(self) -> &'static str {
        match self {
            RowFormat::Csv => "csv",
            RowFormat::Jsonl => "jsonl",
            RowFormat::Text => "text",
        }
    }
}

/// Writes rows of numbers in one format.
pub struct RowWriter {
    columns: Vec<&'static Column>,
    format: RowFormat,
    header: Header,
}

impl RowWriter {
    /// A writer whose header goes in the first piece of a table only ([`Header::First`]).
    pub fn new(columns: Vec<&'static Column>, format: RowFormat) -> RowWriter {
        RowWriter {
            columns,
            format,
            header: Header::First,
        }
    }

    /// The same writer with the header in the pieces `header` names.
    pub fn with_header(self, header: Header) -> RowWriter {
        RowWriter { header, ..self }
    }

    /// Whether piece `k` of a table (shard `k`; 1 for a whole table) starts with the header.
    pub fn heads(&self, k: u64) -> bool {
        self.header.in_piece(k)
    }

    pub fn columns(&self) -> &[&'static Column] {
        &self.columns
    }

    /// The header line (CSV and text; nothing for JSON Lines).
    pub fn header(&self, out: &mut Vec<u8>) {
        match self.format {
            RowFormat::Csv => {
                let mut w = csv::Writer::from_writer(out);
                let _ = w.write_record(self.columns.iter().map(|c| c.name));
                let _ = w.flush();
            }
            // Text: each page of rows carries the names, aligned with its values.
            RowFormat::Text | RowFormat::Jsonl => {}
        }
    }

    /// A buffer for a chunk of `rows` rows in this format, sized for a typical row so it
    /// rarely grows (each growth copies the chunk).
    pub fn buffer(&self, rows: usize) -> RowBuf {
        let per_row = match self.format {
            RowFormat::Csv => 20 * self.columns.len(),
            RowFormat::Jsonl => 32 * self.columns.len(),
            RowFormat::Text => {
                return RowBuf::Text(TextPage {
                    names: self.columns.iter().map(|c| c.name).collect(),
                    named: self.header != Header::Never,
                    fields: Vec::with_capacity(rows.min(1 << 16) * 12 * self.columns.len()),
                    ends: Vec::with_capacity(rows.min(1 << 16) * self.columns.len()),
                });
            }
        };
        RowBuf::Raw(Vec::with_capacity(rows.min(1 << 16) * per_row))
    }

    /// Writes one row of values (all finite).
    pub fn row(&self, values: &[f64], buf: &mut RowBuf, fields: &mut FieldCache) {
        match buf {
            // Fields are ASCII numbers: a CSV writer would never quote them (the header, which
            // names columns, is written by the csv crate), so they are pushed as they are.
            RowBuf::Raw(out) if self.format == RowFormat::Csv => {
                for (i, v) in values.iter().enumerate() {
                    // The comma and the field's whole 32-byte slot are copied (a fixed-size
                    // copy, a few vector moves rather than a call to memmove), then cut back.
                    let (slot, len) = fields.slot(i, *v);
                    let at = out.len() + usize::from(i > 0);
                    if i > 0 {
                        out.push(b',');
                    }
                    out.extend_from_slice(slot);
                    out.truncate(at + len);
                }
                out.push(b'\n');
            }
            // JSON Lines (a text table has its page).
            RowBuf::Raw(out) => {
                out.push(b'{');
                for (i, (c, v)) in self.columns.iter().zip(values).enumerate() {
                    if i > 0 {
                        out.push(b',');
                    }
                    out.push(b'"');
                    out.extend_from_slice(c.name.as_bytes());
                    out.extend_from_slice(b"\":");
                    out.extend_from_slice(fields.format(i, *v));
                }
                out.extend_from_slice(b"}\n");
            }
            RowBuf::Text(page) => {
                for (i, v) in values.iter().enumerate() {
                    page.fields.extend_from_slice(fields.format(i, *v));
                    page.ends.push(page.fields.len());
                }
            }
        }
    }
}

/// A page of a text table (the rows of one chunk): the fields as they come, aligned when the
/// page is done, each column as wide as its widest value (or name), right-aligned; a page wider
/// than the terminal ([`crate::terminal::width`]) is folded into groups of columns, each
/// repeating the first. Every page starts with the names (unless `--header never`): a text
/// table is for people, who read pages, not shards.
pub struct TextPage {
    names: Vec<&'static str>,
    named: bool,
    fields: Vec<u8>,
    /// Where each field ends in `fields`, row after row.
    ends: Vec<usize>,
}

impl TextPage {
    fn into_bytes(self) -> Vec<u8> {
        let columns = self.names.len().max(1);
        let field = |k: usize| {
            let start = if k == 0 { 0 } else { self.ends[k - 1] };
            &self.fields[start..self.ends[k]]
        };
        let rows = self.ends.len() / columns;
        if rows == 0 {
            return Vec::new();
        }
        let mut widths: Vec<usize> = self
            .names
            .iter()
            .map(|n| if self.named { n.len() } else { 0 })
            .collect();
        for k in 0..self.ends.len() {
            widths[k % columns] = widths[k % columns].max(field(k).len());
        }
        let groups = crate::terminal::fold(&widths, 1, 2, crate::terminal::width());
        let mut out = Vec::with_capacity(self.fields.len() + self.ends.len() * 4);
        let cell = |out: &mut Vec<u8>, c: usize, text: &[u8], first: bool| {
            let pad = widths[c] - text.len() + if first { 0 } else { 2 };
            out.extend(std::iter::repeat_n(b' ', pad));
            out.extend_from_slice(text);
        };
        for (g, group) in groups.iter().enumerate() {
            if g > 0 {
                out.push(b'\n');
            }
            if self.named {
                for (j, &c) in group.iter().enumerate() {
                    cell(&mut out, c, self.names[c].as_bytes(), j == 0);
                }
                out.push(b'\n');
            }
            for r in 0..rows {
                for (j, &c) in group.iter().enumerate() {
                    cell(&mut out, c, field(r * columns + c), j == 0);
                }
                out.push(b'\n');
            }
        }
        out
    }
}

/// Shortest round-trip text of each column's last value: in a sweep most fields repeat from one
/// row to the next (inputs that do not vary, and whatever does not depend on the fastest
/// parameter), and formatting numbers is most of a table's cost.
pub struct FieldCache {
    last: Vec<(u64, [u8; 32], u8)>,
}

impl FieldCache {
    pub fn new(columns: usize) -> FieldCache {
        // A NaN bit pattern: never equal to a finite value's.
        FieldCache {
            last: vec![(u64::MAX, [0; 32], 0); columns],
        }
    }

    /// The text of `v` (finite) in column `i`: a 32-byte slot and the text's length in it.
    pub fn slot(&mut self, i: usize, v: f64) -> (&[u8; 32], usize) {
        self.format(i, v);
        let (_, text, len) = &self.last[i];
        (text, *len as usize)
    }

    /// The text of `v` (finite) in column `i`.
    pub fn format(&mut self, i: usize, v: f64) -> &[u8] {
        let (bits, text, len) = &mut self.last[i];
        debug_assert!(v.is_finite(), "tables hold finite values only");
        if *bits != v.to_bits() {
            // SAFETY: ryu writes at most 24 bytes (its documented bound), and the slot has 32.
            // Written in place: through ryu's own buffer, each field was also copied once more.
            *len = unsafe { ryu::raw::format64(v, text.as_mut_ptr()) } as u8;
            *bits = v.to_bits();
        }
        &text[..*len as usize]
    }
}

/// A chunk's bytes as they are written (CSV, JSON Lines), or its text page.
pub enum RowBuf {
    Raw(Vec<u8>),
    Text(TextPage),
}

impl RowBuf {
    pub fn into_bytes(self) -> Vec<u8> {
        match self {
            RowBuf::Raw(v) => v,
            RowBuf::Text(page) => page.into_bytes(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::table::columns::by_names;

    #[test]
    fn formats() {
        let cols = || by_names(&["e", "ke_in"]).unwrap();
        let w = RowWriter::new(cols(), RowFormat::Csv);
        let mut header = Vec::new();
        w.header(&mut header);
        assert_eq!(header, b"e,ke_in\n");
        let mut buf = w.buffer(2);
        let mut f = FieldCache::new(2);
        w.row(&[0.3, 1e300], &mut buf, &mut f);
        w.row(&[0.3, -2.5], &mut buf, &mut f);
        assert_eq!(buf.into_bytes(), b"0.3,1e300\n0.3,-2.5\n");
        let w = RowWriter::new(cols(), RowFormat::Jsonl);
        let mut buf = w.buffer(2);
        w.row(&[0.3, 7250.0], &mut buf, &mut FieldCache::new(2));
        assert_eq!(buf.into_bytes(), b"{\"e\":0.3,\"ke_in\":7250.0}\n");
        // Text: columns as wide as their widest value or name, right-aligned, names first.
        let w = RowWriter::new(by_names(&["e", "ke_in"]).unwrap(), RowFormat::Text);
        let mut buf = w.buffer(2);
        let mut f = FieldCache::new(2);
        w.row(&[0.5, 7250.0], &mut buf, &mut f);
        w.row(&[0.25, 1e300], &mut buf, &mut f);
        assert_eq!(
            String::from_utf8(buf.into_bytes()).unwrap(),
            "   e   ke_in\n 0.5  7250.0\n0.25   1e300\n"
        );
        let w = w.with_header(Header::Never);
        let mut buf = w.buffer(1);
        w.row(&[0.5, 1.0], &mut buf, &mut FieldCache::new(2));
        assert_eq!(buf.into_bytes(), b"0.5  1.0\n");
    }
}
