//! Exact rationals: the one type every exact value of collide is held in.
//!
//! `Q` is dashu-ratio's `RBig`, always in lowest terms. It replaced num-rational's `BigRational`
//! because every operation on a rational reduces it by a gcd, and num-bigint's gcd is Stein's
//! binary algorithm (a bit a step), where dashu-int's is Lehmer's (a word a step): on 1,000-digit
//! operands the same solve is about 11 times faster (`benches/exact.rs`).

pub use dashu_int::{IBig, UBig};
pub use dashu_ratio::RBig as Q;

/// The integer `n` as a rational.
pub fn int(n: i64) -> Q {
    Q::from(n)
}

/// `n / d` in lowest terms (`d != 0`).
pub fn ratio(n: i64, d: i64) -> Q {
    Q::from_parts_signed(IBig::from(n), IBig::from(d))
}

/// `1/2`, of kinetic energies `1/2 (m v) v`.
pub fn half() -> Q {
    ratio(1, 2)
}

/// `10^k`.
pub fn pow10(k: usize) -> UBig {
    UBig::from(10u8).pow(k)
}

/// The nearest binary64 to an exact value, ties to even (`None` outside the binary64 range).
pub fn to_f64(q: &Q) -> Option<f64> {
    Some(q.to_f64().value()).filter(|x| x.is_finite())
}

/// The exact value of a binary64 (0 for a non-finite one, which no caller passes on purpose).
pub fn from_f64(x: f64) -> Q {
    Q::try_from(x).unwrap_or_default()
}

/// The binary64 components of `v` scaled by one power of two (exact) so that the largest is
/// about 1: the direction of `v` in binary64 whatever its size. Angles need only directions,
/// and a vector of 1e-170 or 1e155 has products (dot, cross, hypot) that underflow or overflow
/// in binary64 unscaled. A component below 2^-1074 of the largest rounds to 0; the zero vector
/// stays zero.
pub fn direction(v: &[Q]) -> Vec<f64> {
    scaled(v).iter().map(|x| to_f64(x).unwrap_or(0.0)).collect()
}

/// `v` times the power of two that makes its largest component about 1, exactly (see
/// [`direction`]); the zero vector as it is.
pub fn scaled(v: &[Q]) -> Vec<Q> {
    use dashu_int::ops::{BitTest, UnsignedAbs};
    // log2 of a rational to within one: bits of the numerator less bits of the denominator.
    let log2 = |q: &Q| -> Option<isize> {
        (q.numerator() != &IBig::ZERO).then(|| {
            q.numerator().unsigned_abs().bit_len() as isize - q.denominator().bit_len() as isize
        })
    };
    let Some(k) = v.iter().filter_map(log2).max() else {
        return v.to_vec();
    };
    let scale = if k >= 0 {
        Q::from_parts(IBig::ONE, UBig::ONE << k as usize)
    } else {
        Q::from(IBig::ONE << (-k) as usize)
    };
    v.iter().map(|x| x * &scale).collect()
}

/// `2^k`, exactly (`k` of either sign).
pub fn pow2(k: isize) -> Q {
    if k >= 0 {
        Q::from(IBig::ONE << k as usize)
    } else {
        Q::from_parts(IBig::ONE, UBig::ONE << (-k) as usize)
    }
}

/// `log2 |q|` to within one (bits of the numerator less bits of the denominator); `None` for 0.
pub fn log2(q: &Q) -> Option<isize> {
    use dashu_int::ops::{BitTest, UnsignedAbs};
    (q.numerator() != &IBig::ZERO).then(|| {
        q.numerator().unsigned_abs().bit_len() as isize - q.denominator().bit_len() as isize
    })
}

