//! `hyplan`: the command-line tool over the hyplan crates.
//!
//! Thin glue: each subcommand parses its flags, validates them into the libraries' types,
//! calls the libraries and prints. Exit codes: 0 success (a path was found), 1 no path,
//! 2 bad input or any other error.

use std::process::ExitCode;

use clap::{Parser, Subcommand};

mod cmd;
mod planners;

/// Exit code for "no path".
pub const EXIT_NO_PATH: u8 = 1;
/// Exit code for bad input and other errors.
pub const EXIT_ERROR: u8 = 2;

#[derive(Parser)]
#[command(
    name = "hyplan",
    version,
    about = "2-D path planning for mobile robots"
)]
pub(crate) struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Benchmark planners on your maps and queries: CSV, JSON, a Markdown summary with
    /// rank tests, SVG box plots and an OMPL benchmark log per problem.
    Bench(Box<cmd::bench::Args>),
    /// Explore an unknown world with seed 004's RRT frontier detectors (or the
    /// nearest-frontier baseline): coverage over time, the built map, figures (exit 1:
    /// stopped by the time limit).
    Explore(cmd::explore::Args),
    /// Turn a picture, ROS map or MovingAI map into a three-zone safe map.
    Map(cmd::map::Args),
    /// Plan a path with any planner of the registry (`hyplan planners` lists them).
    Plan(cmd::plan::Args),
    /// List the planners with their parameters and defaults.
    Planners(cmd::planners::Args),
    /// Run a MovingAI scenario file (.map + .scen) and compare with its optimal lengths.
    Scen(cmd::scen::Args),
    /// Drive the simulated robot of seed 004 through a scenario with people (exit 1: goal
    /// not reached).
    Sim(cmd::sim::Args),
}

fn main() -> ExitCode {
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        Err(e) => {
            // clap prints help and version to stdout with success; usage errors exit 2.
            let code = if e.use_stderr() { EXIT_ERROR } else { 0 };
            let _ = e.print();
            return ExitCode::from(code);
        }
    };
    let result = match cli.command {
        Command::Bench(args) => cmd::bench::run(&args),
        Command::Explore(args) => cmd::explore::run(&args),
        Command::Map(args) => cmd::map::run(&args),
        Command::Plan(args) => cmd::plan::run(&args),
        Command::Planners(args) => cmd::planners::run(&args),
        Command::Scen(args) => cmd::scen::run(&args),
        Command::Sim(args) => cmd::sim::run(&args),
    };
    match result {
        Ok(code) => code,
        // The reader went away (`hyplan ... | head`): nothing more to say, as ripgrep does.
        Err(e) if is_broken_pipe(&e) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e:#}");
            ExitCode::from(EXIT_ERROR)
        }
    }
}

/// Whether an error comes from writing to a closed pipe.
fn is_broken_pipe(e: &anyhow::Error) -> bool {
    e.chain().any(|cause| {
        cause
            .downcast_ref::<std::io::Error>()
            .is_some_and(|io| io.kind() == std::io::ErrorKind::BrokenPipe)
    })
}
