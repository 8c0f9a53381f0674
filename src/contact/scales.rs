//! Time, length and speed scales of a contact setup: the default steps and tolerances, the
//! choice of `auto`, and the contacts too short to integrate.

use super::closed;
use super::error::ContactError;
use super::law::Law;
use super::system::Slot;
use super::{AUTO_TOL, AUTO_TOL_HERTZ, Adaptive, Method, STIFF_RATIO, Settings, Setup};

/// The shortest contact time integrated (measured: contacts of 1e-75 run as well as any; at
/// 1e-150 the solvers stall on steps).
pub(super) const SHORTEST: f64 = 1e-100;

/// Why the shortest contact is too short: heavy damping (a linear law whose damping rate `c/mu`
/// is above its natural frequency), with the least restitution that would do; else the scales.
pub(super) fn too_short(slots: &[Slot], scales: &Scales) -> ContactError {
    let shortest = (0..slots.len())
        .max_by(|&a, &b| scales.omega[a].total_cmp(&scales.omega[b]))
        .map(|i| &slots[i]);
    if let Some(Slot {
        law: Law::Linear { k, c },
        mu,
        ..
    }) = shortest
        && c / mu > (k / mu).sqrt()
    {
        let contact = closed::Linear::new(*k, *c, *mu);
        // The fastest rate of a heavily damped contact is c/mu = 2 zeta omega0; its time
        // scale pi / (c/mu) is SHORTEST at this zeta. Below zeta = 1 the undamped contact
        // itself is too short: then the scales are the trouble.
        let zeta_max = std::f64::consts::PI / (SHORTEST * 2.0 * contact.omega0);
        if zeta_max <= 1.0 {
            return ContactError::TooShort(scales.t_min);
        }
        return ContactError::TooDamped {
            t: scales.t_min,
            zeta: contact.zeta,
            e: contact.restitution(),
            e_min: closed::Linear::restitution_of(zeta_max),
            zeta_max,
        };
    }
    ContactError::TooShort(scales.t_min)
}

/// Time, length and speed scales of a setup, for tolerances, default steps and `auto`.
#[derive(Clone, Debug, PartialEq)]
pub struct Scales {
    /// Largest initial relative speed.
    pub speed: f64,
    /// Per slot: the fastest rate at that speed, the natural frequency or the damping rate
    /// (`Law::frequency`).
    pub omega: Vec<f64>,
    /// Per slot: the natural (undamped) frequency at that speed, the time scale of the contact.
    pub natural: Vec<f64>,
    /// Smallest deepest overlap over the slots at that speed.
    pub overlap: f64,
    /// Shortest and longest contact time.
    pub t_min: f64,
    pub t_max: f64,
    /// [`AUTO_TOL`], or [`AUTO_TOL_HERTZ`] where any law is Hertzian.
    pub default_tol: f64,
}

impl Scales {
    pub fn of(setup: &Setup, slots: &[Slot]) -> Scales {
        let speed = setup.speed_scale();
        let v = if speed > 0.0 { speed } else { 1.0 };
        let omega: Vec<f64> = slots.iter().map(|s| s.law.frequency(s.mu, v)).collect();
        let natural: Vec<f64> = slots
            .iter()
            .map(|s| s.law.natural_frequency(s.mu, v))
            .collect();
        let overlap = slots
            .iter()
            .map(|s| match s.law {
                Law::Linear { k, .. } => v / (k / s.mu).sqrt(),
                Law::Hertz { k, .. } => closed::hertz_max_overlap(k, s.mu, v),
            })
            .fold(f64::INFINITY, f64::min);
        let times: Vec<f64> = omega.iter().map(|w| std::f64::consts::PI / w).collect();
        Scales {
            speed,
            t_min: times.iter().copied().fold(f64::INFINITY, f64::min),
            t_max: times.iter().copied().fold(0.0, f64::max),
            omega,
            natural,
            overlap,
            default_tol: if slots.iter().any(|s| matches!(s.law, Law::Hertz { .. })) {
                AUTO_TOL_HERTZ
            } else {
                AUTO_TOL
            },
        }
    }

