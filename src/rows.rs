//! Tables of collisions, one row each (`collide sweep`, `collide batch`, `[sweep]` scenes):
//! the columns a user picks, solved by the same solver as `solve`, written as CSV (the csv
//! crate), JSON Lines or aligned text, numbers shortest-round-trip (ryu) with no allocation per
//! field. Rows are solved in parallel (rayon) in chunks and written in order; a bad row stops the
//! run after every row before it has been written whole, or, with `--skip-bad`, is reported on
//! stderr and skipped.

use std::fmt;
use std::fs::File;
use std::io::{self, BufWriter, IsTerminal, Write};
use std::path::{Path, PathBuf};
use std::str::FromStr;
use std::time::{Duration, Instant};

use nalgebra::Vector2;
use rayon::prelude::*;

use crate::collision::Collision;
use crate::frame::Observed;
use crate::inertia::InertiaTensor;
use crate::number::Number;
use crate::restitution::Restitution;
use crate::solver::Solver;

/// A quantity a table can show.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Column {
    M1,
    M2,
    M11,
    M12,
    M22,
    V1,
    V2,
    E,
    Fin1,
    Fin2,
    VCom,
    PTotal,
    KeIn,
    KeFin,
    KeCom,
    Crunch,
    Lost,
    Mu,
    InMIn,
    FinMIn,
    FinMFin,
    ComMIn,
}

impl Column {
    pub const ALL: [Column; 22] = [
        Column::M1,
        Column::M2,
        Column::M11,
        Column::M12,
        Column::M22,
        Column::V1,
        Column::V2,
        Column::E,
        Column::Fin1,
        Column::Fin2,
        Column::VCom,
        Column::PTotal,
        Column::KeIn,
        Column::KeFin,
        Column::KeCom,
        Column::Crunch,
        Column::Lost,
        Column::Mu,
        Column::InMIn,
        Column::FinMIn,
        Column::FinMFin,
        Column::ComMIn,
    ];

    pub fn name(self) -> &'static str {
        match self {
            Column::M1 => "m1",
            Column::M2 => "m2",
            Column::M11 => "m11",
            Column::M12 => "m12",
            Column::M22 => "m22",
            Column::V1 => "v1",
            Column::V2 => "v2",
            Column::E => "e",
            Column::Fin1 => "fin1",
            Column::Fin2 => "fin2",
            Column::VCom => "v_com",
            Column::PTotal => "p_total",
            Column::KeIn => "ke_in",
            Column::KeFin => "ke_fin",
            Column::KeCom => "ke_com",
            Column::Crunch => "crunch",
            Column::Lost => "lost",
            Column::Mu => "mu",
            Column::InMIn => "in_m_in",
            Column::FinMIn => "fin_m_in",
            Column::FinMFin => "fin_m_fin",
            Column::ComMIn => "com_m_in",
        }
    }

    /// The default columns: the inputs, then FIN, V_COM and the energies.
    pub fn defaults(general: bool) -> Vec<Column> {
        let inputs: &[Column] = if general {
            &[
                Column::M11,
                Column::M12,
                Column::M22,
                Column::V1,
                Column::V2,
                Column::E,
            ]
        } else {
            &[Column::M1, Column::M2, Column::V1, Column::V2, Column::E]
        };
        let outputs = [
            Column::Fin1,
            Column::Fin2,
            Column::VCom,
            Column::KeIn,
            Column::KeFin,
            Column::Crunch,
            Column::Lost,
        ];
        inputs.iter().copied().chain(outputs).collect()
    }
}

impl FromStr for Column {
    type Err = String;
    fn from_str(s: &str) -> Result<Column, String> {
        Column::ALL
            .into_iter()
            .find(|c| c.name() == s.trim())
            .ok_or_else(|| {
                let names: Vec<&str> = Column::ALL.iter().map(|c| c.name()).collect();
                format!(
                    "'{}' is not a column: expected one of {}",
                    s.trim(),
                    names.join(", ")
                )
            })
    }
}

impl fmt::Display for Column {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// The inputs of one row: `M = [[m11, m12], [m12, m22]]`, `V`, `e`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RowCase {
    pub m11: f64,
    pub m12: f64,
    pub m22: f64,
    pub v: [f64; 2],
    pub e: f64,
}

/// A row that could not be solved.
#[derive(Clone, Debug, PartialEq)]
pub struct RowError {
    /// `line 17` (batch input) or `row 17` (sweep).
    pub place: String,
    pub message: String,
}

