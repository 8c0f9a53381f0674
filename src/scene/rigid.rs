//! Rigid-body scenes: two `[[body]]` tables and a `[contact]` (docs/rigid.md).
//!
//! ```toml
//! title = "A ball hits a free rod at its end"
//! [[body]]
//! mass = "0.5 kg"
//! position = "(-0.1,0.5) m"
//! velocity = "(2,0) m/s"
//! [[body]]
//! mass = "2 kg"
//! shape = "rod 1 m"         # or inertia = "0.1 kg m^2"; pivot = "(0,-0.5) m"
//! [contact]
//! point = "(0,0.5) m"
//! normal = [1, 0]           # from body 1 to body 2, any length; or "(1,0)", "0deg", "E"
//! restitution = 1
//! friction = 0.3            # optional: law = "poisson" | "newton" | "stronge",
//!                           # tangential_restitution = 1 (Garwin)
//! ```
//! Values are numbers or strings with a unit; vectors are arrays or strings `"(a,b) unit"`, in
//! the plane also `"5 m/s @ 30deg"` or a compass bearing `"5 m/s @ N30E"`;
//! `omega` is a number in the plane and a vector in space, `rpm` a number of turns per minute;
//! `mass = "wall"` or `"floor"` is immovable.

use std::ops::Range;
use std::path::Path;

use serde::Deserialize;
use toml::Spanned;

use super::{About, ExpectTable, SceneError, among, from_toml, located};
use crate::report::Section;
use crate::rigid::impact::Problem;
use crate::rigid::laws::Law;
use crate::rigid::pose::{
    BodyTyped, ContactTyped, Either, InertiaTyped, Input, LawsTyped, MassTyped, NormalTyped,
};
use crate::rigid::shape::ShapeTyped;
use crate::rigid::units::{Measure, Typed, TypedVec};
use crate::values::number::Number;

