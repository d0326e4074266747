//! The course sheet of every shipped scene and every example (read from their
//! directories), with the default 12 positions and with 5: it is made, holds no
//! non-finite number, numbers every position, its positions are evenly spaced over
//! the crank's range, and the output's diagrams start at position 0.

use crate::common;

use linkage::Kinematics;
use linkage_diagram::course::CourseSheet;
use linkage_diagram::svg_course::course_sheet;
use linkage_diagram::words::Lang;

#[test]
fn every_scene_gets_a_course_sheet_with_its_positions_on_its_diagrams() {
    for (file, m) in common::scenes_and_examples() {
        for count in [12, 5] {
            let mut k = Kinematics::new(m.clone()).expect("kinematics");
            let sheet = CourseSheet::compute(&mut k, count, &[1, count - 1])
                .unwrap_or_else(|e| panic!("{file}: {e}"));
            assert_eq!(sheet.positions.len(), count);
            let svg = course_sheet(&sheet, Lang::English).pages.concat();
            assert!(!svg.contains("NaN") && !svg.contains("inf"), "{file}");
            for n in 0..count {
                assert!(
                    svg.contains(&format!("<tspan>{n}</tspan></text>")),
                    "{file}: position {n}"
                );
            }
            let angles: Vec<f64> = sheet.positions.iter().map(|s| s.input_rad).collect();
            let steps: Vec<f64> = angles.windows(2).map(|w| w[1] - w[0]).collect();
            for s in &steps {
                assert!(
                    (s - steps[0]).abs() <= 1e-9 * steps[0].abs(),
                    "{file}: uneven"
                );
            }
            let o = sheet.output.as_ref().expect("an output");
            let first = o.s.first().expect("samples");
            assert!((first[0] - angles[0].to_degrees()).abs() <= 1e-9, "{file}");
        }
    }
}

/// Position 0 where the user puts it: on every shipped scene, 10° into the crank's
/// range, the positions start there, evenly spaced; a crank that rocks refuses an
/// angle past its range, and the refusal names the range.
#[test]
fn the_first_position_is_where_asked() {
    for (file, m) in common::scenes() {
        let mut k = Kinematics::new(m).expect("kinematics");
        let ([a, b], full) = linkage::sweep::sweep_range(&k).expect("a range");
        let first = a.to_degrees() + 10.0;
        let sheet = CourseSheet::compute_from(&mut k, 6, Some(first), &[1])
            .unwrap_or_else(|e| panic!("{file}: {e}"));
        let angles: Vec<f64> = sheet
            .positions
            .iter()
            .map(|s| s.input_rad.to_degrees())
            .collect();
        assert!(
            (angles[0] - first).abs() <= 1e-9 * first.abs().max(1.0),
            "{file}: {angles:?}"
        );
        let span = if full { 360.0 } else { b.to_degrees() - first };
        let step = span / if full { 6.0 } else { 5.0 };
        for w in angles.windows(2) {
            assert!(
                (w[1] - w[0] - step).abs() <= 1e-9 * span,
                "{file}: {angles:?}"
            );
        }
        if !full {
            let past = b.to_degrees() + 5.0;
            let refused = CourseSheet::compute_from(&mut k, 6, Some(past), &[1]);
            let e = refused.expect_err("refused").to_string();
            assert!(e.contains("first position"), "{file}: {e}");
        }
    }
}
