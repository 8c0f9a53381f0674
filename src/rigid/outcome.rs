//! A solved rigid impact and what follows from it, exactly: the motions after, the impulse's
//! normal and tangential parts, the effective mass, the 1D-equivalent collision along the normal
//! (the lecture's IN, COM, FIN and crunch with each body's effective mass at the contact), the
//! energies split into translation and rotation, linear momentum and angular momentum about a
//! stated point, and each pivot's impulse `m (v' - v) - P` (zero at the centre of percussion).

use num_traits::Signed;

use crate::values::quantity::sqrt;
use crate::values::rational::{Q, half, pow10, sqrt_exact};

use super::algebra::{self, dot, neg, scale, sub};
use super::body::{Body, Motion};
use super::impact::{Impact, Problem};
use super::laws::{Law, Tangential};

/// Digits of an irrational `|n|`.
const DIGITS: usize = 40;

/// One impact, before and after.
#[derive(Clone, Debug, PartialEq)]
pub struct Outcome {
    pub problem: Problem,
    pub impact: Impact,
    pub fin: [Motion; 2],
}

/// The collision of the contact points along the unit normal, as on a rail.
#[derive(Clone, Debug, PartialEq)]
pub struct AlongNormal {
    /// Each body's effective mass at the contact along `n`, `1/(n^T K_i n)` (`None`: infinite,
    /// a wall or a pivot that holds it).
    pub masses: [Option<Q>; 2],
    pub v_in: [Q; 2],
    pub v_com: Q,
    pub fin: [Q; 2],
    /// `1/2 m_eff (v1n - v2n)^2`.
    pub crunch: Q,
    /// Whether `|n|` is rational (else these values are held to 40 digits).
    pub exact: bool,
}

/// What happened to the energy.
#[derive(Clone, Debug, PartialEq)]
pub enum Energy {
    Lost(Q),
    Kept,
    /// Energy created: not physics (Kane's paradox, or a kinematic law's).
    Gained(Q),
}

/// The point angular momentum is taken about, and whether it is kept.
#[derive(Clone, Debug, PartialEq)]
pub struct About {
    pub point: Vec<Q>,
    /// "the contact point", "the pivot".
    pub name: &'static str,
    pub kept: bool,
}

impl Outcome {
    /// The motions after the impulse.
    pub fn new(problem: Problem, impact: Impact) -> Outcome {
        let fin = problem
            .pair
            .apply_impulse(&problem.motions, &impact.impulse);
        Outcome {
            problem,
            impact,
            fin,
        }
    }

    pub fn dim(&self) -> usize {
        self.problem.pair.dim()
    }

    pub fn bodies(&self) -> &[Body; 2] {
        &self.problem.pair.bodies
    }

    pub fn v_in(&self) -> &[Motion; 2] {
        &self.problem.motions
    }

    /// Whether any value is rounded or held to 40 digits.
    pub fn approx(&self) -> bool {
        self.problem.approx || self.impact.approx
    }

    fn normal(&self) -> &[Q] {
        &self.problem.pair.contact.normal
    }

    /// `|n|`, and whether it is exact.
    pub fn normal_length(&self) -> (Q, bool) {
        let nn = dot(self.normal(), self.normal());
        match sqrt_exact(&nn) {
            Some(r) => (r, true),
            None => (sqrt(&nn, DIGITS), false),
        }
    }

    /// The unit normal (40 digits when `|n|` is irrational).
    pub fn unit_normal(&self) -> Vec<Q> {
        let (len, _) = self.normal_length();
        self.normal().iter().map(|x| x / &len).collect()
    }

    /// The normal impulse `P.n/|n|`.
    pub fn normal_impulse(&self) -> Q {
        let (len, _) = self.normal_length();
        dot(&self.impact.impulse, self.normal()) / len
    }

    /// The normal impulse at the end of compression.
    pub fn compression_impulse(&self) -> Q {
        &self.impact.compression * self.normal_length().0
    }

    /// The tangential impulse: in the plane along `t = (-n_y, n_x)/|n|` (signed), in space the
    /// vector `P - (P.n^) n^`.
    pub fn tangential_impulse(&self) -> Vec<Q> {
        let n = self.normal();
        let p = &self.impact.impulse;
        if self.dim() == 2 {
            let (len, _) = self.normal_length();
            return vec![(&p[1] * &n[0] - &p[0] * &n[1]) / len];
        }
        let nn = dot(n, n);
        sub(p, &scale(n, &(dot(p, n) / nn)))
    }

    /// `1/K_nn`, the effective mass along the unit normal.
    pub fn effective_mass(&self) -> Option<Q> {
        self.problem.pair.effective_mass()
    }

    /// The 1D-equivalent collision along the normal.
    pub fn along_normal(&self) -> AlongNormal {
        let pair = &self.problem.pair;
        let n = self.normal();
        let nn = dot(n, n);
        let (len, exact) = self.normal_length();
        let masses = [0, 1].map(|i| {
            let k = dot(n, &algebra::apply(&pair.share(i), n));
            k.is_positive().then(|| &nn / k)
        });
        let along = |i: usize, m: &Motion| dot(n, &pair.point_velocity(i, m)) / &len;
        let v_in = [along(0, &self.v_in()[0]), along(1, &self.v_in()[1])];
        let fin = [along(0, &self.fin[0]), along(1, &self.fin[1])];
        let v_com = match &masses {
            [Some(a), Some(b)] => (a * &v_in[0] + b * &v_in[1]) / (a + b),
            [None, _] => v_in[0].clone(),
            [_, None] => v_in[1].clone(),
        };
        let rel = &v_in[0] - &v_in[1];
        let crunch = half() * self.effective_mass().unwrap_or_default() * &rel * &rel;
        AlongNormal {
            masses,
            v_in,
            v_com,
            fin,
            crunch,
            exact,
        }
    }

