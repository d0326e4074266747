//! The model's notices in the user's words and language: what an edit could not
//! do, with the solver's reason worded by [`linkage_diagram::refusal`].

use linkage::scene::LengthUnit;
use linkage_diagram::refusal;
use linkage_diagram::words::Lang;

use super::limit::NotAssembled;
use super::notice::{EditSubject, Notice, PointRefusal, ValueKind};
use super::params::LengthError;
use super::words::{error, mw, significant};

impl Notice {
    /// The notice as the user reads it in `lang`, lengths in the scene's `unit`:
    /// the links by their points, the crank's angle in degrees, never the solver's
    /// terms.
    pub fn words(&self, unit: LengthUnit, lang: Lang) -> String {
        match self {
            Self::LengthRefused {
                label,
                value,
                unit: shown,
                input_deg,
                why,
                limit,
            } => {
                let why = why.words(unit, lang);
                let at = significant(*input_deg, 4);
                let value = significant(*value, 5);
                match limit {
                    Some(limit) => mw!(
                        lang,
                        "notice.length_limit",
                        label = label,
                        value = value,
                        unit = shown,
                        at = at,
                        why = why,
                        limit = significant(*limit, 5)
                    ),
                    None => mw!(
                        lang,
                        "notice.length_refused",
                        label = label,
                        value = value,
                        unit = shown,
                        why = why
                    ),
                }
            }
            Self::LengthInvalid(why) => why.words(lang),
            Self::InvalidValue { what, value, valid } => mw!(
                lang,
                "notice.invalid_value",
                what = value_kind(*what, unit, lang),
                value = significant(*value, 6),
                valid = refusal::valid(lang, valid)
            ),
            other => edit_words(other, unit, lang),
        }
    }
}

/// The notices of edits that moved the crank, a point or the cam, or rebuilt the
/// scene.
fn edit_words(n: &Notice, unit: LengthUnit, lang: Lang) -> String {
    match n {
        Notice::CamSpanRefused {
            segment,
            deg,
            room_deg,
        } => mw!(
            lang,
            "notice.cam_span",
            segment = segment + 1,
            deg = significant(*deg, 5),
            room = significant(*room_deg, 5)
        ),
        Notice::InputRefused(why) => error(why, unit, lang),
        Notice::PointRefused {
            name,
            to,
            unit: shown,
            why,
        } => match why {
            PointRefusal::NoSuchPoint => mw!(lang, "notice.no_such_point", name = name),
            why => mw!(
                lang,
                "notice.point_refused",
                name = name,
                x = format!("{:.2}", to[0]),
                y = format!("{:.2}", to[1]),
                unit = shown,
                why = why.words(unit, lang)
            ),
        },
        Notice::EditRefused { what, why } => mw!(
            lang,
            "notice.edit_refused",
            what = edit_subject(what, lang),
            why = error(why, unit, lang)
        ),
        Notice::HistoryRefused { undo: true, why } => {
            mw!(lang, "notice.cannot_undo", why = error(why, unit, lang))
        }
        Notice::HistoryRefused { undo: false, why } => {
            mw!(lang, "notice.cannot_redo", why = error(why, unit, lang))
        }
        // `Notice::words` words these itself and never passes them here.
        Notice::LengthRefused { .. } | Notice::LengthInvalid(_) | Notice::InvalidValue { .. } => {
            n.words(unit, lang)
        }
    }
}

/// A refused value by what it sets, with its unit.
fn value_kind(what: ValueKind, unit: LengthUnit, lang: Lang) -> String {
    match what {
        ValueKind::SpringConstant => mw!(lang, "notice.spring_constant"),
        ValueKind::Mass => mw!(lang, "notice.mass"),
        ValueKind::CamLift => mw!(
            lang,
            "notice.cam_lift",
            unit = linkage_diagram::numbers::unit_symbol(unit)
        ),
        ValueKind::InputAngle => mw!(lang, "notice.input_angle"),
    }
}

/// An edit by what it changed.
fn edit_subject(what: &EditSubject, lang: Lang) -> String {
    match what {
        EditSubject::SpringConstant { ends: [a, b] } => {
            mw!(lang, "notice.edit_spring", a = a, b = b)
        }
        EditSubject::Mass { link } => mw!(lang, "notice.edit_mass", link = link),
        EditSubject::Branch { point } => mw!(lang, "notice.edit_branch", point = point),
        EditSubject::Cam { cam, follower } => {
            mw!(lang, "notice.edit_cam", cam = cam, follower = follower)
        }
        EditSubject::Design => mw!(lang, "notice.edit_design"),
        EditSubject::Reset => mw!(lang, "notice.edit_reset"),
    }
}

impl PointRefusal {
    /// Why a point cannot go where it was dragged, in `lang`.
    pub fn words(&self, unit: LengthUnit, lang: Lang) -> String {
        match self {
            Self::NotFinite => mw!(lang, "notice.not_finite"),
            Self::NoSuchPoint => mw!(lang, "notice.no_link_carries"),
            Self::NotAssembled(why) => why.words(unit, lang),
            Self::OffGuide => mw!(lang, "notice.off_guide"),
            Self::OtherBranch => mw!(lang, "notice.other_branch"),
        }
    }
}

impl NotAssembled {
    /// The reason in `lang`, lengths in `unit`: the links by their points and the
    /// distances that do not fit, never the solver's dyad kind or margin.
    pub fn words(&self, unit: LengthUnit, lang: Lang) -> String {
        match self {
            Self::Solver(e) => error(e, unit, lang),
            Self::Open {
                dyad, shortfall, ..
            } => refusal::open(lang, dyad, shortfall.as_deref(), unit),
        }
    }
}

impl LengthError {
    /// Why a length cannot be set, in `lang`.
    pub fn words(&self, lang: Lang) -> String {
        match self {
            Self::NotPositive {
                label,
                value,
                range: [lo, hi],
            } => mw!(
                lang,
                "notice.not_positive",
                label = label,
                value = significant(*value, 6),
                lo = significant(*lo, 4),
                hi = significant(*hi, 4)
            ),
            Self::PointsGone { label } => mw!(lang, "notice.points_gone", label = label),
        }
    }
}
