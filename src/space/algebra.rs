//! The algebra of a problem's unknowns: the laws (momentum, restitution along the line of
//! impact, energy, unit directions) are polynomials of degree at most 2 in the unknowns, with
//! exact rational coefficients. The linear ones are solved by exact Gaussian elimination; what
//! is left (at most one or two free parameters) is fixed by the quadratic ones.

use std::collections::BTreeMap;

use num_traits::{Signed, Zero};

use crate::values::rational::Q;

/// `c + sum a_i x_i + sum b_ij x_i x_j`.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Poly {
    pub c: Q,
    pub lin: BTreeMap<usize, Q>,
    /// Keys `(i, j)` with `i <= j`.
    pub quad: BTreeMap<(usize, usize), Q>,
}

/// A product of unknowns of degree above 2 (a mass and a velocity both unknown in a kinetic
/// energy).
#[derive(Clone, Copy, Debug, PartialEq, Eq, thiserror::Error)]
#[error("a product of three unknowns")]
pub struct TooNonlinear;

impl Poly {
    pub fn constant(c: Q) -> Poly {
        Poly {
            c,
            ..Poly::default()
        }
    }

    pub fn var(i: usize) -> Poly {
        let mut p = Poly::default();
        p.lin.insert(i, Q::ONE);
        p
    }

    pub fn is_linear(&self) -> bool {
        self.quad.values().all(Zero::is_zero)
    }

    pub fn is_zero(&self) -> bool {
        self.c.is_zero() && self.lin.values().all(Zero::is_zero) && self.is_linear()
    }

    /// The unknowns it involves.
    pub fn vars(&self) -> impl Iterator<Item = usize> + '_ {
        let lin = self
            .lin
            .iter()
            .filter(|(_, a)| !a.is_zero())
            .map(|(i, _)| *i);
        let quad = self
            .quad
            .iter()
            .filter(|(_, b)| !b.is_zero())
            .flat_map(|((i, j), _)| [*i, *j]);
        lin.chain(quad)
    }

    pub fn add(&self, o: &Poly) -> Poly {
        let mut p = self.clone();
        p.c += &o.c;
        for (i, a) in &o.lin {
            *p.lin.entry(*i).or_default() += a;
        }
        for (k, b) in &o.quad {
            *p.quad.entry(*k).or_default() += b;
        }
        p.prune();
        p
    }

    /// `self += o` in place: only `o`'s terms are touched, so a sum of `n` short terms costs
    /// `O(n log n)` (`add` copies the sum each time: `O(n^2)`).
    pub fn add_assign(&mut self, o: &Poly) {
        self.c += &o.c;
        for (i, a) in &o.lin {
            let entry = self.lin.entry(*i).or_default();
            *entry += a;
            if entry.is_zero() {
                self.lin.remove(i);
            }
        }
        for (k, b) in &o.quad {
            let entry = self.quad.entry(*k).or_default();
            *entry += b;
            if entry.is_zero() {
                self.quad.remove(k);
            }
        }
    }

    pub fn neg(&self) -> Poly {
        self.scale(&-Q::ONE)
    }

    pub fn sub(&self, o: &Poly) -> Poly {
        self.add(&o.neg())
    }

    pub fn scale(&self, s: &Q) -> Poly {
        let mut p = Poly {
            c: &self.c * s,
            lin: self.lin.iter().map(|(i, a)| (*i, a * s)).collect(),
            quad: self.quad.iter().map(|(k, b)| (*k, b * s)).collect(),
        };
        p.prune();
        p
    }

    /// The product, refused above degree 2.
    pub fn mul(&self, o: &Poly) -> Result<Poly, TooNonlinear> {
        let constant = |p: &Poly| p.lin.is_empty() && p.is_linear();
        if !(self.is_linear() || constant(o)) || !(o.is_linear() || constant(self)) {
            return Err(TooNonlinear);
        }
        let mut p = self.scale(&o.c).add(&o.scale(&self.c));
        p.c = &self.c * &o.c;
        for (i, a) in &self.lin {
            for (j, b) in &o.lin {
                let k = (*i.min(j), *i.max(j));
                *p.quad.entry(k).or_default() += a * b;
            }
        }
        p.prune();
        Ok(p)
    }

    fn prune(&mut self) {
        self.lin.retain(|_, a| !a.is_zero());
        self.quad.retain(|_, b| !b.is_zero());
    }

    /// The value at `x` (every unknown it involves given).
    pub fn eval(&self, x: &[Q]) -> Q {
        let mut s = self.c.clone();
        for (i, a) in &self.lin {
            s += a * &x[*i];
        }
        for ((i, j), b) in &self.quad {
            s += b * &x[*i] * &x[*j];
        }
        s
    }

    /// The sum of the terms' magnitudes at `x`, exactly: the scale a residual is judged by.
    pub fn scale_at(&self, x: &[Q]) -> Q {
        let mut s = self.c.abs();
        for (i, a) in &self.lin {
            s += (a * &x[*i]).abs();
        }
        for ((i, j), b) in &self.quad {
            s += (b * &x[*i] * &x[*j]).abs();
        }
        s
    }

    /// Substitutes `x = x0 + sum_k t_k z_k`: a polynomial in the parameters `t`.
    pub fn substitute(&self, x0: &[Q], basis: &[Vec<Q>]) -> Poly {
        // Each unknown as a polynomial in t.
        let as_poly = |i: usize| -> Poly {
            let mut p = Poly::constant(x0[i].clone());
            for (k, z) in basis.iter().enumerate() {
                if !z[i].is_zero() {
                    p.lin.insert(k, z[i].clone());
                }
            }
            p
        };
        let mut out = Poly::constant(self.c.clone());
        for (i, a) in &self.lin {
            out = out.add(&as_poly(*i).scale(a));
        }
        for ((i, j), b) in &self.quad {
            let prod = as_poly(*i)
                .mul(&as_poly(*j))
                .expect("linear times linear is quadratic");
            out = out.add(&prod.scale(b));
        }
        out
    }
}

