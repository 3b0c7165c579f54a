//! One module per subcommand.

/// `println!` that returns the write error instead of panicking, so a closed pipe
/// (`hyplan ... | head`) ends the program quietly (see `main`).
macro_rules! outln {
    ($($arg:tt)*) => {{
        use std::io::Write as _;
        writeln!(std::io::stdout().lock(), $($arg)*)
    }};
}

/// `envmap::load_map`, with the flag that raises the memory limit named when a map is
/// refused for its size.
pub fn load_map(
    path: &std::path::Path,
    opts: &envmap::LoadOptions,
) -> anyhow::Result<envmap::LoadedMap> {
    load_map_topic(path, envmap::DEFAULT_MAP_TOPIC, opts)
}

/// [`load_map`], a ROS 2 bag's map read from `topic`.
pub fn load_map_topic(
    path: &std::path::Path,
    topic: &str,
    opts: &envmap::LoadOptions,
) -> anyhow::Result<envmap::LoadedMap> {
    envmap::load_map_topic(path, topic, opts).map_err(|e| match e {
        envmap::MapError::TooLarge { width, height, .. } => anyhow::anyhow!(
            "{e}; raise the limit with --max-cells {}",
            width.saturating_mul(height)
        ),
        e => e.into(),
    })
}

/// A simulation scenario's error, with the flag that raises the memory limit named when
/// a grid of the run or the scenario's map file is refused for its size.
pub fn sim_scenario_error(e: ::sim::ScenarioError) -> anyhow::Error {
    let cells = match &e {
        ::sim::ScenarioError::TooLarge { cells, .. } => *cells,
        ::sim::ScenarioError::Map {
            source: envmap::MapError::TooLarge { width, height, .. },
            ..
        } => *width as f64 * *height as f64,
        _ => return e.into(),
    };
    if cells <= usize::MAX as f64 {
        anyhow::anyhow!("{e}; raise the limit with --max-cells {cells:.0}")
    } else {
        anyhow::anyhow!(
            "{e}; no --max-cells value can hold that many cells: coarsen the resolution or shrink the world"
        )
    }
}

/// World units per input unit: a cell for maps given in cells, else 1.
pub fn input_scale(frame: &envmap::InputFrame) -> f64 {
    match *frame {
        envmap::InputFrame::Cells { resolution, .. } => resolution,
        envmap::InputFrame::World | envmap::InputFrame::MapFrame { .. } => 1.0,
    }
}

/// A point given as `X,Y` on the command line.
pub fn parse_xy(s: &str) -> anyhow::Result<(f64, f64)> {
    use anyhow::Context as _;
    let (x, y) = s
        .split_once(',')
        .with_context(|| format!("expected X,Y, got {s:?}"))?;
    let parse = |v: &str| {
        v.trim()
            .parse::<f64>()
            .with_context(|| format!("{v:?} in {s:?} is not a number"))
    };
    Ok((parse(x)?, parse(y)?))
}

/// Whether `path` is a ROS map (`map_server` `.yaml`), which `hyplan sim` and `hyplan
/// explore` take in place of a scenario.
pub fn is_ros_map(path: &std::path::Path) -> bool {
    path.extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("yaml") || e.eq_ignore_ascii_case("yml"))
}

/// What a scenario made from a ROS map says besides the map: the robot's start and goal,
/// whether the map is known in advance, and the time limit.
pub struct OnMap {
    /// `explore` or `nav`, the start of the scenario's name.
    pub kind: &'static str,
    /// Start, metres in the map frame.
    pub start: (f64, f64),
    /// Goal, metres in the map frame.
    pub goal: (f64, f64),
    /// Whether the robot knows the map in advance.
    pub known_map: bool,
    /// Simulated seconds before the run is stopped.
    pub time_limit: f64,
}

/// The scenario of the ROS map `map` (its `.yaml`) with `on` and the defaults: the
/// scenario takes the map's path, so that its file name resolves beside it and errors
/// name the file given.
pub fn scenario_on_map(map: &std::path::Path, on: &OnMap) -> anyhow::Result<::sim::Scenario> {
    use anyhow::Context as _;
    // The simulator runs in the grid's frame; on a map whose origin has a yaw that is the
    // map frame turned by it, so the flags' map-frame points are turned into it (as
    // `hyplan plan` does). A YAML that does not read is the scenario's error below.
    let frame = envmap::read_ros_yaml(map).map_or(envmap::InputFrame::World, |meta| {
        envmap::InputFrame::ros(meta.origin, meta.yaw)
    });
    let (start, goal) = (
        frame.to_world(on.start.0, on.start.1),
        frame.to_world(on.goal.0, on.goal.1),
    );
    let file = map
        .file_name()
        .with_context(|| format!("{}: not a file", map.display()))?
        .to_string_lossy()
        .into_owned();
    let stem = file.split('.').next().unwrap_or("map");
    let text = format!(
        "SimScenario(name: {name:?}, description: {what:?}, world: (map: Some(Ros({file:?}))), \
         start: ({:?}, {:?}), goal: ({:?}, {:?}), known_map: {}, time_limit: {:?})",
        start.x,
        start.y,
        goal.x,
        goal.y,
        on.known_map,
        on.time_limit,
        name = format!("{}-{stem}", on.kind),
        what = format!(
            "{file} with the defaults ({} scenario made from the map)",
            on.kind
        ),
    );
    ::sim::Scenario::parse(&text, map).map_err(sim_scenario_error)
}

/// `--time-limit`, when given, in place of the scenario's.
pub fn set_time_limit(scenario: &mut ::sim::Scenario, limit: Option<f64>) -> anyhow::Result<()> {
    if let Some(limit) = limit {
        if !(limit.is_finite() && limit > 0.0) {
            anyhow::bail!("--time-limit = {limit}: must be finite and > 0 (seconds)");
        }
        scenario.time_limit = limit;
    }
    Ok(())
}

/// A scenario's error; for a scenario made from a map (`on_map`), a bad start or goal is
/// the flag's (`--start`, `--goal`).
pub fn map_point_error(e: ::sim::ScenarioError, on_map: bool) -> anyhow::Error {
    match e {
        ::sim::ScenarioError::Field {
            field,
            value,
            reason,
            ..
        } if on_map && (field == "start" || field == "goal") => {
            anyhow::anyhow!("--{field} {value}: {reason}")
        }
        e => sim_scenario_error(e),
    }
}

pub mod bench;
pub mod explore;
pub mod map;
pub mod plan;
pub mod planners;
pub mod scen;
pub mod sim;
