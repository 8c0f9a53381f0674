//! Exact arithmetic (`--exact`, and the reference every accuracy test measures against): every
//! rational quantity as a `Q`, by the lecture's formulas taken literally, since exact
//! arithmetic needs no care about cancellation. Irrational quantities (ellipse radii and, for a
//! general tensor, its axes) are computed from the exact energies to well past
//! `APPROX_DIGITS` digits and marked approximate.

use crate::values::rational::{Q, half};
use num_traits::{One, Signed, Zero};

use crate::line::case::Case;
use crate::line::collision::Collision;
use crate::line::ellipse::Ellipse;
use crate::line::frame::Frame;
use crate::solver::{Lab, Pair, Solver};
use crate::values::quantity::{APPROX_DIGITS, Exact, from_f64, sqrt};

/// Digits carried inside irrational computations before the final truncation.
const WORK_DIGITS: usize = APPROX_DIGITS + 20;

/// A collision in exact rationals: `M = [[a, c], [c, b]]`, `V_IN`, `e`.
#[derive(Clone, Debug, PartialEq)]
pub struct ExactCollision {
    pub a: Q,
    pub b: Q,
    pub c: Q,
    pub v: Pair<Q>,
    pub e: Q,
    /// `(V_COM, V_FIN, crunch)` once computed: every section reuses them, and each rational
    /// operation on long numbers costs a gcd.
    memo: std::cell::OnceCell<(Q, Pair<Q>, Q)>,
}

fn r(q: Q) -> Exact {
    Exact::Rational(q)
}

impl ExactCollision {
    /// From the text the user typed (`0.1` is one tenth, `2/3` two thirds).
    pub fn from_case(case: &Case) -> ExactCollision {
        let m = case.inertia().entries();
        ExactCollision {
            a: m[0][0].exact(),
            b: m[1][1].exact(),
            c: m[0][1].exact(),
            v: [case.velocities[0].exact(), case.velocities[1].exact()],
            e: case.restitution().number().exact(),
            memo: Default::default(),
        }
    }

    /// From the binary64 values a `Collision` computes with: the reference for its errors.
    pub fn from_binary64(c: &Collision) -> ExactCollision {
        let m = c.inertia.matrix();
        ExactCollision {
            a: from_f64(m[(0, 0)]),
            b: from_f64(m[(1, 1)]),
            c: from_f64(m[(0, 1)]),
            v: [from_f64(c.v_in.x), from_f64(c.v_in.y)],
            e: from_f64(c.restitution.value()),
            memo: Default::default(),
        }
    }

    /// The same collision seen by an observer moving at `w`: every velocity shifted by `-w`.
    pub fn observed(&self, w: &Q) -> ExactCollision {
        // A new memo: the shifted velocities have their own V_COM and FIN.
        ExactCollision {
            a: self.a.clone(),
            b: self.b.clone(),
            c: self.c.clone(),
            v: [&self.v[0] - w, &self.v[1] - w],
            e: self.e.clone(),
            memo: Default::default(),
        }
    }

    /// The observer's velocity of `frame` (a typed velocity from its text).
    pub fn observer_velocity(&self, frame: &Frame) -> Q {
        match frame {
            Frame::Lab => Q::zero(),
            Frame::Com => self.v_com_q(),
            Frame::RestIn(i) => self.v[i - 1].clone(),
            Frame::RestFin(i) => self.v_fin_q()[i - 1].clone(),
            Frame::Velocity(n) => n.exact(),
            // Refused on a line by `Frame::on_line` before a solver sees it.
            Frame::Vector(v) => v
                .first()
                .map_or_else(Q::zero, crate::values::number::Number::exact),
        }
    }

    /// Whether the time-reversed collision (IN' = -FIN, FIN' = -IN) equals the original seen from
    /// an observer at `w`: exactly when `IN + FIN = 2 w` and the collision is elastic, that is
    /// when `w` is the COM velocity (lecture Sec. 4).
    pub fn is_own_time_reverse_at(&self, w: &Q) -> bool {
        let [f1, f2] = self.v_fin_q();
        let two_w = w + w;
        self.e.is_one() && &self.v[0] + f1 == two_w && &self.v[1] + f2 == two_w
    }

