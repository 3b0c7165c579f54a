//! `hyplan planners`: every planner of the registry with its help line, its parameters at
//! their defaults (in the form `--planner NAME:key=value,...` and the scenario files take)
//! and what it can do; with a name, each parameter's type and meaning too.

use std::process::ExitCode;

use registry::{Capabilities, Explored, PlannerConfig, PlannerKind};

/// Options of `hyplan planners`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// Show only this planner, with each parameter's type and meaning.
    #[arg(value_parser = crate::planners::SpecParser::default())]
    pub name: Option<String>,
}

/// Prints the registry; exit 2 for an unknown name.
pub fn run(args: &Args) -> anyhow::Result<ExitCode> {
    let configs: Vec<PlannerConfig> = match &args.name {
        Some(name) => vec![PlannerConfig::by_name(name)?],
        None => PlannerConfig::all().collect(),
    };
    for c in &configs {
        outln!("{:<18} {}", c.name(), c.help())?;
        let pairs: Vec<String> = c.params().iter().map(|(k, v)| format!("{k}={v}")).collect();
        outln!("{:<18} defaults: {}", "", pairs.join(", "))?;
        outln!(
            "{:<18} capabilities: {}",
            "",
            capability_words(&c.capabilities())
        )?;
        if args.name.is_some() {
            for p in c.parameters() {
                outln!(
                    "{:<18}   {:<24} {:<14} {:<12} {}",
                    "",
                    p.name,
                    p.ty,
                    p.default,
                    p.doc
                )?;
            }
        }
    }
    let placeholder: Vec<&str> = PlannerKind::all()
        .filter(|k| k.capabilities().wants_default_step && *k != PlannerKind::RrtAstarBt)
        .map(PlannerKind::name)
        .collect();
    outln!(
        "\nbudget.max_iterations=None: the planner's rule. Grid searches run until they find \
         the path or prove there is none; the others sample max(100000, cells / 4) times \
         (GA-PCHIP: 200 generations). --max-iter N or --time-limit S set a budget.\n\
         A step of a few units ({}) is replaced by 5% of the map's diagonal unless \
         --step or NAME:step=X is given. rrt-astar-bt's step and goal radius (seed 000's \
         pixels) are scaled to the map as they were to the paper's 960 x 640 px room.",
        placeholder.join(", ")
    )?;
    Ok(ExitCode::SUCCESS)
}

/// The capabilities as a short phrase list.
fn capability_words(c: &Capabilities) -> String {
    let family = c.family.to_string();
    let randomness = if c.deterministic {
        "deterministic"
    } else {
        "randomised"
    };
    let explored = match c.explored {
        Explored::Nodes => "explored = tree nodes",
        Explored::Expansions => "explored = cells expanded",
    };
    // The phrases of the capabilities a planner may have, in the order they are listed.
    let optional = [
        (c.grid_only, "grid maps only"),
        (
            c.has_step && c.wants_default_step,
            "step (map-sized by default)",
        ),
        (c.has_step && !c.wants_default_step, "step"),
        (c.goal_bias, "goal bias"),
        (c.own_goal_radius, "own goal radius"),
        (c.uses_risk, "pays for the risk band"),
    ];
    let mut words = vec![family.as_str(), randomness];
    words.extend(optional.iter().filter(|(has, _)| *has).map(|(_, w)| *w));
    words.push(explored);
    words.join(", ")
}
