//! How a collision is computed: the quantities a report needs, in whatever arithmetic. Binary64
//! with the stable formulas (`binary64`, seen from any frame; the default), or exact rationals
//! (`exact`, for `--exact` and as the reference the accuracy tests measure against). A new
//! arithmetic is a new implementation of `Solver`; reports, frames tables and pictures take any.

pub mod binary64;
pub mod exact;
pub mod rounded;

use crate::line::ellipse::Ellipse;
use crate::line::frame::Frame;
use crate::values::quantity::Scalar;

pub type Pair<N> = [N; 2];

/// The quantities of lecture Secs. 1-3 for one collision.
pub trait Solver {
    type N: Scalar;
    fn restitution(&self) -> Self::N;
    /// Which body is on the left, from the velocities at IN (`line::order`; the same in every
    /// frame): the bodies meet iff `V1 != V2`.
    fn order(&self) -> crate::line::order::Order;
    /// `e > 1` as typed: energy is released (`lost` is negative).
    fn superelastic(&self) -> bool;
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
    /// `e` from this frame's own velocities, `-(FIN1 - FIN2) / (IN1 - IN2)`; `None` when
    /// `V1 = V2`.
    fn restitution_seen(&self) -> Option<Self::N>;
    /// Relative residuals of momentum conservation and of `KE_FIN = KE_COM + e^2 crunch`.
    fn residuals(&self) -> (f64, f64);
    /// The momentum line `k1 V1 + k2 V2 = P_total`: `(k1, k2, slope = -k1/k2)`, with no slope
    /// when the line is vertical (`k2 = 0`, possible for a general tensor).
    fn momentum_line(&self) -> (Self::N, Self::N, Option<Self::N>);
    /// This frame's collision in exact rationals (of the values this solver computes with), for
    /// the quantities that are cheap enough to give exactly and round once (`changes`).
    fn exact(&self) -> exact::ExactCollision;
}

/// A lab collision in one arithmetic, from which the collision seen from any frame is made: the
/// seam that lets one report, frames table or picture serve binary64 and exact arithmetic.
pub trait Lab {
    type N: Scalar;
    type Seen<'a>: Solver<N = Self::N>
    where
        Self: 'a;
    /// The observer velocity `w` of `frame`, and the collision as that observer sees it.
    fn seen_from(&self, frame: &Frame) -> (Self::N, Self::Seen<'_>);
    /// Whether the time-reversed collision equals the original seen from `frame` (decided in
    /// exact arithmetic).
    fn is_own_time_reverse(&self, frame: &Frame) -> bool;
}
