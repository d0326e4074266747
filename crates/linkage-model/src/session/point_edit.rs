//! Moving a point of the mechanism: the edit an editor's drag makes. Every link that
//! carries the point gets its new place in that link's own coordinates, taken from
//! the link's place in the current pose, so that at the current crank angle the point
//! lands where it was put and everything else stays. Where the chain would not
//! assemble, or would put the point elsewhere (on its other branch, or a slider's
//! point off its guide's line), the edit is refused with the reason and the last
//! valid geometry stays.

use linkage::{SceneFile, Vec2};

use super::history::EditTarget;
use super::limit;
use super::notice::{Notice, PointRefusal};
use super::{Built, Session};

impl Session {
    /// Moves point `name` to `to_m` (world coordinates, metres) at the current input.
    pub(super) fn move_point(&mut self, name: &str, to_m: [f64; 2]) {
        match self.point_moved(name, to_m) {
            Ok((scene, built)) => self.commit(EditTarget::Point(name.to_string()), scene, built),
            Err(why) => {
                let metres = self.scene().length_unit.to_metres();
                self.message = Some(Notice::PointRefused {
                    name: name.to_string(),
                    to: [to_m[0] / metres, to_m[1] / metres],
                    unit: super::unit_label(self.scene()),
                    why,
                });
            }
        }
    }

    /// The scene with point `name` at `to_m`, built, or why not.
    fn point_moved(&self, name: &str, to_m: [f64; 2]) -> Result<(SceneFile, Built), PointRefusal> {
        if !(to_m[0].is_finite() && to_m[1].is_finite()) {
            return Err(PointRefusal::NotFinite);
        }
        let metres = self.scene().length_unit.to_metres();
        let target = Vec2::new(to_m[0], to_m[1]);
        let mut scene = self.scene().clone();
        let mut carried = false;
        for (link, spec) in scene.links.iter_mut().enumerate() {
            if let Some(xy) = spec.points.get_mut(name) {
                let lm = &self.pose().links[link];
                let local = lm.rotation.inverse() * (target - lm.origin.position);
                *xy = (local.x / metres, local.y / metres);
                carried = true;
            }
        }
        if !carried {
            return Err(PointRefusal::NoSuchPoint);
        }
        let built = limit::try_assemble(&scene, self.input_rad(), &self.curves().cams)
            .map_err(PointRefusal::NotAssembled)?;
        let landed = built.point_position(name);
        let tolerance = 1e-9 * self.mechanism().size_m.max(1e-3);
        if landed.is_none_or(|p| (p - target).norm() > tolerance) {
            let m = self.mechanism();
            let on_guide = m.sliders.iter().any(|sl| m.points[sl.point].name == name);
            return Err(if on_guide {
                PointRefusal::OffGuide
            } else {
                PointRefusal::OtherBranch
            });
        }
        Ok((scene, built))
    }
}
