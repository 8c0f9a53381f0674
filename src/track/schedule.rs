//! The scheduler of the track engine: the next time of each contact slot, earliest first, ties
//! to the leftmost slot. Few slots are scanned (cheaper than a heap), many kept in a binary heap
//! with versions (a rescheduled slot's old entry is skipped); both pick the same event.

use std::cmp::Reverse;
use std::collections::BinaryHeap;

/// A time ordered totally, for the heap.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct Time(f64);

impl Eq for Time {}
impl PartialOrd for Time {
    fn partial_cmp(&self, o: &Self) -> Option<std::cmp::Ordering> {
        Some(self.cmp(o))
    }
}
impl Ord for Time {
    fn cmp(&self, o: &Self) -> std::cmp::Ordering {
        self.0.total_cmp(&o.0)
    }
}

/// The next time of each slot (0 = left wall, i + 1 = pair (i, i + 1), n = right wall), with
/// the earliest `(time, slot)` taken first.
pub(super) enum Slots {
    Few(Vec<Option<f64>>),
    Many {
        version: Vec<u64>,
        heap: BinaryHeap<Reverse<(Time, usize, u64)>>,
    },
}

/// Up to this many slots are scanned; more go in a heap.
const FEW: usize = 16;

impl Slots {
    pub(super) fn new(slots: usize) -> Slots {
        if slots <= FEW {
            Slots::Few(vec![None; slots])
        } else {
            Slots::Many {
                version: vec![0; slots],
                heap: BinaryHeap::new(),
            }
        }
    }

    pub(super) fn set(&mut self, slot: usize, t: Option<f64>) {
        match self {
            Slots::Few(times) => times[slot] = t,
            Slots::Many { version, heap } => {
                version[slot] += 1;
                if let Some(t) = t {
                    heap.push(Reverse((Time(t), slot, version[slot])));
                }
            }
        }
    }

    pub(super) fn pop(&mut self) -> Option<(f64, usize)> {
        match self {
            Slots::Few(times) => {
                let mut best: Option<(f64, usize)> = None;
                for (slot, t) in times.iter().enumerate() {
                    if let Some(t) = *t
                        && best.is_none_or(|(b, _)| t.total_cmp(&b).is_lt())
                    {
                        best = Some((t, slot));
                    }
                }
                if let Some((_, slot)) = best {
                    times[slot] = None;
                }
                best
            }
            Slots::Many { version, heap } => {
                while let Some(Reverse((Time(t), slot, v))) = heap.pop() {
                    if v == version[slot] {
                        return Some((t, slot));
                    }
                }
                None
            }
        }
    }
}
