//! The two-body collision on a rail (lecture Sec. 1-3), solved where the momentum line meets the
//! energy ellipse.
//!
//! Along the momentum line through IN, `V(s) = V_IN + s t` with `t = (M12 + M22, -(M11 + M12))`
//! (so `u.M.t = 0`: momentum is the same at every `s`), the energy is the quadratic
//! `q(s) = V_IN.M.V_IN + 2 s t.M.V_IN + s^2 t.M.t`. One root is IN itself, `s = 0`; by Vieta's rule
//! the other is `s_el = -2 t.M.V_IN / t.M.t`. Since `M t = det M (1, -1)`, `t.M.V_IN = det M (V1 - V2)`
//! and `t.M.t = det M M_total`, so `s_el = 2 (V2 - V1) / M_total`: the elastic FIN, found from the
//! relative velocity alone, with no quadratic formula and no difference of large energies. With
//! restitution `e`, FIN sits at `(1 + e)/2` of the way from IN to it:
//! `V_FIN = V_IN + (1 + e) (V2 - V1) (w2, -w1)` with the COM weights `w = t / M_total` swapped
//! (`w2 = (M12 + M22)/M_total`): the impulse form of `V_FIN = (1 + e) V_COM u - e V_IN`.

use nalgebra::Vector2;

use crate::line::inertia::InertiaTensor;
use crate::line::restitution::Restitution;
use crate::values::compensated::Dd;

/// A collision to solve: tensor, initial velocities, restitution.
#[derive(Clone, Debug)]
pub struct Collision {
    pub inertia: InertiaTensor,
    pub v_in: Vector2<f64>,
    pub restitution: Restitution,
}

impl Collision {
    pub fn new(inertia: InertiaTensor, v_in: Vector2<f64>, restitution: Restitution) -> Self {
        Collision {
            inertia,
            v_in,
            restitution,
        }
    }

    /// Relative velocity `V1 - V2` at IN.
    pub fn relative_velocity(&self) -> f64 {
        self.v_in.x - self.v_in.y
    }

    /// `P_total = u.M.V_IN` (Axiom 1: the same at IN, COM and FIN).
    pub fn total_momentum(&self) -> f64 {
        self.inertia.total_momentum(&self.v_in)
    }

    /// `V_COM = P_total / M_total`: the momentum line meets the diagonal `V1 = V2` (Sec. 1),
    /// written as a weighted mean (`v_com_dd`) so it cannot overflow where `P_total` would, and
    /// evaluated in double-double so the one rounding is the last.
    pub fn v_com(&self) -> f64 {
        self.v_com_dd().value()
    }

    /// `V2 - V1` exactly, as a double-double.
    pub fn relative_velocity_dd(&self) -> Dd {
        Dd::sum(self.v_in.y, -self.v_in.x)
    }

    /// The direction of the momentum line through IN, scaled to `(w2, -w1) = t / M_total`.
    pub fn momentum_line_direction(&self) -> Vector2<f64> {
        let (w1, w2) = self.inertia.weights();
        Vector2::new(w2, -w1)
    }

    /// Parameter of the elastic FIN on the momentum line `V_IN + s (w2, -w1)`: the second root
    /// of the energy quadratic by Vieta's rule (module docs), `s_el = 2 (V2 - V1)`.
    pub fn elastic_root(&self) -> f64 {
        2.0 * (self.v_in.y - self.v_in.x)
    }

    /// `V_FIN = V_IN + (1 + e)/2 s_el (w2, -w1)` (the impulse form), componentwise from the
    /// relative velocity, evaluated in double-double and rounded once: each component is
    /// correctly rounded but for near-ties, however IN's components compare in size.
    pub fn v_fin(&self) -> Vector2<f64> {
        let [f1, f2] = self.v_fin_dd();
        Vector2::new(f1.value(), f2.value())
    }

    /// `V_FIN` as double-doubles (see `v_fin`).
    pub fn v_fin_dd(&self) -> [Dd; 2] {
        if self.restitution.is_totally_inelastic() {
            let c = self.v_com_dd();
            return [c, c];
        }
        let (w1, w2) = self.inertia.weights_dd();
        let d = self.relative_velocity_dd();
        let k = Dd::sum(1.0, self.restitution.value());
        let kd = k * d;
        [
            Dd::new(self.v_in.x) + w2 * kd,
            Dd::new(self.v_in.y) - w1 * kd,
        ]
    }

    /// `V_COM` as a double-double (see `v_com`): from the body with the larger weight, moved
    /// toward the other by the smaller weight, `V1 + w2 (V2 - V1)` or `V2 - w1 (V2 - V1)`, so the
    /// correction is the small term (with a mass ratio of 1e27, the other form cancels two terms
    /// 1e27 times larger than the result).
    pub fn v_com_dd(&self) -> Dd {
        let (w1, w2) = self.inertia.weights_dd();
        let d = self.relative_velocity_dd();
        if w2.hi.abs() <= w1.hi.abs() {
            Dd::new(self.v_in.x) + w2 * d
        } else {
            Dd::new(self.v_in.y) - w1 * d
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::line::inertia::Mass;

    fn case(m1: &str, m2: &str, v1: f64, v2: f64, e: &str) -> Collision {
        let m = InertiaTensor::diagonal(&m1.parse::<Mass>().unwrap(), &m2.parse::<Mass>().unwrap());
        Collision::new(m.unwrap(), Vector2::new(v1, v2), e.parse().unwrap())
    }

    #[test]
    fn fig_1_3_elastic() {
        let c = case("4", "1", 60.0, 10.0, "elastic");
        assert_eq!(c.total_momentum(), 250.0);
        assert_eq!(c.v_com(), 50.0);
        assert_eq!(c.v_fin(), Vector2::new(40.0, 90.0));
    }

    #[test]
    fn fig_1_3_inelastic_sticks_at_com() {
        let c = case("4", "1", 60.0, 10.0, "inelastic");
        assert_eq!(c.v_fin(), Vector2::new(50.0, 50.0));
    }

    #[test]
    fn fig_2_3_ka_whump() {
        let c = case("6", "1", 3.0, -4.0, "2/3");
        let fin = c.v_fin();
        approx::assert_relative_eq!(fin.x, 4.0 / 3.0, max_relative = 2.0 * f64::EPSILON);
        approx::assert_relative_eq!(fin.y, 6.0, max_relative = 2.0 * f64::EPSILON);
    }

    #[test]
    fn the_second_root_of_the_energy_quadratic_is_elastic_fin() {
        // q(s) = (V_IN + s t).M.(V_IN + s t) equals q(0) at s = s_el: IN and FIN share an ellipse.
        let c = case("4", "1", 60.0, 10.0, "elastic");
        let s = c.elastic_root();
        let fin = c.v_in + s * c.momentum_line_direction();
        assert_eq!(fin, Vector2::new(40.0, 90.0));
        assert_eq!(c.inertia.form(&fin, &fin), c.inertia.form(&c.v_in, &c.v_in));
    }
}
