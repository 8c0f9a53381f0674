//! The ODE of the slip in the normal impulse (see the parent module), integrated with diffsol's
//! Tsitouras 5(4): the command line's only (feature `cli`).

use std::time::Instant;

use diffsol::{NalgebraMat, OdeBuilder, OdeSolverMethod, Vector};

use super::{Estimated, Law, Mode, Run, Slip, SlipError};

type M = NalgebraMat<f64>;

/// Most steps of one run.
const MAX_STEPS: u64 = 200_000;

/// State: `w_n, w_t1, w_t2, W, P_t1, P_t2`.
type Y = [f64; 6];

/// What drives a phase.
#[derive(Clone, Copy, Debug)]
enum Phase {
    /// Slipping, the direction from `w_t`.
    Turning,
    /// Constant rates (`dY/dP_n` but for `W`, whose rate is `w_n`).
    Fixed(Y),
}

fn norm2(a: f64, b: f64) -> f64 {
    a.hypot(b)
}

impl Slip {
    /// `dY/dP_n` for an impulse direction `(1, f1, f2)` per unit normal impulse.
    fn rates(&self, f: [f64; 3], wn: f64) -> Y {
        let k = &self.k;
        let dw = |r: usize| -(k[r][0] + k[r][1] * f[1] + k[r][2] * f[2]);
        [dw(0), dw(1), dw(2), wn, f[1], f[2]]
    }

    fn rhs(&self, phase: Phase, y: &[f64]) -> Y {
        match phase {
            Phase::Fixed(mut r) => {
                r[3] = y[0];
                r
            }
            Phase::Turning => {
                let s = norm2(y[1], y[2]);
                let (s1, s2) = if s > 0.0 {
                    (y[1] / s, y[2] / s)
                } else {
                    (0.0, 0.0)
                };
                self.rates([1.0, self.mu * s1, self.mu * s2], y[0])
            }
        }
    }

