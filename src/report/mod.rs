//! What is printed, and how. The two-body report: the sections a user asked for, each computed
//! only when asked for, as one serializable structure that the text and JSON formats render;
//! and the renderers of the other commands' results (frames, tables of methods, tracks, scenes).

#[cfg(feature = "cli")]
pub mod accuracy;
pub mod asked;
pub mod block;
#[cfg(feature = "cli")]
pub mod contact;
pub mod floor;
pub mod frames;
pub mod json;
pub mod not_shown;
pub mod pi;
pub mod range;
pub mod rigid;
#[cfg(feature = "cli")]
pub mod scene;
pub mod sections;
pub mod separation;
pub mod simultaneous;
pub mod solved;
pub mod space;
pub mod special;
pub mod stages;
pub mod text;
pub mod track;
pub mod wall;

use crate::values::rational::Q;
use serde::{Deserialize, Serialize};

use crate::line::case::Case;
use crate::line::changes::Changes;
use crate::line::ellipse::Ellipse;
use crate::line::frame::Frame;
use crate::line::unknowns::Solved;
use crate::solver::exact::ExactCollision;
use crate::solver::{Lab, Solver};
use crate::values::quantity::{Exact, Scalar};
pub use sections::{Section, Sections};

/// `"frame": {"name": "com", "w": 2.0}` in JSON.
#[derive(Clone, Debug, Serialize, PartialEq)]
pub struct FrameInfo<N> {
    pub name: String,
    pub w: N,
}

/// The solved collision, with the requested sections filled in. Field names are the JSON schema.
/// `N` is `f64`, or `Exact` with `--exact`.
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
#[serde(bound(deserialize = "N: Deserialize<'de> + Default"))]
pub struct Report<N = f64> {
    pub restitution: N,
    pub inertia: [[N; 2]; 2],
    /// The frame, when not the lab (`--frame`).
    #[serde(
        default = "none",
        skip_deserializing,
        skip_serializing_if = "Option::is_none"
    )]
    pub frame: Option<FrameInfo<N>>,
    #[serde(flatten, default = "none", skip_serializing_if = "Option::is_none")]
    pub vectors: Option<Vectors<N>>,
    #[serde(default = "none", skip_serializing_if = "Option::is_none")]
    pub momentum: Option<Momentum<N>>,
    #[serde(default = "none", skip_serializing_if = "Option::is_none")]
    pub forms: Option<Forms<N>>,
    #[serde(default = "none", skip_serializing_if = "Option::is_none")]
    pub energy: Option<Energy<N>>,
    #[serde(default = "none", skip_serializing_if = "Option::is_none")]
    pub ellipses: Option<Ellipses<N>>,
    #[serde(default = "none", skip_serializing_if = "Option::is_none")]
    pub products: Option<Products<N>>,
    #[serde(default = "none", skip_serializing_if = "Option::is_none")]
    pub changes: Option<ChangeReport<N>>,
    #[serde(default = "none", skip_serializing_if = "Option::is_none")]
    pub heights: Option<Heights<N>>,
    /// What a homework problem asks beyond the sections (`--spring`).
    #[serde(flatten, default)]
    pub asked: asked::AskedReport<N>,
    #[serde(default = "none", skip_serializing_if = "Option::is_none")]
    pub diagnostics: Option<Diagnostics>,
    /// The time-reversed collision (`--reverse`).
    #[serde(
        default = "none",
        skip_deserializing,
        skip_serializing_if = "Option::is_none"
    )]
    pub reverse: Option<Reverse<N>>,
    /// What the text notes quote (not part of the JSON schema).
    #[serde(skip)]
    pub notes: Notes<N>,
}

fn none<T>() -> Option<T> {
    None
}

#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct Vectors<N = f64> {
    #[serde(rename = "in")]
    pub v_in: [N; 2],
    pub com: [N; 2],
    pub fin: [N; 2],
    pub v_com: N,
    /// The bodies meet: `V1 != V2` at IN (on a rail with no positions, the body faster in `+x`
    /// is behind it, whichever was typed first: `line::order`). False only for `V1 = V2`.
    #[serde(default)]
    pub approaching: bool,
    /// `2` when body 2 is on the left (`V1 < V2`: it catches body 1); absent when body 1 is.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub left: Option<u8>,
}

