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
    let (j1, j2) = coefficients(m, v, n, e)?;
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

/// The impulse form's two coefficients, `v1' = v1 - j1 n` and `v2' = v2 + j2 n` with
/// `j1 = (1 + e) s m2 / M`, `j2 = (1 + e) s m1 / M`, `s = n.(v1 - v2) / n.n`, in double-double
/// with their error bounds; `None` outside the range where double-double is exact.
#[inline(always)]
fn coefficients<const D: usize>(
    m: [f64; 2],
    v: [[f64; D]; 2],
    n: [f64; D],
    e: f64,
) -> Option<(Bounded, Bounded)> {
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
    Some((
        q.mul(Bounded::exact(Dd::new(m[1]))),
        q.mul(Bounded::exact(Dd::new(m[0]))),
    ))
}

/// How far each body turned (from `v_i` to `v_i'`, 0 for a body at rest before or after) and
/// the angle between `v1'` and `v2'` (`None` if either is zero), in degrees, in the plane: the
/// angles `collide solve` prints ([`crate::space::outcome::angle_between`]), bit for bit,
/// from the same inputs. That function takes `atan2(|a x b|, a.b)` of the exact products,
/// each rounded once (of the vectors scaled by powers of two, which changes neither the
/// rounding nor `atan2` while the values are normal). Here the products come from the impulse
/// form itself, never from the rounded final velocities (whose rounding would leave almost
/// nothing of a turn by 1e-13 rad):
/// `v_i x v_i' = -+ j_i (v_i x n)`, `v_i.v_i' = v_i.v_i -+ j_i (v_i.n)`,
/// `v1' x v2' = v1 x v2 + j2 (v1 x n) + j1 (v2 x n)`,
/// `v1'.v2' = v1.v2 + j2 (v1.n) - j1 (v2.n) - j1 j2 (n.n)`,
/// in double-double with an error bound; where the bound cannot decide a rounding, or a
/// value comes near binary64's range, the exact rationals decide through that same function.
pub fn angles(m: [f64; 2], v: [[f64; 2]; 2], n: [f64; 2], e: f64) -> ([f64; 2], Option<f64>) {
    fast_angles(m, v, n, e).unwrap_or_else(|| exact_angles(m, v, n, e))
}

/// Whether every input is 0 or of a moderate size (1e-60 to 1e60): then every product of the
/// fast paths stays far inside binary64 (and so do the vectors as `angle_between` scales
/// them), so no rounding meets a subnormal or an overflow.
#[inline(always)]
fn moderate(m: [f64; 2], v: [[f64; 2]; 2], n: [f64; 2], e: f64) -> bool {
    let ok = |x: f64| x == 0.0 || (x.abs() > 1e-60 && x.abs() < 1e60);
    m.iter().chain(v.iter().flatten()).chain(&n).all(|x| ok(*x)) && ok(e)
}

