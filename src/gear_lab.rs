//! The gear-cutting lab (范成法): a rack cutter rolls against a blank and the teeth
//! appear, undercut where they are too few and the cutter not shifted out. What it
//! holds (the gear's numbers, how far the cutter has rolled, whether it plays) and
//! what follows from it (the gear, the cutter's positions so far); the side panel
//! (`ui::gear_lab`) edits it and the GPU pass (`render::gear_shapes`) draws it.

use linkage::gears::{CentreDistance, Gear, GearError, GearPair, GearSpec, PairSpec};

use crate::render::view::Camera;
use crate::train_view::TrainView;

/// The cutter's positions over the whole roll: enough that the traces show the
/// envelope, few enough that every frame draws them all.
pub const POSITIONS: usize = 72;
/// Seconds a full roll takes while playing.
const ROLL_S: f64 = 8.0;
/// Cutter teeth either side of the middle one.
pub const CUTTER_TEETH: usize = 2;

/// What the lab shows.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum LabMode {
    /// A rack cutter generating one gear.
    #[default]
    Cutting,
    /// That gear (the pinion) meshing with a wheel.
    Pair,
    /// A gear train's schematic, every member turning at its speed.
    Train,
}

/// Seconds a pinion turn takes while the pair plays.
const PINION_TURN_S: f64 = 12.0;

/// The lab's state.
#[derive(Clone, Debug, PartialEq)]
pub struct GearLab {
    /// What it shows.
    pub mode: LabMode,
    /// The wheel's teeth, in the pair.
    pub wheel_teeth: u32,
    /// The wheel's profile shift, in the pair.
    pub wheel_shift: f64,
    /// The pinion's turn in the pair, rad (counter-clockwise).
    pub turn_rad: f64,
    /// Teeth z.
    pub teeth: u32,
    /// Module m, mm.
    pub module_mm: f64,
    /// Profile shift coefficient x (the cutter moved x·m away from the centre).
    pub shift: f64,
    /// Pressure angle α, degrees.
    pub pressure_angle_deg: f64,
    /// How far the cutter has rolled, 0 (not started) to 1 (the whole roll).
    pub roll: f64,
    /// Whether the roll plays.
    pub playing: bool,
    /// The lab's own view (the mechanism's stays as it was).
    pub camera: Camera,
    /// The train view.
    pub train: TrainView,
}

impl Default for GearLab {
    /// 12 teeth of module 10 mm, unshifted: undercut, as the textbooks show first.
    fn default() -> Self {
        Self {
            mode: LabMode::Cutting,
            wheel_teeth: 40,
            wheel_shift: 0.0,
            turn_rad: 0.0,
            teeth: 12,
            module_mm: 10.0,
            shift: 0.0,
            pressure_angle_deg: 20.0,
            roll: 0.5,
            playing: false,
            camera: Camera::default(),
            train: TrainView::default(),
        }
    }
}

impl GearLab {
    /// The gear being cut (GB/T 1356's coefficients).
    ///
    /// # Errors
    /// Numbers outside the gear's ranges (the sliders keep within them).
    pub fn gear(&self) -> Result<Gear, GearError> {
        let spec = GearSpec {
            pressure_angle_rad: self.pressure_angle_deg.to_radians(),
            ..GearSpec::standard(self.module_mm * 1e-3, self.teeth).shifted(self.shift)
        };
        Gear::new(spec)
    }

    /// The gear's turn at each cutter position rolled so far, rad (clockwise): the
    /// whole roll turns the blank while the cutter's teeth cross it, a few pitches
    /// either side of the middle.
    pub fn positions(&self, g: &Gear) -> Vec<f64> {
        let reach = roll_reach(g);
        let last = (self.roll.clamp(0.0, 1.0) * (POSITIONS - 1) as f64).round() as usize;
        (0..=last)
            .map(|i| -reach + 2.0 * reach * i as f64 / (POSITIONS - 1) as f64)
            .collect()
    }

    /// The pinion (the gear being cut) meshing with the wheel, the centres from the
    /// shifts (no backlash).
    ///
    /// # Errors
    /// Gears or a pair outside their ranges.
    pub fn pair(&self) -> Result<GearPair, GearError> {
        let pinion = self.gear()?.spec;
        let wheel = GearSpec {
            shift: self.wheel_shift,
            teeth: self.wheel_teeth,
            ..pinion
        };
        GearPair::new(PairSpec {
            pinion,
            wheel,
            centre: CentreDistance::FromShifts,
        })
    }

    /// Moves the roll (or the pair's or the train's turn) on by `dt` seconds of
    /// play; the roll stops at its end, the pair and the train turn on.
    pub fn advance(&mut self, dt: f64) {
        if !self.playing {
            return;
        }
        if self.mode == LabMode::Train {
            self.train.advance(dt);
            return;
        }
        if self.mode == LabMode::Pair {
            self.turn_rad = (self.turn_rad + std::f64::consts::TAU * dt / PINION_TURN_S)
                % std::f64::consts::TAU;
            return;
        }
        self.roll = (self.roll + dt / ROLL_S).min(1.0);
        if self.roll >= 1.0 {
            self.playing = false;
        }
    }

    /// Plays from the start, or from where it is; pauses if playing.
    pub fn toggle_play(&mut self) {
        if self.mode == LabMode::Cutting && !self.playing && self.roll >= 1.0 {
            self.roll = 0.0;
        }
        self.playing = !self.playing;
    }

    /// Whether the teeth are undercut: a shift below the least that avoids it.
    pub fn undercut(g: &Gear) -> bool {
        g.spec.shift < g.least_shift_without_undercut() - 1e-9
    }
}

/// Half the roll, rad: from before the cutter's middle tooth enters the blank's tip
/// circle until after it leaves it (its tip line meets the tip circle
/// √(r_a² − r_f²) either side of the centre line, and the tooth is half a pitch wide).
pub fn roll_reach(g: &Gear) -> f64 {
    let (ra, rf) = (g.tip_radius_m, g.root_radius_m);
    let half_pitch = 0.5 * std::f64::consts::PI * g.spec.module_m;
    ((ra * ra - rf * rf).max(0.0).sqrt() + half_pitch) / g.pitch_radius_m
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn twelve_teeth_unshifted_are_undercut_and_the_least_shift_cures_them() {
        let mut lab = GearLab::default();
        let g = lab.gear().expect("a gear");
        assert!(GearLab::undercut(&g));
        lab.shift = g.least_shift_without_undercut();
        assert!(!GearLab::undercut(&lab.gear().expect("a gear")));
    }

    #[test]
    fn the_roll_plays_to_its_end_and_starts_again() {
        let mut lab = GearLab {
            roll: 0.0,
            ..GearLab::default()
        };
        let g = lab.gear().expect("a gear");
        assert_eq!(lab.positions(&g).len(), 1);
        lab.toggle_play();
        for _ in 0..1000 {
            lab.advance(0.1);
        }
        assert!(!lab.playing && lab.roll == 1.0);
        assert_eq!(lab.positions(&g).len(), POSITIONS);
        lab.toggle_play();
        assert!(lab.playing && lab.roll == 0.0);
    }
}
