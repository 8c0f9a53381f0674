//! Error against run time (`collide accuracy`): several ways to solve the same collision, each
//! measured against exact rational arithmetic on seeded families of cases, from the lecture's to
//! the extreme ones (mass ratios of 1e290, overflow-prone products, huge boosts, grazing).

use std::hint::black_box;
use std::time::Instant;

use crate::values::rational::Q;
use nalgebra::{Matrix2, Vector2};
use num_traits::Signed;
use serde::Serialize;

use crate::line::collision::Collision;
use crate::line::inertia::InertiaTensor;
use crate::line::restitution::Restitution;
use crate::solver::Solver;
use crate::solver::binary64::Binary64;
use crate::solver::exact::ExactCollision;
use crate::values::compensated::exponent;
use crate::values::number::Number;
use crate::values::quantity::{from_f64, to_f64};

/// A way to compute FIN, the crunch energy and the energy lost.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, clap::ValueEnum)]
#[serde(rename_all = "kebab-case")]
pub enum Method {
    /// The default solver: impulse form from the relative velocity, crunch from the reduced mass
    Impulse,
    /// ((m1 - e m2) u1 + (1 + e) m2 u2) / (m1 + m2), and KE_IN - KE_COM by subtraction
    Textbook,
    /// The momentum line meets the energy ellipse, roots by the quadratic formula
    Quadratic,
    /// nalgebra matrix expressions throughout (P = u.M.V, KE = V.M.V / 2, differences)
    Tensor,
    /// exact rational arithmetic (`rational::Q`), rounded to binary64 at the end
    Exact,
}

impl Method {
    pub const ALL: [Method; 5] = [
        Method::Impulse,
        Method::Textbook,
        Method::Quadratic,
        Method::Tensor,
        Method::Exact,
    ];

    pub fn name(self) -> &'static str {
        match self {
            Method::Impulse => "impulse",
            Method::Textbook => "textbook",
            Method::Quadratic => "quadratic",
            Method::Tensor => "tensor",
            Method::Exact => "exact",
        }
    }
}

/// What every method computes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Outcome {
    pub fin: [f64; 2],
    pub crunch: f64,
    pub lost: f64,
}

/// Solves `c` by `method`.
pub fn solve(method: Method, c: &Collision) -> Outcome {
    match method {
        Method::Impulse => {
            let s = Binary64::lab(c);
            Outcome {
                fin: s.v_fin(),
                crunch: s.crunch(),
                lost: s.lost(),
            }
        }
        Method::Textbook => textbook(c),
        Method::Quadratic => quadratic(c),
        Method::Tensor => tensor(c),
        Method::Exact => {
            let x = ExactCollision::from_binary64(c);
            let [f1, f2] = x.v_fin_q();
            let f = |q: &Q| to_f64(q).unwrap_or(f64::INFINITY);
            Outcome {
                fin: [f(&f1), f(&f2)],
                crunch: f(&x.crunch_q()),
                lost: f(&x.lost_q()),
            }
        }
    }
}

fn abc(c: &Collision) -> (f64, f64, f64) {
    let m = c.inertia.matrix();
    (m[(0, 0)], m[(1, 1)], m[(0, 1)])
}

/// The textbook formulas, in the order they are usually written.
fn textbook(c: &Collision) -> Outcome {
    let (a, b, cc) = abc(c);
    let (k1, k2) = (a + cc, cc + b);
    let (u1, u2) = (c.v_in.x, c.v_in.y);
    let e = c.restitution.value();
    let mt = a + 2.0 * cc + b;
    let fin1 = ((k1 - e * k2) * u1 + (1.0 + e) * k2 * u2) / mt;
    let fin2 = ((k2 - e * k1) * u2 + (1.0 + e) * k1 * u1) / mt;
    let ke = |x: f64, y: f64| 0.5 * a * x * x + cc * x * y + 0.5 * b * y * y;
    let vcom = (k1 * u1 + k2 * u2) / mt;
    let ke_in = ke(u1, u2);
    let ke_com = 0.5 * mt * vcom * vcom;
    let ke_fin = ke(fin1, fin2);
    Outcome {
        fin: [fin1, fin2],
        crunch: ke_in - ke_com,
        lost: ke_in - ke_fin,
    }
}

