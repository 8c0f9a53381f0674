//! A quantity of a rigid impact as a function of one unknown, exactly: without friction (and for
//! bodies that join, or Garwin's rough contact) the impulse is `P = (1 + e) (n.w)/(n.K.n) n` or
//! `P = K^-1 (w - w')`, rational in a speed, a mass, the hit point or `e`, and so is every value
//! after; with Coulomb friction each of Routh's phases is (a contact that slides throughout:
//! `P_t = mu P_n`, rational in mu). Such a function is found from its exact values at a few
//! points (rational interpolation: `N(x) - y D(x) = 0` at each sample, a linear system for the
//! coefficients, of the lowest degrees that fit every sample), and the unknown is a real root of
//! its numerator: exact for degrees 1 and 2 (a quadratic's root when its discriminant is a
//! square), else to 40 digits by bisection.

use num_traits::Signed;

use crate::values::quantity::sqrt;
use crate::values::rational::{Q, int, ratio, sqrt_exact};

/// The highest degree of a numerator or denominator looked for.
pub const MAX_DEGREE: usize = 6;

/// How many samples a fit of every degree up to `MAX_DEGREE` needs, with two to check it.
pub const SAMPLES: usize = 2 * MAX_DEGREE + 3;

/// Digits of a root that is not rational (or not found as one).
const DIGITS: usize = 40;

/// A polynomial, lowest coefficient first.
pub type Poly = Vec<Q>;

/// `p(x)`, by Horner's rule.
pub fn eval(p: &[Q], x: &Q) -> Q {
    p.iter().rev().fold(Q::ZERO, |s, c| s * x + c)
}

/// The degree of `p` (`None` for the zero polynomial).
pub fn degree(p: &[Q]) -> Option<usize> {
    p.iter().rposition(|c| !c.is_zero())
}

/// `N / D` of the lowest total degree that equals `y` at every sample `(x, y)`, or `None`
/// (not a rational function of degrees up to `MAX_DEGREE`, or too few samples to tell).
pub fn fit(samples: &[(Q, Q)]) -> Option<(Poly, Poly)> {
    for total in 0..=2 * MAX_DEGREE {
        // Two samples beyond those that fix the coefficients check the fit.
        if total + 3 > samples.len() {
            return None;
        }
        for p in 0..=total.min(MAX_DEGREE) {
            let q = total - p;
            if q > MAX_DEGREE {
                continue;
            }
            if let Some(f) = fit_degrees(samples, p, q) {
                return Some(f);
            }
        }
    }
    None
}

/// `N` of degree `p` and `D` of degree `q` through the first `p + q + 1` samples (their null
/// space, when it is one vector), checked at all of them.
fn fit_degrees(samples: &[(Q, Q)], p: usize, q: usize) -> Option<(Poly, Poly)> {
    let rows: Vec<Vec<Q>> = samples[..p + q + 1]
        .iter()
        .map(|(x, y)| {
            let mut row = powers(x, p);
            row.extend(powers(x, q).into_iter().map(|c| -(y * c)));
            row
        })
        .collect();
    let v = null_vector(rows, p + q + 2)?;
    let (n, d) = (v[..=p].to_vec(), v[p + 1..].to_vec());
    let fits = samples.iter().all(|(x, y)| {
        let dx = eval(&d, x);
        !dx.is_zero() && eval(&n, x) == y * dx
    });
    fits.then_some((n, d))
}

/// `1, x, ..., x^k`.
fn powers(x: &Q, k: usize) -> Vec<Q> {
    let mut out = Vec::with_capacity(k + 1);
    let mut p = Q::ONE;
    for _ in 0..=k {
        out.push(p.clone());
        p = &p * x;
    }
    out
}

/// The one vector (up to scale) with `rows . v = 0`, by Gauss-Jordan elimination; `None` when
/// the null space is not one-dimensional.
fn null_vector(mut rows: Vec<Vec<Q>>, cols: usize) -> Option<Vec<Q>> {
    let mut pivots = Vec::new();
    let mut r = 0;
    for c in 0..cols {
        let Some(k) = (r..rows.len()).find(|&k| !rows[k][c].is_zero()) else {
            continue;
        };
        rows.swap(r, k);
        let lead = rows[r][c].clone();
        rows[r] = rows[r].iter().map(|x| x / &lead).collect();
        for k in 0..rows.len() {
            if k != r && !rows[k][c].is_zero() {
                let f = rows[k][c].clone();
                let pivot_row = rows[r].clone();
                for (a, b) in rows[k].iter_mut().zip(&pivot_row) {
                    *a -= &f * b;
                }
            }
        }
        pivots.push(c);
        r += 1;
        if r == rows.len() {
            break;
        }
    }
    let free: Vec<usize> = (0..cols).filter(|c| !pivots.contains(c)).collect();
    let [f] = free.as_slice() else {
        return None;
    };
    let mut v = vec![Q::ZERO; cols];
    v[*f] = Q::ONE;
    for (row, &c) in pivots.iter().enumerate() {
        v[c] = -rows[row][*f].clone();
    }
    Some(v)
}

