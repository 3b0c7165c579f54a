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
        let fields = harness::ron_options().to_string(&c)?;
        // `Rrt(step:1.0,...)` -> `step=1.0, ...`: the pairs `--planner` takes.
        let inner = fields
            .split_once('(')
            .and_then(|(_, rest)| rest.strip_suffix(')'))
            .unwrap_or("");
        outln!(
            "{:<18} defaults: {}",
            "",
            inner.replace(':', "=").replace(",", ", ")
        )?;
    }
    Ok(ExitCode::SUCCESS)
}
