//! Exact Gaussian elimination (Gauss-Jordan, to reduced row echelon form) of a linear system
//! `A x = b` in rationals: the chain of stages solved as one system (issue 42 §5). Every step is
//! exact (`Q`), so a rank is a rank and a contradiction is a contradiction, never a rounding.

use crate::values::rational::Q;

/// Why a system has no single solution.
#[derive(Clone, Debug, PartialEq)]
pub enum Unsolvable {
    /// Fewer independent equations (`rank`) than unknowns: the unknowns (by index) that the
    /// equations leave free or tied to a free one.
    Underdetermined { rank: usize, open: Vec<usize> },
    /// Equation `row` (by index) is a combination of the others with another right-hand side:
    /// `0 = residual`.
    Contradiction { row: usize, residual: Q },
}

/// Solves `rows` (each the coefficients of the `n` unknowns, then the right-hand side) exactly.
/// More equations than unknowns are allowed: the extra ones must hold.
pub fn solve(rows: &[Vec<Q>], n: usize) -> Result<Vec<Q>, Unsolvable> {
    let mut a: Vec<Vec<Q>> = rows.to_vec();
    // The original index of each row, to name the one that contradicts.
    let mut origin: Vec<usize> = (0..a.len()).collect();
    let mut pivots: Vec<usize> = Vec::new();
    let mut r = 0;
    for c in 0..n {
        let Some(p) = (r..a.len()).find(|&i| !a[i][c].is_zero()) else {
            continue;
        };
        a.swap(r, p);
        origin.swap(r, p);
        let inv = Q::ONE / &a[r][c];
        for x in a[r].iter_mut() {
            *x = &*x * &inv;
        }
        let pivot = a[r].clone();
        for (i, row) in a.iter_mut().enumerate() {
            if i == r || row[c].is_zero() {
                continue;
            }
            let f = row[c].clone();
            for (x, y) in row.iter_mut().zip(&pivot) {
                *x = &*x - &f * y;
            }
        }
        pivots.push(c);
        r += 1;
    }
    if let Some(i) = (r..a.len()).find(|&i| !a[i][n].is_zero()) {
        return Err(Unsolvable::Contradiction {
            row: origin[i],
            residual: a[i][n].clone(),
        });
    }
    if r < n {
        // A pivot's unknown is fixed when its row has no free unknown in it.
        let free: Vec<usize> = (0..n).filter(|c| !pivots.contains(c)).collect();
        let fixed: Vec<usize> = pivots
            .iter()
            .enumerate()
            .filter(|(k, _)| free.iter().all(|&f| a[*k][f].is_zero()))
            .map(|(_, &c)| c)
            .collect();
        let open = (0..n).filter(|c| !fixed.contains(c)).collect();
        return Err(Unsolvable::Underdetermined { rank: r, open });
    }
    let mut x = vec![Q::ZERO; n];
    for (k, &c) in pivots.iter().enumerate() {
        x[c] = a[k][n].clone();
    }
    Ok(x)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::values::rational::{int, ratio};

    fn rows(r: &[&[i64]]) -> Vec<Vec<Q>> {
        r.iter()
            .map(|row| row.iter().map(|&x| int(x)).collect())
            .collect()
    }

    #[test]
    fn a_square_system_solves_exactly() {
        // x + y = 3, x - 2y = 0: y = 1, x = 2; and 3x = 1 needs pivoting past a zero.
        assert_eq!(
            solve(&rows(&[&[1, 1, 3], &[1, -2, 0]]), 2),
            Ok(vec![int(2), int(1)])
        );
        assert_eq!(
            solve(&rows(&[&[0, 1, 5], &[3, 0, 1]]), 2),
            Ok(vec![ratio(1, 3), int(5)])
        );
    }

    #[test]
    fn extra_equations_must_hold_and_free_unknowns_are_named() {
        // x = 1, y = 2, x + y = 3 holds; x + y = 4 misses by 1 (row 2).
        assert!(solve(&rows(&[&[1, 0, 1], &[0, 1, 2], &[1, 1, 3]]), 2).is_ok());
        assert_eq!(
            solve(&rows(&[&[1, 0, 1], &[0, 1, 2], &[1, 1, 4]]), 2),
            Err(Unsolvable::Contradiction {
                row: 2,
                residual: int(1)
            })
        );
        // z = 1 is fixed; x + y = 2 leaves x and y open: rank 2 of 3.
        assert_eq!(
            solve(&rows(&[&[0, 0, 1, 1], &[1, 1, 0, 2]]), 3),
            Err(Unsolvable::Underdetermined {
                rank: 2,
                open: vec![0, 1]
            })
        );
    }
}
