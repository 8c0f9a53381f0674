//! Two pucks in the plane for the page's third panel: the inputs as typed (`m1`, `m2`, `v1`,
//! `v2` as vectors, `e`, and the line of impact as `normal`, or as the radii `r1`, `r2` and the
//! impact parameter `b` of smooth disks), posed and solved by the same path as `collide solve`
//! in the plane (`space::pose`, `space::solve`, `report::space::solved::render`), answered with
//! the JSON that `collide solve --format json` prints (byte for byte), the command line and scene
//! that reproduce it, and what the page draws: the pucks with their velocity arrows, the
//! momentum triangles `p1 + p2 = P = p1' + p2'` and the lecture's velocity plane of the normal
//! parts `(v1.n, v2.n)` (physics.md section 7).

use serde::Serialize;

use crate::line::case::Case;
use crate::line::frame::Frame;
use crate::line::inertia::{InertiaTensor, Mass};
use crate::line::restitution::Restitution;
use crate::report::json;
use crate::report::space::Show;
use crate::report::space::solved::{Judged, Options, RenderError, Verdict, judge, render};
use crate::space::outcome::{Outcome, angle_between, dot, polar};
use crate::space::pose::{Input, NormalGiven, Posed};
use crate::space::solve;
use crate::space::typed::{Typed, parse_masses, split_bodies};
use crate::values::number::{Given, Number};
use crate::values::rational::{Q, to_f64};

use super::InputError;
use super::input::{PlaneInput, largest_field};
use super::two_body::Picture as RailPicture;

/// The answer to two pucks.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct PlaneSolved {
    /// `collide solve ... --format json` of the case, as the command line prints it.
    pub state: String,
    /// The `collide solve` command line of the case.
    pub command: String,
    /// The same case as a scene file (`collide scene FILE.toml`).
    pub scene: String,
    pub picture: PlanePicture,
}

/// What the panel draws, in the frame asked for, in binary64 (each value rounded once from the
/// exact one).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct PlanePicture {
    /// The frame's observer velocity.
    pub w: [f64; 2],
    pub masses: [f64; 2],
    /// Restitution, where it means something (not for pucks that do not meet).
    pub e: Option<f64>,
    /// The line of impact as a unit vector from body 1 to body 2, and its angle from +x.
    pub normal: Option<[f64; 2]>,
    pub normal_deg: Option<f64>,
    /// The disks' radii and impact parameter, when the line of impact comes from them.
    pub radii: Option<[f64; 2]>,
    pub b: Option<f64>,
    /// The velocities' unit (`m/s`), when the case has one.
    pub velocity_unit: Option<String>,
    #[serde(rename = "in")]
    pub v_in: [[f64; 2]; 2],
    /// `None` when the pucks do not approach along the line of impact: no collision.
    pub fin: Option<[[f64; 2]; 2]>,
    /// `[speed, angle in degrees]` of `v1`, `v2` (the angle `None` for a zero vector).
    pub in_polar: [(f64, Option<f64>); 2],
    pub v_com: [f64; 2],
    pub v_com_polar: (f64, Option<f64>),
    /// Momenta `m_i v_i` before and after, and their sum `P` (the same before and after).
    pub p_in: [[f64; 2]; 2],
    pub p_fin: Option<[[f64; 2]; 2]>,
    pub p_total: [f64; 2],
    /// Each body's kinetic energy `1/2 m_i |v_i|^2` before and after (exact, rounded once):
    /// the page's energy bars (they add up to the report's `energy.in` and `energy.fin`).
    pub ke_in: [f64; 2],
    pub ke_fin: Option<[f64; 2]>,
    /// The impulse on body 2, `m2 (v2' - v2)`.
    pub impulse: Option<[f64; 2]>,
    /// Whether the pucks approach along the line of impact, `n.(v1 - v2) > 0`.
    pub approaching: bool,
    /// The angle between `v1 - v2` and the line of impact (degrees), with one.
    pub phi_deg: Option<f64>,
    /// The lecture's velocity plane of the normal parts `(v1.n, v2.n)`, `|n| = 1`: the same
    /// masses and e as a collision on a rail (`None` without a line of impact or a collision).
    pub normal_parts: Option<RailPicture>,
}

/// A field's text: trimmed.
fn t(s: &str) -> &str {
    s.trim()
}

