//! `hyplan map`.

use std::path::PathBuf;
use std::process::ExitCode;

/// Options of `hyplan map`.
#[derive(clap::Args)]
pub struct Args {
    /// An image (PNG, PGM, PPM), a ROS map_server `.yaml` or a MovingAI `.map`.
    pub input: PathBuf,
}

/// Runs `hyplan map`.
pub fn run(args: &Args) -> anyhow::Result<ExitCode> {
    anyhow::bail!("{}: map loading is not implemented yet", args.input.display())
}
