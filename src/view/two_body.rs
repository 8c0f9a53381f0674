//! One collision for the page's velocity plane and dual panel: the inputs as typed (`m1`, `m2`,
//! `v1`, `v2`, `e`, or a tensor), solved by the same path as `collide solve`, answered with the
//! report JSON that `collide solve --format json` prints (byte for byte), the command line and
//! scene that reproduce it, and the geometry the page draws (lecture Figs. 1.3, 2.3 and 2.5).

use serde::Serialize;

use crate::line::case::parse_inertia;
use crate::line::collision::Collision;
use crate::line::frame::Frame;
use crate::line::problem::{Posed, Problem};
use crate::line::restitution::Restitution;
use crate::report::{AnyReport, Report, Section, Sections, json, solved};
use crate::solver::{Lab, Solver};
use crate::values::number::Given;
use crate::values::units::{Dimension, HeightScale, parse_pair};

use super::InputError;
use super::input::CaseInput;

/// The answer to a case.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Solved {
    /// `collide solve ... --format json` of the case, as the command line prints it.
    pub state: String,
    /// The `collide solve` command line of the case.
    pub command: String,
    /// The same case as a scene file (`collide scene FILE.toml`).
    pub scene: String,
    pub picture: Picture,
}

/// What the velocity plane and the space-time diagrams show, in the chosen frame.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Picture {
    /// The frame's observer velocity.
    pub w: f64,
    pub e: f64,
    pub inertia: [[f64; 2]; 2],
    #[serde(rename = "in")]
    pub v_in: [f64; 2],
    pub com: [f64; 2],
    pub fin: [f64; 2],
    /// The bodies meet (`V1 != V2`; the body faster in `+x` is on the left).
    pub approaching: bool,
    /// `2` when body 2 is on the left (`V1 < V2`); absent when body 1 is.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub left: Option<u8>,
    /// The momentum line `k1 V1 + k2 V2 = P_total`, as `[k1, k2, P_total]`.
    pub line: [f64; 3],
    /// The IN, COM and FIN energy ellipses `1/2 V.M.V = KE`.
    pub ellipses: Ellipses,
    /// `M^(1/2)`: "Space vs Space" scaled by it turns every energy ellipse into a circle and an
    /// elastic collision into a reflection in the line `x1 = x2` (lecture Sec. 3).
    pub sqrt_m: [[f64; 2]; 2],
    /// The standard frames (Fig. 2.5), each with its observer velocity and points.
    pub frames: Vec<FramePoints>,
    /// The time-reversed collision (`--reverse`): `IN' = -FIN`, `FIN' = -IN`, `e' = 1/e`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub reverse: Option<Reversed>,
    /// The bodies' momenta `P = M V` before and after, as `collide solve --show momentum` prints
    /// them (the page's momentum bars).
    pub momentum: Momenta,
    /// The bodies' kinetic energies `1/2 M_i V_i^2` before and after (the page's energy bars;
    /// they add up to the ellipses' `ke`). `None` for a general tensor, whose energy
    /// `1/2 V.M.V` has cross terms that belong to neither body.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub kinetic: Option<Kinetic>,
}

/// Each body's momentum before and after, and the total (the same before and after).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Momenta {
    #[serde(rename = "in")]
    pub p_in: [f64; 2],
    pub fin: [f64; 2],
    pub total: f64,
}

/// Each body's kinetic energy before and after.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Kinetic {
    #[serde(rename = "in")]
    pub ke_in: [f64; 2],
    pub fin: [f64; 2],
}

#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Ellipses {
    #[serde(rename = "in")]
    pub e_in: Shape,
    pub com: Shape,
    pub fin: Shape,
}

/// An ellipse centred on the frame's origin: radii `a`, `b` along the unit `axes`, and its
/// energy.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Shape {
    pub ke: f64,
    pub a: f64,
    pub b: f64,
    pub axes: [[f64; 2]; 2],
}

#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct FramePoints {
    /// The frame's word on the command line (`com`, `rest-in:1`, ...).
    pub name: String,
    pub label: String,
    pub w: f64,
    #[serde(rename = "in")]
    pub v_in: [f64; 2],
    pub com: [f64; 2],
    pub fin: [f64; 2],
}

#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Reversed {
    #[serde(rename = "in")]
    pub v_in: [f64; 2],
    pub fin: [f64; 2],
    pub equals_original: bool,
}

/// The typed values as `collide solve` would read them.
struct Typed {
    problem: Problem,
    inertia: Option<crate::line::inertia::InertiaTensor>,
    frame: Frame,
}