impl PlaneInput {
    /// The line of impact as typed, if any, checked for the fields it needs.
    fn line_of_impact(&self) -> Result<Option<NormalGiven>, InputError> {
        let disks = [&self.r1, &self.r2, &self.b]
            .iter()
            .any(|s| !t(s).is_empty());
        if !t(&self.normal).is_empty() {
            if disks {
                return Err(InputError::new(
                    "normal",
                    "give the line of impact as --normal, or as --radii with \
                     --impact-parameter, not both",
                ));
            }
            return t(&self.normal)
                .parse::<NormalGiven>()
                .map(Some)
                .map_err(|e| InputError::new("normal", format!("--normal: {e}")));
        }
        if self.line == "normal" {
            return Err(InputError::new(
                "normal",
                "the line of impact n is missing: give its angle (30deg, N30E) or its direction \
                 ((1,1)), or choose none (then only e = 0 fixes the outcome)",
            ));
        }
        if !disks && self.line != "disks" {
            return Ok(None);
        }
        // Numbers, or lengths with units (`2.5 cm`), read as `collide solve --radii` reads them.
        let length = |field: &'static str, text: &str, what: &str| {
            if t(text).is_empty() {
                return Err(InputError::new(
                    field,
                    format!("{what} is missing: the disks need R1, R2 and the impact parameter B"),
                ));
            }
            crate::values::units::parse(t(text), crate::values::units::Dimension::Length)
                .map_err(|e| InputError::new(field, format!("{what} '{}': {e}", t(text))))
        };
        let r1 = length("r1", &self.r1, "radius R1")?;
        let r2 = length("r2", &self.r2, "radius R2")?;
        let b = length("b", &self.b, "impact parameter B")?;
        let (radii, b) = crate::space::pose::geometry([&r1, &r2], &b).map_err(|e| {
            // The field whose unit is missing, or extra.
            let unit = [r1.unit.is_some(), r2.unit.is_some(), b.unit.is_some()];
            let odd = if unit[0] == unit[1] {
                "b"
            } else if unit[0] == unit[2] {
                "r2"
            } else {
                "r1"
            };
            InputError::new(odd, e)
        })?;
        Ok(Some(NormalGiven::Geometry { radii, b }))
    }

    /// The typed fields with their names.
    fn fields(&self) -> [(&'static str, &String); 9] {
        [
            ("m1", &self.m1),
            ("m2", &self.m2),
            ("v1", &self.v1),
            ("v2", &self.v2),
            ("e", &self.e),
            ("normal", &self.normal),
            ("r1", &self.r1),
            ("r2", &self.r2),
            ("b", &self.b),
        ]
    }

    /// The fields a `?` (an unknown) may not be in: the page draws a case with every value given.
    fn no_unknowns(&self) -> Result<(), InputError> {
        match self
            .fields()
            .into_iter()
            .find(|(_, text)| text.contains('?'))
        {
            Some((field, _)) => Err(InputError::new(
                field,
                "'?' marks an unknown, which `collide solve` solves for: the page draws a \
                 collision whose masses, velocities and e are all given",
            )),
            None => Ok(()),
        }
    }

    /// The problem as `collide solve` would read it from the command line of [`Self::command`].
    fn input(&self) -> Result<Input, InputError> {
        self.no_unknowns()?;
        fn one<'a>(field: &'static str, text: &'a str) -> Result<&'a str, InputError> {
            if t(text).is_empty() {
                let what = if field.starts_with('m') {
                    "a mass, e.g. 1 or 1500 kg"
                } else {
                    "a velocity, e.g. (4,0) or '6 @ 30deg'"
                };
                return Err(InputError::new(
                    field,
                    format!("{field} is empty: give {what}"),
                ));
            }
            match split_bodies(text) {
                Ok(list) if list.len() == 1 => Ok(list[0]),
                Ok(list) => Err(InputError::new(
                    field,
                    format!(
                        "'{}' is {} values: {field} is one body's, e.g. (4,0) or '6 @ 30deg' \
                         for a velocity",
                        t(text),
                        list.len()
                    ),
                )),
                Err(e) => Err(InputError::new(field, e)),
            }
        }
        let mut masses = Vec::new();
        for (field, text) in [("m1", &self.m1), ("m2", &self.m2)] {
            let m = parse_masses(one(field, text)?).map_err(|e| InputError::new(field, e))?;
            masses.extend(m);
        }
        let mut v_in = Vec::new();
        for (field, text) in [("v1", &self.v1), ("v2", &self.v2)] {
            v_in.push(Typed::parse(one(field, text)?).map_err(|e| InputError::new(field, e))?);
        }
        if v_in.iter().all(|v| matches!(v, Typed::Scalar(_))) {
            return Err(InputError::new(
                "v1",
                "the plane needs vectors: give v1 or v2 as components, e.g. (4,0), or as speed \
                 @ angle, e.g. '6 @ 30deg' (numbers alone are a collision on a line)",
            ));
        }
        // No -e on the command line for the default, as `collide solve` reads it.
        let e = (t(&self.e) != "elastic")
            .then(|| {
                Given::parse(t(&self.e), |s| {
                    s.parse::<Restitution>().map(|r| r.number().clone())
                })
                .map_err(|e| InputError::new("e", e))
            })
            .transpose()?;
        Ok(Input {
            masses,
            v_in,
            fin: None,
            normal: self.line_of_impact()?,
            e,
            si: false,
            exact: self.exact,
        })
    }

    /// The field whose text an error message quotes (`mass '-1' must be ...`), else `default`.
    fn quoted(&self, error: &str, default: &'static str) -> &'static str {
        self.fields()
            .into_iter()
            .filter(|(_, text)| !t(text).is_empty())
            .find(|(_, text)| error.contains(&format!("'{}'", t(text))))
            .map_or(default, |(field, _)| field)
    }

    /// Solves the case as `collide solve` does and answers with its JSON, command line, scene
    /// and picture; an error in the page's words (its fields, not the command line's flags).
    pub fn solve(&self) -> Result<PlaneSolved, InputError> {
        self.solve_typed().map_err(|e| self.in_page_words(e))
    }

    /// An error of the command line's path as the page says it: a case without a line of
    /// impact that needs one, a result beyond binary64 at the largest value typed, and the
    /// flags named as the page's fields.
    fn in_page_words(&self, e: InputError) -> InputError {
        let no_line = t(&self.normal).is_empty()
            && [&self.r1, &self.r2, &self.b]
                .iter()
                .all(|s| t(s).is_empty());
        if no_line
            && (e.error.contains("unknowns and") || e.error.contains("without a line of impact"))
        {
            return InputError::new(
                "e",
                "without a line of impact only e = 0 (the pucks stick) fixes the outcome: set \
                 e = 0, or give the line of impact (at an angle, or disks)",
            );
        }
        let field = if e.error.contains("beyond binary64") || e.error.contains("representable") {
            largest_field(&self.fields())
        } else {
            e.field
        };
        InputError::new(field, page_words(&e.error))
    }

    /// [`PlaneInput::solve`] with every refusal in the command line's words (the Python
    /// module's errors).
    pub fn solve_typed(&self) -> Result<PlaneSolved, InputError> {
        let input = self.input()?;
        let frame: Frame = t(&self.frame)
            .parse()
            .map_err(|e| InputError::new("frame", e))?;
        let posed = input.pose().map_err(|e| {
            let message = e.to_string();
            let number = |text: &str| text.split_whitespace().next().map(str::to_string);
            let default = match e {
                crate::space::pose::PoseError::Mass(m) if number(&self.m2) == Some(m.clone()) => {
                    "m2"
                }
                crate::space::pose::PoseError::Miss { .. } => "b",
                crate::space::pose::PoseError::Radius(_) => "r1",
                crate::space::pose::PoseError::NormalSize(..)
                | crate::space::pose::PoseError::ZeroNormal
                | crate::space::pose::PoseError::Irrational { .. } => "normal",
                crate::space::pose::PoseError::GeometryVelocities => "v2",
                _ => "m1",
            };
            InputError::new(self.quoted(&message, default), message)
        })?;
        if posed.statement.dim != 2 {
            return Err(InputError::new(
                "v1",
                format!(
                    "the plane panel draws 2-vectors; these velocities have {} components",
                    posed.statement.dim
                ),
            ));
        }
        let solved = solve::solve(&posed.statement).map_err(|e| InputError::new("e", e))?;
        let rendered = render(
            &posed,
            &solved,
            &Options {
                frame: &frame,
                show: Show::default(),
                exact: self.exact,
                reverse: self.reverse,
                fin_given: false,
                energy_unit: None,
            },
        )
        .map_err(|e| {
            let field = match e {
                RenderError::Frame(_) => "frame",
                _ if self.reverse => "reverse",
                _ => "m1",
            };
            InputError::new(field, e)
        })?;
        let picture = self.picture(&posed, &solved, &frame)?;
        Ok(PlaneSolved {
            state: json::render(&rendered.json),
            command: super::shell::plane_command(self),
            scene: super::shell::plane_scene(self),
            picture,
        })
    }

    /// The picture of the solution `render` prints: the physical one, seen from `frame`.
    fn picture(
        &self,
        posed: &Posed,
        solved: &solve::Solved,
        frame: &Frame,
    ) -> Result<PlanePicture, InputError> {
        // The outcome `solve` prints (judged once): pucks that do not approach do not collide,
        // FIN = IN for a "finally at rest" frame.
        let judged = judge(posed, solved, false, false).map_err(|e| InputError::new("m1", e))?;
        let (lab, collides) = match judged {
            Judged::Receding { o, .. } => (*o, false),
            Judged::Solutions { kept, .. } => {
                let (o, _, v) = kept
                    .into_iter()
                    .next()
                    .ok_or_else(|| InputError::new("m1", RenderError::NoSolution))?;
                (o, v == Verdict::Physical)
            }
        };
        let seen = if collides {
            lab.clone()
        } else {
            lab.as_happens()
        };
        let w = seen
            .observer(frame, posed.typed_values)
            .map_err(|e| InputError::new("frame", e))?;
        let o = lab.boost(&w, seen.observer_approx(frame));
        let approaching = match &o.normal {
            Some(n) => dot(n, &crate::space::outcome::sub(&o.v_in[0], &o.v_in[1])) > Q::ZERO,
            None => true,
        };
        let collides = approaching && collides;
        let f = |q: &Q| to_f64(q).unwrap_or(f64::NAN);
        let pair = |v: &[Q]| [f(&v[0]), f(&v[1])];
        let both = |vs: &[Vec<Q>]| [pair(&vs[0]), pair(&vs[1])];
        let momenta = |vs: &[Vec<Q>]| {
            let p = |i: usize| -> Vec<Q> { vs[i].iter().map(|x| x * &o.masses[i]).collect() };
            [pair(&p(0)), pair(&p(1))]
        };
        let unit = o.normal.as_ref().map(|n| {
            let (x, y) = (f(&n[0]), f(&n[1]));
            let len = libm::hypot(x, y);
            [x / len, y / len]
        });
        let geometry = match self.line_of_impact()? {
            Some(NormalGiven::Geometry { radii, b }) => Some((radii, b)),
            _ => None,
        };
        let relative = crate::space::outcome::sub(&o.v_in[0], &o.v_in[1]);
        Ok(PlanePicture {
            w: pair(&w),
            masses: [f(&o.masses[0]), f(&o.masses[1])],
            e: o.e.as_ref().map(f),
            normal: unit,
            normal_deg: unit.map(|[x, y]| libm::atan2(y, x).to_degrees()),
            radii: geometry.as_ref().map(|(r, _)| [r[0].value(), r[1].value()]),
            b: geometry.as_ref().map(|(_, b)| b.value()),
            velocity_unit: posed.units.velocity.map(str::to_string),
            v_in: both(&o.v_in),
            fin: collides.then(|| both(&o.fin)),
            in_polar: [polar(&o.v_in[0]), polar(&o.v_in[1])],
            v_com: pair(&o.v_com()),
            v_com_polar: polar(&o.v_com()),
            p_in: momenta(&o.v_in),
            p_fin: collides.then(|| momenta(&o.fin)),
            p_total: pair(&o.momentum(&o.v_in)),
            ke_in: pair(&o.kinetic_each(&o.v_in)),
            ke_fin: collides.then(|| pair(&o.kinetic_each(&o.fin))),
            impulse: collides.then(|| pair(&o.impulse(1))),
            approaching,
            phi_deg: o.normal.as_ref().and_then(|n| angle_between(&relative, n)),
            normal_parts: if collides {
                normal_parts(&o, self.reverse)
            } else {
                None
            },
        })
    }
}

/// A command line's message in the page's words: its flags named as the page's fields.
pub(super) fn page_words(message: &str) -> String {
    super::in_words(
        message,
        &[
            ("--impact-parameter", "the impact parameter b"),
            ("--radii", "the radii R1, R2"),
            ("--normal", "the line of impact n"),
            ("--exact", "'exact (fractions)'"),
            ("--show", "the report's sections"),
        ],
    )
}

/// The velocity plane of the normal parts: the masses, the velocities' components along the
/// unit normal and the same e, as a collision on a rail (physics.md section 7: the tangential
/// parts pass unchanged), with its time reverse when asked (not for e = 0, which has none).
/// `None` where a value does not fit binary64.
fn normal_parts(o: &Outcome, reverse: bool) -> Option<RailPicture> {
    let parts = o.normal_parts()?;
    let q = |x: &Q| to_f64(x).filter(|v| v.is_finite());
    let mass = |i: usize| Mass::from_f64(q(&o.masses[i])?).ok();
    let speed = |x: &Q| Number::from_f64(q(x)?).ok();
    let inertia = InertiaTensor::diagonal(&mass(0)?, &mass(1)?).ok()?;
    let e = Restitution::new(Number::from_f64(q(o.e.as_ref()?)?).ok()?).ok()?;
    let case = Case::new(inertia, [speed(&parts.v_in[0])?, speed(&parts.v_in[1])?], e);
    let reverse = reverse && o.e.as_ref().is_some_and(|e| !e.is_zero());
    super::two_body::picture(&case.collision, &Frame::Lab, reverse).ok()
}