/// The solutions of linear equations `p(x) = 0`: `x = x0 + sum_k t_k z_k`.
#[derive(Clone, Debug, PartialEq)]
pub struct Affine {
    pub x0: Vec<Q>,
    pub basis: Vec<Vec<Q>>,
}

/// Linear equations that contradict each other: the index of an equation left as `0 = c`.
#[derive(Clone, Debug, PartialEq)]
pub struct Contradiction {
    pub equation: usize,
}

/// Solves the linear equations `eqs` (each `c + a.x = 0`) in `n` unknowns exactly; equations
/// that follow from the others are dropped, one that contradicts them is named. The unknowns in
/// `last` are eliminated last, so they are the free parameters where any are left (a free
/// unknown `x_f` has `z_f = 1` in its basis vector: its parameter is its value).
pub fn solve_linear(eqs: &[&Poly], n: usize, last: &[usize]) -> Result<Affine, Contradiction> {
    // Rows [a | -c], remembering each row's equation.
    let mut rows: Vec<(usize, Vec<Q>, Q)> = eqs
        .iter()
        .enumerate()
        .map(|(k, p)| {
            let mut a = vec![Q::ZERO; n];
            for (i, v) in &p.lin {
                a[*i] = v.clone();
            }
            (k, a, -p.c.clone())
        })
        .collect();
    let mut pivots: Vec<usize> = Vec::new();
    let mut r = 0;
    let order = (0..n)
        .filter(|c| !last.contains(c))
        .chain(last.iter().copied());
    for col in order {
        let Some(p) = (r..rows.len()).find(|&i| !rows[i].1[col].is_zero()) else {
            continue;
        };
        rows.swap(r, p);
        let inv = Q::ONE / &rows[r].1[col];
        let (_, a, b) = &mut rows[r];
        for v in a.iter_mut() {
            *v *= &inv;
        }
        *b *= &inv;
        let (pa, pb) = (rows[r].1.clone(), rows[r].2.clone());
        for (i, row) in rows.iter_mut().enumerate() {
            if i == r || row.1[col].is_zero() {
                continue;
            }
            let f = row.1[col].clone();
            for (v, w) in row.1.iter_mut().zip(&pa) {
                *v -= &f * w;
            }
            row.2 -= &f * &pb;
        }
        pivots.push(col);
        r += 1;
    }
    if let Some((k, _, _)) = rows[r..].iter().find(|(_, _, b)| !b.is_zero()) {
        return Err(Contradiction { equation: *k });
    }
    let mut x0 = vec![Q::ZERO; n];
    for (row, &col) in rows.iter().zip(&pivots) {
        x0[col] = row.2.clone();
    }
    let free: Vec<usize> = (0..n)
        .filter(|c| !last.contains(c))
        .chain(last.iter().copied())
        .filter(|c| !pivots.contains(c))
        .collect();
    let basis = free
        .iter()
        .map(|&f| {
            let mut z = vec![Q::ZERO; n];
            z[f] = Q::ONE;
            for (row, &col) in rows.iter().zip(&pivots) {
                z[col] = -row.1[f].clone();
            }
            z
        })
        .collect();
    Ok(Affine { x0, basis })
}