/// The construction taken literally: along `V_IN + s t`, `t = (k2, -k1)`, solve
/// `A s^2 + B s + (C - 2 KE_IN) = 0` by the quadratic formula; COM at the vertex `s = -B / 2A`.
fn quadratic(c: &Collision) -> Outcome {
    let (a, b, cc) = abc(c);
    let (k1, k2) = (a + cc, cc + b);
    let v = c.v_in;
    let e = c.restitution.value();
    let t = Vector2::new(k2, -k1);
    let m = c.inertia.matrix();
    let form = |x: &Vector2<f64>, y: &Vector2<f64>| x.dot(&(m * y));
    let qa = form(&t, &t);
    let qb = 2.0 * form(&t, &v);
    let qc = form(&v, &v) - 2.0 * (0.5 * form(&v, &v));
    let disc = (qb * qb - 4.0 * qa * qc).max(0.0).sqrt();
    let (r1, r2) = ((-qb + disc) / (2.0 * qa), (-qb - disc) / (2.0 * qa));
    let s_el = if r1.abs() >= r2.abs() { r1 } else { r2 };
    let fin = v + (1.0 + e) / 2.0 * s_el * t;
    let com = v + (-qb / (2.0 * qa)) * t;
    let ke_in = 0.5 * form(&v, &v);
    let ke_com = 0.5 * form(&com, &com);
    let crunch = ke_in - ke_com;
    Outcome {
        fin: [fin.x, fin.y],
        crunch,
        lost: (1.0 - e * e) * crunch,
    }
}

/// Matrix expressions: `P = u.M.V`, `M_total = u.M.u`, `KE = V.M.V / 2`, energies subtracted.
fn tensor(c: &Collision) -> Outcome {
    let m: &Matrix2<f64> = c.inertia.matrix();
    let u = Vector2::new(1.0, 1.0);
    let v = c.v_in;
    let e = c.restitution.value();
    let p = u.dot(&(m * v));
    let mt = u.dot(&(m * u));
    let vcom = p / mt;
    let fin = (1.0 + e) * vcom * u - e * v;
    let ke = |x: &Vector2<f64>| 0.5 * x.dot(&(m * x));
    let ke_in = ke(&v);
    let ke_com = ke(&(vcom * u));
    Outcome {
        fin: [fin.x, fin.y],
        crunch: ke_in - ke_com,
        lost: ke_in - ke(&fin),
    }
}

/// The exact values a method is measured against, with their scales.
#[derive(Clone, Debug)]
pub struct Reference {
    pub fin: [Q; 2],
    pub crunch: Q,
    pub lost: Q,
    /// `max(|V1|, |V2|, |FIN1|, |FIN2|)`: the natural scale of velocity errors.
    pub velocity_scale: f64,
}

impl Reference {
    pub fn of(c: &Collision) -> Reference {
        let x = ExactCollision::from_binary64(c);
        let fin = x.v_fin_q();
        let mut scale = c.v_in.x.abs().max(c.v_in.y.abs());
        for f in &fin {
            scale = scale.max(to_f64(&f.abs()).unwrap_or(f64::MAX));
        }
        Reference {
            crunch: x.crunch_q(),
            lost: x.lost_q(),
            fin,
            velocity_scale: scale,
        }
    }
}

/// Error in units of the last place of `scale`: `|approx - exact| / ulp(scale)`; `inf` for a
/// non-finite approximation, or a non-zero one where the exact value (and so the scale) is 0.
pub fn ulps(approx: f64, exact: &Q, scale: f64) -> f64 {
    if !approx.is_finite() {
        return f64::INFINITY;
    }
    let err = (from_f64(approx) - exact).abs();
    if err.is_zero() {
        return 0.0;
    }
    if scale == 0.0 {
        return f64::INFINITY;
    }
    to_f64(&(err / from_f64(ulp(scale)))).unwrap_or(f64::INFINITY)
}

/// The unit in the last place of a finite `x`: `2^max(e - 52, -1074)` with `2^e <= |x| <
/// 2^(e+1)` (IEEE 754's spacing of binary64 at `x`; `2^-1074` for subnormals and 0, the
/// smallest spacing there is). Below `2^-970` it is a subnormal, not `2^-1022`.
pub fn ulp(x: f64) -> f64 {
    let k = (exponent(x) - 52).max(-1074);
    if k >= -1022 {
        crate::values::compensated::pow2(k)
    } else {
        f64::from_bits(1u64 << (k + 1074))
    }
}

