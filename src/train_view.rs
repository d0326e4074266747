//! The gear lab's train view: one of the shipped trains (`assets/trains`), its
//! inputs' speeds as the user sets them, every member's angle as it turns (the
//! lab's Play turns it). The side panel (`ui::gear_train`) edits it; the GPU pass
//! (`render::train_shapes`) draws its schematic with each gear turning at its speed.

use linkage::gears::train_file::TrainFile;
use linkage::gears::{Train, TrainError, TrainSolution};

use crate::catalog::TRAINS;
use crate::render::view::Camera;

/// The fastest member's speed as shown, rpm: a motor at 1450 rpm cannot be watched,
/// so the whole train is shown that many times slower (and says so).
pub const SHOWN_FASTEST_RPM: f64 = 20.0;

/// The train view's state.
#[derive(Clone, Debug, PartialEq)]
pub struct TrainView {
    /// Which shipped train (index in `TRAINS`).
    pub choice: usize,
    /// Its file, with the inputs' speeds as set: set them with
    /// [`Self::set_input_rpm`], which solves the train again.
    pub file: TrainFile,
    /// Every member's turn so far, rad (counter-clockwise seen from the front).
    pub angles: Vec<f64>,
    /// The view's own camera.
    pub camera: Camera,
    /// Every member's speed from the inputs as set: solved when they change, not in
    /// every frame's panel, drawing and play (three solves a frame before).
    solution: Result<TrainSolution, TrainError>,
}

impl Default for TrainView {
    /// The planetary set: the textbook's first epicyclic train.
    fn default() -> Self {
        let choice = TRAINS
            .iter()
            .position(|t| t.key == "planetary_ring_fixed")
            .unwrap_or(0);
        Self::of(choice)
    }
}

impl TrainView {
    /// The shipped train `choice` as its file gives it, standing still.
    pub fn of(choice: usize) -> Self {
        let file = TRAINS
            .get(choice)
            .and_then(|t| TrainFile::from_ron(t.text).ok())
            .unwrap_or_default();
        Self {
            choice,
            angles: vec![0.0; file.members.len()],
            solution: solve(&file),
            file,
            camera: Camera::default(),
        }
    }

    /// Sets input `index`'s speed, rpm, and solves the train again.
    pub fn set_input_rpm(&mut self, index: usize, rpm: f64) {
        let Some(input) = self.file.inputs.get_mut(index) else {
            return;
        };
        if input.rpm != rpm {
            input.rpm = rpm;
            self.solution = solve(&self.file);
        }
    }

    /// Every member's speed from the inputs as set.
    ///
    /// # Errors
    /// The train's refusal (a shipped file solves; inputs set to tie it up cannot
    /// be, since the view only changes their speeds).
    pub fn solve(&self) -> Result<&TrainSolution, &TrainError> {
        self.solution.as_ref()
    }
}

impl TrainView {
    /// The members held still: inputs set to 0 rpm (a brake). The textbooks count
    /// such a member as fixed: a planetary train of F = 1 rather than a differential
    /// of F = 2. The panel's count and the drawing's hatching both ask this.
    pub fn held(&self) -> impl Iterator<Item = &str> {
        self.file
            .inputs
            .iter()
            .filter(|i| i.rpm == 0.0)
            .map(|i| i.member.as_str())
    }
}

/// Every member's speed from `file`'s inputs.
fn solve(file: &TrainFile) -> Result<TrainSolution, TrainError> {
    Train::new(file.clone())?.solve()
}

impl TrainView {
    /// How many times slower than life the train is shown: the fastest member at
    /// [`SHOWN_FASTEST_RPM`], never faster than life.
    pub fn slowed(solution: &TrainSolution) -> f64 {
        let fastest = solution
            .speeds_rpm
            .iter()
            .map(|s| s.rpm.abs())
            .fold(0.0, f64::max);
        (fastest / SHOWN_FASTEST_RPM).max(1.0)
    }

    /// Turns every member on by `dt` seconds of play, slowed as [`Self::slowed`] says.
    pub fn advance(&mut self, dt: f64) {
        let Ok(solution) = &self.solution else {
            return;
        };
        let slowed = Self::slowed(solution);
        for (angle, speed) in self.angles.iter_mut().zip(&solution.speeds_rpm) {
            let omega = speed.rpm * std::f64::consts::TAU / 60.0;
            *angle = (*angle + omega * dt / slowed) % std::f64::consts::TAU;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The planetary set with the ring held: the carrier turns at the sun's
    /// 1/(1 + 80/20) and the same way; shown slowed, the angles keep that ratio.
    #[test]
    fn members_turn_at_their_speeds_slowed_alike() {
        let mut view = TrainView::default();
        let solution = view.solve().expect("solves");
        let slowed = TrainView::slowed(solution);
        assert!((slowed - 1450.0 / SHOWN_FASTEST_RPM).abs() < 1e-9 * slowed);
        view.advance(0.1);
        let index = |name: &str| {
            view.file
                .members
                .iter()
                .position(|m| m.name == name)
                .expect("member")
        };
        let (sun, carrier) = (view.angles[index("sun")], view.angles[index("carrier")]);
        assert!((carrier / sun - 0.2).abs() < 1e-12, "{carrier} {sun}");
        assert_eq!(view.angles[index("ring")], 0.0);
    }

    /// The speeds follow an input set: solved again when it changes (the view keeps
    /// its solution between frames).
    #[test]
    fn an_input_set_solves_the_train_again() {
        let mut view = TrainView::default();
        let carrier = |view: &TrainView| view.solve().ok().and_then(|s| s.speed_rpm("carrier"));
        let before = carrier(&view).expect("the carrier turns");
        let rpm = view.file.inputs[0].rpm;
        view.set_input_rpm(0, 2.0 * rpm);
        let after = carrier(&view).expect("the carrier turns");
        assert!(
            (after - 2.0 * before).abs() < 1e-9 * before.abs(),
            "{before} -> {after}"
        );
        assert_eq!(view.file.inputs[0].rpm, 2.0 * rpm);
    }

    #[test]
    fn every_shipped_train_opens_and_solves() {
        for (choice, train) in TRAINS.iter().enumerate() {
            let view = TrainView::of(choice);
            assert!(!view.file.members.is_empty(), "{}", train.key);
            assert!(view.solve().is_ok(), "{}", train.key);
        }
    }
}
