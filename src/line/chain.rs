//! A chain of collisions on one line (issue 27 §4): two-body collisions and bounces off walls,
//! one after another, as in the A-level problems where a ball hits a second one, which rebounds
//! from a wall and meets the first again.
//!
//! Bodies on a line never pass through each other or through a wall, so their order is fixed
//! for good: two objects that collide are neighbours before, and stay neighbours ever after
//! (nothing can come between them). A collision happens when one catches the other: the one
//! faster in +x is on the left, whichever is typed first; a wall is on the side it is typed on. After
//! the last collision two neighbours meet again exactly when the left one moves faster than
//! the right one: `v_left > v_right`, closing at `v_left - v_right` (a wall moves at its own
//! `w`, usually 0). Everything here is exact.

use std::collections::BTreeMap;
use std::fmt;

use crate::values::rational::Q;

/// The side of the line a wall is on.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Side {
    Left,
    Right,
}

/// Something on the line: a body (numbered in order of appearance) or a wall at one end.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Object {
    Body(usize),
    Wall(Side),
}

/// Neighbours on the line: who is on each object's right and left, and since which collision
/// (an index the caller chooses, such as the stage).
#[derive(Clone, Debug, Default)]
pub struct Line {
    right: BTreeMap<Object, (Object, usize)>,
    left: BTreeMap<Object, (Object, usize)>,
}

/// Why two objects cannot collide, given the collisions before.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum OrderError {
    /// `right` is already known to be on the left of `left`: they would pass through each other.
    Reversed { left: Object, right: Object },
    /// `object`'s neighbour on `side` is `neighbour` (since collision `since`), not the other.
    Taken {
        object: Object,
        side: Side,
        neighbour: Object,
        since: usize,
    },
}

/// Two neighbours that approach after the last collision: `left` catches `right`.
#[derive(Clone, Debug, PartialEq)]
pub struct Meeting {
    pub left: Object,
    pub right: Object,
    /// `v_left - v_right > 0`.
    pub closing: Q,
}

impl Line {
    /// Whether `a` is known to be the left neighbour of `b` (they met before).
    pub fn left_of(&self, a: Object, b: Object) -> bool {
        self.right.get(&a).map(|n| n.0) == Some(b)
    }

    /// Records that `left` (on the left) and `right` collide at collision `at`: they must be
    /// neighbours already, or each free on that side and not known in the other order.
    pub fn collide(&mut self, left: Object, right: Object, at: usize) -> Result<(), OrderError> {
        if self.right.get(&left).map(|n| n.0) == Some(right) {
            return Ok(());
        }
        for (object, side, map) in [
            (left, Side::Right, &self.right),
            (right, Side::Left, &self.left),
        ] {
            if let Some(&(neighbour, since)) = map.get(&object) {
                return Err(OrderError::Taken {
                    object,
                    side,
                    neighbour,
                    since,
                });
            }
        }
        // Both are free on the facing side; `right` must not already be on the left of `left`
        // (walking right from `right` reaches `left`): they would pass through each other.
        if self.rightward(right).contains(&left) {
            return Err(OrderError::Reversed { left, right });
        }
        self.right.insert(left, (right, at));
        self.left.insert(right, (left, at));
        Ok(())
    }

    /// Records that `left` passes through `right` at event `at` (a bullet through a block):
    /// they meet as in [`Line::collide`], then swap places, so `X left right Y` becomes
    /// `X right left Y`.
    pub fn pass(&mut self, left: Object, right: Object, at: usize) -> Result<(), OrderError> {
        self.collide(left, right, at)?;
        let outer_left = self.left.remove(&left);
        let outer_right = self.right.remove(&right);
        self.right.remove(&left);
        self.left.remove(&right);
        if let Some((x, since)) = outer_left {
            self.right.insert(x, (right, since));
            self.left.insert(right, (x, since));
        }
        if let Some((y, since)) = outer_right {
            self.left.insert(y, (left, since));
            self.right.insert(left, (y, since));
        }
        self.right.insert(right, (left, at));
        self.left.insert(left, (right, at));
        Ok(())
    }

