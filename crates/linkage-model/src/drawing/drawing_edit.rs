//! What an edit of the drawing says, as a value (the canvas turns clicks and drags
//! into these), and why one is refused. A leaf of the drawing: [`super::edit`] and
//! [`super::loads`] make the edits.

use linkage::Vec2;
use linkage::scene::{ForceWhen, Models};
use linkage_diagram::words::Lang;

use crate::session::words::mw;

/// One end of a new link: a point already drawn, or a new one at a place (m).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum End {
    /// An existing point, by index.
    Point(usize),
    /// A new moving point at this world place.
    New(Vec2),
}

/// What a name belongs to.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Named {
    /// A point, by index.
    Point(usize),
    /// A link, by index.
    Link(usize),
}

/// One change to a drawing.
#[derive(Clone, Debug, PartialEq)]
pub enum DrawingEdit {
    /// A new ground pivot at a world place.
    AddPivot(Vec2),
    /// Fixes an existing point to the frame, or frees it.
    SetGround {
        /// The point.
        point: usize,
        /// Fixed or free.
        ground: bool,
    },
    /// A binary link between two ends.
    AddLink(End, End),
    /// One more point on a link (a plate when it had two).
    AddPointToLink {
        /// The link.
        link: usize,
        /// The point added.
        end: End,
    },
    /// A slider block pinned at a point, on a ground guide through it.
    AddSlider {
        /// The block's pin.
        point: usize,
        /// The guide's direction, rad.
        angle_rad: f64,
    },
    /// A slider's guide: ground (`None`) or a link, and its direction as drawn.
    SetGuide {
        /// The slider, by index.
        slider: usize,
        /// The link carrying the guide; `None`: ground.
        guide: Option<usize>,
        /// The guide's direction, rad.
        angle_rad: f64,
    },
    /// The input link.
    SetDriver(usize),
    /// A point to a new world place.
    MovePoint {
        /// The point.
        point: usize,
        /// Where to, m.
        to: Vec2,
    },
    /// A point, with the links left with fewer than two points and its sliders.
    DeletePoint(usize),
    /// A link, with the points it alone carried.
    DeleteLink(usize),
    /// A new name for a point or a link.
    Rename(Named, String),
    /// The input speed, rpm (positive counter-clockwise).
    SetSpeedRpm(f64),
    /// The main output for the time ratio (`None`: the last link).
    SetOutput(Option<usize>),
    /// Kinematics only, or kinetostatics with the masses and gravity.
    SetModels(Models),
    /// A body's mass, kg (`None`: massless).
    SetMass(Body, Option<f64>),
    /// Gravity on or off.
    SetGravity(bool),
    /// The drive on the input: motor, gear, flywheel (`None`: the input turns at its
    /// speed, with no motor).
    SetDrive(Option<linkage::scene::DriveSpec>),
    /// A spring between two points, 1000 N/m, unstretched as drawn.
    AddSpring(usize, usize),
    /// A linear damper between two points, 10 N·s/m.
    AddDamper(usize, usize),
    /// A force of 100 N down the drawing at a point.
    AddForce(usize),
    /// A spring's stiffness, N/m, and free length, m (`None`: as drawn).
    SetSpring {
        /// The spring, by index.
        spring: usize,
        /// Stiffness, N/m.
        k_n_per_m: f64,
        /// Free length, m.
        free_length_m: Option<f64>,
    },
    /// A damper's coefficient, N·s/m.
    SetDamper {
        /// The damper, by index.
        damper: usize,
        /// Coefficient, N·s/m.
        c_n_s_per_m: f64,
    },
    /// A point force's vector, N, and when it acts.
    SetForce {
        /// The force, by index.
        force: usize,
        /// The vector, N.
        force_n: Vec2,
        /// Always, or on the working stroke only.
        when: ForceWhen,
    },
    /// A spring, damper or force removed.
    DeleteElement(Element),
    /// A link's own centroid (world, as drawn, m) and inertia (kg·m²); `None`: a
    /// uniform body's.
    SetBody {
        /// The link.
        link: usize,
        /// Its centroid.
        centroid: Option<Vec2>,
        /// Its moment of inertia about the centroid.
        inertia_kg_m2: Option<f64>,
    },
}

/// A force element of a drawing, by index.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Element {
    /// A spring.
    Spring(usize),
    /// A damper.
    Damper(usize),
    /// A point force.
    Force(usize),
}

/// A body that can carry a mass.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Body {
    /// A link, by index.
    Link(usize),
    /// A slider's block, by the slider's index.
    Block(usize),
}

/// Why an edit was not made.
#[derive(Clone, Debug, PartialEq)]
pub enum Refusal {
    /// Both ends of a link at one point.
    SameEnds,
    /// The two points are already on one link.
    AlreadyJoined(String),
    /// The point already carries a slider.
    AlreadySlider(String),
    /// The driver must turn about a ground pivot.
    DriverNotGrounded(String),
    /// A place that is not a finite number.
    NotFinite,
    /// A name that is empty or already another's.
    Name(String),
    /// A speed that is zero or not finite.
    Speed(f64),
    /// A guide on a link through the slider's own pin.
    GuideThroughPin(String),
    /// A mass that is not a positive finite number.
    Mass(f64),
    /// A stiffness, free length or damping coefficient that is negative or not finite.
    Coefficient(f64),
    /// A drive the scene would refuse, with the solver's reason (the field and its
    /// valid range).
    Drive(linkage::LinkageError),
}

impl Refusal {
    /// Why the edit was not made, in `lang`.
    pub fn words(&self, lang: Lang) -> String {
        match self {
            Self::SameEnds => mw!(lang, "drawing.same_ends"),
            Self::AlreadyJoined(link) => mw!(lang, "drawing.already_joined", link = link),
            Self::AlreadySlider(p) => mw!(lang, "drawing.already_slider", point = p),
            Self::DriverNotGrounded(link) => mw!(lang, "drawing.driver_not_grounded", link = link),
            Self::NotFinite => mw!(lang, "drawing.not_finite"),
            Self::Name(name) if name.trim().is_empty() => mw!(lang, "drawing.empty_name"),
            Self::Name(name) => mw!(lang, "drawing.name_taken", name = name),
            Self::GuideThroughPin(link) => mw!(lang, "drawing.guide_through_pin", link = link),
            Self::Mass(kg) => mw!(lang, "drawing.mass", kg = kg),
            Self::Speed(rpm) => mw!(lang, "drawing.speed", rpm = rpm),
            Self::Coefficient(v) => mw!(lang, "drawing.coefficient", value = v),
            Self::Drive(e) => {
                linkage_diagram::refusal::error(lang, e, linkage::scene::LengthUnit::Metre)
            }
        }
    }
}

impl std::fmt::Display for Refusal {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.words(Lang::English))
    }
}

/// `Ok` if both coordinates of `at` are finite.
pub(crate) fn finite(at: Vec2) -> Result<(), Refusal> {
    if at.x.is_finite() && at.y.is_finite() {
        Ok(())
    } else {
        Err(Refusal::NotFinite)
    }
}