impl fmt::Display for RowError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: {}", self.place, self.message)
    }
}

impl std::error::Error for RowError {}

/// Solves a row's columns into `out`. `shared` is the tensor when every row has the same one.
pub fn solve_row(
    case: &RowCase,
    shared: Option<&InertiaTensor>,
    columns: &[Column],
    out: &mut [f64],
) -> Result<(), String> {
    let n = |x: f64| Number::from_f64(x).map_err(|e| e.to_string());
    let inertia = match shared {
        Some(t) => t.clone(),
        None => {
            InertiaTensor::general([[n(case.m11)?, n(case.m12)?], [n(case.m12)?, n(case.m22)?]])
                .map_err(|e| e.to_string())?
        }
    };
    let e = Restitution::new(n(case.e)?)?;
    let c = Collision::new(inertia, Vector2::new(case.v[0], case.v[1]), e);
    let seen = Observed::lab(&c);
    let mut fin: Option<[f64; 2]> = None;
    let mut fin = || *fin.get_or_insert_with(|| seen.v_fin());
    for (slot, col) in out.iter_mut().zip(columns) {
        *slot = match col {
            Column::M1 | Column::M11 => case.m11,
            Column::M2 | Column::M22 => case.m22,
            Column::M12 => case.m12,
            Column::V1 => case.v[0],
            Column::V2 => case.v[1],
            Column::E => case.e,
            Column::Fin1 => fin()[0],
            Column::Fin2 => fin()[1],
            Column::VCom => seen.v_com(),
            Column::PTotal => seen.total_momentum(),
            Column::KeIn => seen.ke_in(),
            Column::KeFin => seen.ke_fin(),
            Column::KeCom => seen.ke_com(),
            Column::Crunch => seen.crunch(),
            Column::Lost => seen.lost(),
            Column::Mu => seen.reduced_mass(),
            Column::InMIn => seen.form(&seen.v_in(), &seen.v_in()),
            Column::FinMIn => seen.form(&fin(), &seen.v_in()),
            Column::FinMFin => seen.form(&fin(), &fin()),
            Column::ComMIn => seen.com_form(),
        };
        if !slot.is_finite() {
            return Err(format!(
                "{col} is not representable in binary64 (beyond 2.2e-308 to 1.8e308); \
                 rescale the units or use collide solve --exact"
            ));
        }
    }
    Ok(())
}

/// How rows are written.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum RowFormat {
    /// Comma-separated values with a header line
    Csv,
    /// One JSON object a line
    Jsonl,
    /// Aligned columns for people
    Text,
}

/// Width of a text column: the longest shortest-round-trip binary64 ("-1.2345678901234567e-308").
const TEXT_WIDTH: usize = 24;

/// Writes rows of numbers in one format.
pub struct RowWriter {
    columns: Vec<Column>,
    format: RowFormat,
}

impl RowWriter {
    pub fn new(columns: Vec<Column>, format: RowFormat) -> RowWriter {
        RowWriter { columns, format }
    }

    pub fn columns(&self) -> &[Column] {
        &self.columns
    }

    /// The header line (CSV and text; nothing for JSON Lines).
    pub fn header(&self, out: &mut Vec<u8>) {
        match self.format {
            RowFormat::Csv => {
                let mut w = csv::Writer::from_writer(out);
                let _ = w.write_record(self.columns.iter().map(|c| c.name()));
                let _ = w.flush();
            }
            RowFormat::Text => {
                for (i, c) in self.columns.iter().enumerate() {
                    let sep = if i == 0 { "" } else { " " };
                    let _ = write!(out, "{sep}{:>TEXT_WIDTH$}", c.name());
                }
                out.push(b'\n');
            }
            RowFormat::Jsonl => {}
        }
    }

    /// A buffer for a chunk of rows in this format.
    pub fn buffer(&self) -> RowBuf {
        match self.format {
            RowFormat::Csv => RowBuf::Csv(Box::new(
                csv::WriterBuilder::new()
                    .has_headers(false)
                    // Fields are numbers: they never need quotes, so skip looking for them.
                    .quote_style(csv::QuoteStyle::Never)
                    .from_writer(Vec::with_capacity(1 << 16)),
            )),
            _ => RowBuf::Raw(Vec::with_capacity(1 << 16)),
        }
    }

