//! Which body is on the left (issue 27 §2). On a rail with no positions only the velocities say
//! where the bodies are: two bodies meet iff their velocities differ, and the one moving faster
//! in `+x` is the one behind, on the left, whichever was typed first. The collision itself does
//! not depend on it: momentum and `f2 - f1 = e (v1 - v2)` are the same equations with the
//! labels swapped. After a separation (bodies that start together) the piece moving faster in
//! `+x` ends up on the right.

/// Where the bodies are, as the velocities tell it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Order {
    /// Body 1 on the left: `V1 > V2` before a collision, `f1 < f2` after a separation.
    Body1Left,
    /// Body 2 on the left: `V1 < V2` before (body 2 catches body 1), `f1 > f2` after.
    Body2Left,
    /// Equal velocities: the bodies never meet (or, after a separation, never part).
    Together,
}

impl Order {
    /// Before a collision: the body faster in `+x` is behind, on the left.
    pub fn before<T: PartialOrd>(v1: &T, v2: &T) -> Order {
        match v1.partial_cmp(v2) {
            Some(std::cmp::Ordering::Greater) => Order::Body1Left,
            Some(std::cmp::Ordering::Less) => Order::Body2Left,
            _ => Order::Together,
        }
    }

    /// After a separation from a common point: the piece faster in `+x` ends up on the right.
    pub fn after<T: PartialOrd>(f1: &T, f2: &T) -> Order {
        Order::before(f2, f1)
    }

    /// Whether the bodies meet (or part): their velocities differ.
    pub fn meet(self) -> bool {
        self != Order::Together
    }

    /// `Some(2)` when body 2 is the one on the left (the JSON key `left`), `None` otherwise:
    /// body 1 on the left is the order a problem is usually typed in, and its output is unchanged.
    pub fn left_when_body_2(self) -> Option<u8> {
        (self == Order::Body2Left).then_some(2)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_faster_body_in_plus_x_is_behind() {
        // Case A (60, 10): the SUV behind the VW. Typed the other way round, (10, 60): the VW
        // is behind and catches the SUV.
        assert_eq!(Order::before(&60, &10), Order::Body1Left);
        assert_eq!(Order::before(&10, &60), Order::Body2Left);
        assert_eq!(Order::before(&-4.0, &3.0), Order::Body2Left);
        assert_eq!(Order::before(&5, &5), Order::Together);
        assert!(!Order::before(&f64::NAN, &1.0).meet());
        // A rifle fired from rest: bullet +550, rifle -1.375: the bullet ends up on the right.
        assert_eq!(Order::after(&550.0, &-1.375), Order::Body2Left);
        assert_eq!(Order::after(&-0.5, &10.0), Order::Body1Left);
        assert_eq!(Order::Body2Left.left_when_body_2(), Some(2));
        assert_eq!(Order::Body1Left.left_when_body_2(), None);
    }
}
