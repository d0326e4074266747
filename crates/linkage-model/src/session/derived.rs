//! An analysis derived from the mechanism (the report, the torque and J, M curves),
//! computed when a panel shows it, but not in a frame that carried an edit: while
//! edits come frame after frame (a slider being dragged), the panel keeps the last
//! value, marked out of date, and the first frame without an edit computes the new
//! one. The edit's own frame then holds only what must move with the slider: the
//! pose, the polygons and the curves.

use std::cell::{Cell, OnceCell};

/// What a panel can show of a derived analysis.
#[derive(Debug)]
pub enum Shown<'a, T> {
    /// Computed for the mechanism as it is.
    Current(&'a T),
    /// Computed before the last edit; the current one follows.
    Outdated(&'a T),
    /// Nothing computed yet (a scene just opened); it follows.
    Pending,
}

/// A value computed from the mechanism, kept across edits until it is recomputed.
#[derive(Debug)]
pub struct Derived<T> {
    current: OnceCell<T>,
    outdated: Option<T>,
    /// A panel showed the outdated value (or none): compute at the next catch-up.
    wanted: Cell<bool>,
}

impl<T> Default for Derived<T> {
    fn default() -> Self {
        Self {
            current: OnceCell::new(),
            outdated: None,
            wanted: Cell::new(false),
        }
    }
}

impl<T> Derived<T> {
    /// The current value, computed now if it is not yet (tests, exports).
    pub fn get_or_init(&self, compute: impl FnOnce() -> T) -> &T {
        self.current.get_or_init(compute)
    }

    /// What a panel can show now; an outdated or missing value is computed at the next
    /// [`Derived::catch_up`].
    pub fn shown(&self) -> Shown<'_, T> {
        if let Some(v) = self.current.get() {
            return Shown::Current(v);
        }
        self.wanted.set(true);
        match &self.outdated {
            Some(v) => Shown::Outdated(v),
            None => Shown::Pending,
        }
    }

    /// The mechanism changed: the current value becomes the outdated one.
    pub fn invalidate(&mut self) {
        if let Some(v) = self.current.take() {
            self.outdated = Some(v);
        }
    }

    /// Computes the value if a panel asked for it since it went out of date. Returns
    /// whether it computed (the panel shows the new value next frame).
    pub fn catch_up(&self, compute: impl FnOnce() -> T) -> bool {
        if !self.wanted.replace(false) || self.current.get().is_some() {
            return false;
        }
        self.current.get_or_init(compute);
        true
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_edit_keeps_the_old_value_until_a_frame_without_one_catches_up() {
        let mut d = Derived::default();
        assert!(matches!(d.shown(), Shown::Pending));
        assert!(d.catch_up(|| 1), "a panel asked for it");
        assert!(matches!(d.shown(), Shown::Current(1)));
        d.invalidate();
        assert!(!d.catch_up(|| 2), "no panel showed it since the edit");
        assert!(matches!(d.shown(), Shown::Outdated(1)));
        assert!(d.catch_up(|| 2));
        assert!(matches!(d.shown(), Shown::Current(2)));
        assert!(!d.catch_up(|| 3), "already current");
        d.invalidate();
        assert_eq!(
            *d.get_or_init(|| 4),
            4,
            "asked for directly, computed at once"
        );
    }
}
