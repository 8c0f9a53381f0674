//! The inertia tensor `M` of the lecture (Sec. 2): momentum `P = M.V`, kinetic energy
//! `1/2 V.M.V`, total mass `u.M.u` with `u = (1, 1)`. Checked once, when it is made: finite,
//! symmetric and positive definite. Every number derived from it here is computed so that
//! no product can overflow or underflow while the result itself is representable.

use nalgebra::{Cholesky, Matrix2, SymmetricEigen, Vector2};

use crate::values::compensated::{
    Dd, diff_of_products, dot2, exponent, pow2, sum2, two_prod, two_sum,
};
use crate::values::number::{Number, NumberError};

/// A body's mass: a finite number > 0.
#[derive(Clone, Debug, PartialEq)]
pub struct Mass(Number);

/// Why a value is not a mass.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum MassError {
    #[error("mass '{0}' must be greater than 0")]
    NotPositive(String),
    #[error("mass {0}")]
    Number(NumberError),
}

// Not `#[from]`: that would make the number error the source too, and the error chain would
// print it twice.
impl From<NumberError> for MassError {
    fn from(e: NumberError) -> MassError {
        MassError::Number(e)
    }
}

impl Mass {
    pub fn new(n: Number) -> Result<Mass, MassError> {
        if n.value() > 0.0 {
            Ok(Mass(n))
        } else {
            Err(MassError::NotPositive(n.to_string()))
        }
    }
    /// The mass of a binary64 value (its exact value, as if typed in full).
    pub fn from_f64(x: f64) -> Result<Mass, MassError> {
        Mass::new(Number::from_f64(x)?)
    }
    pub fn value(&self) -> f64 {
        self.0.value()
    }
    pub fn number(&self) -> &Number {
        &self.0
    }
}

impl std::str::FromStr for Mass {
    type Err = MassError;
    fn from_str(s: &str) -> Result<Mass, MassError> {
        Mass::new(s.parse()?)
    }
}

impl<'de> serde::Deserialize<'de> for Mass {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Mass, D::Error> {
        Mass::new(Number::deserialize(d)?).map_err(serde::de::Error::custom)
    }
}

/// Why a matrix is not an inertia tensor.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum InertiaError {
    #[error("inertia tensor is not symmetric: M12 = {0} but M21 = {1} (expected M12 = M21)")]
    NotSymmetric(String, String),
    #[error(
        "inertia tensor is not positive definite (expected M11 > 0, M22 > 0 and M11 M22 > M12^2): {0}"
    )]
    NotPositiveDefinite(String),
    #[error("total mass u.M.u = {0} is too large for binary64; use smaller units")]
    TooLarge(String),
}

/// A symmetric positive definite 2x2 inertia tensor, as typed and as a nalgebra matrix, with the
/// quantities every solve needs computed once, when it is validated.
#[derive(Clone, Debug, PartialEq)]
pub struct InertiaTensor {
    entries: [[Number; 2]; 2],
    m: Matrix2<f64>,
    derived: Derived,
}

/// Tensor-only quantities, computed once.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
struct Derived {
    total: f64,
    weights: (Dd, Dd),
    reduced_mass: Dd,
}

impl InertiaTensor {
    /// `M = diag(M1, M2)`: two bodies on a rail (lecture Fig. 1.3).
    pub fn diagonal(m1: &Mass, m2: &Mass) -> Result<InertiaTensor, InertiaError> {
        let zero = Number::from_f64(0.0).expect("0 is a number");
        InertiaTensor::general([
            [m1.number().clone(), zero.clone()],
            [zero, m2.number().clone()],
        ])
    }