/// Errors of one outcome, in ulps of each quantity's natural scale (velocities: `velocity_scale`;
/// crunch and lost: themselves).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Errors {
    pub fin: f64,
    pub crunch: f64,
    pub lost: f64,
}

pub fn errors(o: &Outcome, r: &Reference) -> Errors {
    let self_scale = |q: &Q| to_f64(&q.abs()).unwrap_or(f64::MAX);
    Errors {
        fin: ulps(o.fin[0], &r.fin[0], r.velocity_scale).max(ulps(
            o.fin[1],
            &r.fin[1],
            r.velocity_scale,
        )),
        crunch: ulps(o.crunch, &r.crunch, self_scale(&r.crunch)),
        lost: ulps(o.lost, &r.lost, self_scale(&r.lost)),
    }
}

/// A named, seeded family of cases.
#[derive(Clone, Debug)]
pub struct Family {
    pub name: &'static str,
    pub about: &'static str,
    pub cases: Vec<Collision>,
}

/// SplitMix64: a small, fixed, portable generator, so a seed means the same cases everywhere.
#[derive(Clone, Debug)]
pub struct Rng(u64);

impl Rng {
    pub fn new(seed: u64) -> Rng {
        Rng(seed)
    }
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    /// Uniform in [0, 1).
    pub fn unit(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 * (1.0 / (1u64 << 53) as f64)
    }
    pub fn uniform(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.unit()
    }
    /// `10^x` with `x` uniform in [lo, hi).
    pub fn log_uniform(&mut self, lo: f64, hi: f64) -> f64 {
        10f64.powf(self.uniform(lo, hi))
    }
    pub fn sign(&mut self) -> f64 {
        if self.next_u64() & 1 == 0 { 1.0 } else { -1.0 }
    }
    /// `e` cycling through 0, 1 and a random value in between.
    pub fn restitution(&mut self, i: usize) -> f64 {
        match i % 3 {
            0 => 1.0,
            1 => 0.0,
            _ => self.unit(),
        }
    }
}

/// A binary64 case (inputs taken exactly as the given binary64 values).
pub fn case(m: [[f64; 2]; 2], v: [f64; 2], e: f64) -> Option<Collision> {
    let n = |x: f64| Number::from_f64(x).ok();
    let inertia =
        InertiaTensor::general([[n(m[0][0])?, n(m[0][1])?], [n(m[1][0])?, n(m[1][1])?]]).ok()?;
    let e = Restitution::new(n(e)?).ok()?;
    Some(Collision::new(inertia, Vector2::new(v[0], v[1]), e))
}

fn diag(m1: f64, m2: f64, v: [f64; 2], e: f64) -> Option<Collision> {
    case([[m1, 0.0], [0.0, m2]], v, e)
}

/// A diagonal case with masses `10^[-decades, decades)` each, velocities `v`, and the `i`-th
/// restitution of the cycle.
fn random_masses(r: &mut Rng, decades: f64, v: [f64; 2], i: usize) -> Option<Collision> {
    let m1 = r.log_uniform(-decades, decades);
    let m2 = r.log_uniform(-decades, decades);
    diag(m1, m2, v, r.restitution(i))
}