impl CaseInput {
    fn typed(&self) -> Result<Typed, InputError> {
        let (masses, inertia) = match &self.inertia {
            Some(t) => (
                None,
                Some(parse_inertia(t).map_err(|e| InputError::new("inertia", e))?),
            ),
            None => {
                let masses = parse_pair(
                    &format!("{},{}", self.m1, self.m2),
                    Dimension::Mass,
                    "masses M1,M2",
                )
                .map_err(|e| self.error(e, "m1"))?;
                (Some(masses), None)
            }
        };
        let velocities = parse_pair(
            &format!("{},{}", self.v1, self.v2),
            Dimension::Velocity,
            "velocities V1,V2",
        )
        .map_err(|e| self.error(e, "v1"))?;
        let restitution = Given::parse(&self.e, str::parse::<Restitution>)
            .map_err(|e| InputError::new("e", e))?;
        let frame: Frame = self
            .frame
            .parse()
            .map_err(|e| InputError::new("frame", e))?;
        let problem = Problem {
            masses,
            velocities,
            fin: None,
            restitution: Some(restitution),
            si: false,
            gravity: None,
            energy_unit: None,
            exact: self.exact,
            knowns: Default::default(),
            velocity_unit: None,
        };
        if problem.has_unknowns() {
            return Err(InputError::new(
                "e",
                "'?' marks an unknown, which `collide solve` solves for: the page draws a \
                 collision whose masses, velocities and e are all given",
            ));
        }
        Ok(Typed {
            problem,
            inertia,
            frame,
        })
    }

