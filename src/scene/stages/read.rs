//! Reading a scene of stages: each `[[stage]]` in turn, its references resolved against the
//! stages before it, its bodies named and followed from stage to stage.

use std::collections::{BTreeMap, BTreeSet};
use std::ops::Range;
use std::path::Path;

use serde::Deserialize;
use toml::Spanned;

use super::super::two_body::{Two, Typed, pair, report_key, wall_key};
use super::super::{About, ExpectTable, SceneError, among, from_toml, located};
use super::{MAX_STAGES, STAGE_SHOW, STAGES_KEYS, Stage, StagesScene, Taken};
use crate::line::chain::{Object, Side};
use crate::line::problem::Problem;
use crate::line::restitution::Restitution;
use crate::report::Section;
use crate::values::number::{Given, Number};
use crate::values::units::{Dimension, Pair};

/// The file as written. Field names are the scene format.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct StagesFile {
    title: Option<String>,
    source: Option<String>,
    exact: Option<bool>,
    show: Option<Vec<Section>>,
    stage: Vec<Spanned<StageTable>>,
    expect: Option<ExpectTable>,
    /// A condition on what follows the last stage, asked as a range of one stage's `e`.
    condition: Option<Spanned<String>>,
}

/// One `[[stage]]` as written.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct StageTable {
    name: Option<Spanned<String>>,
    bodies: Option<Spanned<Two<String>>>,
    masses: Spanned<Two<Typed>>,
    velocities: Spanned<Two<Spanned<Typed>>>,
    fin: Option<Spanned<Two<Typed>>>,
    restitution: Option<Spanned<Typed>>,
    /// Body 1 passes through body 2 (a bullet through a block): momentum alone.
    pass_through: Option<bool>,
    si: Option<bool>,
    gravity: Option<Number>,
    energy_unit: Option<Spanned<String>>,
    show: Option<Vec<Section>>,
    contact_time: Option<Spanned<String>>,
    expect: Option<ExpectTable>,
}

/// `NAME.QUANTITY` when `text` has the form of a reference (an identifier, a dot, a word).
pub(super) fn reference(text: &str) -> Option<(&str, &str)> {
    let (stage, quantity) = text.trim().split_once('.')?;
    let word = !quantity.is_empty()
        && quantity
            .chars()
            .all(|c| c.is_ascii_alphanumeric() || c == '_');
    (identifier(stage) && word).then_some((stage, quantity))
}

/// A stage's or body's name: a letter, then letters, digits, `_` or `-`, at most 32.
fn identifier(s: &str) -> bool {
    let mut chars = s.chars();
    chars.next().is_some_and(|c| c.is_ascii_alphabetic())
        && chars.all(|c| c.is_ascii_alphanumeric() || c == '_' || c == '-')
        && s.len() <= 32
}

/// The default name of stage `i` (0-based).
fn default_name(i: usize) -> String {
    format!("stage{}", i + 1)
}

/// What reading one stage needs from the ones before it.
struct Reader<'a> {
    path: &'a Path,
    text: &'a str,
    /// Every stage's name, as given or `stageN` (a reference to a later one is told so).
    names: Vec<String>,
    /// The stages read so far.
    stages: Vec<Stage>,
    bodies: Vec<String>,
    /// Names given in `bodies` anywhere in the file (default names avoid them).
    reserved: BTreeSet<String>,
    /// Each body's latest stage and place in it.
    latest: BTreeMap<usize, (usize, usize)>,
}

