//! `hyplan planners`: every planner of the registry with its help line and its parameters
//! at their defaults, in the form `--planner NAME:key=value,...` and the scenario files
//! take.

use std::process::ExitCode;

use harness::PlannerConfig;

/// Options of `hyplan planners`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// Show only this planner.
    pub name: Option<String>,
}

/// Prints the registry; exit 2 for an unknown name.
pub fn run(args: &Args) -> anyhow::Result<ExitCode> {
    let configs: Vec<PlannerConfig> = match &args.name {
        Some(name) => vec![PlannerConfig::by_name(name)?],
        None => PlannerConfig::all().collect(),
    };
    for c in configs {
        outln!("{:<18} {}", c.name(), c.help())?;
        let pairs: Vec<String> = c.params().iter().map(|(k, v)| format!("{k}={v}")).collect();
        outln!("{:<18} defaults: {}", "", pairs.join(", "))?;
    }
    Ok(ExitCode::SUCCESS)
}
