//! The binary64 solver: every quantity of lecture Secs. 1-3 from the impulse-form kinematics of
//! `collision`, seen by an observer moving at `w` (`w = 0`: the lab). This is the one place the
//! binary64 energies are computed; each is a short formula evaluated in double-double and rounded
//! once:
//!
//! - crunch `1/2 (mu d) d` from the relative velocity `d = V1 - V2` and the reduced mass (Sec. 2),
//!   never a difference of energies;
//! - `KE_COM = 1/2 (M_total V_COM) V_COM` (Sec. 2, the least energy on the momentum line);
//! - `KE_IN = KE_COM + crunch` (Koenig) and `KE_FIN = KE_COM + e^2 crunch`: sums of non-negative
//!   terms;
//! - lost `(1 - e^2) crunch` with `1 - e^2 = (1 - e)(1 + e)` exact in its factors.
//!
//! Shifts are exact: `w` is held as a double-double (`V_COM` or a body's FIN velocity exactly as
//! the kinematics have them), so the COM frame puts COM at 0 and "body i finally at rest" puts
//! FIN_i at 0, and each frame's energies come from its own relative velocity. In the frames that
//! move with COM or with a body's FIN, the velocities that are small multiples of `e` are not
//! differences of lab velocities (which would keep only their rounding, 1e-33 for `e = 1e-150`)
//! but the impulse form's own terms: with `d = V2 - V1`, weights `w1, w2` (`w1 + w2 = 1`) and
//! `k = 1 + e`, `IN_COM = (-w2 d, w1 d)`, `FIN_COM = e (w2 d, -w1 d)`; finally at rest,
//! `FIN = (0, -e d)` (body 1) or `(e d, 0)` (body 2), `IN = FIN - k (w2 d, -w1 d)`.

use nalgebra::Vector2;

use crate::line::collision::Collision;
use crate::line::ellipse::Ellipse;
use crate::line::frame::Frame;
use crate::solver::exact::ExactCollision;
use crate::solver::{Lab, Pair, Solver};
use crate::values::compensated::{Dd, dot2};

/// A binary64 collision seen by an observer moving at `w`.
#[derive(Clone, Debug)]
pub struct Binary64<'a> {
    pub lab: &'a Collision,
    pub w: Dd,
    /// How the frame's velocities are formed (module docs).
    shift: Shift,
    /// `(KE_COM, crunch)` once computed: every energy is built from these two (a table row
    /// asks for several).
    parts: std::cell::Cell<Option<(Dd, Dd)>>,
}

/// How a frame's velocities are formed from the lab's.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Shift {
    /// Every velocity less `w` (the lab, a body initially at rest, an observer velocity).
    By,
    /// Moving with COM.
    Com,
    /// Moving with body `i`'s FIN (0 or 1).
    Fin(usize),
}

/// The observer's velocity of `frame` for a binary64 collision (lecture Sec. 4).
pub fn observer_velocity(c: &Collision, frame: &Frame) -> Dd {
    match frame {
        Frame::Lab => Dd::new(0.0),
        Frame::Com => c.v_com_dd(),
        Frame::RestIn(i) => Dd::new(c.v_in[i - 1]),
        Frame::RestFin(i) => c.v_fin_dd()[i - 1],
        Frame::Velocity(n) => Dd::new(n.value()),
        // Refused on a line by `Frame::on_line` before a solver sees it.
        Frame::Vector(v) => Dd::new(v.first().map_or(0.0, crate::values::number::Number::value)),
    }
}

