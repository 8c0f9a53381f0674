//! Contact laws: the force with which two overlapping bodies (or a body and a wall) push apart,
//! as a function of the overlap `d` and its rate `d'` (positive while they press together).
//!
//! - Linear (Kelvin-Voigt spring-dashpot): `F = k d + c d'`.
//! - Hertz (elastic spheres): `F = k d^(3/2)`; with Hunt-Crossley damping
//!   `F = k d^(3/2) (1 + chi d')` (K. H. Hunt, F. R. E. Crossley, "Coefficient of restitution
//!   interpreted as damping in vibroimpact", J. Appl. Mech. 42 (1975) 440).
//!
//! A contact pushes only: it is active while `d > 0` and the force is positive, and it ends when
//! the force reaches zero, possibly with the bodies still overlapping (T. Schwager, T. Poeschel,
//! "Coefficient of restitution and linear-dashpot model revisited", Granular Matter 9 (2007)
//! 465). [`Law::gate`] is positive exactly when the contact is active; its zeros are the events.

/// A contact law with its constants.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Law {
    /// `F = k d + c d'`.
    Linear { k: f64, c: f64 },
    /// `F = k d^(3/2) (1 + chi d')`; `chi = 0` is plain Hertz.
    Hertz { k: f64, chi: f64 },
}

impl Law {
    /// The force (positive: pushing apart) while the contact is active. `d` below 0 counts as 0
    /// for Hertz, so the force is smooth where a step ends slightly past the touching point.
    pub fn force(&self, d: f64, rate: f64) -> f64 {
        match *self {
            Law::Linear { k, c } => k * d + c * rate,
            Law::Hertz { k, chi } => {
                let d = d.max(0.0);
                k * d * d.sqrt() * (1.0 + chi * rate)
            }
        }
    }

    /// `(dF/dd, dF/dd')`, for the Jacobian of implicit methods.
    pub fn slopes(&self, d: f64, rate: f64) -> (f64, f64) {
        match *self {
            Law::Linear { k, c } => (k, c),
            Law::Hertz { k, chi } => {
                let d = d.max(0.0);
                (
                    1.5 * k * d.sqrt() * (1.0 + chi * rate),
                    k * d * d.sqrt() * chi,
                )
            }
        }
    }

    /// Positive exactly when the contact pushes: `min(d, F/k)` in length units for the linear law
    /// (`d + (c/k) d'`), `min(d, d (1 + chi d'))` for Hertz.
    pub fn gate(&self, d: f64, rate: f64) -> f64 {
        match *self {
            Law::Linear { k, c } => d.min(d + c / k * rate),
            Law::Hertz { chi, .. } => d.min(d * (1.0 + chi * rate)),
        }
    }

    /// The elastic energy stored at overlap `d`: `k d^2 / 2` or `2/5 k d^(5/2)`.
    pub fn potential(&self, d: f64) -> f64 {
        let d = d.max(0.0);
        match *self {
            Law::Linear { k, .. } => 0.5 * k * d * d,
            Law::Hertz { k, .. } => 0.4 * k * d * d * d.sqrt(),
        }
    }

    /// The stiffness `k`.
    pub fn k(&self) -> f64 {
        match *self {
            Law::Linear { k, .. } | Law::Hertz { k, .. } => k,
        }
    }

    /// The fastest rate of a contact with reduced mass `mu` hit at speed `v`: its natural
    /// frequency, or its damping rate where that is faster (`c/mu` for the linear law,
    /// `k d^(3/2) chi / mu` at the largest overlap for Hunt-Crossley). Used to pick a method and
    /// to flag explicit steps past their stability limit.
    pub fn frequency(&self, mu: f64, v: f64) -> f64 {
        let natural = self.natural_frequency(mu, v);
        match *self {
            Law::Linear { c, .. } => natural.max(c / mu),
            Law::Hertz { k, chi } => {
                let d = super::closed::hertz_max_overlap(k, mu, v);
                natural.max(k * d * d.sqrt() * chi / mu)
            }
        }
    }

