//! Edits of the viewed scene as values. The panels do not change the session while
//! they are laid out: they return a [`SceneEdit`], which the app applies with
//! [`Session::apply`] between panels (and times). Each edit either succeeds or
//! leaves a [`Notice`] and the last valid state.

use linkage::SceneFile;

use super::Session;
use super::dynamic_run::IntegratorChoice;
use super::history::EditTarget;
use super::limit;
use super::notice::{EditSubject, Notice, ValueKind};
use linkage::error::Valid;

/// One edit a user makes in the viewer.
#[derive(Clone, Debug, PartialEq)]
pub enum SceneEdit {
    /// Move the crank to this angle, deg (wrapped for a full turn).
    Input {
        /// The angle, deg.
        deg: f64,
    },
    /// Show the dynamic run at this time, s (clamped to the run).
    RunTime {
        /// The time, s.
        s: f64,
    },
    /// Set a length, by its index in [`Session::lengths`], scene units.
    Length {
        /// Which length.
        index: usize,
        /// The new length.
        value: f64,
    },
    /// Set the constant of a spring, by its index in the scene, N/m.
    SpringK {
        /// Which spring.
        index: usize,
        /// The new constant.
        n_per_m: f64,
    },
    /// Set the mass of a link, by its index in the scene, kg (the inertia scales).
    Mass {
        /// Which link.
        index: usize,
        /// The new mass.
        kg: f64,
    },
    /// Flip the assembly branch of the dyad at a point.
    FlipBranch {
        /// The dyad's point.
        point: String,
    },
    /// Change the integrator of the dynamic run (it runs again).
    Integrator(IntegratorChoice),
    /// Move a point to a place in the world, m, at the current input.
    MovePoint {
        /// The point's name.
        name: String,
        /// Where to, metres.
        to_m: [f64; 2],
    },
    /// Change a cam joint's program or roller, by its index in the scene's `cams`.
    Cam {
        /// Which cam joint.
        cam: usize,
        /// What changes.
        edit: super::cam_edit::CamEdit,
    },
    /// Put back the scene as opened.
    Reset,
    /// Put a whole scene (a synthesized design) in place of this one, at its own
    /// start; undo puts this one back.
    Replace(Box<SceneFile>),
    /// Take the last edit back.
    Undo,
    /// Make the last undone edit again.
    Redo,
}

impl Session {
    /// Applies `edit`: on success the pose, polygons and curves are new at once (the
    /// rest follows when shown); on failure [`Session::notice`] says why and nothing
    /// else changes.
    pub fn apply(&mut self, edit: SceneEdit) {
        self.edits += 1;
        match edit {
            SceneEdit::Input { deg } => self.move_to_deg(deg),
            SceneEdit::RunTime { s } => self.show_time(s),
            SceneEdit::Length { index, value } => self.set_length(index, value),
            SceneEdit::SpringK { index, n_per_m } => self.set_spring_k(index, n_per_m),
            SceneEdit::Mass { index, kg } => self.set_mass(index, kg),
            SceneEdit::FlipBranch { point } => self.flip_branch(&point),
            SceneEdit::Integrator(choice) => self.set_integrator(choice),
            SceneEdit::MovePoint { name, to_m } => self.move_point(&name, to_m),
            SceneEdit::Cam { cam, edit } => self.edit_cam(cam, edit),
            SceneEdit::Reset => self.reset(),
            SceneEdit::Replace(scene) => self.replace(*scene),
            SceneEdit::Undo => self.travel(true),
            SceneEdit::Redo => self.travel(false),
        }
    }

    fn set_length(&mut self, index: usize, value: f64) {
        let Some(param) = self.lengths.get(index).cloned() else {
            return;
        };
        let mut scene = self.scene().clone();
        if let Err(e) = param.apply(&mut scene, value) {
            self.message = Some(Notice::LengthInvalid(e));
            return;
        }
        let input = self.edit_input();
        let why = match limit::try_assemble(&scene, input, &self.curves().cams) {
            Ok(built) => return self.commit(EditTarget::Length(index), scene, built),
            Err(why) => why,
        };
        let good = param.value(self.scene());
        let limit =
            good.and_then(|good| limit::length_limit(self.scene(), &param, good, value, input));
        self.message = Some(Notice::LengthRefused {
            label: param.label.clone(),
            value,
            unit: super::unit_label(self.scene()),
            input_deg: input.to_degrees(),
            why,
            limit,
        });
    }