/// A real root, and whether it is exact.
#[derive(Clone, Debug, PartialEq)]
pub struct Root {
    pub x: Q,
    pub exact: bool,
}

/// What the roots of a polynomial are.
#[derive(Clone, Debug, PartialEq)]
pub enum Roots {
    /// The zero polynomial: every value is a root.
    All,
    /// Its real roots within `[lo, hi]`, ascending (roots of degree 3 and more found by a sign
    /// change on a grid: a double root is not found).
    Some(Vec<Root>),
}

/// The real roots of `p` in `[lo, hi]` (exact for degrees 1 and 2 with a square discriminant).
pub fn roots(p: &[Q], lo: &Q, hi: &Q) -> Roots {
    let Some(deg) = degree(p) else {
        return Roots::All;
    };
    let inside = |x: &Q| x >= lo && x <= hi;
    let found = match deg {
        0 => Vec::new(),
        1 => vec![Root {
            x: -(&p[0] / &p[1]),
            exact: true,
        }],
        2 => quadratic(&p[2], &p[1], &p[0]),
        _ => bisected(p, lo, hi),
    };
    let mut found: Vec<Root> = found.into_iter().filter(|r| inside(&r.x)).collect();
    found.sort_by(|a, b| a.x.cmp(&b.x));
    found.dedup_by(|a, b| a.x == b.x);
    Roots::Some(found)
}

/// The real roots of `a x^2 + b x + c` (`a != 0`), in the stable form: `q = -(b + sign(b)
/// sqrt(d))/2`, roots `q/a` and `c/q`.
fn quadratic(a: &Q, b: &Q, c: &Q) -> Vec<Root> {
    let d = b * b - int(4) * a * c;
    if d.is_negative() {
        return Vec::new();
    }
    let (s, exact) = match sqrt_exact(&d) {
        Some(s) => (s, true),
        None => (sqrt(&d, DIGITS), false),
    };
    let q = if b.is_negative() {
        (-b + &s) * ratio(1, 2)
    } else {
        -(b + &s) * ratio(1, 2)
    };
    if q.is_zero() {
        // b = 0 and d = 0: the double root 0.
        return vec![Root { x: Q::ZERO, exact }];
    }
    vec![Root { x: &q / a, exact }, Root { x: c / &q, exact }]
}

/// Roots of `p` in `[lo, hi]` where it changes sign on a grid of 4096 steps, each bisected to
/// `DIGITS` digits (exact when the grid or a bisection lands on it).
fn bisected(p: &[Q], lo: &Q, hi: &Q) -> Vec<Root> {
    const STEPS: i64 = 4096;
    let step = (hi - lo) / int(STEPS);
    let mut out = Vec::new();
    let mut a = lo.clone();
    let mut fa = eval(p, &a);
    for k in 1..=STEPS {
        let b = lo + &step * int(k);
        let fb = eval(p, &b);
        if fa.is_zero() {
            out.push(Root {
                x: a.clone(),
                exact: true,
            });
        } else if fa.is_positive() != fb.is_positive() && !fb.is_zero() {
            out.push(bisect(p, a.clone(), b.clone(), fa.is_positive()));
        }
        a = b;
        fa = fb;
    }
    if fa.is_zero() {
        out.push(Root { x: a, exact: true });
    }
    out
}

/// Bisection of a sign change of `p` in `(a, b)` to `DIGITS` digits of the interval.
fn bisect(p: &[Q], mut a: Q, mut b: Q, a_positive: bool) -> Root {
    let width = (&b - &a).abs();
    let tol = width / Q::from(crate::values::rational::pow10(DIGITS));
    while (&b - &a).abs() > tol {
        let m = (&a + &b) * ratio(1, 2);
        let fm = eval(p, &m);
        if fm.is_zero() {
            return Root { x: m, exact: true };
        }
        if fm.is_positive() == a_positive {
            a = m;
        } else {
            b = m;
        }
    }
    Root {
        x: (a + b) * ratio(1, 2),
        exact: false,
    }
}

/// The continued-fraction convergents of `x` (at most 16): the simplest rationals near it, to
/// try as the exact value of a bisected root.
pub fn convergents(x: &Q) -> Vec<Q> {
    use crate::values::rational::IBig;
    let (mut h0, mut h1) = (IBig::ZERO, IBig::ONE);
    let (mut k0, mut k1) = (IBig::ONE, IBig::ZERO);
    let mut r = x.clone();
    let mut out = Vec::new();
    for _ in 0..16 {
        let a = r.floor();
        let h = &a * &h1 + &h0;
        let k = &a * &k1 + &k0;
        out.push(Q::from(h.clone()) / Q::from(k.clone()));
        (h0, h1, k0, k1) = (h1, h, k1, k);
        let rest = &r - Q::from(a);
        if rest.is_zero() {
            break;
        }
        r = Q::ONE / rest;
    }
    out
}