impl<'a> Binary64<'a> {
    /// `lab` seen from `frame`.
    pub fn new(lab: &'a Collision, frame: &Frame) -> Binary64<'a> {
        let shift = match frame {
            Frame::Com => Shift::Com,
            Frame::RestFin(i) => Shift::Fin(i - 1),
            _ => Shift::By,
        };
        Binary64 {
            lab,
            w: observer_velocity(lab, frame),
            shift,
            parts: Default::default(),
        }
    }

    /// The lab frame itself.
    pub fn lab(lab: &'a Collision) -> Binary64<'a> {
        Binary64 {
            lab,
            w: Dd::new(0.0),
            shift: Shift::By,
            parts: Default::default(),
        }
    }

    /// `(d, w1 d, w2 d, e)` with `d = V2 - V1`: the terms of the impulse form.
    fn terms(&self) -> (Dd, Dd, Dd, Dd) {
        let (w1, w2) = self.lab.inertia.weights_dd();
        let d = self.lab.relative_velocity_dd();
        (d, w1 * d, w2 * d, Dd::new(self.lab.restitution.value()))
    }
    /// The impulse's change of velocity `k (w2 d, -w1 d)`, the same in every frame.
    fn kick(&self) -> [Dd; 2] {
        let (_, w1d, w2d, e) = self.terms();
        let k = Dd::new(1.0) + e;
        [k * w2d, zero() - k * w1d]
    }
    fn in_dd(&self) -> [Dd; 2] {
        match self.shift {
            Shift::By => [
                Dd::new(self.lab.v_in.x) - self.w,
                Dd::new(self.lab.v_in.y) - self.w,
            ],
            Shift::Com => {
                let (_, w1d, w2d, _) = self.terms();
                [zero() - w2d, w1d]
            }
            Shift::Fin(_) => {
                let [f1, f2] = self.fin_dd();
                let [k1, k2] = self.kick();
                [f1 - k1, f2 - k2]
            }
        }
    }
    fn fin_dd(&self) -> [Dd; 2] {
        if self.lab.restitution.is_totally_inelastic() {
            let c = self.com_dd();
            return [c, c];
        }
        let (d, w1d, w2d, e) = self.terms();
        match self.shift {
            Shift::By => self.lab.v_fin_dd().map(|f| f - self.w),
            Shift::Com => [e * w2d, zero() - e * w1d],
            Shift::Fin(0) => [zero(), zero() - e * d],
            Shift::Fin(_) => [e * d, zero()],
        }
    }
    fn com_dd(&self) -> Dd {
        let (_, w1d, w2d, e) = self.terms();
        match self.shift {
            Shift::By => self.lab.v_com_dd() - self.w,
            Shift::Com => zero(),
            // V_COM - FIN1 = -e w2 d, V_COM - FIN2 = e w1 d.
            Shift::Fin(0) => zero() - e * w2d,
            Shift::Fin(_) => e * w1d,
        }
    }
    /// `V1 - V2` from this frame's own IN velocities.
    fn relative_dd(&self) -> Dd {
        let [a, b] = self.in_dd();
        a - b
    }
    fn crunch_dd(&self) -> Dd {
        self.parts().1
    }
    /// `KE_COM = 1/2 (M_total V_COM) V_COM`.
    fn ke_com_dd(&self) -> Dd {
        self.parts().0
    }
    /// `(KE_COM, crunch)`, computed once.
    fn parts(&self) -> (Dd, Dd) {
        if let Some(p) = self.parts.get() {
            return p;
        }
        let vc = self.com_dd();
        let ke_com = Dd::new(0.5) * ((self.lab.inertia.total_dd() * vc) * vc);
        let d = self.relative_dd();
        let crunch = Dd::new(0.5) * ((self.lab.inertia.reduced_mass_dd() * d) * d);
        self.parts.set(Some((ke_com, crunch)));
        (ke_com, crunch)
    }
    fn e2(&self) -> Dd {
        let e = self.lab.restitution.value();
        Dd::prod(e, e)
    }
    fn moving(&self) -> bool {
        self.relative_dd().value() != 0.0
    }
}

/// A double-double 0, so that `zero() - x` of a zero `x` is +0 (a negation would print -0).
fn zero() -> Dd {
    Dd::new(0.0)
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

impl Solver for Binary64<'_> {
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
        if e == 1.0 && !self.lab.restitution.is_elastic() {
            // A typed e within half an ulp of 1 but not 1 (0.99999999999999999999999): the
            // factor 1 - e^2 exactly from the typed value, rounded once, so the energy printed
            // agrees with the label.
            let x = self.lab.restitution.number().exact();
            let factor = crate::values::rational::int(1) - &x * &x;
            let factor = crate::values::quantity::to_f64(&factor).unwrap_or(0.0);
            return (Dd::new(factor) * self.crunch_dd()).value();
        }
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
    /// `-(FIN1 - FIN2) / (IN1 - IN2)` from this frame's velocities, in double-double.
    fn restitution_seen(&self) -> Option<f64> {
        let [f1, f2] = self.fin_dd();
        let d = self.relative_dd();
        (d.value() != 0.0).then(|| ((f2 - f1) / d).value())
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
    /// The binary64 inputs exactly, seen by the observer at `w` (a double-double, exact too).
    fn order(&self) -> crate::line::order::Order {
        crate::line::order::Order::before(&self.lab.v_in.x, &self.lab.v_in.y)
    }
    fn superelastic(&self) -> bool {
        self.lab.restitution.is_superelastic()
    }
    fn exact(&self) -> ExactCollision {
        let x = ExactCollision::from_binary64(self.lab);
        // COM and FIN frames move with the exact COM or FIN of these values, as the binary64
        // frame moves with them (module docs).
        let w = match self.shift {
            Shift::By => {
                crate::values::quantity::from_f64(self.w.hi)
                    + crate::values::quantity::from_f64(self.w.lo)
            }
            Shift::Com => x.observer_velocity(&Frame::Com),
            Shift::Fin(i) => x.observer_velocity(&Frame::RestFin(i + 1)),
        };
        x.observed(&w)
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

impl Lab for Collision {
    type N = f64;
    type Seen<'a> = Binary64<'a>;
    fn seen_from(&self, frame: &Frame) -> (f64, Binary64<'_>) {
        let seen = Binary64::new(self, frame);
        (seen.w.value(), seen)
    }
    /// Decided exactly, on the binary64 values this collision computes with.
    fn is_own_time_reverse(&self, frame: &Frame) -> bool {
        let x = ExactCollision::from_binary64(self);
        x.is_own_time_reverse_at(&x.observer_velocity(frame))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::line::inertia::{InertiaTensor, Mass};

    fn case(m1: &str, m2: &str, v: [f64; 2], e: &str) -> Collision {
        let m = InertiaTensor::diagonal(&m1.parse::<Mass>().unwrap(), &m2.parse::<Mass>().unwrap());
        Collision::new(m.unwrap(), Vector2::new(v[0], v[1]), e.parse().unwrap())
    }

    #[test]
    fn fig_1_3_energies() {
        let c = case("4", "1", [60.0, 10.0], "elastic");
        let s = Binary64::lab(&c);
        assert_eq!(s.ke_in(), 7250.0);
        assert_eq!(s.ke_com(), 6250.0);
        assert_eq!(s.ke_fin(), 7250.0);
        assert_eq!(s.crunch(), 1000.0);
        assert_eq!(s.lost(), 0.0);
        let stuck = case("4", "1", [60.0, 10.0], "inelastic");
        assert_eq!(Binary64::lab(&stuck).lost(), 1000.0);
    }

    #[test]
    fn fig_2_3_ka_whump_energies() {
        let c = case("6", "1", [3.0, -4.0], "2/3");
        let s = Binary64::lab(&c);
        approx::assert_relative_eq!(s.ke_fin(), 70.0 / 3.0, max_relative = 2.0 * f64::EPSILON);
        assert_eq!(s.ke_com(), 14.0);
        assert_eq!(s.crunch(), 21.0);
    }

    #[test]
    fn boosted_crunch_keeps_full_accuracy() {
        // KE_IN ~ 1e30 here; the crunch of 1/2 (1/2) 1^2 = 0.25 survives exactly.
        let c = case("1", "1", [1e15 + 1.0, 1e15], "elastic");
        assert_eq!(Binary64::lab(&c).crunch(), 0.25);
    }

    #[test]
    fn fig_3_4_vw_finally_at_rest_is_exactly_at_rest() {
        let c = case("6", "1", [3.0, -4.0], "elastic");
        let o = Binary64::new(&c, &Frame::RestFin(2));
        assert_eq!(o.w.value(), 8.0);
        assert_eq!(o.v_in(), [-5.0, -12.0]);
        assert_eq!(o.v_fin(), [-7.0, 0.0]);
        assert_eq!(o.crunch(), 21.0);
        assert_eq!(o.restitution_seen(), Some(1.0));
    }
}
