//! The exercise's words in the app's language: the model's
//! ([`linkage_model::exercise::words`], which the task sheets use too), in the
//! language of the frame.

use linkage_model::exercise::SubjectData;
use linkage_model::exercise::code::TypedAnswerError;
use linkage_model::exercise::quantity::Quantity;
use linkage_model::exercise::words;

use crate::session::Session;
use crate::ui::words::lang;

pub use words::{tolerance, unit_words};

/// A question about `subject` as the student reads it.
pub fn question(q: &Quantity, subject: &SubjectData) -> String {
    words::question(q, subject, lang())
}

/// Why a typed answer was refused.
pub fn refusal(e: &TypedAnswerError) -> String {
    words::refusal(e, lang())
}

/// The mechanism's data.
pub fn mechanism_data(session: &Session) -> Vec<(String, String)> {
    words::mechanism_data(session.scene(), lang())
}

/// A cam's data.
pub fn cam_data(cam: &linkage::cam::CamSpec) -> Vec<(String, String)> {
    words::cam_data(cam, lang())
}
