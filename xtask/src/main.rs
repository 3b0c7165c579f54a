//! `cargo xtask`: the project's tasks.
//!
//! - `cargo xtask reproduce [--quick] [--only NAME] [--runs N] [--out DIR]`: replays the
//!   seed papers' experiments and writes a report.
//! - `cargo xtask bench-peers [--runs N] [--only CASE] [--planners LIST]`: our sampling
//!   planners against OMPL 1.5, table of median-time ratios.

use std::process::ExitCode;

use clap::{Parser, Subcommand};

mod bench_peers;
mod reproduce;
mod rooms;
mod sim004;

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
    /// Compare our sampling planners with OMPL 1.5 (builds the OMPL peer).
    BenchPeers(bench_peers::Args),
    /// Draw the synthetic room pictures into scenarios/maps/.
    Rooms,
    /// Generate the nine Table 4 workspaces of seed 000 into scenarios/.
    Table4,
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = match cli.task {
        Task::Reproduce(args) => reproduce::run(&args),
        Task::BenchPeers(args) => bench_peers::run(&args),
        Task::Table4 => rooms::write_table4(std::path::Path::new("scenarios")).map(|files| {
            for f in files {
                println!("wrote {}", f.display());
            }
        }),
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
