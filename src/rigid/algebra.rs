//! Small exact linear algebra for rigid bodies: vectors of 2 or 3 rational components, the
//! cross products of the plane (`omega x r = omega (-r_y, r_x)`, `r x p = r_x p_y - r_y p_x`) and
//! of space, and square rational matrices (the inertia tensors, their inverses by Gauss-Jordan
//! elimination, `K = J M^-1 J^T`).

use num_traits::Zero;

use crate::values::rational::Q;

/// A square (or any) rational matrix, row by row.
pub type Mat = Vec<Vec<Q>>;

/// `a.b`.
pub fn dot(a: &[Q], b: &[Q]) -> Q {
    a.iter().zip(b).fold(Q::ZERO, |s, (x, y)| s + x * y)
}

/// `a + b`.
pub fn add(a: &[Q], b: &[Q]) -> Vec<Q> {
    a.iter().zip(b).map(|(x, y)| x + y).collect()
}

/// `a - b`.
pub fn sub(a: &[Q], b: &[Q]) -> Vec<Q> {
    a.iter().zip(b).map(|(x, y)| x - y).collect()
}

/// `s a`.
pub fn scale(a: &[Q], s: &Q) -> Vec<Q> {
    a.iter().map(|x| x * s).collect()
}

/// `-a`.
pub fn neg(a: &[Q]) -> Vec<Q> {
    a.iter().map(|x| -x).collect()
}

/// Whether every component is 0.
pub fn is_zero(a: &[Q]) -> bool {
    a.iter().all(Zero::is_zero)
}

/// The number of rotational degrees of freedom in `dim` dimensions: 1 in the plane (a spin about
/// z), 3 in space.
pub fn rot_dim(dim: usize) -> usize {
    if dim == 2 { 1 } else { 3 }
}

/// `omega x r`: in the plane `omega` is the one component about z, and the result
/// `omega (-r_y, r_x)`; in space the cross product.
pub fn spin_at(omega: &[Q], r: &[Q]) -> Vec<Q> {
    match r.len() {
        2 => vec![-(&omega[0] * &r[1]), &omega[0] * &r[0]],
        _ => cross3(omega, r),
    }
}

/// `r x p`, the moment of `p` at lever `r`: in the plane its z component (one number), in
/// space the vector.
pub fn moment(r: &[Q], p: &[Q]) -> Vec<Q> {
    match r.len() {
        2 => vec![&r[0] * &p[1] - &r[1] * &p[0]],
        _ => cross3(r, p),
    }
}

fn cross3(a: &[Q], b: &[Q]) -> Vec<Q> {
    vec![
        &a[1] * &b[2] - &a[2] * &b[1],
        &a[2] * &b[0] - &a[0] * &b[2],
        &a[0] * &b[1] - &a[1] * &b[0],
    ]
}

/// The `dim x rot` matrix `W(r)` with `W(r) omega = omega x r` (the velocity of a point at `r`
/// from the spin): in the plane the column `(-r_y, r_x)`, in space `-[r]x`.
pub fn spin_matrix(r: &[Q]) -> Mat {
    match r.len() {
        2 => vec![vec![-r[1].clone()], vec![r[0].clone()]],
        _ => vec![
            vec![Q::ZERO, r[2].clone(), -r[1].clone()],
            vec![-r[2].clone(), Q::ZERO, r[0].clone()],
            vec![r[1].clone(), -r[0].clone(), Q::ZERO],
        ],
    }
}

/// The `n x n` identity times `s`.
pub fn diag(n: usize, s: &Q) -> Mat {
    (0..n)
        .map(|i| {
            (0..n)
                .map(|j| if i == j { s.clone() } else { Q::ZERO })
                .collect()
        })
        .collect()
}

/// `A B`.
pub fn mul(a: &Mat, b: &Mat) -> Mat {
    let cols = b.first().map_or(0, Vec::len);
    a.iter()
        .map(|row| {
            (0..cols)
                .map(|j| {
                    row.iter()
                        .zip(b)
                        .fold(Q::ZERO, |s, (x, brow)| s + x * &brow[j])
                })
                .collect()
        })
        .collect()
}

/// `A x`.
pub fn apply(a: &Mat, x: &[Q]) -> Vec<Q> {
    a.iter().map(|row| dot(row, x)).collect()
}

