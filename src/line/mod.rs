//! The rail (lecture Secs. 1-4): two bodies on a line, the momentum line meeting the energy
//! ellipse with an explicit inertia tensor `M`.
//!
//! Physics first (`inertia`, `restitution`, `collision`, `order`, `ellipse`, `changes`,
//! `separation`, `spring`, `pendulum`, `wall`, `chain`), then what a user asks of it (`case`,
//! `problem`, `unknowns`, `knowns`, `slide`, `frame`). The plane and space (`crate::space`) build on this
//! layer: the normal parts of a smooth contact collide by its 1D rule.

// The physics of two bodies on a rail.
pub mod chain;
pub mod changes;
pub mod collision;
pub mod ellipse;
pub mod inertia;
pub mod order;
pub mod pendulum;
pub mod restitution;
pub mod separation;
pub mod spring;
pub mod wall;

// What the user asked.
pub mod case;
pub mod frame;
pub mod knowns;
pub mod problem;
pub mod slide;
pub mod unknowns;
