//! One rigid impact: the impulse `P` on body 2 (and `-P` on body 1) at the contact, by the law
//! asked for (physics.md section 7).
//!
//! - Smooth (no friction): `P = l n` with `l = (1 + e) (n.w) / (n^T K n)`, which is
//!   `u_FIN = u_IN - (1 + e) (J_n u_IN) / K_nn M^-1 J_n^T` for the unit normal: the lecture's 1D
//!   collision along the normal with the effective mass `1/K_nn`. The three laws agree.
//! - Coulomb friction in the plane: Routh's piecewise-linear method (`routh`), exact.
//! - Coulomb friction in space: the ODE in the normal impulse (`slip`), in binary64 with an error
//!   estimate; a contact that does not slip and whose normal impulse does not push sideways
//!   (`K n` along `n`) takes the smooth impulse, exactly.
//! - Garwin's rough contact (`tangential_restitution` beta): the contact velocity after is
//!   `w' = -e w_n n - beta w_t`, so `P = K^-1 (w - w')`; with a friction limit `mu` that this
//!   impulse would exceed, the tangential impulse `mu P_n` along the same direction and
//!   `v_n' = -e v_n` (Walton's rule).

use num_traits::Signed;

use crate::values::rational::{Q, from_f64, to_f64};

use super::algebra::{self, Mat, apply, dot, scale, sub};
use super::body::Motion;
use super::jacobian::Pair;
use super::laws::{Law, Mode, Tangential};
use super::routh::{self, Corner};
use super::slip::{self, Estimated, Slip};

/// An impact to solve.
#[derive(Clone, Debug, PartialEq)]
pub struct Problem {
    pub pair: Pair,
    pub motions: [Motion; 2],
    pub e: Q,
    pub law: Law,
    pub tangential: Tangential,
    /// Some input was rounded (a turn in rad/s, an angle).
    pub approx: bool,
    /// Tolerance of the ODE in space.
    pub rtol: f64,
    /// The values are in SI (some value was typed with a unit).
    pub si: bool,
}

/// The impulse found.
#[derive(Clone, Debug, PartialEq)]
pub struct Impact {
    /// On body 2, in world axes.
    pub impulse: Vec<Q>,
    pub mode: Mode,
    /// Routh's path in `(l_n, l_t)`, `P = l_n n + l_t t` (in the plane, with friction).
    pub path: Option<Vec<Corner>>,
    /// `l_c`: the normal impulse at the end of compression is `l_c |n|`.
    pub compression: Q,
    /// The ODE's run (in space, with friction).
    pub ode: Option<Estimated>,
    /// A value is held to 40 digits or is binary64.
    pub approx: bool,
    /// Why the law asked for was not the one used (a rough contact beyond its friction limit).
    pub note: Option<String>,
}

/// Why an impact cannot be solved.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum ImpactError {
    #[error(
        "the bodies do not approach at the contact: n.w = {0} <= 0 (w the relative velocity of \
         the contact points), so they do not collide"
    )]
    NotApproaching(String),
    #[error(
        "neither body can move along the contact normal (walls, or pivots whose lever is along \
         it): the impact has no solution"
    )]
    Held,
    #[error(transparent)]
    Routh(#[from] routh::RouthError),
    #[error(transparent)]
    Slip(#[from] slip::SlipError),
    #[error(
        "Garwin's rough contact sets both the normal and the tangential velocity after, which \
         this contact cannot reach (its collision matrix is singular: a pivoted body against a \
         wall?): use friction instead"
    )]
    RoughSingular,
}

