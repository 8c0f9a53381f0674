//! Scene files: a case in TOML, with the sections to show and the numbers to expect. One file
//! per kind of scene: a two-body collision, separation or wall case (`two_body`, also `[sweep]`
//! and `[plot]`), bodies on a track (`track`, `[track]`) and contact forces (`contact`,
//! `[contact]`), the plane, space and N bodies (`space`), rigid bodies (`rigid`, `[[body]]`),
//! chains of two-body stages (`stages`, `[[stage]]`) and touching balls (`balls`, `positions`
//! or `contacts`); this module holds what they share: reading a file, locating a problem in it,
//! the `[expect]` table and a layout of bodies.
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

mod balls;
mod contact;
mod rigid;
mod space;
mod stages;
mod track;
mod two_body;

use std::collections::BTreeMap;
use std::fmt;
use std::ops::Range;
use std::path::{Path, PathBuf};

use toml::Spanned;

use crate::expect::{ExpectError, Expectation};
use crate::values::number::{Number, NumberError};

pub use balls::{BALLS_KEYS, BallsScene};
pub use contact::{CONTACT_KEYS, ContactScene};
pub use rigid::{RIGID_KEYS, RigidScene};
pub use space::{SPACE_KEYS, SpaceScene, Texts as SpaceTexts, show_of};
pub use stages::{
    Asked, STAGE_SHOW, STAGES_KEYS, SolvedRange, SolvedStages, Stage, StageRun, StagesScene, Taken,
};
pub use track::{TRACK_KEYS, TrackScene};
pub use two_body::{PlotTable, Scene, SceneSweep, SpecialEvent, SpecialScene};

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

/// A scene file's text (`-`: standard input), read once, at most [`MAX_SCENE_BYTES`].
fn read_capped(path: &Path) -> Result<String, String> {
    use std::io::Read;
    let file: Box<dyn Read> = if path == Path::new("-") {
        Box::new(std::io::stdin())
    } else {
        Box::new(std::fs::File::open(path).map_err(|e| format!("cannot read scene file: {e}"))?)
    };
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
    crate::values::number::printable(text)
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

/// A scene file of either kind.
#[derive(Clone, Debug)]
#[allow(clippy::large_enum_variant)] // one per file, loaded once
pub enum AnyScene {
    Case(Scene),
    Special(SpecialScene),
    Track(TrackScene),
    Contact(ContactScene),
    /// In the plane, in space or of N bodies.
    Space(SpaceScene),
    /// Rigid bodies at impact.
    Rigid(RigidScene),
    /// Touching balls: several contacts at once.
    Balls(BallsScene),
    /// A chain of two-body stages (`[[stage]]`).
    Stages(StagesScene),
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
    /// Reads a scene of any kind: a two-body case (or `[sweep]`), a `[track]`, a `[contact]`,
    /// rigid bodies (`[[body]]`) or a chain of stages (`[[stage]]`).
    /// `path` is read once (a FIFO, `/dev/stdin`, `<(cat x.toml)`); `-` is standard input,
    /// named `<stdin>` in messages and reports.
    pub fn load_any(path: &Path) -> Result<AnyScene, SceneError> {
        let text = read_capped(path);
        let path = if path == Path::new("-") {
            Path::new("<stdin>")
        } else {
            path
        };
        let text = text.map_err(|message| SceneError {
            path: path.to_path_buf(),
            at: None,
            message,
        })?;
        // `[[body]]` by its header line, so that a rigid scene with a bad number is reported
        // by the rigid reader.
        if StagesScene::is_stages(&text) {
            StagesScene::parse(path, &text).map(AnyScene::Stages)
        } else if text.lines().any(|l| l.trim_start().starts_with("[[body]]")) {
            RigidScene::parse(path, &text).map(AnyScene::Rigid)
        } else if has_table(&text, "contact") {
            ContactScene::parse(path, &text).map(AnyScene::Contact)
        } else if has_table(&text, "track") {
            TrackScene::parse(path, &text).map(AnyScene::Track)
        } else if balls::is_balls(&text) {
            BallsScene::parse(path, &text).map(AnyScene::Balls)
        } else if space::is_space(&text) {
            SpaceScene::parse(path, &text).map(AnyScene::Space)
        } else {
            Scene::parse_any(path, &text)
        }
    }
}

/// Whether scene text holds a table `name` (`[track]`, `[contact]`).
pub fn has_table(text: &str, name: &str) -> bool {
    toml::from_str::<toml::Table>(text).is_ok_and(|t| t.contains_key(name))
}

/// Sections to compute for a two-body report: those in `show` and those `expect` reads.
fn needed(show: &crate::report::Sections, expect: &[Expectation]) -> crate::report::Sections {
    let mut s = show.clone();
    for e in expect {
        let top = e.key.split('.').next().unwrap_or_default();
        if let Some(section) = crate::report::Section::of_json_key(top) {
            s.insert(section);
        }
    }
    s
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
        crate::track::BodiesError::Track(e) => err(
            where_in_layout(&e, [masses, positions], sizes),
            format!("[{table}] {e}"),
        ),
    })
}

/// The list a layout error is about: positions for bodies out of order, outside a wall or not
/// finite; sizes for a bad size; masses otherwise.
fn where_in_layout(
    e: &crate::track::TrackError,
    [masses, positions]: [&Spanned<Vec<Number>>; 2],
    sizes: Option<&Spanned<Vec<Number>>>,
) -> Range<usize> {
    use crate::track::TrackError;
    match e {
        TrackError::Order(_)
        | TrackError::LeftOfWall(_)
        | TrackError::RightOfWall(..)
        | TrackError::NotFinite(_) => positions.span(),
        TrackError::Size(..) => sizes.unwrap_or(masses).span(),
        _ => masses.span(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn line_and_column() {
        assert_eq!(line_col("ab\ncd", 0), (1, 1));
        assert_eq!(line_col("ab\ncd", 4), (2, 2));
    }
}
