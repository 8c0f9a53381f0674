//! Galilean frames and time reversal (lecture Sec. 4). An observer moving at `w` sees every
//! velocity shifted by `-w`: a 45-degree shift in the velocity plane. Crunch energy, `e` and the
//! relative velocity are the same in every frame; kinetic energies are not. Reversing time
//! (`t -> -t`) maps `V -> -V` and swaps IN and FIN; only in the COM frame does the reversed
//! collision look the same as the original.
//!
//! Shifts are exact: `w` is held as a double-double (`V_COM` or a body's FIN velocity exactly as
//! the solver has them), so the COM frame puts COM at 0 and "body i finally at rest" puts FIN_i
//! at 0, and each frame's energies come from its own relative velocity, never from a difference
//! of large energies.

use std::fmt;
use std::str::FromStr;

use nalgebra::Vector2;
use num_rational::BigRational;
use serde::Serialize;

use crate::collision::Collision;
use crate::compensated::{Dd, dot2};
use crate::ellipse::Ellipse;
use crate::exact::ExactCollision;
use crate::number::Number;
use crate::quantity::{Exact, Scalar};
use crate::report::{Energy, Report, Section, Sections, Unrepresentable};
use crate::solver::{Pair, Solver};

/// A frame of reference (`--frame`, `frame = "..."` in a scene).
#[derive(Clone, Debug, PartialEq)]
pub enum Frame {
    /// The lab (the lecture's Earth frame), `w = 0`.
    Lab,
    /// Center of momentum, `w = V_COM`.
    Com,
    /// Body 1 or 2 initially at rest, `w = V_i^IN`.
    RestIn(usize),
    /// Body 1 or 2 finally at rest, `w = V_i^FIN`.
    RestFin(usize),
    /// An observer moving at this velocity.
    Velocity(Number),
}

impl Frame {
    /// The lecture's standard frames (Figs. 2.5 and 3.4), in the order of the frames table.
    pub fn standard() -> [Frame; 6] {
        [
            Frame::Lab,
            Frame::RestIn(1),
            Frame::RestIn(2),
            Frame::Com,
            Frame::RestFin(1),
            Frame::RestFin(2),
        ]
    }

    /// What the frame is, for people.
    pub fn describe(&self) -> String {
        match self {
            Frame::Lab => "lab (Earth)".into(),
            Frame::Com => "COM".into(),
            Frame::RestIn(i) => format!("body {i} initially at rest"),
            Frame::RestFin(i) => format!("body {i} finally at rest"),
            Frame::Velocity(n) => format!("observer at {n}"),
        }
    }

    /// The observer's velocity for a binary64 collision.
    pub fn w(&self, c: &Collision) -> Dd {
        match self {
            Frame::Lab => Dd::new(0.0),
            Frame::Com => c.v_com_dd(),
            Frame::RestIn(i) => Dd::new(c.v_in[i - 1]),
            Frame::RestFin(i) => c.v_fin_dd()[i - 1],
            Frame::Velocity(n) => Dd::new(n.value()),
        }
    }

    /// The observer's velocity in exact arithmetic (a typed velocity from its text).
    pub fn w_exact(&self, x: &ExactCollision) -> BigRational {
        match self {
            Frame::Lab => BigRational::default(),
            Frame::Com => x.v_com_q(),
            Frame::RestIn(i) => x.v[i - 1].clone(),
            Frame::RestFin(i) => x.v_fin_q()[i - 1].clone(),
            Frame::Velocity(n) => n.exact(),
        }
    }
}

impl fmt::Display for Frame {
    /// The word that names the frame on the command line.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Frame::Lab => write!(f, "lab"),
            Frame::Com => write!(f, "com"),
            Frame::RestIn(i) => write!(f, "rest-in:{i}"),
            Frame::RestFin(i) => write!(f, "rest-fin:{i}"),
            Frame::Velocity(n) => write!(f, "{n}"),
        }
    }
}