    /// The undamped angular frequency: `sqrt(k/mu)` for the linear law, for Hertz that of the
    /// stiffness `dF/dd` at the largest overlap, `sqrt(3/2 k d^(1/2) / mu)`.
    pub fn natural_frequency(&self, mu: f64, v: f64) -> f64 {
        match *self {
            Law::Linear { k, .. } => (k / mu).sqrt(),
            Law::Hertz { k, .. } => {
                let d = super::closed::hertz_max_overlap(k, mu, v);
                (1.5 * k * d.sqrt() / mu).sqrt()
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every quantity of both laws at hand-picked values where each is exact or nearly: linear
    /// k = 4, c = 2; Hertz k = 2, chi = 1/2 at d = 4 (sqrt d = 2), rate 2 (1 + chi rate = 2).
    #[test]
    fn forces_slopes_gates_and_energies_by_hand() {
        let linear = Law::Linear { k: 4.0, c: 2.0 };
        let hertz = Law::Hertz { k: 2.0, chi: 0.5 };
        // F = k d + c d' = 4 + 6; Hertz k d^(3/2) (1 + chi d') = 2 * 8 * 2.
        assert_eq!(linear.force(1.0, 3.0), 10.0);
        assert_eq!(hertz.force(4.0, 2.0), 32.0);
        assert_eq!(hertz.force(-1.0, 2.0), 0.0);
        // dF/dd = 3/2 k d^(1/2) (1 + chi d') = 12; dF/dd' = k d^(3/2) chi = 8.
        assert_eq!(linear.slopes(1.0, 3.0), (4.0, 2.0));
        assert_eq!(hertz.slopes(4.0, 2.0), (12.0, 8.0));
        // The gate: d + (c/k) d' = 1 - 1.5 while separating fast (the force pulls: negative);
        // d (1 + chi d') = 4 (1 - 2) = -4; approaching, the overlap itself.
        assert_eq!(linear.gate(1.0, -3.0), -0.5);
        assert_eq!(linear.gate(1.0, 3.0), 1.0);
        assert_eq!(hertz.gate(4.0, -4.0), -4.0);
        assert_eq!(hertz.gate(4.0, 2.0), 4.0);
        // k d^2 / 2 = 18; 2/5 k d^(5/2) = 0.4 * 2 * 32 = 25.6 (to an ulp: 0.4 is not binary).
        assert_eq!(linear.potential(3.0), 18.0);
        assert!((hertz.potential(4.0) - 25.6).abs() <= 25.6 * f64::EPSILON);
        assert_eq!(linear.potential(-1.0), 0.0);
        assert_eq!((linear.k(), hertz.k()), (4.0, 2.0));
    }

    /// Frequencies: linear sqrt(k/mu) = 2 (k = 4, mu = 1), or c/mu = 10 when damping is faster.
    /// Hertz with k = 0.625, mu = 1 hit at 4 m/s reaches d = 4 (closed.rs's test): natural
    /// sqrt(3/2 k d^(1/2) / mu) = sqrt(1.875); with chi = 1 the damping rate k d^(3/2) chi / mu
    /// = 5 is faster.
    #[test]
    fn frequencies_by_hand() {
        assert_eq!(
            Law::Linear { k: 4.0, c: 1.0 }.natural_frequency(1.0, 3.0),
            2.0
        );
        assert_eq!(Law::Linear { k: 4.0, c: 1.0 }.frequency(1.0, 3.0), 2.0);
        assert_eq!(Law::Linear { k: 4.0, c: 10.0 }.frequency(1.0, 3.0), 10.0);
        let hertz = Law::Hertz { k: 0.625, chi: 1.0 };
        let natural = hertz.natural_frequency(1.0, 4.0);
        assert!(
            (natural - 1.875f64.sqrt()).abs() <= 2.0 * f64::EPSILON,
            "{natural}"
        );
        let fastest = hertz.frequency(1.0, 4.0);
        assert!((fastest - 5.0).abs() <= 8.0 * f64::EPSILON, "{fastest}");
        // A reduced mass of 2 (every rate above is over mu = 1, where `/ mu` and `* mu`
        // agree): linear k = 8, c = 10: sqrt(8/2) = 2 against 10/2 = 5. Hertz k = 1.25 hit at
        // 4 m/s: 5/4 mu v^2 / k = 32, d = 4 again; natural sqrt(3/2 k d^(1/2) / mu) =
        // sqrt(1.875), damping k d^(3/2) chi / mu = 5.
        let linear = Law::Linear { k: 8.0, c: 10.0 };
        assert_eq!(linear.natural_frequency(2.0, 3.0), 2.0);
        assert_eq!(linear.frequency(2.0, 3.0), 5.0);
        let hertz = Law::Hertz { k: 1.25, chi: 1.0 };
        let natural = hertz.natural_frequency(2.0, 4.0);
        assert!(
            (natural - 1.875f64.sqrt()).abs() <= 2.0 * f64::EPSILON,
            "{natural}"
        );
        let fastest = hertz.frequency(2.0, 4.0);
        assert!((fastest - 5.0).abs() <= 8.0 * f64::EPSILON, "{fastest}");
        let undamped = Law::Hertz { k: 0.625, chi: 0.0 };
        assert_eq!(
            undamped.frequency(1.0, 4.0),
            undamped.natural_frequency(1.0, 4.0)
        );
    }
}