    /// The fastest rate (a contact's frequency or damping rate) over the slowest natural
    /// frequency: a soft contact beside a stiff one, or one contact damped so heavily that its
    /// damping rate `c/mu` outruns its own time scale (`2 zeta` times its natural frequency),
    /// is stiff.
    pub fn stiffness_ratio(&self) -> f64 {
        let hi = self.omega.iter().copied().fold(0.0, f64::max);
        let lo = self.natural.iter().copied().fold(f64::INFINITY, f64::min);
        if lo > 0.0 && lo.is_finite() {
            hi / lo
        } else {
            1.0
        }
    }

    /// `auto`: bdf where two time scales differ by more than [`STIFF_RATIO`] (two contacts, or
    /// one damped with `zeta` above 50), else tsit45.
    pub fn auto(&self) -> Method {
        if self.stiffness_ratio() > STIFF_RATIO {
            Method::Adaptive(Adaptive::Bdf)
        } else {
            Method::Adaptive(Adaptive::Tsit45)
        }
    }

    /// The stiffest slot, named, and its frequency.
    pub(super) fn fastest(&self, setup: &Setup) -> Option<(String, f64)> {
        let contacts = setup.contacts();
        let (i, w) = self
            .omega
            .iter()
            .enumerate()
            .max_by(|a, b| a.1.total_cmp(b.1))?;
        Some((contacts[i].describe(setup.bodies.len()), *w))
    }
}

/// The step (fixed) or tolerance (adaptive) to use.
pub(super) fn steps_for(
    method: Method,
    settings: &Settings,
    scales: &Scales,
) -> Result<(Option<f64>, Option<f64>), ContactError> {
    match method {
        Method::Fixed(_) => {
            if settings.tol.is_some() {
                return Err(ContactError::WrongStep(method.name()));
            }
            // Explicit methods need steps under their stability limit on the stiffest contact;
            // implicit ones only need to resolve the slowest.
            let dt = settings.dt.unwrap_or(if method.implicit() {
                scales.t_max / 1000.0
            } else {
                scales.t_min / 64.0
            });
            if !(dt > 0.0 && dt.is_finite()) {
                return Err(ContactError::Dt(dt));
            }
            // A step that cannot get through the shortest contact within the step budget is
            // refused before the run (a run would spend the whole budget and end in error).
            let t = scales.t_min.min(settings.until.unwrap_or(f64::INFINITY));
            if t / dt > settings.max_steps as f64 {
                return Err(ContactError::DtTooSmall {
                    dt,
                    t,
                    max_steps: settings.max_steps,
                });
            }
            Ok((Some(dt), None))
        }
        Method::Adaptive(_) => {
            if settings.dt.is_some() {
                return Err(ContactError::WrongStep(method.name()));
            }
            let tol = settings.tol.unwrap_or(scales.default_tol);
            if !(1e-14..=0.1).contains(&tol) {
                return Err(ContactError::Tol(tol));
            }
            Ok((None, Some(tol)))
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scales(omega: Vec<f64>, natural: Vec<f64>) -> Scales {
        Scales {
            speed: 1.0,
            omega,
            natural,
            overlap: 1.0,
            t_min: 1.0,
            t_max: 1.0,
            default_tol: 1e-10,
        }
    }

    /// Fastest rate over slowest natural frequency; 1 (not stiff) where there is no natural
    /// frequency to compare with: none at all, or one that underflowed to 0 (k / mu below
    /// 2^-1074), which would make every run "infinitely stiff".
    #[test]
    fn the_stiffness_ratio_by_hand() {
        assert_eq!(
            scales(vec![2.0, 100.0], vec![2.0, 4.0]).stiffness_ratio(),
            50.0
        );
        assert_eq!(scales(vec![3.0], vec![3.0]).stiffness_ratio(), 1.0);
        assert_eq!(scales(vec![1.0], vec![0.0]).stiffness_ratio(), 1.0);
        assert_eq!(scales(Vec::new(), Vec::new()).stiffness_ratio(), 1.0);
    }
}