    /// A general symmetric tensor (lecture Sec. 2: `M12 = M21`).
    pub fn general(entries: [[Number; 2]; 2]) -> Result<InertiaTensor, InertiaError> {
        let m = Matrix2::new(
            entries[0][0].value(),
            entries[0][1].value(),
            entries[1][0].value(),
            entries[1][1].value(),
        );
        if !entries[0][1].same_value(&entries[1][0]) {
            return Err(InertiaError::NotSymmetric(
                entries[0][1].to_string(),
                entries[1][0].to_string(),
            ));
        }
        let mut t = InertiaTensor {
            entries,
            m,
            derived: Derived::default(),
        };
        let text = || t.describe();
        if Cholesky::new(m).is_none() || t.scaled_det().0 <= 0.0 {
            return Err(InertiaError::NotPositiveDefinite(text()));
        }
        let total = t.compute_total();
        if !total.is_finite() {
            return Err(InertiaError::TooLarge(text()));
        }
        t.derived = Derived {
            total,
            weights: t.compute_weights_dd(),
            reduced_mass: t.compute_reduced_mass(),
        };
        Ok(t)
    }

    /// The same tensor with its entries as binary64 values only, so a clone allocates nothing
    /// (tables solve millions of rows with one tensor).
    pub fn untyped(&self) -> InertiaTensor {
        InertiaTensor {
            entries: self.entries.clone().map(|row| row.map(|n| n.untyped())),
            ..self.clone()
        }
    }

    /// The tensor as typed.
    pub fn entries(&self) -> &[[Number; 2]; 2] {
        &self.entries
    }

    pub fn matrix(&self) -> &Matrix2<f64> {
        &self.m
    }

    pub fn is_diagonal(&self) -> bool {
        self.m[(0, 1)] == 0.0
    }

    /// `diag(4, 1)` or `[[4, 0.5], [0.5, 1]]`, as typed.
    pub fn describe(&self) -> String {
        self.describe_with(Number::brief)
    }

    /// `describe` with each entry shown by `show` (`--exact`: a solved mass as its fraction).
    pub fn describe_with(&self, show: impl Fn(&Number) -> String) -> String {
        let e = &self.entries;
        if self.is_diagonal() {
            format!("diag({}, {})", show(&e[0][0]), show(&e[1][1]))
        } else {
            format!(
                "[[{}, {}], [{}, {}]]",
                show(&e[0][0]),
                show(&e[0][1]),
                show(&e[1][0]),
                show(&e[1][1])
            )
        }
    }

    /// `M_total = u.M.u = M11 + 2 M12 + M22`, summed with one rounding.
    pub fn total(&self) -> f64 {
        self.derived.total
    }

    /// `M_total` as a double-double (exact but for extreme magnitude spreads).
    pub fn total_dd(&self) -> Dd {
        let (a, b, c) = self.abc();
        Dd::sum(a, 2.0 * c) + Dd::new(b)
    }

    fn compute_total(&self) -> f64 {
        let (a, b, c) = self.abc();
        sum2(&[a, 2.0 * c, b])
    }

    /// Center-of-momentum weights `(w1, w2) = ((M11 + M12), (M12 + M22)) / M_total`, so that
    /// `V_COM = w1 V1 + w2 V2` and `w1 + w2 = 1` (mass-weighted average, lecture Sec. 1).
    pub fn weights(&self) -> (f64, f64) {
        let (a, b, c) = self.abc();
        let total = self.total();
        ((a + c) / total, (c + b) / total)
    }

    /// The weights as double-doubles, from the exact sums `M11 + M12`, `M12 + M22` and
    /// `M_total`.
    pub fn weights_dd(&self) -> (Dd, Dd) {
        self.derived.weights
    }

    fn compute_weights_dd(&self) -> (Dd, Dd) {
        let (a, b, c) = self.abc();
        let total = Dd::sum(a, 2.0 * c) + Dd::new(b);
        (Dd::sum(a, c) / total, Dd::sum(c, b) / total)
    }

    /// `P_total = u.M.V = (M11 + M12) V1 + (M12 + M22) V2`, as if in twice the precision.
    pub fn total_momentum(&self, v: &Vector2<f64>) -> f64 {
        let (a, b, c) = self.abc();
        dot2(&[a, c, c, b], &[v.x, v.x, v.y, v.y])
    }

    /// Generalised reduced mass `mu = det M / M_total` (`M1 M2 / (M1 + M2)` for a diagonal
    /// tensor): crunch energy is `1/2 mu (V1 - V2)^2` (lecture Sec. 2). Both are computed on the
    /// tensor scaled by the power of two nearest the geometric mean of `M11` and `M22`, so
    /// `M11 M22` cannot overflow or underflow, and the scale is put back last.
    pub fn reduced_mass(&self) -> f64 {
        self.derived.reduced_mass.value()
    }

