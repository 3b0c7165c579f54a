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
    outln!(
        "\nbudget.max_iterations=None: the planner's rule. Grid searches run until they find \
         the path or prove there is none; the others sample max(100000, cells / 4) times \
         (GA-PCHIP: 200 generations). --max-iter N or --time-limit S set a budget.\n\
         A step of a few units (rrt, rrt-star, bi-rrt, rrt-connect, rrt-astar-refine, \
         hybrid-rrt-astar, safe-rrt-star) is replaced by 5% of the map's diagonal unless \
         --step or NAME:step=X is given."
    )?;
    Ok(ExitCode::SUCCESS)
}