#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct Momentum<N = f64> {
    #[serde(rename = "in")]
    pub p_in: [N; 2],
    pub fin: [N; 2],
    pub total: N,
}

/// The quadratic forms `X.M.Y` of Sec. 2.
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct Forms<N = f64> {
    pub com_m_in: N,
    pub fin_m_in: N,
    pub in_m_in: N,
    pub fin_m_fin: N,
    pub com_m_com: N,
}

#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct Energy<N = f64> {
    #[serde(rename = "in")]
    pub ke_in: N,
    pub fin: N,
    pub com: N,
    pub crunch: N,
    /// `(1 - e^2) crunch`, for `e <= 1`.
    #[serde(default = "none", skip_serializing_if = "Option::is_none")]
    pub lost: Option<N>,
    /// `(e^2 - 1) crunch`, for a superelastic `e > 1` (or, for a separation, `1/2 mu (f1 - f2)^2`).
    #[serde(default = "none", skip_serializing_if = "Option::is_none")]
    pub released: Option<N>,
}

impl<N: Scalar> Energy<N> {
    /// Every energy times `q` (a change of unit).
    pub fn scaled(self, q: &Q) -> Energy<N> {
        let s = |x: N| x.scale(q);
        Energy {
            ke_in: s(self.ke_in),
            fin: s(self.fin),
            com: s(self.com),
            crunch: s(self.crunch),
            lost: self.lost.map(s),
            released: self.released.map(s),
        }
    }

    /// `(1 - e^2) crunch` with its sign: negative when energy is released.
    pub fn lost_signed(&self) -> N {
        match (&self.lost, &self.released) {
            (Some(l), _) => l.clone(),
            (None, Some(r)) => r.neg(),
            (None, None) => N::default(),
        }
    }
}

#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
#[serde(bound(deserialize = "N: Deserialize<'de> + Default"))]
pub struct Ellipses<N = f64> {
    #[serde(rename = "in")]
    pub e_in: Ellipse<N>,
    pub fin: Ellipse<N>,
    pub com: Ellipse<N>,
}

#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct Products<N = f64> {
    pub dot_fin_in: N,
    pub outer_in_fin: [[N; 2]; 2],
}

/// What the event changed for each body (`--show changes`, see `changes`); a key is absent
/// when it means nothing for the case (per-body energies with a general tensor, the fraction
/// transferred unless one body was at rest, forces without `--contact-time`).
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
#[serde(bound(deserialize = "N: Deserialize<'de> + Default"))]
pub struct ChangeReport<N = f64> {
    pub dv: [N; 2],
    pub impulse: [N; 2],
    #[serde(default = "none", skip_serializing_if = "Option::is_none")]
    pub ke_in: Option<[N; 2]>,
    #[serde(default = "none", skip_serializing_if = "Option::is_none")]
    pub ke_fin: Option<[N; 2]>,
    #[serde(default = "none", skip_serializing_if = "Option::is_none")]
    pub dke: Option<[N; 2]>,
    #[serde(default = "none", skip_serializing_if = "Option::is_none")]
    pub lost_fraction: Option<N>,
    #[serde(default = "none", skip_serializing_if = "Option::is_none")]
    pub transferred_fraction: Option<N>,
    #[serde(default = "none", skip_serializing_if = "Option::is_none")]
    pub average_force: Option<[N; 2]>,
}

impl<N: Scalar> ChangeReport<N> {
    /// The exact changes in this report's arithmetic (each rounded once in binary64), energies
    /// times `energy_scale` (a change of unit).
    pub fn of(c: &Changes, energy_scale: Option<&Q>, force_scale: Option<&Q>) -> ChangeReport<N> {
        let one = |q: &Q| N::of_rational(q);
        let two = |p: &[Q; 2]| [one(&p[0]), one(&p[1])];
        let energy = |p: &[Q; 2]| match energy_scale {
            Some(k) => [one(&(&p[0] * k)), one(&(&p[1] * k))],
            None => two(p),
        };
        ChangeReport {
            dv: two(&c.dv),
            impulse: two(&c.impulse),
            ke_in: c.ke_in.as_ref().map(energy),
            ke_fin: c.ke_fin.as_ref().map(energy),
            dke: c.dke.as_ref().map(energy),
            lost_fraction: c.lost_fraction.as_ref().map(one),
            transferred_fraction: c.transferred_fraction.as_ref().map(one),
            average_force: c.average_force.as_ref().map(|f| match force_scale {
                Some(k) => [one(&(&f[0] * k)), one(&(&f[1] * k))],
                None => two(f),
            }),
        }
    }
}

