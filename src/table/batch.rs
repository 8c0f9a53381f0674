//! Cases for `collide batch`: CSV with a header naming `m1,m2,v1,v2` and optionally `e` (or
//! `m11,m12,m22` for a general tensor), or JSON Lines with the same keys. In the plane, two
//! bodies with velocity components `v1x,v1y,v2x,v2y` and a line of impact: `normal_deg`, or
//! `nx,ny`, or disks `b,r1,r2` (the parameters of a sweep in the plane, `table::runs::plane`).
//! Read as a stream, one
//! row at a time: memory stays constant whatever the input size. A line is at most
//! [`MAX_LINE_BYTES`] (`/dev/zero` is refused at once); a read error (a directory,
//! `/proc/self/mem`) ends the run; an empty input is a table of no rows; a UTF-8 byte-order mark
//! is skipped; a column or key given twice is refused.

use std::fs::File;
use std::io::{self, BufRead, BufReader, Read};
use std::path::Path;

use super::row::{LayoutError, RowCase, RowError, RowProblem, ValueProblem, check};
use super::runs::plane::{Line, PlaneSweep};
use super::runs::{Kind, Knob};
use crate::values::number::Number;

/// Input format (`--input-format`; by default from the file's extension, or for stdin from its
/// first character: `{` means JSON Lines).
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum InputFormat {
    Csv,
    Jsonl,
}

/// Longest line of an input, in bytes (4 MiB: a row of cases is a few dozen bytes; a longer
/// line is a binary file or `/dev/zero`, which would otherwise be read into memory whole).
pub const MAX_LINE_BYTES: usize = 4 << 20;

/// A reader that fails once a line grows beyond [`MAX_LINE_BYTES`], and after that.
struct LineCap<R> {
    inner: R,
    /// Bytes since the last newline.
    run: usize,
}

impl<R: Read> Read for LineCap<R> {
    fn read(&mut self, buf: &mut [u8]) -> io::Result<usize> {
        if self.run <= MAX_LINE_BYTES {
            let n = self.inner.read(buf)?;
            match buf[..n].iter().rposition(|&b| b == b'\n') {
                Some(i) => self.run = n - 1 - i,
                None => self.run += n,
            }
            if self.run <= MAX_LINE_BYTES {
                return Ok(n);
            }
        }
        Err(io::Error::new(
            io::ErrorKind::InvalidData,
            format!(
                "a line is longer than {MAX_LINE_BYTES} bytes (4 MiB): not a table of cases \
                 (a binary file, or /dev/zero?)"
            ),
        ))
    }
}

const DIAGONAL: [&str; 4] = ["m1", "m2", "v1", "v2"];
const GENERAL: [&str; 5] = ["m11", "m12", "m22", "v1", "v2"];

/// Why an input cannot be read.
#[derive(Debug, thiserror::Error)]
pub enum BatchError {
    #[error("cannot read {name}: {error}")]
    Read { name: String, error: std::io::Error },
    #[error("{name}: cannot read the CSV header: {error}")]
    Header { name: String, error: csv::Error },
    /// A bad header or first object, at `place` (`line 1 (header)`, `line 3`).
    #[error("{name}: {place}: {problem}")]
    Layout {
        name: String,
        place: String,
        problem: RowProblem,
    },
}

/// One case of a batch: on a line, or in the plane (the values of the parameters of
/// [`Batch::plane`]'s sweep, in the order of [`Batch::params`]).
#[derive(Clone, Debug, PartialEq)]
pub enum Case {
    Line(RowCase),
    Plane(Vec<(Knob, f64)>),
}

/// Which columns hold what.
#[derive(Clone, Debug)]
enum Layout {
    Line(LineLayout),
    Plane(PlaneLayout),
}

/// The columns of a case on a line.
#[derive(Clone, Debug)]
struct LineLayout {
    general: bool,
    /// Field index of m11 (m1), m12, m22 (m2), v1, v2, e.
    at: [Option<usize>; 6],
}

/// How a batch in the plane gives its line of impact.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum LineColumns {
    Degrees,
    Components,
    Disks,
}

impl LineColumns {
    fn names(self) -> &'static [&'static str] {
        match self {
            LineColumns::Degrees => &["normal_deg"],
            LineColumns::Components => &["nx", "ny"],
            LineColumns::Disks => &["b", "r1", "r2"],
        }
    }
}

