//! `linkage`: the headless command line over scene files.
//!
//! A contract scripts depend on: see docs/cli.md. Errors go to stderr with a
//! non-zero exit status and a message naming the cause.

#![forbid(unsafe_code)]

mod args;
mod commands;
mod counts;
mod diagram;
mod error;
mod io;
mod kinetostatics;
mod plot;
mod simulate;
mod synth_function;
mod synth_motion;
mod synth_path;
mod tradeoff;

use std::io::{ErrorKind, Write};
use std::process::ExitCode;

use clap::Parser as _;

use args::Cli;
use error::CliError;

fn main() -> ExitCode {
    let cli = Cli::parse();
    let mut out = std::io::BufWriter::new(std::io::stdout().lock());
    let result = commands::run(cli.command, &mut out).and_then(|()| Ok(out.flush()?));
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