/// `sqrt(q)` for `q >= 0` of any size, within an ulp: `q` is scaled exactly by an even power of
/// two, `4^-k`, to about 1, rounded once to binary64, given its correctly rounded root, and
/// scaled back by `2^k` (exactly). The root of `q` rounded to binary64 first is wrong once `q`
/// leaves binary64's range though its root fits (`2 E / mu = 6e310`: 2^1023 instead of
/// 2.4e155; 4e-600: 0 instead of 2e-300). The result is a binary64 times a power of two: not
/// itself in binary64's range when the root is not. Negative `q`: 0.
pub fn sqrt_binary64(q: &Q) -> Q {
    let Some(bits) = log2(q).filter(|_| q > &Q::ZERO) else {
        return Q::ZERO;
    };
    let k = bits.div_euclid(2);
    let scaled = q * pow2(-2 * k);
    let root = to_f64(&scaled).map_or(0.0, f64::sqrt);
    from_f64(root) * pow2(k)
}

/// `sqrt(q)` when it is rational (`q >= 0` in lowest terms with a square numerator and
/// denominator), else `None`.
pub fn sqrt_exact(q: &Q) -> Option<Q> {
    use dashu_int::ops::{SquareRoot, UnsignedAbs};
    let root = |n: &UBig| Some(n.sqrt()).filter(|r| &(r * r) == n);
    if q.numerator() < &IBig::ZERO {
        return None;
    }
    let n = root(&q.numerator().unsigned_abs())?;
    let d = root(q.denominator())?;
    Some(Q::from_parts(n.into(), d))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn conversions_are_exact_and_correctly_rounded() {
        assert_eq!(ratio(6, -4), Q::from_parts(IBig::from(-3), UBig::from(2u8)));
        assert_eq!(
            from_f64(0.1),
            Q::from_parts(IBig::from(3602879701896397i64), UBig::ONE << 55)
        );
        assert_eq!(to_f64(&ratio(1, 10)), Some(0.1));
        // 2^-1074 is the smallest subnormal; 2^-1075 is a tie and rounds to even (0).
        let tiny = Q::from_parts(IBig::ONE, UBig::ONE << 1074);
        assert_eq!(to_f64(&tiny), Some(f64::from_bits(1)));
        assert_eq!(to_f64(&(tiny / int(2))), Some(0.0));
        assert_eq!(to_f64(&Q::from(IBig::from(10u8).pow(309))), None);
        assert_eq!(pow10(3), UBig::from(1000u16));
    }

    #[test]
    fn directions_are_scaled_by_a_power_of_two() {
        let big = Q::from(IBig::from(10u8).pow(400));
        let tiny = Q::from_parts(IBig::ONE, UBig::from(10u8).pow(400));
        for s in [big, tiny, int(1), ratio(-3, 7)] {
            let v = [&s * int(3), &s * int(-4)];
            // Exactly v times a power of two: the ratio of the components is kept exactly.
            let q = scaled(&v);
            assert_eq!(&q[0] / &q[1], ratio(-3, 4));
            assert_eq!(&q[0] / &v[0], &q[1] / &v[1]);
            let d = direction(&v);
            assert!(d[0].abs().max(d[1].abs()) >= 0.5 && d[0].abs().max(d[1].abs()) <= 8.0);
        }
        assert_eq!(direction(&[int(0), int(0)]), vec![0.0, 0.0]);
    }

    #[test]
    fn square_roots_are_exact_or_none() {
        assert_eq!(sqrt_exact(&ratio(9, 4)), Some(ratio(3, 2)));
        assert_eq!(sqrt_exact(&int(0)), Some(int(0)));
        assert_eq!(sqrt_exact(&ratio(4, 100)), Some(ratio(1, 5)));
        assert_eq!(sqrt_exact(&int(2)), None);
        assert_eq!(sqrt_exact(&ratio(1, 8)), None);
        assert_eq!(sqrt_exact(&int(-4)), None);
        // 2 g h with g = 9.80665, h = 2: 39.2266, not a square.
        assert_eq!(sqrt_exact(&ratio(392266, 10000)), None);
        let big = Q::from(pow10(1000) + UBig::ONE);
        assert_eq!(sqrt_exact(&(&big * &big)), Some(big));
    }
}