type Val = Spanned<toml::Value>;

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RigidFile {
    title: Option<String>,
    source: Option<String>,
    show: Option<Vec<Section>>,
    exact: Option<bool>,
    tol: Option<f64>,
    energy_unit: Option<Spanned<String>>,
    body: Spanned<Vec<Spanned<BodyTable>>>,
    contact: Spanned<ContactTable>,
    expect: Option<ExpectTable>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct BodyTable {
    mass: Val,
    position: Option<Val>,
    velocity: Option<Val>,
    omega: Option<Val>,
    rpm: Option<Val>,
    inertia: Option<Val>,
    shape: Option<Spanned<String>>,
    pivot: Option<Val>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct ContactTable {
    point: Val,
    normal: Val,
    restitution: Option<Spanned<Number>>,
    friction: Option<Spanned<Number>>,
    law: Option<Law>,
    tangential_restitution: Option<Spanned<Number>>,
}

/// A rigid scene, validated.
#[derive(Clone, Debug)]
pub struct RigidScene {
    pub about: About,
    pub problem: Problem,
    pub show: Vec<Section>,
    pub exact: bool,
    pub energy_unit: Option<&'static crate::values::units::EnergyUnit>,
}

/// A value as a number (a TOML number or a string holding one).
fn number(v: &toml::Value) -> Result<Number, String> {
    Number::deserialize(v.clone()).map_err(|e| e.to_string())
}

/// One quantity: a number (in the case's units), or a string with its unit.
fn one(v: &toml::Value, measure: Measure, what: &str) -> Result<Typed, String> {
    match v {
        toml::Value::String(s) => Typed::parse(s, measure, what).map_err(|e| e.to_string()),
        other => number(other).map(|number| Typed {
            text: number.to_string(),
            number,
            unit: None,
            measure,
        }),
    }
}

/// A vector: an array of numbers, or a string `"(a,b) unit"`.
fn vector(v: &toml::Value, measure: Measure, what: &str) -> Result<TypedVec, String> {
    match v {
        toml::Value::String(s) => {
            TypedVec::parse(s, measure, what, &[2, 3]).map_err(|e| e.to_string())
        }
        toml::Value::Array(items) => {
            let parts = items.iter().map(number).collect::<Result<Vec<_>, _>>()?;
            if !(2..=3).contains(&parts.len()) {
                return Err(format!("{what}: a vector has 2 or 3 components"));
            }
            Ok(TypedVec::plain(parts, measure))
        }
        _ => Err(format!(
            "{what}: expected a vector, [a, b] or \"(a,b) unit\""
        )),
    }
}

/// A number or a vector (`Either::parse` reads a string, as on the command line).
fn either(v: &toml::Value, measure: Measure, what: &str) -> Result<Either, String> {
    match v {
        toml::Value::Array(_) => vector(v, measure, what).map(Either::Vector),
        toml::Value::String(s) => Either::parse(s, measure, what).map_err(|e| e.to_string()),
        _ => one(v, measure, what).map(Either::One),
    }
}

/// The contact normal: an array of numbers, or a string as `--normal` takes it (`"(1, 0)"`,
/// `"30deg"`, `"N30E"`).
fn normal(v: &toml::Value) -> Result<NormalTyped, String> {
    let what = "[contact] normal";
    match v {
        toml::Value::String(s) => s.parse().map_err(|e| format!("{what}: {e}")),
        toml::Value::Array(items) => items
            .iter()
            .map(number)
            .collect::<Result<Vec<_>, _>>()
            .map(NormalTyped::Components)
            .map_err(|e| format!("{what}: {e}")),
        _ => Err(format!(
            "{what}: expected a direction, [a, b], \"(a,b)\" or an angle \"30deg\""
        )),
    }
}

/// An inertia: a number, principal moments, or rows.
fn inertia(v: &toml::Value) -> Result<InertiaTyped, String> {
    let what = "inertia";
    match v {
        toml::Value::Array(rows) if rows.iter().all(toml::Value::is_array) => rows
            .iter()
            .map(|r| vector(r, Measure::Inertia, what))
            .collect::<Result<Vec<_>, _>>()
            .map(InertiaTyped::Rows),
        toml::Value::Array(_) => {
            vector(v, Measure::Inertia, what).map(|r| InertiaTyped::Rows(vec![r]))
        }
        toml::Value::String(s) if s.trim_start().starts_with('(') => {
            vector(v, Measure::Inertia, what).map(|r| InertiaTyped::Rows(vec![r]))
        }
        _ => one(v, Measure::Inertia, what).map(InertiaTyped::One),
    }
}

/// An optional value, read by `f`, its problem located.
fn optional<T>(
    v: &Option<Val>,
    f: &dyn Fn(&toml::Value) -> Result<T, String>,
    err: &dyn Fn(Option<Range<usize>>, String) -> SceneError,
) -> Result<Option<T>, SceneError> {
    v.as_ref()
        .map(|v| f(v.get_ref()).map_err(|m| err(Some(v.span()), m)))
        .transpose()
}

/// Top-level keys of a rigid report, for `[expect]`.
pub const RIGID_KEYS: [&str; 26] = crate::report::rigid::KEYS;

impl RigidScene {
    pub fn parse(path: &Path, text: &str) -> Result<RigidScene, SceneError> {
        let err = |span: Option<Range<usize>>, message: String| located(path, text, span, message);
        let file: RigidFile = from_toml(path, text)?;
        let tables = file.body.get_ref();
        if tables.len() != 2 {
            return Err(err(
                Some(file.body.span()),
                format!(
                    "a rigid scene has two [[body]] tables, this one {}",
                    tables.len()
                ),
            ));
        }
        let at = |v: &Val| Some(v.span());
        let body = |i: usize, b: &BodyTable| -> Result<BodyTyped, SceneError> {
            let name = |key: &str| format!("[[body]] {} {key}", i + 1);
            let mass = match b.mass.get_ref() {
                toml::Value::String(s) => {
                    MassTyped::parse(s, &name("mass")).map_err(|e| e.to_string())
                }
                other => one(other, Measure::Mass, &name("mass")).map(MassTyped::Mass),
            }
            .map_err(|m| err(at(&b.mass), m))?;
            let position = optional(
                &b.position,
                &|v| vector(v, Measure::Length, &name("position")),
                &err,
            )?;
            let pivot = optional(
                &b.pivot,
                &|v| vector(v, Measure::Length, &name("pivot")),
                &err,
            )?;
            let velocity = optional(
                &b.velocity,
                &|v| either(v, Measure::Velocity, &name("velocity")),
                &err,
            )?;
            let omega = match (&b.omega, &b.rpm) {
                (Some(_), Some(r)) => {
                    return Err(err(
                        at(r),
                        format!("{}: give omega or rpm, not both", name("rpm")),
                    ));
                }
                (Some(_), None) => optional(
                    &b.omega,
                    &|v| either(v, Measure::Spin, &name("omega")),
                    &err,
                )?,
                (None, Some(r)) => {
                    let n = number(r.get_ref()).map_err(|m| err(at(r), m))?;
                    Some(Either::One(
                        Typed::parse(&format!("{} rpm", n.text()), Measure::Spin, &name("rpm"))
                            .map_err(|e| err(at(r), e.to_string()))?,
                    ))
                }
                (None, None) => None,
            };
            let inertia = optional(&b.inertia, &inertia, &err)?;
            let shape = b
                .shape
                .as_ref()
                .map(|s| {
                    s.get_ref()
                        .parse::<ShapeTyped>()
                        .map_err(|e| err(Some(s.span()), e.to_string()))
                })
                .transpose()?;
            Ok(BodyTyped {
                mass,
                position,
                velocity,
                omega,
                inertia,
                shape,
                pivot,
            })
        };
        let bodies = [body(0, tables[0].get_ref())?, body(1, tables[1].get_ref())?];
        let c = file.contact.get_ref();
        let point = vector(c.point.get_ref(), Measure::Length, "[contact] point")
            .map_err(|m| err(at(&c.point), m))?;
        let one_number = |n: &Option<Spanned<Number>>| n.as_ref().map(|s| s.get_ref().clone());
        let input = Input {
            bodies,
            contact: ContactTyped {
                point,
                normal: normal(c.normal.get_ref()).map_err(|m| err(at(&c.normal), m))?,
                laws: LawsTyped {
                    restitution: one_number(&c.restitution)
                        .unwrap_or_else(|| Number::from_f64(1.0).expect("finite")),
                    friction: one_number(&c.friction),
                    law: c.law,
                    tangential_restitution: one_number(&c.tangential_restitution),
                    join: false,
                },
            },
            exact: file.exact.unwrap_or(false),
            rtol: file.tol,
        };
        // A body's problem at its table, the contact's at [contact].
        let problem = input.pose().map_err(|e| {
            let message = e.to_string();
            let span = (0..2)
                .find(|i| message.starts_with(&format!("body {}", i + 1)))
                .map_or_else(|| file.contact.span(), |i| tables[i].span());
            err(Some(span), message)
        })?;
        let energy_unit = file
            .energy_unit
            .as_ref()
            .map(|u| {
                crate::values::units::energy_unit(u.get_ref())
                    .map_err(|e| err(Some(u.span()), e.to_string()))
            })
            .transpose()?;
        let about = About::new(
            (path, text),
            file.title,
            file.source,
            file.expect,
            among(&RIGID_KEYS),
        )?;
        Ok(RigidScene {
            about,
            problem,
            show: file.show.unwrap_or_default(),
            exact: file.exact.unwrap_or(false),
            energy_unit,
        })
    }
}