/// The columns of a case in the plane: the parameters, in a fixed order (whatever the order of
/// the header or of an object's keys), and the field each is read from (`None`: `e` not given,
/// the default).
#[derive(Clone, Debug)]
struct PlaneLayout {
    line: LineColumns,
    params: Vec<(Knob, &'static str, Option<usize>)>,
}

/// The columns of the plane that a case on a line does not have.
const PLANE_ONLY: [&str; 10] = [
    "v1x",
    "v1y",
    "v2x",
    "v2y",
    "normal_deg",
    "nx",
    "ny",
    "b",
    "r1",
    "r2",
];

/// Refuses a name given twice.
fn once(names: &[String]) -> Result<(), LayoutError> {
    for (i, n) in names.iter().enumerate() {
        if names[..i].contains(n) {
            return Err(LayoutError::Twice(n.clone()));
        }
    }
    Ok(())
}

impl Layout {
    fn of(names: &[String]) -> Result<Layout, LayoutError> {
        once(names)?;
        if names.iter().any(|n| PLANE_ONLY.contains(&n.as_str())) {
            PlaneLayout::of(names).map(Layout::Plane)
        } else {
            LineLayout::of(names).map(Layout::Line)
        }
    }

    /// Whether two layouts read the same kind of case (JSON Lines objects must agree).
    fn same_kind(&self, other: &Layout) -> bool {
        match (self, other) {
            (Layout::Line(a), Layout::Line(b)) => a.general == b.general,
            (Layout::Plane(a), Layout::Plane(b)) => a.line == b.line,
            _ => false,
        }
    }

    fn case<'a>(
        &self,
        get: impl Fn(usize) -> Option<&'a str>,
        line: u64,
        default_e: f64,
    ) -> Result<(u64, Case), RowError> {
        match self {
            Layout::Line(l) => l
                .case(get, line, default_e)
                .map(|(l, c)| (l, Case::Line(c))),
            Layout::Plane(p) => p.case(get, line, default_e),
        }
    }
}

impl PlaneLayout {
    fn of(names: &[String]) -> Result<PlaneLayout, LayoutError> {
        let find = |n: &str| names.iter().position(|h| h == n);
        let known = ["m1", "m2", "v1x", "v1y", "v2x", "v2y", "e"];
        let given: Vec<LineColumns> = [
            LineColumns::Degrees,
            LineColumns::Components,
            LineColumns::Disks,
        ]
        .into_iter()
        .filter(|l| l.names().iter().any(|n| find(n).is_some()))
        .collect();
        let line = match given[..] {
            [l] => l,
            [] => return Err(LayoutError::PlaneLine),
            _ => return Err(LayoutError::PlaneLines),
        };
        for n in names {
            if !known.contains(&n.as_str()) && !line.names().contains(&n.as_str()) {
                return Err(LayoutError::UnknownInPlane(n.clone()));
            }
        }
        let mut params = Vec::new();
        for n in known.iter().chain(line.names()) {
            let at = find(n);
            if at.is_none() && *n != "e" {
                return Err(LayoutError::MissingInPlane(n));
            }
            let knob = match *n {
                "m1" => Knob::Mass(0),
                "m2" => Knob::Mass(1),
                other => Knob::Named(other),
            };
            params.push((knob, *n, at));
        }
        Ok(PlaneLayout { line, params })
    }

    /// The sweep whose parameters a row gives (every value of it is the row's).
    fn base(&self) -> PlaneSweep {
        PlaneSweep {
            m: [1.0, 1.0],
            v: [[0.0, 0.0], [0.0, 0.0]],
            line: match self.line {
                LineColumns::Disks => Line::Geometry {
                    r: [1.0, 1.0],
                    b: 0.0,
                },
                _ => Line::Normal([1.0, 0.0]),
            },
            e: 1.0,
        }
    }

    fn case<'a>(
        &self,
        get: impl Fn(usize) -> Option<&'a str>,
        line: u64,
        default_e: f64,
    ) -> Result<(u64, Case), RowError> {
        let base = self.base();
        let mut point = Vec::with_capacity(self.params.len());
        for &(knob, field, at) in &self.params {
            let bad = |problem: ValueProblem| RowError {
                place: format!("line {line}"),
                problem: RowProblem::Field { field, problem },
            };
            let Some(i) = at else {
                point.push((knob, default_e));
                continue;
            };
            let text = get(i).ok_or_else(|| bad(ValueProblem::Missing))?;
            let n: Number = text.parse().map_err(|e| bad(plane_number(text, e)))?;
            base.check(knob, &n).map_err(bad)?;
            point.push((knob, n.value()));
        }
        Ok((line, Case::Plane(point)))
    }
}