impl Reader<'_> {
    fn err(&self, span: Range<usize>, message: String) -> SceneError {
        located(self.path, self.text, Some(span), message)
    }

    /// The stage a reference names, among those before stage `i`.
    fn stage_named(&self, name: &str, i: usize, span: Range<usize>) -> Result<usize, SceneError> {
        let named = |j: usize, given: &str| given == name || default_name(j) == name;
        let message = match self.names.iter().enumerate().position(|(j, n)| named(j, n)) {
            Some(j) if j < i => return Ok(j),
            Some(j) if j == i => format!(
                "'{name}' is this stage: a stage takes the results of earlier stages only (so a \
                 chain cannot loop)"
            ),
            Some(_) => format!(
                "'{name}' comes after this stage ({}): a stage takes the results of earlier \
                 stages only (so a chain cannot loop)",
                self.names[i]
            ),
            None if i == 0 => format!(
                "no stage is named '{name}', and this first stage has no results to take: type \
                 its velocities"
            ),
            None => format!(
                "no stage is named '{name}': expected one of the stages before this one, {}",
                self.names[..i].join(", ")
            ),
        };
        Err(self.err(span, message))
    }

    /// A velocity taken from an earlier stage (`"stage1.fin2"`) for stage `i`.
    fn take(
        &self,
        (stage, quantity): (&str, &str),
        i: usize,
        span: Range<usize>,
    ) -> Result<(Taken, usize), SceneError> {
        let j = self.stage_named(stage, i, span.clone())?;
        let from = &self.stages[j];
        let body = match quantity {
            "fin1" => 0,
            "fin2" => 1,
            _ => {
                return Err(self.err(
                    span,
                    format!(
                        "{stage} has no result '{quantity}': expected fin1 or fin2 (the velocity \
                         body 1 or body 2 leaves {stage} with)"
                    ),
                ));
            }
        };
        let text = format!("{stage}.{quantity}");
        let b = match from.objects[body] {
            Object::Body(b) => b,
            Object::Wall(_) => {
                return Err(self.err(
                    span,
                    format!(
                        "'{text}': body {} of {stage} is a wall; take a body's velocity",
                        body + 1
                    ),
                ));
            }
        };
        if let Some(&(k, place)) = self.latest.get(&b).filter(|l| l.0 != j) {
            let newer = format!("{}.fin{}", self.stages[k].name, place + 1);
            return Err(self.err(
                span,
                format!(
                    "'{text}' is out of date: {} collided again in {}, so its velocity now is \
                     \"{newer}\"",
                    self.bodies[b], self.stages[k].name
                ),
            ));
        }
        Ok((
            Taken {
                stage: j,
                body,
                text,
            },
            b,
        ))
    }

    /// A name for a new body: the one given, or the next free letter.
    fn new_name(&self, given: Option<&str>) -> String {
        if let Some(g) = given {
            return g.to_string();
        }
        let used = |n: &str| self.reserved.contains(n) || self.bodies.iter().any(|b| b == n);
        ('A'..='Z')
            .map(String::from)
            .find(|n| !used(n))
            .unwrap_or_else(|| format!("body{}", self.bodies.len() + 1))
    }

    /// Reads stage `i`.
    fn stage(&mut self, i: usize, t: Spanned<StageTable>) -> Result<(), SceneError> {
        let at = t.span();
        let t = t.into_inner();
        let line = super::super::line_col(self.text, at.start).0;
        let name = match &t.name {
            None => default_name(i),
            Some(n) => {
                let s = n.get_ref().trim();
                let numbered = s
                    .strip_prefix("stage")
                    .is_some_and(|d| !d.is_empty() && d.chars().all(|c| c.is_ascii_digit()));
                let problem = if !identifier(s) {
                    Some(
                        "a stage's name is a letter, then letters, digits, '_' or '-' (at most 32)"
                            .to_string(),
                    )
                } else if numbered && s != default_name(i) {
                    Some(format!(
                        "'{s}' names another stage by number; this is {}: choose a word",
                        default_name(i)
                    ))
                } else if self.stages.iter().any(|x| x.name == s) {
                    Some(format!("two stages are named '{s}'"))
                } else {
                    None
                };
                if let Some(m) = problem {
                    return Err(self.err(n.span(), format!("name: {m}")));
                }
                s.to_string()
            }
        };
        // Masses, FIN and restitution are typed in each stage.
        for (list, what) in [(Some(&t.masses), "masses"), (t.fin.as_ref(), "fin")] {
            let Some(list) = list else { continue };
            if let Some(r) = list.get_ref().0.iter().find(|v| reference(&v.0).is_some()) {
                return Err(self.err(
                    list.span(),
                    format!(
                        "{what}: '{}': only velocities are taken from earlier stages; type the \
                         {what} of every stage",
                        r.0
                    ),
                ));
            }
        }
        let masses = pair(t.masses.get_ref(), Dimension::Mass, "masses")
            .map_err(|e| self.err(t.masses.span(), e.to_string()))?;
        let wall = masses.0.each_ref().map(Given::is_wall);
        if wall == [true, true] {
            return Err(self.err(
                t.masses.span(),
                "masses: two walls: at most one body of a stage is immovable".into(),
            ));
        }
        // Velocities: typed, or taken from an earlier stage.
        let mut takes: [Option<Taken>; 2] = [None, None];
        let mut taken_bodies: [Option<usize>; 2] = [None, None];
        let mut velocities = [Given::Unknown, Given::Unknown];
        for (slot, v) in t.velocities.get_ref().0.iter().enumerate() {
            let (typed, span) = (v.get_ref().0.as_str(), v.span());
            if let Some(r) = reference(typed) {
                if wall[slot] {
                    return Err(self.err(
                        span,
                        format!(
                            "velocities: body {} is a wall: its velocity is typed (usually 0), \
                             not taken from a body",
                            slot + 1
                        ),
                    ));
                }
                let (taken, b) = self.take(r, i, span)?;
                takes[slot] = Some(taken);
                taken_bodies[slot] = Some(b);
                continue;
            }
            velocities[slot] = Given::parse(typed, |x| {
                crate::values::units::parse(x, Dimension::Velocity)
            })
            .map_err(|e| {
                let hint = if typed.trim().starts_with(|c: char| c.is_ascii_alphabetic()) {
                    " (or an earlier stage's result, such as \"stage1.fin2\")"
                } else {
                    ""
                };
                self.err(span.clone(), format!("velocities: velocity {e}{hint}"))
            })?;
        }
        if let [Some(a), Some(b)] = taken_bodies
            && a == b
        {
            return Err(self.err(
                t.velocities.span(),
                format!(
                    "velocities: both are {}: a body cannot collide with itself",
                    self.bodies[a]
                ),
            ));
        }
        // Who is on each side.
        let names = t.bodies.as_ref().map(|b| b.get_ref().0.clone());
        let mut objects = [Object::Body(0); 2];
        for slot in 0..2 {
            let given = names.as_ref().map(|n| n[slot].trim().to_string());
            let bad = |m: String| {
                let span = t.bodies.as_ref().map_or(at.clone(), Spanned::span);
                self.err(span, format!("bodies: {m}"))
            };
            objects[slot] = if wall[slot] {
                if given
                    .as_ref()
                    .is_some_and(|g| !g.eq_ignore_ascii_case("wall"))
                {
                    return Err(bad(format!(
                        "body {} is a wall (its mass is \"wall\"): name it \"wall\"",
                        slot + 1
                    )));
                }
                Object::Wall(if slot == 0 { Side::Left } else { Side::Right })
            } else if let Some(b) = taken_bodies[slot] {
                if let Some(g) = given.as_ref().filter(|g| **g != self.bodies[b]) {
                    return Err(bad(format!(
                        "body {} is {} (its velocity is taken from {}), not '{g}'",
                        slot + 1,
                        self.bodies[b],
                        takes[slot].as_ref().map_or("", |t| t.text.as_str())
                    )));
                }
                Object::Body(b)
            } else {
                if let Some(g) = &given {
                    if !identifier(g) || g.eq_ignore_ascii_case("wall") {
                        return Err(bad(format!(
                            "'{g}': a body's name is a letter, then letters, digits, '_' or '-' \
                             (at most 32), and not \"wall\""
                        )));
                    }
                    if let Some(old) = self.bodies.iter().position(|b| b == g) {
                        // The other body of this stage, or one of an earlier stage.
                        let earlier = self
                            .latest
                            .get(&old)
                            .filter(|_| !taken_bodies.contains(&Some(old)));
                        return Err(bad(match earlier {
                            Some(&(k, place)) => format!(
                                "'{g}' already names a body (its velocity is typed here, so this \
                                 is a new body); to go on with {g}, take its velocity \
                                 \"{}.fin{}\"",
                                self.stages[k].name,
                                place + 1
                            ),
                            None => format!("'{g}' names both bodies of this stage"),
                        }));
                    }
                }
                let name = self.new_name(given.as_deref());
                self.bodies.push(name);
                Object::Body(self.bodies.len() - 1)
            };
        }
        for (slot, o) in objects.iter().enumerate() {
            if let Object::Body(b) = o {
                self.latest.insert(*b, (i, slot));
            }
        }
        let err = |span: Range<usize>, m: String| self.err(span, m);
        let velocities = Pair(velocities);
        let fin = match &t.fin {
            Some(f) => Some(
                pair(f.get_ref(), Dimension::Velocity, "fin")
                    .map_err(|e| err(f.span(), e.to_string()))?,
            ),
            None => None,
        };
        let restitution = match &t.restitution {
            None => None,
            Some(r) => Some(
                Given::parse(&r.get_ref().0, str::parse::<Restitution>)
                    .map_err(|e| err(r.span(), e.to_string()))?,
            ),
        };
        let energy_unit = match &t.energy_unit {
            Some(u) => Some(
                crate::values::units::energy_unit(u.get_ref())
                    .map_err(|e| err(u.span(), e.to_string()))?,
            ),
            None => None,
        };
        let contact_time = match &t.contact_time {
            None => None,
            Some(c) => Some(
                crate::values::units::seconds(c.get_ref())
                    .map_err(|e| err(c.span(), format!("contact_time: {e}")))?,
            ),
        };
        let keys: fn(&str) -> Result<(), crate::expect::ExpectError> = if wall.contains(&true) {
            wall_key
        } else {
            report_key
        };
        let expect = About::new((self.path, self.text), None, None, t.expect, keys)?.expect;
        let problem = Problem {
            masses: Some(masses),
            velocities,
            fin,
            restitution,
            si: t.si.unwrap_or(false),
            gravity: t.gravity,
            energy_unit,
            exact: false,
            knowns: crate::line::problem::Knowns {
                pass_through: t.pass_through.unwrap_or(false),
                ..Default::default()
            },
            velocity_unit: None,
        };
        self.stages.push(Stage {
            name,
            line,
            objects,
            takes,
            problem,
            show: t.show.unwrap_or_default(),
            contact_time,
            expect,
        });
        Ok(())
    }
}

