//! The smooth impact of two bodies in binary64, fast, for tables (`collide sweep` in the
//! plane): the general form of physics.md section 7,
//! `v1' = v1 - (1 + e) w2 s n`, `v2' = v2 + (1 + e) w1 s n`, with `s = n.(v1 - v2) / n.n` and
//! the centre-of-mass weights `w_i = m_i / (m1 + m2)` (stable for any mass ratio), evaluated in
//! double-double with a running error bound. Where the bound cannot decide the rounding (a
//! component near a tie, or one that cancels to far below its terms), or a value is outside
//! the range where double-double is exact, the exact rational form decides: every component is
//! the correctly rounded value of the exact impulse form, as `collide solve` prints it.
//!
//! `by_normal_parts` is the other form, kept to check this one: the normal parts `v.n^` collide
//! by the rail's rule (`collision::Collision`), the tangential parts pass unchanged.

use crate::values::compensated::Dd;
use crate::values::rational::{Q, from_f64, to_f64};

/// Unit roundoff of binary64.
const U: f64 = f64::EPSILON / 2.0;

/// Values whose size is outside `[2^-900, 2^900]` go to the exact form (products and the
/// double-double error terms must neither overflow nor underflow).
// `#[inline(always)]` on this file's binary64 path: it is inlined into the table's row loop,
// which is compiled for AVX2 and FMA where the processor has them (`table::runs::chunk`).
#[inline(always)]
fn in_range(x: f64) -> bool {
    x == 0.0 || (x.abs() > 1e-270 && x.abs() < 1e270)
}

/// A double-double with a bound on its absolute error.
#[derive(Clone, Copy, Debug)]
struct Bounded {
    v: Dd,
    err: f64,
}

impl Bounded {
    #[inline(always)]
    fn exact(v: Dd) -> Bounded {
        Bounded { v, err: 0.0 }
    }
    #[inline(always)]
    fn mag(&self) -> f64 {
        self.v.hi.abs() * (1.0 + 4.0 * U)
    }
    /// `a + b`: the double-double sum is within `4 u^2 |a + b|`-ish; bounded by the terms.
    #[inline(always)]
    fn add(self, o: Bounded) -> Bounded {
        let v = self.v + o.v;
        let err = self.err + o.err + 8.0 * U * U * (self.mag() + o.mag());
        Bounded { v, err }
    }
    #[inline(always)]
    fn mul(self, o: Bounded) -> Bounded {
        let v = self.v * o.v;
        let err =
            self.err * o.mag() + o.err * self.mag() + self.err * o.err + 8.0 * U * U * v.hi.abs();
        Bounded { v, err }
    }
    #[inline(always)]
    fn div(self, o: Bounded) -> Bounded {
        let v = self.v / o.v;
        let d = o.mag() * (1.0 - 8.0 * U) - o.err;
        let err = if d > 0.0 {
            (self.err + v.hi.abs() * o.err) / d + 8.0 * U * U * v.hi.abs()
        } else {
            f64::INFINITY
        };
        Bounded { v, err }
    }
    /// The binary64 nearest the value, when the error bound cannot change it.
    #[inline(always)]
    fn round(self) -> Option<f64> {
        let r = self.v.hi + self.v.lo;
        let margin = 2.0 * self.err + 4.0 * U * U * r.abs();
        let lo = self.v.hi + (self.v.lo - margin);
        let hi = self.v.hi + (self.v.lo + margin);
        (r.is_finite() && lo == r && hi == r).then_some(r)
    }
}

/// The final velocities of two bodies of masses `m` with velocities `v` meeting along `n` with
/// restitution `e`, each component correctly rounded.
#[inline(always)]
pub fn general<const D: usize>(
    m: [f64; 2],
    v: [[f64; D]; 2],
    n: [f64; D],
    e: f64,
) -> [[f64; D]; 2] {
    bounded(m, v, n, e).unwrap_or_else(|| exact(m, v, n, e))
}

