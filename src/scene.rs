//! Scene files: a case in TOML, with the sections to show and the numbers to expect.
//!
//! ```toml
//! title = "60 mph 4-ton SUV rear-ends 10 mph 1-ton VW"
//! masses = [4, 1]
//! velocities = [60, 10]
//! restitution = "elastic"
//! show = ["vectors", "energy"]
//! [expect]
//! fin = [40, 90]
//! "energy.crunch" = 1000
//! "ellipses.com.a" = { value = 55.90, abs = 0.005 }
//! ```
//! Every problem (unknown key, wrong type, bad value, missing field) is reported with the file,
//! line and column.

use std::collections::BTreeMap;
use std::fmt;
use std::ops::Range;
use std::path::{Path, PathBuf};

use serde::Deserialize;
use toml::Spanned;

use crate::case::Case;
use crate::contact::{Damping, LawKind, Laws, Method, Settings, Setup};
use crate::expect::{ExpectError, Expectation};
use crate::frame::Frame;
use crate::inertia::InertiaTensor;
use crate::number::{Given, Number, NumberError};
use crate::problem::{Posed, Problem};
use crate::report::special::Special;
use crate::report::{Section, Sections};
use crate::restitution::{Restitution, RestitutionError};
use crate::separation::Separation;
use crate::table::columns::Column;
use crate::table::sweep::{DEFAULT_MAX_ROWS, Grid};
use crate::table::writer::RowFormat;
use crate::track::{Limits, Track};
use crate::units::{Dimension, Pair, PairError, parse_pair};
use crate::unknowns::Solved;
use crate::wall::WallCase;

/// The file as written. Field names are the scene format.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct SceneFile {
    title: Option<String>,
    source: Option<String>,
    masses: Option<Spanned<Two<Typed>>>,
    inertia: Option<Spanned<Two<Two<Number>>>>,
    velocities: Spanned<Two<Typed>>,
    fin: Option<Spanned<Two<Typed>>>,
    restitution: Option<Spanned<Typed>>,
    si: Option<bool>,
    gravity: Option<Number>,
    energy_unit: Option<Spanned<String>>,
    show: Option<Vec<Section>>,
    contact_time: Option<Spanned<String>>,
    exact: Option<bool>,
    frame: Option<Frame>,
    sweep: Option<Spanned<SweepTable>>,
    plot: Option<PlotTable>,
    expect: Option<ExpectTable>,
}

/// `[plot]`: draw the scene's case to an SVG file.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PlotTable {
    /// The SVG file, relative to the scene file's folder (resolved when the scene is loaded).
    pub output: PathBuf,
    /// velocity (default), newton or minkowski.
    #[serde(default = "velocity")]
    pub kind: crate::plot::Kind,
    /// Overlay the standard frames (lecture Fig. 2.5).
    #[serde(default)]
    pub frames: bool,
}

fn velocity() -> crate::plot::Kind {
    crate::plot::Kind::Velocity
}

/// `[sweep]`: the scene's case is the base of a table.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct SweepTable {
    vary: Vec<String>,
    columns: Option<Vec<String>>,
    format: Option<RowFormat>,
    max_rows: Option<u64>,
    skip_bad: Option<bool>,
}

/// A scene's sweep, validated.
#[derive(Clone, Debug)]
pub struct SceneSweep {
    pub grid: Grid,
    pub columns: Vec<&'static Column>,
    pub format: RowFormat,
    pub skip_bad: bool,
}

/// A value as typed in a scene: a number, a string with a unit (`"4 t"`), or `"?"`.
#[derive(Clone, Debug)]
struct Typed(String);

impl std::str::FromStr for Typed {
    type Err = std::convert::Infallible;
    fn from_str(s: &str) -> Result<Typed, Self::Err> {
        Ok(Typed(s.to_string()))
    }
}

impl<'de> Deserialize<'de> for Typed {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Typed, D::Error> {
        crate::number::deserialize_parsed(
            d,
            "a number, a string with a unit such as \"4 t\", or \"?\"",
        )
    }
}

fn pair(Two(v): &Two<Typed>, dimension: Dimension, what: &str) -> Result<Pair, PairError> {
    parse_pair(&format!("{},{}", v[0].0, v[1].0), dimension, what)
}

/// Exactly two values (`[60, 10]`): a longer or shorter array is an error at its line.
#[derive(Clone, Debug)]
struct Two<T>([T; 2]);

impl<'de, T: Deserialize<'de>> Deserialize<'de> for Two<T> {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Two<T>, D::Error> {
        let v = Vec::<T>::deserialize(d)?;
        let n = v.len();
        <[T; 2]>::try_from(v)
            .map(Two)
            .map_err(|_| serde::de::Error::invalid_length(n, &"exactly 2 values"))
    }
}