    /// Kinetic energy of a state: per body (translation, rotation).
    pub fn energies(&self, motions: &[Motion; 2]) -> [(Q, Q); 2] {
        [0, 1].map(|i| {
            let b = &self.bodies()[i];
            (
                b.translation_energy(&motions[i]),
                b.rotation_energy(&motions[i]),
            )
        })
    }

    /// Total kinetic energy of a state.
    pub fn kinetic(&self, motions: &[Motion; 2]) -> Q {
        self.energies(motions)
            .iter()
            .fold(Q::ZERO, |s, (t, r)| s + t + r)
    }

    pub fn ke_in(&self) -> Q {
        self.kinetic(self.v_in())
    }

    pub fn ke_fin(&self) -> Q {
        self.kinetic(&self.fin)
    }

    /// `KE_IN - KE_FIN` judged: below the accuracy of the values (40 digits, or the ODE's error
    /// estimate) a difference is none.
    pub fn energy(&self) -> Energy {
        let (ki, kf) = (self.ke_in(), self.ke_fin());
        let d = &ki - &kf;
        let scale_of = &ki + &kf;
        let tolerance = if let Some(ode) = &self.impact.ode {
            let rel = 10.0 * ode.error + 1e-13;
            crate::values::rational::from_f64(rel) * &scale_of
        } else if self.impact.approx {
            scale_of / Q::from(pow10(30))
        } else {
            Q::ZERO
        };
        if d.clone().abs() <= tolerance {
            Energy::Kept
        } else if d.is_positive() {
            Energy::Lost(d)
        } else {
            Energy::Gained(-d)
        }
    }

    /// Why energy was created, for the report (`None` when it was not).
    pub fn paradox(&self) -> Option<String> {
        if !matches!(self.energy(), Energy::Gained(_)) {
            return None;
        }
        let p = &self.problem;
        Some(match (&p.tangential, p.law) {
            (Tangential::Rough { .. }, _) => "energy gained: Garwin's kinematic rough contact \
                 (v_n' = -e v_n, v_t' = -beta v_t) creates energy at this off-centre contact; \
                 this FIN is not physical: use friction with the law stronge"
                .into(),
            (_, Law::Newton) => "energy gained: Newton's law with friction at an off-centre \
                 contact creates energy here (Kane's paradox; Stronge 1991); this FIN is not \
                 physical: use --law stronge (energetic), which never creates energy"
                .into(),
            (_, law) => format!(
                "energy gained: the {} law with friction (the slip stopped or reversed) creates \
                 energy here (Stronge 1991); this FIN is not physical: use --law stronge",
                law.name()
            ),
        })
    }

    /// Total linear momentum of a state, and whether it is kept (no pivot and no wall).
    pub fn momentum(&self, motions: &[Motion; 2]) -> Vec<Q> {
        let [a, b] = self.bodies();
        algebra::add(&a.momentum(&motions[0]), &b.momentum(&motions[1]))
    }

    pub fn momentum_kept(&self) -> bool {
        self.bodies()
            .iter()
            .all(|b| b.pivot().is_none() && b.immovable().is_none())
    }

    /// Angular momentum is taken about the one pivot (the pivot's impulse has no moment there),
    /// else about the contact point (where a wall's impulse acts); it is kept unless both a
    /// pivot and a wall, or two pivots, act.
    pub fn about(&self) -> About {
        let pivots: Vec<&[Q]> = self.bodies().iter().filter_map(Body::pivot).collect();
        let walls = self
            .bodies()
            .iter()
            .filter(|b| b.immovable().is_some())
            .count();
        match (pivots.as_slice(), walls) {
            ([p], 0) => About {
                point: p.to_vec(),
                name: "the pivot",
                kept: true,
            },
            ([], _) => About {
                point: self.problem.pair.contact.point.clone(),
                name: "the contact point",
                kept: true,
            },
            _ => About {
                point: self.problem.pair.contact.point.clone(),
                name: "the contact point",
                kept: false,
            },
        }
    }

    /// Angular momentum of a state about `o`.
    pub fn angular(&self, motions: &[Motion; 2], o: &[Q]) -> Vec<Q> {
        let [a, b] = self.bodies();
        algebra::add(
            &a.angular_momentum(&motions[0], o),
            &b.angular_momentum(&motions[1], o),
        )
    }

    /// The impulse each pivot gives its body, `m (v' - v) - P_contact` (`None` for a body
    /// without a pivot).
    pub fn pivot_impulses(&self) -> [Option<Vec<Q>>; 2] {
        let p = &self.impact.impulse;
        [0, 1].map(|i| {
            let b = &self.bodies()[i];
            b.pivot()?;
            let m = b.mass.clone().unwrap_or_default();
            let dp = scale(&sub(&self.fin[i].v, &self.v_in()[i].v), &m);
            let contact = if i == 0 { neg(p) } else { p.clone() };
            Some(sub(&dp, &contact))
        })
    }

    /// The restitution seen along the normal, `-(v1n' - v2n') / (v1n - v2n)`.
    pub fn restitution_along(&self) -> Q {
        let a = self.along_normal();
        let before = &a.v_in[0] - &a.v_in[1];
        if before.is_zero() {
            return Q::ZERO;
        }
        -(&a.fin[0] - &a.fin[1]) / before
    }
}
