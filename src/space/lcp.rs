//! The linear complementarity problem `LCP(q, A)`: find `z` with
//! `y = q + A z >= 0`, `z >= 0`, `z.y = 0`, solved exactly in rationals by Lemke's
//! complementary pivoting method (C. E. Lemke, "Bimatrix equilibrium points and mathematical
//! programming", Management Science 11, 1965; Cottle, Pang & Stone, *The Linear
//! Complementarity Problem*, 1992, section 4.4).
//!
//! Why Lemke's method: several contacts at once (`super::contacts`) give `A = J M^-1 J^T`,
//! symmetric positive semidefinite and singular whenever the contacts outnumber what the bodies
//! can feel (a rack of 15 balls has 30 contacts among 32 velocity components, 2 of them the
//! centre of mass's). Enumerating the `2^m` active sets is fine for three contacts, not for 30;
//! Lemke's method takes a few pivots per contact and, for a positive semidefinite `A`, either
//! solves the problem or proves it has no solution (Cottle, Pang & Stone, theorem 4.4.13). The
//! pivots are exact (rational arithmetic: no tolerance decides a sign) and the ratio test is
//! lexicographic, which keeps a degenerate problem (a symmetric rack has many ties) from
//! cycling (theorem 4.4.2 there). The answer is checked afterwards, every condition exactly
//! (`check`), never assumed.

use num_traits::Signed;

use crate::values::rational::Q;

/// Why Lemke's method stopped without a solution.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum LcpError {
    /// The method left along a ray: for a positive semidefinite matrix, no solution exists.
    #[error(
        "the contact problem has no solution (Lemke's method ended on a ray): the contacts \
         cannot all be kept from closing"
    )]
    Ray,
    #[error("the contact problem took more than {0} pivots (Lemke's method did not end)")]
    Pivots(usize),
}

/// Which condition a candidate answer breaks (`check`), with the index of the first row that
/// breaks it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Broken {
    /// `z_k < 0`.
    Negative(usize),
    /// `y_k = (q + A z)_k < 0`.
    Closing(usize),
    /// `z_k y_k != 0`.
    Complementarity(usize),
}

/// `y = q + A z`.
pub fn slack(a: &[Vec<Q>], q: &[Q], z: &[Q]) -> Vec<Q> {
    a.iter()
        .zip(q)
        .map(|(row, qk)| row.iter().zip(z).fold(qk.clone(), |s, (x, zj)| s + x * zj))
        .collect()
}

/// Checks every condition of `LCP(q, A)` at `z` exactly: `z >= 0`, `y >= 0`, `z_k y_k = 0`.
pub fn check(a: &[Vec<Q>], q: &[Q], z: &[Q]) -> Result<(), Broken> {
    let y = slack(a, q, z);
    for (k, (zk, yk)) in z.iter().zip(&y).enumerate() {
        if zk.is_negative() {
            return Err(Broken::Negative(k));
        }
        if yk.is_negative() {
            return Err(Broken::Closing(k));
        }
        if !(zk * yk).is_zero() {
            return Err(Broken::Complementarity(k));
        }
    }
    Ok(())
}

/// Solves `LCP(q, A)` for `z` by Lemke's method with the covering vector `d = (1, ..., 1)`.
///
/// The tableau holds `w - A z - d z0 = q` (columns: `w_0..w_m`, `z_0..z_m`, `z0`); the basis
/// starts as `w`. When `q >= 0`, `z = 0`. Otherwise `z0` enters at the most negative `q_k`,
/// and each step brings in the complement of the variable that just left, until `z0` leaves.
pub fn lemke(a: &[Vec<Q>], q: &[Q]) -> Result<Vec<Q>, LcpError> {
    let m = q.len();
    if q.iter().all(|x| !x.is_negative()) {
        return Ok(vec![Q::ZERO; m]);
    }
    let cols = 2 * m + 1;
    let art = 2 * m;
    let mut t: Vec<Vec<Q>> = (0..m)
        .map(|i| {
            let mut row = vec![Q::ZERO; cols];
            row[i] = Q::ONE;
            for j in 0..m {
                row[m + j] = -a[i][j].clone();
            }
            row[art] = -Q::ONE;
            row
        })
        .collect();
    let mut rhs: Vec<Q> = q.to_vec();
    let mut basis: Vec<usize> = (0..m).collect();
    // z0 enters where it must be largest, -q_k: the lexicographic minimum of (q_k, row of the
    // basis inverse), all with pivot entry -1.
    let first = (0..m)
        .min_by(|&i, &j| lex_key(&t, &rhs, i, m).cmp(&lex_key(&t, &rhs, j, m)))
        .expect("m > 0: q has a negative entry");
    pivot(&mut t, &mut rhs, first, art);
    let mut entering = basis[first] + m; // w_k left: z_k enters.
    basis[first] = art;
    let limit = 50 * (m + 1) * (m + 1);
    for _ in 0..limit {
        let Some(row) = ratio_test(&t, &rhs, &basis, entering, m, art) else {
            return Err(LcpError::Ray);
        };
        pivot(&mut t, &mut rhs, row, entering);
        let leaving = basis[row];
        basis[row] = entering;
        if leaving == art {
            let mut z = vec![Q::ZERO; m];
            for (i, &b) in basis.iter().enumerate() {
                if (m..2 * m).contains(&b) {
                    z[b - m] = rhs[i].clone();
                }
            }
            return Ok(z);
        }
        entering = if leaving < m {
            leaving + m
        } else {
            leaving - m
        };
    }
    Err(LcpError::Pivots(limit))
}