    pub fn m_total(&self) -> Q {
        &self.a + &self.c + &self.c + &self.b
    }
    pub fn p_total(&self) -> Q {
        (&self.a + &self.c) * &self.v[0] + (&self.c + &self.b) * &self.v[1]
    }
    /// `(V_COM, V_FIN, crunch)`, computed once.
    fn memo(&self) -> &(Q, Pair<Q>, Q) {
        self.memo.get_or_init(|| {
            let vc = self.p_total() / self.m_total();
            let fin = self.v_fin_from(&vc);
            let crunch = half() * self.form_q(&self.v, &self.v) - half() * &vc * self.p_total();
            (vc, fin, crunch)
        })
    }
    pub fn v_com_q(&self) -> Q {
        self.memo().0.clone()
    }
    pub fn v_fin_q(&self) -> Pair<Q> {
        self.memo().1.clone()
    }
    fn v_fin_from(&self, vc: &Q) -> Pair<Q> {
        let k = Q::one() + &self.e;
        [
            &k * vc - &self.e * &self.v[0],
            &k * vc - &self.e * &self.v[1],
        ]
    }
    pub fn form_q(&self, x: &Pair<Q>, y: &Pair<Q>) -> Q {
        &x[0] * (&self.a * &y[0] + &self.c * &y[1]) + &x[1] * (&self.c * &y[0] + &self.b * &y[1])
    }
    pub fn ke_in_q(&self) -> Q {
        half() * self.form_q(&self.v, &self.v)
    }
    pub fn ke_com_q(&self) -> Q {
        half() * self.v_com_q() * self.p_total()
    }
    /// By definition, `KE_IN - KE_COM`: exact arithmetic may subtract.
    pub fn crunch_q(&self) -> Q {
        self.memo().2.clone()
    }
    pub fn ke_fin_q(&self) -> Q {
        let f = self.v_fin_q();
        half() * self.form_q(&f, &f)
    }
    pub fn lost_q(&self) -> Q {
        (Q::one() - &self.e * &self.e) * self.crunch_q()
    }
    /// What the collision changes for each body (`changes`).
    pub fn changes(&self, contact_time: Option<&Q>) -> crate::line::changes::Changes {
        let fin = self.v_fin_q();
        crate::line::changes::Changes::of(
            &crate::line::changes::Event {
                tensor: [[&self.a, &self.c], [&self.c, &self.b]],
                v_in: &self.v,
                fin: &fin,
            },
            contact_time,
        )
    }
    pub fn det(&self) -> Q {
        &self.a * &self.b - &self.c * &self.c
    }

    /// Eigenvalues (ascending) and unit eigenvectors of `M`, to `WORK_DIGITS` digits.
    /// `lambda_min = det / lambda_max` avoids the cancellation in `(tr - sqrt(disc)) / 2`.
    fn principal_axes(&self) -> [(Q, Pair<Q>); 2] {
        let tr = &self.a + &self.b;
        let disc = (&self.a - &self.b) * (&self.a - &self.b)
            + crate::values::rational::int(4) * &self.c * &self.c;
        let l_max = (&tr + sqrt(&disc, WORK_DIGITS)) * half();
        let l_min = self.det() / &l_max;
        let axis = |l: &Q| {
            // (M - l I) q = 0: q = (c, l - a) or (l - b, c), whichever is longer.
            let p = [self.c.clone(), l - &self.a];
            let s = [l - &self.b, self.c.clone()];
            let n2 = |v: &Pair<Q>| &v[0] * &v[0] + &v[1] * &v[1];
            let q = if n2(&p) >= n2(&s) { p } else { s };
            let norm = sqrt(&n2(&q), WORK_DIGITS);
            let mut unit = [&q[0] / &norm, &q[1] / &norm];
            if unit[0].is_negative() || (unit[0].is_zero() && unit[1].is_negative()) {
                unit = [-&unit[0], -&unit[1]];
            }
            unit
        };
        let (qa, qb) = (axis(&l_min), axis(&l_max));
        [(l_min, qa), (l_max, qb)]
    }
}