/// The families of `collide accuracy` and of the accuracy tests: `n` cases each (the lecture
/// family has its five).
pub fn families(seed: u64, n: usize) -> Vec<Family> {
    let mut rng = Rng::new(seed);
    let mut make = |name, about, f: &mut dyn FnMut(&mut Rng, usize) -> Option<Collision>| {
        let cases = (0..n * 4).filter_map(|i| f(&mut rng, i)).take(n).collect();
        Family { name, about, cases }
    };
    let lecture = Family {
        name: "lecture",
        about: "cases A and B of lecture Figs. 1.3 and 2.3",
        cases: [
            diag(4.0, 1.0, [60.0, 10.0], 1.0),
            diag(4.0, 1.0, [60.0, 10.0], 0.0),
            diag(6.0, 1.0, [3.0, -4.0], 1.0),
            diag(6.0, 1.0, [3.0, -4.0], 2.0 / 3.0),
            diag(6.0, 1.0, [3.0, -4.0], 0.0),
        ]
        .into_iter()
        .flatten()
        .collect(),
    };
    let moderate = make(
        "moderate",
        "masses 1e-3..1e3, velocities -100..100",
        &mut |r, i| {
            let v = [r.uniform(-100.0, 100.0), r.uniform(-100.0, 100.0)];
            random_masses(r, 3.0, v, i)
        },
    );
    let ratio = make(
        "mass-ratio",
        "m2/m1 = 1e-290..1e290, both orders",
        &mut |r, i| {
            let k = r.uniform(0.0, 290.0) * r.sign();
            let m1 = r.log_uniform(-1.0, 1.0);
            let v = [r.uniform(-100.0, 100.0), r.uniform(-100.0, 100.0)];
            if i % 2 == 0 {
                diag(m1, m1 * 10f64.powf(k), v, r.restitution(i / 2))
            } else {
                diag(m1 * 10f64.powf(k), m1, v, r.restitution(i / 2))
            }
        },
    );
    let overflow = make(
        "overflow-prone",
        "M=(1e300,1e10); M=(1e-200,2e-200), V~1e245; M~1e200, V~1e-200",
        &mut |r, i| {
            let jitter = |r: &mut Rng| r.uniform(1.0, 2.0);
            match i % 3 {
                0 => diag(
                    1e300 * jitter(r),
                    1e10 * jitter(r),
                    [r.uniform(-9.0, 9.0), r.uniform(-9.0, 9.0)],
                    r.restitution(i / 3),
                ),
                1 => diag(
                    1e-200 * jitter(r),
                    2e-200 * jitter(r),
                    [1e245 * r.uniform(-1.0, 1.0), 1e245 * r.uniform(-1.0, 1.0)],
                    r.restitution(i / 3),
                ),
                _ => diag(
                    1e200 * jitter(r),
                    1e200 * jitter(r),
                    [1e-200 * r.uniform(-1.0, 1.0), 1e-200 * r.uniform(-1.0, 1.0)],
                    r.restitution(i / 3),
                ),
            }
        },
    );
    let boost = make(
        "boost",
        "common velocity 1e6..1e15, relative velocity ~1",
        &mut |r, i| {
            let w = r.log_uniform(6.0, 15.0) * r.sign();
            let v = [w + r.uniform(-1.0, 1.0), w + r.uniform(-1.0, 1.0)];
            random_masses(r, 2.0, v, i)
        },
    );
    let grazing = make(
        "grazing",
        "relative velocity 1e-15..1e-8 of V; equal; receding",
        &mut |r, i| {
            let x = r.uniform(-100.0, 100.0);
            let v = match i % 6 {
                0 => [x, x],
                1 => [-x.abs(), x.abs()],
                _ => [x, x * (1.0 + r.log_uniform(-15.0, -8.0) * r.sign())],
            };
            random_masses(r, 2.0, v, i)
        },
    );
    let general = make(
        "general-tensor",
        "symmetric M with M12 = rho sqrt(M11 M22), |rho| < 0.99",
        &mut |r, i| {
            let (a, b) = (r.log_uniform(-3.0, 3.0), r.log_uniform(-3.0, 3.0));
            let c = r.uniform(-0.99, 0.99) * (a * b).sqrt();
            let v = [r.uniform(-100.0, 100.0), r.uniform(-100.0, 100.0)];
            case([[a, c], [c, b]], v, r.restitution(i))
        },
    );
    vec![lecture, moderate, ratio, overflow, boost, grazing, general]
}

/// Median and worst of a set of errors (`inf` counts as worst).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Spread {
    pub median: f64,
    pub worst: f64,
}

fn spread(mut xs: Vec<f64>) -> Spread {
    xs.sort_by(f64::total_cmp);
    let median = xs.get(xs.len() / 2).copied().unwrap_or(0.0);
    Spread {
        median,
        worst: xs.last().copied().unwrap_or(0.0),
    }
}