/// What every scene has besides its physics: where it is, what it is called, and the numbers it
/// expects.
#[derive(Clone, Debug)]
pub struct About {
    pub path: PathBuf,
    pub title: Option<String>,
    pub source: Option<String>,
    pub expect: Vec<Expectation>,
}

/// Largest scene file read (`/dev/zero` or a stray binary is refused, not read forever).
pub const MAX_SCENE_BYTES: u64 = 1 << 20;

/// A scene file's text, at most [`MAX_SCENE_BYTES`].
fn read_capped(path: &Path) -> Result<String, String> {
    use std::io::Read;
    let file = std::fs::File::open(path).map_err(|e| format!("cannot read scene file: {e}"))?;
    let mut bytes = Vec::new();
    file.take(MAX_SCENE_BYTES + 1)
        .read_to_end(&mut bytes)
        .map_err(|e| format!("cannot read scene file: {e}"))?;
    if bytes.len() as u64 > MAX_SCENE_BYTES {
        return Err(format!(
            "the scene file is larger than {} bytes (1 MiB): a scene is a short TOML file",
            MAX_SCENE_BYTES
        ));
    }
    String::from_utf8(bytes).map_err(|e| {
        format!(
            "the scene file is not UTF-8 text (invalid byte at offset {})",
            e.utf8_error().valid_up_to()
        )
    })
}

/// Text with its control characters escaped (`\u{1b}`): a shared scene cannot send escape
/// sequences to a terminal.
fn printable(text: &str) -> String {
    crate::number::printable(text)
}

/// `[expect]` as written: JSON paths of the report, each with its value and place.
type ExpectTable = BTreeMap<String, Spanned<toml::Value>>;

impl About {
    /// `known` says whether a key's first part names a quantity of the scene's report.
    fn new(
        (path, text): (&Path, &str),
        title: Option<String>,
        source: Option<String>,
        table: Option<ExpectTable>,
        known: impl Fn(&str) -> Result<(), ExpectError>,
    ) -> Result<About, SceneError> {
        let mut expect = Vec::new();
        for (key, value) in table.unwrap_or_default() {
            let span = value.span();
            let e = known(key.split('.').next().unwrap_or_default())
                .and_then(|()| Expectation::from_toml(&key, value.into_inner()))
                .map_err(|m| {
                    located(
                        path,
                        text,
                        Some(span.clone()),
                        format!("[expect] \"{key}\": {m}"),
                    )
                })?;
            expect.push(e.at_line(line_col(text, span.start).0));
        }
        Ok(About {
            path: path.to_path_buf(),
            title: title.as_deref().map(printable),
            source: source.as_deref().map(printable),
            expect,
        })
    }
}

/// A problem at `span` of a scene file's `text`.
fn located(path: &Path, text: &str, span: Option<Range<usize>>, message: String) -> SceneError {
    SceneError {
        path: path.to_path_buf(),
        at: span.map(|s| line_col(text, s.start)),
        message,
    }
}

/// The file's text as `T`, or the first problem, located.
fn from_toml<T: serde::de::DeserializeOwned>(path: &Path, text: &str) -> Result<T, SceneError> {
    let value = toml::from_str(text)
        .map_err(|e| located(path, text, e.span(), e.message().trim().to_string()))?;
    // The TOML reader rounds `1e-400` to 0 and `1e400` to inf before we see it: the number
    // literals are checked as written, by the same rule as the command line.
    for (at, literal) in toml_numbers(text) {
        let digits = literal.replace('_', "");
        if let Err(
            e
            @ (NumberError::Overflow(_) | NumberError::Underflow(_) | NumberError::TooLong { .. }),
        ) = digits.parse::<Number>()
        {
            return Err(located(
                path,
                text,
                Some(at..at + literal.len()),
                e.to_string(),
            ));
        }
    }
    Ok(value)
}

/// The number literals of a TOML text with their byte offsets: runs of number characters that
/// start a value (a digit, or a sign or `.` before one), outside strings and comments.
fn toml_numbers(text: &str) -> Vec<(usize, &str)> {
    let b = text.as_bytes();
    let mut out = Vec::new();
    let mut i = 0;
    let word = |c: u8| c.is_ascii_alphanumeric() || matches!(c, b'_' | b'.' | b'+' | b'-' | b':');
    while i < b.len() {
        match b[i] {
            b'#' => {
                while i < b.len() && b[i] != b'\n' {
                    i += 1;
                }
            }
            q @ (b'"' | b'\'') => {
                let triple = b[i..].starts_with(&[q, q, q]);
                i += if triple { 3 } else { 1 };
                while i < b.len() {
                    if q == b'"' && b[i] == b'\\' {
                        i += 2;
                        continue;
                    }
                    if triple && b[i..].starts_with(&[q, q, q]) {
                        i += 3;
                        break;
                    }
                    if !triple && (b[i] == q || b[i] == b'\n') {
                        i += 1;
                        break;
                    }
                    i += 1;
                }
            }
            c if word(c) => {
                let start = i;
                while i < b.len() && word(b[i]) {
                    i += 1;
                }
                let run = &text[start..i];
                let first_digit = run
                    .trim_start_matches(['+', '-', '.'])
                    .starts_with(|c: char| c.is_ascii_digit());
                if first_digit && !run.contains(':') {
                    out.push((start, run));
                }
            }
            _ => i += 1,
        }
    }
    out
}

