//! `[contact]` scenes: bodies pushing with contact forces (`collide contact`).

use std::ops::Range;
use std::path::Path;

use serde::Deserialize;
use toml::Spanned;

use super::{About, ExpectTable, SceneError, among, from_toml, layout, located};
use crate::contact::{Damping, LawKind, Laws, Method, Settings, Setup};
use crate::track::Limits;
use crate::values::number::Number;

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