/// The double-double evaluation alone: `None` where its error bound cannot decide a rounding
/// (then `exact` does).
#[inline(always)]
pub fn bounded<const D: usize>(
    m: [f64; 2],
    v: [[f64; D]; 2],
    n: [f64; D],
    e: f64,
) -> Option<[[f64; D]; 2]> {
    let within = |xs: &[f64]| xs.iter().all(|x| in_range(*x));
    if !(within(&m) && v.iter().all(|w| within(w)) && within(&n) && in_range(e)) {
        return None;
    }
    let mut s_num = Bounded::exact(Dd::default());
    let mut nn = Bounded::exact(Dd::default());
    for k in 0..D {
        let d = Dd::sum(v[0][k], -v[1][k]);
        s_num = s_num.add(Bounded::exact(Dd::new(n[k])).mul(Bounded::exact(d)));
        nn = nn.add(Bounded::exact(Dd::prod(n[k], n[k])));
    }
    if nn.v.hi == 0.0 {
        return None;
    }
    // One division: (1 + e) s / (m1 + m2), then times each mass (w_i s = m_i s / M).
    let total = Bounded::exact(Dd::sum(m[0], m[1]));
    let k = Bounded::exact(Dd::sum(1.0, e));
    let q = k.mul(s_num).div(nn.mul(total));
    let j1 = q.mul(Bounded::exact(Dd::new(m[1])));
    let j2 = q.mul(Bounded::exact(Dd::new(m[0])));
    let mut out = [[0.0; D]; 2];
    for c in 0..D {
        let nk = Bounded::exact(Dd::new(n[c]));
        out[0][c] = Bounded::exact(Dd::new(v[0][c]))
            .add(j1.mul(nk).neg())
            .round()?;
        out[1][c] = Bounded::exact(Dd::new(v[1][c])).add(j2.mul(nk)).round()?;
    }
    Some(out)
}

impl Bounded {
    #[inline(always)]
    fn neg(self) -> Bounded {
        Bounded {
            v: -self.v,
            err: self.err,
        }
    }
}

/// The exact impulse form from the binary64 inputs, rounded once (the fallback, and the
/// reference of the tests).
pub fn exact<const D: usize>(m: [f64; 2], v: [[f64; D]; 2], n: [f64; D], e: f64) -> [[f64; D]; 2] {
    let q = |x: f64| from_f64(x);
    let (m1, m2) = (q(m[0]), q(m[1]));
    let mut s_num = Q::ZERO;
    let mut nn = Q::ZERO;
    for k in 0..D {
        s_num += q(n[k]) * (q(v[0][k]) - q(v[1][k]));
        nn += q(n[k]) * q(n[k]);
    }
    let total = &m1 + &m2;
    let j = (Q::ONE + q(e)) * s_num / nn / total;
    let mut out = [[0.0; D]; 2];
    for c in 0..D {
        let jn = &j * q(n[c]);
        out[0][c] = to_f64(&(q(v[0][c]) - &jn * &m2)).unwrap_or(f64::NAN);
        out[1][c] = to_f64(&(q(v[1][c]) + &jn * &m1)).unwrap_or(f64::NAN);
    }
    out
}

/// The same impact by the rail's rule, the check of `general`: with the unit normal
/// `n^ = n/|n|`, the normal parts `a_i = v_i.n^` collide as on a rail,
/// `a1' = a1 + (1 + e) w2 (a2 - a1)`, `a2' = a2 - (1 + e) w1 (a2 - a1)` (`collision`'s impulse
/// form), and the tangential parts pass: `v_i' = v_i + (a_i' - a_i) n^`. In double-double,
/// rounded once: it agrees with `general` to an ulp of the larger of `|v_i|` and `|v_i'|`.
pub fn by_normal_parts<const D: usize>(
    m: [f64; 2],
    v: [[f64; D]; 2],
    n: [f64; D],
    e: f64,
) -> [[f64; D]; 2] {
    let nn = n.iter().fold(Dd::default(), |s, x| s + Dd::prod(*x, *x));
    // sqrt in double-double: one Newton step from the binary64 root.
    let r = nn.hi.sqrt();
    let len = Dd::new(r) + (nn - Dd::prod(r, r)) / Dd::new(2.0 * r);
    let unit: Vec<Dd> = n.iter().map(|x| Dd::new(*x) / len).collect();
    let along = |w: &[f64; D]| {
        w.iter()
            .zip(&unit)
            .fold(Dd::default(), |s, (x, u)| s + Dd::new(*x) * *u)
    };
    let a = [along(&v[0]), along(&v[1])];
    let total = Dd::sum(m[0], m[1]);
    let (w1, w2) = (Dd::new(m[0]) / total, Dd::new(m[1]) / total);
    let k = Dd::sum(1.0, e) * (a[1] - a[0]);
    let da = [w2 * k, -(w1 * k)];
    let mut out = v;
    for (i, row) in out.iter_mut().enumerate() {
        for (x, u) in row.iter_mut().zip(&unit) {
            *x = (Dd::new(*x) + da[i] * *u).value();
        }
    }
    out
}

