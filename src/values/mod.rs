//! Values, the bottom layer: exact rationals (`Q`), numbers as typed (with `Given<T>` for `?`),
//! units with exact factors to SI (and derived ones: impulse, energy, spring constant), exact and approximate scalars (`Quantity`), double-double
//! arithmetic, atomic file output and the width text fits. Nothing here knows any physics.

pub mod case_units;
pub mod compensated;
pub mod derived;
pub mod heights;
pub mod measure;
pub mod number;
#[cfg(feature = "cli")]
pub mod output;
pub mod quantity;
pub mod rational;
pub mod terminal;
#[cfg(feature = "cli")]
pub mod uncached;
pub mod unit_table;
pub mod units;