    /// The field whose text an error message quotes (`mass '-1' must be ...`), else `default`.
    fn quoted(&self, error: &str, default: &'static str) -> &'static str {
        let fields = [
            ("m1", &self.m1),
            ("m2", &self.m2),
            ("v1", &self.v1),
            ("v2", &self.v2),
            ("e", &self.e),
        ];
        fields
            .into_iter()
            .find(|(_, text)| error.contains(&format!("'{}'", text.trim())))
            .map_or(default, |(field, _)| field)
    }

    /// An error, in the field it quotes.
    fn error(&self, e: impl std::fmt::Display, default: &'static str) -> InputError {
        let message = e.to_string();
        InputError::new(self.quoted(&message, default), message)
    }

    /// A report that cannot be printed (a value beyond binary64), at the field typed with the
    /// largest or smallest number (not always m1), in the page's words.
    fn beyond_binary64(&self, e: impl std::fmt::Display) -> InputError {
        let message = e.to_string().replace(
            "use --exact, rescale the units, or ask only for other sections with --show",
            "rescale the units (collide solve --exact computes it in fractions)",
        );
        let field = if self.reverse {
            "reverse"
        } else {
            super::input::largest_field(&[
                ("m1", &self.m1),
                ("m2", &self.m2),
                ("v1", &self.v1),
                ("v2", &self.v2),
                ("e", &self.e),
            ])
        };
        InputError::new(field, message)
    }

    /// Solves the case as `collide solve` does and answers with its JSON, command line, scene
    /// and picture; a result beyond binary64 refused in the page's words.
    pub fn solve(&self) -> Result<Solved, InputError> {
        self.solve_with(|e| self.beyond_binary64(e))
    }

    /// [`CaseInput::solve`] with every refusal in the command line's words (the Python
    /// module's errors).
    pub fn solve_typed(&self) -> Result<Solved, InputError> {
        self.solve_with(|e| InputError::new("m1", e))
    }

    fn solve_with(
        &self,
        beyond: impl Fn(crate::report::ReportError) -> InputError,
    ) -> Result<Solved, InputError> {
        let typed = self.typed()?;
        let case = match typed.problem.solve(typed.inertia) {
            Ok(Posed::Collision(case, _)) => case,
            Ok(Posed::Separation(..) | Posed::Separations(..)) => {
                return Err(InputError::new(
                    "v2",
                    "the bodies start together (V1 = V2) and are pushed apart: a separation, \
                     which `collide solve` describes; the page draws collisions",
                ));
            }
            Ok(Posed::Wall(..)) => {
                return Err(InputError::new(
                    "m1",
                    "a wall (an immovable body) has no velocity plane: `collide solve` solves \
                     it; the page draws a collision of two movable bodies",
                ));
            }
            Err(e) => return Err(self.error(e, "m1")),
        };
        // `collide solve --format json`: its default sections, units and heights.
        let mut sections = Sections::new(Section::DEFAULT);
        sections.heights = Some(HeightScale::new(None, &case.units));
        sections.energy_scale = case.units.energy_scale();
        sections.force_scale = case.units.force_scale();
        let frame = &typed.frame;
        let report =
            AnyReport::of(&case, frame, self.exact, &sections, self.reverse).map_err(beyond)?;
        let mut value = report.json();
        solved::annotate(&mut value, &case.units, None, self.exact);
        Ok(Solved {
            state: json::render(&value),
            command: super::shell::solve_command(self),
            scene: super::shell::solve_scene(self),
            picture: picture(&case.collision, frame, self.reverse)
                .map_err(|e| InputError::new("m1", e))?,
        })
    }
}

/// The picture of `c` seen from `frame`.
pub(super) fn picture(
    c: &Collision,
    frame: &Frame,
    reverse: bool,
) -> Result<Picture, crate::report::ReportError> {
    let drawn = Sections::new([
        Section::Vectors,
        Section::Momentum,
        Section::Energy,
        Section::Ellipses,
    ]);
    let r: Report<f64> = Report::of(c, frame, &drawn, reverse)?;
    let (Some(v), Some(m), Some(energy), Some(ell)) =
        (&r.vectors, &r.momentum, &r.energy, &r.ellipses)
    else {
        unreachable!("the sections asked for are computed");
    };
    let shape = |e: &crate::line::ellipse::Ellipse<f64>, ke: f64| Shape {
        ke,
        a: e.a,
        b: e.b,
        axes: e.axes.unwrap_or([[1.0, 0.0], [0.0, 1.0]]),
    };
    let (k1, k2, _) = r.notes.line;
    let momentum = Momenta {
        p_in: m.p_in,
        fin: m.fin,
        total: m.total,
    };
    let frames = Frame::standard()
        .into_iter()
        .map(|f| {
            let (w, seen) = c.seen_from(&f);
            let vc = seen.v_com();
            FramePoints {
                name: f.to_string(),
                label: f.describe(),
                w,
                v_in: seen.v_in(),
                com: [vc, vc],
                fin: seen.v_fin(),
            }
        })
        .collect();
    Ok(Picture {
        w: r.frame.as_ref().map_or(0.0, |f| f.w),
        e: r.restitution,
        inertia: r.inertia,
        v_in: v.v_in,
        com: v.com,
        fin: v.fin,
        approaching: v.approaching,
        left: v.left,
        line: [k1, k2, m.total],
        ellipses: Ellipses {
            e_in: shape(&ell.e_in, energy.ke_in),
            com: shape(&ell.com, energy.com),
            fin: shape(&ell.fin, energy.fin),
        },
        sqrt_m: sqrt_m(&c.inertia),
        frames,
        reverse: r.reverse.map(|x| Reversed {
            v_in: x.v_in,
            fin: x.fin,
            equals_original: x.equals_original,
        }),
        kinetic: kinetic(&r.inertia, &momentum, &v.v_in, &v.fin),
        momentum,
    })
}

/// `KE_i = 1/2 P_i V_i` of each body before and after, from the report's momenta `P_i = M_i V_i`
/// (a product, nothing cancels; halving `V_i` first is exact, and `P_i V_i` never passes through
/// `V_i^2`, which overflows for `V = 1e308` while `1/2 M V^2` with `M = 1e-308` does not), for
/// diagonal masses; `None` for a general tensor.
fn kinetic(m: &[[f64; 2]; 2], p: &Momenta, v_in: &[f64; 2], fin: &[f64; 2]) -> Option<Kinetic> {
    if m[0][1] != 0.0 || m[1][0] != 0.0 {
        return None;
    }
    let each = |p: &[f64; 2], v: &[f64; 2]| [p[0] * (0.5 * v[0]), p[1] * (0.5 * v[1])];
    Some(Kinetic {
        ke_in: each(&p.p_in, v_in),
        fin: each(&p.fin, fin),
    })
}

/// `M^(1/2) = sum sqrt(lambda_i) q_i q_i^T` over the principal axes (`diag(sqrt M1, sqrt M2)` for
/// masses).
fn sqrt_m(m: &crate::line::inertia::InertiaTensor) -> [[f64; 2]; 2] {
    if m.is_diagonal() {
        let d = m.matrix();
        return [[d[(0, 0)].sqrt(), 0.0], [0.0, d[(1, 1)].sqrt()]];
    }
    let mut s = [[0.0; 2]; 2];
    for (lambda, q) in m.principal_axes() {
        let r = lambda.sqrt();
        for (i, row) in s.iter_mut().enumerate() {
            for (j, x) in row.iter_mut().enumerate() {
                *x += r * q[i] * q[j];
            }
        }
    }
    s
}