/// `angles` in double-double alone: `None` where it cannot decide a rounding.
#[inline(always)]
fn fast_angles(
    m: [f64; 2],
    v: [[f64; 2]; 2],
    n: [f64; 2],
    e: f64,
) -> Option<([f64; 2], Option<f64>)> {
    if !moderate(m, v, n, e) {
        return None;
    }
    let (j1, j2) = coefficients(m, v, n, e)?;
    let cross = |a: [f64; 2], c: [f64; 2]| {
        Bounded::exact(Dd::prod(a[0], c[1])).add(Bounded::exact(Dd::prod(a[1], c[0])).neg())
    };
    let dot = |a: [f64; 2], c: [f64; 2]| {
        Bounded::exact(Dd::prod(a[0], c[0])).add(Bounded::exact(Dd::prod(a[1], c[1])))
    };
    // The angle of a (cross, dot) pair, when both round for certain and are not both zero
    // (a zero vector: the exact form says which), and neither is so small that it or its
    // scaled form is subnormal (`big`: a bound on the product of the two vectors' sizes).
    let angle = |c: Bounded, d: Bounded, big: f64| -> Option<f64> {
        let (c, d) = (c.round()?, d.round()?);
        let tiny = |x: f64| x != 0.0 && (x.abs() < 1e-200 * big || x.abs() < 1e-290);
        if (c == 0.0 && d == 0.0) || tiny(c) || tiny(d) {
            return None;
        }
        Some(libm::atan2(c.abs(), d).to_degrees())
    };
    let size = |a: [f64; 2]| a[0].abs().max(a[1].abs());
    let (n_x, n_n) = (cross(v[0], n), dot(v[0], n));
    let (m_x, m_n) = (cross(v[1], n), dot(v[1], n));
    // Body 1: |v1 x v1'| = |j1 (v1 x n)|, v1.v1' = v1.v1 - j1 (v1.n); body 2 with + j2.
    let mut turned = [0.0; 2];
    for (i, (j, vx, vn)) in [(j1.neg(), n_x, n_n), (j2, m_x, m_n)]
        .into_iter()
        .enumerate()
    {
        if v[i] == [0.0, 0.0] {
            continue;
        }
        let big = size(v[i]) * (size(v[i]) + j.v.hi.abs() * size(n));
        turned[i] = angle(j.mul(vx), dot(v[i], v[i]).add(j.mul(vn)), big)?;
    }
    let c = cross(v[0], v[1]).add(j2.mul(n_x)).add(j1.mul(m_x));
    let d = dot(v[0], v[1])
        .add(j2.mul(n_n))
        .add(j1.mul(m_n).neg())
        .add(j1.mul(j2).mul(dot(n, n)).neg());
    let w = [
        size(v[0]) + j1.v.hi.abs() * size(n),
        size(v[1]) + j2.v.hi.abs() * size(n),
    ];
    let between = angle(c, d, w[0] * w[1])?;
    Some((turned, Some(between)))
}

/// The energies of an impact and the impulse on body 2, each the exact value rounded once:
/// what `collide solve` prints for the same inputs (`Outcome`'s `ke_in`, `ke_fin`, `ke_com`,
/// `crunch`, `lost` and `impulse(1)`), bit for bit.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Energies {
    pub ke_in: f64,
    pub ke_fin: f64,
    pub ke_com: f64,
    pub crunch: f64,
    pub lost: f64,
    pub impulse: [f64; 2],
}

/// [`Energies`] of the impact: `KE_IN = 1/2 sum m_i (v_i.v_i)`, the crunch `1/2 mu (n.d)^2 /
/// n.n` (`mu = m1 m2 / M`, physics.md section 7), `lost = (1 - e)(1 + e) crunch`,
/// `KE_FIN = KE_IN - lost`, `KE_COM = 1/2 |P|^2 / M`, the impulse `j2 m2 n` (`j2` of
/// [`coefficients`]), in double-double with an error bound; where the bound cannot decide a
/// rounding (`KE_FIN` after a loss of nearly everything), or a value is outside moderate
/// sizes, the exact rationals decide through `Outcome` itself.
pub fn energies(m: [f64; 2], v: [[f64; 2]; 2], n: [f64; 2], e: f64) -> Energies {
    fast_energies(m, v, n, e).unwrap_or_else(|| exact_energies(m, v, n, e))
}

/// `energies` in double-double alone: `None` where it cannot decide a rounding.
#[inline(always)]
fn fast_energies(m: [f64; 2], v: [[f64; 2]; 2], n: [f64; 2], e: f64) -> Option<Energies> {
    if !moderate(m, v, n, e) {
        return None;
    }
    let (_, j2) = coefficients(m, v, n, e)?;
    let b = |x: Dd| Bounded::exact(x);
    let half = b(Dd::new(0.5));
    let total = b(Dd::sum(m[0], m[1]));
    let mut nd = b(Dd::default());
    let mut nn = b(Dd::default());
    let mut p2 = b(Dd::default());
    let mut ke = b(Dd::default());
    for k in 0..2 {
        nd = nd.add(b(Dd::new(n[k])).mul(b(Dd::sum(v[0][k], -v[1][k]))));
        nn = nn.add(b(Dd::prod(n[k], n[k])));
        let p = b(Dd::prod(m[0], v[0][k])).add(b(Dd::prod(m[1], v[1][k])));
        p2 = p2.add(p.mul(p));
    }
    for i in 0..2 {
        let vv = b(Dd::prod(v[i][0], v[i][0])).add(b(Dd::prod(v[i][1], v[i][1])));
        ke = ke.add(b(Dd::new(m[i])).mul(vv));
    }
    let ke_in = half.mul(ke);
    let mu = b(Dd::prod(m[0], m[1])).div(total);
    let crunch = half.mul(mu).mul(nd).mul(nd).div(nn);
    let lost = b(Dd::sum(1.0, -e)).mul(b(Dd::sum(1.0, e))).mul(crunch);
    let ke_fin = ke_in.add(lost.neg());
    let ke_com = half.mul(p2).div(total);
    let impulse = j2.mul(b(Dd::new(m[1])));
    Some(Energies {
        ke_in: ke_in.round()?,
        ke_fin: ke_fin.round()?,
        ke_com: ke_com.round()?,
        crunch: crunch.round()?,
        lost: lost.round()?,
        impulse: [
            impulse.mul(b(Dd::new(n[0]))).round()?,
            impulse.mul(b(Dd::new(n[1]))).round()?,
        ],
    })
}

