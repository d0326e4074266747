//! The real system dialog (`file_dialog::SystemDialog`, rfd underneath) on a desktop
//! without an XDG portal, where rfd falls back to zenity. A stand-in `zenity` script on
//! PATH records its arguments and answers like zenity: this checks what the app asks
//! (title, file type, suggested name, save vs open), that the answer comes back as a
//! path, and that a desktop with neither portal nor zenity is reported as such.
//!
//! The environment has to change for the dialog, and changing it inside the test
//! process would race the other tests (and needs `unsafe`), so each case re-runs this
//! test binary in a child process with the environment set, running only the
//! `#[ignore]`d `dialog_in_child` test.

#![cfg(all(unix, not(target_arch = "wasm32")))]

use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::Duration;

use linkage_lab::file_dialog::{PathAnswer, PathChooser, PathRequest, SystemDialog};
use linkage_lab::ui::files::FileAction;

/// Asks the system dialog what the environment says, prints the answer.
#[test]
#[ignore = "run by the other tests in a child process, with a stand-in zenity on PATH"]
fn dialog_in_child() {
    let action = match std::env::var("DIALOG_ACTION").as_deref() {
        Ok("open") => FileAction::Open,
        Ok("save") => FileAction::SaveScene,
        _ => FileAction::ExportCsv,
    };
    let (send, receive) = std::sync::mpsc::channel();
    SystemDialog.choose(
        PathRequest {
            action,
            suggested_name: "die_cutter.ron".into(),
            directory: None,
        },
        None,
        Box::new(move |answer| send.send(answer).expect("the test waits")),
    );
    let answer = receive
        .recv_timeout(Duration::from_secs(60))
        .expect("the dialog answers");
    println!("ANSWER={answer:?}");
}

/// A folder holding the stand-in `zenity`, which logs its arguments one per line to
/// `args.log` and, after `delay_s`, prints `answer` (if any) and exits with `status`.
fn fake_zenity(case: &str, answer: &str, status: i32, delay_s: f64) -> PathBuf {
    use std::os::unix::fs::PermissionsExt as _;
    let dir =
        std::env::temp_dir().join(format!("linkage-lab-zenity-{case}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let log = dir.join("args.log");
    // Like zenity, it prints nothing at all on cancel.
    let print = if answer.is_empty() {
        String::new()
    } else {
        format!("printf '%s\\n' '{answer}'\n")
    };
    let script = format!(
        "#!/bin/sh\nfor a in \"$@\"; do printf '%s\\n' \"$a\"; done > '{}'\nsleep {delay_s}\n\
         {print}exit {status}\n",
        log.display()
    );
    let path = dir.join("zenity");
    std::fs::write(&path, script).expect("write script");
    std::fs::set_permissions(&path, std::fs::Permissions::from_mode(0o755)).expect("chmod");
    dir
}

/// Runs `dialog_in_child` with `path_dirs` first on PATH and no reachable session
/// bus (so no portal answers); returns its printed answer.
fn run_child(action: &str, path_dirs: &[&Path], keep_system_path: bool) -> String {
    let mut path: Vec<PathBuf> = path_dirs.iter().map(|d| d.to_path_buf()).collect();
    if keep_system_path {
        // After the stand-in, which so shadows a real zenity (the script needs sleep).
        let system = std::env::var_os("PATH").unwrap_or_default();
        path.extend(std::env::split_paths(&system));
    }
    let out = Command::new(std::env::current_exe().expect("test binary"))
        .args([
            "system_file_dialog::dialog_in_child",
            "--exact",
            "--ignored",
            "--nocapture",
        ])
        .env("PATH", std::env::join_paths(path).expect("PATH"))
        .env(
            "DBUS_SESSION_BUS_ADDRESS",
            "unix:path=/nonexistent/linkage-lab-bus",
        )
        .env("DIALOG_ACTION", action)
        .output()
        .expect("child runs");
    let stdout = String::from_utf8_lossy(&out.stdout).into_owned();
    assert!(
        out.status.success(),
        "child failed:\n{stdout}\n{}",
        String::from_utf8_lossy(&out.stderr)
    );
    stdout
        .lines()
        .find_map(|l| l.strip_prefix("ANSWER="))
        .unwrap_or_else(|| panic!("no answer in:\n{stdout}"))
        .to_string()
}

fn logged_args(dir: &Path) -> Vec<String> {
    std::fs::read_to_string(dir.join("args.log"))
        .expect("zenity was run")
        .lines()
        .map(str::to_string)
        .collect()
}

#[test]
fn save_asks_zenity_for_a_ron_file_with_the_suggested_name() {
    let dir = fake_zenity("save", "/home/student/cutter.ron", 0, 0.0);
    let answer = run_child("save", &[&dir], true);
    assert_eq!(
        answer,
        format!(
            "{:?}",
            PathAnswer::Chosen("/home/student/cutter.ron".into())
        )
    );
    let args = logged_args(&dir);
    for expected in [
        "--file-selection",
        "--save",
        "--filename",
        "die_cutter.ron",
        "Linkage scene | *.ron",
    ] {
        assert!(args.iter().any(|a| a == expected), "{expected} in {args:?}");
    }
    std::fs::remove_dir_all(dir).expect("clean up");
}

#[test]
fn open_and_export_ask_for_their_file_types() {
    let dir = fake_zenity("open", "/srv/scenes/cam.ron", 0, 0.0);
    let answer = run_child("open", &[&dir], true);
    assert_eq!(
        answer,
        format!("{:?}", PathAnswer::Chosen("/srv/scenes/cam.ron".into()))
    );
    let args = logged_args(&dir);
    assert!(args.iter().any(|a| a == "--file-selection"), "{args:?}");
    assert!(
        !args.iter().any(|a| a == "--save"),
        "open is no save: {args:?}"
    );
    std::fs::remove_dir_all(&dir).expect("clean up");

    let dir = fake_zenity("export", "/tmp/sweep.csv", 0, 0.0);
    run_child("export", &[&dir], true);
    let args = logged_args(&dir);
    assert!(args.iter().any(|a| a == "CSV table | *.csv"), "{args:?}");
    std::fs::remove_dir_all(dir).expect("clean up");
}

#[test]
fn closing_the_dialog_is_a_cancel() {
    // zenity prints nothing and exits 1 on cancel; a person takes longer than 600 ms.
    let dir = fake_zenity("cancel", "", 1, 1.0);
    let answer = run_child("open", &[&dir], true);
    assert_eq!(answer, format!("{:?}", PathAnswer::Cancelled));
    std::fs::remove_dir_all(dir).expect("clean up");
}

#[test]
fn no_portal_and_no_zenity_is_reported_as_unavailable() {
    let empty = std::env::temp_dir().join(format!("linkage-lab-no-zenity-{}", std::process::id()));
    std::fs::create_dir_all(&empty).expect("temp dir");
    let answer = run_child("open", &[&empty], false);
    assert_eq!(answer, format!("{:?}", PathAnswer::Unavailable));
    std::fs::remove_dir_all(empty).expect("clean up");
}