    /// `mu` as a double-double.
    pub fn reduced_mass_dd(&self) -> Dd {
        self.derived.reduced_mass
    }

    fn compute_reduced_mass(&self) -> Dd {
        let (a, b, c) = self.abc();
        let k = self.scale_exponent();
        let s = pow2(-k);
        let (a, b, c) = (a * s, b * s, c * s);
        let det = Dd::prod(a, b) - Dd::prod(c, c);
        let total = Dd::sum(a, 2.0 * c) + Dd::new(b);
        det / total * Dd::new(pow2(k))
    }

    /// The power of two nearest the geometric mean of `M11` and `M22`: dividing by it keeps
    /// `M11 M22` near 1, far from overflow and underflow.
    fn scale_exponent(&self) -> i32 {
        let (a, b, _) = self.abc();
        ((exponent(a) + exponent(b)) / 2).clamp(-1022, 1022)
    }

    /// `det(M / 2^k)` with the `k` used (Kahan's 2x2 determinant, 1.5 ulp).
    fn scaled_det(&self) -> (f64, i32) {
        let (a, b, c) = self.abc();
        let k = self.scale_exponent();
        let s = pow2(-k);
        (diff_of_products(a * s, b * s, c * s, c * s), k)
    }

    /// `P = M.V`.
    pub fn momentum(&self, v: &Vector2<f64>) -> Vector2<f64> {
        let [(p1, l1), (p2, l2)] = self.momentum_dd(v);
        Vector2::new(p1 + l1, p2 + l2)
    }

    /// `x.M.y`, evaluated as `x.(M.y)` (momentum first: `(m v) v`) in twice the precision.
    pub fn form(&self, x: &Vector2<f64>, y: &Vector2<f64>) -> f64 {
        let [(p1, l1), (p2, l2)] = self.momentum_dd(y);
        dot2(&[x.x, x.x, x.y, x.y], &[p1, l1, p2, l2])
    }

    /// `M.y` as unevaluated sums `hi + lo` (double-double).
    fn momentum_dd(&self, y: &Vector2<f64>) -> [(f64, f64); 2] {
        let (a, b, c) = self.abc();
        let row = |d: f64, o: f64, yd: f64, yo: f64| {
            let (p, ep) = two_prod(d, yd);
            let (q, eq) = two_prod(o, yo);
            let (s, es) = two_sum(p, q);
            (s, es + ep + eq)
        };
        [row(a, c, y.x, y.y), row(b, c, y.y, y.x)]
    }

    /// Principal axes: eigenvalues in ascending order with their unit eigenvectors (nalgebra's
    /// symmetric eigen decomposition). The smaller eigenvalue is recomputed as `det / lambda_max`,
    /// which keeps its relative accuracy when `M` is nearly singular.
    pub fn principal_axes(&self) -> [(f64, Vector2<f64>); 2] {
        let (k_det, k) = self.scaled_det();
        let s = pow2(-k);
        let eig = SymmetricEigen::new(self.m * s);
        let (i_min, i_max) = if eig.eigenvalues[0] <= eig.eigenvalues[1] {
            (0, 1)
        } else {
            (1, 0)
        };
        let l_max = eig.eigenvalues[i_max];
        let l_min = k_det / l_max;
        let axis = |i: usize| {
            let q: Vector2<f64> = eig.eigenvectors.column(i).into();
            // A fixed sign convention: first non-zero component positive.
            if q.x < 0.0 || (q.x == 0.0 && q.y < 0.0) {
                -q
            } else {
                q
            }
        };
        [
            (l_min * pow2(k), axis(i_min)),
            (l_max * pow2(k), axis(i_max)),
        ]
    }