/// A loaded, validated scene.
#[derive(Clone, Debug)]
pub struct Scene {
    pub about: About,
    pub case: Case,
    /// Sections to print.
    pub show: Sections,
    /// Exact rational arithmetic (`exact = true`).
    pub exact: bool,
    /// The frame to see the collision from (`frame = "com"`).
    pub frame: Frame,
    /// A table over a grid of parameters instead of a single case (`[sweep]`).
    pub sweep: Option<SceneSweep>,
    /// A picture to draw (`[plot]`).
    pub plot: Option<PlotTable>,
    /// What was solved for (`"?"` values, or `fin` given).
    pub solved: Option<Solved>,
}

/// A two-body scene that is not a collision of two movable bodies: a separation (the bodies
/// start together and are pushed apart, `e` undefined) or a ball against a wall.
#[derive(Clone, Debug)]
pub struct SpecialScene {
    pub about: About,
    pub event: SpecialEvent,
    pub solved: Option<Solved>,
    pub show: Sections,
    pub exact: bool,
}

/// The event of a `SpecialScene`.
#[derive(Clone, Debug)]
pub enum SpecialEvent {
    Separation(Separation),
    Wall(WallCase),
}

impl SpecialEvent {
    pub fn special(&self) -> Special<'_> {
        match self {
            SpecialEvent::Separation(s) => Special::Separation(s),
            SpecialEvent::Wall(w) => Special::Wall(w),
        }
    }
}

/// A scene file of either kind.
#[derive(Clone, Debug)]
#[allow(clippy::large_enum_variant)] // one per file, loaded once
pub enum AnyScene {
    Case(Scene),
    Special(SpecialScene),
    Track(TrackScene),
    Contact(ContactScene),
}

/// A problem in a scene file, located.
#[derive(Clone, Debug, PartialEq)]
pub struct SceneError {
    pub path: PathBuf,
    /// 1-based line and column, when known.
    pub at: Option<(usize, usize)>,
    pub message: String,
}

impl fmt::Display for SceneError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.at {
            Some((line, col)) => {
                write!(f, "{}:{line}:{col}: {}", self.path.display(), self.message)
            }
            None => write!(f, "{}: {}", self.path.display(), self.message),
        }
    }
}

impl std::error::Error for SceneError {}

/// 1-based line and column of byte offset `at` in `text`.
pub fn line_col(text: &str, at: usize) -> (usize, usize) {
    let before = &text[..at.min(text.len())];
    let line = before.matches('\n').count() + 1;
    let col = before.rsplit('\n').next().map_or(0, |l| l.chars().count()) + 1;
    (line, col)
}

impl Scene {
    /// Reads a scene of any kind: a two-body case (or `[sweep]`), a `[track]` or a `[contact]`.
    pub fn load_any(path: &Path) -> Result<AnyScene, SceneError> {
        let text = read_capped(path).map_err(|message| SceneError {
            path: path.to_path_buf(),
            at: None,
            message,
        })?;
        if has_table(&text, "contact") {
            ContactScene::parse(path, &text).map(AnyScene::Contact)
        } else if has_table(&text, "track") {
            TrackScene::parse(path, &text).map(AnyScene::Track)
        } else {
            Scene::parse_any(path, &text)
        }
    }

    /// Parses the text of a two-body scene (a collision); `path` names it in errors.
    pub fn parse(path: &Path, text: &str) -> Result<Scene, SceneError> {
        match Scene::parse_any(path, text)? {
            AnyScene::Case(scene) => Ok(scene),
            _ => Err(located(
                path,
                text,
                None,
                "the bodies start together and come apart: a separation, not a collision".into(),
            )),
        }
    }