/// One row of the work-precision report.
#[derive(Clone, Debug, Serialize)]
pub struct Row {
    pub method: Method,
    pub family: &'static str,
    pub cases: usize,
    /// Errors in ulps of each quantity's natural scale.
    pub fin_ulps: Spread,
    pub crunch_ulps: Spread,
    pub lost_ulps: Spread,
    /// The same, as relative errors (ulps times 2^-52 at most).
    pub fin_rel: Spread,
    pub crunch_rel: Spread,
    pub lost_rel: Spread,
    /// Median time of one solve, and the fastest and slowest of the timed passes, in ns.
    pub ns_median: f64,
    pub ns_min: f64,
    pub ns_max: f64,
    /// The lower and upper quartiles of the timed passes, in ns: the spread a report shows (one
    /// pass slowed by the machine moves the slowest, not these).
    pub ns_q1: f64,
    pub ns_q3: f64,
}

/// A method's time per solve over the timed passes, in ns.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Timing {
    pub median: f64,
    pub min: f64,
    pub max: f64,
    pub q1: f64,
    pub q3: f64,
}

/// Relative error from ulps of the scale: at most `ulps * 2^-52`.
fn rel(s: Spread) -> Spread {
    Spread {
        median: s.median * f64::EPSILON,
        worst: s.worst * f64::EPSILON,
    }
}

/// Times `method` over `cases`: passes over the whole family for about `budget_ms` (at least one
/// pass, so a family slower than the budget takes one pass).
pub fn time(method: Method, cases: &[Collision], budget_ms: u64) -> Timing {
    let mut per_pass = Vec::new();
    let start = Instant::now();
    while per_pass.is_empty() || (start.elapsed().as_millis() as u64) < budget_ms {
        let t = Instant::now();
        for c in cases {
            black_box(solve(method, black_box(c)));
        }
        per_pass.push(t.elapsed().as_nanos() as f64 / cases.len().max(1) as f64);
        if per_pass.len() >= 10_000 {
            break;
        }
    }
    per_pass.sort_by(f64::total_cmp);
    // Quartiles by rank, as the median: passes that were measured, q1 <= median <= q3.
    let n = per_pass.len();
    Timing {
        median: per_pass[n / 2],
        min: per_pass[0],
        max: per_pass[n - 1],
        q1: per_pass[n / 4],
        q3: per_pass[(3 * n / 4).min(n - 1)],
    }
}

/// Cases per family timed by [`Cost::measure`].
const SAMPLE: usize = 8;

/// What a report costs besides its timing passes, measured before it runs.
#[derive(Clone, Copy, Debug)]
pub struct Cost {
    /// Seconds a case costs: its exact reference, and each method's solve, errors and share of
    /// a timing pass.
    pub per_case: f64,
    /// Families of a report (the lecture family among them).
    pub families: usize,
}

impl Cost {
    /// Measured on a sample of [`SAMPLE`] cases a family, drawn from `seed` like the report's
    /// (the same distributions), so that a report too large for its budget is refused before
    /// its cases are even drawn.
    pub fn measure(seed: u64, methods: &[Method]) -> Cost {
        let sample = families(seed, SAMPLE);
        let cases: usize = sample.iter().map(|f| f.cases.len()).sum();
        let start = Instant::now();
        for f in &sample {
            for c in &f.cases {
                let r = Reference::of(c);
                for &m in methods {
                    black_box(errors(&solve(m, c), &r));
                    black_box(solve(m, black_box(c)));
                }
            }
        }
        Cost {
            per_case: start.elapsed().as_secs_f64() / cases.max(1) as f64,
            families: sample.len(),
        }
    }

    /// Cases of a report with `n` a family (the lecture family has its five).
    pub fn cases(&self, n: u64) -> u64 {
        5 + (self.families as u64 - 1) * n
    }

    /// Seconds a report with `n` cases a family spends besides its timing passes.
    pub fn seconds(&self, n: u64) -> f64 {
        self.per_case * self.cases(n) as f64
    }
}