/// Reads a scene of stages; `path` names it in errors.
pub(super) fn parse(path: &Path, text: &str) -> Result<StagesScene, SceneError> {
    let file: StagesFile = from_toml(path, text)?;
    if file.stage.is_empty() {
        return Err(located(path, text, None, "no [[stage]] table".into()));
    }
    if let Some(extra) = file.stage.get(MAX_STAGES) {
        return Err(located(
            path,
            text,
            Some(extra.span()),
            format!(
                "more than {MAX_STAGES} stages: a scene of stages is a problem in a few steps; \
                 many collisions in turn are a run of `collide track`"
            ),
        ));
    }
    let exact = file.exact.unwrap_or(false);
    let reserved = file
        .stage
        .iter()
        .filter_map(|s| s.get_ref().bodies.as_ref())
        .flat_map(|b| b.get_ref().0.iter().map(|n| n.trim().to_string()))
        .collect();
    let names = file
        .stage
        .iter()
        .enumerate()
        .map(|(i, s)| {
            s.get_ref()
                .name
                .as_ref()
                .map_or_else(|| default_name(i), |n| n.get_ref().trim().to_string())
        })
        .collect();
    let mut reader = Reader {
        path,
        text,
        names,
        stages: Vec::new(),
        bodies: Vec::new(),
        reserved,
        latest: BTreeMap::new(),
    };
    let shared = file.show.unwrap_or_else(|| STAGE_SHOW.to_vec());
    for (i, t) in file.stage.into_iter().enumerate() {
        reader.stage(i, t)?;
        let s = reader.stages.last_mut().expect("just read");
        if s.show.is_empty() {
            s.show = shared.clone();
        }
        s.problem.exact = exact;
    }
    let range = match &file.condition {
        Some(c) => Some(super::range::asked(
            (path, text),
            c,
            &reader.stages,
            &reader.bodies,
        )?),
        None => None,
    };
    let about = About::new(
        (path, text),
        file.title,
        file.source,
        file.expect,
        among(&STAGES_KEYS),
    )?;
    Ok(StagesScene {
        about,
        exact,
        stages: reader.stages,
        bodies: reader.bodies,
        range,
    })
}