    /// Parses the text of a two-body scene: a collision, or a separation.
    fn parse_any(path: &Path, text: &str) -> Result<AnyScene, SceneError> {
        let err = |span: Option<Range<usize>>, message: String| located(path, text, span, message);
        let file: SceneFile = from_toml(path, text)?;
        let masses = match (&file.masses, &file.inertia) {
            (Some(_), Some(t)) => {
                return Err(err(
                    Some(t.span()),
                    "give either `masses` or `inertia`, not both".into(),
                ));
            }
            (None, None) => {
                return Err(err(
                    None,
                    "missing `masses = [M1, M2]` (or `inertia = [[M11, M12], [M21, M22]]`)".into(),
                ));
            }
            (Some(m), None) => Some(
                pair(m.get_ref(), Dimension::Mass, "masses")
                    .map_err(|e| err(Some(m.span()), e.to_string()))?,
            ),
            (None, Some(_)) => None,
        };
        let inertia = match &file.inertia {
            Some(t) => Some(
                InertiaTensor::general({
                    let Two([Two(a), Two(b)]) = t.get_ref().clone();
                    [a, b]
                })
                .map_err(|e| err(Some(t.span()), format!("inertia: {e}")))?,
            ),
            None => None,
        };
        let v = &file.velocities;
        let velocities = pair(v.get_ref(), Dimension::Velocity, "velocities")
            .map_err(|e| err(Some(v.span()), e.to_string()))?;
        let fin = match &file.fin {
            Some(f) => Some(
                pair(f.get_ref(), Dimension::Velocity, "fin")
                    .map_err(|e| err(Some(f.span()), e.to_string()))?,
            ),
            None => None,
        };
        let restitution = match &file.restitution {
            None => None,
            Some(r) => Some(
                Given::parse(&r.get_ref().0, str::parse::<Restitution>)
                    .map_err(|e| err(Some(r.span()), e.to_string()))?,
            ),
        };
        let problem = Problem {
            masses,
            velocities,
            fin,
            restitution,
            si: file.si.unwrap_or(false),
            gravity: file.gravity.clone(),
            energy_unit: match &file.energy_unit {
                Some(u) => Some(
                    crate::units::energy_unit(u.get_ref())
                        .map_err(|e| err(Some(u.span()), e.to_string()))?,
                ),
                None => None,
            },
            exact: file.exact.unwrap_or(false),
        };
        let span = file
            .masses
            .as_ref()
            .map(|m| m.span())
            .or(file.inertia.as_ref().map(|t| t.span()));
        let posed = problem
            .solve(inertia)
            .map_err(|e| err(span, format!("{e:#}")))?;
        let contact_time = match &file.contact_time {
            None => None,
            Some(t) => Some(
                crate::units::seconds(t.get_ref())
                    .map_err(|e| err(Some(t.span()), format!("contact_time: {e}")))?,
            ),
        };
        let mut show = Sections::new(file.show.unwrap_or_else(|| Section::DEFAULT.to_vec()));
        show.contact_time = contact_time;
        let units = posed.units().clone();
        show.heights = Some(crate::units::HeightScale::new(
            file.gravity.as_ref(),
            &units,
        ));
        let (case, solved) = match posed {
            Posed::Collision(case, solved) => (case, solved),
            Posed::Separation(..) | Posed::Wall(..) => {
                let extra = [
                    file.sweep.as_ref().map(|_| "[sweep]"),
                    file.plot.as_ref().map(|_| "[plot]"),
                    file.frame
                        .as_ref()
                        .filter(|f| **f != Frame::Lab)
                        .map(|_| "frame"),
                ];
                if let Some(key) = extra.into_iter().flatten().next() {
                    return Err(err(
                        None,
                        format!(
                            "{key}: a separation (bodies starting together) or a wall has no {key}"
                        ),
                    ));
                }
                let (event, solved, keys): (_, _, KeyCheck) = match posed {
                    Posed::Separation(s, solved) => {
                        (SpecialEvent::Separation(s), Some(solved), separation_key)
                    }
                    Posed::Wall(w, solved) => (SpecialEvent::Wall(w), solved, wall_key),
                    Posed::Collision(..) => unreachable!("matched above"),
                };
                let about = About::new((path, text), file.title, file.source, file.expect, keys)?;
                return Ok(AnyScene::Special(SpecialScene {
                    about,
                    event,
                    solved,
                    show,
                    exact: file.exact.unwrap_or(false),
                }));
            }
        };
        let sweep = match file.sweep {
            None => None,
            Some(t) => {
                let span = t.span();
                let t = t.into_inner();
                let at = |m: &dyn fmt::Display| err(Some(span.clone()), format!("[sweep] {m}"));
                if file.expect.is_some() {
                    return Err(at(
                        &"a scene with [sweep] writes a table; it cannot have [expect]",
                    ));
                }
                let vary = t
                    .vary
                    .iter()
                    .map(|v| v.parse())
                    .collect::<Result<Vec<_>, _>>()
                    .map_err(|e| at(&e))?;
                let grid =
                    Grid::new(vary, t.max_rows.unwrap_or(DEFAULT_MAX_ROWS)).map_err(|e| at(&e))?;
                let columns = t
                    .columns
                    .unwrap_or_default()
                    .iter()
                    .map(|c| c.parse())
                    .collect::<Result<Vec<&Column>, _>>()
                    .map_err(|e| at(&e))?;
                Some(SceneSweep {
                    grid,
                    columns,
                    format: t.format.unwrap_or(RowFormat::Csv),
                    skip_bad: t.skip_bad.unwrap_or(false),
                })
            }
        };
        let about = About::new(
            (path, text),
            file.title,
            file.source,
            file.expect,
            report_key,
        )?;
        Ok(AnyScene::Case(Scene {
            about,
            case,
            show,
            exact: file.exact.unwrap_or(false),
            frame: file.frame.unwrap_or(Frame::Lab),
            sweep,
            plot: match file.plot {
                Some(p) => {
                    Some(confine_plot(path, p).map_err(|m| err(None, format!("[plot] {m}")))?)
                }
                None => None,
            },
            solved,
        }))
    }