/// `--show heights`: `v^2 / 2g` of each body's IN and FIN speed, in metres.
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct Heights<N = f64> {
    /// `g` in m/s^2.
    pub g: N,
    #[serde(rename = "in")]
    pub at_in: [N; 2],
    pub fin: [N; 2],
}

impl<N: Scalar> Heights<N> {
    /// The heights of the speeds of `x` (the lab's: a height is a physical rise), each exact
    /// and rounded once, never 0 for a speed that is not (`Scalar::unless_underflow`).
    pub fn of(x: &ExactCollision, h: &crate::values::units::HeightScale) -> Heights<N> {
        let f = x.v_fin_q();
        let v_in = [x.v[0].clone(), x.v[1].clone()];
        Heights::of_speeds(&v_in, &[f[0].clone(), f[1].clone()], h)
    }

    /// The heights of the speeds `v_in` and `fin` (a collision's, a separation's or a
    /// pass-through's).
    pub fn of_speeds(
        v_in: &[Q; 2],
        fin: &[Q; 2],
        h: &crate::values::units::HeightScale,
    ) -> Heights<N> {
        let one = |v: &Q| {
            let h = h.height(v);
            N::of_rational(&h).unless_underflow(&h)
        };
        Heights {
            g: N::of_rational(&h.g),
            at_in: [one(&v_in[0]), one(&v_in[1])],
            fin: [one(&fin[0]), one(&fin[1])],
        }
    }
}

/// A solve's own error beside its own run time (`--show diagnostics`).
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct Diagnostics {
    /// `|u.M.V_FIN - u.M.V_IN|` relative to the sum of the magnitudes of its terms.
    pub momentum_residual: f64,
    /// `|1/2 V_FIN.M.V_FIN - (KE_COM + e^2 crunch)|` relative to `KE_FIN`.
    pub energy_residual: f64,
    /// Median wall-clock time of one solve (FIN, V_COM and the energies), in nanoseconds.
    pub solve_ns: f64,
    /// How many solves were timed.
    pub repetitions: usize,
}

/// The time-reversed collision: `t -> -t`, so `IN' = -FIN` and `FIN' = -IN` (lecture Sec. 4).
#[derive(Clone, Debug, Serialize, PartialEq)]
pub struct Reverse<N> {
    #[serde(rename = "in")]
    pub v_in: [N; 2],
    pub fin: [N; 2],
    /// `1/e`: above 1 for `e < 1`, an explosion that gains the energy the original lost.
    pub restitution: N,
    pub energy: ReverseEnergy<N>,
    /// Whether it is the original collision again (elastic, seen from the COM frame).
    pub equals_original: bool,
}

#[derive(Clone, Debug, Serialize, PartialEq)]
pub struct ReverseEnergy<N> {
    /// `KE_IN' = KE_FIN`.
    #[serde(rename = "in")]
    pub ke_in: N,
    /// `KE_FIN' = KE_IN`.
    pub fin: N,
    /// `KE_FIN' - KE_IN'`, the original's energy lost (`e <= 1`): never negative.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub gained: Option<N>,
    /// `KE_IN' - KE_FIN'`, the original's energy released (`e > 1`): never negative.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub lost: Option<N>,
}

/// Why a collision cannot be reversed.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[error(
    "the time reverse of a totally inelastic collision (e = 0) is not determined: bodies stuck \
     together at COM can split apart in any way that conserves momentum, so there is no unique \
     IN' to print; use e > 0"
)]
pub struct Irreversible;