/// The exact impact of the binary64 inputs as `collide solve` holds it: `None` for `n = 0`.
pub fn exact_outcome(
    m: [f64; 2],
    v: [[f64; 2]; 2],
    n: [f64; 2],
    e: f64,
) -> Option<crate::space::outcome::Outcome> {
    let q = |x: f64| from_f64(x);
    let (m1, m2) = (q(m[0]), q(m[1]));
    let nq: Vec<Q> = n.iter().map(|x| q(*x)).collect();
    let vq: Vec<Vec<Q>> = v
        .iter()
        .map(|w| w.iter().map(|x| q(*x)).collect())
        .collect();
    let mut s_num = Q::ZERO;
    let mut nn = Q::ZERO;
    for k in 0..2 {
        s_num += &nq[k] * (&vq[0][k] - &vq[1][k]);
        nn += &nq[k] * &nq[k];
    }
    if nn == Q::ZERO {
        return None;
    }
    let j = (Q::ONE + q(e)) * s_num / nn / (&m1 + &m2);
    let fin: Vec<Vec<Q>> = vec![
        (0..2).map(|k| &vq[0][k] - &j * &m2 * &nq[k]).collect(),
        (0..2).map(|k| &vq[1][k] + &j * &m1 * &nq[k]).collect(),
    ];
    Some(crate::space::outcome::Outcome {
        dim: 2,
        masses: vec![m1, m2],
        v_in: vq,
        fin,
        normal: Some(nq),
        e: Some(q(e)),
        approx: crate::space::outcome::Marks::default(),
    })
}

/// `energies` from the exact impact through `Outcome`'s own methods (the fallback, and the
/// tests' reference).
pub fn exact_energies(m: [f64; 2], v: [[f64; 2]; 2], n: [f64; 2], e: f64) -> Energies {
    let f = |x: &Q| to_f64(x).unwrap_or(f64::NAN);
    let Some(o) = exact_outcome(m, v, n, e) else {
        return Energies {
            ke_in: f64::NAN,
            ke_fin: f64::NAN,
            ke_com: f64::NAN,
            crunch: f64::NAN,
            lost: f64::NAN,
            impulse: [f64::NAN; 2],
        };
    };
    let j = o.impulse(1);
    Energies {
        ke_in: f(&o.ke_in()),
        ke_fin: f(&o.ke_fin()),
        ke_com: f(&o.ke_com()),
        crunch: f(&o.crunch()),
        lost: f(&o.lost()),
        impulse: [f(&j[0]), f(&j[1])],
    }
}

/// `angles` from the exact impulse form of the binary64 inputs, through
/// [`crate::space::outcome::angle_between`] itself (the fallback, and the tests' reference).
pub fn exact_angles(m: [f64; 2], v: [[f64; 2]; 2], n: [f64; 2], e: f64) -> ([f64; 2], Option<f64>) {
    use crate::space::outcome::angle_between;
    let Some(o) = exact_outcome(m, v, n, e) else {
        return ([f64::NAN; 2], None);
    };
    let turned = [0, 1].map(|i| angle_between(&o.v_in[i], &o.fin[i]).unwrap_or(0.0));
    (turned, angle_between(&o.fin[0], &o.fin[1]))
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
