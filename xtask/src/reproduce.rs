//! `cargo xtask reproduce`.

use std::path::PathBuf;

/// Options of `cargo xtask reproduce`.
#[derive(clap::Args)]
pub struct Args {
    /// Few runs per experiment, for CI (at most a minute).
    #[arg(long)]
    pub quick: bool,
    /// Only the experiments whose name contains this text.
    #[arg(long)]
    pub only: Option<String>,
    /// Runs per planner, overriding the scenario files.
    #[arg(long)]
    pub runs: Option<u32>,
    /// Output folder (default `target/reproduce`).
    #[arg(long)]
    pub out: Option<PathBuf>,
}

/// Runs the reproduction.
pub fn run(args: &Args) -> anyhow::Result<()> {
    let out = args
        .out
        .clone()
        .unwrap_or_else(|| PathBuf::from("target/reproduce"));
    std::fs::create_dir_all(&out)?;
    println!("nothing to reproduce yet; report folder {}", out.display());
    Ok(())
}