impl FromStr for Frame {
    type Err = String;
    fn from_str(s: &str) -> Result<Frame, String> {
        let t = s.trim();
        Ok(match t {
            "lab" | "earth" => Frame::Lab,
            "com" => Frame::Com,
            "rest-in:1" => Frame::RestIn(1),
            "rest-in:2" => Frame::RestIn(2),
            "rest-fin:1" => Frame::RestFin(1),
            "rest-fin:2" => Frame::RestFin(2),
            _ => Frame::Velocity(t.parse().map_err(|_| {
                format!(
                    "frame '{t}' is not a frame: expected lab, com, rest-in:1, rest-in:2, \
                     rest-fin:1, rest-fin:2, or an observer velocity such as 2.5"
                )
            })?),
        })
    }
}

/// Serde: a frame word (`"com"`) or an observer velocity (`2.5`, `"-4"`).
impl<'de> serde::Deserialize<'de> for Frame {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Frame, D::Error> {
        crate::number::deserialize_parsed(
            d,
            "a frame (\"lab\", \"com\", \"rest-in:1\", ...) or an observer velocity",
        )
    }
}

/// `"frame": {"name": "com", "w": 2.0}` in JSON.
#[derive(Clone, Debug, Serialize, PartialEq)]
pub struct FrameInfo<N> {
    pub name: String,
    pub w: N,
}

/// A binary64 collision seen by an observer moving at `w`.
#[derive(Clone, Debug)]
pub struct Observed<'a> {
    pub lab: &'a Collision,
    pub w: Dd,
}