/// A time reverse whose `e' = 1/e` binary64 cannot hold.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[error(
    "--reverse: e' = 1/e = 1/{e} is above binary64's largest number (1.8e308), so it cannot be \
     printed in binary64; --exact prints it exactly"
)]
pub struct ReverseOverflow {
    /// `e` as typed.
    pub e: String,
}

impl<N: Scalar> Report<N> {
    /// Adds the time-reversed collision (needs the vectors and energy of `c`), its energies
    /// times `energy_scale` (`--energy-unit`).
    pub fn with_reverse<S: Solver<N = N>>(
        mut self,
        c: &S,
        equals_original: bool,
        energy_scale: Option<&Q>,
    ) -> Result<Self, ReportError> {
        let recip = c.restitution().recip().ok_or(Irreversible)?;
        if !recip.is_representable() {
            return Err(ReportError::ReverseOverflow(ReverseOverflow {
                e: c.restitution().show(),
            }));
        }
        let energy = |x: N| match energy_scale {
            Some(q) => x.scale(q),
            None => x,
        };
        let fin = c.v_fin();
        let v_in = c.v_in();
        let superelastic = c.superelastic();
        self.reverse = Some(Reverse {
            v_in: [fin[0].neg(), fin[1].neg()],
            fin: [v_in[0].neg(), v_in[1].neg()],
            restitution: recip,
            energy: ReverseEnergy {
                ke_in: energy(c.ke_fin()),
                fin: energy(c.ke_in()),
                gained: (!superelastic).then(|| energy(c.lost())),
                lost: superelastic.then(|| energy(c.lost().neg())),
            },
            equals_original,
        });
        self.check_representable()?;
        Ok(self)
    }
}

/// Values the text notes quote beside the sections.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Notes<N = f64> {
    /// `mu = det M / M_total`.
    pub reduced_mass: N,
    /// `V1 - V2`.
    pub relative_velocity: N,
    /// The crunch energy in the case's own unit (mass unit x velocity unit^2), the unit of the
    /// quadratic forms, whatever unit the energies are printed in.
    pub crunch: N,
    /// Momentum line `k1 V1 + k2 V2 = P_total` and its slope.
    pub line: (N, N, Option<N>),
}

/// Why a report cannot be given in binary64.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[error(
    "{quantity} is not representable in binary64 (its magnitude is outside 2.2e-308 to 1.8e308): \
     {way_out}"
)]
pub struct Unrepresentable {
    pub quantity: String,
    /// What the command offers instead ([`WAY_OUT_SOLVE`] by default).
    pub way_out: &'static str,
}

/// `collide solve` and a scene: other arithmetic, other units or other sections.
pub const WAY_OUT_SOLVE: &str =
    "use --exact, rescale the units, or ask only for other sections with --show";

impl Unrepresentable {
    /// `quantity` (a JSON path, `energy.in`), with `solve`'s ways out.
    pub fn new(quantity: impl Into<String>) -> Unrepresentable {
        Unrepresentable {
            quantity: quantity.into(),
            way_out: WAY_OUT_SOLVE,
        }
    }

    /// The same, with the ways out a command that has no `--show` (or no `--exact`) offers.
    pub fn with_way_out(self, way_out: &'static str) -> Unrepresentable {
        Unrepresentable { way_out, ..self }
    }
}