    /// Sections to compute: the shown ones and those the expectations read.
    pub fn sections_needed(&self) -> Sections {
        let mut s = self.show.clone();
        for e in &self.about.expect {
            if let Some(section) = Section::of_json_key(e.key.split('.').next().unwrap_or_default())
            {
                s.insert(section);
            }
        }
        s
    }
}

/// The quantities an `[expect]` key of a two-body scene may name.
const TOP_LEVEL: &str = "in, com, fin, v_com, restitution, inertia, frame.w, momentum.*, forms.*, \
                         energy.*, ellipses.*, products.*, changes.*, heights.*, diagnostics.*, \
                         solved.*, check.*, units.*";

/// A scene's picture goes beside the scene (a relative `output` is resolved against the scene
/// file's folder), must be an `.svg`, and may replace only an SVG file: scenes are shared as
/// graders, and one must not be able to overwrite a user's other files.
fn confine_plot(scene: &Path, mut p: PlotTable) -> Result<PlotTable, String> {
    if p.output.is_relative() {
        let folder = scene.parent().unwrap_or(Path::new(""));
        p.output = folder.join(&p.output);
    }
    let shown = p.output.display().to_string();
    if p.output
        .extension()
        .is_none_or(|x| !x.eq_ignore_ascii_case("svg"))
    {
        return Err(format!("output '{shown}' must be an .svg file"));
    }
    if let Ok(meta) = std::fs::symlink_metadata(&p.output) {
        let svg = meta.is_file()
            && std::fs::read(&p.output).is_ok_and(|bytes| {
                let head = String::from_utf8_lossy(&bytes[..bytes.len().min(512)]).into_owned();
                let head = head.trim_start();
                head.starts_with("<svg") || (head.starts_with("<?xml") && head.contains("<svg"))
            });
        if !svg {
            return Err(format!(
                "output '{shown}' exists and is not an SVG picture: a scene replaces only its own \
                 pictures"
            ));
        }
    }
    Ok(p)
}

/// A check of an `[expect]` key's first part.
type KeyCheck = fn(&str) -> Result<(), ExpectError>;

/// `Ok` when `top` is one of `keys` (a report's top-level keys, `.*` for objects), else the
/// error listing them with `note`.
fn one_of(top: &str, keys: &[&str], note: &str) -> Result<(), ExpectError> {
    if keys.iter().any(|k| k.trim_end_matches(".*") == top) {
        return Ok(());
    }
    Err(ExpectError::UnknownQuantity {
        top: top.to_string(),
        expected: format!("{} {note}", keys.join(", ")),
    })
}

/// Checks that `top` names a quantity of a wall case's report.
fn wall_key(top: &str) -> Result<(), ExpectError> {
    let keys = [
        "wall",
        "restitution",
        "mass",
        "in",
        "fin",
        "approaching",
        "momentum.*",
        "energy.*",
        "changes.*",
        "heights.*",
        "solved.*",
        "check.*",
        "units.*",
    ];
    one_of(top, &keys, "(the ball's values)")
}

/// Checks that `top` names a quantity of a separation's report.
fn separation_key(top: &str) -> Result<(), ExpectError> {
    let keys = [
        "masses",
        "in",
        "com",
        "fin",
        "v_com",
        "momentum.*",
        "energy.*",
        "changes.*",
        "solved.*",
        "check.*",
        "units.*",
    ];
    one_of(
        top,
        &keys,
        "(a separation has no restitution, forms or ellipses)",
    )
}