/// A bound on the size of every root of `p` (Cauchy's: `1 + max |a_i / a_n|`).
pub fn root_bound(p: &[Q]) -> Q {
    let Some(n) = degree(p) else {
        return Q::ONE;
    };
    let lead = p[n].clone().abs();
    p[..n]
        .iter()
        .map(|c| c.clone().abs() / &lead)
        .fold(Q::ZERO, |m, x| if x > m { x } else { m })
        + Q::ONE
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(n: i64) -> Q {
        int(n)
    }

    #[test]
    fn a_rational_function_is_found_from_its_values() {
        // y = (3x + 1)/(x^2 + 2): degrees (1, 2), found from 15 samples and equal at each.
        let samples: Vec<(Q, Q)> = (1..=15)
            .map(|k| {
                let x = q(k);
                let y = (int(3) * &x + Q::ONE) / (&x * &x + int(2));
                (x, y)
            })
            .collect();
        let (n, d) = fit(&samples).expect("a fit");
        assert_eq!((degree(&n), degree(&d)), (Some(1), Some(2)));
        let x = ratio(7, 3);
        assert_eq!(
            eval(&n, &x) / eval(&d, &x),
            (int(3) * &x + Q::ONE) / (&x * &x + int(2))
        );
    }

    #[test]
    fn a_fit_of_the_highest_total_degree_is_found() {
        // y = (x^6 + 1)/(x^6 + x + 2): degrees (6, 6), total 12 = 2 MAX_DEGREE, the last total
        // the 15 samples (SAMPLES) can fix and check; a search that stopped at a lower total
        // finds nothing. The fit is unique up to a factor: N/D equals y at a point not sampled.
        let y = |x: &Q| {
            let x6 = (0..6).fold(Q::ONE, |p, _| p * x);
            (&x6 + Q::ONE) / (x6 + x + int(2))
        };
        let samples: Vec<(Q, Q)> = (1..=SAMPLES as i64).map(|k| (q(k), y(&q(k)))).collect();
        let (n, d) = fit(&samples).expect("a fit of total degree 12");
        assert_eq!((degree(&n), degree(&d)), (Some(6), Some(6)));
        let x = ratio(-7, 3);
        assert_eq!(eval(&n, &x) / eval(&d, &x), y(&x));
    }

    #[test]
    fn a_quadratic_with_a_negative_middle_coefficient() {
        // (x - 2/3)(x - 5) = x^2 - 17/3 x + 10/3: b < 0, so q = (-b + sqrt(d))/2 with d =
        // 289/9 - 40/3 = 169/9: q = (17/3 + 13/3)/2 = 5, roots q/a = 5 and c/q = 2/3, exact.
        let r = quadratic(&Q::ONE, &ratio(-17, 3), &ratio(10, 3));
        assert_eq!(
            r.iter().map(|r| (r.x.clone(), r.exact)).collect::<Vec<_>>(),
            [(q(5), true), (ratio(2, 3), true)]
        );
    }

    #[test]
    fn roots_exact_and_to_forty_digits() {
        // (x - 2/3)(x + 5) = x^2 + 13/3 x - 10/3: both roots exact.
        let p = vec![ratio(-10, 3), ratio(13, 3), Q::ONE];
        let Roots::Some(r) = roots(&p, &q(-10), &q(10)) else {
            panic!()
        };
        assert_eq!(
            r.iter().map(|r| r.x.clone()).collect::<Vec<_>>(),
            [q(-5), ratio(2, 3)]
        );
        assert!(r.iter().all(|r| r.exact));
        // x^2 - 2: sqrt(2) to 40 digits, marked inexact; only the positive one in [0, 10].
        let Roots::Some(r) = roots(&[q(-2), Q::ZERO, Q::ONE], &Q::ZERO, &q(10)) else {
            panic!()
        };
        assert_eq!(r.len(), 1);
        assert!(!r[0].exact);
        let err = (&r[0].x * &r[0].x - q(2)).abs();
        assert!(err < ratio(1, 1_000_000_000_000_000_000));
        // x^3 - x = x (x - 1)(x + 1) on [-2, 2]: grid points, exact; on [-1/2, 2], 0 and 1
        // by bisection to 40 digits.
        let cubic = [Q::ZERO, q(-1), Q::ZERO, Q::ONE];
        let Roots::Some(r) = roots(&cubic, &q(-2), &q(2)) else {
            panic!()
        };
        assert_eq!(
            r.iter().map(|r| r.x.clone()).collect::<Vec<_>>(),
            [q(-1), Q::ZERO, Q::ONE]
        );
        let Roots::Some(r) = roots(&cubic, &ratio(-1, 2), &q(2)) else {
            panic!()
        };
        assert_eq!(r.len(), 2);
        for (root, want) in r.iter().zip([Q::ZERO, Q::ONE]) {
            assert!((&root.x - want).abs() < ratio(1, 1_000_000_000_000_000_000));
        }
        assert_eq!(roots(&[Q::ZERO], &Q::ZERO, &Q::ONE), Roots::All);
        assert!(root_bound(&[q(-6), Q::ONE]) >= q(6));
    }
}
