//! `collide`: collisions on a rail, in the plane and in space, solved where the momentum line
//! meets the energy ellipse, with an explicit inertia tensor, in the notation of W. G. Harter,
//! *Classical Mechanics with a BANG!*, Unit 1, Lecture 1.
//!
//! The modules are layers; each imports only from the layers above it in this list:
//!
//! 1. `values`: rationals, numbers as typed, units, quantities, compensated sums, output, width;
//! 2. `line`, the rail: two-body physics (`inertia`, `restitution`, `collision`, `ellipse`,
//!    `changes`, `separation`, `wall`) and what the user asked of it (`case`, `problem`,
//!    `unknowns`, `frame`);
//! 3. the plane and space (`space`: vectors, lines of impact, N bodies), built on `line`; rigid
//!    bodies at impact (`rigid`);
//! 4. how it is computed: `solver` (the `Solver` trait, `binary64`, `exact`);
//! 5. computations beyond one solve: `accuracy`, `expect`, `table`, `track`, `contact` (which
//!    runs `track` as its impulse model);
//! 6. what is printed: `report`, `plot`, `view` (the web page's requests and answers);
//! 7. files: `scene`.
//!
//! 8. the command line (feature `cli`): `cli` (its flags), `usage` (its usage errors) and
//!    `commands` (one per subcommand: parse, solve, render), under the thin binary `src/main.rs`
//!    and linked by the Python module (`python/`) too, so that both run one build of them.
//!
//! The feature `cli`
//! (default) adds what only the command line needs (`output`, `accuracy`, `contact`, `expect`,
//! `table`, `plot`, `scene` and their crates); without it the library is the part that `wasm/`
//! compiles to WebAssembly for `collide view`.
//!
//! ```
//! use collide::line::{case::{Case, parse_masses, parse_velocities}, inertia::InertiaTensor};
//! let [m1, m2] = parse_masses("4,1").unwrap();
//! let case = Case::new(InertiaTensor::diagonal(&m1, &m2).unwrap(),
//!                      parse_velocities("60,10").unwrap(), "elastic".parse().unwrap());
//! let fin = case.collision.v_fin();
//! assert_eq!((fin.x, fin.y), (40.0, 90.0)); // lecture Fig. 1.3
//! ```

// 1. values
pub mod values;

// 2-3. the rail: two-body physics and what the user asked of it
pub mod line;

// 3b. the plane and space, rigid bodies
pub mod rigid;
pub mod space;

// 4. how it is computed
pub mod solver;

// 5. computations beyond one solve
#[cfg(feature = "cli")]
pub mod accuracy;
#[cfg(feature = "cli")]
pub mod contact;
#[cfg(feature = "cli")]
pub mod expect;
#[cfg(feature = "cli")]
pub mod table;
pub mod track;

// 6. what is printed
#[cfg(feature = "cli")]
pub mod plot;
pub mod report;
pub mod view;

// 7. files
#[cfg(feature = "cli")]
pub mod scene;

// 8. the command line: its flags, usage errors and commands (written as the binary's code, naming
// the library `collide::`, hence the alias)
#[cfg(feature = "cli")]
extern crate self as collide;
#[cfg(feature = "cli")]
pub mod cli;
#[cfg(feature = "cli")]
pub mod commands;
#[cfg(feature = "cli")]
pub mod usage;
