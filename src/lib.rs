//! `collide`: two-body collisions on a rail, solved where the momentum line meets the energy
//! ellipse, with an explicit inertia tensor, in the notation of W. G. Harter, *Classical Mechanics
//! with a BANG!*, Unit 1, Lecture 1.
//!
//! ```
//! use collide::{case::{Case, parse_masses, parse_velocities}, inertia::InertiaTensor};
//! let [m1, m2] = parse_masses("4,1").unwrap();
//! let case = Case::new(InertiaTensor::diagonal(&m1, &m2).unwrap(),
//!                      parse_velocities("60,10").unwrap(), "elastic".parse().unwrap());
//! let fin = case.collision.v_fin();
//! assert_eq!((fin.x, fin.y), (40.0, 90.0)); // lecture Fig. 1.3
//! ```

pub mod accuracy;
pub mod app;
pub mod batch;
pub mod case;
pub mod cli;
pub mod collision;
pub mod compensated;
pub mod ellipse;
pub mod exact;
pub mod expect;
pub mod frame;
pub mod inertia;
pub mod number;
pub mod plot;
pub mod problem;
pub mod quantity;
pub mod report;
pub mod restitution;
pub mod rows;
pub mod scene;
pub mod solver;
pub mod sweep;
pub mod track;
pub mod units;
pub mod unknowns;
