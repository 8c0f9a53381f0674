//! Two to five pucks in the plane for the page's N-ball panel, posed and solved by `collide
//! solve`'s own paths: N bodies that stick (`-e 0`) or explode (`--fin` with a `?`: momentum
//! gives the last velocity) go through `space::pose`, `space::solve` and
//! `report::space::solved::render`; touching balls (`--positions`, `--radii`) through
//! `report::simultaneous::run`, Newton's law at every contact at once (physics.md section 8,
//! docs/plane.md "Several contacts at once"). The answer is the JSON that `collide solve
//! --format json` prints (byte for byte), the command line that reproduces it, and what the page
//! draws: each puck's velocity and momentum `p_i = m_i v_i` before and after, from the solved
//! outcome (exact, each value rounded once), with the centres and radii of touching balls.

use serde::Serialize;

use crate::line::frame::Frame;
use crate::line::restitution::Restitution;
use crate::report::json;
use crate::report::simultaneous;
use crate::report::space::Show;
use crate::report::space::solved::{Judged, Options, judge, render};
use crate::space::balls::{BallsInput, parse_radii};
use crate::space::outcome::Outcome;
use crate::space::pose::Input;
use crate::space::solve;
use crate::space::typed::{Typed, parse_list, parse_masses, split_bodies};
use crate::values::number::{Given, Number};
use crate::values::rational::{Q, to_f64};

use super::InputError;
use super::input::NBodyInput;

/// The most pucks the panel takes.
pub const MOST: usize = 5;

/// The page's field of each puck's value, by list: `m3`, `v2`, `f1` (a final velocity), `x4` (a
/// centre), `r5` (a radius).
const FIELDS: [[&str; MOST]; 5] = [
    ["m1", "m2", "m3", "m4", "m5"],
    ["v1", "v2", "v3", "v4", "v5"],
    ["f1", "f2", "f3", "f4", "f5"],
    ["x1", "x2", "x3", "x4", "x5"],
    ["r1", "r2", "r3", "r4", "r5"],
];

/// How the pucks meet.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Mode {
    /// `-e 0`: one body after, at the velocity of the centre of mass.
    Stick,
    /// `--fin`, with a `?` for the velocity momentum gives.
    Explode,
    /// `--positions`, `--radii`: touching balls, Newton's law at every contact at once.
    Contacts,
}

/// The answer to N pucks.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct NBodySolved {
    /// `collide solve ... --format json` of the case, as the command line prints it.
    pub state: String,
    /// The `collide solve` command line of the case.
    pub command: String,
    pub picture: NBodyPicture,
}

/// What the panel draws, in the lab, in binary64 (each value rounded once from the exact one).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct NBodyPicture {
    pub masses: Vec<f64>,
    #[serde(rename = "in")]
    pub v_in: Vec<[f64; 2]>,
    pub fin: Vec<[f64; 2]>,
    /// Momenta `m_i v_i` before and after, and their sum `P` (the same before and after);
    /// `None` where one is beyond binary64 (`1e300` at `1e300`): the page says so, never draws
    /// an infinity.
    pub momenta: Option<Momenta>,
    /// Touching balls: each centre at the instant of impact and each radius (one length unit).
    pub positions: Option<Vec<[f64; 2]>>,
    pub radii: Option<Vec<f64>>,
    /// The velocities' unit (`m/s`), when the case has one.
    pub velocity_unit: Option<String>,
}

/// Each puck's momentum before and after, and the total, `P`.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Momenta {
    pub p_in: Vec<[f64; 2]>,
    pub p_fin: Vec<[f64; 2]>,
    pub p_total: [f64; 2],
}

/// A field's text: trimmed.
fn t(s: &str) -> &str {
    s.trim()
}

/// A refusal of the command line's path in the page's words: its flags named as the panel's
/// fields.
fn page_words(message: &str) -> String {
    super::in_words(
        message,
        &[
            ("--positions", "the centres x"),
            ("--radii", "the radii R"),
            ("--fin", "the final velocities v'"),
            ("--masses", "the masses"),
            ("--contacts", "the contacts"),
            ("-e 0", "stick"),
        ],
    )
}

impl NBodyInput {
    fn mode(&self) -> Result<Mode, InputError> {
        match t(&self.mode) {
            "stick" => Ok(Mode::Stick),
            "explode" => Ok(Mode::Explode),
            "contacts" => Ok(Mode::Contacts),
            other => Err(InputError::new(
                "mode",
                format!("mode '{other}': stick, explode or contacts"),
            )),
        }
    }

