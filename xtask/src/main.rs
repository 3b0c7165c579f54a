//! `cargo xtask`: the project's tasks.
//!
//! - `cargo xtask reproduce [--quick] [--only NAME] [--runs N] [--out DIR]`: replays the
//!   seed papers' experiments and writes a report.
//! - `cargo xtask bench-peers [--runs N] [--rounds R] [--only CASE] [--planners LIST]`: our
//!   sampling planners against OMPL 1.5, table of median-time ratios.
//! - `cargo xtask soak [--minutes N] [--seed S]`: every planner and smoothing method on
//!   seeded generated maps, each path checked by an exact segment-versus-cell test;
//!   prints plans checked, colliding and panics per planner; `--maps M --shard K/N
//!   --out DIR` runs one shard of M maps, `cargo xtask soak-merge DIR...` joins them.
//! - `cargo xtask proptest-soak [--minutes N]`: the property tests, round after round
//!   with fresh seeds; a failure prints the seed that replays it.
//! - `cargo xtask explore-maps [--maps LIST] [--detectors LIST] [--seeds LIST] [--out DIR]`:
//!   exploration of every building map (issue 27), each detector and seed; a Markdown
//!   table and JSON of coverage, how each run ended and simulated / wall time.
//! - `cargo xtask crowd [--runs N] [--densities LIST] [--flows LIST] [--controllers LIST]
//!   [--models LIST] [--out DIR]`: the robot among generated crowds (issue 29); a Markdown
//!   table of success, contacts, time against the empty room, personal space, the people's
//!   delay and the tracker against the truth.

use std::process::ExitCode;

use clap::{Parser, Subcommand};

mod bench_peers;
mod crowd;
mod explore004;
mod explore_maps;
mod report;
mod reproduce;
mod rooms;
mod sim004;
mod soak;

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
    /// Every planner and smoothing method on generated maps, paths checked exactly.
    Soak(soak::Args),
    /// Check that soak shards cover one soak exactly once and print the whole table.
    SoakMerge(soak::MergeArgs),
    /// The property tests with fresh seeds, round after round.
    ProptestSoak(soak::PropArgs),
    /// Explore every building map with every detector and seed: coverage table and JSON.
    ExploreMaps(explore_maps::Args),
    /// The robot among generated crowds: densities x controllers x people models.
    Crowd(crowd::Args),
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = match cli.task {
        Task::Reproduce(args) => reproduce::run(&args),
        Task::BenchPeers(args) => bench_peers::run(&args),
        Task::Soak(args) => soak::run(&args),
        Task::SoakMerge(args) => soak::merge(&args),
        Task::ProptestSoak(args) => soak::run_proptests(&args),
        Task::ExploreMaps(args) => explore_maps::run(&args),
        Task::Crowd(args) => crowd::run(&args),
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
