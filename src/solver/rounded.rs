//! A solved homework problem's collision in binary64 as the exact one rounded once: every
//! quantity of the report is the exact rational of the solved values (`exact`), rounded to the
//! nearest binary64. A solved value is itself a rounding of its exact solution, so computing
//! FIN and the energies again in binary64 from it (the default `binary64` path) would print a
//! FIN that is neither the typed nor the solved one (`-1.224, 0.0069999999999999` where 0.007
//! was typed, issue 41): the one answer is the exact one.

use crate::line::ellipse::Ellipse;
use crate::line::frame::Frame;
use crate::solver::exact::ExactCollision;
use crate::solver::{Lab, Pair, Solver};
use crate::values::quantity::Exact;
use crate::values::rational::to_f64;

/// An exact value, rounded once (`NaN` beyond binary64's range, which the report refuses).
fn round(x: &Exact) -> f64 {
    to_f64(x.rational()).unwrap_or(f64::NAN)
}

fn pair(p: &Pair<Exact>) -> Pair<f64> {
    [round(&p[0]), round(&p[1])]
}

/// An exact collision whose every quantity is given rounded once.
#[derive(Clone, Debug)]
pub struct Rounded {
    exact: ExactCollision,
}

impl Rounded {
    pub fn new(exact: ExactCollision) -> Rounded {
        Rounded { exact }
    }

    /// The exact vector a rounded one stands for: IN, FIN or COM (the vectors a report forms
    /// products of), else the binary64 value itself, exactly.
    fn vector(&self, v: &Pair<f64>) -> Pair<Exact> {
        let com = self.exact.v_com();
        let known = [self.exact.v_in(), self.exact.v_fin(), [com.clone(), com]];
        known
            .into_iter()
            .find(|k| pair(k) == *v)
            .unwrap_or_else(|| v.map(|x| Exact::Rational(crate::values::rational::from_f64(x))))
    }

    /// The exact energy a rounded one stands for (KE_IN, KE_FIN or KE_COM), else the value.
    fn energy(&self, ke: f64) -> Exact {
        [self.exact.ke_in(), self.exact.ke_fin(), self.exact.ke_com()]
            .into_iter()
            .find(|k| round(k) == ke)
            .unwrap_or_else(|| Exact::Rational(crate::values::rational::from_f64(ke)))
    }
}

impl Solver for Rounded {
    type N = f64;
    fn restitution(&self) -> f64 {
        round(&self.exact.restitution())
    }
    fn order(&self) -> crate::line::order::Order {
        self.exact.order()
    }
    fn superelastic(&self) -> bool {
        self.exact.superelastic()
    }
    fn inertia(&self) -> [Pair<f64>; 2] {
        self.exact.inertia().map(|row| pair(&row))
    }
    fn v_in(&self) -> Pair<f64> {
        pair(&self.exact.v_in())
    }
    fn v_com(&self) -> f64 {
        round(&self.exact.v_com())
    }
    fn v_fin(&self) -> Pair<f64> {
        pair(&self.exact.v_fin())
    }
    fn total_momentum(&self) -> f64 {
        round(&self.exact.total_momentum())
    }
    fn momentum(&self, v: &Pair<f64>) -> Pair<f64> {
        pair(&self.exact.momentum(&self.vector(v)))
    }
    fn form(&self, x: &Pair<f64>, y: &Pair<f64>) -> f64 {
        round(&self.exact.form(&self.vector(x), &self.vector(y)))
    }
    fn com_form(&self) -> f64 {
        round(&self.exact.com_form())
    }
    fn ke_in(&self) -> f64 {
        round(&self.exact.ke_in())
    }
    fn ke_fin(&self) -> f64 {
        round(&self.exact.ke_fin())
    }
    fn ke_com(&self) -> f64 {
        round(&self.exact.ke_com())
    }
    fn crunch(&self) -> f64 {
        round(&self.exact.crunch())
    }
    fn lost(&self) -> f64 {
        round(&self.exact.lost())
    }
    fn ellipse(&self, ke: &f64) -> Ellipse<f64> {
        let e = self.exact.ellipse(&self.energy(*ke));
        Ellipse {
            a: round(&e.a),
            b: round(&e.b),
            axes: e.axes.map(|a| a.map(|p| pair(&p))),
            approx: false,
        }
    }
    fn dot(&self, x: &Pair<f64>, y: &Pair<f64>) -> f64 {
        round(&self.exact.dot(&self.vector(x), &self.vector(y)))
    }
    fn outer(&self, x: &Pair<f64>, y: &Pair<f64>) -> [Pair<f64>; 2] {
        self.exact
            .outer(&self.vector(x), &self.vector(y))
            .map(|row| pair(&row))
    }
    fn reduced_mass(&self) -> f64 {
        round(&self.exact.reduced_mass())
    }
    fn relative_velocity(&self) -> f64 {
        round(&self.exact.relative_velocity())
    }
    fn restitution_seen(&self) -> Option<f64> {
        self.exact.restitution_seen().map(|e| round(&e))
    }
    fn residuals(&self) -> (f64, f64) {
        self.exact.residuals()
    }
    fn momentum_line(&self) -> (f64, f64, Option<f64>) {
        let (k1, k2, slope) = self.exact.momentum_line();
        (round(&k1), round(&k2), slope.map(|s| round(&s)))
    }
    fn exact(&self) -> ExactCollision {
        self.exact.clone()
    }
}

impl Lab for Rounded {
    type N = f64;
    type Seen<'a> = Rounded;
    fn seen_from(&self, frame: &Frame) -> (f64, Rounded) {
        let (w, seen) = self.exact.seen_from(frame);
        (round(&w), Rounded::new(seen))
    }
    fn is_own_time_reverse(&self, frame: &Frame) -> bool {
        self.exact.is_own_time_reverse(frame)
    }
}