    fn abc(&self) -> (f64, f64, f64) {
        (self.m[(0, 0)], self.m[(1, 1)], self.m[(0, 1)])
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn n(s: &str) -> Number {
        s.parse().unwrap()
    }
    fn mass(s: &str) -> Mass {
        s.parse().unwrap()
    }
    fn tensor(a: &str, c: &str, b: &str) -> Result<InertiaTensor, InertiaError> {
        InertiaTensor::general([[n(a), n(c)], [n(c), n(b)]])
    }

    #[test]
    fn fig_1_3_suv_and_vw() {
        let m = InertiaTensor::diagonal(&mass("4"), &mass("1")).unwrap();
        assert!(m.is_diagonal());
        assert_eq!(m.describe(), "diag(4, 1)");
        assert_eq!(m.total(), 5.0);
        assert_eq!(m.weights(), (0.8, 0.2));
        assert_eq!(m.reduced_mass(), 0.8);
        let v = Vector2::new(60.0, 10.0);
        assert_eq!(m.total_momentum(&v), 250.0);
        assert_eq!(m.momentum(&v), Vector2::new(240.0, 10.0));
        assert_eq!(m.form(&v, &v), 14500.0);
    }

    #[test]
    fn masses_must_be_positive() {
        for bad in ["0", "-1", "-0"] {
            let e = bad.parse::<Mass>().unwrap_err().to_string();
            assert!(e.contains(bad) && e.contains("greater than 0"), "{e}");
        }
        assert!(
            "abc"
                .parse::<Mass>()
                .unwrap_err()
                .to_string()
                .contains("'abc' is not a number")
        );
    }

    #[test]
    fn general_tensor_checks() {
        let m = tensor("4", "0.5", "1").unwrap();
        assert!(!m.is_diagonal());
        assert_eq!(m.total(), 6.0);
        // mu = det / total = (4 - 0.25) / 6
        assert_eq!(m.reduced_mass(), 3.75 / 6.0);
        let e = InertiaTensor::general([[n("4"), n("0.5")], [n("0.4"), n("1")]]).unwrap_err();
        assert_eq!(e, InertiaError::NotSymmetric("0.5".into(), "0.4".into()));
        assert!(matches!(
            tensor("1", "2", "1"),
            Err(InertiaError::NotPositiveDefinite(_))
        ));
        assert!(matches!(
            tensor("1", "1", "1"),
            Err(InertiaError::NotPositiveDefinite(_))
        ));
        assert!(matches!(
            tensor("-1", "0", "1"),
            Err(InertiaError::NotPositiveDefinite(_))
        ));
        assert!(matches!(
            tensor("1e308", "0", "1e308"),
            Err(InertiaError::TooLarge(_))
        ));
    }

    #[test]
    fn reduced_mass_of_extreme_ratios_does_not_underflow() {
        // mu = m1 m2 / (m1 + m2) ~ 1e-290 when m1 = 1e-290, m2 = 1e290: m1 m2 = 1 and
        // m1 / (m1 + m2) = 1e-580 would both go wrong in the naive orders.
        let m = InertiaTensor::diagonal(&mass("1e-290"), &mass("1e290")).unwrap();
        approx::assert_relative_eq!(m.reduced_mass(), 1e-290, max_relative = 4.0 * f64::EPSILON);
        let m = InertiaTensor::diagonal(&mass("1e290"), &mass("1e290")).unwrap();
        approx::assert_relative_eq!(m.reduced_mass(), 0.5e290, max_relative = 4.0 * f64::EPSILON);
    }

    #[test]
    fn principal_axes_of_a_general_tensor() {
        // [[2, 1], [1, 2]]: eigenvalues 1 along (1, -1)/sqrt2 and 3 along (1, 1)/sqrt2.
        let m = tensor("2", "1", "2").unwrap();
        let [(l1, q1), (l2, q2)] = m.principal_axes();
        approx::assert_relative_eq!(l1, 1.0, max_relative = 4.0 * f64::EPSILON);
        approx::assert_relative_eq!(l2, 3.0, max_relative = 4.0 * f64::EPSILON);
        let h = std::f64::consts::FRAC_1_SQRT_2;
        approx::assert_relative_eq!(q1, Vector2::new(h, -h), max_relative = 4.0 * f64::EPSILON);
        approx::assert_relative_eq!(q2, Vector2::new(h, h), max_relative = 4.0 * f64::EPSILON);
    }
}