/// Row `i`'s `(rhs_i, B^-1 row i)`, the key of the lexicographic ratio test (`B^-1` is in the
/// columns of `w`, the starting basis).
fn lex_key(t: &[Vec<Q>], rhs: &[Q], i: usize, m: usize) -> Vec<Q> {
    std::iter::once(rhs[i].clone())
        .chain(t[i][..m].iter().cloned())
        .collect()
}

/// The row that leaves when column `e` enters: among rows with a positive entry in `e`, the
/// lexicographic minimum of `(rhs_i, B^-1 row i) / t[i][e]`; `z0`'s row wins a tie in `rhs`
/// (the method then ends). `None`: no row blocks (a ray).
fn ratio_test(
    t: &[Vec<Q>],
    rhs: &[Q],
    basis: &[usize],
    e: usize,
    m: usize,
    art: usize,
) -> Option<usize> {
    let rows: Vec<usize> = (0..t.len()).filter(|&i| t[i][e].is_positive()).collect();
    let ratio = |i: usize| &rhs[i] / &t[i][e];
    let least = rows.iter().map(|&i| ratio(i)).min()?;
    if let Some(&i) = rows.iter().find(|&&i| basis[i] == art && ratio(i) == least) {
        return Some(i);
    }
    rows.into_iter().min_by(|&i, &j| {
        let key = |r: usize| -> Vec<Q> {
            lex_key(t, rhs, r, m)
                .into_iter()
                .map(|x| x / &t[r][e])
                .collect()
        };
        key(i).cmp(&key(j))
    })
}

/// Gauss-Jordan pivot on `t[r][c]`.
fn pivot(t: &mut [Vec<Q>], rhs: &mut [Q], r: usize, c: usize) {
    let p = t[r][c].clone();
    for x in t[r].iter_mut() {
        *x = &*x / &p;
    }
    rhs[r] = &rhs[r] / &p;
    let (row_r, rhs_r) = (t[r].clone(), rhs[r].clone());
    for i in 0..t.len() {
        if i == r || t[i][c].is_zero() {
            continue;
        }
        let f = t[i][c].clone();
        for (x, y) in t[i].iter_mut().zip(&row_r) {
            if !y.is_zero() {
                *x -= &f * y;
            }
        }
        rhs[i] -= &f * &rhs_r;
    }
}

/// The rank of a matrix, exactly (Gaussian elimination).
pub fn rank(a: &[Vec<Q>]) -> usize {
    let mut a: Vec<Vec<Q>> = a.to_vec();
    let cols = a.first().map_or(0, Vec::len);
    let mut r = 0;
    for c in 0..cols {
        let Some(p) = (r..a.len()).find(|&i| !a[i][c].is_zero()) else {
            continue;
        };
        a.swap(r, p);
        let pivot_row = a[r].clone();
        for row in a.iter_mut().skip(r + 1) {
            if row[c].is_zero() {
                continue;
            }
            let f = &row[c] / &pivot_row[c];
            for (x, y) in row.iter_mut().zip(&pivot_row) {
                *x -= &f * y;
            }
        }
        r += 1;
    }
    r
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::values::rational::{int, ratio};

    fn m(rows: &[&[i64]]) -> Vec<Vec<Q>> {
        rows.iter()
            .map(|r| r.iter().map(|&x| int(x)).collect())
            .collect()
    }

    #[test]
    fn nonnegative_q_needs_nothing() {
        let a = m(&[&[2, -1], &[-1, 2]]);
        assert_eq!(lemke(&a, &[int(0), int(3)]), Ok(vec![int(0), int(0)]));
    }

    #[test]
    fn a_cradle_of_three_by_hand() {
        // Three unit balls in a row, the first at 1: w = (-1, 0), e = 1, q = 2w = (-2, 0),
        // A = [[2, -1], [-1, 2]]. Both active: 2 z1 - z2 = 2, -z1 + 2 z2 = 0, so
        // z = (4/3, 2/3).
        let a = m(&[&[2, -1], &[-1, 2]]);
        let q = [int(-2), int(0)];
        let z = lemke(&a, &q).unwrap();
        assert_eq!(z, vec![ratio(4, 3), ratio(2, 3)]);
        assert_eq!(check(&a, &q, &z), Ok(()));
    }

    #[test]
    fn an_inactive_contact_stays_at_zero() {
        // A = I, q = (-1, 2): z = (1, 0), y = (0, 2).
        let a = m(&[&[1, 0], &[0, 1]]);
        let z = lemke(&a, &[int(-1), int(2)]).unwrap();
        assert_eq!(z, vec![int(1), int(0)]);
    }

    #[test]
    fn a_singular_matrix_is_solved() {
        // A = [[1, 1], [1, 1]] (rank 1), q = (-2, -2): any z >= 0 with z1 + z2 = 2.
        let a = m(&[&[1, 1], &[1, 1]]);
        let q = [int(-2), int(-2)];
        let z = lemke(&a, &q).unwrap();
        assert_eq!(check(&a, &q, &z), Ok(()));
        assert_eq!(&z[0] + &z[1], int(2));
        assert_eq!(rank(&a), 1);
    }

    #[test]
    fn no_solution_is_a_ray() {
        // A = 0, q = (-1): y = -1 whatever z.
        assert_eq!(lemke(&m(&[&[0]]), &[int(-1)]), Err(LcpError::Ray));
    }

    #[test]
    fn check_names_the_broken_condition() {
        let a = m(&[&[1]]);
        assert_eq!(check(&a, &[int(-1)], &[int(-1)]), Err(Broken::Negative(0)));
        assert_eq!(check(&a, &[int(-2)], &[int(1)]), Err(Broken::Closing(0)));
        assert_eq!(
            check(&a, &[int(0)], &[int(1)]),
            Err(Broken::Complementarity(0))
        );
    }
}
