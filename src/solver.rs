//! What a report needs from a solved collision, in whatever arithmetic: binary64 with the stable
//! formulas of `collision` (the default), or exact rationals (`exact`, for `--exact` and as the
//! reference the accuracy tests measure against).

use nalgebra::Vector2;

use crate::collision::Collision;
use crate::compensated::dot2;
use crate::ellipse::Ellipse;
use crate::quantity::Scalar;

pub type Pair<N> = [N; 2];

/// The quantities of lecture Secs. 1-3 for one collision.
pub trait Solver {
    type N: Scalar;
    fn restitution(&self) -> Self::N;
    fn inertia(&self) -> [Pair<Self::N>; 2];
    fn v_in(&self) -> Pair<Self::N>;
    /// `V_COM = P_total / M_total`.
    fn v_com(&self) -> Self::N;
    /// `V_FIN = (1 + e) V_COM u - e V_IN`.
    fn v_fin(&self) -> Pair<Self::N>;
    /// `P_total = u.M.V`.
    fn total_momentum(&self) -> Self::N;
    /// `P = M.V`.
    fn momentum(&self, v: &Pair<Self::N>) -> Pair<Self::N>;
    /// `X.M.Y`.
    fn form(&self, x: &Pair<Self::N>, y: &Pair<Self::N>) -> Self::N;
    /// `V_COM P_total` (= `V_COM.M.V_IN` = `V_COM.M.V_COM` = `2 KE_COM`).
    fn com_form(&self) -> Self::N;
    fn ke_in(&self) -> Self::N;
    fn ke_fin(&self) -> Self::N;
    fn ke_com(&self) -> Self::N;
    /// `KE_IN - KE_COM = 1/2 mu (V1 - V2)^2`.
    fn crunch(&self) -> Self::N;
    /// `(1 - e^2) crunch`.
    fn lost(&self) -> Self::N;
    /// The energy ellipse `1/2 V.M.V = ke`.
    fn ellipse(&self, ke: &Self::N) -> Ellipse<Self::N>;
    /// Plain dot product `X.Y`.
    fn dot(&self, x: &Pair<Self::N>, y: &Pair<Self::N>) -> Self::N;
    /// Outer product `X (x) Y`.
    fn outer(&self, x: &Pair<Self::N>, y: &Pair<Self::N>) -> [Pair<Self::N>; 2];
    /// `mu = det M / M_total`.
    fn reduced_mass(&self) -> Self::N;
    /// `V1 - V2`.
    fn relative_velocity(&self) -> Self::N;
    /// Relative residuals of momentum conservation and of `KE_FIN = KE_COM + e^2 crunch`.
    fn residuals(&self) -> (f64, f64);
    /// The momentum line `k1 V1 + k2 V2 = P_total`: `(k1, k2, slope = -k1/k2)`, with no slope
    /// when the line is vertical (`k2 = 0`, possible for a general tensor).
    fn momentum_line(&self) -> (Self::N, Self::N, Option<Self::N>);
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

impl Solver for Collision {
    type N = f64;
    fn restitution(&self) -> f64 {
        self.restitution.value()
    }
    fn inertia(&self) -> [Pair<f64>; 2] {
        let m = self.inertia.matrix();
        [[m[(0, 0)], m[(0, 1)]], [m[(1, 0)], m[(1, 1)]]]
    }
    fn v_in(&self) -> Pair<f64> {
        [self.v_in.x, self.v_in.y]
    }
    fn v_com(&self) -> f64 {
        Collision::v_com(self)
    }
    fn v_fin(&self) -> Pair<f64> {
        let f = Collision::v_fin(self);
        [f.x, f.y]
    }
    fn total_momentum(&self) -> f64 {
        Collision::total_momentum(self)
    }
    fn momentum(&self, v: &Pair<f64>) -> Pair<f64> {
        let p = self.inertia.momentum(&vec2(v));
        [p.x, p.y]
    }
    fn form(&self, x: &Pair<f64>, y: &Pair<f64>) -> f64 {
        self.inertia.form(&vec2(x), &vec2(y))
    }
    fn com_form(&self) -> f64 {
        2.0 * Collision::ke_com(self)
    }
    fn ke_in(&self) -> f64 {
        unless_underflow(Collision::ke_in(self), self.v_in != Vector2::zeros())
    }
    fn ke_fin(&self) -> f64 {
        let e = self.restitution.value();
        let moving = Collision::v_com(self) != 0.0 || (e != 0.0 && self.moving_apart());
        unless_underflow(Collision::ke_fin(self), moving)
    }
    fn ke_com(&self) -> f64 {
        unless_underflow(Collision::ke_com(self), Collision::v_com(self) != 0.0)
    }
    fn crunch(&self) -> f64 {
        unless_underflow(Collision::crunch(self), self.moving_apart())
    }
    fn lost(&self) -> f64 {
        let inelastic = !self.restitution.is_elastic();
        unless_underflow(self.energy_lost(), inelastic && self.moving_apart())
    }
    fn ellipse(&self, ke: &f64) -> Ellipse<f64> {
        let axes = (!self.inertia.is_diagonal()).then(|| self.inertia.principal_axes());
        Ellipse::new(&self.inertia, *ke, axes.as_ref())
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
        self.inertia.reduced_mass()
    }
    fn relative_velocity(&self) -> f64 {
        Collision::relative_velocity(self)
    }
    fn residuals(&self) -> (f64, f64) {
        let m = self.inertia.matrix();
        let (k1, k2) = (m[(0, 0)] + m[(0, 1)], m[(0, 1)] + m[(1, 1)]);
        let fin = Collision::v_fin(self);
        let (p_in, p_fin) = (
            Collision::total_momentum(self),
            self.inertia.total_momentum(&fin),
        );
        let scale = (k1 * self.v_in.x).abs() + (k2 * self.v_in.y).abs();
        let scale = scale.max((k1 * fin.x).abs() + (k2 * fin.y).abs());
        let momentum = if scale > 0.0 {
            (p_fin - p_in).abs() / scale
        } else {
            0.0
        };
        let ke_fin = 0.5 * self.inertia.form(&fin, &fin);
        let ke_rule = Collision::ke_fin(self);
        let energy = if ke_fin > 0.0 {
            (ke_fin - ke_rule).abs() / ke_fin
        } else {
            ke_rule.abs()
        };
        (momentum, energy)
    }
    fn momentum_line(&self) -> (f64, f64, Option<f64>) {
        let m = self.inertia.matrix();
        let (k1, k2) = (m[(0, 0)] + m[(0, 1)], m[(0, 1)] + m[(1, 1)]);
        (
            k1,
            k2,
            (k2 != 0.0).then(|| -k1 / k2).filter(|s| s.is_finite()),
        )
    }
}
