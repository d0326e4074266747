//! Typed indices of a mechanism's links and points, so that a link's index cannot be
//! passed where a point's is meant (both were `usize`). Slices and vectors of links,
//! points and their motions are indexed by them directly.

use std::ops::{Index, IndexMut};

use serde::{Deserialize, Serialize};

/// The index of a link in [`crate::Mechanism::links`] (and in a solution's links).
#[derive(
    Clone, Copy, Debug, Default, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize,
)]
#[serde(transparent)]
pub struct LinkId(pub usize);

/// The index of a named point in [`crate::Mechanism::points`] (and in a solution's
/// points).
#[derive(
    Clone, Copy, Debug, Default, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize,
)]
#[serde(transparent)]
pub struct PointId(pub usize);

impl LinkId {
    /// The plain index.
    pub fn index(self) -> usize {
        self.0
    }
}

impl PointId {
    /// The plain index.
    pub fn index(self) -> usize {
        self.0
    }
}

// The plain number, as an index is printed in diagnostics (a link is shown to the
// user by its name, which the mechanism holds).
impl std::fmt::Display for LinkId {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        self.0.fmt(f)
    }
}

impl std::fmt::Display for PointId {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        self.0.fmt(f)
    }
}

/// Indexing of slices and vectors by an id.
macro_rules! index_by {
    ($id:ty) => {
        impl<T> Index<$id> for [T] {
            type Output = T;
            fn index(&self, id: $id) -> &T {
                &self[id.0]
            }
        }
        impl<T> IndexMut<$id> for [T] {
            fn index_mut(&mut self, id: $id) -> &mut T {
                &mut self[id.0]
            }
        }
        impl<T> Index<$id> for Vec<T> {
            type Output = T;
            fn index(&self, id: $id) -> &T {
                &self[id.0]
            }
        }
        impl<T> IndexMut<$id> for Vec<T> {
            fn index_mut(&mut self, id: $id) -> &mut T {
                &mut self[id.0]
            }
        }
    };
}

index_by!(LinkId);
index_by!(PointId);