/// A number that does not parse; a vector gets a hint (a batch takes components).
fn plane_number(text: &str, e: crate::values::number::NumberError) -> ValueProblem {
    if text.trim_start().starts_with('(') {
        ValueProblem::Range(format!(
            "'{text}' is a vector: a batch in the plane gives each component in its own column \
             (v1x, v1y, v2x, v2y; nx, ny)"
        ))
    } else {
        ValueProblem::Number(e)
    }
}

impl LineLayout {
    fn of(names: &[String]) -> Result<LineLayout, LayoutError> {
        let find = |n: &str| names.iter().position(|h| h == n);
        for n in names {
            if !DIAGONAL.contains(&n.as_str()) && !GENERAL.contains(&n.as_str()) && n != "e" {
                return Err(LayoutError::Unknown(n.clone()));
            }
        }
        let general = find("m11").is_some() || find("m12").is_some() || find("m22").is_some();
        let needed: &[&str] = if general { &GENERAL } else { &DIAGONAL };
        if let Some(missing) = needed.iter().find(|n| find(n).is_none()) {
            return Err(LayoutError::Missing(missing));
        }
        if general && (find("m1").is_some() || find("m2").is_some()) {
            return Err(LayoutError::Both);
        }
        let at = if general {
            [
                find("m11"),
                find("m12"),
                find("m22"),
                find("v1"),
                find("v2"),
                find("e"),
            ]
        } else {
            [
                find("m1"),
                None,
                find("m2"),
                find("v1"),
                find("v2"),
                find("e"),
            ]
        };
        Ok(LineLayout { general, at })
    }

    /// A row from its fields (`get(i)` is field `i` as text).
    fn case<'a>(
        &self,
        get: impl Fn(usize) -> Option<&'a str>,
        line: u64,
        default_e: f64,
    ) -> Result<(u64, RowCase), RowError> {
        let names = if self.general {
            ["m11", "m12", "m22", "v1", "v2", "e"]
        } else {
            ["m1", "m12", "m2", "v1", "v2", "e"]
        };
        let mut x = [0.0, 0.0, 0.0, 0.0, 0.0, default_e];
        for (k, slot) in x.iter_mut().enumerate() {
            let Some(i) = self.at[k] else { continue };
            let field = names[k];
            let bad = |problem: ValueProblem| RowError {
                place: format!("line {line}"),
                problem: RowProblem::Field { field, problem },
            };
            let text = get(i).ok_or_else(|| bad(ValueProblem::Missing))?;
            let n: Number = text.parse().map_err(|e| bad(line_number(text, e)))?;
            *slot = n.value();
            // Each value is validated by the type that holds it.
            check(field, n).map_err(bad)?;
        }
        Ok((
            line,
            RowCase {
                m11: x[0],
                m12: x[1],
                m22: x[2],
                v: [x[3], x[4]],
                e: x[5],
            },
        ))
    }
}

/// A number on a line that does not parse; a vector gets a hint (the plane needs a line of
/// impact).
fn line_number(text: &str, e: crate::values::number::NumberError) -> ValueProblem {
    if text.trim_start().starts_with('(') {
        ValueProblem::Range(format!(
            "'{text}' is a vector: a batch in the plane gives the components in columns v1x, \
             v1y, v2x, v2y and the line of impact in normal_deg, or nx, ny, or b, r1, r2"
        ))
    } else {
        ValueProblem::Number(e)
    }
}

/// A stream of cases.
pub struct Batch {
    /// Whether the input gives a general tensor (so the default columns are m11, m12, m22).
    pub general: bool,
    /// In the plane: the sweep whose parameters each row gives, and those parameters in the
    /// order each row holds them.
    pub plane: Option<(PlaneSweep, Vec<Knob>)>,
    rows: Box<dyn Iterator<Item = Result<(u64, Case), RowError>>>,
    /// An error ended the input.
    ended: bool,
}

impl Batch {
    fn new(
        layout: Option<&Layout>,
        rows: Box<dyn Iterator<Item = Result<(u64, Case), RowError>>>,
    ) -> Batch {
        Batch {
            general: matches!(layout, Some(Layout::Line(l)) if l.general),
            plane: match layout {
                Some(Layout::Plane(p)) => {
                    Some((p.base(), p.params.iter().map(|(k, _, _)| *k).collect()))
                }
                _ => None,
            },
            rows,
            ended: false,
        }
    }

