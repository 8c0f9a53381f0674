//! Collisions in the plane and in space (`../shared/physics.md` section 7): N bodies in d
//! dimensions, one state vector `V` in R^(dN), `M = diag(m1 I_d, ..., mN I_d)`. A smooth
//! contact between bodies 1 and 2 with line of impact `n` changes `V` only along `M^-1 G`,
//! `G = (n, -n, 0, ...)`: FIN lies on the line `IN + s M^-1 G`, which meets the energy
//! ellipsoid at IN and at the elastic FIN, the lecture's construction in R^(dN).
//!
//! - `angle`: angles and compass bearings;
//! - `algebra`: the laws as polynomials in the unknowns, solved exactly;
//! - `solve`: the laws of a problem and its solutions;
//! - `lcp`, `contacts`, `balls`: several contacts at once (Newton's law as a linear
//!   complementarity problem, solved by Lemke's method), and touching balls as typed.

pub mod algebra;
pub mod angle;
pub mod balls;
pub mod contacts;
pub mod impact;
pub mod lcp;
pub mod outcome;
pub mod pose;
pub mod solve;
pub mod typed;
