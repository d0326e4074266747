//! The messages issue 22's fuzzing of the CLI found unclear (about 20,000 runs, 44
//! unclear): a count that is negative or not whole, a speed whose velocities
//! overflow, a link given by name and answered by index. Each test is named after
//! its finding and checks that the message names the input and its valid range.

use crate::common;

use common::{run_linkage as linkage, scene};

#[test]
fn a_negative_step_count_names_the_option_and_its_range() {
    // Was: "unexpected argument '-1' found".
    for (args, want) in [
        (vec!["sweep", "--steps", "-1"], "at least 2"),
        (vec!["sweep", "--steps", "2.5"], "not a whole number"),
        (vec!["kinetostatics", "--steps", "-4"], "at least 1"),
    ] {
        let mut all = vec![args[0], ""];
        let file = scene("die_cutter.ron");
        all[1] = &file;
        all.extend(&args[1..]);
        let (code, _, err) = linkage(&all);
        assert_eq!(code, Some(2), "{err}");
        assert!(
            err.contains("--steps") && err.contains(want),
            "{args:?}: {err}"
        );
    }
    let (_, _, err) = linkage(&["synth", "path", "--points", "x.csv", "--solutions", "0"]);
    assert!(
        err.contains("--solutions") && err.contains("at least 1"),
        "{err}"
    );
}

#[test]
fn an_overflowing_speed_names_the_input_and_the_largest_speed_that_works() {
    // Was: "non-finite value in sweep (column 17)".
    let (code, _, err) = linkage(&["sweep", &scene("die_cutter.ron"), "--speed-rad-s", "1e308"]);
    assert_eq!(code, Some(1), "{err}");
    assert!(
        err.contains("--speed-rad-s 1e308")
            && err.contains("give at most")
            && !err.contains("column"),
        "{err}"
    );
    // The scene's own speed: 1e300 rpm.
    let text = std::fs::read_to_string(scene("die_cutter.ron"))
        .unwrap_or_default()
        .replace("Rpm(50.0)", "Rpm(1e300)");
    let dir = std::env::temp_dir().join(format!("linkage-overflow-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap_or_default();
    let file = dir.join("fast.ron");
    std::fs::write(&file, text).unwrap_or_default();
    let path = file.display().to_string();
    for command in ["sweep", "kinetostatics", "at"] {
        let mut args = vec![command, &path];
        if command == "at" {
            args.extend(["--input-deg", "10"]);
        }
        let (_, _, err) = linkage(&args);
        assert!(
            err.contains("the scene's driver speed")
                && err.contains("1e300 rpm")
                && err.contains("at most"),
            "{command}: {err}"
        );
    }
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_coordinate_link_is_named_by_its_name_with_the_links_that_can_be() {
    // Was: "coordinate link = 2 is invalid".
    let (code, _, err) = linkage(&[
        "simulate",
        &scene("gravity_flipper.ron"),
        "--coordinate",
        "table",
    ]);
    assert_eq!(code, Some(1), "{err}");
    assert!(
        err.contains("`table`") && err.contains("link1, link3") && !err.contains("= 2"),
        "{err}"
    );
}
