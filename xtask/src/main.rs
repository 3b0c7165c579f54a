//! `cargo xtask`: the project's tasks.
//!
//! - `cargo xtask reproduce [--quick] [--only NAME] [--runs N] [--out DIR]`: replays the
//!   seed papers' experiments and writes a report.

use std::process::ExitCode;

use clap::{Parser, Subcommand};

mod reproduce;
mod rooms;

#[derive(Parser)]
#[command(name = "xtask", about = "hyplan project tasks")]
struct Cli {
    #[command(subcommand)]
    task: Task,
}

#[derive(Subcommand)]
enum Task {
    /// Replay the seed papers' experiments and write a report.
    Reproduce(reproduce::Args),
    /// Draw the synthetic room pictures into scenarios/maps/.
    Rooms,
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = match cli.task {
        Task::Reproduce(args) => reproduce::run(&args),
        Task::Rooms => rooms::write_rooms(std::path::Path::new("scenarios/maps")).map(|files| {
            for f in files {
                println!("wrote {}", f.display());
            }
        }),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e:#}");
            ExitCode::from(2)
        }
    }
}
