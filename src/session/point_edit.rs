//! Moving a point of the mechanism: the edit an editor's drag makes. Every link that
//! carries the point gets its new place in that link's own coordinates, taken from
//! the link's place in the current pose, so that at the current crank angle the point
//! lands where it was put and everything else stays. Where the chain would not
//! assemble, or would put the point elsewhere (on its other branch, or a slider's
//! point off its guide's line), the edit is refused with the reason and the last
//! valid geometry stays.

use linkage::Vec2;

use super::Session;
use super::history::EditTarget;
use super::limit;
use super::notice::Notice;

impl Session {
    /// Moves point `name` to `to_m` (world coordinates, metres) at the current input.
    pub fn move_point(&mut self, name: &str, to_m: [f64; 2]) {
        self.edits += 1;
        let unit = super::unit_label(&self.scene);
        let metres = self.scene.length_unit.to_metres();
        let shown = |v: f64| v / metres;
        if !(to_m[0].is_finite() && to_m[1].is_finite()) {
            self.message = Some(Notice::Text(format!(
                "{name} cannot go to a point that is not finite"
            )));
            return;
        }
        let target = Vec2::new(to_m[0], to_m[1]);
        let mut scene = self.scene.clone();
        let mut carried = false;
        for (link, spec) in scene.links.iter_mut().enumerate() {
            if let Some(xy) = spec.points.get_mut(name) {
                let lm = &self.pose.links[link];
                let local = lm.rotation.inverse() * (target - lm.origin.position);
                *xy = (local.x / metres, local.y / metres);
                carried = true;
            }
        }
        if !carried {
            self.message = Some(Notice::Text(format!("there is no point named {name}")));
            return;
        }
        let refuse = |why: String| {
            Notice::Text(format!(
                "{name} cannot go to ({:.2}, {:.2}) {unit}: {why}",
                shown(to_m[0]),
                shown(to_m[1])
            ))
        };
        let built = match limit::try_assemble(&scene, self.input_rad()) {
            Ok(built) => built,
            Err(why) => {
                self.message = Some(refuse(why));
                return;
            }
        };
        let landed = built.point_position(name);
        let tolerance = 1e-9 * self.mechanism().size_m.max(1e-3);
        if landed.is_none_or(|p| (p - target).norm() > tolerance) {
            let m = self.mechanism();
            let on_guide = m.sliders.iter().any(|sl| m.points[sl.point].name == name);
            let why = if on_guide {
                "it slides on a guide, so it can move only along the guide's line"
            } else {
                "the chain assembles there only on its other branch (flip the branch first)"
            };
            self.message = Some(refuse(why.into()));
            return;
        }
        self.commit(EditTarget::Point(name.to_string()), scene, built);
    }
}
