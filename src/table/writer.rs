//! Rows written as CSV (the csv crate), JSON Lines, aligned text or Parquet (`table::parquet`),
//! numbers shortest round-trip (ryu's text, written by zmij) with no allocation per field.
//!
//! A two-body table's cells are all numbers. A table of runs (`table::runs`) may have missing
//! cells (a contact that did not happen: NaN stands for missing there, written as an empty CSV
//! field, `null` in JSON Lines and Parquet, `-` in text) and one text column, the `error` of a
//! run that failed.

use std::io::{self, Write};

use super::columnar::Columns;
use super::columns::Column;
use super::parquet;

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
    /// Apache Parquet, zstd, float64 columns (needs -o FILE; the `parquet` Cargo feature)
    Parquet,
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
            RowFormat::Parquet => "parquet",
        }
    }
}

/// Writes rows of numbers in one format.
pub struct RowWriter {
    /// A two-body table's columns (empty for a table of runs).
    columns: Vec<&'static Column>,
    /// The header's names.
    names: Vec<String>,
    /// Each name as a JSON key with its colon (`"fin1x":`), made once for JSON Lines rows.
    keys: Vec<Vec<u8>>,
    /// Where the text column (`error`) is, in a table of runs.
    text: Option<usize>,
    /// Whether cells may be missing (a table of runs).
    optional: bool,
    /// Which columns count (collisions, steps): integers in every format (issue 45 §3).
    integers: Vec<bool>,
    format: RowFormat,
    header: Header,
    parquet: Option<parquet::Schema>,
}

impl RowWriter {
    /// A writer of a two-body table, whose header goes in the first piece of a table only
    /// ([`Header::First`]). Parquet needs the `parquet` feature (see [`RowWriter::check`]).
    pub fn new(columns: Vec<&'static Column>, format: RowFormat) -> RowWriter {
        let names = columns.iter().map(|c| c.name.to_string()).collect();
        RowWriter::build(columns, names, None, false, format)
    }

    /// A writer of a table of runs: cells may be missing, and `text` is the column of the
    /// `error` text, if chosen.
    pub fn runs(names: Vec<String>, text: Option<usize>, format: RowFormat) -> RowWriter {
        RowWriter::build(Vec::new(), names, text, true, format)
    }

    fn build(
        columns: Vec<&'static Column>,
        names: Vec<String>,
        text: Option<usize>,
        optional: bool,
        format: RowFormat,
    ) -> RowWriter {
        let parquet = (format == RowFormat::Parquet)
            .then(|| parquet::Schema::new(&names, optional, text, &[]))
            .and_then(Result::ok);
        let keys = names
            .iter()
            .map(|n| {
                let mut key = serde_json::to_vec(n).unwrap_or_default();
                key.push(b':');
                key
            })
            .collect();
        RowWriter {
            columns,
            names,
            keys,
            text,
            optional,
            integers: Vec::new(),
            format,
            header: Header::First,
            parquet,
        }
    }

    /// The same writer with the columns `integers` marks written as integers: `3` in CSV and
    /// JSON Lines rather than `3.0`, an INT64 column in Parquet. Counts only (whole numbers
    /// below 2^53, exact as binary64).
    pub fn with_integers(self, integers: Vec<bool>) -> RowWriter {
        let parquet = self.parquet.as_ref().and_then(|_| {
            parquet::Schema::new(&self.names, self.optional, self.text, &integers).ok()
        });
        RowWriter {
            integers,
            parquet,
            ..self
        }
    }

    /// The length of the field `text` (a value of column `i`) as written: an integer column's
    /// `3.0` is `3`.
    #[inline(always)]
    fn cut(&self, i: usize, text: &[u8], len: usize) -> usize {
        if self.integers.get(i) == Some(&true) && text[..len].ends_with(b".0") {
            len - 2
        } else {
            len
        }
    }