/// `A^T`.
pub fn transpose(a: &Mat) -> Mat {
    let cols = a.first().map_or(0, Vec::len);
    (0..cols)
        .map(|j| a.iter().map(|row| row[j].clone()).collect())
        .collect()
}

/// `A + B`.
pub fn add_mat(a: &Mat, b: &Mat) -> Mat {
    a.iter().zip(b).map(|(x, y)| add(x, y)).collect()
}

/// `A^-1` by Gauss-Jordan elimination in exact arithmetic; `None` when `A` is singular.
pub fn inverse(a: &Mat) -> Option<Mat> {
    let n = a.len();
    let mut m: Mat = a
        .iter()
        .enumerate()
        .map(|(i, row)| {
            let mut r = row.clone();
            r.extend((0..n).map(|j| if i == j { Q::ONE } else { Q::ZERO }));
            r
        })
        .collect();
    for col in 0..n {
        let pivot = (col..n).find(|&r| !m[r][col].is_zero())?;
        m.swap(col, pivot);
        let p = m[col][col].clone();
        for x in m[col].iter_mut() {
            *x /= &p;
        }
        for r in 0..n {
            if r != col && !m[r][col].is_zero() {
                let f = m[r][col].clone();
                let pivot_row = m[col].clone();
                for (x, y) in m[r].iter_mut().zip(&pivot_row) {
                    *x -= &f * y;
                }
            }
        }
    }
    Some(m.into_iter().map(|row| row[n..].to_vec()).collect())
}

/// Whether a symmetric matrix is positive definite (Sylvester's criterion: every leading
/// principal minor > 0), exactly.
pub fn positive_definite(a: &Mat) -> bool {
    (1..=a.len()).all(|k| {
        let minor: Mat = a[..k].iter().map(|r| r[..k].to_vec()).collect();
        determinant(&minor) > Q::ZERO
    })
}

/// The determinant, by elimination.
pub fn determinant(a: &Mat) -> Q {
    let n = a.len();
    let mut m = a.clone();
    let mut det = Q::ONE;
    for col in 0..n {
        let Some(pivot) = (col..n).find(|&r| !m[r][col].is_zero()) else {
            return Q::ZERO;
        };
        if pivot != col {
            m.swap(col, pivot);
            det = -det;
        }
        let p = m[col][col].clone();
        det *= &p;
        for r in col + 1..n {
            let f = &m[r][col] / &p;
            let pivot_row = m[col].clone();
            for (x, y) in m[r].iter_mut().zip(&pivot_row) {
                *x -= &f * y;
            }
        }
    }
    det
}

/// Whether a matrix equals its transpose.
pub fn symmetric(a: &Mat) -> bool {
    a.iter()
        .enumerate()
        .all(|(i, row)| row.iter().enumerate().all(|(j, x)| *x == a[j][i]))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::values::rational::{int, ratio};

    fn m(rows: &[&[i64]]) -> Mat {
        rows.iter()
            .map(|r| r.iter().map(|x| int(*x)).collect())
            .collect()
    }

    #[test]
    fn inverse_and_determinant() {
        let a = m(&[&[2, 1, 0], &[1, 3, 1], &[0, 1, 4]]);
        // det = 2 (12 - 1) - 1 (4 - 0) = 18.
        assert_eq!(determinant(&a), int(18));
        let inv = inverse(&a).unwrap();
        assert_eq!(mul(&a, &inv), diag(3, &Q::ONE));
        assert_eq!(inv[0][0], ratio(11, 18));
        assert!(positive_definite(&a));
        assert!(!positive_definite(&m(&[&[1, 2], &[2, 1]])));
        assert!(inverse(&m(&[&[1, 2], &[2, 4]])).is_none());
    }

    #[test]
    fn cross_products_of_the_plane_and_space() {
        // omega = 2 about z at r = (1, 0): velocity (0, 2); the same in space.
        assert_eq!(spin_at(&[int(2)], &[int(1), int(0)]), vec![int(0), int(2)]);
        assert_eq!(
            spin_at(&[int(0), int(0), int(2)], &[int(1), int(0), int(0)]),
            vec![int(0), int(2), int(0)]
        );
        // W(r) omega = omega x r.
        let r = [int(1), int(-2), int(3)];
        let w = [int(4), int(5), int(-6)];
        assert_eq!(apply(&spin_matrix(&r), &w), spin_at(&w, &r));
        assert_eq!(moment(&[int(0), int(1)], &[int(1), int(0)]), vec![int(-1)]);
    }
}