impl<'a> Observed<'a> {
    pub fn new(lab: &'a Collision, frame: &Frame) -> Observed<'a> {
        Observed {
            lab,
            w: frame.w(lab),
        }
    }

    /// The lab frame itself.
    pub fn lab(lab: &'a Collision) -> Observed<'a> {
        Observed {
            lab,
            w: Dd::new(0.0),
        }
    }

    fn in_dd(&self) -> [Dd; 2] {
        [
            Dd::new(self.lab.v_in.x) - self.w,
            Dd::new(self.lab.v_in.y) - self.w,
        ]
    }
    fn fin_dd(&self) -> [Dd; 2] {
        self.lab.v_fin_dd().map(|f| f - self.w)
    }
    fn com_dd(&self) -> Dd {
        self.lab.v_com_dd() - self.w
    }
    /// `V1 - V2` from this frame's own IN velocities.
    fn relative_dd(&self) -> Dd {
        let [a, b] = self.in_dd();
        a - b
    }
    fn crunch_dd(&self) -> Dd {
        let d = self.relative_dd();
        Dd::new(0.5) * ((self.lab.inertia.reduced_mass_dd() * d) * d)
    }
    /// `KE_COM = 1/2 (M_total V_COM) V_COM`.
    fn ke_com_dd(&self) -> Dd {
        let vc = self.com_dd();
        Dd::new(0.5) * ((self.lab.inertia.total_dd() * vc) * vc)
    }
    fn e2(&self) -> Dd {
        let e = self.lab.restitution.value();
        Dd::prod(e, e)
    }
    fn moving(&self) -> bool {
        self.relative_dd().value() != 0.0
    }
}

fn vec2(p: &Pair<f64>) -> Vector2<f64> {
    Vector2::new(p[0], p[1])
}

/// `x`, or NaN (reported as unrepresentable) when a quantity known to be non-zero came out
/// below the normal range: it underflowed, and printing 0 or a subnormal would be wrong.
fn unless_underflow(x: f64, nonzero: bool) -> f64 {
    if nonzero && x.abs() < f64::MIN_POSITIVE {
        f64::NAN
    } else {
        x
    }
}

/// `x * y`, or NaN when two non-zero factors underflow.
fn product(x: f64, y: f64) -> f64 {
    unless_underflow(x * y, x != 0.0 && y != 0.0)
}

impl Solver for Observed<'_> {
    type N = f64;
    fn restitution(&self) -> f64 {
        self.lab.restitution.value()
    }
    fn inertia(&self) -> [Pair<f64>; 2] {
        let m = self.lab.inertia.matrix();
        [[m[(0, 0)], m[(0, 1)]], [m[(1, 0)], m[(1, 1)]]]
    }
    fn v_in(&self) -> Pair<f64> {
        self.in_dd().map(Dd::value)
    }
    fn v_com(&self) -> f64 {
        self.com_dd().value()
    }
    fn v_fin(&self) -> Pair<f64> {
        self.fin_dd().map(Dd::value)
    }
    /// `P_total = M_total V_COM` in this frame.
    fn total_momentum(&self) -> f64 {
        (self.lab.inertia.total_dd() * self.com_dd()).value()
    }
    fn momentum(&self, v: &Pair<f64>) -> Pair<f64> {
        let p = self.lab.inertia.momentum(&vec2(v));
        [p.x, p.y]
    }
    fn form(&self, x: &Pair<f64>, y: &Pair<f64>) -> f64 {
        self.lab.inertia.form(&vec2(x), &vec2(y))
    }
    fn com_form(&self) -> f64 {
        (Dd::new(2.0) * self.ke_com_dd()).value()
    }
    /// Koenig: `KE_IN = KE_COM + crunch`, a sum of non-negative terms.
    fn ke_in(&self) -> f64 {
        let v = self.v_in();
        unless_underflow(
            (self.ke_com_dd() + self.crunch_dd()).value(),
            v != [0.0, 0.0],
        )
    }
    /// `KE_FIN = KE_COM + e^2 crunch`.
    fn ke_fin(&self) -> f64 {
        let e = self.lab.restitution.value();
        let nonzero = self.v_com() != 0.0 || (e != 0.0 && self.moving());
        unless_underflow(
            (self.ke_com_dd() + self.e2() * self.crunch_dd()).value(),
            nonzero,
        )
    }
    fn ke_com(&self) -> f64 {
        unless_underflow(self.ke_com_dd().value(), self.v_com() != 0.0)
    }
    fn crunch(&self) -> f64 {
        unless_underflow(self.crunch_dd().value(), self.moving())
    }
    /// `(1 - e^2) crunch` with `1 - e^2 = (1 - e)(1 + e)`.
    fn lost(&self) -> f64 {
        let e = self.lab.restitution.value();
        let lost = Dd::sum(1.0, -e) * Dd::sum(1.0, e) * self.crunch_dd();
        unless_underflow(lost.value(), e != 1.0 && self.moving())
    }
    fn ellipse(&self, ke: &f64) -> Ellipse<f64> {
        let axes = (!self.lab.inertia.is_diagonal()).then(|| self.lab.inertia.principal_axes());
        Ellipse::new(&self.lab.inertia, *ke, axes.as_ref())
    }
    fn dot(&self, x: &Pair<f64>, y: &Pair<f64>) -> f64 {
        let underflow = (0..2).any(|i| product(x[i], y[i]).is_nan());
        if underflow { f64::NAN } else { dot2(x, y) }
    }
    fn outer(&self, x: &Pair<f64>, y: &Pair<f64>) -> [Pair<f64>; 2] {
        [
            [product(x[0], y[0]), product(x[0], y[1])],
            [product(x[1], y[0]), product(x[1], y[1])],
        ]
    }
    fn reduced_mass(&self) -> f64 {
        self.lab.inertia.reduced_mass()
    }
    fn relative_velocity(&self) -> f64 {
        self.relative_dd().value()
    }
    fn residuals(&self) -> (f64, f64) {
        let m = self.lab.inertia.matrix();
        let (k1, k2) = (m[(0, 0)] + m[(0, 1)], m[(0, 1)] + m[(1, 1)]);
        let (v, f) = (vec2(&self.v_in()), vec2(&self.v_fin()));
        let (p_in, p_fin) = (
            self.lab.inertia.total_momentum(&v),
            self.lab.inertia.total_momentum(&f),
        );
        let scale = ((k1 * v.x).abs() + (k2 * v.y).abs()).max((k1 * f.x).abs() + (k2 * f.y).abs());
        let momentum = if scale > 0.0 {
            (p_fin - p_in).abs() / scale
        } else {
            0.0
        };
        let ke_fin = 0.5 * self.lab.inertia.form(&f, &f);
        let ke_rule = self.ke_fin();
        let energy = if ke_fin > 0.0 {
            (ke_fin - ke_rule).abs() / ke_fin
        } else {
            ke_rule.abs()
        };
        (momentum, energy)
    }
    fn momentum_line(&self) -> (f64, f64, Option<f64>) {
        let m = self.lab.inertia.matrix();
        let (k1, k2) = (m[(0, 0)] + m[(0, 1)], m[(0, 1)] + m[(1, 1)]);
        (
            k1,
            k2,
            (k2 != 0.0).then(|| -k1 / k2).filter(|s| s.is_finite()),
        )
    }
}

/// One row of the frames table.
#[derive(Clone, Debug, Serialize)]
pub struct FrameRow<N> {
    pub name: String,
    pub w: N,
    #[serde(rename = "in")]
    pub v_in: [N; 2],
    pub com: [N; 2],
    pub fin: [N; 2],
    pub energy: Energy<N>,
    /// Whether the time-reversed collision equals the original in this frame (`--reverse`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub reverse_equals_original: Option<bool>,
    #[serde(skip)]
    pub label: String,
}

/// The quantities every frame must agree on.
#[derive(Clone, Debug, Serialize)]
pub struct Invariants<N> {
    pub crunch: N,
    pub lost: N,
    pub relative_velocity: N,
    /// `e`, and in each frame `-(FIN1 - FIN2) / (IN1 - IN2)`; `None` when `V1 = V2`.
    pub restitution: N,
}

/// The frames table of lecture Figs. 2.5 and 3.4.
#[derive(Clone, Debug, Serialize)]
pub struct FramesTable<N> {
    pub frames: Vec<FrameRow<N>>,
    pub invariants: Invariants<N>,
}

/// An invariant that differs between frames.
#[derive(Clone, Debug, thiserror::Error)]
#[error("{quantity} is not the same in every frame: {lab} in the lab but {other} in frame {frame}")]
pub struct BrokenInvariant {
    pub quantity: &'static str,
    pub frame: String,
    pub lab: String,
    pub other: String,
}

/// Relative agreement within `ulps` (2^-52 each) for binary64; exact equality for rationals.
pub trait Agree: Scalar {
    fn agrees(&self, other: &Self) -> bool;
}

impl Agree for f64 {
    fn agrees(&self, other: &f64) -> bool {
        (self - other).abs() <= 2.0 * f64::EPSILON * self.abs().max(other.abs())
    }
}

impl Agree for Exact {
    fn agrees(&self, other: &Exact) -> bool {
        self.rational() == other.rational()
    }
}

/// The frames table for the frames given, checking the invariants row by row. `rows` pairs each
/// frame with its solver; `restitution_of` computes `e` from a row's own IN and FIN.
pub fn table<N: Agree, S: Solver<N = N>>(
    rows: Vec<(Frame, N, S, Option<bool>)>,
    restitution_of: impl Fn(&S) -> Option<N>,
) -> Result<FramesTable<N>, FramesError> {
    let sections = Sections::new([Section::Vectors, Section::Energy]);
    let mut frames = Vec::new();
    let mut invariants: Option<Invariants<N>> = None;
    for (frame, w, solver, reverse) in rows {
        let r: Report<N> = Report::build(&solver, &sections)?;
        let (v, energy) = (r.vectors.expect("vectors"), r.energy.expect("energy"));
        let row_e = restitution_of(&solver).unwrap_or_else(|| solver.restitution());
        let inv = Invariants {
            crunch: energy.crunch.clone(),
            lost: energy.lost.clone(),
            relative_velocity: solver.relative_velocity(),
            restitution: row_e,
        };
        if let Some(lab) = &invariants {
            for (quantity, a, b) in [
                ("crunch", &lab.crunch, &inv.crunch),
                ("energy lost", &lab.lost, &inv.lost),
                (
                    "relative velocity V1 - V2",
                    &lab.relative_velocity,
                    &inv.relative_velocity,
                ),
                ("restitution e", &lab.restitution, &inv.restitution),
            ] {
                if !a.agrees(b) {
                    return Err(FramesError::Broken(BrokenInvariant {
                        quantity,
                        frame: frame.to_string(),
                        lab: a.show(),
                        other: b.show(),
                    }));
                }
            }
        } else {
            invariants = Some(inv);
        }
        frames.push(FrameRow {
            name: frame.to_string(),
            label: frame.describe(),
            w,
            v_in: v.v_in,
            com: v.com,
            fin: v.fin,
            energy,
            reverse_equals_original: reverse,
        });
    }
    Ok(FramesTable {
        frames,
        invariants: invariants.expect("the lab row comes first"),
    })
}

/// Why a frames table could not be made.
#[derive(Clone, Debug, thiserror::Error)]
pub enum FramesError {
    #[error(transparent)]
    Unrepresentable(#[from] Unrepresentable),
    #[error(transparent)]
    Broken(#[from] BrokenInvariant),
}

/// `e` from a frame's own velocities: `-(FIN1 - FIN2) / (IN1 - IN2)`, in double-double.
pub fn restitution_observed(o: &Observed) -> Option<f64> {
    let [i1, i2] = o.in_dd();
    let [f1, f2] = o.fin_dd();
    let d = i1 - i2;
    (d.value() != 0.0).then(|| ((f2 - f1) / d).value())
}

/// `e` from exact velocities.
pub fn restitution_exact(x: &ExactCollision) -> Option<Exact> {
    let [f1, f2] = x.v_fin_q();
    let d = &x.v[0] - &x.v[1];
    (d != BigRational::default()).then(|| Exact::Rational((f2 - f1) / d))
}

/// Whether the time-reversed collision (IN' = -FIN, FIN' = -IN) equals the original seen from an
/// observer at `w`: exactly when `IN + FIN = 2 w` and the collision is elastic, that is when `w`
/// is the COM velocity. Decided in exact arithmetic.
pub fn reverse_equals_original(x: &ExactCollision, w: &BigRational) -> bool {
    use num_traits::One;
    let [f1, f2] = x.v_fin_q();
    let two_w = w + w;
    x.e.is_one() && &x.v[0] + f1 == two_w && &x.v[1] + f2 == two_w
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::accuracy::case;

    #[test]
    fn frame_words() {
        assert_eq!("com".parse::<Frame>().unwrap(), Frame::Com);
        assert_eq!("rest-fin:2".parse::<Frame>().unwrap(), Frame::RestFin(2));
        assert_eq!("-4".parse::<Frame>().unwrap().to_string(), "-4");
        let e = "rest-in:3".parse::<Frame>().unwrap_err();
        assert!(e.contains("'rest-in:3'") && e.contains("rest-in:1"), "{e}");
    }

    #[test]
    fn fig_3_4_vw_finally_at_rest_is_exactly_at_rest() {
        let c = case([[6.0, 0.0], [0.0, 1.0]], [3.0, -4.0], 1.0).unwrap();
        let o = Observed::new(&c, &Frame::RestFin(2));
        assert_eq!(o.w.value(), 8.0);
        assert_eq!(o.v_in(), [-5.0, -12.0]);
        assert_eq!(o.v_fin(), [-7.0, 0.0]);
        assert_eq!(o.crunch(), 21.0);
    }

    #[test]
    fn a_frame_that_disagrees_is_reported() {
        // Two rows from different collisions: the check must catch the different crunch.
        let a = case([[6.0, 0.0], [0.0, 1.0]], [3.0, -4.0], 1.0).unwrap();
        let b = case([[6.0, 0.0], [0.0, 1.0]], [3.0, -5.0], 1.0).unwrap();
        let rows = vec![
            (Frame::Lab, 0.0, Observed::lab(&a), None),
            (Frame::Com, 0.0, Observed::lab(&b), None),
        ];
        match table(rows, restitution_observed) {
            Err(FramesError::Broken(e)) => {
                assert_eq!(e.quantity, "crunch");
                assert_eq!(e.frame, "com");
                // 1/2 (6/7) 7^2 = 21 against 1/2 (6/7) 8^2 = 192/7.
                assert_eq!(e.lab, "21");
                assert_eq!(e.other, (192.0f64 / 7.0).to_string());
            }
            other => panic!("expected a broken invariant, got {other:?}"),
        }
    }

    #[test]
    fn reversal_equals_the_original_only_in_the_com_frame() {
        let c = case([[4.0, 0.0], [0.0, 1.0]], [60.0, 10.0], 1.0).unwrap();
        let x = ExactCollision::from_binary64(&c);
        for f in Frame::standard() {
            assert_eq!(
                reverse_equals_original(&x, &f.w_exact(&x)),
                f == Frame::Com,
                "{f}"
            );
        }
        let whump = case([[6.0, 0.0], [0.0, 1.0]], [3.0, -4.0], 0.5).unwrap();
        let x = ExactCollision::from_binary64(&whump);
        assert!(!reverse_equals_original(&x, &Frame::Com.w_exact(&x)));
    }
}
