//! Scenes in the plane, in space or of N bodies (`../shared/physics.md` section 7): vectors
//! wherever a velocity is written, a line of impact, and `[expect]` with vectors.
//!
//! ```toml
//! title = "Two pucks at 45 degrees"
//! masses = [1, 1]
//! velocities = [[4, 0], 0]          # or ["(4,0)", "0"], ["4 m/s @ 0deg", "0"]
//! normal = [1, 1]                   # or "30deg", "N30E"
//! exact = true
//! [expect]
//! fin = [[2, -2], [2, 2]]
//! "energy.crunch" = 2
//! ```
//! A file is of this kind when it has a `normal` or `radii`, more than two masses, or a
//! velocity written as a vector.

use std::path::Path;

use serde::Deserialize;
use toml::Spanned;

use super::{About, ExpectTable, SceneError, among, from_toml, located};
use crate::line::frame::Frame;
use crate::report::Section;
use crate::report::space::Show;
use crate::space::pose::{Input, NormalGiven};
use crate::space::typed::parse_masses;
use crate::values::number::Given;
use crate::values::units::{Dimension, Quantity, parse as parse_quantity};

/// The file as written.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct SpaceFile {
    title: Option<String>,
    source: Option<String>,
    masses: Spanned<Vec<Value>>,
    velocities: Spanned<Vec<Value>>,
    fin: Option<Spanned<Vec<Value>>>,
    normal: Option<Spanned<Value>>,
    radii: Option<Spanned<Vec<Value>>>,
    impact_parameter: Option<Spanned<Value>>,
    restitution: Option<Spanned<Value>>,
    si: Option<bool>,
    energy_unit: Option<Spanned<String>>,
    show: Option<Vec<Section>>,
    exact: Option<bool>,
    frame: Option<Frame>,
    reverse: Option<bool>,
    expect: Option<ExpectTable>,
}

/// A value as written: a number, a string (`"4 m/s @ 30deg"`, `"?"`), or an array of them (a
/// vector's components: `[4, 0]`, `["?", 3]`).
#[derive(Clone, Debug, Deserialize)]
#[serde(untagged)]
pub(super) enum Value {
    Text(String),
    Integer(i64),
    Float(f64),
    List(Vec<Value>),
}

impl Value {
    /// The text the command line would take: `[4, 0]` is `(4,0)`.
    pub(super) fn text(&self) -> String {
        match self {
            Value::Text(s) => s.clone(),
            Value::Integer(i) => i.to_string(),
            // The shortest decimal that reads back as the same binary64, which is what was
            // written (the TOML literal itself is checked when the file is read).
            Value::Float(x) => format!("{x:?}"),
            Value::List(parts) => {
                let inner: Vec<String> = parts.iter().map(Value::text).collect();
                format!("({})", inner.join(","))
            }
        }
    }
}

/// A planar (or spatial, or N-body) scene, validated.
#[derive(Clone, Debug)]
pub struct SpaceScene {
    pub about: About,
    pub input: Input,
    /// The values as written, in the command line's words (`[4, 0]` is `(4,0)`): what
    /// `collide view` puts in its page's inputs.
    pub texts: Texts,
    pub frame: Frame,
    pub show: Show,
    pub reverse: bool,
    pub energy_unit: Option<&'static crate::values::units::EnergyUnit>,
}

/// A scene's values as the command line would take them, one text per body.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Texts {
    pub masses: Vec<String>,
    pub velocities: Vec<String>,
    pub normal: Option<String>,
    pub radii: Option<Vec<String>>,
    pub impact_parameter: Option<String>,
    pub restitution: Option<String>,
}

/// Top-level keys of the plane's JSON report (`[expect]` addresses them).
pub const SPACE_KEYS: [&str; 19] = [
    "dim",
    "masses",
    "restitution",
    "normal",
    "in",
    "fin",
    "fin_speed",
    "fin_angle_deg",
    "v_com",
    "impulse",
    "normal_parts",
    "momentum",
    "energy",
    "angle_between_deg",
    "turned_deg",
    "solved",
    "solutions",
    "units",
    "reverse",
];

/// Whether scene text is of this kind (see the module docs).
pub fn is_space(text: &str) -> bool {
    let Ok(t) = toml::from_str::<toml::Table>(text) else {
        return false;
    };
    if t.contains_key("normal") || t.contains_key("radii") {
        return true;
    }
    if t.get("masses")
        .and_then(toml::Value::as_array)
        .is_some_and(|m| m.len() > 2)
    {
        return true;
    }
    let vector = |v: &toml::Value| match v {
        toml::Value::Array(_) => true,
        toml::Value::String(s) => s.contains(['(', '@']),
        _ => false,
    };
    ["velocities", "fin"].iter().any(|k| {
        t.get(*k)
            .and_then(toml::Value::as_array)
            .is_some_and(|list| list.iter().any(vector))
    })
}

