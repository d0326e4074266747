//! Why a gear train is refused, and why a scene's drive train cannot drive its crank,
//! in the reader's words: the train file's members and gears by their names, every
//! number with its range. The file's own keys (`motor_member`, `gear_ratio`) stay as
//! written there, so that the reader finds them.

use linkage::error::{DriveEnd, DriveTrainProblem, FieldOwner, NameKind, TrainError, TrainField};

use super::list;
use crate::numbers::significant;
use crate::words::{Lang, sw};

/// Why a train is refused.
pub fn train(lang: Lang, e: &TrainError) -> String {
    match e {
        TrainError::Unknown { what, name, kind } => {
            let kind = match kind {
                NameKind::Gears => sw!(lang, "train.kind_gears"),
                NameKind::Members => sw!(lang, "train.kind_members"),
                NameKind::TurningMembers => sw!(lang, "train.kind_turning"),
            };
            let what = field(lang, what);
            sw!(lang, "train.unknown", what = what, name = name, kind = kind)
        }
        TrainError::Duplicate { name } => sw!(lang, "train.duplicate", name = name),
        TrainError::LossesIndeterminate => sw!(lang, "train.losses_indeterminate"),
        TrainError::SelfLocking => sw!(lang, "train.self_locking"),
        TrainError::OutOfRange {
            what,
            value,
            min,
            max,
        } => sw!(
            lang,
            "train.out_of_range",
            what = field(lang, what),
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

/// Where in the train file: the member, gear or stage by its name, the file's key as
/// written there.
fn field(lang: Lang, f: &TrainField) -> String {
    let key = f.key().unwrap_or_default();
    match f.owner() {
        FieldOwner::Member(member) => {
            sw!(lang, "train.field_member_key", member = member, key = key)
        }
        FieldOwner::Gear(gear) => sw!(lang, "train.field_gear_key", gear = gear, key = key),
        FieldOwner::Mesh(a, b) => sw!(lang, "train.field_mesh", a = a, b = b),
        FieldOwner::Stage(from, to) => {
            sw!(
                lang,
                "train.field_stage_key",
                from = from,
                to = to,
                key = key
            )
        }
        FieldOwner::Input(member) if f.key().is_some() => {
            sw!(lang, "train.field_input_key", member = member, key = key)
        }
        FieldOwner::Input(member) => sw!(lang, "train.field_input", member = member),
        FieldOwner::InputOnFrame => sw!(lang, "train.field_an_input"),
        FieldOwner::File => sw!(lang, "train.field_key", key = key),
        FieldOwner::Load => sw!(lang, "train.field_load"),
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
                what: TrainField::GearMember { gear: name("z1") },
                name: name("shaft"),
                kind: NameKind::Members,
            },
            TrainError::Unknown {
                what: TrainField::Mesh {
                    a: name("z1"),
                    b: name("z9"),
                },
                name: name("z9"),
                kind: NameKind::Gears,
            },
            TrainError::Unknown {
                what: TrainField::InputOnFrame,
                name: name("frame"),
                kind: NameKind::TurningMembers,
            },
            TrainError::Unknown {
                what: TrainField::Input {
                    member: name("frame"),
                },
                name: name("frame"),
                kind: NameKind::TurningMembers,
            },
            TrainError::Unknown {
                what: TrainField::Load,
                name: name("rotor"),
                kind: NameKind::Members,
            },
            TrainError::OutOfRange {
                what: TrainField::AxisOn {
                    member: name("sun"),
                },
                value: -1.0,
                min: 0.0,
                max: 1e9,
            },
            TrainError::OutOfRange {
                what: TrainField::Inertia {
                    member: name("sun"),
                },
                value: -1.0,
                min: 0.0,
                max: 1e9,
            },
            TrainError::OutOfRange {
                what: TrainField::StageRatio {
                    from: name("motor"),
                    to: name("shaft"),
                },
                value: 0.0,
                min: 1e-6,
                max: 1e6,
            },
            TrainError::OutOfRange {
                what: TrainField::StageFrom {
                    from: name("motor"),
                    to: name("shaft"),
                },
                value: 0.0,
                min: 1e-6,
                max: 1e6,
            },
            TrainError::OutOfRange {
                what: TrainField::StageTo {
                    from: name("motor"),
                    to: name("shaft"),
                },
                value: 0.0,
                min: 1e-6,
                max: 1e6,
            },
            TrainError::OutOfRange {
                what: TrainField::MeshEfficiency,
                value: 0.0,
                min: 0.01,
                max: 1.0,
            },
            TrainError::OutOfRange {
                what: TrainField::StageEfficiency {
                    from: name("motor"),
                    to: name("shaft"),
                },
                value: 1.5,
                min: 0.01,
                max: 1.0,
            },
            TrainError::OutOfRange {
                what: TrainField::InputRpm {
                    member: name("sun"),
                },
                value: 1e8,
                min: -1e7,
                max: 1e7,
            },
            TrainError::Duplicate { name: name("z1") },
            TrainError::OutOfRange {
                what: TrainField::Teeth { gear: name("z1") },
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
            TrainError::LossesIndeterminate,
            TrainError::SelfLocking,
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
    /// in them; the Chinese is not the English fallback and holds no English word but
    /// the file's names and keys.
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
            // No English in the Chinese but the file's names and keys as written.
            let file_words = [
                "rotor",
                "motor",
                "crank",
                "shaft",
                "sun",
                "ring",
                "carrier",
                "carrier2",
                "frame",
                "axis_on",
                "inertia_kg_m2",
                "member",
                "teeth",
                "from",
                "ratio",
                "rpm",
                "motor_member",
                "crank_member",
                "gear_ratio",
                "mesh_efficiency",
                "efficiency",
                // The unit r/min.
                "min",
            ];
            for word in zh.split(|c: char| !c.is_ascii_alphanumeric() && c != '_') {
                let english =
                    word.len() >= 3 && word.chars().all(|c| c.is_ascii_alphabetic() || c == '_');
                assert!(!english || file_words.contains(&word), "{word:?} in {zh}");
            }
        }
    }
}