/// `p(s) = sum c_k s^k` at `s`, exactly.
pub fn horner(c: &[Q], s: &Q) -> Q {
    c.iter().rev().fold(Q::ZERO, |acc, ck| acc * s + ck)
}

/// The real roots of the polynomial `c` (coefficients from the constant up) where it changes
/// sign, each bracketed on a binary64 grid over the real line (`s = tan(theta/2)`, theta on a
/// fine grid) and narrowed by exact bisection to a width of `10^-digits` of its size: simple
/// roots (a double root, a tangency, is not a sign change and is not found).
pub fn sign_change_roots(c: &[Q], digits: usize) -> Vec<Q> {
    const GRID: usize = 8192;
    let f = |s: &Q| horner(c, s);
    let at = |k: usize| -> Option<Q> {
        let theta = -std::f64::consts::PI + std::f64::consts::TAU * k as f64 / GRID as f64;
        let s = (theta / 2.0).tan();
        s.is_finite().then(|| crate::values::rational::from_f64(s))
    };
    let mut out = Vec::new();
    let mut prev: Option<(Q, Q)> = None;
    for k in 1..GRID {
        let Some(s) = at(k) else { continue };
        let v = f(&s);
        if v.is_zero() {
            out.push(s.clone());
        } else if let Some((ps, pv)) = &prev
            && !pv.is_zero()
            && pv.is_negative() != v.is_negative()
        {
            out.push(bisect(&f, ps.clone(), s.clone(), pv.is_negative(), digits));
        }
        prev = Some((s, v));
    }
    out
}

/// Every real root of the polynomial `c` (coefficients from the constant up), each once, and
/// whether it is exact: the roots of its square-free part `c / gcd(c, c')` (exact polynomial
/// arithmetic), whose every root is simple, so a double root of `c` (a tangency: two bodies
/// that leave together) is a sign change there and is found; each root found to `digits`
/// digits is then tried against the rationals of small denominator near it (the convergents of
/// its continued fraction), and one that is a root exactly is kept exact.
pub fn real_roots(c: &[Q], digits: usize) -> Vec<(Q, bool)> {
    let p = trim(c.to_vec());
    if p.len() <= 1 {
        return Vec::new();
    }
    let g = gcd(&p, &derivative(&p));
    let free = if g.len() > 1 { divide(&p, &g) } else { p };
    sign_change_roots(&free, digits)
        .into_iter()
        .map(|r| match snap(&free, &r) {
            Some(q) => (q, true),
            None => (r, false),
        })
        .collect()
}