impl Problem {
    /// The law's name as reports print it: `join` for bodies that join (`--join` sets `e = 0`
    /// and no slip, so no restitution law is used), else the restitution law's.
    pub fn law_name(&self) -> &'static str {
        match self.tangential {
            Tangential::Join => "join",
            _ => self.law.name(),
        }
    }

    /// The relative velocity at the contact before.
    pub fn w(&self) -> Vec<Q> {
        self.pair.relative_velocity(&self.motions)
    }

    /// Solves the impact.
    pub fn solve(&self) -> Result<Impact, ImpactError> {
        let n = &self.pair.contact.normal;
        let w = self.w();
        let along = dot(n, &w);
        if matches!(self.tangential, Tangential::Join) {
            return self.join(&w, &along);
        }
        if !along.is_positive() {
            return Err(not_approaching(&along));
        }
        let k = self.pair.collision_matrix();
        let knn = dot(n, &apply(&k, n));
        if !knn.is_positive() {
            return Err(ImpactError::Held);
        }
        let lc = &along / &knn;
        match &self.tangential {
            Tangential::Smooth => Ok(self.solve_smooth(lc)),
            Tangential::Coulomb(mu) if mu.is_zero() => Ok(self.solve_smooth(lc)),
            Tangential::Coulomb(mu) => self.coulomb(&k, &w, mu, lc),
            Tangential::Rough { beta, mu } => self.rough(&k, &w, beta, mu.as_ref(), lc),
            Tangential::Join => self.join(&w, &along),
        }
    }

    /// Coulomb friction: Routh in the plane, the ODE in space.
    fn coulomb(&self, k: &Mat, w: &[Q], mu: &Q, lc: Q) -> Result<Impact, ImpactError> {
        let n = &self.pair.contact.normal;
        let nn = dot(n, n);
        if self.pair.dim() == 2 {
            let t = self.pair.tangent();
            let kt = [
                [dot(n, &apply(k, n)), dot(n, &apply(k, &t))],
                [dot(&t, &apply(k, n)), dot(&t, &apply(k, &t))],
            ];
            let r = routh::solve(&kt, &[dot(n, w), dot(&t, w)], mu, self.law, &self.e)?;
            let impulse = algebra::add(&scale(n, &r.impulse[0]), &scale(&t, &r.impulse[1]));
            return Ok(Impact {
                impulse,
                mode: r.mode,
                compression: r
                    .path
                    .iter()
                    .find(|c| c.event == routh::Event::Compression)
                    .map_or(lc, |c| c.at[0].clone()),
                path: Some(r.path),
                ode: None,
                approx: self.approx || r.approx,
                note: None,
            });
        }
        // In space: no slip and a normal impulse that does not push sideways keep the impulse
        // normal (friction has nothing to do), exactly.
        let slip_now = sub(w, &scale(n, &(dot(n, w) / &nn)));
        let kn = apply(k, n);
        let sideways = sub(&kn, &scale(n, &(dot(n, &kn) / &nn)));
        if algebra::is_zero(&slip_now) && algebra::is_zero(&sideways) {
            let mut i = self.solve_smooth(lc);
            i.mode = Mode::Stick;
            return Ok(i);
        }
        let f = |q: &Q| to_f64(q).unwrap_or(f64::NAN);
        let nf: Vec<f64> = n.iter().map(f).collect();
        let len = nf.iter().fold(0.0f64, |s, x| s.hypot(*x));
        let nh = [nf[0] / len, nf[1] / len, nf[2] / len];
        let wf: Vec<f64> = w.iter().map(f).collect();
        let slip_f: Vec<f64> = slip_now.iter().map(f).collect();
        let t1 = unit_perpendicular(&nh, &slip_f);
        let t2 = cross(&nh, &t1);
        let frame = [nh, t1, t2];
        let kf: Vec<Vec<f64>> = k.iter().map(|r| r.iter().map(f).collect()).collect();
        let mut kc = [[0.0; 3]; 3];
        for (a, fa) in frame.iter().enumerate() {
            for (b, fb) in frame.iter().enumerate() {
                kc[a][b] = (0..3)
                    .map(|i| fa[i] * (0..3).map(|j| kf[i][j] * fb[j]).sum::<f64>())
                    .sum();
            }
        }
        let w0 = frame.map(|d| d.iter().zip(&wf).map(|(a, b)| a * b).sum::<f64>());
        let problem = Slip {
            k: kc,
            w0,
            mu: f(mu),
            e: f(&self.e),
            law: self.law,
        };
        let est = problem.estimated(self.rtol)?;
        let p = est.run.impulse;
        let world: Vec<Q> = (0..3)
            .map(|i| from_f64(p[0] * nh[i] + p[1] * t1[i] + p[2] * t2[i]))
            .collect();
        Ok(Impact {
            impulse: world,
            mode: est.run.mode,
            path: None,
            compression: from_f64(est.run.compression / len),
            ode: Some(est),
            approx: true,
            note: None,
        })
    }

    /// The bodies join (physics.md section 8): the contact points move together after,
    /// `w' = w - K P = 0`, so `P = K^-1 w`, exactly. A grazing contact (`n.w = 0`: a bullet
    /// along a tangent into a rim) joins too; bodies that separate (`n.w < 0`) or do not move
    /// relative to each other (`w = 0`) do not meet. The normal impulse is all compression.
    fn join(&self, w: &[Q], along: &Q) -> Result<Impact, ImpactError> {
        if along.is_negative() || algebra::is_zero(w) {
            return Err(not_approaching(along));
        }
        let k = self.pair.collision_matrix();
        let kinv = algebra::inverse(&k).ok_or(ImpactError::Held)?;
        let impulse = apply(&kinv, w);
        let n = &self.pair.contact.normal;
        Ok(Impact {
            compression: dot(&impulse, n) / dot(n, n),
            impulse,
            mode: Mode::Joined,
            path: None,
            ode: None,
            approx: self.approx,
            note: None,
        })
    }

    fn solve_smooth(&self, lc: Q) -> Impact {
        Impact {
            impulse: scale(&self.pair.contact.normal, &((Q::ONE + &self.e) * &lc)),
            mode: Mode::Smooth,
            path: None,
            compression: lc,
            ode: None,
            approx: self.approx,
            note: None,
        }
    }

    /// Garwin's rough contact: `w' = -beta w + (beta - e) (n.w) n / n.n`, `P = K^-1 (w - w')`;
    /// beyond the friction limit, Walton's rule ([`Problem::walton`]).
    fn rough(
        &self,
        k: &Mat,
        w: &[Q],
        beta: &Q,
        mu: Option<&Q>,
        lc: Q,
    ) -> Result<Impact, ImpactError> {
        let n = &self.pair.contact.normal;
        let nn = dot(n, n);
        let wn = dot(n, w) / &nn;
        let after: Vec<Q> = w
            .iter()
            .zip(n)
            .map(|(wi, ni)| -(beta * wi) + (beta - &self.e) * &wn * ni)
            .collect();
        let kinv = algebra::inverse(k).ok_or(ImpactError::RoughSingular)?;
        let mut impulse = apply(&kinv, &sub(w, &after));
        let (mut approx, mut note) = (self.approx, None);
        if let Some(mu) = mu {
            // |P_t|^2 <= mu^2 P_n^2, with P_n = P.n/|n|: P.P - (P.n)^2/n.n <= mu^2 (P.n)^2/n.n.
            let pn = dot(&impulse, n);
            let pt2 = dot(&impulse, &impulse) - &pn * &pn / &nn;
            if pt2 > mu * mu * &pn * &pn / &nn {
                let q = sub(&impulse, &scale(n, &(pn / &nn)));
                match self.walton(k, w, mu, &q, &mut approx) {
                    Some(p) => impulse = p,
                    None => return self.coulomb(k, w, mu, lc),
                }
                note = Some("beyond the limit, Walton's rule: |P_t| = mu P_n".into());
            }
        }
        let after = sub(w, &apply(k, &impulse));
        let slip = sub(w, &scale(n, &wn));
        let slip_after = sub(&after, &scale(n, &(dot(n, &after) / &nn)));
        let mode = if algebra::is_zero(&slip_after) {
            Mode::Stick
        } else if dot(&slip, &slip_after).is_negative() {
            Mode::Reverse
        } else {
            Mode::Slip
        };
        Ok(Impact {
            impulse,
            mode,
            path: None,
            compression: lc,
            ode: None,
            approx,
            note,
        })
    }

    /// Walton's rule (O. R. Walton, in *Particulate Two-Phase Flow*, 1993): a rough contact
    /// whose impulse would exceed the friction limit keeps `v_n' = -e v_n` and takes the
    /// tangential impulse `mu P_n` along the one it would have taken, `q` (across `n`):
    /// `P = a (n + rho q)` with `rho = mu sqrt(n.n / q.q)`, and `n.(w - K P) = -e n.w` gives
    /// `a = (1 + e) n.w / (n.K n + rho n.K q)`. `None` when that denominator is not positive
    /// (the normal impulse could not push the bodies apart).
    fn walton(&self, k: &Mat, w: &[Q], mu: &Q, q: &[Q], approx: &mut bool) -> Option<Vec<Q>> {
        let n = &self.pair.contact.normal;
        let rho = mu * routh::root(&(dot(n, n) / dot(q, q)), approx);
        let d = dot(n, &apply(k, n)) + &rho * dot(n, &apply(k, q));
        if !d.is_positive() {
            return None;
        }
        let a = (Q::ONE + &self.e) * dot(n, w) / d;
        Some(scale(&algebra::add(n, &scale(q, &rho)), &a))
    }
}

