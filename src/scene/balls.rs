//! Scenes of touching balls, several contacts at once (`../shared/physics.md` section 8):
//! positions and radii, or contacts named as pairs with their lines of impact, as on the
//! command line (`collide solve --positions ... --radii ...`).
//!
//! ```toml
//! title = "Newton's cradle of three balls"
//! masses = [1, 1, 1]
//! velocities = [[1, 0], 0, 0]
//! positions = [[0, 0], [2, 0], [4, 0]]     # or contacts = ["1-2 @ 0deg", "2-3 @ 0deg"]
//! radii = [1, 1, 1]
//! sequential = true
//! exact = true
//! [expect]
//! fin = [["-1/3", 0], ["2/3", 0], ["2/3", 0]]
//! ```
//! A file is of this kind when it has `positions` or `contacts`.

use std::path::Path;

use serde::Deserialize;
use toml::Spanned;

use super::space::Value;
use super::{About, ExpectTable, SceneError, among, from_toml, located};
use crate::space::balls::{BallsInput, parse_radii};
use crate::space::pose::Input;
use crate::space::typed::{parse_list, parse_masses};
use crate::values::number::Given;

/// The file as written.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct BallsFile {
    title: Option<String>,
    source: Option<String>,
    masses: Spanned<Vec<Value>>,
    velocities: Spanned<Vec<Value>>,
    positions: Option<Spanned<Vec<Value>>>,
    radii: Option<Spanned<Vec<Value>>>,
    contacts: Option<Spanned<Vec<String>>>,
    restitution: Option<Spanned<Value>>,
    sequential: Option<bool>,
    exact: Option<bool>,
    expect: Option<ExpectTable>,
}

/// Top-level keys of the report's JSON (`[expect]` addresses them).
pub const BALLS_KEYS: [&str; 15] = [
    "dim",
    "masses",
    "restitution",
    "in",
    "fin",
    "fin_speed",
    "fin_angle_deg",
    "v_com",
    "energy",
    "law",
    "positions",
    "radii",
    "contacts",
    "impulses_unique",
    "sequential",
];

/// A scene of touching balls, validated.
#[derive(Clone, Debug)]
pub struct BallsScene {
    pub about: About,
    pub input: BallsInput,
    pub sequential: bool,
}

/// Whether scene text is of this kind (see the module docs).
pub fn is_balls(text: &str) -> bool {
    toml::from_str::<toml::Table>(text)
        .is_ok_and(|t| t.contains_key("positions") || t.contains_key("contacts"))
}

impl BallsScene {
    pub fn parse(path: &Path, text: &str) -> Result<BallsScene, SceneError> {
        let err = |span: Option<std::ops::Range<usize>>, message: String| {
            located(path, text, span, message)
        };
        let file: BallsFile = from_toml(path, text)?;
        let list =
            |v: &[Value]| -> String { v.iter().map(Value::text).collect::<Vec<_>>().join(",") };
        let masses = parse_masses(&list(file.masses.get_ref()))
            .map_err(|e| err(Some(file.masses.span()), format!("masses: {e}")))?;
        let v_in = parse_list(&list(file.velocities.get_ref()))
            .map_err(|e| err(Some(file.velocities.span()), format!("velocities: {e}")))?;
        let radii = file
            .radii
            .as_ref()
            .map(|r| {
                parse_radii(&list(r.get_ref()))
                    .map_err(|e| err(Some(r.span()), format!("radii: {e}")))
            })
            .transpose()?;
        let e = match &file.restitution {
            None => None,
            Some(r) => Some(
                Given::parse(&r.get_ref().text(), |s| {
                    s.parse::<crate::line::restitution::Restitution>()
                        .map(|r| r.number().clone())
                })
                .map_err(|e| err(Some(r.span()), format!("restitution: {e}")))?,
            ),
        };
        let about = About::new(
            (path, text),
            file.title,
            file.source,
            file.expect,
            among(&BALLS_KEYS),
        )?;
        Ok(BallsScene {
            about,
            input: BallsInput {
                input: Input {
                    masses,
                    v_in,
                    fin: None,
                    normal: None,
                    e,
                    si: false,
                    exact: file.exact.unwrap_or(false),
                },
                positions: file.positions.as_ref().map(|p| list(p.get_ref())),
                radii,
                contacts: file.contacts.as_ref().map(|c| c.get_ref().join(",")),
            },
            sequential: file.sequential.unwrap_or(false),
        })
    }
}