/// `p` without zero coefficients at the top.
fn trim(mut p: Vec<Q>) -> Vec<Q> {
    while p.last().is_some_and(Zero::is_zero) {
        p.pop();
    }
    p
}

fn derivative(p: &[Q]) -> Vec<Q> {
    p.iter()
        .enumerate()
        .skip(1)
        .map(|(k, c)| c * Q::from(k as i64))
        .collect()
}

/// The quotient and remainder of `a / b` (`b` not zero).
fn div_rem(a: &[Q], b: &[Q]) -> (Vec<Q>, Vec<Q>) {
    let b = trim(b.to_vec());
    let mut r = trim(a.to_vec());
    let lead = b.last().cloned().unwrap_or(Q::ONE);
    let mut q = vec![Q::ZERO; r.len().saturating_sub(b.len()) + 1];
    while r.len() >= b.len() && !r.is_empty() {
        let shift = r.len() - b.len();
        let f = r.last().cloned().unwrap_or_default() / &lead;
        for (k, bk) in b.iter().enumerate() {
            r[shift + k] -= &f * bk;
        }
        q[shift] = f;
        r.pop();
        r = trim(r);
    }
    (trim(q), r)
}

fn divide(a: &[Q], b: &[Q]) -> Vec<Q> {
    div_rem(a, b).0
}

/// The greatest common divisor of two polynomials (Euclid's algorithm, exactly).
fn gcd(a: &[Q], b: &[Q]) -> Vec<Q> {
    let (mut a, mut b) = (trim(a.to_vec()), trim(b.to_vec()));
    while !b.is_empty() {
        let r = div_rem(&a, &b).1;
        a = b;
        b = r;
    }
    a
}

/// A rational of small denominator within the root's bracket that is a root of `p` exactly:
/// the convergents of the continued fraction of `r`, denominators up to 10^12.
fn snap(p: &[Q], r: &Q) -> Option<Q> {
    use dashu_int::IBig;
    let (mut h0, mut h1) = (IBig::ZERO, IBig::ONE);
    let (mut k0, mut k1) = (IBig::ONE, IBig::ZERO);
    let mut x = r.clone();
    let limit = IBig::from(10u8).pow(12);
    for _ in 0..64 {
        let a = x.floor();
        let (h, k) = (&a * &h1 + &h0, &a * &k1 + &k0);
        if k > limit {
            return None;
        }
        let candidate = Q::from_parts_signed(h.clone(), k.clone());
        if horner(p, &candidate).is_zero() {
            return Some(candidate);
        }
        (h0, h1, k0, k1) = (h1, h, k1, k);
        let frac = &x - Q::from(a);
        if frac.is_zero() {
            return None;
        }
        x = Q::ONE / frac;
    }
    None
}