/// The whole report: every method on every family.
pub fn report(families: &[Family], methods: &[Method], budget_ms: u64) -> Vec<Row> {
    let mut rows = Vec::new();
    for f in families {
        let refs: Vec<Reference> = f.cases.iter().map(Reference::of).collect();
        for &m in methods {
            let errs: Vec<Errors> = f
                .cases
                .iter()
                .zip(&refs)
                .map(|(c, r)| errors(&solve(m, c), r))
                .collect();
            let fin = spread(errs.iter().map(|e| e.fin).collect());
            let crunch = spread(errs.iter().map(|e| e.crunch).collect());
            let lost = spread(errs.iter().map(|e| e.lost).collect());
            let t = time(m, &f.cases, budget_ms);
            rows.push(Row {
                method: m,
                family: f.name,
                cases: f.cases.len(),
                fin_ulps: fin,
                crunch_ulps: crunch,
                lost_ulps: lost,
                fin_rel: rel(fin),
                crunch_rel: rel(crunch),
                lost_rel: rel(lost),
                ns_median: t.median,
                ns_min: t.min,
                ns_max: t.max,
                ns_q1: t.q1,
                ns_q3: t.q3,
            });
        }
    }
    rows
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_method_solves_the_lecture_cases() {
        let c = diag(4.0, 1.0, [60.0, 10.0], 1.0).unwrap();
        for m in Method::ALL {
            let o = solve(m, &c);
            assert_eq!(o.fin, [40.0, 90.0], "{m:?}");
            assert_eq!(o.crunch, 1000.0, "{m:?}");
        }
    }

    #[test]
    fn ulps_are_measured_against_the_scale() {
        let exact = from_f64(1.0);
        assert_eq!(ulps(1.0, &exact, 1.0), 0.0);
        assert_eq!(ulps(1.0 + f64::EPSILON, &exact, 1.0), 1.0);
        assert_eq!(ulps(f64::NAN, &exact, 1.0), f64::INFINITY);
        // An error of 1 at scale 2^52 is one ulp.
        assert_eq!(
            ulps(2f64.powi(52) + 1.0, &from_f64(2f64.powi(52)), 2f64.powi(52)),
            1.0
        );
    }

    #[test]
    fn an_ulp_is_the_spacing_of_binary64_down_to_the_subnormals() {
        // A tie: 1 + 2^-53 lies halfway between 1 and next_up(1), half an ulp from each.
        let tie = from_f64(1.0) + from_f64(2f64.powi(-53));
        assert_eq!(ulps(1.0, &tie, 1.0), 0.5);
        assert_eq!(ulps(1.0f64.next_up(), &tie, 1.0), 0.5);
        // next_up is one ulp away at every exponent, including 1e-300 (below 2^-970, where a
        // clamp at 2^-1022 measured 7.45e-9 ulps) and the subnormals.
        for x in [
            1.0,
            3.0,
            1e300,
            1e-300,
            2f64.powi(-1000),
            2f64.powi(-1022),
            1e-310,
            5e-324,
        ] {
            assert_eq!(ulps(x.next_up(), &from_f64(x), x), 1.0, "{x:e}");
            assert_eq!(ulp(x), x.next_up() - x, "{x:e}");
            assert_eq!(ulp(-x), ulp(x), "{x:e}");
        }
        // 2^-1074 is the ulp of every subnormal and of 2^-1022; 2^-1023 - 2^-1074 is an
        // exact subnormal.
        assert_eq!(ulp(1e-310), f64::from_bits(1));
        assert_eq!(ulp(f64::MIN_POSITIVE), f64::from_bits(1));
        assert_eq!(ulp(2f64.powi(-1021)), f64::from_bits(2));
        assert_eq!(ulp(1e-300), 2f64.powi(-997 - 52));
        // 1e-8 relative at 1e-300 is about 6.0e7 ulps (of 2^-1049), not a fraction of one.
        let x = 1e-300;
        let err = ulps(x * (1.0 + 1e-8), &from_f64(x), x);
        assert!((5.5e7..6.5e7).contains(&err), "{err}");
    }

    #[test]
    fn families_are_reproducible_and_full() {
        let a = families(7, 24);
        let b = families(7, 24);
        assert_eq!(a.len(), 7);
        for (x, y) in a.iter().zip(&b) {
            assert_eq!(
                x.cases.len(),
                if x.name == "lecture" { 5 } else { 24 },
                "{}",
                x.name
            );
            let vx: Vec<_> = x.cases.iter().map(|c| c.v_in).collect();
            let vy: Vec<_> = y.cases.iter().map(|c| c.v_in).collect();
            assert_eq!(vx, vy);
        }
    }
}