    /// Writes one row of values (all finite).
    pub fn row(&self, values: &[f64], buf: &mut RowBuf, fields: &mut FieldCache) {
        match buf {
            RowBuf::Csv(csv) => {
                for (i, v) in values.iter().enumerate() {
                    let _ = csv.write_field(fields.format(i, *v));
                }
                let _ = csv.write_record(None::<&[u8]>);
            }
            RowBuf::Raw(out) if self.format == RowFormat::Jsonl => {
                out.push(b'{');
                for (i, (c, v)) in self.columns.iter().zip(values).enumerate() {
                    if i > 0 {
                        out.push(b',');
                    }
                    out.push(b'"');
                    out.extend_from_slice(c.name().as_bytes());
                    out.extend_from_slice(b"\":");
                    out.extend_from_slice(fields.format(i, *v));
                }
                out.extend_from_slice(b"}\n");
            }
            RowBuf::Raw(out) => {
                for (i, v) in values.iter().enumerate() {
                    let s = fields.format(i, *v);
                    let pad = TEXT_WIDTH.saturating_sub(s.len()) + usize::from(i > 0);
                    out.extend(std::iter::repeat_n(b' ', pad));
                    out.extend_from_slice(s);
                }
                out.push(b'\n');
            }
        }
    }
}

/// Shortest round-trip text of each column's last value: in a sweep most fields repeat from one
/// row to the next (inputs that do not vary, and whatever does not depend on the fastest
/// parameter), and formatting numbers is most of a table's cost.
pub struct FieldCache {
    last: Vec<(u64, [u8; 32], u8)>,
    ryu: ryu::Buffer,
}

impl FieldCache {
    pub fn new(columns: usize) -> FieldCache {
        // A NaN bit pattern: never equal to a finite value's.
        FieldCache {
            last: vec![(u64::MAX, [0; 32], 0); columns],
            ryu: ryu::Buffer::new(),
        }
    }

    /// The text of `v` (finite) in column `i`.
    pub fn format(&mut self, i: usize, v: f64) -> &[u8] {
        let (bits, text, len) = &mut self.last[i];
        if *bits != v.to_bits() {
            let s = self.ryu.format_finite(v).as_bytes();
            text[..s.len()].copy_from_slice(s);
            *len = s.len() as u8;
            *bits = v.to_bits();
        }
        &text[..*len as usize]
    }
}

/// A chunk's bytes as they are written.
pub enum RowBuf {
    Csv(Box<csv::Writer<Vec<u8>>>),
    Raw(Vec<u8>),
}

impl RowBuf {
    pub fn into_bytes(self) -> Vec<u8> {
        match self {
            RowBuf::Csv(w) => w.into_inner().unwrap_or_default(),
            RowBuf::Raw(v) => v,
        }
    }
}

/// What a chunk of rows became.
pub struct ChunkOut {
    pub bytes: Vec<u8>,
    pub rows: u64,
    /// Rows skipped (`--skip-bad`), in order.
    pub skipped: Vec<RowError>,
    /// The row that stopped the run; `bytes` holds every row before it.
    pub stop: Option<RowError>,
}

/// Solves and formats a chunk of rows: `(place, case)` or an input error.
pub fn chunk(
    items: impl Iterator<Item = Result<(u64, RowCase), RowError>>,
    place: &dyn Fn(u64) -> String,
    shared: Option<&InertiaTensor>,
    writer: &RowWriter,
    skip_bad: bool,
) -> ChunkOut {
    let mut buf = writer.buffer();
    let mut fields = FieldCache::new(writer.columns.len());
    let mut values = vec![0.0; writer.columns.len()];
    let mut out = ChunkOut {
        bytes: Vec::new(),
        rows: 0,
        skipped: Vec::new(),
        stop: None,
    };
    for item in items {
        let result = item.and_then(|(at, case)| {
            solve_row(&case, shared, &writer.columns, &mut values).map_err(|message| RowError {
                place: place(at),
                message,
            })
        });
        match result {
            Ok(()) => {
                writer.row(&values, &mut buf, &mut fields);
                out.rows += 1;
            }
            Err(e) if skip_bad => out.skipped.push(e),
            Err(e) => {
                out.stop = Some(e);
                break;
            }
        }
    }
    out.bytes = buf.into_bytes();
    out
}