/// Exact bisection of `f` on `[lo, hi]` (`f(lo) < 0` when `lo_negative`) to a width of
/// `10^-digits` times the bracket's size (and at least 1e-300 absolute).
fn bisect(f: &impl Fn(&Q) -> Q, mut lo: Q, mut hi: Q, lo_negative: bool, digits: usize) -> Q {
    let size = lo.clone().abs().max(hi.clone().abs()).max(Q::ONE);
    let width = size / Q::from(crate::values::rational::pow10(digits));
    let two = crate::values::rational::int(2);
    for _ in 0..2000 {
        if (&hi - &lo).abs() <= width {
            break;
        }
        let mid = (&lo + &hi) / &two;
        let v = f(&mid);
        if v.is_zero() {
            return mid;
        }
        if v.is_negative() == lo_negative {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    (lo + hi) / two
}

/// A root of a quadratic: exact when rational, else to `digits` significant digits.
#[derive(Clone, Debug, PartialEq)]
pub enum Root {
    Exact(Q),
    Approx(Q),
}

impl Root {
    pub fn value(&self) -> &Q {
        match self {
            Root::Exact(q) | Root::Approx(q) => q,
        }
    }
}

/// Digits kept of an irrational root.
pub const ROOT_DIGITS: usize = 40;

/// The real roots of `a t^2 + b t + c = 0` (`a` and `b` not both 0), in increasing order; a
/// double root once. Exact when the discriminant is a rational square; otherwise the square root
/// to [`ROOT_DIGITS`] digits, each root from the form without cancellation
/// (`q = -(b + sign(b) sqrt(D))/2`, roots `q/a` and `c/q`).
pub fn quadratic_roots(a: &Q, b: &Q, c: &Q) -> Vec<Root> {
    if a.is_zero() {
        if b.is_zero() {
            return Vec::new();
        }
        return vec![Root::Exact(-c / b)];
    }
    let four = crate::values::rational::int(4);
    let d = b * b - four * a * c;
    if d.is_negative() {
        return Vec::new();
    }
    let two = crate::values::rational::int(2);
    if d.is_zero() {
        return vec![Root::Exact(-b / (two * a))];
    }
    let (root, exact) = match crate::values::rational::sqrt_exact(&d) {
        Some(r) => (r, true),
        None => (crate::values::quantity::sqrt(&d, ROOT_DIGITS + 5), false),
    };
    let q = if b.is_negative() {
        -(b - &root) / &two
    } else {
        -(b + &root) / &two
    };
    let wrap = |x: Q| {
        if exact {
            Root::Exact(x)
        } else {
            Root::Approx(x)
        }
    };
    let mut roots = vec![wrap(&q / a)];
    if !q.is_zero() {
        roots.push(wrap(c / &q));
    }
    roots.sort_by(|x, y| x.value().cmp(y.value()));
    roots
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::values::rational::{int, ratio};

    #[test]
    fn products_of_unknowns() {
        let x = Poly::var(0);
        let y = Poly::var(1);
        let xy = x.mul(&y).unwrap();
        assert_eq!(xy.quad.get(&(0, 1)), Some(&int(1)));
        assert!(xy.mul(&x).is_err());
        let p = x.add(&Poly::constant(int(2))).mul(&x).unwrap(); // x^2 + 2x
        assert_eq!(p.eval(&[int(3)]), int(15));
    }

    #[test]
    fn gaussian_elimination_keeps_a_free_parameter() {
        // x + y = 2, 2x + 2y = 4 (dependent): x = 2 - t, y = t.
        let e1 = Poly::var(0).add(&Poly::var(1)).sub(&Poly::constant(int(2)));
        let e2 = e1.scale(&int(2));
        let s = solve_linear(&[&e1, &e2], 2, &[]).unwrap();
        assert_eq!(s.basis.len(), 1);
        assert_eq!(s.x0, vec![int(2), int(0)]);
        assert_eq!(s.basis[0], vec![int(-1), int(1)]);
        // x + y = 3 contradicts x + y = 2.
        let e3 = Poly::var(0).add(&Poly::var(1)).sub(&Poly::constant(int(3)));
        assert_eq!(
            solve_linear(&[&e1, &e3], 2, &[]),
            Err(Contradiction { equation: 1 })
        );
    }

    #[test]
    fn roots_are_exact_when_rational() {
        // (t - 1/2)(t + 3) = t^2 + 5/2 t - 3/2.
        let r = quadratic_roots(&int(1), &ratio(5, 2), &ratio(-3, 2));
        assert_eq!(r, vec![Root::Exact(int(-3)), Root::Exact(ratio(1, 2))]);
        // t^2 - 2: +-sqrt(2) to 40 digits.
        let r = quadratic_roots(&int(1), &int(0), &int(-2));
        let Root::Approx(q) = &r[1] else {
            panic!("sqrt 2 is irrational")
        };
        let sq = q * q - int(2);
        assert!(sq.abs() < crate::values::rational::ratio(1, 1_000_000_000_000_000_000));
        assert!(quadratic_roots(&int(1), &int(0), &int(1)).is_empty());
    }
}