    /// The lists the mode reads, with their fields: masses and velocities, and the final
    /// velocities (explode) or the centres and radii (contacts).
    fn lists(&self, mode: Mode) -> Vec<(&'static [&'static str; MOST], &Vec<String>)> {
        let mut out = vec![(&FIELDS[0], &self.masses), (&FIELDS[1], &self.velocities)];
        match mode {
            Mode::Stick => {}
            Mode::Explode => out.push((&FIELDS[2], &self.fin)),
            Mode::Contacts => {
                out.push((&FIELDS[3], &self.positions));
                out.push((&FIELDS[4], &self.radii));
            }
        }
        out
    }

    /// A list as `collide solve` takes it (`1,2 kg,3`): one value per puck, each checked to be
    /// one value.
    fn joined(fields: &[&'static str; MOST], list: &[String]) -> Result<String, InputError> {
        let mut out = Vec::new();
        for (field, text) in fields.iter().zip(list) {
            if t(text).is_empty() {
                return Err(InputError::new(field, format!("{field} is empty")));
            }
            match split_bodies(t(text)) {
                Ok(v) if v.len() == 1 => out.push(t(text)),
                Ok(v) => {
                    return Err(InputError::new(
                        field,
                        format!("'{}' is {} values: {field} is one puck's", t(text), v.len()),
                    ));
                }
                Err(e) => return Err(InputError::new(field, e)),
            }
        }
        Ok(out.join(","))
    }

    /// The field whose text an error message quotes (`'(1,0' ...`, `mass -1 must be ...`), else
    /// `default`.
    fn quoted(&self, mode: Mode, error: &str, default: &'static str) -> &'static str {
        self.lists(mode)
            .into_iter()
            .flat_map(|(fields, list)| fields.iter().zip(list.iter()))
            .filter(|(_, text)| !t(text).is_empty())
            .find(|(field, text)| {
                error.contains(&format!("'{}'", t(text)))
                    || (field.starts_with('m') && error.contains(&format!("mass {} ", t(text))))
            })
            .map_or(default, |(field, _)| field)
    }

    /// `-e`'s value as `collide solve` reads it (none for the default, `elastic`).
    fn restitution(text: &str) -> Result<Option<Given<Number>>, InputError> {
        (t(text) != "elastic")
            .then(|| {
                Given::parse(t(text), |s| {
                    s.parse::<Restitution>().map(|r| r.number().clone())
                })
                .map_err(|e| InputError::new("e", e))
            })
            .transpose()
    }

    /// Solves the pucks as `collide solve` does and answers with its JSON, the command line and
    /// the picture; an error names the panel's field.
    pub fn solve(&self) -> Result<NBodySolved, InputError> {
        let mode = self.mode()?;
        let n = self.masses.len();
        if !(2..=MOST).contains(&n) {
            return Err(InputError::new(
                "count",
                format!("the panel takes 2 to {MOST} pucks; this case has {n}"),
            ));
        }
        for (fields, list) in self.lists(mode) {
            if list.len() != n {
                return Err(InputError::new(
                    fields[list.len().min(n - 1)],
                    format!("{} values for {n} pucks: give one per puck", list.len()),
                ));
            }
        }
        let named = |e: String, default: &'static str| {
            InputError::new(self.quoted(mode, &e, default), page_words(&e))
        };
        let masses = parse_masses(&Self::joined(&FIELDS[0], &self.masses)?)
            .map_err(|e| named(e.to_string(), "m1"))?;
        let v_in = parse_list(&Self::joined(&FIELDS[1], &self.velocities)?)
            .map_err(|e| named(e.to_string(), "v1"))?;
        let fin = if mode == Mode::Explode {
            Some(
                parse_list(&Self::joined(&FIELDS[2], &self.fin)?)
                    .map_err(|e| named(e.to_string(), "f1"))?,
            )
        } else {
            None
        };
        let scalar = |v: &Typed| matches!(v, Typed::Scalar(_));
        if v_in.iter().chain(fin.iter().flatten()).all(scalar) {
            return Err(InputError::new(
                "v1",
                "the plane needs vectors: give a velocity as components, e.g. (4,0), or as \
                 speed @ angle, e.g. '6 @ 30deg' (numbers alone are bodies on a line)",
            ));
        }
        let mut input = Input {
            masses,
            v_in,
            ..Input::default()
        };
        let command = super::shell::nbody_command(self);
        if mode == Mode::Contacts {
            input.e = Self::restitution(&self.e)?;
            let balls = BallsInput {
                input,
                positions: Some(Self::joined(&FIELDS[3], &self.positions)?),
                radii: Some(
                    parse_radii(&Self::joined(&FIELDS[4], &self.radii)?)
                        .map_err(|e| named(format!("--radii: {e}"), "r1"))?,
                ),
                contacts: None,
            };
            let r = simultaneous::run(&balls, false, None).map_err(|e| {
                let m = e.to_string();
                let default = if m.contains("radi") {
                    "r1"
                } else if m.contains("posit") || m.contains("overlap") || m.contains("touch") {
                    "x1"
                } else {
                    "m1"
                };
                named(m, default)
            })?;
            let picture = picture(
                &r.outcome,
                r.balls.positions.as_deref(),
                r.balls.radii.as_deref(),
                r.balls.posed.units.velocity,
            );
            return Ok(NBodySolved {
                state: json::render(&r.json),
                command,
                picture,
            });
        }
        let explode = mode == Mode::Explode;
        if explode {
            input.fin = fin;
        } else {
            input.e = Self::restitution("0")?;
        }
        let posed = input.pose().map_err(|e| named(e.to_string(), "m1"))?;
        if posed.statement.dim != 2 {
            return Err(InputError::new(
                "v1",
                format!(
                    "the panel draws 2-vectors; these velocities have {} components",
                    posed.statement.dim
                ),
            ));
        }
        let unknown = if explode { "f1" } else { "m1" };
        let solved = solve::solve(&posed.statement).map_err(|e| named(e.to_string(), unknown))?;
        let rendered = render(
            &posed,
            &solved,
            &Options {
                frame: &Frame::Lab,
                show: Show::default(),
                exact: false,
                reverse: false,
                fin_given: explode,
                energy_unit: None,
            },
        )
        .map_err(|e| named(e.to_string(), unknown))?;
        // The outcome `solve` prints (judged once): one collision, consistent with the laws.
        let kept = match judge(&posed, &solved, explode, false)
            .map_err(|e| named(e.to_string(), unknown))?
        {
            Judged::Solutions { kept, inconsistent } if !inconsistent && kept.len() == 1 => kept,
            _ => {
                return Err(InputError::new(
                    unknown,
                    "the final velocities given contradict momentum (collide solve prints the \
                     check): leave one of them as ?",
                ));
            }
        };
        let o = &kept[0].0;
        Ok(NBodySolved {
            state: json::render(&rendered.json),
            command,
            picture: picture(o, None, None, posed.units.velocity),
        })
    }
}