    fn set_spring_k(&mut self, index: usize, k_n_per_m: f64) {
        if !(k_n_per_m.is_finite() && k_n_per_m >= 0.0) {
            self.message = Some(Notice::InvalidValue {
                what: ValueKind::SpringConstant,
                value: k_n_per_m,
                valid: Valid::NonNegative,
            });
            return;
        }
        let mut scene = self.scene().clone();
        let Some(spring) = scene.forces.springs.get_mut(index) else {
            return;
        };
        spring.k_n_per_m = k_n_per_m;
        let what = EditSubject::SpringConstant {
            ends: [spring.a.clone(), spring.b.clone()],
        };
        self.rebuild(EditTarget::Spring(index), scene, what);
    }

    fn set_mass(&mut self, index: usize, mass_kg: f64) {
        if !(mass_kg.is_finite() && mass_kg > 0.0) {
            self.message = Some(Notice::InvalidValue {
                what: ValueKind::Mass,
                value: mass_kg,
                valid: Valid::Positive,
            });
            return;
        }
        let mut scene = self.scene().clone();
        let Some(link) = scene.links.get_mut(index) else {
            return;
        };
        // Scale the inertia with the mass: same shape, denser material.
        if let (Some(old), Some(i)) = (link.mass, link.inertia.as_mut())
            && old > 0.0
        {
            *i *= mass_kg / old;
        }
        link.mass = Some(mass_kg);
        let what = EditSubject::Mass {
            link: link.name.clone(),
        };
        self.rebuild(EditTarget::Mass(index), scene, what);
    }

    fn flip_branch(&mut self, point: &str) {
        let m = self.mechanism();
        let Some(b) = m
            .branches
            .iter()
            .find(|(p, _)| m.points[*p].name == point)
            .map(|(_, b)| b.flipped())
        else {
            return;
        };
        let mut scene = self.scene().clone();
        scene.branches.insert(point.to_string(), b);
        let what = EditSubject::Branch {
            point: point.to_string(),
        };
        self.rebuild(EditTarget::Branch(point.to_string()), scene, what);
    }

    fn set_integrator(&mut self, choice: IntegratorChoice) {
        self.analyses.set_integrator(choice);
        self.start_run();
        self.time_s = 0.0;
    }

    fn replace(&mut self, scene: SceneFile) {
        match super::Built::new(&scene, None, &self.curves().cams) {
            Ok(built) => self.commit(EditTarget::Replaced, scene, built),
            Err(why) => {
                self.message = Some(Notice::EditRefused {
                    what: EditSubject::Design,
                    why,
                })
            }
        }
    }

    fn reset(&mut self) {
        let scene = self.original().clone();
        if &scene == self.scene() {
            return;
        }
        self.rebuild(EditTarget::Reset, scene, EditSubject::Reset);
    }

    /// Puts back the scene the history holds next, backwards (undo) or forwards
    /// (redo); a scene that no longer builds stays in the history, with the reason
    /// shown.
    fn travel(&mut self, back: bool) {
        let Some(to) = self.doc.travel_target(back).cloned() else {
            return;
        };
        // At the current input, or where it stood if it does not assemble here.
        let cams = &self.curves().cams;
        let built = super::Built::new(&to.scene, Some(self.input_rad()), cams)
            .or_else(|_| super::Built::new(&to.scene, Some(to.input_rad), cams));
        match built {
            Ok(built) => {
                self.doc.travel(back, self.input_rad());
                self.accept(built);
            }
            Err(why) => self.message = Some(Notice::HistoryRefused { undo: back, why }),
        }
    }

    /// Rebuilds everything from `scene` at the current input; on failure nothing
    /// changes and the notice says `what` failed and why.
    pub(super) fn rebuild(&mut self, target: EditTarget, scene: SceneFile, what: EditSubject) {
        match super::Built::new(&scene, Some(self.edit_input()), &self.curves().cams) {
            Ok(built) => self.commit(target, scene, built),
            Err(why) => self.message = Some(Notice::EditRefused { what, why }),
        }
    }

    /// The input an edit builds the scene at: the current one; for a dynamic scene
    /// the run's start (the driver's start angle), since the edit runs it again from
    /// there and the pose shown is the run's at its time 0.
    fn edit_input(&self) -> f64 {
        if self.models() == linkage::scene::Models::Dynamics {
            self.mechanism().driver.start_rad
        } else {
            self.input_rad()
        }
    }

    /// Makes an edit of `target` current, the scene before it kept for undo.
    pub(super) fn commit(&mut self, target: EditTarget, scene: SceneFile, built: super::Built) {
        self.doc.commit(target, scene, self.input_rad());
        self.accept(built);
    }
}