impl Solver for ExactCollision {
    type N = Exact;
    fn restitution(&self) -> Exact {
        r(self.e.clone())
    }
    fn inertia(&self) -> [Pair<Exact>; 2] {
        [
            [r(self.a.clone()), r(self.c.clone())],
            [r(self.c.clone()), r(self.b.clone())],
        ]
    }
    fn v_in(&self) -> Pair<Exact> {
        [r(self.v[0].clone()), r(self.v[1].clone())]
    }
    fn v_com(&self) -> Exact {
        r(self.v_com_q())
    }
    fn v_fin(&self) -> Pair<Exact> {
        let [x, y] = self.v_fin_q();
        [r(x), r(y)]
    }
    fn total_momentum(&self) -> Exact {
        r(self.p_total())
    }
    fn momentum(&self, v: &Pair<Exact>) -> Pair<Exact> {
        let (x, y) = (v[0].rational(), v[1].rational());
        [r(&self.a * x + &self.c * y), r(&self.c * x + &self.b * y)]
    }
    fn form(&self, x: &Pair<Exact>, y: &Pair<Exact>) -> Exact {
        let q = |p: &Pair<Exact>| [p[0].rational().clone(), p[1].rational().clone()];
        r(self.form_q(&q(x), &q(y)))
    }
    fn com_form(&self) -> Exact {
        r(self.v_com_q() * self.p_total())
    }
    fn ke_in(&self) -> Exact {
        r(self.ke_in_q())
    }
    fn ke_fin(&self) -> Exact {
        r(self.ke_fin_q())
    }
    fn ke_com(&self) -> Exact {
        r(self.ke_com_q())
    }
    fn crunch(&self) -> Exact {
        r(self.crunch_q())
    }
    fn lost(&self) -> Exact {
        r(self.lost_q())
    }
    fn ellipse(&self, ke: &Exact) -> Ellipse<Exact> {
        let two_ke = ke.rational() * crate::values::rational::int(2);
        let radius = |l: &Q| Exact::Approx(sqrt(&(&two_ke / l), WORK_DIGITS));
        if self.c.is_zero() {
            return Ellipse {
                a: radius(&self.a),
                b: radius(&self.b),
                axes: None,
                approx: true,
            };
        }
        let [(l1, q1), (l2, q2)] = self.principal_axes();
        let ax = |q: Pair<Q>| [Exact::Approx(q[0].clone()), Exact::Approx(q[1].clone())];
        Ellipse {
            a: radius(&l1),
            b: radius(&l2),
            axes: Some([ax(q1), ax(q2)]),
            approx: true,
        }
    }
    fn dot(&self, x: &Pair<Exact>, y: &Pair<Exact>) -> Exact {
        r(x[0].rational() * y[0].rational() + x[1].rational() * y[1].rational())
    }
    fn outer(&self, x: &Pair<Exact>, y: &Pair<Exact>) -> [Pair<Exact>; 2] {
        let p = |i: usize, j: usize| r(x[i].rational() * y[j].rational());
        [[p(0, 0), p(0, 1)], [p(1, 0), p(1, 1)]]
    }
    fn reduced_mass(&self) -> Exact {
        r(self.det() / self.m_total())
    }
    fn relative_velocity(&self) -> Exact {
        r(&self.v[0] - &self.v[1])
    }
    fn restitution_seen(&self) -> Option<Exact> {
        let [f1, f2] = self.v_fin_q();
        let d = &self.v[0] - &self.v[1];
        (!d.is_zero()).then(|| r((f2 - f1) / d))
    }
    fn residuals(&self) -> (f64, f64) {
        // Exact arithmetic: both are identically zero, computed rather than assumed.
        let [f1, f2] = self.v_fin_q();
        let p_fin = (&self.a + &self.c) * f1 + (&self.c + &self.b) * f2;
        let momentum = (p_fin - self.p_total()).abs();
        let energy =
            (self.ke_fin_q() - self.ke_com_q() - &self.e * &self.e * self.crunch_q()).abs();
        (
            crate::values::quantity::to_f64(&momentum).unwrap_or(f64::MAX),
            crate::values::quantity::to_f64(&energy).unwrap_or(f64::MAX),
        )
    }
    fn order(&self) -> crate::line::order::Order {
        crate::line::order::Order::before(&self.v[0], &self.v[1])
    }
    fn superelastic(&self) -> bool {
        self.e > Q::one()
    }
    fn exact(&self) -> ExactCollision {
        self.clone()
    }
    fn momentum_line(&self) -> (Exact, Exact, Option<Exact>) {
        let (k1, k2) = (&self.a + &self.c, &self.c + &self.b);
        let slope = (!k2.is_zero()).then(|| r(-&k1 / &k2));
        (r(k1), r(k2), slope)
    }
}

impl Lab for ExactCollision {
    type N = Exact;
    type Seen<'a> = ExactCollision;
    fn seen_from(&self, frame: &Frame) -> (Exact, ExactCollision) {
        let w = self.observer_velocity(frame);
        let seen = self.observed(&w);
        (r(w), seen)
    }
    fn is_own_time_reverse(&self, frame: &Frame) -> bool {
        self.is_own_time_reverse_at(&self.observer_velocity(frame))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::accuracy::case;

    #[test]
    fn reversal_equals_the_original_only_in_the_com_frame() {
        let c = case([[4.0, 0.0], [0.0, 1.0]], [60.0, 10.0], 1.0).unwrap();
        let x = ExactCollision::from_binary64(&c);
        for f in Frame::standard() {
            assert_eq!(
                x.is_own_time_reverse_at(&x.observer_velocity(&f)),
                f == Frame::Com,
                "{f}"
            );
        }
        let whump = case([[6.0, 0.0], [0.0, 1.0]], [3.0, -4.0], 0.5).unwrap();
        let x = ExactCollision::from_binary64(&whump);
        assert!(!x.is_own_time_reverse(&Frame::Com));
    }
}
