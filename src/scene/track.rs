//! `[track]` scenes: bodies on a track (`collide track`).

use std::ops::Range;
use std::path::Path;

use serde::Deserialize;
use toml::Spanned;

use super::{About, ExpectTable, SceneError, among, from_toml, layout, located, where_in_layout};
use crate::line::restitution::{Restitution, RestitutionError};
use crate::track::{Limits, Track, TrackError};
use crate::values::number::Number;

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
    restitution: Option<Spanned<Restitution>>,
    wall_restitution: Option<Spanned<Restitution>>,
    gravity: Option<Spanned<Number>>,
    until: Option<Spanned<Number>>,
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
        for (key, r) in [
            ("restitution", &t.restitution),
            ("wall_restitution", &t.wall_restitution),
        ] {
            if let Some(r) = r
                && r.get_ref().is_superelastic()
            {
                let e = RestitutionError::Superelastic(r.get_ref().to_string());
                return Err(err(Some(r.span()), format!("[track] {key}: {e}")));
            }
        }
        let e = t
            .restitution
            .as_ref()
            .map_or_else(Restitution::elastic, |r| r.get_ref().clone())
            .value();
        let track = Track {
            bodies,
            left_wall: t.left_wall.map(|n| n.value()),
            right_wall: t.right_wall.map(|n| n.value()),
            e,
            e_wall: Track::walls_restitution(
                e,
                t.wall_restitution.as_ref().map(|r| r.get_ref().value()),
            ),
            gravity: t.gravity.as_ref().map_or(0.0, |g| g.get_ref().value()),
        };
        track.check().map_err(|e| {
            let span = match (&e, &t.gravity) {
                (TrackError::Gravity(_) | TrackError::NoFloor, Some(g)) => g.span(),
                _ => where_in_layout(&e, [&t.masses, &t.positions], t.sizes.as_ref()),
            };
            err(Some(span), format!("[track] {e}"))
        })?;
        let limits = Limits {
            until: t.until.as_ref().map(|u| u.get_ref().value()),
            max_collisions: t
                .max_collisions
                .unwrap_or(crate::track::DEFAULT_MAX_COLLISIONS),
        };
        limits
            .check()
            .map_err(|e| err(t.until.as_ref().map(|u| u.span()), format!("[track] {e}")))?;
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
