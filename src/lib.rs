//! `collide`: two-body collisions on a rail, solved where the momentum line meets the energy
//! ellipse, with an explicit inertia tensor, in the notation of W. G. Harter, *Classical Mechanics
//! with a BANG!*, Unit 1, Lecture 1.
//!
//! The modules are layers; each imports only from the layers above it in this list:
//!
//! 1. values: `rational`, `number`, `units`, `quantity`, `compensated`, `output`, `terminal`;
//! 2. two-body physics: `inertia`, `restitution`, `collision`, `ellipse`;
//! 3. what the user asked: `case`, `problem`, `unknowns`, `frame`; the plane and space
//!    (`space`) and rigid bodies at impact (`rigid`);
//! 4. how it is computed: `solver` (the `Solver` trait, `binary64`, `exact`);
//! 5. computations beyond one solve: `accuracy`, `expect`, `table`, `track`, `contact` (which
//!    runs `track` as its impulse model);
//! 6. what is printed: `report`, `plot`;
//! 7. files: `scene`.
//!
//! The binary (`src/main.rs`, `src/cli.rs`, `src/commands/`) sits on top.
//!
//! ```
//! use collide::{case::{Case, parse_masses, parse_velocities}, inertia::InertiaTensor};
//! let [m1, m2] = parse_masses("4,1").unwrap();
//! let case = Case::new(InertiaTensor::diagonal(&m1, &m2).unwrap(),
//!                      parse_velocities("60,10").unwrap(), "elastic".parse().unwrap());
//! let fin = case.collision.v_fin();
//! assert_eq!((fin.x, fin.y), (40.0, 90.0)); // lecture Fig. 1.3
//! ```

// 1. values
pub mod compensated;
pub mod number;
pub mod output;
pub mod quantity;
pub mod rational;
pub mod terminal;
pub mod units;

// 2. two-body physics
pub mod changes;
pub mod collision;
pub mod ellipse;
pub mod inertia;
pub mod restitution;
pub mod separation;

// 3. what the user asked
pub mod case;
pub mod frame;
pub mod problem;
pub mod unknowns;
pub mod wall;

// 3b. the plane and space, rigid bodies
pub mod rigid;
pub mod space;

// 4. how it is computed
pub mod solver;

// 5. computations beyond one solve
pub mod accuracy;
pub mod contact;
pub mod expect;
pub mod table;
pub mod track;

// 6. what is printed
pub mod plot;
pub mod report;

// 7. files
pub mod scene;
