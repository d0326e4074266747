//! Why a gear train is refused, and why a scene's drive train cannot drive its crank,
//! in the reader's words: the train file's members and gears by their names, every
//! number with its range. The file's own keys (`motor_member`, `gear_ratio`) stay as
//! written there, so that the reader finds them.

use linkage::error::{DriveEnd, DriveTrainProblem, TrainError};

use super::list;
use crate::numbers::significant;
use crate::words::{Lang, sw};

/// Why a train is refused.
pub fn train(lang: Lang, e: &TrainError) -> String {
    match e {
        TrainError::Unknown { what, name, kind } => {
            let kind = match *kind {
                "gears" => sw!(lang, "train.kind_gears"),
                _ => sw!(lang, "train.kind_members"),
            };
            sw!(lang, "train.unknown", what = what, name = name, kind = kind)
        }
        TrainError::Duplicate { name } => sw!(lang, "train.duplicate", name = name),
        TrainError::OutOfRange {
            what,
            value,
            min,
            max,
        } => sw!(
            lang,
            "train.out_of_range",
            what = what,
            value = significant(*value, 6),
            min = significant(*min, 6),
            max = significant(*max, 6)
        ),
        TrainError::AxesApart {
            a,
            b,
            a_axis,
            b_axis,
        } => sw!(
            lang,
            "train.axes_apart",
            a = a,
            b = b,
            a_axis = a_axis,
            b_axis = b_axis
        ),
        TrainError::RingTooSmall {
            ring,
            ring_teeth,
            mate,
            mate_teeth,
        } => sw!(
            lang,
            "train.ring_too_small",
            ring = ring,
            ring_teeth = ring_teeth,
            mate = mate,
            mate_teeth = mate_teeth
        ),
        TrainError::NoMembers => sw!(lang, "train.no_members"),
        TrainError::BothInternal { a, b } => sw!(lang, "train.both_internal", a = a, b = b),
        TrainError::Inputs { dof, given } => sw!(lang, "train.inputs", dof = dof, given = given),
        TrainError::InputsTied { member } => sw!(lang, "train.inputs_tied", member = member),
        TrainError::LoadWhereSpeedGiven { member } => {
            sw!(lang, "train.load_where_speed_given", member = member)
        }
    }
}

/// Why a scene's drive train cannot drive the crank.
pub fn drive_train(lang: Lang, p: &DriveTrainProblem) -> String {
    match p {
        DriveTrainProblem::Train(e) => train(lang, e),
        DriveTrainProblem::NoSuchMember { end, name, known } => sw!(
            lang,
            "train.no_such_member",
            key = end.key(),
            name = name,
            known = list(lang, known)
        ),
        DriveTrainProblem::SecondInput { member, rpm } => sw!(
            lang,
            "train.second_input",
            member = member,
            rpm = significant(*rpm, 6)
        ),
        DriveTrainProblem::StandsStill { end, name } => {
            let end = match end {
                DriveEnd::Motor => sw!(lang, "train.end_motor"),
                DriveEnd::Crank => sw!(lang, "train.end_crank"),
            };
            sw!(lang, "train.stands_still", name = name, end = end)
        }
        DriveTrainProblem::RatioContradicts { given, train } => sw!(
            lang,
            "train.ratio_contradicts",
            key = "gear_ratio",
            given = significant(*given, 6),
            train = significant(*train, 6)
        ),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// One of each refusal.
    fn every_problem() -> Vec<DriveTrainProblem> {
        let name = |s: &str| s.to_string();
        let trains = vec![
            TrainError::Unknown {
                what: name("gear z1's member"),
                name: name("shaft"),
                kind: "members",
            },
            TrainError::Unknown {
                what: name("mesh"),
                name: name("z9"),
                kind: "gears",
            },
            TrainError::Duplicate { name: name("z1") },
            TrainError::OutOfRange {
                what: name("gear z1's teeth"),
                value: 3.0,
                min: 4.0,
                max: 10000.0,
            },
            TrainError::AxesApart {
                a: name("z1"),
                b: name("z2"),
                a_axis: name("carrier"),
                b_axis: name("carrier2"),
            },
            TrainError::RingTooSmall {
                ring: name("z3"),
                ring_teeth: 20,
                mate: name("z2"),
                mate_teeth: 30,
            },
            TrainError::NoMembers,
            TrainError::BothInternal {
                a: name("z3"),
                b: name("z4"),
            },
            TrainError::Inputs { dof: 2, given: 1 },
            TrainError::InputsTied {
                member: name("sun"),
            },
            TrainError::LoadWhereSpeedGiven {
                member: name("sun"),
            },
        ];
        let mut all: Vec<DriveTrainProblem> =
            trains.into_iter().map(DriveTrainProblem::Train).collect();
        all.extend([
            DriveTrainProblem::NoSuchMember {
                end: DriveEnd::Motor,
                name: name("rotor"),
                known: vec![name("motor"), name("crank")],
            },
            DriveTrainProblem::SecondInput {
                member: name("ring"),
                rpm: 10.0,
            },
            DriveTrainProblem::StandsStill {
                end: DriveEnd::Crank,
                name: name("crank"),
            },
            DriveTrainProblem::RatioContradicts {
                given: 30.0,
                train: 29.0,
            },
        ]);
        all
    }

    /// Every refusal has its own words in both languages, with the names and numbers
    /// in them; the Chinese is not the English fallback.
    #[test]
    fn every_train_refusal_is_worded_in_both_languages() {
        for p in every_problem() {
            let en = drive_train(Lang::English, &p);
            let zh = drive_train(Lang::Chinese, &p);
            assert!(
                !en.contains("train.") && !zh.contains("train."),
                "{en} / {zh}"
            );
            assert_ne!(en, zh, "{p:?}");
            assert!(
                zh.chars().any(|c| ('\u{4e00}'..='\u{9fff}').contains(&c)),
                "{zh}"
            );
            let english_names = en.split(|c: char| !c.is_alphanumeric() && c != '_');
            for word in
                english_names.filter(|w| ["rotor", "z1", "z9", "sun", "30", "29"].contains(w))
            {
                assert!(zh.contains(word), "{word} missing from {zh}");
            }
        }
    }
}