impl SpaceScene {
    pub fn parse(path: &Path, text: &str) -> Result<SpaceScene, SceneError> {
        let err = |span: Option<std::ops::Range<usize>>, message: String| {
            located(path, text, span, message)
        };
        let file: SpaceFile = from_toml(path, text)?;
        let list = |v: &Spanned<Vec<Value>>| -> String {
            v.get_ref()
                .iter()
                .map(Value::text)
                .collect::<Vec<_>>()
                .join(",")
        };
        let masses = parse_masses(&list(&file.masses))
            .map_err(|e| err(Some(file.masses.span()), format!("masses: {e}")))?;
        let velocities = |v: &Spanned<Vec<Value>>, key: &str| {
            crate::space::typed::parse_list(&list(v))
                .map_err(|e| err(Some(v.span()), format!("{key}: {e}")))
        };
        let v_in = velocities(&file.velocities, "velocities")?;
        let fin = file
            .fin
            .as_ref()
            .map(|f| velocities(f, "fin"))
            .transpose()?;
        let normal = match (&file.normal, &file.radii, &file.impact_parameter) {
            (Some(n), None, None) => Some(
                n.get_ref()
                    .text()
                    .parse::<NormalGiven>()
                    .map_err(|e| err(Some(n.span()), format!("normal: {e}")))?,
            ),
            (None, Some(r), Some(b)) => {
                let length = |x: &Value, span, key: &str| {
                    parse_quantity(&x.text(), Dimension::Length)
                        .map_err(|e| err(Some(span), format!("{key}: {e}")))
                };
                let radii: Vec<Quantity> = r
                    .get_ref()
                    .iter()
                    .map(|x| length(x, r.span(), "radii"))
                    .collect::<Result<_, _>>()?;
                let [r1, r2]: [Quantity; 2] = radii.try_into().map_err(|r: Vec<Quantity>| {
                    err(
                        Some(file.radii.as_ref().map(Spanned::span).unwrap_or_default()),
                        format!("radii: expected 2 values (R1, R2), got {}", r.len()),
                    )
                })?;
                let bq = length(b.get_ref(), b.span(), "impact_parameter")?;
                let (radii, b) = crate::space::pose::geometry([&r1, &r2], &bq)
                    .map_err(|e| err(Some(r.span()), e))?;
                Some(NormalGiven::Geometry { radii, b })
            }
            (None, None, None) => None,
            _ => {
                return Err(err(
                    None,
                    "give the line of impact as `normal`, or as `radii` with `impact_parameter`"
                        .into(),
                ));
            }
        };
        let e = match &file.restitution {
            None => None,
            Some(r) => {
                let t = r.get_ref().text();
                Some(
                    Given::parse(&t, |s| {
                        s.parse::<crate::line::restitution::Restitution>()
                            .map(|r| r.number().clone())
                    })
                    .map_err(|e| err(Some(r.span()), format!("restitution: {e}")))?,
                )
            }
        };
        let energy_unit = match &file.energy_unit {
            None => None,
            Some(u) => Some(
                crate::values::units::energy_unit(u.get_ref())
                    .map_err(|e| err(Some(u.span()), format!("energy_unit: {e}")))?,
            ),
        };
        let show = match &file.show {
            None => Show::default(),
            Some(list) => show_of(list).map_err(|m| err(None, format!("show: {m}")))?,
        };
        let about = About::new(
            (path, text),
            file.title,
            file.source,
            file.expect,
            among(&SPACE_KEYS),
        )?;
        let texts = Texts {
            masses: file.masses.get_ref().iter().map(Value::text).collect(),
            velocities: file.velocities.get_ref().iter().map(Value::text).collect(),
            normal: file.normal.as_ref().map(|n| n.get_ref().text()),
            radii: file
                .radii
                .as_ref()
                .map(|r| r.get_ref().iter().map(Value::text).collect()),
            impact_parameter: file.impact_parameter.as_ref().map(|b| b.get_ref().text()),
            restitution: file.restitution.as_ref().map(|r| r.get_ref().text()),
        };
        Ok(SpaceScene {
            about,
            texts,
            input: Input {
                masses,
                v_in,
                fin,
                normal,
                e,
                si: file.si.unwrap_or(false),
                exact: file.exact.unwrap_or(false),
            },
            frame: file.frame.unwrap_or(Frame::Lab),
            show,
            reverse: file.reverse.unwrap_or(false),
            energy_unit,
        })
    }
}

/// The sections of a planar report among those asked for (`--show`, `show = [...]`).
pub fn show_of(list: &[Section]) -> Result<Show, String> {
    if list.is_empty() {
        return Ok(Show::default());
    }
    let mut s = Show::none();
    for section in list {
        match section {
            Section::Vectors => s.vectors = true,
            Section::Momentum => s.momentum = true,
            Section::Forms => s.forms = true,
            Section::Energy => s.energy = true,
            Section::Angles => {
                s.angles = true;
                s.named_angles = true;
            }
            Section::Changes => s.changes = true,
            Section::All => {
                let named = s.named_angles;
                s = Show::all();
                s.named_angles = named;
            }
            other => {
                return Err(format!(
                    "{}: in the plane, in space and for N bodies the sections are vectors, \
                     momentum, forms, energy, angles, changes and all",
                    clap::ValueEnum::to_possible_value(other)
                        .map(|v| v.get_name().to_string())
                        .unwrap_or_default()
                ));
            }
        }
    }
    Ok(s)
}