    /// `from` and the objects known to be on its right, nearest first.
    fn rightward(&self, from: Object) -> Vec<Object> {
        let mut out = vec![from];
        let mut at = from;
        while let Some(&(next, _)) = self.right.get(&at) {
            out.push(next);
            at = next;
        }
        out
    }

    /// Every pair of neighbours, left to right within each run of neighbours, as
    /// `(left, right, since)`.
    pub fn neighbours(&self) -> Vec<(Object, Object, usize)> {
        let heads = self.right.keys().filter(|o| !self.left.contains_key(o));
        let mut out = Vec::new();
        for &head in heads {
            let run = self.rightward(head);
            for pair in run.windows(2) {
                let since = self.right[&pair[0]].1;
                out.push((pair[0], pair[1], since));
            }
        }
        out
    }

    /// The neighbours that approach, given each object's velocity (`velocity` of a wall: its
    /// own): `v_left > v_right`.
    pub fn meetings(&self, velocity: impl Fn(Object) -> Q) -> Vec<Meeting> {
        self.neighbours()
            .into_iter()
            .filter_map(|(left, right, _)| {
                let closing = velocity(left) - velocity(right);
                (closing > Q::ZERO).then_some(Meeting {
                    left,
                    right,
                    closing,
                })
            })
            .collect()
    }
}

impl fmt::Display for Side {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Side::Left => "left",
            Side::Right => "right",
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::values::rational::int;

    const A: Object = Object::Body(0);
    const B: Object = Object::Body(1);
    const C: Object = Object::Body(2);
    const WALL: Object = Object::Wall(Side::Right);

    #[test]
    fn a_ball_between_a_ball_and_a_wall_meets_it_again_when_it_comes_back_faster() {
        // A hits B, B hits the wall and comes back at -1 while A moves on at 3/2: A catches B
        // at 5/2; B moves away from the wall.
        let mut line = Line::default();
        line.collide(A, B, 0).unwrap();
        line.collide(B, WALL, 1).unwrap();
        line.collide(A, B, 2).unwrap();
        assert_eq!(line.neighbours(), vec![(A, B, 0), (B, WALL, 1)]);
        let v = |o| match o {
            A => int(3) / int(2),
            B => int(-1),
            _ => int(0),
        };
        let m = line.meetings(v);
        assert_eq!(
            m,
            vec![Meeting {
                left: A,
                right: B,
                closing: int(5) / int(2)
            }]
        );
    }

    #[test]
    fn nothing_passes_between_neighbours_or_through_them() {
        let mut line = Line::default();
        line.collide(A, B, 0).unwrap();
        // C cannot come between A and B, on either side of the pair.
        assert_eq!(
            line.collide(A, C, 1),
            Err(OrderError::Taken {
                object: A,
                side: Side::Right,
                neighbour: B,
                since: 0
            })
        );
        assert_eq!(
            line.collide(C, B, 1),
            Err(OrderError::Taken {
                object: B,
                side: Side::Left,
                neighbour: A,
                since: 0
            })
        );
        // B on the left of A: they would pass through each other.
        line.collide(B, C, 1).unwrap();
        assert_eq!(
            line.collide(C, A, 2),
            Err(OrderError::Reversed { left: C, right: A })
        );
        assert_eq!(
            line.neighbours(),
            vec![(A, B, 0), (B, C, 1)],
            "one run, left to right"
        );
        // Moving apart, or together: no meeting.
        assert!(line.meetings(|_| int(1)).is_empty());
    }

    #[test]
    fn a_body_that_passes_through_another_changes_places_with_it() {
        // C meets A from the left, then A passes through B (on its right): C A B becomes
        // C B A.
        let mut line = Line::default();
        line.collide(C, A, 0).unwrap();
        line.pass(A, B, 1).unwrap();
        assert_eq!(line.neighbours(), vec![(C, B, 0), (B, A, 1)]);
        // A cannot meet C now without passing through B.
        assert!(line.collide(C, A, 2).is_err());
        // Two free bodies: they swap.
        let mut line = Line::default();
        line.pass(A, B, 0).unwrap();
        assert_eq!(line.neighbours(), vec![(B, A, 0)]);
        line.collide(A, C, 1).unwrap();
        assert_eq!(line.neighbours(), vec![(B, A, 0), (A, C, 1)]);
    }
}