    /// The phase after the slip has stopped: stick, or slip again in the invariant direction;
    /// and whether it slips.
    fn after_stop(&self) -> Result<(Phase, bool), SlipError> {
        let k = &self.k;
        let (a, b, c) = (k[1][1], k[1][2], k[2][2]);
        let det = a * c - b * b;
        if det <= 1e-14 * (a * c).abs().max(f64::MIN_POSITIVE) {
            return Err(SlipError::Singular);
        }
        let (tn1, tn2) = (k[1][0], k[2][0]);
        // Stick: K_tt r = -K_tn.
        let r = [-(c * tn1 - b * tn2) / det, -(a * tn2 - b * tn1) / det];
        if norm2(r[0], r[1]) <= self.mu {
            return Ok((Phase::Fixed(self.rates([1.0, r[0], r[1]], 0.0)), false));
        }
        // Slip again along s = -(lambda 1 + mu K_tt)^-1 K_tn with |s| = 1: |s| falls with
        // lambda from above 1 at lambda = 0 (stick impossible); bisection.
        let s_of = |lambda: f64| -> [f64; 2] {
            let (p, q, t) = (lambda + self.mu * a, self.mu * b, lambda + self.mu * c);
            let d = p * t - q * q;
            [-(t * tn1 - q * tn2) / d, -(p * tn2 - q * tn1) / d]
        };
        let mut hi = 1.0f64.max(norm2(tn1, tn2));
        while norm2(s_of(hi)[0], s_of(hi)[1]) > 1.0 {
            hi *= 2.0;
        }
        let mut lo = 0.0;
        for _ in 0..200 {
            let mid = 0.5 * (lo + hi);
            if mid <= lo || mid >= hi {
                break;
            }
            let s = s_of(mid);
            if norm2(s[0], s[1]) > 1.0 {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        let s = s_of(hi);
        let n = norm2(s[0], s[1]);
        let f = [1.0, self.mu * s[0] / n, self.mu * s[1] / n];
        Ok((Phase::Fixed(self.rates(f, 0.0)), true))
    }

    /// One run at relative tolerance `rtol`.
    pub fn run(&self, rtol: f64) -> Result<Run, SlipError> {
        let speed = norm2(self.w0[0], norm2(self.w0[1], self.w0[2]));
        let p_scale = self.w0[0] / self.k[0][0].max(f64::MIN_POSITIVE);
        // Near stick the slip direction flips within a step and the steps chatter about
        // |w_t| ~ 10 atol: the slip is closed linearly from 100 atol, a second-order error in
        // the turning direction (none when it does not turn).
        let delta = 100.0 * rtol * speed;
        let mut y: Y = [self.w0[0], self.w0[1], self.w0[2], 0.0, 0.0, 0.0];
        let mut x = 0.0;
        let mut compression: Option<(f64, f64)> = None;
        let mut stick = None;
        let mut resumed = false;
        let slipping_at_start = norm2(y[1], y[2]) > delta;
        let mut phase = if slipping_at_start {
            Phase::Turning
        } else {
            y[1] = 0.0;
            y[2] = 0.0;
            let (p, slips) = self.after_stop()?;
            resumed = slips;
            p
        };
        let mut steps = 0u64;
        let mut rhs_evals = 0u64;
        loop {
            let out = self.integrate(
                phase,
                (x, y),
                compression,
                Tol {
                    rtol,
                    speed,
                    p_scale,
                    delta,
                },
                &mut steps,
                &mut rhs_evals,
            )?;
            x = out.x;
            y = out.y;
            match out.event {
                Ev::Compression => {
                    y[0] = 0.0;
                    compression = Some((x, y[3]));
                }
                Ev::Stick => {
                    // Close the last delta of slip linearly, then stick or slip again.
                    let r = self.rhs(Phase::Turning, &y);
                    let s = norm2(y[1], y[2]);
                    let rate = (y[1] * r[1] + y[2] * r[2]) / s.max(f64::MIN_POSITIVE);
                    if rate < 0.0 {
                        let d = s / -rate;
                        // Compression within the closing (the slip stops where the bodies stop
                        // approaching, to within delta): at its linear point, `W` there with
                        // it; else the next phase would start past `w_n = 0` and never see it.
                        if compression.is_none() && y[0] + r[0] * d <= 0.0 {
                            let dc = (y[0] / -r[0]).clamp(0.0, d);
                            compression = Some((x + dc, y[3] + y[0] * dc + 0.5 * r[0] * dc * dc));
                        }
                        for (yi, ri) in y.iter_mut().zip(r) {
                            *yi += ri * d;
                        }
                        y[3] += 0.5 * r[0] * d * d;
                        x += d;
                    }
                    y[1] = 0.0;
                    y[2] = 0.0;
                    stick = Some(x);
                    let (p, slips) = self.after_stop()?;
                    resumed = slips;
                    phase = p;
                }
                Ev::End => {
                    let mode = match (stick, resumed) {
                        (Some(_), true) => Mode::Reverse,
                        (Some(_), false) => Mode::Stick,
                        (None, _) if slipping_at_start || resumed => Mode::Slip,
                        (None, _) => Mode::Stick,
                    };
                    return Ok(Run {
                        impulse: [x, y[4], y[5]],
                        mode,
                        compression: compression.map_or(x, |c| c.0),
                        stick,
                        steps,
                        rhs_evals,
                    });
                }
            }
        }
    }

    /// Two runs, at `rtol` and `rtol / 100`: the finer one's answer, the difference as the error
    /// estimate, the time both took.
    pub fn estimated(&self, rtol: f64) -> Result<Estimated, SlipError> {
        let start = Instant::now();
        let coarse = self.run(rtol)?;
        let fine = self.run(rtol / 100.0)?;
        let seconds = start.elapsed().as_secs_f64();
        let size = norm2(fine.impulse[0], norm2(fine.impulse[1], fine.impulse[2]));
        let diff = (0..3)
            .map(|k| coarse.impulse[k] - fine.impulse[k])
            .fold(0.0f64, |s, d| s.hypot(d));
        Ok(Estimated {
            run: fine,
            rtol: rtol / 100.0,
            error: if size > 0.0 { diff / size } else { diff },
            seconds,
            steps: coarse.steps + fine.steps,
        })
    }

    /// The event functions: compression (until it has happened), stick (in a slipping phase),
    /// the law's end (after compression). Each is positive before its event.
    fn events(
        &self,
        (x, y): (f64, &[f64]),
        compression: Option<(f64, f64)>,
        turning: Option<[f64; 2]>,
        delta: f64,
    ) -> [Option<f64>; 3] {
        let compress = compression.is_none().then_some(y[0]);
        let stick = turning.map(|s| y[1] * s[0] + y[2] * s[1] - delta);
        let end = compression.map(|(xc, wc)| match self.law {
            Law::Poisson => (1.0 + self.e) * xc - x,
            Law::Newton => y[0] + self.e * self.w0[0],
            Law::Stronge => y[3] - (1.0 - self.e * self.e) * wc,
        });
        [compress, stick, end]
    }

    /// Integrates one phase until its first event.
    fn integrate(
        &self,
        phase: Phase,
        (x0, y0): (f64, Y),
        compression: Option<(f64, f64)>,
        tol: Tol,
        steps: &mut u64,
        rhs_evals: &mut u64,
    ) -> Result<Out, SlipError> {
        // An event already due at the start (a law that ends at compression, e = 0).
        let turning_dir = |y: &[f64]| -> Option<[f64; 2]> {
            matches!(phase, Phase::Turning).then(|| {
                let s = norm2(y[1], y[2]);
                [y[1] / s, y[2] / s]
            })
        };
        let first = self.events((x0, &y0), compression, turning_dir(&y0), tol.delta);
        // (Compression due at the start too: a phase begun at `w_n <= 0` never sees `w_n`
        // fall through 0, and its end, which follows compression, would never come.)
        for (k, event) in [(2, Ev::End), (0, Ev::Compression)] {
            if let Some(g) = first[k]
                && g <= 0.0
            {
                return Ok(Out {
                    x: x0,
                    y: y0,
                    event,
                });
            }
        }
        let evals = std::cell::Cell::new(0u64);
        let atol: Vec<f64> = [
            tol.speed,
            tol.speed,
            tol.speed,
            tol.speed * tol.p_scale,
            tol.p_scale,
            tol.p_scale,
        ]
        .iter()
        .map(|s| tol.rtol * s)
        .collect();
        let problem = OdeBuilder::<M>::new()
            .t0(x0)
            .h0(1e-3 * tol.p_scale)
            .rtol(tol.rtol)
            .atol(atol)
            .rhs(|y, _p, _t, f| {
                evals.set(evals.get() + 1);
                f.copy_from_slice(&self.rhs(phase, y));
            })
            .init(|_p, _t, y| y.copy_from_slice(&y0), 6)
            .build()
            .map_err(|e| SlipError::Solver(e.to_string()))?;
        let fail = |e: diffsol::error::DiffsolError| SlipError::Solver(e.to_string());
        let mut solver = problem.tsit45().map_err(fail)?;
        let (mut xa, mut ya) = (x0, y0.to_vec());
        let out = loop {
            if *steps >= MAX_STEPS {
                return Err(SlipError::Steps(MAX_STEPS));
            }
            *steps += 1;
            solver.step().map_err(fail)?;
            let state = solver.state();
            let (xb, yb) = (state.t, state.y.clone_as_vec());
            if !xb.is_finite() || yb.iter().any(|v| !v.is_finite()) {
                return Err(SlipError::Solver("the state became infinite".into()));
            }
            // The first event in (xa, xb], located on the dense output. The stick function
            // measures the slip along its direction at the step's start, so a step that carries
            // the slip through zero is caught as well as one that ends below delta.
            let dir = turning_dir(&ya);
            let ga = self.events((xa, &ya), compression, dir, tol.delta);
            let gb = self.events((xb, &yb), compression, dir, tol.delta);
            let mut best: Option<(f64, usize)> = None;
            for k in 0..3 {
                if let (Some(a), Some(b)) = (ga[k], gb[k])
                    && a > 0.0
                    && b <= 0.0
                {
                    let mut f = |x: f64| -> Result<f64, SlipError> {
                        let y = solver.interpolate(x).map_err(fail)?.clone_as_vec();
                        Ok(self.events((x, &y), compression, dir, tol.delta)[k].unwrap_or(0.0))
                    };
                    let at = locate(&mut f, (xa, a), (xb, b))?;
                    if best.is_none_or(|(t, _)| at < t) {
                        best = Some((at, k));
                    }
                }
            }
            if let Some((x, k)) = best {
                let mut y = [0.0; 6];
                y.copy_from_slice(&solver.interpolate(x).map_err(fail)?.clone_as_vec());
                let event = [Ev::Compression, Ev::Stick, Ev::End][k];
                break Out { x, y, event };
            }
            xa = xb;
            ya = yb;
        };
        *rhs_evals += evals.get();
        Ok(out)
    }
}

/// Tolerances and scales of a run.
#[derive(Clone, Copy, Debug)]
struct Tol {
    rtol: f64,
    speed: f64,
    p_scale: f64,
    delta: f64,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Ev {
    Compression,
    Stick,
    End,
}

struct Out {
    x: f64,
    y: Y,
    event: Ev,
}

/// Where `f` falls through 0 between `a` (value `fa > 0`) and `b` (`fb <= 0`): bisection of the
/// dense output down to adjacent binary64 times, ending on the far side (at most ~60 halvings, a
/// few microseconds; the steps, not the events, are the cost).
fn locate(
    f: &mut dyn FnMut(f64) -> Result<f64, SlipError>,
    (mut a, _): (f64, f64),
    (mut b, _): (f64, f64),
) -> Result<f64, SlipError> {
    loop {
        let mid = a + 0.5 * (b - a);
        if mid <= a || mid >= b {
            return Ok(b);
        }
        if f(mid)? <= 0.0 {
            b = mid;
        } else {
            a = mid;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A sphere (m = 1, R = 1, I = 2/5) on a floor in the contact frame: K_nn = 1, K_tt = 7/2.
    fn floor(w0: [f64; 3], mu: f64) -> Slip {
        Slip {
            k: [[1.0, 0.0, 0.0], [0.0, 3.5, 0.0], [0.0, 0.0, 3.5]],
            w0,
            mu,
            e: 0.5,
            law: Law::Poisson,
        }
    }

    #[test]
    fn a_sliding_ball_sticks_where_routh_says() {
        // Sliding at (0.6, 0.8) (speed 1): it sticks when 7/2 mu P_n = 1, P_n = 2/7 with mu = 1,
        // P_t = 2/7 along the slip; compression ends at 1, Poisson at 3/2 (as in the plane).
        // The slip does not turn (K_tt is isotropic), so the rates are constant and Tsitouras'
        // steps are exact but for rounding: what is left is the rounding of the steps and of the
        // bisected events. Measured (2026-11-27) at rtol 1e-10: P_n off by 8.0e-15 (36 ulps of
        // 1.5), P_t1 by 0 and P_t2 by 5.6e-17 (2 ulps of 0.23), the estimate 3.5e-15; at rtol
        // 1e-6 to 1e-12 at most 2.0e-14, 1.4e-16 and 1.1e-14. The bounds below are about twice
        // the worst of those, far below the tolerance: steps not exact for constant rates fail.
        let r = floor([1.0, 0.6, 0.8], 1.0).estimated(1e-10).unwrap();
        assert_eq!(r.run.mode, Mode::Stick);
        let p = r.run.impulse;
        assert!((p[0] - 1.5).abs() < 4e-14, "{p:?}");
        assert!((p[1] - 0.6 * 2.0 / 7.0).abs() < 3e-16, "{p:?}");
        assert!((p[2] - 0.8 * 2.0 / 7.0).abs() < 3e-16, "{p:?}");
        assert!(r.error < 2e-14, "{}", r.error);
    }

    #[test]
    fn too_little_friction_slips_throughout() {
        // P_t = mu P_n = 0.15 along the slip, exact rates again: measured (2026-11-27) P_n off by
        // 2.2e-14 (98 ulps of 1.5: the rounding of the steps and the bisected end) and |P_t| by
        // 1.7e-16 (6 ulps of 0.15); bounds about twice that.
        let r = floor([1.0, 0.6, 0.8], 0.1).run(1e-10).unwrap();
        assert_eq!(r.mode, Mode::Slip);
        assert!((r.impulse[0] - 1.5).abs() < 5e-14, "{:?}", r.impulse);
        let pt = r.impulse[1].hypot(r.impulse[2]);
        assert!((pt - 0.15).abs() < 4e-16, "{pt}");
    }
}
