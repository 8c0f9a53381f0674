//! A section asked for by name that does not apply to the case says why (issue 42 section 3),
//! never nothing: a separation or a pass-through has only momentum (no energy ellipse, no
//! restitution), a wall is immovable, angles belong to the plane, a swing and rolling to rigid
//! bodies. `all` asks only for the sections that apply, so it adds no notes.

use serde_json::{Map, Value};

use super::Section;
use super::text::Block;

/// The kind of event on a rail.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Event {
    /// Two movable bodies collide.
    Collision,
    /// Bodies that start together are pushed apart (e undefined).
    Separation,
    /// One body passes through the other (e is no law).
    PassThrough,
    /// A ball against a wall.
    Wall,
}

/// Why `section` is not shown for `event`, or `None` when it is.
pub fn why(event: Event, section: Section) -> Option<&'static str> {
    let momentum_alone = matches!(event, Event::Separation | Event::PassThrough);
    match section {
        Section::Forms | Section::Ellipses | Section::Products if momentum_alone => Some(
            "they describe a collision's energy ellipse and restitution; here only momentum \
             holds (e undefined or no law)",
        ),
        Section::Forms | Section::Ellipses | Section::Products if event == Event::Wall => Some(
            "a wall is immovable (no mass): there is no two-body tensor or ellipse; the ball's \
             momentum, energy and changes are its sections",
        ),
        Section::Diagnostics if event != Event::Collision => Some(
            "the self-check times the collision solver, which this event does not use (its \
             values are exact, rounded once)",
        ),
        Section::Angles => {
            Some("angles are for the plane and space: on a rail every velocity is along the line")
        }
        Section::Swing => Some(
            "the swing is for a rigid body on a pivot (--target, --pivot, --show swing); on a \
             rail, --length gives a pendulum's swing",
        ),
        Section::Rolling => Some(
            "rolling is for a round rigid body (--ball 'sphere R' or --target 'sphere R'); a \
             body on a rail has no size or spin",
        ),
        _ => None,
    }
}

/// The sections named in `asked` that `event` does not show, with why.
fn notes(event: Event, asked: &[Section]) -> Vec<(Section, &'static str)> {
    let mut out: Vec<(Section, &'static str)> = Vec::new();
    for &s in asked {
        if let Some(w) = why(event, s)
            && !out.iter().any(|(t, _)| *t == s)
        {
            out.push((s, w));
        }
    }
    out
}

/// The section's name as `--show` takes it (each is one word).
fn name(s: Section) -> String {
    format!("{s:?}").to_lowercase()
}

/// The notes as text (empty when every section named applies).
pub fn text(event: Event, asked: &[Section]) -> String {
    let notes = notes(event, asked);
    let mut out = String::new();
    if notes.is_empty() {
        return out;
    }
    let mut b = Block::new("Not shown (asked for, but not for this case)");
    for (s, w) in notes {
        b.row(name(s), "", w);
    }
    b.render(&mut out);
    out
}

/// The notes as JSON `{"section": "why", ...}`, or `None`.
pub fn json(event: Event, asked: &[Section]) -> Option<Value> {
    let notes = notes(event, asked);
    if notes.is_empty() {
        return None;
    }
    let mut m = Map::new();
    for (s, w) in notes {
        m.insert(name(s), Value::String(w.to_string()));
    }
    Some(Value::Object(m))
}