    /// The cases on a line (a case in the plane, which a batch on a line never holds, is an
    /// error row).
    pub fn on_a_line(self) -> impl Iterator<Item = Result<(u64, RowCase), RowError>> {
        self.map(|r| {
            r.and_then(|(line, case)| match case {
                Case::Line(c) => Ok((line, c)),
                Case::Plane(_) => Err(RowError {
                    place: format!("line {line}"),
                    problem: RowProblem::OtherLayout,
                }),
            })
        })
    }

    /// The cases in the plane, as the parameters of a sweep's point.
    pub fn in_the_plane(self) -> impl Iterator<Item = super::runs::Point> {
        self.map(|r| {
            r.and_then(|(line, case)| match case {
                Case::Plane(p) => Ok((line, p)),
                Case::Line(_) => Err(RowError {
                    place: format!("line {line}"),
                    problem: RowProblem::OtherLayout,
                }),
            })
        })
    }
}

impl Iterator for Batch {
    type Item = Result<(u64, Case), RowError>;
    /// The next row; nothing more after an error that ends the input ([`RowProblem::Read`]).
    fn next(&mut self) -> Option<Self::Item> {
        if self.ended {
            return None;
        }
        let next = self.rows.next();
        if let Some(Err(e)) = &next {
            self.ended = e.problem.ends_input();
        }
        next
    }
}

/// Opens `path` (`None` or `-`: stdin). `default_e` is used where a row has no `e`.
pub fn open(
    path: Option<&Path>,
    format: Option<InputFormat>,
    default_e: f64,
) -> Result<Batch, BatchError> {
    let (reader, name): (Box<dyn Read>, String) = match path {
        None => (Box::new(io::stdin()), "stdin".into()),
        Some(p) if p == Path::new("-") => (Box::new(io::stdin()), "stdin".into()),
        Some(p) => (
            Box::new(File::open(p).map_err(|error| BatchError::Read {
                name: p.display().to_string(),
                error,
            })?),
            p.display().to_string(),
        ),
    };
    let mut reader = BufReader::with_capacity(
        1 << 20,
        LineCap {
            inner: reader,
            run: 0,
        },
    );
    let read_error = |error| BatchError::Read {
        name: name.clone(),
        error,
    };
    // A byte-order mark (as some editors write) is no part of the first line.
    if reader
        .fill_buf()
        .map_err(read_error)?
        .starts_with(b"\xEF\xBB\xBF")
    {
        reader.consume(3);
    }
    let format = match format {
        Some(f) => f,
        None => match path.and_then(|p| p.extension()).and_then(|e| e.to_str()) {
            Some("jsonl" | "ndjson") => InputFormat::Jsonl,
            Some("csv") => InputFormat::Csv,
            _ => {
                let head = reader.fill_buf().map_err(read_error)?;
                let first = head.iter().find(|b| !b.is_ascii_whitespace());
                if first == Some(&b'{') {
                    InputFormat::Jsonl
                } else {
                    InputFormat::Csv
                }
            }
        },
    };
    match format {
        InputFormat::Csv => csv_rows(reader, &name, default_e),
        InputFormat::Jsonl => jsonl_rows(reader, &name, default_e),
    }
}

fn csv_rows(reader: impl Read + 'static, name: &str, default_e: f64) -> Result<Batch, BatchError> {
    let mut r = csv::ReaderBuilder::new()
        .trim(csv::Trim::All)
        .flexible(true)
        .from_reader(reader);
    let header: Vec<String> = r
        .headers()
        .map_err(|error| BatchError::Header {
            name: name.to_string(),
            error,
        })?
        .iter()
        .map(String::from)
        .collect();
    // An empty input (no header, no rows): a table of no rows, as an empty JSON Lines input.
    if header.is_empty() {
        return Ok(Batch::new(None, Box::new(std::iter::empty())));
    }
    let layout = Layout::of(&header).map_err(|e| BatchError::Layout {
        name: name.to_string(),
        place: "line 1 (header)".into(),
        problem: e.into(),
    })?;
    let shell = Batch::new(Some(&layout), Box::new(std::iter::empty()));
    let rows = r.into_records().map(move |rec| {
        let rec = rec.map_err(|e| RowError {
            place: format!("line {}", e.position().map_or(0, |p| p.line())),
            problem: if e.is_io_error() {
                RowProblem::Unreadable(e.to_string())
            } else {
                RowProblem::NotCsv(e.to_string())
            },
        })?;
        let line = rec.position().map_or(0, |p| p.line());
        if rec.len() != header.len() {
            return Err(RowError {
                place: format!("line {line}"),
                problem: RowProblem::FieldCount {
                    got: rec.len(),
                    named: header.len(),
                },
            });
        }
        layout.case(|i| rec.get(i), line, default_e)
    });
    Ok(Batch {
        rows: Box::new(rows),
        ..shell
    })
}

