//! The gear-cutting lab (范成法): a rack cutter rolls against a blank and the teeth
//! appear, undercut where they are too few and the cutter not shifted out. What it
//! holds (the gear's numbers, how far the cutter has rolled, whether it plays) and
//! what follows from it (the gear, the cutter's positions so far); the side panel
//! (`ui::gear_lab`) edits it and the GPU pass (`render::gear_shapes`) draws it.

use linkage::gears::{Gear, GearError, GearSpec};

use crate::render::view::Camera;

/// The cutter's positions over the whole roll: enough that the traces show the
/// envelope, few enough that every frame draws them all.
pub const POSITIONS: usize = 72;
/// Seconds a full roll takes while playing.
const ROLL_S: f64 = 8.0;
/// Cutter teeth either side of the middle one.
pub const CUTTER_TEETH: usize = 2;

/// The lab's state.
#[derive(Clone, Debug, PartialEq)]
pub struct GearLab {
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
}

impl Default for GearLab {
    /// 12 teeth of module 10 mm, unshifted: undercut, as the textbooks show first.
    fn default() -> Self {
        Self {
            teeth: 12,
            module_mm: 10.0,
            shift: 0.0,
            pressure_angle_deg: 20.0,
            roll: 0.5,
            playing: false,
            camera: Camera::default(),
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

    /// Moves the roll on by `dt` seconds of play; stops at its end.
    pub fn advance(&mut self, dt: f64) {
        if !self.playing {
            return;
        }
        self.roll = (self.roll + dt / ROLL_S).min(1.0);
        if self.roll >= 1.0 {
            self.playing = false;
        }
    }

    /// Plays from the start, or from where it is; pauses if playing.
    pub fn toggle_play(&mut self) {
        if !self.playing && self.roll >= 1.0 {
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