/// The picture of an outcome in the plane: each value rounded once from the exact one.
fn picture(
    o: &Outcome,
    positions: Option<&[Vec<Q>]>,
    radii: Option<&[Q]>,
    velocity_unit: Option<&str>,
) -> NBodyPicture {
    let f = |q: &Q| to_f64(q).unwrap_or(f64::NAN);
    let pair = |v: &[Q]| [f(&v[0]), f(&v[1])];
    let all = |vs: &[Vec<Q>]| vs.iter().map(|v| pair(v)).collect::<Vec<_>>();
    let momenta = |vs: &[Vec<Q>]| {
        vs.iter()
            .zip(&o.masses)
            .map(|(v, m)| [f(&(&v[0] * m)), f(&(&v[1] * m))])
            .collect::<Vec<_>>()
    };
    let p = Momenta {
        p_in: momenta(&o.v_in),
        p_fin: momenta(&o.fin),
        p_total: pair(&o.momentum(&o.v_in)),
    };
    let finite = p
        .p_in
        .iter()
        .chain(&p.p_fin)
        .chain([&p.p_total])
        .all(|q| q.iter().all(|x| x.is_finite()));
    NBodyPicture {
        masses: o.masses.iter().map(f).collect(),
        v_in: all(&o.v_in),
        fin: all(&o.fin),
        momenta: finite.then_some(p),
        positions: positions.map(all),
        radii: radii.map(|r| r.iter().map(f).collect()),
        velocity_unit: velocity_unit.map(str::to_string),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn case(mode: &str, m: &[&str], v: &[&str]) -> NBodyInput {
        NBodyInput {
            mode: mode.into(),
            masses: m.iter().map(|s| s.to_string()).collect(),
            velocities: v.iter().map(|s| s.to_string()).collect(),
            fin: vec![],
            positions: vec![],
            radii: vec![],
            e: "elastic".into(),
        }
    }

    #[test]
    fn three_pucks_stick_at_the_centre_of_mass_velocity() {
        // p = (1,0) + 2 (0,1) + 3 (-1,-1) = (-2, -1), M = 6: V = (-1/3, -1/6) for all three,
        // each coordinate the binary64 nearest (one rounding of the exact fraction).
        let a = case("stick", &["1", "2", "3"], &["(1,0)", "(0,1)", "(-1,-1)"])
            .solve()
            .unwrap();
        let v = [-1.0 / 3.0, -1.0 / 6.0];
        assert_eq!(a.picture.fin, vec![v; 3]);
        let p = a.picture.momenta.unwrap();
        assert_eq!(p.p_total, [-2.0, -1.0]);
        assert_eq!(p.p_fin[2], [-1.0, -0.5]);
        assert_eq!(
            a.command,
            "collide solve -m 1,2,3 -v '(1,0),(0,1),(-1,-1)' -e 0"
        );
    }

    #[test]
    fn a_bad_puck_names_its_field() {
        let e = case("stick", &["1", "-2", "3"], &["(1,0)", "(0,1)", "(-1,-1)"])
            .solve()
            .unwrap_err();
        assert_eq!(e.field, "m2", "{e:?}");
        let e = case("stick", &["1"], &["(1,0)"]).solve().unwrap_err();
        assert_eq!(e.field, "count", "{e:?}");
        let mut c = case("contacts", &["1", "1"], &["(1,0)", "0"]);
        c.positions = vec!["(0,0)".into(), "(1,0)".into()];
        c.radii = vec!["1".into(), "1".into()];
        // Centres 1 apart with radii 1 and 1 overlap (2 would touch).
        let e = c.solve().unwrap_err();
        assert!(
            e.field.starts_with('x') || e.field.starts_with('r'),
            "{e:?}"
        );
    }
}