/// Why a report cannot be given.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum ReportError {
    #[error(transparent)]
    Unrepresentable(#[from] Unrepresentable),
    #[error(transparent)]
    ExactTooLong(#[from] crate::values::number::ExactTooLong),
    #[error(transparent)]
    Irreversible(#[from] Irreversible),
    #[error(transparent)]
    ReverseOverflow(#[from] ReverseOverflow),
    #[error(transparent)]
    Asked(#[from] asked::AskedError),
}

impl<N: Scalar> Report<N> {
    /// The report of `lab` seen from `frame`, with the time-reversed collision when `reverse`.
    pub fn of<L: Lab<N = N>>(
        lab: &L,
        frame: &Frame,
        sections: &Sections,
        reverse: bool,
    ) -> Result<Report<N>, ReportError> {
        let (w, seen) = lab.seen_from(frame);
        let mut r = Report::build(&seen, sections)?;
        // Heights belong to the lab, whatever frame the vectors are seen from: how high a body
        // rises is a physical rise (in a moving frame a body that sticks would "rise" 0).
        if let (Some(h), true, true) = (
            sections.heights.as_ref(),
            r.heights.is_some(),
            *frame != Frame::Lab,
        ) {
            r.heights = Some(Heights::of(&lab.seen_from(&Frame::Lab).1.exact(), h));
            r.check_representable()?;
        }
        if !sections.asked.is_empty() {
            // Heights and swings belong to the lab; a spring's numbers are the same anywhere.
            let x = lab.seen_from(&Frame::Lab).1.exact();
            let motion = asked::Motion {
                fin: x.v_fin_q(),
                crunch: x.crunch_q(),
                mu: (&x.a * &x.b - &x.c * &x.c) / (&x.a + &x.b + Q::from(2) * &x.c),
                e: Some(x.e.clone()),
                v_in: x.v,
            };
            r.asked = asked::AskedReport::of(&motion, &sections.asked)?;
        }
        r.frame = (*frame != Frame::Lab).then(|| FrameInfo {
            name: frame.to_string(),
            w,
        });
        if reverse {
            r = r.with_reverse(
                &seen,
                lab.is_own_time_reverse(frame),
                sections.energy_scale.as_ref(),
            )?;
        }
        Ok(r)
    }

    /// Computes the requested sections of a solved collision, and nothing else.
    pub fn build<S: Solver<N = N>>(
        c: &S,
        sections: &Sections,
    ) -> Result<Report<N>, Unrepresentable> {
        let has = |s| sections.contains(s);
        let need_fin = [
            Section::Vectors,
            Section::Momentum,
            Section::Forms,
            Section::Products,
        ]
        .into_iter()
        .any(has);
        let fin = need_fin.then(|| c.v_fin());
        let fin = || {
            fin.clone()
                .expect("FIN is computed for every section that uses it")
        };
        let v_in = c.v_in();
        let energy = (has(Section::Energy) || has(Section::Ellipses)).then(|| Energy {
            ke_in: c.ke_in(),
            fin: c.ke_fin(),
            com: c.ke_com(),
            crunch: c.crunch(),
            lost: (!c.superelastic()).then(|| c.lost()),
            released: c.superelastic().then(|| c.lost().neg()),
        });
        let report = Report {
            restitution: c.restitution(),
            inertia: c.inertia(),
            frame: None,
            reverse: None,
            vectors: has(Section::Vectors).then(|| {
                let v_com = c.v_com();
                Vectors {
                    v_in: v_in.clone(),
                    com: [v_com.clone(), v_com.clone()],
                    fin: fin(),
                    v_com,
                    approaching: c.order().meet(),
                    left: c.order().left_when_body_2(),
                }
            }),
            momentum: has(Section::Momentum).then(|| Momentum {
                p_in: c.momentum(&v_in),
                fin: c.momentum(&fin()),
                total: c.total_momentum(),
            }),
            forms: has(Section::Forms).then(|| {
                let com = c.com_form();
                Forms {
                    com_m_in: com.clone(),
                    fin_m_in: c.form(&fin(), &v_in),
                    in_m_in: c.form(&v_in, &v_in),
                    fin_m_fin: c.form(&fin(), &fin()),
                    com_m_com: com,
                }
            }),
            ellipses: has(Section::Ellipses).then(|| {
                let e = energy
                    .as_ref()
                    .expect("energies are computed for the ellipses");
                Ellipses {
                    e_in: c.ellipse(&e.ke_in),
                    fin: c.ellipse(&e.fin),
                    com: c.ellipse(&e.com),
                }
            }),
            products: has(Section::Products).then(|| Products {
                dot_fin_in: c.dot(&fin(), &v_in),
                outer_in_fin: c.outer(&v_in, &fin()),
            }),
            // Ellipses were drawn from the energies in the case's units; printed ones may be in
            // another (`--energy-unit`).
            energy: energy
                .filter(|_| has(Section::Energy))
                .map(|e| match &sections.energy_scale {
                    Some(q) => e.scaled(q),
                    None => e,
                }),
            changes: has(Section::Changes).then(|| {
                ChangeReport::of(
                    &c.exact().changes(sections.contact_time.as_ref()),
                    sections.energy_scale.as_ref(),
                    sections.force_scale.as_ref(),
                )
            }),
            heights: sections
                .heights
                .as_ref()
                .filter(|_| has(Section::Heights))
                .map(|h| Heights::of(&c.exact(), h)),
            asked: asked::AskedReport::default(),
            diagnostics: has(Section::Diagnostics).then(|| {
                let (momentum_residual, energy_residual) = c.residuals();
                let (solve_ns, repetitions) = time_solves(c);
                Diagnostics {
                    momentum_residual,
                    energy_residual,
                    solve_ns,
                    repetitions,
                }
            }),
            notes: Notes {
                reduced_mass: if has(Section::Energy) {
                    c.reduced_mass()
                } else {
                    N::default()
                },
                relative_velocity: c.relative_velocity(),
                crunch: if has(Section::Forms) {
                    c.crunch()
                } else {
                    N::default()
                },
                line: if has(Section::Momentum) {
                    c.momentum_line()
                } else {
                    (N::default(), N::default(), None)
                },
            },
        };
        report.check_representable()?;
        Ok(report)
    }

    /// The same report with only the sections in `show`.
    pub fn only(&self, show: &Sections) -> Report<N> {
        let keep = |s| show.contains(s);
        let mut r = self.clone();
        r.vectors = r.vectors.filter(|_| keep(Section::Vectors));
        r.momentum = r.momentum.filter(|_| keep(Section::Momentum));
        r.forms = r.forms.filter(|_| keep(Section::Forms));
        r.energy = r.energy.filter(|_| keep(Section::Energy));
        r.ellipses = r.ellipses.filter(|_| keep(Section::Ellipses));
        r.products = r.products.filter(|_| keep(Section::Products));
        r.changes = r.changes.filter(|_| keep(Section::Changes));
        r.heights = r.heights.filter(|_| keep(Section::Heights));
        r.diagnostics = r.diagnostics.filter(|_| keep(Section::Diagnostics));
        r
    }

    /// Every number in the report must be a real result: an overflow is reported by name.
    fn check_representable(&self) -> Result<(), Unrepresentable> {
        let value = serde_json::to_value(self).expect("a report serializes");
        if let Some(quantity) = first_unrepresentable(&value) {
            return Err(Unrepresentable::new(quantity));
        }
        let n = &self.notes;
        if !(n.reduced_mass.is_representable() && n.relative_velocity.is_representable()) {
            return Err(Unrepresentable::new("the relative velocity V1 - V2"));
        }
        Ok(())
    }
}

/// A report in the arithmetic that was asked for.
pub enum AnyReport {
    Binary64(Box<Report<f64>>),
    Exact(Box<Report<Exact>>),
}

impl AnyReport {
    /// `case` seen from `frame`, in exact arithmetic from the typed values or in binary64.
    pub fn of(
        case: &Case,
        frame: &Frame,
        exact: bool,
        sections: &Sections,
        reverse: bool,
    ) -> Result<AnyReport, ReportError> {
        AnyReport::compute(case, frame, exact, sections, reverse).map_err(|e| match e {
            // Named as typed (5e-324), not as its binary64 (4.94065645841247e-324).
            ReportError::ReverseOverflow(_) => ReportError::ReverseOverflow(ReverseOverflow {
                e: case.restitution().number().to_string(),
            }),
            e => e,
        })
    }

    fn compute(
        case: &Case,
        frame: &Frame,
        exact: bool,
        sections: &Sections,
        reverse: bool,
    ) -> Result<AnyReport, ReportError> {
        Ok(if exact {
            case.check_exact()?;
            let lab = ExactCollision::from_case(case);
            AnyReport::Exact(Box::new(Report::of(&lab, frame, sections, reverse)?))
        } else if case.solved() && case.check_exact().is_ok() {
            // A solved problem: the exact solution rounded once, so FIN is the typed or the
            // solved value and nothing is computed again from a rounded one.
            let lab = crate::solver::rounded::Rounded::new(ExactCollision::from_case(case));
            AnyReport::Binary64(Box::new(Report::of(&lab, frame, sections, reverse)?))
        } else {
            let mut r = Report::of(&case.collision, frame, sections, reverse)?;
            // Whether the bodies approach, and which is behind, from the values as typed (or
            // carried exactly from an earlier stage), as a chain of stages decides it: two
            // velocities that differ may round to one binary64 (0.6666666666666666 and the
            // binary64 of 2/3), and "V1 = V2: the bodies never meet" would then be false. The
            // order is the same in every frame (both velocities shift by w).
            let order = crate::line::order::Order::before(
                &case.velocities[0].exact(),
                &case.velocities[1].exact(),
            );
            if let Some(v) = r.vectors.as_mut() {
                v.approaching = order.meet();
                v.left = order.left_when_body_2();
            }
            AnyReport::Binary64(Box::new(r))
        })
    }

    pub fn json(&self) -> serde_json::Value {
        match self {
            AnyReport::Binary64(r) => serde_json::to_value(r),
            AnyReport::Exact(r) => serde_json::to_value(r),
        }
        .expect("reports serialize")
    }

    /// Text of the sections in `show` (others were computed only for a scene's checks), under
    /// what the unknowns `solved` came out as and, for a case with units, the answer.
    pub fn text(&self, case: &Case, show: &Sections, solved: Option<&Solved>) -> String {
        let (head, body) = match self {
            AnyReport::Binary64(r) => (text::answer(case, r), text::render(case, &r.only(show))),
            AnyReport::Exact(r) => (text::answer(case, r), text::render(case, &r.only(show))),
        };
        let exact = matches!(self, AnyReport::Exact(_));
        let mut out = solved.map_or_else(String::new, |s| solved::lines(s, exact, &case.units));
        if show.contains(Section::Vectors) {
            out.push_str(&head.unwrap_or_default());
        }
        if out.is_empty() {
            body
        } else {
            out + "\n" + &body
        }
    }
}

/// The path of the first number in `v` that is not a real result (serde_json writes a non-finite
/// float as null), as `energy.in` or `x[1]`.
pub fn first_unrepresentable(v: &serde_json::Value) -> Option<String> {
    first_path(v, &|x| x.is_null())
}

/// The path (`energy.in`, `fin[0][1]`, depth first in the report's order) of the first value of
/// `v` that `hit` picks: one walk for every check that names a quantity by its place.
pub(crate) fn first_path(
    v: &serde_json::Value,
    hit: &dyn Fn(&serde_json::Value) -> bool,
) -> Option<String> {
    fn find(
        v: &serde_json::Value,
        path: &str,
        hit: &dyn Fn(&serde_json::Value) -> bool,
    ) -> Option<String> {
        if hit(v) {
            return Some(path.to_string());
        }
        match v {
            serde_json::Value::Array(a) => a
                .iter()
                .enumerate()
                .find_map(|(i, x)| find(x, &format!("{path}[{i}]"), hit)),
            serde_json::Value::Object(o) => o.iter().find_map(|(k, x)| {
                let p = if path.is_empty() {
                    k.clone()
                } else {
                    format!("{path}.{k}")
                };
                find(x, &p, hit)
            }),
            _ => None,
        }
    }
    find(v, "", hit)
}

/// Median time of one solve of `c`, over batches filling about a millisecond.
fn time_solves<S: Solver>(c: &S) -> (f64, usize) {
    use std::hint::black_box;
    use std::time::Instant;
    let solve = || {
        black_box(c.v_fin());
        black_box(c.ke_fin());
        black_box(c.crunch());
    };
    // Size a batch to take ~100 us, then time 11 batches and take the median.
    let mut batch = 1usize;
    loop {
        let t = Instant::now();
        for _ in 0..batch {
            solve();
        }
        if t.elapsed().as_micros() >= 100 || batch >= 1 << 20 {
            break;
        }
        batch *= 2;
    }
    let mut per: Vec<f64> = (0..11)
        .map(|_| {
            let t = Instant::now();
            for _ in 0..batch {
                solve();
            }
            t.elapsed().as_nanos() as f64 / batch as f64
        })
        .collect();
    per.sort_by(f64::total_cmp);
    (per[per.len() / 2], 11 * batch)
}