fn jsonl_rows(
    reader: impl BufRead + 'static,
    name: &str,
    default_e: f64,
) -> Result<Batch, BatchError> {
    // Lines as bytes, each decoded on its own: a line that is not UTF-8 is a bad row at its
    // line, not the end of the input.
    let mut lines = reader.split(b'\n').enumerate().map(|(i, bytes)| {
        let line = bytes
            .map_err(|e| RowProblem::Unreadable(e.to_string()))
            .and_then(|mut b| {
                if b.last() == Some(&b'\r') {
                    b.pop();
                }
                String::from_utf8(b).map_err(|e| {
                    RowProblem::Read(format!(
                        "the line is not valid UTF-8 (bad byte at column {})",
                        e.utf8_error().valid_up_to() + 1
                    ))
                })
            });
        (i, line)
    });
    // The first readable object decides the layout; every object must have the same keys.
    let mut layout: Option<Layout> = None;
    let mut head = Vec::new();
    for (i, l) in lines.by_ref() {
        let at = |problem: RowProblem| BatchError::Layout {
            name: name.to_string(),
            place: format!("line {}", i + 1),
            problem,
        };
        // A read error ends the input (it looped for ever on a directory).
        let first = match &l {
            Ok(text) if !text.trim().is_empty() => Some(text.clone()),
            Err(e) if e.ends_input() => return Err(at(e.clone())),
            _ => None,
        };
        head.push((i, l));
        let Some(first) = first else { continue };
        let keys = object(&first)
            .map(|o| o.into_iter().map(|(k, _)| k).collect::<Vec<_>>())
            .map_err(at)?;
        layout = Some(Layout::of(&keys).map_err(|e| at(e.into()))?);
        break;
    }
    let shell = Batch::new(layout.as_ref(), Box::new(std::iter::empty()));
    let lines = head.into_iter().chain(lines);
    let rows = lines.filter_map(move |(i, l)| {
        let line = i as u64 + 1;
        let err = |problem: RowProblem| RowError {
            place: format!("line {line}"),
            problem,
        };
        let l = match l {
            Ok(l) => l,
            Err(e) => return Some(Err(err(e))),
        };
        if l.trim().is_empty() {
            return None;
        }
        let layout = layout.as_ref()?;
        Some((|| {
            let (keys, values): (Vec<String>, Vec<String>) =
                object(&l).map_err(err)?.into_iter().unzip();
            let this = Layout::of(&keys).map_err(|e| err(e.into()))?;
            if !this.same_kind(layout) {
                return Err(err(RowProblem::OtherLayout));
            }
            this.case(|k| values.get(k).map(String::as_str), line, default_e)
        })())
    });
    Ok(Batch {
        rows: Box::new(rows),
        ..shell
    })
}

/// A JSON object of numbers (or strings holding numbers), as text, its keys in order (a key
/// given twice is refused by `Layout::of`: JSON readers differ on which value they keep).
fn object(line: &str) -> Result<Vec<(String, String)>, RowProblem> {
    let Fields(fields) =
        serde_json::from_str(line).map_err(|e| RowProblem::NotJson(e.to_string()))?;
    fields
        .ok_or(RowProblem::NotObject)?
        .into_iter()
        .map(|(k, v)| match v {
            serde_json::Value::Number(n) => Ok((k, n.to_string())),
            serde_json::Value::String(s) => Ok((k, s)),
            other => Err(RowProblem::NotNumber(k, other.to_string())),
        })
        .collect()
}

/// A JSON value read as an object's fields in order, every one kept (`serde_json::Map` keeps
/// the last of a key given twice); `None` for a value that is not an object.
struct Fields(Option<Vec<(String, serde_json::Value)>>);

impl<'de> serde::Deserialize<'de> for Fields {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Fields, D::Error> {
        d.deserialize_any(FieldsVisitor)
    }
}

struct FieldsVisitor;

impl<'de> serde::de::Visitor<'de> for FieldsVisitor {
    type Value = Fields;

    fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        f.write_str("a JSON value")
    }

    fn visit_map<A: serde::de::MapAccess<'de>>(self, mut map: A) -> Result<Fields, A::Error> {
        let mut fields = Vec::new();
        while let Some(field) = map.next_entry()? {
            fields.push(field);
        }
        Ok(Fields(Some(fields)))
    }

    fn visit_seq<A: serde::de::SeqAccess<'de>>(self, mut seq: A) -> Result<Fields, A::Error> {
        while seq.next_element::<serde::de::IgnoredAny>()?.is_some() {}
        Ok(Fields(None))
    }

    fn visit_bool<E>(self, _: bool) -> Result<Fields, E> {
        Ok(Fields(None))
    }

    fn visit_i64<E>(self, _: i64) -> Result<Fields, E> {
        Ok(Fields(None))
    }

    fn visit_u64<E>(self, _: u64) -> Result<Fields, E> {
        Ok(Fields(None))
    }

    fn visit_f64<E>(self, _: f64) -> Result<Fields, E> {
        Ok(Fields(None))
    }

    fn visit_str<E>(self, _: &str) -> Result<Fields, E> {
        Ok(Fields(None))
    }

    fn visit_unit<E>(self) -> Result<Fields, E> {
        Ok(Fields(None))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn read(text: &str, format: InputFormat) -> Vec<Result<(u64, RowCase), RowError>> {
        static N: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
        let n = N.fetch_add(1, std::sync::atomic::Ordering::SeqCst);
        let path = std::env::temp_dir().join(format!("collide-batch-{}-{n}", std::process::id()));
        std::fs::write(&path, text).unwrap();
        let rows: Vec<_> = open(Some(&path), Some(format), 1.0)
            .unwrap()
            .on_a_line()
            .collect();
        std::fs::remove_file(&path).ok();
        rows
    }

    #[test]
    fn csv_with_and_without_e() {
        let rows = read("m1,m2,v1,v2\n4,1,60,10\n6, 1, 3, -4\n", InputFormat::Csv);
        assert_eq!(rows.len(), 2);
        let (line, c) = rows[1].clone().unwrap();
        assert_eq!(
            (line, c.m11, c.m22, c.v, c.e),
            (3, 6.0, 1.0, [3.0, -4.0], 1.0)
        );
        let rows = read("v1,v2,e,m2,m1\n3,-4,2/3,1,6\n", InputFormat::Csv);
        assert_eq!(rows[0].clone().unwrap().1.e, 2.0 / 3.0);
    }

    #[test]
    fn bad_rows_name_line_and_field() {
        let rows = read(
            "m1,m2,v1,v2\n4,1,60,10\n4,-1,60,10\n4,1,x,10\n4,1\n",
            InputFormat::Csv,
        );
        let e = rows[1].clone().unwrap_err();
        assert_eq!(
            e.to_string(),
            "line 3: field 'm2': mass '-1' must be greater than 0"
        );
        assert!(
            rows[2]
                .clone()
                .unwrap_err()
                .to_string()
                .starts_with("line 4: field 'v1': 'x' is not a number")
        );
        assert!(
            rows[3]
                .clone()
                .unwrap_err()
                .to_string()
                .starts_with("line 5: 2 fields")
        );
    }

    #[test]
    fn jsonl_rows() {
        let rows = read(
            "{\"m1\": 4, \"m2\": 1, \"v1\": 60, \"v2\": 10}\n\n{\"m1\": \"6\", \"m2\": 1, \"v1\": 3, \"v2\": -4, \"e\": \"2/3\"}\n{\"m1\": 1}\n",
            InputFormat::Jsonl,
        );
        assert_eq!(rows.len(), 3);
        assert_eq!(rows[1].clone().unwrap().0, 3);
        assert_eq!(rows[1].clone().unwrap().1.e, 2.0 / 3.0);
        assert!(
            rows[2]
                .clone()
                .unwrap_err()
                .to_string()
                .contains("line 4: missing column 'm2'")
        );
    }

    #[test]
    fn headers_are_checked() {
        let path = std::env::temp_dir().join(format!("collide-batch-h-{}", std::process::id()));
        std::fs::write(&path, "m1,m2,v1,speed\n").unwrap();
        let e = open(Some(&path), Some(InputFormat::Csv), 1.0)
            .err()
            .unwrap()
            .to_string();
        assert!(e.contains("unknown column 'speed'"), "{e}");
        std::fs::remove_file(&path).ok();
    }
}