/// The line of impact of two smooth disks (physics.md section 7), as the two weights of
/// `n = c d + s d_perp` (`d` the relative velocity `v1 - v2`, `d_perp` it turned by +90
/// degrees): `s = sin(phi) = b / (R1 + R2)` and `c = cos(phi) = sqrt((1 - |s|)(1 + |s|))`.
/// Written with the ratio `s`, it never squares a radius, so disks of 1e200 or 1e-200 give the
/// same line as disks of 1; `c` has no cancellation near a grazing contact. `None` when the
/// disks miss (`|b| > R1 + R2`); `c = 0` at a grazing contact, where they do not approach.
pub fn disks(s: f64) -> Option<(f64, f64)> {
    let a = s.abs();
    (a <= 1.0).then(|| (((1.0 - a) * (1.0 + a)).sqrt(), s))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pucks_at_45_degrees() {
        let f = general([1.0, 1.0], [[4.0, 0.0], [0.0, 0.0]], [1.0, 1.0], 1.0);
        assert_eq!(f, [[2.0, -2.0], [2.0, 2.0]]);
    }

    #[test]
    fn the_fast_form_is_the_exact_one_rounded() {
        // A small linear congruential generator: the same cases every run.
        let mut x: u64 = 2026;
        let mut next = || {
            x = x
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            ((x >> 11) as f64 / (1u64 << 53) as f64 - 0.5) * 2.0
        };
        for _ in 0..20_000 {
            let scale = 10f64.powi((next() * 8.0) as i32);
            let m = [1.0 + next().abs() * 10.0, 10f64.powf(next() * 6.0)];
            let v = [[next() * scale, next() * scale], [next(), next() * scale]];
            let n = [next(), next()];
            let e = next().abs();
            assert_eq!(
                general(m, v, n, e),
                exact(m, v, n, e),
                "{m:?} {v:?} {n:?} {e}"
            );
        }
    }
}

#[cfg(test)]
mod agreement {
    use super::*;

    /// `|a - b|` in ulps of the larger of the body's speeds before and after (`v`).
    fn ulps<const D: usize>(v: &[[f64; D]; 2], a: &[[f64; D]; 2], b: &[[f64; D]; 2]) -> f64 {
        let mut worst = 0.0f64;
        for ((ra, rb), rv) in a.iter().zip(b).zip(v) {
            let big = ra.iter().chain(rv).fold(0.0f64, |s, x| s.max(x.abs()));
            let ulp = f64::EPSILON * big.max(f64::MIN_POSITIVE);
            for (x, y) in ra.iter().zip(rb) {
                worst = worst.max((x - y).abs() / ulp);
            }
        }
        worst
    }

    /// physics.md section 7: "the normal parts collide by the 1D rule" and the general impulse
    /// form agree, to 2 ulps of each body's larger speed (before or after), on random cases of
    /// every hard family: mass ratios up to 1e300, a common velocity 1e15 times the relative
    /// one, 2 and 3 dimensions; and the general form is the exact one rounded (0 ulps).
    #[test]
    fn the_general_form_and_the_normal_parts_agree() {
        let mut x: u64 = 7;
        let mut next = || {
            x = x
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            ((x >> 11) as f64 / (1u64 << 53) as f64 - 0.5) * 2.0
        };
        let mut worst = 0.0f64;
        for family in 0..4 {
            for _ in 0..5_000 {
                let ratio = match family {
                    1 => 10f64.powf(next() * 300.0),
                    _ => 10f64.powf(next() * 3.0),
                };
                let boost = if family == 2 { 1e15 } else { 0.0 };
                let m = [1.0 + next().abs(), ratio];
                let e = next().abs();
                if family == 3 {
                    let v = [[next() + boost, next(), next()], [next(), next(), next()]];
                    let n = [next(), next(), next()];
                    assert_eq!(general(m, v, n, e), exact(m, v, n, e));
                    worst = worst.max(ulps(&v, &general(m, v, n, e), &by_normal_parts(m, v, n, e)));
                } else {
                    let v = [[next() + boost, next()], [next() + boost, next()]];
                    let n = [next(), next()];
                    assert_eq!(general(m, v, n, e), exact(m, v, n, e));
                    worst = worst.max(ulps(&v, &general(m, v, n, e), &by_normal_parts(m, v, n, e)));
                }
            }
        }
        assert!(worst <= 2.0, "worst {worst} ulps");
    }
}