/// Checks that `top`, the first part of an `[expect]` key, names a quantity of a two-body report.
fn report_key(top: &str) -> Result<(), ExpectError> {
    let always = [
        "restitution",
        "inertia",
        "frame",
        "solved",
        "check",
        "units",
    ];
    if Section::of_json_key(top).is_none() && !always.contains(&top) {
        return Err(ExpectError::UnknownQuantity {
            top: top.to_string(),
            expected: TOP_LEVEL.to_string(),
        });
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn parse(text: &str) -> Result<Scene, SceneError> {
        Scene::parse(Path::new("t.toml"), text)
    }

    #[test]
    fn a_lecture_scene() {
        let s = parse(
            "title = \"A\"\nmasses = [4, 1]\nvelocities = [60, 10]\nrestitution = \"2/3\"\n\
             [expect]\nfin = [40, 90]\n\"energy.crunch\" = { value = 1000, abs = 0.5 }\n",
        )
        .unwrap();
        assert_eq!(s.about.title.as_deref(), Some("A"));
        assert_eq!(s.case.restitution().value(), 2.0 / 3.0);
        assert_eq!(s.about.expect.len(), 2);
        assert!(s.sections_needed().contains(Section::Energy));
        assert!(s.sections_needed().contains(Section::Vectors));
        assert!(!s.sections_needed().contains(Section::Ellipses));
    }

    #[test]
    fn unknown_key_names_file_line_and_key() {
        let e = parse("masses = [4, 1]\nvelocities = [60, 10]\nelasticity = 1\n").unwrap_err();
        assert_eq!(e.at.map(|a| a.0), Some(3));
        assert!(e.to_string().starts_with("t.toml:3:"), "{e}");
        assert!(e.message.contains("elasticity"), "{e}");
    }

    #[test]
    fn bad_values_are_located() {
        let e = parse("masses = [4, -1]\nvelocities = [60, 10]\n").unwrap_err();
        assert_eq!(e.at.map(|a| a.0), Some(1));
        assert!(
            e.message.contains("'-1'") && e.message.contains("greater than 0"),
            "{e}"
        );
        let e = parse("masses = [4, 1]\nvelocities = [60, \"x\"]\n").unwrap_err();
        assert_eq!(e.at.map(|a| a.0), Some(2));
        assert!(e.message.contains("'x' is not a number"), "{e}");
        let e = parse("masses = [4, 1]\nvelocities = [60]\n").unwrap_err();
        assert_eq!(e.at.map(|a| a.0), Some(2), "{e}");
        let e = parse("masses = [4, 1]\nvelocities = [60, 1]\nrestitution = -2\n").unwrap_err();
        assert!(e.message.contains("negative"), "{e}");
        let e = parse("masses = [4, 1]\nvelocities = [60, 1]\nshow = [\"vectorz\"]\n").unwrap_err();
        assert!(e.message.contains("vectorz"), "{e}");
        let e = parse("masses = \"4,1\"\nvelocities = [60, 1]\n").unwrap_err();
        assert_eq!(e.at.map(|a| a.0), Some(1), "{e}");
    }

    #[test]
    fn missing_and_conflicting_fields() {
        let e = parse("masses = [4, 1]\n").unwrap_err();
        assert!(e.message.contains("velocities"), "{e}");
        let e = parse("velocities = [1, 2]\n").unwrap_err();
        assert!(e.message.contains("masses"), "{e}");
        let e = parse("masses = [4, 1]\ninertia = [[4, 0], [0, 1]]\nvelocities = [1, 2]\n")
            .unwrap_err();
        assert!(
            e.message.contains("not both") && e.at.unwrap().0 == 2,
            "{e}"
        );
        let e = parse("inertia = [[1, 2], [2, 1]]\nvelocities = [1, 2]\n").unwrap_err();
        assert!(e.message.contains("positive definite"), "{e}");
    }

    #[test]
    fn sweep_tables() {
        let s = parse("masses = [4, 1]\nvelocities = [60, 10]\n[sweep]\nvary = [\"e=0:1:11\"]\ncolumns = [\"e\", \"lost\"]\n")
            .unwrap();
        let sw = s.sweep.unwrap();
        assert_eq!(sw.grid.total, 11);
        assert_eq!(
            sw.columns,
            crate::table::columns::by_names(&["e", "lost"]).unwrap()
        );
        let e = parse("masses = [4, 1]\nvelocities = [60, 10]\n[sweep]\nvary = [\"e=-1:1:3\"]\n")
            .unwrap_err();
        assert!(
            e.message.contains("[sweep]") && e.message.contains("negative") && e.at.unwrap().0 == 3,
            "{e}"
        );
        let e = parse(
            "masses = [4, 1]\nvelocities = [60, 10]\n[sweep]\nvary = [\"e=0:1:3\"]\nrows = 3\n",
        )
        .unwrap_err();
        assert!(e.message.contains("unknown field `rows`"), "{e}");
    }

    #[test]
    fn expect_keys_must_name_a_quantity() {
        let e = parse("masses = [4, 1]\nvelocities = [60, 10]\n[expect]\n\"energyy.crunch\" = 1\n")
            .unwrap_err();
        assert!(e.message.contains("unknown quantity 'energyy'"), "{e}");
        assert_eq!(e.at.map(|a| a.0), Some(4));
        assert!(report_key("frame").is_ok());
    }

    #[test]
    fn line_and_column() {
        assert_eq!(line_col("ab\ncd", 0), (1, 1));
        assert_eq!(line_col("ab\ncd", 4), (2, 2));
    }
}

/// `[track]` in a scene: bodies on a track (`collide track`).
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct TrackFile {
    title: Option<String>,
    source: Option<String>,
    track: TrackTable,
    expect: Option<ExpectTable>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct TrackTable {
    masses: Spanned<Vec<Number>>,
    positions: Spanned<Vec<Number>>,
    velocities: Spanned<Vec<Number>>,
    sizes: Option<Spanned<Vec<Number>>>,
    left_wall: Option<Number>,
    right_wall: Option<Number>,
    restitution: Option<Restitution>,
    wall_restitution: Option<Restitution>,
    gravity: Option<Number>,
    until: Option<Number>,
    max_collisions: Option<u64>,
}

/// A track scene, validated.
#[derive(Clone, Debug)]
pub struct TrackScene {
    pub about: About,
    pub track: Track,
    pub limits: Limits,
}

/// Top-level keys of `collide track --format json`.
pub const TRACK_KEYS: [&str; 11] = [
    "collisions",
    "pair_collisions",
    "wall_collisions",
    "simultaneous",
    "time",
    "x",
    "v",
    "stop",
    "momentum",
    "energy",
    "pi",
];

/// Whether scene text holds a table `name` (`[track]`, `[contact]`).
pub fn has_table(text: &str, name: &str) -> bool {
    toml::from_str::<toml::Table>(text).is_ok_and(|t| t.contains_key(name))
}

impl TrackScene {
    pub fn parse(path: &Path, text: &str) -> Result<TrackScene, SceneError> {
        let err = |span: Option<Range<usize>>, message: String| located(path, text, span, message);
        let file: TrackFile = from_toml(path, text)?;
        let t = file.track;
        let bodies = layout(
            (path, text),
            "track",
            [&t.masses, &t.positions, &t.velocities],
            t.sizes.as_ref(),
        )?;
        for r in [&t.restitution, &t.wall_restitution].into_iter().flatten() {
            if r.is_superelastic() {
                let e = RestitutionError::Superelastic(r.to_string());
                return Err(err(None, format!("[track] {e}")));
            }
        }
        let e = t.restitution.unwrap_or_else(Restitution::elastic).value();
        let track = Track {
            bodies,
            left_wall: t.left_wall.map(|n| n.value()),
            right_wall: t.right_wall.map(|n| n.value()),
            e,
            e_wall: t.wall_restitution.map_or(e, |r| r.value()),
            gravity: t.gravity.map_or(0.0, |g| g.value()),
        };
        track
            .check()
            .map_err(|e| err(Some(t.masses.span()), format!("[track] {e}")))?;
        let limits = Limits {
            until: t.until.map(|u| u.value()),
            max_collisions: t
                .max_collisions
                .unwrap_or(crate::track::DEFAULT_MAX_COLLISIONS),
        };
        limits
            .check()
            .map_err(|e| err(None, format!("[track] {e}")))?;
        let about = About::new(
            (path, text),
            file.title,
            file.source,
            file.expect,
            among(&TRACK_KEYS),
        )?;
        Ok(TrackScene {
            about,
            track,
            limits,
        })
    }
}

/// `[expect]` keys of a report whose top-level keys are `keys`.
fn among(keys: &'static [&'static str]) -> impl Fn(&str) -> Result<(), ExpectError> {
    move |top| {
        if keys.contains(&top) {
            Ok(())
        } else {
            Err(ExpectError::UnknownQuantity {
                top: top.to_string(),
                expected: keys.join(", "),
            })
        }
    }
}

/// The bodies of a `[track]` or `[contact]` table, with a miscount or a bad body located.
fn layout(
    (path, text): (&Path, &str),
    table: &str,
    [masses, positions, velocities]: [&Spanned<Vec<Number>>; 3],
    sizes: Option<&Spanned<Vec<Number>>>,
) -> Result<Vec<crate::track::Body>, SceneError> {
    let err = |span: Range<usize>, message: String| located(path, text, Some(span), message);
    crate::track::bodies(
        masses.get_ref(),
        positions.get_ref(),
        velocities.get_ref(),
        sizes.map(|s| s.get_ref().as_slice()),
    )
    .map_err(|e| match e {
        crate::track::BodiesError::Miscount(m) => {
            let list = match m.list {
                "positions" => positions,
                "velocities" => velocities,
                _ => sizes.unwrap_or(masses),
            };
            err(
                list.span(),
                format!(
                    "[{table}] {}: {} values for {} bodies",
                    m.list, m.got, m.bodies
                ),
            )
        }
        crate::track::BodiesError::Track(e) => err(masses.span(), format!("[{table}] {e}")),
    })
}

/// `[contact]` in a scene: bodies pushing with contact forces (`collide contact`).
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct ContactFile {
    title: Option<String>,
    source: Option<String>,
    contact: ContactTable,
    expect: Option<ExpectTable>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct ContactTable {
    masses: Spanned<Vec<Number>>,
    positions: Spanned<Vec<Number>>,
    velocities: Spanned<Vec<Number>>,
    sizes: Option<Spanned<Vec<Number>>>,
    left_wall: Option<Number>,
    right_wall: Option<Number>,
    law: Option<LawKind>,
    stiffness: Option<Number>,
    damping: Option<Number>,
    zeta: Option<Number>,
    restitution: Option<Number>,
    wall_stiffness: Option<Number>,
    wall_damping: Option<Number>,
    wall_zeta: Option<Number>,
    wall_restitution: Option<Number>,
    method: Option<Spanned<String>>,
    dt: Option<Number>,
    tol: Option<Number>,
    until: Option<Number>,
    max_steps: Option<u64>,
}

/// A contact scene, validated.
#[derive(Clone, Debug)]
pub struct ContactScene {
    pub about: About,
    pub setup: Setup,
    pub settings: Settings,
}

/// Top-level keys of `collide contact --format json`.
pub const CONTACT_KEYS: [&str; 12] = [
    "law",
    "method",
    "dt",
    "tol",
    "time",
    "x",
    "v",
    "contacts",
    "energy",
    "stats",
    "impulse_model",
    "stop",
];

impl ContactScene {
    pub fn parse(path: &Path, text: &str) -> Result<ContactScene, SceneError> {
        let err = |span: Option<Range<usize>>, message: String| located(path, text, span, message);
        let file: ContactFile = from_toml(path, text)?;
        let t = file.contact;
        let bodies = layout(
            (path, text),
            "contact",
            [&t.masses, &t.positions, &t.velocities],
            t.sizes.as_ref(),
        )?;
        let value = |n: &Option<Number>| n.as_ref().map(Number::value);
        let damping = |keys: [&str; 3], [c, z, e]: [&Option<Number>; 3]| {
            if [c, z, e].iter().filter(|n| n.is_some()).count() > 1 {
                return Err(err(
                    None,
                    format!("[contact] give at most one of {}", keys.join(", ")),
                ));
            }
            Ok(Damping::given(value(c), value(z), value(e)))
        };
        let laws = Laws {
            kind: t.law.unwrap_or(LawKind::Linear),
            k: value(&t.stiffness).unwrap_or(1.0),
            damping: damping(
                ["damping", "zeta", "restitution"],
                [&t.damping, &t.zeta, &t.restitution],
            )?,
            wall_k: value(&t.wall_stiffness),
            wall_damping: damping(
                ["wall_damping", "wall_zeta", "wall_restitution"],
                [&t.wall_damping, &t.wall_zeta, &t.wall_restitution],
            )?,
        };
        let setup = Setup::new(bodies, (value(&t.left_wall), value(&t.right_wall)), laws);
        setup
            .slots()
            .map_err(|e| err(Some(t.masses.span()), format!("[contact] {e}")))?;
        let method = match &t.method {
            None => None,
            Some(m) if m.get_ref() == "auto" => None,
            Some(m) => Some(Method::parse(m.get_ref()).ok_or_else(|| {
                let names: Vec<&str> = Method::ALL.iter().map(|m| m.name()).collect();
                err(
                    Some(m.span()),
                    format!(
                        "[contact] method '{}': expected auto, {}",
                        m.get_ref(),
                        names.join(", ")
                    ),
                )
            })?),
        };
        let until = value(&t.until);
        Limits {
            until,
            max_collisions: 0,
        }
        .check()
        .map_err(|e| err(None, format!("[contact] {e}")))?;
        let settings = Settings {
            method,
            dt: value(&t.dt),
            tol: value(&t.tol),
            until,
            max_steps: t.max_steps.unwrap_or(crate::contact::DEFAULT_MAX_STEPS),
            trace: false,
        };
        let about = About::new(
            (path, text),
            file.title,
            file.source,
            file.expect,
            among(&CONTACT_KEYS),
        )?;
        Ok(ContactScene {
            about,
            setup,
            settings,
        })
    }
}