/// Where rows go: stdout; a regular file written atomically (a temporary file beside it renamed
/// into place when the run completes, removed if it does not); or a device, FIFO or other
/// non-regular file (`-o /dev/null`), written directly and never replaced.
pub enum Output {
    Stdout(io::StdoutLock<'static>),
    File {
        tmp: PathBuf,
        path: PathBuf,
        file: BufWriter<File>,
        done: bool,
    },
    Direct(BufWriter<File>),
}

impl Output {
    pub fn open(path: Option<&Path>) -> io::Result<Output> {
        let Some(path) = path else {
            return Ok(Output::Stdout(io::stdout().lock()));
        };
        // Follow a symlink to the file it names, so the rename replaces that file, not the link.
        let path = match std::fs::metadata(path) {
            Ok(m) if !m.is_file() => {
                let file = std::fs::OpenOptions::new().write(true).open(path)?;
                return Ok(Output::Direct(BufWriter::with_capacity(1 << 20, file)));
            }
            Ok(_) => std::fs::canonicalize(path)?,
            Err(_) => path.to_path_buf(),
        };
        let name = path
            .file_name()
            .map(|n| n.to_string_lossy().into_owned())
            .unwrap_or_default();
        let tmp = path.with_file_name(format!(".{name}.{}.partial", std::process::id()));
        let file = BufWriter::with_capacity(1 << 20, File::create(&tmp)?);
        Ok(Output::File {
            tmp,
            path,
            file,
            done: false,
        })
    }

    /// Flushes, and renames a file into place.
    pub fn commit(mut self) -> io::Result<()> {
        match &mut self {
            Output::Stdout(s) => s.flush(),
            Output::Direct(f) => f.flush(),
            Output::File {
                tmp,
                path,
                file,
                done,
            } => {
                file.flush()?;
                file.get_ref().sync_all()?;
                std::fs::rename(tmp, path)?;
                *done = true;
                Ok(())
            }
        }
    }
}

impl Write for Output {
    fn write(&mut self, buf: &[u8]) -> io::Result<usize> {
        match self {
            Output::Stdout(s) => s.write(buf),
            Output::File { file, .. } | Output::Direct(file) => file.write(buf),
        }
    }
    fn write_all(&mut self, buf: &[u8]) -> io::Result<()> {
        match self {
            Output::Stdout(s) => s.write_all(buf),
            Output::File { file, .. } | Output::Direct(file) => file.write_all(buf),
        }
    }
    fn flush(&mut self) -> io::Result<()> {
        match self {
            Output::Stdout(s) => s.flush(),
            Output::File { file, .. } | Output::Direct(file) => file.flush(),
        }
    }
}

impl Drop for Output {
    fn drop(&mut self) {
        if let Output::File {
            tmp, done: false, ..
        } = self
        {
            let _ = std::fs::remove_file(tmp);
        }
    }
}

/// A progress bar on stderr for runs longer than about a second, only on a terminal (never in
/// pipes or CI), and not with `TERM=dumb`.
pub struct Progress {
    bar: indicatif::ProgressBar,
    start: Instant,
    shown: bool,
    allowed: bool,
}

impl Progress {
    pub fn new(total: Option<u64>) -> Progress {
        let bar = match total {
            Some(t) => indicatif::ProgressBar::with_draw_target(
                Some(t),
                indicatif::ProgressDrawTarget::hidden(),
            ),
            None => indicatif::ProgressBar::hidden(),
        };
        let allowed = io::stderr().is_terminal()
            && std::env::var_os("TERM").is_none_or(|t| t != "dumb")
            && std::env::var_os("CI").is_none();
        Progress {
            bar,
            start: Instant::now(),
            shown: false,
            allowed,
        }
    }

    pub fn advance(&mut self, rows: u64) {
        self.bar.inc(rows);
        if self.allowed && !self.shown && self.start.elapsed() > Duration::from_secs(1) {
            self.shown = true;
            if let Ok(style) = indicatif::ProgressStyle::with_template(
                "{bar:40} {pos}/{len} rows ({per_sec}, eta {eta})",
            ) {
                self.bar.set_style(style);
            }
            self.bar
                .set_draw_target(indicatif::ProgressDrawTarget::stderr());
        }
    }

