//! Monte-Carlo runs with per-run seeds.

use postproc::Smoothing;
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;

use crate::{Explored, PlannerConfig, PlannerSpec, RunMetrics, Scenario, Scoring, World, measure};

/// The seed of run `run` for base seed `base`: output number `run + 1` of a SplitMix64
/// generator started at `base`, i.e. `mix(base + (run + 1) * 0x9E3779B97F4A7C15)` with
/// SplitMix64's finaliser. Runs get well-spread, independent seeds, and a run's seed
/// depends on its index alone (never on thread order or on how many runs there are).
/// The CLI's `--seed` / `--runs` use the same rule.
///
/// ```
/// // SplitMix64's published first outputs for seed 0 (Vigna's reference implementation).
/// assert_eq!(harness::run_seed(0, 0), 0xE220_A839_7B1D_CDAF);
/// assert_eq!(harness::run_seed(0, 1), 0x6E78_9E6A_A1B9_65F4);
/// ```
#[must_use]
pub fn run_seed(base: u64, run: u64) -> u64 {
    let mut z = base.wrapping_add(run.wrapping_add(1).wrapping_mul(0x9E37_79B9_7F4A_7C15));
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}

/// Makes `map`'s one-time preparation for `planner` (built from `config`), which its
/// timed runs should not pay: the edge checks' stride table for a planner that tests
/// segments, the grid search's tables (kept with the map) for a grid planner. Whether
/// there was any; a grid planner's refusal is left for its runs to report, in their own
/// words. `hyplan plan`, `hyplan bench` and the Python `plan` call it before timing.
///
/// ```
/// use envmap::GridMap;
/// let map = GridMap::from_ascii("....\n.#..\n....")?;
/// let config: harness::PlannerConfig = "astar".parse()?;
/// assert!(harness::prepare_map(&config, &*config.build(), &map));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn prepare_map(
    config: &PlannerConfig,
    planner: &dyn hyplan_core::Planner,
    map: &envmap::GridMap,
) -> bool {
    let strides = config.capabilities().checks_segments && map.blocked_strides().is_some();
    let searches = planner.info().grid_only && planner.prepare(map).is_ok();
    strides || searches
}

/// Runs one planner of a scenario `runs` times and scores each run.
///
/// Run k uses `ChaCha8Rng::seed_from_u64(run_seed(scenario.base_seed, k))`. With the
/// `parallel` feature and `parallel = true` the runs are spread over threads; every number
/// but the times equals the serial run's. `progress` is called once per finished run.
///
/// # Errors
///
/// [`postproc::PostprocError`] for a smoothing method or robot limits that cannot be used
/// (scenarios are validated on load, so this only happens for specs made in code).
pub fn run_planner(
    scenario: &Scenario,
    world: &World,
    spec: &PlannerSpec,
    runs: u32,
    parallel: bool,
    progress: &(dyn Fn() + Sync),
) -> Result<Vec<RunMetrics>, postproc::PostprocError> {
    let planner = spec.planner.build();
    let smoothing = spec
        .smoothing
        .as_deref()
        .map_or(Ok(Smoothing::None), str::parse)?;
    let limits = match scenario.limits {
        Some(l) => {
            l.validate()?;
            Some(l)
        }
        None => None,
    };
    // Clearance is measured to obstacles, whatever zone the planner avoided.
    let mut obstacles = world.map.clone();
    obstacles.blocked_from = hyplan_core::Zone::Forbidden;
    let scoring = Scoring {
        ws: &world.map,
        obstacles: &obstacles,
        explored_by_expansions: spec.planner.explored() == Explored::Expansions,
        smoothing,
        limits,
        // Curves are checked at most a quarter cell apart.
        spacing: world.map.resolution() * 0.25,
    };
    let one = |k: u32| {
        let seed = run_seed(scenario.base_seed, u64::from(k));
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        // The thread's CPU time: a run never leaves its thread, and unlike the wall clock it
        // does not count the time other processes hold the core.
        let cpu = cpu_time::ThreadTime::try_now().ok();
        let outcome = planner.plan(&world.map, &world.query, &mut rng);
        let cpu_s = cpu.map_or(f64::NAN, |t| t.elapsed().as_secs_f64());
        let mut m = measure(&scoring, &outcome, k, seed);
        m.cpu_time_s = cpu_s;
        // Run 0's trees go into the figures; the others' would only cost memory.
        if let (0, Ok(plan)) = (k, outcome) {
            m.trees = plan.trees;
        }
        progress();
        m
    };
    #[cfg(feature = "parallel")]
    if parallel {
        use rayon::prelude::*;
        return Ok((0..runs).into_par_iter().map(one).collect());
    }
    let _ = parallel;
    Ok((0..runs).map(one).collect())
}
