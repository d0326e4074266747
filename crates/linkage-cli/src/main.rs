//! `linkage`: the headless command line over scene files.
//!
//! A contract scripts depend on: see docs/cli.md. Errors go to stderr with a
//! non-zero exit status and a message naming the cause.

#![forbid(unsafe_code)]

mod args;
mod at;
mod cam;
mod counts;
mod course;
mod diagram;
mod error;
mod exercise;
mod flywheel;
mod gears;
mod io;
mod kinetostatics;
mod plot;
mod report;
mod report_text;
mod run_words;
mod shaking;
mod share;
mod simulate;
mod sweep;
mod synth;
mod synth_die_cutter;
mod synth_function;
mod synth_motion;
mod synth_path;
mod timing;
mod tradeoff;
mod train;

use std::io::{ErrorKind, Write};
use std::process::ExitCode;

use clap::Parser as _;

use args::{Cli, Command};
use error::{CliError, Result};

fn main() -> ExitCode {
    let cli = Cli::parse();
    let mut out = std::io::BufWriter::new(std::io::stdout().lock());
    let result = run(cli.command, &mut out).and_then(|()| Ok(out.flush()?));
    match result {
        Ok(()) => ExitCode::SUCCESS,
        // A reader that closed the pipe (`| head`) has all it wanted: not an error.
        Err(CliError::Output(e)) if e.kind() == ErrorKind::BrokenPipe => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
    }
}

/// Runs one command, writing its output to `out`.
fn run(command: Command, out: &mut dyn Write) -> Result<()> {
    let text = match command {
        Command::Sweep {
            scene,
            steps,
            step_deg,
            format,
        } => {
            let rows = sweep::Rows::new(steps, step_deg, format);
            return sweep::sweep(&scene, rows, format, out);
        }
        Command::At {
            scene,
            input_deg,
            format,
        } => at::at(&scene, input_deg, format),
        Command::Report { scene, format } => report::report(&scene, format),
        Command::Exercise { what } => exercise::run(what),
        Command::Synth { what } => synth::synth(what),
        Command::Gears { what } => gears::run(what),
        Command::Train { args } => train::run(&args),
        Command::Diagram { scene, args } => diagram::run(&scene, &args),
        Command::Cam {
            file,
            samples,
            format,
            dxf,
            svg,
            lang,
        } => cam::run(
            &file,
            samples,
            format,
            [dxf.as_deref(), svg.as_deref()],
            lang,
        ),
        Command::CourseSheet { scene, args } => course::run(&scene, &args),
        Command::CourseReport { scene, args } => course::report(&scene, &args),
        Command::Timing {
            scene,
            samples,
            format,
            out,
        } => timing::run(&scene, samples, format, &out),
        Command::Share { scene, decode } => share::share(scene.as_deref(), decode.as_deref()),
        Command::Simulate { scene, sim, format } if sim.steady => simulate::steady(&scene, format),
        Command::Simulate { scene, sim, format } => simulate::run(&scene, &sim, format),
        Command::Tradeoff { scene, args } => tradeoff::run(&scene, &args),
        Command::Flywheel {
            scene,
            delta,
            format,
        } => flywheel::run(&scene, delta, format),
        Command::Shaking {
            scene,
            about,
            on,
            aim,
            format,
        } => shaking::run(&scene, [about[0], about[1]], &on, aim, format),
        Command::Kinetostatics {
            scene,
            steps,
            format,
        } => kinetostatics::run(&scene, steps, format),
    }?;
    out.write_all(text.as_bytes())?;
    Ok(())
}