/// The bodies do not approach: `n.w <= 0`.
fn not_approaching(along: &Q) -> ImpactError {
    ImpactError::NotApproaching(
        to_f64(along).map_or_else(|| along.to_string(), crate::values::number::num),
    )
}

/// A unit vector perpendicular to `n`: along `slip` when it has a part across `n`, else any.
fn unit_perpendicular(n: &[f64; 3], slip: &[f64]) -> [f64; 3] {
    let across = |v: [f64; 3]| -> [f64; 3] {
        let d = v[0] * n[0] + v[1] * n[1] + v[2] * n[2];
        [v[0] - d * n[0], v[1] - d * n[1], v[2] - d * n[2]]
    };
    let norm = |v: [f64; 3]| v[0].hypot(v[1]).hypot(v[2]);
    let s = across([slip[0], slip[1], slip[2]]);
    let pick = if norm(s) > 0.0 {
        s
    } else {
        // The world axis most across n.
        let axis = (0..3)
            .min_by(|&a, &b| n[a].abs().total_cmp(&n[b].abs()))
            .unwrap_or(0);
        let mut e = [0.0; 3];
        e[axis] = 1.0;
        across(e)
    };
    let l = norm(pick);
    [pick[0] / l, pick[1] / l, pick[2] / l]
}

fn cross(a: &[f64; 3], b: &[f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}
