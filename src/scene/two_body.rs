//! Two-body scenes: a collision (with an optional `[sweep]` or `[plot]`), a separation or a ball
//! against a wall.

use std::fmt;
use std::ops::Range;
use std::path::{Component, Path, PathBuf};

use serde::Deserialize;
use toml::Spanned;

use super::{About, AnyScene, ExpectTable, SceneError, from_toml, located};
use crate::expect::ExpectError;
use crate::line::case::Case;
use crate::line::frame::Frame;
use crate::line::inertia::InertiaTensor;
use crate::line::problem::{Posed, Problem};
use crate::line::restitution::Restitution;
use crate::line::separation::Separation;
use crate::line::slide;
use crate::line::unknowns::Solved;
use crate::line::wall::WallCase;
use crate::report::floor::{self, FloorFriction};
use crate::report::special::Special;
use crate::report::{Section, Sections};
use crate::table::columns::Column;
use crate::table::sweep::{DEFAULT_MAX_ROWS, Grid};
use crate::table::writer::RowFormat;
use crate::values::number::{Given, Number};
use crate::values::units::{Dimension, Pair, PairError, parse_pair};

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
pub(super) struct Typed(pub(super) String);

impl std::str::FromStr for Typed {
    type Err = std::convert::Infallible;
    fn from_str(s: &str) -> Result<Typed, Self::Err> {
        Ok(Typed(s.to_string()))
    }
}

impl<'de> Deserialize<'de> for Typed {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Typed, D::Error> {
        crate::values::number::deserialize_parsed(
            d,
            "a number, a string with a unit such as \"4 t\", or \"?\"",
        )
    }
}

pub(super) fn pair(
    Two(v): &Two<Typed>,
    dimension: Dimension,
    what: &str,
) -> Result<Pair, PairError> {
    parse_pair(&format!("{},{}", v[0].0, v[1].0), dimension, what)
}

/// Exactly two values (`[60, 10]`): a longer or shorter array is an error at its line.
#[derive(Clone, Debug)]
pub(super) struct Two<T>(pub(super) [T; 2]);

impl<'de, T: Deserialize<'de>> Deserialize<'de> for Two<T> {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Two<T>, D::Error> {
        let v = Vec::<T>::deserialize(d)?;
        let n = v.len();
        <[T; 2]>::try_from(v)
            .map(Two)
            .map_err(|_| serde::de::Error::invalid_length(n, &"exactly 2 values"))
    }
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
    /// The floor's mu, solved from a slide in `fin` (`slide 50 cm mu ?`).
    pub floor: Option<FloorFriction>,
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

impl SpecialScene {
    /// Sections to compute: the shown ones and those the expectations read.
    pub fn sections_needed(&self) -> Sections {
        super::needed(&self.show, &self.about.expect)
    }
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

impl Scene {
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
    pub(super) fn parse_any(path: &Path, text: &str) -> Result<AnyScene, SceneError> {
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
        // `slide 50 cm mu ?`: that final velocity is left to the collision (read as `?`), and
        // the floor's mu follows from it (`report::floor`), as `--fin` on the command line.
        let (fin, slides) = match &file.fin {
            Some(f) => {
                let Two([a, b]) = f.get_ref();
                let typed = format!("{},{}", a.0, b.0);
                let at = |m: String| err(Some(f.span()), m);
                let slides = slide::slides(&typed).map_err(|e| at(e.to_string()))?;
                if let Some(bare) = slides.iter().find(|s| s.bare) {
                    return Err(at(format!(
                        "fin: '{}': give the floor's mu ('slide D mu 0.62'), or 'slide D mu ?' to \
                         solve it",
                        bare.typed
                    )));
                }
                let fin = parse_pair(&slide::masked(&typed), Dimension::Velocity, "fin")
                    .map_err(|e| at(e.to_string()))?;
                (Some(fin), slides)
            }
            None => (None, Vec::new()),
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
                    crate::values::units::energy_unit(u.get_ref())
                        .map_err(|e| err(Some(u.span()), e.to_string()))?,
                ),
                None => None,
            },
            exact: file.exact.unwrap_or(false),
            knowns: Default::default(),
            velocity_unit: None,
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
                crate::values::units::seconds(t.get_ref())
                    .map_err(|e| err(Some(t.span()), format!("contact_time: {e}")))?,
            ),
        };
        if let Some(f) = &file.frame {
            f.on_line().map_err(|e| err(None, e.to_string()))?;
        }
        let mut show = Sections::new(file.show.unwrap_or_else(|| Section::DEFAULT.to_vec()));
        show.contact_time = contact_time;
        let units = posed.units().clone();
        show.heights = Some(crate::values::units::HeightScale::new(
            file.gravity.as_ref(),
            &units,
        ));
        let (case, solved) = match posed {
            Posed::Collision(case, solved) => (case, solved),
            _ if !slides.is_empty() => {
                return Err(err(
                    file.fin.as_ref().map(|f| f.span()),
                    format!(
                        "fin: '{}': mu ? in a slide is solved from a collision of two movable \
                         bodies (not a wall, a separation or a pass-through)",
                        slides[0].typed
                    ),
                ));
            }
            Posed::Separations(..) => {
                return Err(err(
                    None,
                    "two solutions (the energy released fixes the relative speed, not which \
                     piece is ahead): give one final velocity"
                        .into(),
                ));
            }
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
                    Posed::Collision(..) | Posed::Separations(..) => {
                        unreachable!("matched above")
                    }
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
        let floor = match &show.heights {
            Some(h) => floor::floor_friction(&case, &slides, h, file.exact.unwrap_or(false))
                .map_err(|e| err(file.fin.as_ref().map(|f| f.span()), format!("fin: {e}")))?,
            None => None,
        };
        // The slides section with the solved mu, in the case's units and g, as collide solve.
        if let (Some(mu), Some(h)) = (&floor, &show.heights) {
            let mut asked = crate::report::asked::Asked::in_units(&units);
            asked.g = h.g.clone();
            asked.friction = Some((mu.value.clone(), mu.shown.clone()));
            show.asked = asked;
        }
        Ok(AnyScene::Case(Scene {
            about,
            floor,
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
        super::needed(&self.show, &self.about.expect)
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
    let typed = p.output.display().to_string();
    let beside = p
        .output
        .components()
        .all(|c| matches!(c, Component::Normal(_) | Component::CurDir));
    if !beside {
        return Err(format!(
            "output '{typed}' must be a file name relative to the scene's folder, without '..' \
             (a scene's picture goes beside the scene)"
        ));
    }
    // A scene read from standard input or a pipe has no folder of its own: the current one.
    let folder = match scene.parent() {
        Some(f) if std::fs::metadata(scene).is_ok_and(|m| m.is_file()) => f,
        _ => Path::new(""),
    };
    p.output = folder.join(&p.output);
    let shown = p.output.display().to_string();
    // Nor through a symlinked subfolder.
    let real = |f: &Path| {
        std::fs::canonicalize(if f.as_os_str().is_empty() {
            Path::new(".")
        } else {
            f
        })
    };
    if let (Ok(base), Some(Ok(parent))) = (real(folder), p.output.parent().map(real))
        && !parent.starts_with(&base)
    {
        return Err(format!(
            "output '{typed}' leads out of the scene's folder (through a symbolic link)"
        ));
    }
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
pub(super) fn wall_key(top: &str) -> Result<(), ExpectError> {
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
        "left",
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
pub(super) fn report_key(top: &str) -> Result<(), ExpectError> {
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
}
