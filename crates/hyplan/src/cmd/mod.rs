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

/// The file name of `path`, for a scenario that names it beside itself.
pub fn file_name(path: &std::path::Path) -> anyhow::Result<String> {
    use anyhow::Context as _;
    Ok(path
        .file_name()
        .with_context(|| format!("{}: not a file", path.display()))?
        .to_string_lossy()
        .into_owned())
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