    /// Whether this writer can write its format: Parquet needs the `parquet` feature.
    pub fn check(&self) -> Result<(), String> {
        match (self.format, &self.parquet) {
            (RowFormat::Parquet, None) => Err(parquet::Schema::new(&self.names, false, None, &[])
                .err()
                .unwrap_or_else(|| "cannot write Parquet".into())),
            _ => Ok(()),
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

    /// A two-body table's columns.
    pub fn columns(&self) -> &[&'static Column] {
        &self.columns
    }

    /// The header's names.
    pub fn names(&self) -> &[String] {
        &self.names
    }

    pub fn format(&self) -> RowFormat {
        self.format
    }

    /// The header line (CSV and text; nothing for JSON Lines and Parquet, whose schema
    /// [`Sink::open`] writes).
    pub fn header(&self, out: &mut Vec<u8>) {
        match self.format {
            RowFormat::Csv => {
                let mut w = csv::Writer::from_writer(out);
                let _ = w.write_record(&self.names);
                let _ = w.flush();
            }
            // Text: each page of rows carries the names, aligned with its values.
            RowFormat::Text | RowFormat::Jsonl | RowFormat::Parquet => {}
        }
    }

    /// A buffer for a chunk of `rows` rows in this format, sized for a typical row so it
    /// rarely grows (each growth copies the chunk).
    pub fn buffer(&self, rows: usize) -> RowBuf {
        let n = self.names.len();
        let per_row = match self.format {
            RowFormat::Csv => 20 * n,
            RowFormat::Jsonl => 32 * n,
            RowFormat::Text => {
                return RowBuf::Text(TextPage {
                    names: self.names.clone(),
                    named: self.header != Header::Never,
                    fields: Vec::with_capacity(rows.min(1 << 16) * 12 * n),
                    ends: Vec::with_capacity(rows.min(1 << 16) * n),
                });
            }
            RowFormat::Parquet => {
                return RowBuf::Columns(Columns {
                    numbers: (0..n).map(|_| Vec::with_capacity(rows)).collect(),
                    texts: Vec::new(),
                    rows: 0,
                });
            }
        };
        RowBuf::Raw(Vec::with_capacity(rows.min(1 << 16) * per_row))
    }

    /// Writes one row of values (all finite: a two-body table).
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
                for (i, (key, v)) in self.keys.iter().zip(values).enumerate() {
                    if i > 0 {
                        out.push(b',');
                    }
                    out.extend_from_slice(key);
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
            RowBuf::Columns(c) => c.push(values, None),
        }
    }

    /// Writes one row of a table of runs: a NaN value is a missing cell, and `error` goes in
    /// the text column (the value there is ignored).
    // Inlined into the row loop compiled for AVX2 and FMA (`table::runs::chunk`).
    #[inline(always)]
    pub fn row_of_run(
        &self,
        values: &[f64],
        error: Option<&str>,
        buf: &mut RowBuf,
        fields: &mut FieldCache,
    ) {
        debug_assert!(self.optional, "a two-body table has no missing cells");
        let out = match buf {
            RowBuf::Raw(out) => out,
            RowBuf::Columns(c) => return c.push(values, self.text.map(|_| error)),
            RowBuf::Text(page) => {
                for (i, v) in values.iter().enumerate() {
                    if Some(i) == self.text {
                        let e = error.map_or("-".into(), |e| e.replace('\n', " "));
                        page.fields.extend_from_slice(e.as_bytes());
                    } else if v.is_nan() {
                        page.fields.push(b'-');
                    } else {
                        let (slot, len) = fields.slot(i, *v);
                        page.fields
                            .extend_from_slice(&slot[..self.cut(i, slot, len)]);
                    }
                    page.ends.push(page.fields.len());
                }
                return;
            }
        };
        let csv = self.format == RowFormat::Csv;
        for (i, v) in values.iter().enumerate() {
            // Written in place, no cell allocated: a sweep writes millions of rows.
            if csv {
                if i > 0 {
                    out.push(b',');
                }
            } else {
                out.push(if i == 0 { b'{' } else { b',' });
                out.extend_from_slice(&self.keys[i]);
            }
            if Some(i) == self.text {
                match error {
                    Some(e) => out.extend_from_slice(&self.quoted(e)),
                    None if !csv => out.extend_from_slice(b"null"),
                    None => {}
                }
            } else if v.is_nan() {
                if !csv {
                    out.extend_from_slice(b"null");
                }
            } else {
                // The whole 32-byte slot, cut back: a fixed-size copy (see `row`).
                let (slot, len) = fields.slot(i, *v);
                let at = out.len() + self.cut(i, slot, len);
                out.extend_from_slice(slot);
                out.truncate(at);
            }
        }
        if self.format == RowFormat::Jsonl {
            out.push(b'}');
        }
        out.push(b'\n');
    }

    /// An error text as a cell: quoted as CSV or JSON needs, on one line for text.
    fn quoted(&self, text: &str) -> Vec<u8> {
        match self.format {
            RowFormat::Csv => {
                let mut w = csv::WriterBuilder::new()
                    .has_headers(false)
                    .terminator(csv::Terminator::Any(b'\n'))
                    .from_writer(Vec::new());
                // A whole record: csv-core closes a quoted field only at its delimiter or
                // terminator (a lone write_field leaves the closing quote out).
                let _ = w.write_record([text]);
                let _ = w.flush();
                let mut cell = w.into_inner().unwrap_or_default();
                if cell.last() == Some(&b'\n') {
                    cell.pop();
                }
                cell
            }
            _ => serde_json::to_string(text).unwrap_or_default().into_bytes(),
        }
    }

    /// A chunk's rows as they go out: bytes, or a Parquet row group encoded here (in the
    /// thread that solved the chunk).
    pub fn seal(&self, buf: RowBuf) -> io::Result<Sealed> {
        match (buf, &self.parquet) {
            (RowBuf::Raw(v), _) => Ok(Sealed::Bytes(v)),
            (RowBuf::Text(page), _) => Ok(Sealed::Bytes(page.into_bytes())),
            (RowBuf::Columns(c), Some(schema)) => schema.encode(&c).map(Sealed::Group),
            (RowBuf::Columns(_), None) => Err(io::Error::other("Parquet is not built in")),
        }
    }
}

/// A chunk ready to go out.
pub enum Sealed {
    Bytes(Vec<u8>),
    Group(parquet::Group),
}

/// Where a table's chunks go, in order: bytes to a writer, or a Parquet file's row groups.
pub enum Sink<'a> {
    Bytes(&'a mut dyn Write),
    Parquet(Box<parquet::File<'a>>),
}

impl<'a> Sink<'a> {
    /// Starts piece `k` of a table on `out`: its header line if it has one, or a Parquet
    /// file's magic number.
    pub fn open(writer: &RowWriter, k: u64, out: &'a mut dyn Write) -> io::Result<Sink<'a>> {
        if let Some(schema) = &writer.parquet {
            return parquet::File::new(schema, out).map(|f| Sink::Parquet(Box::new(f)));
        }
        if writer.heads(k) {
            let mut header = Vec::new();
            writer.header(&mut header);
            out.write_all(&header)?;
        }
        Ok(Sink::Bytes(out))
    }

    pub fn put(&mut self, chunk: Sealed) -> io::Result<()> {
        match (self, chunk) {
            (Sink::Bytes(out), Sealed::Bytes(b)) => out.write_all(&b),
            (Sink::Parquet(f), Sealed::Group(g)) => f.put(g),
            _ => Err(io::Error::other("a chunk of another format")),
        }
    }

    /// Flushes what was written (a Parquet file's row groups so far: the footer comes with
    /// [`Sink::finish`]).
    pub fn flush(&mut self) -> io::Result<()> {
        match self {
            Sink::Bytes(out) => out.flush(),
            Sink::Parquet(f) => f.flush(),
        }
    }

    /// Ends the table: a Parquet file's footer.
    pub fn finish(self) -> io::Result<()> {
        match self {
            Sink::Bytes(out) => out.flush(),
            Sink::Parquet(f) => f.finish(),
        }
    }
}

/// A page of a text table (the rows of one chunk): the fields as they come, aligned when the
/// page is done, each column as wide as its widest value (or name), right-aligned; a page wider
/// than the terminal ([`crate::values::terminal::width`]) is folded into groups of columns, each
/// repeating the first. Every page starts with the names (unless `--header never`): a text
/// table is for people, who read pages, not shards.
pub struct TextPage {
    names: Vec<String>,
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
        let groups = crate::values::terminal::fold(&widths, 1, 2, crate::values::terminal::width());
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
    zmij: zmij::Buffer,
}

impl FieldCache {
    pub fn new(columns: usize) -> FieldCache {
        // A NaN bit pattern: never equal to a finite value's.
        FieldCache {
            last: vec![(u64::MAX, [0; 32], 0); columns],
            zmij: zmij::Buffer::new(),
        }
    }

    /// The text of `v` (finite) in column `i`: a 32-byte slot and the text's length in it.
    #[inline(always)]
    pub fn slot(&mut self, i: usize, v: f64) -> (&[u8; 32], usize) {
        self.format(i, v);
        let (_, text, len) = &self.last[i];
        (text, *len as usize)
    }

    /// The text of `v` (finite) in column `i`.
    #[inline(always)]
    pub fn format(&mut self, i: usize, v: f64) -> &[u8] {
        let (bits, text, len) = &mut self.last[i];
        debug_assert!(v.is_finite(), "tables hold finite values only");
        if *bits != v.to_bits() {
            // zmij prints ryu's text but for a `+` in a positive exponent (`1e+23`, from
            // 1e16 up): dropped, so tables keep ryu's `1e23`. At most 24 bytes; the slot has 32.
            let t = self.zmij.format_finite(v).as_bytes();
            let mut n = t.len();
            text[..n].copy_from_slice(t);
            if v.abs() >= 1e16
                && let Some(plus) = t.iter().position(|&b| b == b'+')
            {
                text.copy_within(plus + 1..n, plus);
                n -= 1;
            }
            *len = n as u8;
            *bits = v.to_bits();
        }
        &text[..*len as usize]
    }
}

/// A chunk's rows as they are written: bytes (CSV, JSON Lines), a text page, or columns for
/// Parquet.
pub enum RowBuf {
    Raw(Vec<u8>),
    Text(TextPage),
    Columns(Columns),
}

impl RowBuf {
    /// The bytes of a text format (none for Parquet's columns).
    pub fn into_bytes(self) -> Vec<u8> {
        match self {
            RowBuf::Raw(v) => v,
            RowBuf::Text(page) => page.into_bytes(),
            RowBuf::Columns(_) => Vec::new(),
        }
    }

    /// Rows in the buffer, for Parquet (text formats do not count them).
    pub fn rows(&self) -> usize {
        match self {
            RowBuf::Raw(_) | RowBuf::Text(_) => 0,
            RowBuf::Columns(c) => c.rows,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::table::columns::by_names;

    /// A table's text of a number is ryu's (the schema's), and reads back as the same
    /// binary64: over every exponent, subnormals, signs and the extremes.
    #[test]
    fn fields_are_ryus_text_and_round_trip() {
        let mut f = FieldCache::new(1);
        let mut ryu = ryu::Buffer::new();
        let mut x: u64 = 0x9E37_79B9_7F4A_7C15;
        let mut values = vec![
            0.0,
            -0.0,
            5e-324,
            f64::MIN_POSITIVE,
            f64::MAX,
            -f64::MAX,
            1e16,
        ];
        for _ in 0..200_000 {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            values.push(f64::from_bits(x));
            values.push((x % 100_000) as f64 / 1000.0);
            values.push((x % 1000) as f64 * 10f64.powi((x % 60) as i32 - 30));
        }
        for v in values.into_iter().filter(|v| v.is_finite()) {
            let text = f.format(0, v).to_vec();
            assert_eq!(text, ryu.format_finite(v).as_bytes(), "{v:e}");
            let back: f64 = std::str::from_utf8(&text).unwrap().parse().unwrap();
            assert_eq!(back.to_bits(), v.to_bits(), "{v:e}");
        }
    }

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