    pub fn finish(&self) {
        self.bar.finish_and_clear();
    }
}

/// How a table run ended.
#[derive(Debug, Default, PartialEq)]
pub struct Summary {
    pub rows: u64,
    pub skipped: u64,
}

/// Why a table run stopped.
#[derive(Debug, thiserror::Error)]
pub enum RowsError {
    #[error(transparent)]
    Row(#[from] RowError),
    #[error(transparent)]
    Io(#[from] io::Error),
}

/// Rows per chunk solved by one thread.
pub const CHUNK_ROWS: usize = 8192;

/// Solves chunks in parallel, a batch at a time, and writes them in order; reports skipped rows
/// on stderr as it goes; stops at the first bad row (after writing every row before it).
pub fn write_chunks<C: Send>(
    batches: impl Iterator<Item = Vec<C>>,
    solve: impl Fn(C) -> ChunkOut + Sync + Send,
    out: &mut dyn Write,
    progress: &mut Progress,
) -> Result<Summary, RowsError> {
    let mut summary = Summary::default();
    for batch in batches {
        let done: Vec<ChunkOut> = batch.into_par_iter().map(&solve).collect();
        for c in done {
            out.write_all(&c.bytes)?;
            summary.rows += c.rows;
            progress.advance(c.rows + c.skipped.len() as u64);
            for s in &c.skipped {
                eprintln!("skipped {s}");
            }
            summary.skipped += c.skipped.len() as u64;
            if let Some(stop) = c.stop {
                out.flush()?;
                return Err(stop.into());
            }
        }
    }
    out.flush()?;
    Ok(summary)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn case(m1: f64, m2: f64, v: [f64; 2], e: f64) -> RowCase {
        RowCase {
            m11: m1,
            m12: 0.0,
            m22: m2,
            v,
            e,
        }
    }

    #[test]
    fn a_row_is_the_lecture_case() {
        let cols = Column::defaults(false);
        let mut out = vec![0.0; cols.len()];
        solve_row(&case(4.0, 1.0, [60.0, 10.0], 1.0), None, &cols, &mut out).unwrap();
        // m1 m2 v1 v2 e fin1 fin2 v_com ke_in ke_fin crunch lost
        assert_eq!(
            out,
            [
                4.0, 1.0, 60.0, 10.0, 1.0, 40.0, 90.0, 50.0, 7250.0, 7250.0, 1000.0, 0.0
            ]
        );
    }

    #[test]
    fn formats() {
        let w = RowWriter::new(vec![Column::E, Column::KeIn], RowFormat::Csv);
        let mut header = Vec::new();
        w.header(&mut header);
        assert_eq!(header, b"e,ke_in\n");
        let mut buf = w.buffer();
        let mut f = FieldCache::new(2);
        w.row(&[0.3, 1e300], &mut buf, &mut f);
        w.row(&[0.3, -2.5], &mut buf, &mut f);
        assert_eq!(buf.into_bytes(), b"0.3,1e300\n0.3,-2.5\n");
        let w = RowWriter::new(vec![Column::E, Column::KeIn], RowFormat::Jsonl);
        let mut buf = w.buffer();
        w.row(&[0.3, 7250.0], &mut buf, &mut FieldCache::new(2));
        assert_eq!(buf.into_bytes(), b"{\"e\":0.3,\"ke_in\":7250.0}\n");
        let w = RowWriter::new(vec![Column::E], RowFormat::Text);
        let mut buf = w.buffer();
        w.row(&[0.5], &mut buf, &mut FieldCache::new(1));
        assert_eq!(buf.into_bytes(), format!("{:>24}\n", "0.5").as_bytes());
    }

    #[test]
    fn bad_rows_stop_or_are_skipped() {
        let w = RowWriter::new(vec![Column::Fin1], RowFormat::Csv);
        let items = || {
            vec![
                Ok((1, case(4.0, 1.0, [60.0, 10.0], 1.0))),
                Ok((2, case(1.0, 1.0, [1e200, -1e200], 1.0))),
                Ok((3, case(4.0, 1.0, [60.0, 10.0], 0.0))),
            ]
            .into_iter()
        };
        let place = |r: u64| format!("row {r}");
        // FIN of row 2 is representable (-1e200, 1e200): only what is asked is computed.
        let all = chunk(items(), &place, None, &w, false);
        assert_eq!(all.bytes, b"40.0\n-1e200\n50.0\n");
        // Its KE (1e400) is not.
        let w = RowWriter::new(vec![Column::KeIn], RowFormat::Csv);
        let stopped = chunk(items(), &place, None, &w, false);
        assert_eq!(stopped.bytes, b"7250.0\n");
        assert_eq!(stopped.stop.unwrap().place, "row 2");
        let skipping = chunk(items(), &place, None, &w, true);
        assert_eq!(skipping.bytes, b"7250.0\n7250.0\n");
        assert_eq!(skipping.skipped.len(), 1);
        assert!(
            skipping.skipped[0]
                .message
                .contains("ke_in is not representable")
        );
    }
}
